#pragma once
#include <whiskermap/cli/Decimator.h>
#include <whiskermap/cli/OutputDir.h>
#include <whiskermap/eval/PerPoseEvaluation.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/eval/Identifiability.h>
#include <whiskermap/maps/PerPoseCsvWriter.h>
#include <whiskermap/maps/SimpleMapWriter.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/render/TopDownImage.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace whiskermap::cli
{
/** whisker-map's outputs (doc/outputs.md), written as the sweeps stream through the map:
 *  contact drawing, robot path and contacts for the 3-D scene (evenly decimated beyond a
 *  bound) and, in the per-pose mode, per-pose rows, montage and per-pose evaluation
 *  accumulate step by step, so memory stays bounded however long the run; finish() writes
 *  the rest. */
class MapOutputs
{
   public:
	struct TSettings
	{
		std::string input, config;
		const world::World* world = nullptr;  ///< ground truth, if given
		double x0 = 0, x1 = 1, y0 = 0, y1 = 1;  ///< picture bounds, metres
		int snapshotPose = -1, snapshotTemperature = 0;
		bool quiet = false;
		bool simpleMap = false;  ///< also write map.simplemap (streamed)
		unsigned jobs = 1;
		size_t sweeps = 0;  ///< sweeps the run will give (RawlogReader::Summary), for map.simplemap
		double maxSigmaR = 0;  ///< largest sigma_r of the log, for the identifiability gate
		std::string summaryName = "summary.json";  ///< file name of the summary
	};

	/** Picture bounds: the arena when known, else the robot positions plus whisker reach. */
	static void pictureBounds(const obs::RawlogReader::Summary& in, const world::World* w, TSettings& s);

	MapOutputs(OutputDir& out, const maps::CHierarchicalObjectMap& map, const TSettings& s);

	/** After sweep `index` was inserted into the map. */
	void onStep(size_t index, const obs::RawlogReader::Sweep& sweep, double ms);
	/** Writes the remaining files; returns the text to print (evaluation table), if any. */
	std::string finish(double wallSeconds);

	size_t steps() const { return m_steps; }
	double medianMs() const;

   private:
	void drawSnapshot(size_t index);
	void writeScene(const std::string& path) const;
	void writeSummary(
		const std::string& path, double wallSeconds, size_t mapped, size_t candidates, const std::string& metricsJson) const;

	OutputDir& m_out;
	const maps::CHierarchicalObjectMap& m_map;
	TSettings m_s;
	std::optional<maps::PerPoseCsvWriter> m_perPose;  ///< per-pose mode only
	render::TopDownImage m_montage, m_contacts;
	Decimator<mrpt::poses::CPose2D> m_path{20000};
	Decimator<obs::Shapelet> m_shapelets{50000};
	std::optional<eval::PerPoseEvaluation::Accumulator> m_eval;
	std::optional<eval::Identifiability::Accumulator> m_ident;
	std::optional<maps::SimpleMapWriter> m_simpleMap;
	Decimator<double> m_ms{100000};  ///< step times (an even subset beyond 100000 steps)
	double m_totalMs = 0;
	size_t m_steps = 0, m_shapeletCount = 0, m_tables = 0, m_maxTables = 0;
	uint64_t m_visited = 0, m_board = 0, m_insertions = 0;  ///< lasting mode: local problem sizes
};
}  // namespace whiskermap::cli
