#pragma once
#include <whiskermap/eval/EvalOptions.h>
#include <whiskermap/eval/Identifiability.h>
#include <whiskermap/eval/MapEvaluation.h>
#include <whiskermap/eval/PerPoseEvaluation.h>

#include <optional>
#include <string>

namespace whiskermap::eval
{
/** Everything whisker-eval reports, as a short human table or one JSON object with a fixed
 *  key order and fixed number formatting (format and example: doc/evaluation.md). */
struct EvalReport
{
	EvalOptions options;
	MapEvaluation map;  ///< the consolidated map
	std::optional<Identifiability> identifiability;  ///< when a rawlog was given
	std::optional<PerPoseEvaluation> perPose;  ///< when per-pose tables were given

	/** `{ "precision": ..., ..., "per_pose": { ... } }`, ending in a newline. Numbers have six
	 *  decimals (counts none); an undefined figure (no matches) is null. */
	std::string toJson() const;
	/** A few lines for a terminal. */
	std::string toText() const;
};
}  // namespace whiskermap::eval
