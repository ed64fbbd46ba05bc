#pragma once
#include <whiskermap/model/Blackboard.h>

#include <vector>

namespace whiskermap::inference
{
/** The posterior existence probability of each table of a (MAP) board given all its evidence
 *  (doc/model.md, "Existence"). For table T with supported legs K (legs explaining contacts):
 *  the alternatives, given the rest of the board, are "no table" (K's legs free), T, and
 *  every rival table built from a pair of legs of K with another leg (the pair proposals of
 *  the sampler: mirror images, other corner assignments), each fitted and completed with
 *  invented legs where that pays, scored by its exact change of logJoint s (eq. 20). Then
 *    P(T) = exp(s_T) / (1 + exp(s_T) + sum_rivals exp(s_R)).
 *  Two touched legs on one side of a table give it and its mirror image 1/2 each; a third
 *  touched leg makes it certain. */
class TableExistence
{
   public:
	/** existence[t] for every live table t of `bb` (0 for unused ids). */
	std::vector<double> of(const model::Blackboard& bb);
	/** The existence of live table t of `bb`. */
	double of(const model::Blackboard& bb, model::Id t);

   private:
	/** An upper bound of the change of logJoint a table with `legs` supported legs can bring
	 *  (each exactly at its corner; the other corners missing or invented, whichever costs less). */
	static double bound(const model::ModelParams& p, size_t legs);
	/** Change of logJoint when table `t` is added to `bb` with leg `leg` and the free legs it
	 *  can reach, fitted to them (`t` leaves fitted), with invented legs at the empty corners
	 *  that pay for themselves. `bb` is left as it was. */
	double scoreRival(model::Blackboard& bb, model::Table& t, model::Id leg);

	model::Blackboard m_without{model::ModelParams{}};  ///< scratch: the board without the table
	std::vector<model::Id> m_orphans, m_adopted, m_invented;
	std::vector<model::Table> m_rivals, m_scored;
	std::vector<const model::Leg*> m_fitLegs;
	std::vector<int> m_fitCorners;
};
}  // namespace whiskermap::inference
