#pragma once

namespace whiskermap::cli
{
/** The whisker-import command line: a text contact log (doc/formats.md) to a rawlog of
 *  whisker sweeps, given the robot's whisker geometry. `whisker-import --help` lists options. */
struct WhiskerImportApp
{
	static int main(int argc, char** argv);
};
}  // namespace whiskermap::cli
