#include <whiskermap/core/Angles.h>
#include <whiskermap/core/MathCache.h>
#include <whiskermap/inference/moves/LegBirthDeath.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/Posterior.h>

#include <limits>

namespace whiskermap::inference::moves
{
using model::Id;
using model::Leg;
using model::NONE;

namespace
{
constexpr double NO_REVERSE = -std::numeric_limits<double>::infinity();

double logGaussian(double d, double sigma)
{
	return sigma > 0 ? -0.5 * (d / sigma) * (d / sigma) - std::log(sigma * std::sqrt(2 * M_PI)) : 0;
}

double logUniformPlusGaussian(double d, double w, double sigma)
{
	if (!(sigma > 0)) return std::abs(d) <= w / 2 ? -std::log(w) : NO_REVERSE;
	const auto phi = [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); };
	return std::log((phi((w / 2 - d) / sigma) - phi((-w / 2 - d) / sigma)) / w);
}

int emptyCorners(const model::Blackboard& bb, Id t, Id without)
{
	int n = 0;
	for (const int c : bb.cornerCounts(t, without)) n += c == 0;
	return n;
}
}  // namespace

Proposal LegBirthDeath::birthFor(MoveContext& ctx, size_t s)
{
	m_birth = true;
	m_leg = ctx.bb.addLeg(ctx.newLegFor(s));
	ctx.bb.setShapeletParent(s, m_leg);
	Proposal p{Move::Priming, model::logOddsLeg(ctx.bb, m_leg)};
	p.logForward = logBirthMass(ctx, s, ctx.bb.leg(m_leg));
	return p;
}

// Q(ch(T) | T): the missing leg at a uniformly chosen empty corner, exactly as eq. 6 expects.
std::optional<Proposal> LegBirthDeath::birthAtCorner(MoveContext& ctx, Id t)
{
	const model::CornerCounts counts = ctx.bb.cornerCounts(t);
	int empty[4], n = 0;
	for (int c = 0; c < 4; c++)
		if (counts[c] == 0) empty[n++] = c;
	if (n == 0) return std::nullopt;
	m_birth = true;
	m_leg = ctx.bb.addLeg(atCorner(ctx.mp, ctx.bb.table(t), empty[ctx.rng.pick(static_cast<size_t>(n))], t));
	Proposal p{Move::Child, model::logOddsLeg(ctx.bb, m_leg)};
	p.logForward = -std::log(n);
	return p;
}

// A leg holding folded contacts never dies: they would be lost (doc/map-plugin.md).
std::optional<Proposal> LegBirthDeath::death(MoveContext& ctx, Id l)
{
	const model::Blackboard& bb = ctx.bb;
	if (!bb.evidence(l).empty()) return std::nullopt;
	m_birth = false;
	m_leg = l;
	Proposal p{Move::Death, -model::logOddsLeg(bb, l)};
	const Leg& leg = bb.leg(l);
	const auto& own = bb.shapeletsOf(l);
	p.logReverse = NO_REVERSE;
	if (leg.parent == NONE && own.size() == 1)
	{
		const obs::Shapelet& sh = bb.shapelets()[static_cast<size_t>(own[0])];
		if (leg.texture == sh.texture && leg.wx == ctx.mp.leg_width && leg.wy == leg.wx)
			p.logReverse = logBirthMass(ctx, static_cast<size_t>(own[0]), leg);
	}
	else if (leg.parent != NONE && own.empty() && standsAtCorner(ctx.mp, leg, bb.table(leg.parent)))
		p.logReverse = -std::log(emptyCorners(bb, leg.parent, l));
	return p;
}

Leg LegBirthDeath::atCorner(const model::ModelParams& p, const model::Table& t, int c, Id parent)
{
	Leg l;
	model::tableCorner(t, c, p, l.x, l.y);
	l.theta = t.theta;
	l.wx = l.wy = t.leg_width;
	l.texture = t.texture;
	l.parent = parent;
	return l;
}

bool LegBirthDeath::standsAtCorner(const model::ModelParams& p, const Leg& leg, const model::Table& t)
{
	const Leg at = atCorner(p, t, leg.corner, leg.parent);
	return at.x == leg.x && at.y == leg.y && leg.theta == at.theta && leg.wx == at.wx && leg.wy == at.wy &&
		   leg.texture == at.texture;
}

void LegBirthDeath::finish(MoveContext& ctx, bool accepted)
{
	if (accepted != m_birth) ctx.bb.removeLeg(m_leg);  // a rejected birth, an accepted death
}

double LegBirthDeath::logBirthDensity(const MoveContext& ctx, size_t s, const Leg& leg)
{
	int drawn = 0;
	return logBirthDensity(ctx, s, leg, drawn);
}

double LegBirthDeath::logBirthMass(const MoveContext& ctx, size_t s, const Leg& leg)
{
	int drawn = 0;
	const double density = logBirthDensity(ctx, s, leg, drawn);
	return density + drawn * core::cachedLog(2 * ctx.mp.delta);  // eq. 19's cell, per drawn coordinate
}

double LegBirthDeath::logBirthDensity(const MoveContext& ctx, size_t s, const Leg& leg, int& drawn)
{
	const obs::Shapelet& sh = ctx.bb.shapelets()[s];
	const double w = ctx.mp.leg_width, nx = std::cos(sh.normal), ny = std::sin(sh.normal);
	if (ctx.broad())  // centre uniform on the disc of radius w about s, yaw uniform (mod 2 pi)
	{
		drawn = 3;
		return std::hypot(leg.x - sh.x, leg.y - sh.y) <= w ? -std::log(M_PI * w * w) - std::log(2 * M_PI) : NO_REVERSE;
	}
	const double sigma = ctx.sp.leg_position_noise, dx = leg.x - sh.x, dy = leg.y - sh.y;
	const double normal = dx * nx + dy * ny + w / 2, along = -dx * ny + dy * nx;
	double fixed = 0;
	const bool adjacent = ctx.adjacentFaceOffset(s, fixed);
	const double alongTerm = adjacent ? logGaussian(along - fixed, sigma) : logUniformPlusGaussian(along, w, sigma);
	drawn = (ctx.sp.leg_angle_noise > 0) + (sigma > 0) + (!adjacent || sigma > 0);
	return logGaussian(core::angleDiff(leg.theta, sh.normal, 2 * M_PI), ctx.sp.leg_angle_noise) +
		   logGaussian(normal, sigma) + alongTerm;
}
}  // namespace whiskermap::inference::moves
