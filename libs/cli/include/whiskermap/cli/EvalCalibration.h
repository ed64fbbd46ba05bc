#pragma once
#include <whiskermap/eval/Calibration.h>
#include <whiskermap/eval/SpreadCoverage.h>

#include <string>

namespace whiskermap::cli
{
/** whisker-eval's calibration inputs and picture (doc/evaluation.md, "Calibration"). */
struct EvalCalibration
{
	/** One map: map_tables.csv and, if `candidates` is not empty, map_candidates.csv pooled
	 *  (both with or both without the class column) against the world's objects. With
	 *  `spread`, the map's pose spread coverage (eval::SpreadCoverage, map_tables.csv only) is
	 *  added to it. */
	static eval::Calibration ofMap(
		const std::string& world, const std::string& map, const std::string& candidates,
		const eval::EvalOptions& opts, eval::SpreadCoverage* spread = nullptr);

	/** Many maps pooled: `list` holds one run per line, `WORLD MAP [CANDIDATES]` separated
	 *  by blanks, relative paths relative to the list's folder (blank lines and lines starting
	 *  with # are skipped). Errors name the list's
	 *  line. `spread` as for ofMap, pooled over the runs. */
	static eval::Calibration ofRuns(
		const std::string& list, const eval::EvalOptions& opts, eval::SpreadCoverage* spread = nullptr);

	/** The reliability diagram as a PNG: per existence bin a bar up to its fraction real,
	 *  a dot at (mean existence, fraction real), the diagonal of perfect calibration, and
	 *  `title` and the ECE as captions. */
	static void plot(const eval::Calibration& c, const std::string& title, const std::string& png);
};
}  // namespace whiskermap::cli
