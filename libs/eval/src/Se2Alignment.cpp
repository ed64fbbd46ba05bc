#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/Se2Alignment.h>

#include <cmath>

namespace whiskermap::eval
{
Se2Alignment Se2Alignment::fit(const std::vector<Eigen::Vector2d>& from, const std::vector<Eigen::Vector2d>& to)
{
	if (from.empty() || from.size() != to.size())
		throw core::Error("Se2Alignment: needs two equal, non-empty point sets");
	Eigen::Vector2d mf = Eigen::Vector2d::Zero(), mt = Eigen::Vector2d::Zero();
	for (size_t i = 0; i < from.size(); i++) mf += from[i], mt += to[i];
	mf /= double(from.size());
	mt /= double(to.size());
	// Centred sets f', g': yaw = atan2(sum f' x g', sum f' . g'), t = mean(to) - R mean(from) (doc/evaluation.md, ATE).
	double dot = 0, cross = 0;
	for (size_t i = 0; i < from.size(); i++)
	{
		const Eigen::Vector2d f = from[i] - mf, g = to[i] - mt;
		dot += f.dot(g);
		cross += f.x() * g.y() - f.y() * g.x();
	}
	return fromMoments(mf, mt, dot, cross);
}

Se2Alignment Se2Alignment::fromMoments(
	const Eigen::Vector2d& mf, const Eigen::Vector2d& mt, double dot, double cross)
{
	Se2Alignment a;
	a.yaw = (dot == 0 && cross == 0) ? 0 : std::atan2(cross, dot);
	a.t = mt - Eigen::Vector2d(std::cos(a.yaw) * mf.x() - std::sin(a.yaw) * mf.y(), std::sin(a.yaw) * mf.x() + std::cos(a.yaw) * mf.y());
	return a;
}

Eigen::Vector2d Se2Alignment::apply(const Eigen::Vector2d& p) const
{
	const double c = std::cos(yaw), s = std::sin(yaw);
	return Eigen::Vector2d(c * p.x() - s * p.y(), s * p.x() + c * p.y()) + t;
}

mrpt::poses::CPose2D Se2Alignment::apply(const mrpt::poses::CPose2D& p) const
{
	const Eigen::Vector2d q = apply(Eigen::Vector2d(p.x(), p.y()));
	return mrpt::poses::CPose2D(q.x(), q.y(), core::wrapToPi(p.phi() + yaw));
}
}  // namespace whiskermap::eval
