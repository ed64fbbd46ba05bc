#include <gtest/gtest.h>
#include <whiskermap/render/TopDownImage.h>

using namespace whiskermap;

TEST(TopDownImage, DrawsWhereTheWorldIs)
{
	// 100 px per metre over [0, 2] x [0, 1], 20 px margin: world (x, y) is pixel
	// (20 + 100 x, 20 + 100 (1 - y)).
	render::TopDownImage img(0, 2, 0, 1, 100);
	EXPECT_EQ(img.image().getWidth(), 240u);
	EXPECT_EQ(img.image().getHeight(), 140u);
	const world::Table t{1.0, 0.5, 0, 1.0, 0.6, 0.05, 0.7};
	img.table(t, {255, 0, 0}, 1);
	// The long side through the leg centres at y = 0.8 runs from x = 0.5 to 1.5.
	// Channels are stored B, G, R (OpenCV order).
	const auto px = [&](int x, int y, int c) { return img.image().at<uint8_t>(x, y, c); };
	EXPECT_EQ(px(120, 40, 2), 255);  // (1.0, 0.8): on the outline, red
	EXPECT_EQ(px(120, 40, 1), 0);
	EXPECT_EQ(px(120, 70, 1), 255);  // (1.0, 0.5): the table's middle stays white
}
