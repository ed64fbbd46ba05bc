#pragma once
#include <whiskermap/eval/EvalOptions.h>
#include <whiskermap/eval/TableCsv.h>
#include <whiskermap/world/Table.h>

#include <array>
#include <string>
#include <vector>

namespace whiskermap::eval
{
/** Reliability of reported existence probabilities (doc/evaluation.md, "Calibration"): objects
 *  binned by their existence into 10 equal bins [0, 0.1), ..., [0.9, 1] and, per bin, how
 *  many, their mean existence and the fraction of them that are real; the expected
 *  calibration error ECE = sum_b (n_b / N) |real_b - conf_b|. Calibrations of several runs
 *  add up (the bins' sums pool exactly). */
class Calibration
{
   public:
	static constexpr size_t BINS = 10;
	struct Bin
	{
		size_t count = 0;  ///< objects in the bin
		double sumExistence = 0;  ///< their summed existence
		size_t real = 0;  ///< of them, matched to a true object
		/** Mean existence (conf_b); NaN when empty. */
		double meanExistence() const;
		/** Fraction real (real_b); NaN when empty. */
		double fractionReal() const;
	};

	/** One object with reported existence in [0, 1] (else core::Error); bin
	 *  min(floor(10 p), 9). */
	void add(double existence, bool real);
	/** Pools another calibration's objects into this one. */
	void add(const Calibration& other);

	/** The objects of one map (map_tables.csv and map_candidates.csv pooled by the caller)
	 *  matched one-to-one against the true objects by MapEvaluation (same gates and classes);
	 *  a matched object is real. */
	static Calibration of(
		const std::vector<world::Table>& truth, const std::vector<TableCsv::MapRow>& objects,
		const EvalOptions& opts, bool hasClass = false);

	const std::array<Bin, BINS>& bins() const { return m_bins; }
	/** Objects added (N). */
	size_t count() const;
	/** Objects that were real. */
	size_t real() const;
	/** sum_b (n_b / N) |real_b - conf_b|; NaN when no object was added. */
	double ece() const;

	/** `{ "objects": N, "real": .., "ece": .., "bins": [ {"lo", "hi", "count",
	 *  "mean_existence", "fraction_real"}, ... ] }` at `indent` spaces (no final newline). */
	std::string toJson(int indent) const;
	/** A few lines: the bin table and the ECE. */
	std::string toText() const;

   private:
	std::array<Bin, BINS> m_bins{};
};
}  // namespace whiskermap::eval
