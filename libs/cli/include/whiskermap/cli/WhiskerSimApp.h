#pragma once

namespace whiskermap::cli
{
/** The whisker-sim command line: simulate a robot whisking along a trajectory in a world
 *  and record the sweeps as a rawlog with ground truth. `whisker-sim --help` lists options. */
struct WhiskerSimApp
{
	static int main(int argc, char** argv);
};
}  // namespace whiskermap::cli
