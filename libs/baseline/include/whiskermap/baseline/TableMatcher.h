#pragma once
#include <whiskermap/baseline/Contact.h>
#include <whiskermap/baseline/FreeSpace.h>
#include <whiskermap/baseline/LegFit.h>
#include <whiskermap/baseline/TBaselineParams.h>
#include <whiskermap/baseline/TableEstimate.h>

#include <vector>

namespace whiskermap::baseline
{
/** Groups legs into known tables (doc/baseline.md, steps 4-6). Every pair of legs whose
 *  spacing matches a side or the diagonal of the known table, and whose yaws agree with the
 *  pair's direction, proposes the tables that would have them at two corners; each proposal
 *  collects the other legs found at its corners and is fitted to its legs' centres. A
 *  proposal with an untouched corner that the whiskers swept through (FreeSpace) is dropped.
 *  Greedy: the proposal with the most legs (then the least cost) is accepted and fitted to
 *  all its contacts, its legs are taken, proposals overlapping it are dropped, and so on. */
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
	std::vector<TableEstimate> propose(const std::vector<bool>& taken) const;
	/** Fills the empty corners with untaken legs found there, nearest first. */
	void collect(TableEstimate& t, const std::vector<bool>& taken, double slack) const;
	/** Fits the pose to the legs' centres (weighted by their covariances) and yaws. */
	void fitToLegs(TableEstimate& t) const;
	bool legFits(const TableEstimate& t, int corner, int leg, double slack) const;
	bool contradictedByFreeSpace(const TableEstimate& t) const;
	double legSigma(int leg) const;

	const std::vector<Contact>& m_contacts;
	const std::vector<LegFit>& m_legs;
	const FreeSpace& m_free;
	const TBaselineParams& m_p;
	mutable size_t m_proposals = 0, m_contradicted = 0;
};
}  // namespace whiskermap::baseline
