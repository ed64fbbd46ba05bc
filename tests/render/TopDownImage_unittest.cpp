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

TEST(TopDownImage, CaptionsWrapInABandAboveTheDrawing)
{
	render::TopDownImage img(0, 2, 0, 1, 100);  // 240 px wide: 25 characters of 9 px a line
	img.table({1.0, 0.5, 0, 1.0, 0.6, 0.05, 0.7}, {255, 0, 0}, 1);
	img.caption("short");
	img.caption("a caption far longer than one line of this picture can hold");  // 59 characters
	EXPECT_EQ(img.image().getHeight(), 140u);  // the drawing keeps its size
	const auto pic = img.picture();
	// 1 + 3 text lines of 15 px and 4 px above and below: the drawing starts 68 px lower.
	ASSERT_EQ(pic.getHeight(), 140u + 68u);
	EXPECT_EQ(pic.getWidth(), 240u);
	EXPECT_EQ((pic.at<uint8_t>(120, 40 + 68, 2)), 255);  // the table's outline, moved down
	EXPECT_EQ((pic.at<uint8_t>(120, 40 + 68, 1)), 0);
	bool ink = false, inkRight = false;  // the caption's text is drawn, and wrapped before the edge
	for (int y = 0; y < 68; y++)
		for (int x = 0; x < 240; x++)
		{
			const bool dark = pic.at<uint8_t>(x, y, 1) < 128;
			ink |= dark;
			inkRight |= dark && x >= 236;
		}
	EXPECT_TRUE(ink);
	EXPECT_FALSE(inkRight);
}
