#pragma once
#include <mrpt/img/CImage.h>
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/obs/Shapelet.h>
#include <whiskermap/world/Table.h>
#include <whiskermap/world/World.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace whiskermap::render
{
/** A top-down PNG picture of (part of) the plane, x to the right and y up, drawn with
 *  MRPT's CImage (no display needed). Used for montages (the paper's figs. 5-7), maps and
 *  the blackboard snapshots (figs. 1-2). */
class TopDownImage
{
   public:
	/** The rectangle [x0, x1] x [y0, y1] (metres) at `pxPerMetre`, with a margin; the scale
	 *  drops so that neither side exceeds `maxSide` pixels (large worlds). */
	TopDownImage(double x0, double x1, double y0, double y1, double pxPerMetre = 150, int maxSide = 4000);

	/** Walls of a world's arena, and its interior walls (their slabs' outlines). */
	void arena(const world::World& w, mrpt::img::TColor c);
	/** A table: the rectangle through its leg centres and its four leg squares. */
	void table(const world::Table& t, mrpt::img::TColor c, unsigned width = 1);
	/** A convex quadrilateral's outline. */
	void quad(const std::array<Eigen::Vector2d, 4>& corners, mrpt::img::TColor c, unsigned width = 1);
	/** A robot pose: a small circle and a heading tick. */
	void robot(const mrpt::poses::CPose2D& p, mrpt::img::TColor c);
	/** A path: the polyline through the poses' positions. */
	void path(const std::vector<mrpt::poses::CPose2D>& poses, mrpt::img::TColor c, unsigned width = 1);
	/** A shapelet: a dot and a short tick along its surface normal. */
	void shapelet(const obs::Shapelet& s, mrpt::img::TColor c);
	/** A caption for the band above the drawing (call repeatedly for more): wrapped at spaces
	 *  to the picture's width, one text line per 15 px (MRPT's default 9x15 font). */
	void caption(const std::string& text, mrpt::img::TColor c = mrpt::img::TColor(0, 0, 0));

	/** The picture: the captions' band, then the drawing. */
	mrpt::img::CImage picture() const;
	/** Writes picture() as PNG (via a temporary file, renamed when complete). Throws core::Error. */
	void save(const std::string& path) const;

	/** The drawing alone, world (x, y) at pixel (px(x), py(y)). */
	const mrpt::img::CImage& image() const { return m_img; }

   private:
	int px(double x) const;
	int py(double y) const;
	void segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, mrpt::img::TColor c, unsigned width);

	struct Line
	{
		std::string text;
		mrpt::img::TColor colour;
	};

	double m_x0, m_y1, m_scale;
	int m_margin = 20;
	mrpt::img::CImage m_img;
	std::vector<Line> m_captions;  ///< wrapped, one per text line
};
}  // namespace whiskermap::render
