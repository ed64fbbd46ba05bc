#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace whiskermap::test
{
/** A fresh directory per test, removed afterwards. */
class TempDirTest : public ::testing::Test
{
   protected:
	void SetUp() override
	{
		const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
		dir = std::filesystem::temp_directory_path() /
			  ("whiskermap_test_" + std::to_string(::getpid()) + "_" + info->test_suite_name() +
			   "_" + info->name());
		std::filesystem::create_directories(dir);
	}
	void TearDown() override { std::filesystem::remove_all(dir); }
	std::string path(const std::string& name) const { return (dir / name).string(); }

	std::filesystem::path dir;
};
}  // namespace whiskermap::test
