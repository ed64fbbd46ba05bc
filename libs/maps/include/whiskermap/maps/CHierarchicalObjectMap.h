#pragma once
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/maps/CMetricMap.h>
#include <mrpt/math/TBoundingBox.h>
#include <whiskermap/inference/BlackboardSampler.h>
#include <whiskermap/inference/SamplerParams.h>
#include <whiskermap/inference/ShapeletMemory.h>
#include <whiskermap/inference/SweptMemory.h>
#include <whiskermap/maps/LastingMap.h>
#include <whiskermap/maps/StepSolver.h>
#include <whiskermap/maps/SweepLikelihood.h>
#include <whiskermap/maps/TMappedObject.h>
#include <whiskermap/maps/TPoseRecord.h>
#include <whiskermap/maps/TableConsolidator.h>
#include <whiskermap/model/ModelParams.h>

#include <array>
#include <functional>
#include <memory>
#include <mutex>

namespace whiskermap::maps
{
/** A hierarchical object map built from whisker contacts: an MRPT metric map (CMetricMap),
 *  created by name ("hierarchicalObjectMap") from a CMultiMetricMap .ini, so it plugs into
 *  MRPT's pipelines and particle filters. Two modes (insertOpts `mode`):
 *
 *  - `lasting` (default): one hierarchical state fuses every contact ever inserted
 *    (LastingMap): insertObservation(CObservationWhiskerContacts, robot pose) explains the
 *    sweep's contacts in the context of the map around them (annealed blackboard sampler,
 *    Fox & Prescott's Algorithm 1, run locally); each table carries its posterior existence
 *    probability; the map is the tables with existence >= min_existence.
 *  - `per_pose` (the paper's): one sampler step per sweep on the working memory of the most
 *    recent shapelets, its MAP tables recorded per pose (the paper's figs. 5-7) and merged
 *    into a consolidated map by votes (TableConsolidator).
 *
 *  computeObservationLikelihood(sweep, pose) casts each whisker against the map's legs
 *  and weighs it by where the map explored (SweepLikelihood, SweptGrid). Options and their .ini sections: doc/map-plugin.md, config/whisker-map.ini. */
class CHierarchicalObjectMap : public mrpt::maps::CMetricMap
{
	DEFINE_SERIALIZABLE(CHierarchicalObjectMap, whiskermap::maps)

   public:
	/** [<prefix>_insertOpts]: working memory, seeding, consolidation. */
	struct TInsertionOptions : public mrpt::config::CLoadableOptions
	{
		enum class TMode : uint8_t
		{
			Lasting,  ///< one lasting state fusing every contact (LastingMap)
			PerPose  ///< the paper's independent steps on the working memory, then votes
		};
		TMode mode = TMode::Lasting;
		LastingMap::TOptions lasting;  ///< the lasting mode's options
		size_t memory_size = 7;  ///< per-pose mode: shapelets in working memory (paper: 7)
		uint64_t seed = 1;  ///< step k uses a seed derived from (seed, k)
		/** Raise the model's sigma_r, sigma_theta, sigma_tau to the noise each sweep reports
		 *  when it is larger (the paper's eq. 7 uses the sensor noise), scaling parent_gate
		 *  with sigma_r; the per-pose mode raises sigma_corner (eq. 6) with sigma_r, the
		 *  lasting mode does not. */
		bool use_sensor_noise = true;
		/** Keep every per-pose record and shapelet (poseRecords(), shapelets()). Off, memory
		 *  stays bounded by the map, whatever the trajectory's length: a streaming consumer
		 *  reads lastRecord() and lastInput() after each insertion instead. */
		bool keep_history = true;
		/** Edge (metres) of the swept grid's cells: where the map explored, its free space and
		 *  where it was touched (model::SweptGrid; the sweep likelihood's eqs. L1-L5). */
		double swept_cell = 0.1;
		/** Record each sweep in the swept grid. Off, the grid stays empty: for a map whose
		 *  likelihood (use_swept_grid) and model (free_space) do not read it, such as a particle
		 *  filter's maps (whisker-slam turns it off there); neither may then be on. */
		bool record_swept = true;
		TableConsolidator::TOptions consolidation;
		void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
		void dumpToTextStream(std::ostream& out) const override;
	};

	/** [<prefix>_likelihoodOpts]: the sweep likelihood and which objects it uses. */
	struct TLikelihoodOptions : public mrpt::config::CLoadableOptions
	{
		SweepLikelihood::TOptions sweep;
		/** Lasting mode: the map holds the tables at least this probable (0.5: those more
		 *  likely there than not). */
		double min_existence = 0.5;
		uint32_t min_support = 3;  ///< per-pose mode: objects supported by fewer poses are ignored
		/** Metres each mapped wall at least wall_extension_min_length long is lengthened by at
		 *  both ends in the likelihood (a wall is straight: a contact a little past its last
		 *  one is predicted on its line, not unexplained); 0: walls as mapped. */
		double wall_extension = 0;
		double wall_extension_min_length = 0.2;  ///< metres: shorter walls (a leg's face) keep their length
		/** Lasting mode: no two mapped tables overlap or touch (eq. 16 made hard, the per-pose
		 *  map's rule): taken most contacts first, a table whose footprint meets one already
		 *  taken is a candidate instead. Off: eq. 16 stays the model's soft factor. */
		bool disjoint_tables = false;
		void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
		void dumpToTextStream(std::ostream& out) const override;
	};

	/** [<prefix>_creationOpts] (besides MRPT's generic keys): 3-D drawing and exports. */
	struct TRenderOptions
	{
		double table_height = 0.7;  ///< metres, for 3-D views and exports
		double top_thickness = 0.03;  ///< table-top slab, metres
		double octomap_resolution = 0.02;  ///< voxel edge of the OctoMap export, metres
	};

	CHierarchicalObjectMap();

	TInsertionOptions insertionOptions;
	TLikelihoodOptions likelihoodOptions;
	TRenderOptions renderOptions;
	model::ModelParams modelParams;  ///< [<prefix>_model]
	inference::SamplerParams samplerParams;  ///< [<prefix>_sampler]

	bool lasting() const { return insertionOptions.mode == TInsertionOptions::TMode::Lasting; }

	/** The map: lasting mode, the tables with existence >= min_existence (with
	 *  disjoint_tables, none overlapping one with more contacts); per-pose mode, the
	 *  consolidated objects with support >= min_support, best supported first, leaving out
	 *  any that overlaps one already taken (eq. 16). What the likelihood, the pictures, the
	 *  exports and the evaluation use, and what map_tables.csv holds. With `spreads` (lasting
	 *  mode only), each with its pose spread (LastingMap::poseSpread, seeded with its row:
	 *  a short chain each, as map_tables.csv reports it). */
	std::vector<TMappedObject> mapObjects(bool spreads = false) const;
	/** Everything else the map considered: tables below min_existence (or left out by
	 *  disjoint_tables), objects below min_support or overlapping a better one
	 *  (map_candidates.csv); `spreads` as above. */
	std::vector<TMappedObject> candidateObjects(bool spreads = false) const;
	/** Lasting mode with the model's walls: the walls with existence >= min_existence
	 *  (map_walls.csv); empty otherwise. */
	std::vector<model::LastingState::StoredWall> mapWalls() const;
	/** The tables of mapObjects(). */
	std::vector<world::Table> mapTables() const;
	/** The lasting state (lasting mode). */
	const LastingMap& lastingMap() const { return m_lasting; }
	/** What the last lasting insertion did. */
	const LastingMap::TStats& lastLastingStats() const { return m_lastLasting; }
	/** Where the map explored: per coarse cell, the sweeps that crossed it free or touched in
	 *  it (both modes; shared between copies, copy-on-write). */
	const model::SweptGrid& sweptGrid() const { return m_sweptGrid; }

	/** Per-pose mode: per inserted sweep, in order (empty unless insertionOptions.keep_history). */
	const std::vector<TPoseRecord>& poseRecords() const { return m_poses; }
	/** The record and the input of the last inserted sweep. */
	const TPoseRecord& lastRecord() const { return m_lastRecord; }
	const TStepInput& lastInput() const { return m_lastInput; }
	/** Sweeps inserted so far. */
	uint64_t steps() const { return m_steps; }
	/** Per-pose mode: the consolidated objects (all of them). */
	const std::vector<TMapObject>& objects() const { return m_consolidator.objects(); }
	/** Every shapelet inserted, world frame (empty unless insertionOptions.keep_history). */
	const std::vector<obs::Shapelet>& shapelets() const { return m_shapelets; }
	/** Totals over all steps of proposals and acceptances per move type. */
	const std::array<uint64_t, inference::MOVE_COUNT>& proposed() const { return m_proposed; }
	/** The same counts per move type (the sampler's MoveRegistry lines), summed over the run. */
	const std::vector<inference::MoveTally>& moveTypes() const { return m_moveTypes; }
	const std::array<uint64_t, inference::MOVE_COUNT>& accepted() const { return m_accepted; }

	/** Per-pose mode: the last step's full result (MAP blackboard, snapshot if asked for). */
	const inference::StepResult& lastStep() const { return m_lastStep; }

	/** Per-pose mode: insertObservation in two halves, for callers that solve steps
	 *  elsewhere (in parallel, with one StepSolver per thread): prepareStep() takes the sweep
	 *  into the working memory and the swept grid and fixes the step's input; integrateStep() records the solved
	 *  step and consolidates it. Calls must alternate, in sweep order. */
	TStepInput prepareStep(const obs::CObservationWhiskerContacts& sweep, const mrpt::poses::CPose2D& pose);
	void integrateStep(TStepInput in, inference::StepResult result);
	/** Ask the next insertions for a blackboard snapshot at this schedule index (-1: none). */
	void setSnapshotTemperature(int index) { m_snapshotTemperature = index; }
	/** Lasting mode: anneals the contacts of the sweeps inserted but not annealed yet
	 *  (insertOpts batch_sweeps > 1; doc/map-plugin.md), with the last sweep's noise model.
	 *  Call it before reading a finished map; nothing to do when none are pending. */
	void annealPending();

	/** A model table as a full table of the known size, yaw in (-90, 90] degrees (it is the
	 *  same table turned by 180). */
	world::Table toWorldTable(const model::Table& t) const;
	/** Per-pose mode: indices of the objects in the map (see mapObjects()). */
	std::vector<size_t> supported() const;
	/** The legs of mapTables() and the walls of mapWalls(), as solids: what the sweep likelihood
	 *  predicts contacts on (cached until the map changes; thread-safe). */
	const std::vector<world::Obstacle>& mappedSolids() const;

	// See base class docs
	bool isEmpty() const override;
	void saveMetricMapRepresentationToFile(const std::string& prefix) const override;
	std::string asString() const override;
	void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;
	/** Shapelets and mapped tables (up to the table height). */
	mrpt::math::TBoundingBoxf boundingBox() const;

   protected:
	void internal_clear() override;
	bool internal_insertObservation(
		const mrpt::obs::CObservation& obs,
		const std::optional<const mrpt::poses::CPose3D>& robotPose) override;
	double internal_computeObservationLikelihood(
		const mrpt::obs::CObservation& obs, const mrpt::poses::CPose3D& takenFrom) const override;
	bool internal_canComputeObservationLikelihood(const mrpt::obs::CObservation& obs) const override;

   private:
	std::vector<TPoseRecord> m_poses;
	TableConsolidator m_consolidator;
	LastingMap m_lasting;
	LastingMap::TStats m_lastLasting;
	model::SweptGrid m_sweptGrid;
	std::vector<obs::Shapelet> m_shapelets;
	inference::ShapeletMemory m_memory;
	/** The working memory's swept free space (model free_space on; not serialized: a reloaded
	 *  map starts it empty). */
	inference::SweptMemory m_sweptMemory;
	std::array<uint64_t, inference::MOVE_COUNT> m_proposed{}, m_accepted{};
	std::vector<inference::MoveTally> m_moveTypes;
	inference::StepResult m_lastStep;
	TPoseRecord m_lastRecord;
	TStepInput m_lastInput;
	uint64_t m_steps = 0;
	/** The sensor noise the last lasting insertion stated (zeros: none yet): the pose spreads
	 *  score the contacts with its model (modelFor), as the reported poses were fitted. */
	obs::TSensorNoise m_lastNoise;
	int m_snapshotTemperature = -1;
	StepSolver m_solver;
	/** mappedSolids() cache; a copy starts empty (invalid). */
	struct LegCache
	{
		std::vector<world::Obstacle> legs;
		bool valid = false;
		uint32_t support = 0;  ///< the thresholds the legs were selected with
		double existence = -1;
		double extension = -1, extensionMin = -1;  ///< and the walls lengthened with
		bool disjoint = false;
		std::mutex mutex;
		LegCache() = default;
		LegCache(const LegCache&) {}
		LegCache& operator=(const LegCache&)
		{
			invalidate();
			return *this;
		}
		void invalidate()
		{
			const std::lock_guard<std::mutex> lock(mutex);
			valid = false;
		}
	};
	mutable LegCache m_legCache;
	/** The model a sweep with this noise is scored with. */
	model::ModelParams modelFor(const obs::TSensorNoise& noise) const;
	/** The sweep's free space and contacts into the swept grid. */
	void recordSwept(
		const mrpt::poses::CPose2D& pose, const std::vector<obs::Shapelet>& shapelets,
		const std::vector<obs::SweptSector>& sectors);
	/** Lasting mode: one insertion. */
	void insertLasting(const obs::CObservationWhiskerContacts& sweep, const mrpt::poses::CPose2D& pose);
	/** A consolidated object (per-pose mode) or a lasting table, as written out. */
	TMappedObject mapped(const TMapObject& o) const;
	TMappedObject mapped(model::Id table) const;
	/** Of the items `order` lists (best first), those whose footprint meets none kept before
	 *  (eq. 16 made hard), in that order. */
	static std::vector<size_t> disjoint(
		const std::vector<size_t>& order, const std::function<world::Obstacle(size_t)>& footprint);
	/** The lasting tables in the map (`inMap`: existence at least min_existence and, with
	 *  disjoint_tables, kept by that rule) or not, in store order, with their pose spreads if
	 *  asked for. */
	std::vector<TMappedObject> lastingObjects(bool inMap, bool spreads) const;

	MAP_DEFINITION_START(CHierarchicalObjectMap)
	TInsertionOptions insertionOptions;
	TLikelihoodOptions likelihoodOptions;
	TRenderOptions renderOptions;
	model::ModelParams modelParams;
	inference::SamplerParams samplerParams;
	/** Whether the map's likelihood (use_swept_grid) or model (free_space) reads the swept grid. */
	bool sweptGridRead() const { return likelihoodOptions.sweep.use_swept_grid || modelParams.free_space; }
	MAP_DEFINITION_END(CHierarchicalObjectMap)
};
}  // namespace whiskermap::maps
