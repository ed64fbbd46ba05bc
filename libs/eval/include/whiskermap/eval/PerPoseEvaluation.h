#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/eval/EvalOptions.h>
#include <whiskermap/eval/Figures.h>
#include <whiskermap/eval/FiguresMean.h>
#include <whiskermap/world/Table.h>

#include <optional>
#include <vector>

namespace whiskermap::eval
{
/** The per-pose MAP tables scored pose by pose (MapEvaluation each) and averaged over the
 *  poses (Figures::mean): against all true tables, and, when the robot poses are known,
 *  against the "local" truth, the tables whose centre lies within EvalOptions::local_radius
 *  of the robot. A pose where nothing was found counts, with its empty estimate. */
struct PerPoseEvaluation
{
	size_t poses = 0;
	Figures all;
	std::optional<Figures> local;  ///< only when robot poses were given

	/** Scores poses one at a time (constant memory, for streaming runs). */
	class Accumulator
	{
	   public:
		/** `withLocal`: robot poses will be given, so the local truth is scored too. */
		Accumulator(std::vector<world::Table> truth, const EvalOptions& opts, bool withLocal);
		void add(const std::vector<world::Table>& tables, const mrpt::poses::CPose2D& robotPose);
		PerPoseEvaluation result() const;

	   private:
		std::vector<world::Table> m_truth, m_near;
		EvalOptions m_opts;
		bool m_withLocal;
		size_t m_poses = 0;
		FiguresMean m_all, m_local;
	};

	/** `perPose[i]`: the MAP tables of pose i. `robotPoses`: empty, or one per pose. */
	static PerPoseEvaluation compute(
		const std::vector<world::Table>& truth,
		const std::vector<std::vector<world::Table>>& perPose,
		const std::vector<mrpt::poses::CPose2D>& robotPoses, const EvalOptions& opts);
};
}  // namespace whiskermap::eval
