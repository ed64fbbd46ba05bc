#include <whiskermap/core/Error.h>
#include <whiskermap/render/TopDownImage.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace whiskermap::render
{
TopDownImage::TopDownImage(double x0, double x1, double y0, double y1, double pxPerMetre, int maxSide)
	: m_x0(x0),
	  m_y1(y1),
	  m_scale(std::min(pxPerMetre, (maxSide - 40) / std::max(x1 - x0, y1 - y0))),
	  m_img(
		  static_cast<unsigned>(std::ceil((x1 - x0) * m_scale)) + 40,
		  static_cast<unsigned>(std::ceil((y1 - y0) * m_scale)) + 40, mrpt::img::CH_RGB)
{
	m_img.filledRectangle(0, 0, m_img.getWidth() - 1, m_img.getHeight() - 1, {255, 255, 255});
}

int TopDownImage::px(double x) const { return m_margin + static_cast<int>(std::lround((x - m_x0) * m_scale)); }
int TopDownImage::py(double y) const { return m_margin + static_cast<int>(std::lround((m_y1 - y) * m_scale)); }

void TopDownImage::segment(
	const Eigen::Vector2d& a, const Eigen::Vector2d& b, mrpt::img::TColor c, unsigned width)
{
	m_img.line(px(a.x()), py(a.y()), px(b.x()), py(b.y()), c, width);
}

void TopDownImage::quad(const std::array<Eigen::Vector2d, 4>& q, mrpt::img::TColor c, unsigned width)
{
	for (int k = 0; k < 4; k++) segment(q[k], q[(k + 1) % 4], c, width);
}

void TopDownImage::arena(const world::World& w, mrpt::img::TColor c)
{
	quad({Eigen::Vector2d(w.x_min, w.y_min), Eigen::Vector2d(w.x_max, w.y_min),
		  Eigen::Vector2d(w.x_max, w.y_max), Eigen::Vector2d(w.x_min, w.y_max)},
		 c, 3);
	for (const auto& v : w.walls) quad(v.slab().corners, c, 2);  // interior walls: their slabs
}

void TopDownImage::table(const world::Table& t, mrpt::img::TColor c, unsigned width)
{
	quad({t.legCentre(0), t.legCentre(1), t.legCentre(2), t.legCentre(3)}, c, width);
	for (int k = 0; k < 4; k++) quad(t.leg(k, 0).corners, c, width);
}

void TopDownImage::robot(const mrpt::poses::CPose2D& p, mrpt::img::TColor c)
{
	m_img.drawCircle(px(p.x()), py(p.y()), 3, c);
	segment({p.x(), p.y()}, {p.x() + 0.08 * std::cos(p.phi()), p.y() + 0.08 * std::sin(p.phi())}, c, 1);
}

void TopDownImage::path(const std::vector<mrpt::poses::CPose2D>& poses, mrpt::img::TColor c, unsigned width)
{
	for (size_t i = 1; i < poses.size(); i++)
		segment({poses[i - 1].x(), poses[i - 1].y()}, {poses[i].x(), poses[i].y()}, c, width);
}

void TopDownImage::shapelet(const obs::Shapelet& s, mrpt::img::TColor c)
{
	m_img.filledRectangle(px(s.x) - 1, py(s.y) - 1, px(s.x) + 1, py(s.y) + 1, c);
	segment({s.x, s.y}, {s.x + 0.06 * std::cos(s.normal), s.y + 0.06 * std::sin(s.normal)}, c, 1);
}

namespace
{
constexpr int CHAR_W = 9, LINE_H = 15, PAD = 4;  // MRPT's default font, 9x15
}

void TopDownImage::caption(const std::string& text, mrpt::img::TColor c)
{
	const size_t width = std::max<size_t>(8, (m_img.getWidth() - 2 * PAD) / CHAR_W);
	size_t from = 0;
	while (text.size() - from > width)
	{
		size_t cut = text.rfind(' ', from + width);
		if (cut == std::string::npos || cut <= from) cut = from + width;  // a word longer than a line
		m_captions.push_back({text.substr(from, cut - from), c});
		from = text[cut] == ' ' ? cut + 1 : cut;
	}
	m_captions.push_back({text.substr(from), c});
}

mrpt::img::CImage TopDownImage::picture() const
{
	if (m_captions.empty()) return m_img;
	const int band = 2 * PAD + LINE_H * static_cast<int>(m_captions.size());
	mrpt::img::CImage out(m_img.getWidth(), m_img.getHeight() + band, mrpt::img::CH_RGB);
	out.filledRectangle(0, 0, out.getWidth() - 1, band - 1, {255, 255, 255});
	for (size_t i = 0; i < m_captions.size(); i++)
		out.textOut(PAD, PAD + LINE_H * static_cast<int>(i), m_captions[i].text, m_captions[i].colour);
	out.drawImage(0, band, m_img);
	return out;
}

void TopDownImage::save(const std::string& path) const
{
	const std::string tmp = path + ".tmp.png";
	if (!picture().saveToFile(tmp)) throw core::Error(path + ": cannot write image");
	std::filesystem::rename(tmp, path);
}
}  // namespace whiskermap::render
