#pragma once
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/maps/CMultiMetricMapPDF.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/slam/PathTree.h>
#include <whiskermap/slam/SampledProposal.h>
#include <whiskermap/slam/TSlamParams.h>

#include <functional>
#include <optional>
#include <vector>

namespace whiskermap::slam
{
/** Tactile SLAM with MRPT's own Rao-Blackwellised particle filter: a CMultiMetricMapPDF
 *  whose particles each hold a CMultiMetricMap with a CHierarchicalObjectMap. Per sweep,
 *  SampledProposal moves and weighs the particles (with one motion sample per particle,
 *  MRPT's standard proposal, draw for draw, as CParticleFilter runs it: particles move by
 *  samples of the odometry increment's Gaussian and are weighted by the map's sweep
 *  likelihood), then every particle's map inserts the sweep at its pose.
 *
 *  With one motion sample, each step is what CMetricMapBuilderRBPF::processActionObservation
 *  does with debugForceInsertion and zero distance thresholds (the same action, the same draws, the
 *  same insertions), minus the builder's two stores that grow with the run: its CSimpleMap
 *  of every sensory frame with every particle's pose at it, and every particle's whole path
 *  (CRBPFParticleData::robotPath, copied at each resampling). Here a particle keeps only its
 *  latest pose and the paths are a PathTree of shared ancestors, so memory is the particles'
 *  maps plus about one pose per step (doc/slam.md, "Memory").
 *
 *  Sweeps come one by one with the odometry pose the rawlog gives them (either layout); the
 *  increment between consecutive odometry poses becomes a CActionRobotMovement2D with the
 *  motion model of TSlamParams::motion. The first sweep's odometry pose is the known start.
 *  Every sweep is localised and inserted (no distance thresholds), so the path has one pose
 *  per sweep. When the normalised effective sample size after a sweep falls below
 *  resample_ess, the particles are resampled before the next one, and their weights made
 *  equal (MRPT 2.5.8's performResampling leaves them unequal: resample()).
 *
 *  Odometry told exact (TSlamParams::exactMotion) runs one particle: any more would repeat
 *  it, path and map.
 *
 *  Reproducible: the constructor seeds MRPT's global random generator with params.seed
 *  (every draw of the filter comes from it; the maps' samplers have their own seeds). */
class RbpfSlam
{
   public:
	struct TStep
	{
		double ms = 0;  ///< wall time of the filter step (prediction, weights, resampling, map updates)
		double ess = 1;  ///< normalised effective sample size before resampling, in (0, 1]
		bool resampled = false;  ///< ESS below resample_ess: the particles are resampled before the next sweep
	};

	/** Metres: two legs whose centres are this close are counted as beside each other in
	 *  TMapTotals (two leg widths of the shipped model; a table's own legs stand 0.6 m apart or more). */
	static constexpr double BESIDE = 0.1;
	/** What the particles' maps hold, summed over the particles (what their memory grows with). */
	struct TMapTotals
	{
		size_t tables = 0, legs = 0, walls = 0;
		size_t legsWithoutTable = 0;  ///< legs no table stands on
		size_t legsBeside = 0;  ///< legs with another leg's centre within BESIDE (LastingState::legsBeside)
		size_t explained = 0, unexplained = 0;  ///< explicit contacts with a leg, and without
		size_t sweptChunks = 0, sharedChunks = 0;  ///< swept-grid chunks, and those shared with a copy
		size_t lastingChunks = 0, lastingShared = 0;  ///< the lasting states' chunks (LastingState::sharing), and those shared
	};

	RbpfSlam(const TSlamParams& params, const mrpt::maps::TSetOfMetricMapInitializers& maps);

	/** One filter step on a sweep; returns its figures. */
	const TStep& step(const obs::RawlogReader::Sweep& sweep);
	/** Resamples the particles now (step() does it before a sweep when the ESS after the
	 *  previous one fell below resample_ess): MRPT's resampling method, then equal weights.
	 *  A parent drawn more than once is copied by cloning its maps (copy constructors), not
	 *  by MRPT's serializing CMultiMetricMap copy. */
	void resample();

	size_t stepCount() const { return m_stepCount; }
	/** The latest step's figures (throws before the first step). */
	const TStep& lastStep() const;
	/** Hands `sink` the path's poses that every particle agrees on (their common ancestors'
	 *  poses, which no resampling can change), oldest first, one per sweep, and forgets them.
	 *  Cheap to call after every step: it walks the paths only when they have doubled since
	 *  it last did (amortised constant time). Returns the count handed over. */
	size_t settle(const std::function<void(const mrpt::poses::CPose2D&)>& sink);
	/** The most path poses kept (default 2^21, 64 MB): when the lineages have not met by
	 *  resampling and settle() finds more alive, every particle's past beyond
	 *  limit / (4 x particles) sweeps becomes the best particle's (PathTree::mergeOlderThan),
	 *  so that memory stays bounded even with resample_ess = 0. */
	void setPathLimit(size_t poses) { m_pathLimit = poses; }
	/** Sweeps whose poses settle() has handed over. */
	size_t settledSweeps() const;
	/** The path of the particle with the highest weight: one pose per sweep after those
	 *  settled (all of them when settle() is never called). */
	std::vector<mrpt::poses::CPose2D> bestPath() const;
	/** The particles' maps' contents, summed (walks every particle's contacts). */
	TMapTotals mapTotals() const;
	/** That particle's map. */
	const maps::CHierarchicalObjectMap& bestMap() const;
	const mrpt::maps::CMultiMetricMapPDF& particles() const { return m_pdf; }
	/** Every particle's path. */
	const PathTree& paths() const { return m_paths; }

   private:
	size_t bestParticle() const;

	TSlamParams m_params;
	mrpt::maps::CMultiMetricMapPDF m_pdf;
	SampledProposal m_proposal;
	PathTree m_paths;
	std::optional<mrpt::poses::CPose2D> m_lastOdometry;
	TStep m_last;
	size_t m_stepCount = 0;
	size_t m_settleAt = 0;  ///< settle() walks the paths when they hold this many nodes
	size_t m_pathLimit = size_t(1) << 21;
	bool m_resamplePending = false;
};
}  // namespace whiskermap::slam
