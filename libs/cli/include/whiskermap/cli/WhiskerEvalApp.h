#pragma once

namespace whiskermap::cli
{
/** The whisker-eval command line: score a whisker-map result (consolidated map, optionally
 *  the per-pose MAP tables and the rawlog they came from) against the true world.
 *  `whisker-eval --help` lists options; doc/evaluation.md defines every figure. */
struct WhiskerEvalApp
{
	static int main(int argc, char** argv);
};
}  // namespace whiskermap::cli
