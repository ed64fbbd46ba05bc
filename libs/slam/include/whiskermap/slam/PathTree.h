#pragma once
#include <mrpt/math/TPose2D.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace whiskermap::slam
{
/** Every particle's path of a particle filter, as a tree of shared ancestors.
 *
 *  Resampling copies particles, so after a few steps most particles descend from a few
 *  ancestors and share the start of their paths. Kept as one list per particle (as MRPT's
 *  CRBPFParticleData::robotPath is), the paths take particles x steps poses and every
 *  resampling copies them; here each pose is a node that points at the pose before it and
 *  counts the nodes and particles that point at it, and a node nobody points at is freed at
 *  once. The nodes alive are the distinct lineages back to the particles' common ancestor,
 *  then that ancestor's single path, which settle() hands over and frees: particles x the
 *  lineages' depth, whatever the run's length. Nodes live in one vector with a free list; freeing
 *  walks up iteratively (no recursion however long the path). */
class PathTree
{
   public:
	/** `particles` paths, each holding only `start`. */
	void reset(size_t particles, const mrpt::math::TPose2D& start);

	/** Appends `pose` to particle `i`'s path. */
	void extend(size_t i, const mrpt::math::TPose2D& pose);

	/** After resampling: particle j continues the path of particle parents[j] (as
	 *  CParticleFilterCapable::performSubstitution copies particles). Any count of parents. */
	void resample(const std::vector<size_t>& parents);

	/** Particle `i`'s path, from the start (or the first pose not yet settled) to its
	 *  latest pose. */
	std::vector<mrpt::math::TPose2D> path(size_t i) const;

	/** Hands `sink` the poses every particle's path holds before the particles' latest
	 *  common ancestor (the settled trunk: no resampling can change it), oldest first, and
	 *  frees them; path() then starts at that ancestor. Costs one walk up particle 0's path.
	 *  Returns how many poses it handed over. */
	size_t settle(const std::function<void(const mrpt::math::TPose2D&)>& sink);
	/** Every particle's poses more than `lag` steps before its latest become particle `i`'s
	 *  (the particles' paths must be equally long): the paths then meet `lag` + 1 steps back,
	 *  and what only other particles held there is freed. A fixed-lag cut for filters whose
	 *  lineages do not meet by resampling. */
	void mergeOlderThan(size_t i, size_t lag);
	/** Poses handed over by settle() since reset(). */
	size_t settled() const { return m_settled; }

	size_t particles() const { return m_leaf.size(); }
	/** Nodes alive: the memory the paths take, in poses. */
	size_t nodes() const { return m_nodes.size() - m_free.size(); }

   private:
	static constexpr uint32_t NONE = UINT32_MAX;
	struct Node
	{
		mrpt::math::TPose2D pose;
		uint32_t parent = NONE;
		uint32_t refs = 0;  ///< children plus particles whose latest pose this is
	};

	uint32_t make(const mrpt::math::TPose2D& pose, uint32_t parent);
	void release(uint32_t n);

	std::vector<Node> m_nodes;
	std::vector<uint32_t> m_free;
	std::vector<uint32_t> m_leaf;  ///< each particle's latest pose
	size_t m_settled = 0;
};
}  // namespace whiskermap::slam
