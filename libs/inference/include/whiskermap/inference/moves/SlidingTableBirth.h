#pragma once
#include <whiskermap/inference/moves/TableBirthDeath.h>
#include <whiskermap/inference/moves/TableRefit.h>

#include <vector>

namespace whiskermap::inference::moves
{
/** A table for leg l whose legs slide to its corners (doc/sampler.md, "Moves"): the birth of
 *  TableBirthDeath (adopting the same legs), then, in the same move, TableRefit of the new
 *  table (its legs refit to their contacts and corners, the table to its legs, twice). A leg
 *  whose contacts pin it only across a face stands anywhere along that face: the plain birth
 *  fits the table between two such legs, each a few cm from its corner (eq. 6), and loses to
 *  no table; slid to the corners, they win. Judged on the whole change (eq. 20 of each step).
 *  Deterministic given the table, with no reverse (logReverse = -inf): the polish offers it
 *  for every pair table (tablesForPairs) of a leg without a table. */
class SlidingTableBirth
{
   public:
	explicit SlidingTableBirth(const model::ModelParams& p) : m_birth(p) {}

	/** The sliding birth of table `chosen` for leg l (a pair table of l). */
	Proposal propose(MoveContext& ctx, model::Id l, const model::Table& chosen);
	void finish(MoveContext& ctx, bool accepted);
	/** Fills `out` with the tables offered for leg l: its pair tables (l and another leg at
	 *  two corners) of each class whose texture is within MAX_TEXTURE_SIGMAS sigma_tau of
	 *  l's, with l within MAX_SLIDE_WIDTHS leg widths of its corner; none when l has a table
	 *  or when corners bind legs tighter than readings (the parent move then refits every
	 *  leg it adopts itself). */
	static void candidates(const MoveContext& ctx, model::Id l, std::vector<model::Table>& out);

	/** Wall contacts (texture 0.3 against the tables' 0.7 in the paper arena: 4 sigma_tau)
	 *  line up in pairs at a table's corner distances and slide along the wall: offered for
	 *  them, the move was proposed 372,860 times in the very noisy lasting map, accepted 8
	 *  times, and doubled the map's time (doc/sampler.md). */
	static constexpr double MAX_TEXTURE_SIGMAS = 3;
	/** A slide along a face makes up a few cm (the missed tables of the oracle agreement test:
	 *  2-4 cm a leg); the pair tables' gate (2 parent gates of mismatch) is far wider at
	 *  very noisy readings, where the slides built tables of legs of two neighbouring tables:
	 *  the per-pose map of very-noisy.rawlog got a spurious table on 3 of 4 seeds (F1 0.83-0.92)
	 *  offering every pair table, on 1 of 4 at 1 leg width (257/260 agreement), on none at 0.75
	 *  (256/260; 0.5: 253/260). */
	static constexpr double MAX_SLIDE_WIDTHS = 0.75;

   private:
	TableBirthDeath m_birth;
	TableRefit m_refit;
	bool m_refitted = false;  ///< the refit ran (undone before the birth on rejection)
};
}  // namespace whiskermap::inference::moves
