#include <gtest/gtest.h>
#include <octomap/OcTree.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/render/OcTreeExport.h>

#include <filesystem>

using namespace whiskermap;

namespace
{
/** Occupied volume (m^3) and leaf count of an octree file. */
std::pair<double, size_t> occupied(const std::string& path)
{
	octomap::OcTree tree(0.1);
	EXPECT_TRUE(tree.readBinary(path));
	double v = 0;
	size_t n = 0;
	for (auto it = tree.begin_leafs(); it != tree.end_leafs(); ++it)
		if (tree.isNodeOccupied(*it)) v += std::pow(it.getSize(), 3), n++;
	return {v, n};
}
}  // namespace

TEST(OcTreeExport, OneTableHasTheVolumeOfItsLegsAndTop)
{
	// 1 cm voxels; a yaw-0 table placed off the voxel boundaries so the count is exact:
	// top 105 x 65 x 3 voxels (1.05 x 0.65 x 0.03 m), legs 4 x 5 x 5 x 67 voxels below it.
	const world::Table t{1.003, 1.003, 0, 1.0, 0.6, 0.05, 0.7};
	const auto path = (std::filesystem::temp_directory_path() / "whiskermap_table.bt").string();
	const size_t inserted = render::OcTreeExport::write({t}, {0.01, 0.7, 0.03}, path);
	EXPECT_EQ(inserted, 105u * 65 * 3 + 4 * 25 * 67);
	const auto [volume, leaves] = occupied(path);
	EXPECT_NEAR(volume, inserted * 1e-6, 1e-9);  // every inserted voxel, nothing else
	EXPECT_GT(leaves, 0u);
	// Two tables: twice the volume.
	const world::Table u{3.003, 1.003, 0, 1.0, 0.6, 0.05, 0.7};
	render::OcTreeExport::write({t, u}, {0.01, 0.7, 0.03}, path);
	EXPECT_NEAR(occupied(path).first, 2 * inserted * 1e-6, 1e-9);
	std::filesystem::remove(path);
}

TEST(OcTreeExport, UnwritablePathIsAnError)
{
	EXPECT_THROW(render::OcTreeExport::write({}, {}, "/dev/null/x.bt"), std::exception);
}

// Regression (issue 8): far from the origin `x += resolution` stopped advancing (a hang);
// now a table beyond the octree's 16-bit key range is a clear error, and one inside it works.
TEST(OcTreeExport, FarTablesAreRefusedAndTablesNearTheRangeWork)
{
	const auto path = (std::filesystem::temp_directory_path() / "whiskermap_far.bt").string();
	for (const double x : {1e15, -4.3e8, 2.1e9, 700.0})
		EXPECT_THROW(render::OcTreeExport::write({{x, 0, 0, 1.0, 0.6, 0.05, 0.7}}, {0.02, 0.7, 0.03}, path),
					 whiskermap::core::Error) << x;
	EXPECT_FALSE(std::filesystem::exists(path));
	EXPECT_GT(render::OcTreeExport::write({{600.0, -600.0, 0, 1.0, 0.6, 0.05, 0.7}}, {0.02, 0.7, 0.03}, path), 0u);
	std::filesystem::remove(path);
}
