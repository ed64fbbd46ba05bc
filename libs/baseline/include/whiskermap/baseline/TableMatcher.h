#pragma once
#include <whiskermap/baseline/Contact.h>
#include <whiskermap/baseline/FreeSpace.h>
#include <whiskermap/baseline/LegFit.h>
#include <whiskermap/baseline/TBaselineParams.h>
#include <whiskermap/baseline/TableEstimate.h>

#include <map>
#include <optional>
#include <vector>

namespace whiskermap::baseline
{
/** Groups legs into known tables (doc/baseline.md, steps 4-6). Every pair of legs whose
 *  spacing matches a side or the diagonal of the known table, and whose yaws agree with the
 *  pair's direction, proposes the tables that would have them at two corners; each proposal
 *  collects the other legs found at its corners and is fitted to its legs' centres. A
 *  proposal with an untouched corner that the whiskers swept through (FreeSpace) is dropped.
 *  Greedy: the proposal with the most legs (then the least cost) is accepted and fitted to
 *  all its contacts, its legs are taken, proposals that considered them are rebuilt without
 *  them, proposals overlapping it are dropped, and so on. */
class TableMatcher
{
   public:
	TableMatcher(
		const std::vector<Contact>& contacts, const std::vector<LegFit>& legs, const FreeSpace& free,
		const TBaselineParams& p);

	std::vector<TableEstimate> run();

	size_t proposals() const { return m_proposals; }  ///< tables proposed, over all rounds
	size_t contradicted() const { return m_contradicted; }  ///< of which dropped by free space

   private:
	/** Leg a at corner ka, leg b at corner kb: a way two legs could belong to one table. */
	struct Seed
	{
		int a, b, ka, kb;
	};
	/** Every seed whose leg spacing matches its corners' spacing. */
	std::vector<Seed> seeds() const;
	/** The table a seed proposes, with the legs it considered (in `used`), unless its legs'
	 *  yaws disagree, fewer than two legs fit, or free space contradicts it. */
	std::optional<TableEstimate> propose(const Seed& s, const std::vector<bool>& taken, std::vector<int>& used) const;
	/** Fills the empty corners with untaken legs found there, nearest first. */
	void collect(TableEstimate& t, const std::vector<bool>& taken, double slack) const;
	/** Fits the pose to the legs' centres (weighted by their covariances) and yaws. */
	void fitToLegs(TableEstimate& t) const;
	bool legFits(const TableEstimate& t, int corner, int leg, double slack) const;
	bool contradictedByFreeSpace(const TableEstimate& t) const;
	using Cell = std::pair<long, long>;
	Cell cell(const Eigen::Vector2d& c) const;
	/** Legs in the grid cells around `c` (a table's diagonal apart at most), sorted. */
	std::vector<int> legsNear(const Eigen::Vector2d& c) const;

	const std::vector<Contact>& m_contacts;
	const std::vector<LegFit>& m_legs;
	const FreeSpace& m_free;
	const TBaselineParams& m_p;
	double m_cell;  ///< grid cell: the table's diagonal + 20 cm
	std::vector<double> m_sigma;  ///< per leg: largest std-dev of its centre, with the floor
	std::map<Cell, std::vector<int>> m_grid;  ///< legs per cell
	mutable size_t m_proposals = 0, m_contradicted = 0;
};
}  // namespace whiskermap::baseline
