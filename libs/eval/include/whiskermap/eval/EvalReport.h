#pragma once
#include <whiskermap/eval/Calibration.h>
#include <whiskermap/eval/EvalOptions.h>
#include <whiskermap/eval/Identifiability.h>
#include <whiskermap/eval/MapEvaluation.h>
#include <whiskermap/eval/PerPoseEvaluation.h>
#include <whiskermap/eval/SpreadCoverage.h>
#include <whiskermap/eval/TrajectoryEvaluation.h>
#include <whiskermap/eval/WallEvaluation.h>

#include <optional>
#include <string>

namespace whiskermap::eval
{
/** Everything whisker-eval reports, as a short human table or one JSON object with a fixed
 *  key order and fixed number formatting (format and example: doc/evaluation.md). */
struct EvalReport
{
	EvalOptions options;
	std::optional<MapEvaluation> map;  ///< the consolidated map, when one was given
	std::optional<size_t> objectsOnWalls;  ///< the map's objects on a true wall (ObjectsOnWalls)
	std::optional<Identifiability> identifiability;  ///< when a rawlog was given (with a map)
	std::optional<PerPoseEvaluation> perPose;  ///< when per-pose tables were given
	std::optional<TrajectoryEvaluation> trajectory;  ///< when an estimated path was given
	std::optional<WallEvaluation> walls;  ///< when estimated walls were given
	std::optional<Calibration> calibration;  ///< existence calibration (--calibration)
	std::optional<SpreadCoverage> spread;  ///< pose spread coverage, when the map reports spreads

	/** `{ "precision": ..., ..., "per_pose": { ... }, "trajectory": { ... } }`, ending in a
	 *  newline; the map's figures only with a map. Numbers have six decimals (counts none); an
	 *  undefined figure (no matches, no RPE segment) is null. */
	std::string toJson() const;
	/** A few lines for a terminal. */
	std::string toText() const;

   private:
	std::string mapText() const;
};
}  // namespace whiskermap::eval
