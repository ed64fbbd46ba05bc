#include <whiskermap/core/Angles.h>
#include <whiskermap/inference/Acceptance.h>
#include <whiskermap/inference/PoseFit.h>
#include <whiskermap/inference/moves/MoveContext.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/Posterior.h>

#include <algorithm>
#include <limits>

namespace whiskermap::inference::moves
{
using model::Id;
using model::Leg;

namespace
{
/** Weight of "stay near the current centre" in a free leg's refit: it only fixes the
 *  position along a face when the contacts leave it open (PoseFit.h). */
constexpr double FREE_LEG_PULL = 1e-3;
}  // namespace

MoveContext::MoveContext(
	model::Blackboard& board, const model::ModelParams& modelParams, const SamplerParams& samplerParams,
	SamplerRandom& random, const Acceptance& acceptance)
	: bb(board), mp(modelParams), sp(samplerParams), rng(random), m_acceptance(acceptance)
{
}

bool MoveContext::accept(const Proposal& p)
{
	const bool yes = m_acceptance.accept(p, beta, rng);
	count(p.kind, yes);
	return yes;
}

void MoveContext::count(Move m, bool accepted)
{
	const auto i = static_cast<size_t>(m);
	result->proposed[i]++;
	result->accepted[i] += accepted;
	if (entry < result->moveTypes.size())
	{
		result->moveTypes[entry].proposed++;
		result->moveTypes[entry].accepted += accepted;
	}
}

// The contact lies on the leg's face with outward normal theta_S: the centre is half a leg
// width inward along -normal, anywhere along the face.
Leg MoveContext::newLegFor(size_t s)
{
	const obs::Shapelet& sh = bb.shapelets()[s];
	const double w = mp.leg_width, nx = std::cos(sh.normal), ny = std::sin(sh.normal);
	if (broad())
	{
		const double r = w * std::sqrt(rng.uniform()), bearing = 2 * M_PI * rng.uniform();
		Leg l;
		l.x = sh.x + r * std::cos(bearing);
		l.y = sh.y + r * std::sin(bearing);
		l.theta = 2 * M_PI * rng.uniform();
		l.wx = l.wy = w;
		l.texture = sh.texture;
		return l;
	}
	double along = 0;
	if (!adjacentFaceOffset(s, along)) along = (rng.uniform() - 0.5) * w;
	Leg l;
	l.x = sh.x - nx * w / 2 - ny * along + sp.leg_position_noise * rng.gaussian();
	l.y = sh.y - ny * w / 2 + nx * along + sp.leg_position_noise * rng.gaussian();
	l.theta = sh.normal + sp.leg_angle_noise * rng.gaussian();
	l.wx = l.wy = w;
	l.texture = sh.texture;
	return l;
}

// Another shapelet nearby with a normal a quarter turn away lies on the adjacent face of the
// same square leg, which fixes the offset.
bool MoveContext::adjacentFaceOffset(size_t s, double& offset) const
{
	const double w = mp.leg_width, gate = 3 * mp.sigma_theta;
	const obs::Shapelet& a = bb.shapelets()[s];
	for (const obs::Shapelet& b : bb.shapelets())
	{
		const double dx = b.x - a.x, dy = b.y - a.y;
		if (dx * dx + dy * dy > 2.25 * w * w) continue;  // farther than 1.5 w (most are): no angle needed
		const double turn = core::angleDiff(b.normal, a.normal, 2 * M_PI);
		if (std::abs(std::abs(turn) - M_PI_2) > gate) continue;
		const double side = turn > 0 ? 1 : -1;  // b's normal = a's tangent * side
		const double tx = -std::sin(a.normal), ty = std::cos(a.normal);
		offset = std::clamp(side * ((b.x - a.x) * tx * side + (b.y - a.y) * ty * side - w / 2), -w / 2, w / 2);
		return true;
	}
	return false;
}

void MoveContext::legsNearShapelet(size_t s, std::vector<Id>& out) const
{
	const obs::Shapelet& sh = bb.shapelets()[s];
	out.clear();
	bb.forEachLegNear(sh.x, sh.y, bb.maxLegRadius() + mp.parent_gate, [&](Id l) {
		if (model::legRect(bb.leg(l)).perimeter(sh.x, sh.y).distance <= mp.parent_gate) out.push_back(l);
	});
}

bool MoveContext::fittedLeg(Id l, const model::Table* t, Leg& out)
{
	const Leg& leg = bb.leg(l);
	m_contacts.clear();
	for (const Id s : bb.shapeletsOf(l)) m_contacts.push_back(&bb.shapelets()[static_cast<size_t>(s)]);
	const model::LegEvidence& evidence = bb.evidence(l);
	if (m_contacts.empty() && evidence.empty() && !t) return false;
	double qx = leg.x, qy = leg.y, pull = FREE_LEG_PULL;
	if (t)
	{
		model::tableCorner(*t, model::logLegGivenTable(leg, *t, mp).corner, mp, qx, qy);
		pull = mp.cornerPull();
	}
	if (broad())
	{
		out = leg;
		randomWalk(out.x, out.y, out.theta);
	}
	else
		out = fitLeg(mp, m_contacts.data(), m_contacts.size(), t, qx, qy, pull, &evidence);
	out.parent = leg.parent;
	const model::OrientedRect r = model::legRect(out);
	for (const obs::Shapelet* s : m_contacts)
		if (r.perimeter(s->x, s->y).distance > mp.parent_gate) return false;
	return !t || std::hypot(out.x - qx, out.y - qy) <= mp.parent_gate;
}

bool MoveContext::fitUnderParent(Id l, Leg& out)
{
	const Id parent = bb.leg(l).parent;
	return fittedLeg(l, parent == model::NONE ? nullptr : &bb.table(parent), out);
}

void MoveContext::moveLeg(Id l, const Leg& to, double& gain)
{
	gain -= model::logOddsLeg(bb, l);
	bb.setLeg(l, to);
	gain += model::logOddsLeg(bb, l);
}

bool MoveContext::refitInPlace(Id l, double& gain)
{
	Leg fit;
	if (!fitUnderParent(l, fit)) return false;
	moveLeg(l, fit, gain);
	return true;
}

bool MoveContext::drawRefit(Id l, double& gain, double& logForward)
{
	Leg fit;
	if (!fitUnderParent(l, fit)) return false;
	Leg drawn = fit;
	drawn.x += sp.leg_position_noise * rng.gaussian();
	drawn.y += sp.leg_position_noise * rng.gaussian();
	drawn.theta += sp.leg_angle_noise * rng.gaussian();
	logForward += logDrawnAbout(drawn, fit);
	moveLeg(l, drawn, gain);
	return true;
}

double MoveContext::logRefitTo(Id l, const Leg& pose)
{
	Leg fit;
	return fitUnderParent(l, fit) ? logDrawnAbout(pose, fit) : -std::numeric_limits<double>::infinity();
}

double MoveContext::logDrawnAbout(const Leg& leg, const Leg& fit) const
{
	if (leg.texture != fit.texture || leg.wx != fit.wx || leg.wy != fit.wy) return -std::numeric_limits<double>::infinity();
	return logNoise(leg.x - fit.x, sp.leg_position_noise) + logNoise(leg.y - fit.y, sp.leg_position_noise) +
		   logNoise(core::angleDiff(leg.theta, fit.theta, 2 * M_PI), sp.leg_angle_noise);
}

model::Table MoveContext::drawnTable(const model::Table& fit, bool size)
{
	model::Table d = fit;
	const double sigma = sp.leg_position_noise;
	d.x += sigma * rng.gaussian();
	d.y += sigma * rng.gaussian();
	d.theta += tableAngleNoise(fit) * rng.gaussian();
	if (size) d.d_length += sigma * rng.gaussian(), d.d_width += sigma * rng.gaussian();
	return d;
}

double MoveContext::logTableDrawnAbout(const model::Table& table, const model::Table& fit, bool size) const
{
	constexpr double NO = -std::numeric_limits<double>::infinity();
	if (table.cls != fit.cls || table.leg_width != fit.leg_width || table.texture != fit.texture) return NO;
	const double sigma = sp.leg_position_noise;
	double sum = 0;
	if (size)
		sum = logNoise(table.d_length - fit.d_length, sigma) + logNoise(table.d_width - fit.d_width, sigma);
	else if (table.d_length != fit.d_length || table.d_width != fit.d_width)
		return NO;
	// A table turned by pi (a square one by pi/2) is the same table, its corners relabelled:
	// the yaw is drawn on that circle, so that every representation of a table has its density.
	const double period = mp.lengthOf(fit) == mp.widthOf(fit) ? M_PI_2 : M_PI;
	return sum + logNoise(table.x - fit.x, sigma) + logNoise(table.y - fit.y, sigma) +
		   logNoise(core::angleDiff(table.theta, fit.theta, period), tableAngleNoise(fit));
}

double MoveContext::tableAngleNoise(const model::Table& t) const
{
	return sp.leg_position_noise / (0.5 * std::hypot(mp.lengthOf(t), mp.widthOf(t)));
}

double MoveContext::logNoise(double d, double sigma)
{
	if (!(sigma > 0)) return d == 0 ? 0.0 : -std::numeric_limits<double>::infinity();
	return -0.5 * (d / sigma) * (d / sigma) - std::log(sigma * std::sqrt(2 * M_PI));
}

bool MoveContext::atFit(Id l)
{
	if (broad()) return false;
	Leg fit;
	if (!fitUnderParent(l, fit)) return true;
	const Leg& leg = bb.leg(l);
	constexpr double EPS = 1e-12;
	return std::abs(fit.x - leg.x) <= EPS && std::abs(fit.y - leg.y) <= EPS && std::abs(fit.theta - leg.theta) <= EPS &&
		   std::abs(fit.texture - leg.texture) <= EPS;
}

void MoveContext::randomWalk(double& x, double& y, double& theta)
{
	const double scale = rng.uniform() < 0.5 ? 1 : 10;
	x += scale * sp.leg_position_noise * rng.gaussian();
	y += scale * sp.leg_position_noise * rng.gaussian();
	theta += scale * sp.leg_angle_noise * rng.gaussian();
}
}  // namespace whiskermap::inference::moves
