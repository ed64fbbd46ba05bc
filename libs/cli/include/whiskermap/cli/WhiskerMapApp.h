#pragma once

namespace whiskermap::cli
{
/** The whisker-map command line: run a CHierarchicalObjectMap (inside a CMultiMetricMap
 *  built from a .ini) over every whisker sweep of a rawlog and write the per-pose and
 *  consolidated maps, pictures and a summary. `whisker-map --help` lists the options;
 *  doc/outputs.md describes every output file. */
struct WhiskerMapApp
{
	static int main(int argc, char** argv);
};
}  // namespace whiskermap::cli
