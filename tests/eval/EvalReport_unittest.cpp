#include "Fixtures.h"

#include <whiskermap/eval/EvalReport.h>

using namespace whiskermap;

namespace
{
eval::EvalReport report()
{
	const std::vector<world::Table> truth{test::table(1, 1, 0), test::table(3, 1, 0)};
	eval::EvalReport r;
	r.map = eval::MapEvaluation::compute(truth, {test::table(1.03, 1.04, 0)}, r.options);
	return r;
}
}  // namespace

TEST(EvalReport, MapOnlyJson)
{
	EXPECT_EQ(
		report().toJson(),
		"{\n"
		"  \"precision\": 1.000000,\n"
		"  \"recall\": 0.500000,\n"
		"  \"f1\": 0.666667,\n"
		"  \"rmse_m\": 0.050000,\n"
		"  \"rmse_aligned_m\": null,\n"
		"  \"yaw_err_deg\": 0.000000,\n"
		"  \"ospa\": 0.275000,\n"
		"  \"count_error\": -1,\n"
		"  \"estimated\": 1,\n"
		"  \"truth\": 2,\n"
		"  \"matched\": 1\n"
		"}\n");
}

TEST(EvalReport, FullJsonWithIdentifiabilityAndPerPose)
{
	auto r = report();
	r.identifiability = eval::Identifiability{{0, 1}, 0.04};
	r.perPose = eval::PerPoseEvaluation{};
	r.perPose->poses = 2;
	r.perPose->all = eval::Figures::of(1, 2, 0, 0, 0, 0.5);  // nothing matched: nulls
	r.perPose->local = eval::Figures::of(2, 1, 1, 0.01, 4, 0.25);
	EXPECT_EQ(
		r.toJson().substr(r.toJson().find("  \"identifiable_tables\"")),
		"  \"identifiable_tables\": 2,\n"
		"  \"recall_identifiable\": 0.500000,\n"
		"  \"per_pose\": {\n"
		"    \"poses\": 2,\n"
		"    \"precision\": 0.000000,\n"
		"    \"recall\": 0.000000,\n"
		"    \"f1\": 0.000000,\n"
		"    \"rmse_m\": null,\n"
		"    \"rmse_aligned_m\": null,\n"
		"    \"yaw_err_deg\": null,\n"
		"    \"ospa\": 0.500000,\n"
		"    \"count_error\": -1.000000,\n"
		"    \"local\": {\n"
		"      \"precision\": 0.500000,\n"
		"      \"recall\": 1.000000,\n"
		"      \"f1\": 0.666667,\n"
		"      \"rmse_m\": 0.100000,\n"
		"      \"rmse_aligned_m\": null,\n"
		"      \"yaw_err_deg\": 4.000000,\n"
		"      \"ospa\": 0.250000,\n"
		"      \"count_error\": 1.000000\n"
		"    }\n"
		"  }\n"
		"}\n");
}

TEST(EvalReport, TextNamesEveryFigure)
{
	auto r = report();
	r.perPose = eval::PerPoseEvaluation{2, eval::Figures{}, eval::Figures{}};
	const auto text = r.toText();
	for (const char* s : {"precision", "recall", "F1", "centre RMSE (m)", "centre RMSE aligned (m)", "yaw error (deg)",
						  "OSPA (m)", "count error", "per-pose local", "averaged over 2 poses",
						  "1 tables estimated, 2 true, 1 matched"})
		EXPECT_NE(text.find(s), std::string::npos) << s << " not in:\n" << text;
	EXPECT_EQ(text.find("identifiable"), std::string::npos);
}
