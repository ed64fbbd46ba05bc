#pragma once

namespace whiskermap::cli
{
/** The whisker-baseline command line: the plain batch geometric fit (baseline::BatchFit) over
 *  every contact of a rawlog, written as OUTDIR/map_tables.csv (the columns of whisker-map's,
 *  so whisker-eval scores it) and OUTDIR/baseline_legs.csv. `whisker-baseline --help` lists
 *  the options; doc/baseline.md describes the method. */
struct WhiskerBaselineApp
{
	static int main(int argc, char** argv);
};
}  // namespace whiskermap::cli
