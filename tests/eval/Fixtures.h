#pragma once
#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/world/Table.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace whiskermap::test
{
/** A paper-sized table (1.0 x 0.6 m, 5 cm legs) at (x, y, yaw_deg). */
inline world::Table table(double x, double y, double yawDeg)
{
	world::Table t;
	t.x = x, t.y = y, t.yaw = core::deg2rad(yawDeg);
	t.length = 1.0, t.width = 0.6, t.leg_width = 0.05, t.texture = 0.7;
	return t;
}

/** A fresh directory per test, removed afterwards. */
class TempDirTest : public ::testing::Test
{
   protected:
	void SetUp() override
	{
		const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
		dir = std::filesystem::temp_directory_path() /
			  ("whiskermap_eval_" + std::to_string(::getpid()) + "_" + info->test_suite_name() +
			   "_" + info->name());
		std::filesystem::create_directories(dir);
	}
	void TearDown() override { std::filesystem::remove_all(dir); }
	std::string path(const std::string& name) const { return (dir / name).string(); }

	std::filesystem::path dir;
};
}  // namespace whiskermap::test
