#pragma once
#include <whiskermap/eval/EvalOptions.h>
#include <whiskermap/eval/TableCsv.h>
#include <whiskermap/world/Table.h>

#include <array>
#include <string>
#include <vector>

namespace whiskermap::eval
{
/** Do a map's reported pose spreads (map_tables.csv's sd_x, sd_y, sd_yaw_deg) cover the truth
 *  (doc/evaluation.md, "Pose spread")? Over the objects matched one-to-one by MapEvaluation,
 *  per axis (x, y, yaw): the fraction whose error is within one and within two reported
 *  standard deviations, and the root mean square of error / sd. A calibrated spread with
 *  Gaussian errors gives 0.68, 0.95 and 1. Coverages of several maps add up. */
class SpreadCoverage
{
   public:
	/** Per axis: x, y, yaw. */
	struct Axis
	{
		size_t within1 = 0, within2 = 0;
		double sumZ2 = 0;  ///< sum of (error / sd)^2
	};

	/** One matched object: its errors (metres, metres, radians) and reported standard
	 *  deviations (the same units); a zero sd counts as within only for a zero error. */
	void add(const std::array<double, 3>& error, const std::array<double, 3>& sd);
	void add(const SpreadCoverage& other);

	/** The matched objects of one map (rows with spreads; rows without are skipped). */
	static SpreadCoverage of(
		const std::vector<world::Table>& truth, const std::vector<TableCsv::MapRow>& rows, const EvalOptions& opts,
		bool hasClass = false);
	/** The same with the matching already made (MapEvaluation::truthMatch of `rows`' tables). */
	static SpreadCoverage of(
		const std::vector<world::Table>& truth, const std::vector<TableCsv::MapRow>& rows,
		const std::vector<int>& truthMatch);

	size_t count() const { return m_count; }
	const std::array<Axis, 3>& axes() const { return m_axes; }
	/** Fraction of the objects within `k` (1 or 2) sd on axis `a`; NaN without objects. */
	double within(size_t a, int k) const;
	/** sqrt(mean (error / sd)^2) on axis `a`; NaN without objects. */
	double rmsZ(size_t a) const;

	/** `{"objects": N, "x": {"within_1sd", "within_2sd", "rms_z"}, "y": {...}, "yaw": {...}}`. */
	std::string toJson(int indent) const;
	/** One line per axis. */
	std::string toText() const;

   private:
	size_t m_count = 0;
	std::array<Axis, 3> m_axes{};
};
}  // namespace whiskermap::eval
