// Walls (doc/model.md, "Walls"): the geometry of a wall's faces, eq. 22 and eq. 23 on
// hand-computed values, and the folded evidence against the densities it sums.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/IniSection.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/WallEvidence.h>

#include <cmath>

using namespace whiskermap::model;
using whiskermap::obs::Shapelet;

namespace
{
ModelParams handParams()
{
	ModelParams p;
	p.sigma_r = 0.01;
	p.sigma_theta = 0.1;
	p.sigma_tau = 0.1;
	p.alpha_S = std::exp(3.0);
	p.delta = 0.05;
	p.c_W = std::exp(-5.0);
	p.wall_length_scale = 4;
	p.wall_thickness = 0.1;
	return p;
}
// Along +x from (0, 0) to (2, 0): face +1 is y = +0.05 (normal +90 deg), face -1 is y = -0.05.
const Wall wall{0, 0, 2, 0, 0.1, 0.3};

Shapelet contact(double x, double y, double normal, double texture)
{
	Shapelet s;
	s.x = x, s.y = y, s.normal = normal, s.texture = texture;
	return s;
}
}  // namespace

TEST(Wall, FaceGeometry)
{
	EXPECT_DOUBLE_EQ(wall.length(), 2);
	const Wall::FaceHit a = wall.nearestFace(1, 0.07);
	EXPECT_EQ(a.side, 1);
	EXPECT_NEAR(a.across, 0.02, 1e-12);
	EXPECT_NEAR(a.along, 1, 1e-12);
	EXPECT_EQ(a.excess, 0);
	EXPECT_NEAR(a.normal, M_PI_2, 1e-12);
	const Wall::FaceHit b = wall.nearestFace(1, -0.08);
	EXPECT_EQ(b.side, -1);
	EXPECT_NEAR(b.across, 0.03, 1e-12);
	EXPECT_NEAR(b.normal, -M_PI_2, 1e-12);
	// Inside the slab: negative across; past the ends: the excess along the line.
	EXPECT_NEAR(wall.face(1, 0.01, 1).across, -0.04, 1e-12);
	EXPECT_NEAR(wall.face(2.3, 0.05, 1).excess, 0.3, 1e-12);
	EXPECT_NEAR(wall.face(-0.4, 0.05, 1).excess, 0.4, 1e-12);
	EXPECT_NEAR(wall.faceDistance(2.3, 0.09, 1), std::hypot(0.3, 0.04), 1e-12);
	// The same wall drawn the other way round swaps its faces.
	const Wall back{2, 0, 0, 0, 0.1, 0.3};
	EXPECT_EQ(back.nearestFace(1, 0.07).side, -1);
	EXPECT_NEAR(back.nearestFace(1, 0.07).normal, M_PI_2, 1e-12);
	const OrientedRect r = wall.rect();
	EXPECT_NEAR(r.cx, 1, 1e-12);
	EXPECT_NEAR(r.hx, 1, 1e-12);
	EXPECT_NEAR(r.hy, 0.05, 1e-12);
}

// The cheap reject the overlap and link searches run first: it must never reject a point
// within d of the slab (that would change their results), and rejects what lies well outside
// the centre line's box.
TEST(Wall, FarFromNeverRejectsAPointNearTheSlab)
{
	// By hand: the +x wall's box grown by 0.05 + 0.1 is [-0.15, 2.15] x [-0.15, 0.15].
	EXPECT_FALSE(wall.farFrom(2.149, 0.149, 0.1));
	EXPECT_TRUE(wall.farFrom(2.151, 0, 0.1));
	EXPECT_TRUE(wall.farFrom(1, -0.151, 0.1));
	EXPECT_FALSE(wall.farFrom(1, 0, 0));  // on the centre line
	// Turned walls, points on a grid around them: whenever the exact distance to the slab (its
	// rectangle's perimeter, 0 inside) is within d, farFrom is false.
	int near = 0, rejected = 0;
	for (const double yaw : {0.0, 0.3, 1.2, M_PI_2, 2.5, -2.9})
	{
		const Wall w{0.5, -0.2, 0.5 + 1.3 * std::cos(yaw), -0.2 + 1.3 * std::sin(yaw), 0.1, 0.3};
		const OrientedRect r = w.rect();
		for (double x = -1.5; x <= 2.5; x += 0.02)
			for (double y = -1.7; y <= 1.7; y += 0.02)
			{
				const double dx = x - r.cx, dy = y - r.cy, c = std::cos(r.theta), sn = std::sin(r.theta);
				const double lx = c * dx + sn * dy, ly = -sn * dx + c * dy;
				const bool inside = std::abs(lx) <= r.hx && std::abs(ly) <= r.hy;
				const double distance = inside ? 0 : r.perimeter(x, y).distance;
				for (const double d : {0.0, 0.05, 0.2})
				{
					const bool far = w.farFrom(x, y, d);
					if (distance <= d)
					{
						near++;
						EXPECT_FALSE(far) << x << " " << y << " " << d << " yaw " << yaw;
					}
					rejected += far;
				}
			}
	}
	EXPECT_GT(near, 1000);
	EXPECT_GT(rejected, 10000);  // and it does reject: most of the grid lies far from the wall
}

// The per-wall frame gives the same faces, bit for bit, as the one-point queries.
TEST(Wall, FrameQueriesMatchThePointQueries)
{
	const Wall w{0.3, 0.1, -0.9, 1.4, 0.1, 0.3};
	const Wall::Frame fr = w.frame();
	for (const int f : Wall::FACES)
	{
		const Wall::FaceHit a = w.hit(0.7, -0.2, f), b = w.hit(fr, 0.7, -0.2, f);
		EXPECT_EQ(a.across, b.across);
		EXPECT_EQ(a.along, b.along);
		EXPECT_EQ(a.excess, b.excess);
		EXPECT_EQ(a.normal, b.normal);
	}
	EXPECT_EQ(fr.len, w.length());
	// Each face's normal (computed once per frame) is its outward direction: +-n = +-(-uy, ux)
	// for the long faces, +-u for the end caps.
	const double ux = (w.x1 - w.x0) / w.length(), uy = (w.y1 - w.y0) / w.length();
	const double out[4][2] = {{-uy, ux}, {uy, -ux}, {ux, uy}, {-ux, -uy}};
	for (int k = 0; k < 4; k++)
	{
		EXPECT_EQ(Wall::faceIndex(Wall::FACES[k]), k);
		EXPECT_NEAR(std::cos(fr.normal[k]), out[k][0], 1e-12) << Wall::FACES[k];
		EXPECT_NEAR(std::sin(fr.normal[k]), out[k][1], 1e-12) << Wall::FACES[k];
		EXPECT_EQ(w.hit(fr, 0.7, -0.2, Wall::FACES[k]).normal, fr.normal[k]);
	}
}

TEST(Wall, ShapeletDensityByHand)
{
	const ModelParams p = handParams();
	// 1 cm off face +1 (1 sigma_r), 0.05 rad off its normal (half sigma_theta), texture 0.1 off:
	// log p = 3 - 1 - 0.25 - 1 (eq. 22).
	EXPECT_NEAR(logShapeletGivenWall(contact(1, 0.06, M_PI_2 + 0.05, 0.4), wall, p), 0.75, 1e-9);
	EXPECT_EQ(bestWallFace(contact(1, 0.06, M_PI_2 + 0.05, 0.4), wall, p), 1);
	// On face +1's line but 2 cm past the end: the excess counts like a distance: 3 - 4.
	EXPECT_NEAR(logShapeletGivenWall(contact(2.02, 0.05, M_PI_2, 0.3), wall, p), -1, 1e-9);
	// On face -1, normal pointing out of it.
	EXPECT_NEAR(logShapeletGivenWall(contact(0.5, -0.05, -M_PI_2, 0.3), wall, p), 3, 1e-9);
	// On face +1 with a normal pointing into the wall: face -1 (10 cm away, the normal its own)
	// explains it better than face +1 (a half turn off): 3 - 10^2.
	EXPECT_NEAR(logShapeletGivenWall(contact(1, 0.05, -M_PI_2, 0.3), wall, p), -97, 1e-9);
	EXPECT_EQ(bestWallFace(contact(1, 0.05, -M_PI_2, 0.3), wall, p), -1);
}

TEST(Wall, EndCapsByHand)
{
	const ModelParams p = handParams();
	// Cap +2 at (2, 0), outward normal +x; cap -2 at (0, 0), normal -x; each 0.1 m wide.
	const Wall::FaceHit a = wall.hit(2.03, 0.01, 2);
	EXPECT_NEAR(a.across, 0.03, 1e-12);
	EXPECT_NEAR(a.along, 0.01, 1e-12);
	EXPECT_EQ(a.excess, 0);
	EXPECT_NEAR(a.normal, 0, 1e-12);
	const Wall::FaceHit b = wall.hit(-0.1, 0.08, -2);
	EXPECT_NEAR(b.across, 0.1, 1e-12);
	EXPECT_NEAR(b.excess, 0.03, 1e-12);
	EXPECT_NEAR(std::abs(b.normal), M_PI, 1e-12);
	EXPECT_NEAR(wall.hit(1, 0.07, 1).across, wall.face(1, 0.07, 1).across, 0);  // long faces as face()
	// 1 cm outside cap +2 (1 sigma_r), its own normal: log p = 3 - 1 (eq. 22 on the cap).
	EXPECT_NEAR(logShapeletGivenWall(contact(2.01, 0.02, 0, 0.3), wall, p), 2, 1e-9);
	EXPECT_EQ(bestWallFace(contact(2.01, 0.02, 0, 0.3), wall, p), 2);
	// 2 cm outside cap -2 and 2 cm past the slab's side: 3 - 4 - 4; face -1, 2 cm from its
	// corner, would add a quarter turn of normal error.
	EXPECT_NEAR(logShapeletGivenWall(contact(-0.02, -0.07, M_PI, 0.3), wall, p), -5, 1e-9);
	EXPECT_EQ(bestWallFace(contact(-0.02, -0.07, M_PI, 0.3), wall, p), -2);
}

TEST(Wall, EndCapsOfAThickWallByHand)
{
	// The caps span the wall's thickness, whatever it is: a 0.3 m wall from (0, 0) to (2, 0)
	// has cap +2 at x = 2 for y in [-0.15, 0.15] and its long face +1 at y = 0.15.
	const ModelParams p = handParams();
	const Wall thick{0, 0, 2, 0, 0.3, 0.3};
	const Wall::FaceHit in = thick.hit(2.03, 0.12, 2);
	EXPECT_NEAR(in.across, 0.03, 1e-12);
	EXPECT_NEAR(in.along, 0.12, 1e-12);
	EXPECT_EQ(in.excess, 0);  // within the cap (on the 0.1 m wall it would be 0.07 past it)
	EXPECT_NEAR(thick.hit(2.03, 0.18, 2).excess, 0.03, 1e-12);
	EXPECT_NEAR(thick.hit(1, 0.17, 1).across, 0.02, 1e-12);
	// 1 cm outside cap +2, 12 cm off the centre line, its own normal: log p = 3 - 1 (eq. 22 on
	// the cap, as on the thin wall's cap at 2 cm off the line).
	EXPECT_NEAR(logShapeletGivenWall(contact(2.01, 0.12, 0, 0.3), thick, p), 2, 1e-9);
	EXPECT_EQ(bestWallFace(contact(2.01, 0.12, 0, 0.3), thick, p), 2);
	// The thin wall explains the same contact far worse: 7 cm past its cap's end.
	EXPECT_LT(logShapeletGivenWall(contact(2.01, 0.12, 0, 0.3), wall, p), -40);
}

TEST(Wall, PriorByHand)
{
	const ModelParams p = handParams();
	// (2 delta)^4 c_W exp(-length / lambda_W) = 0.1^4 e^-5 e^-0.5 (eq. 23).
	EXPECT_NEAR(logWallPrior(wall, p), 4 * std::log(0.1) - 5.5, 1e-12);
	const Wall longer{0, 0, 6, 0, 0.1, 0.3};
	EXPECT_NEAR(logWallPrior(longer, p) - logWallPrior(wall, p), -1, 1e-12);
}

TEST(WallEvidence, SumsTheDensitiesAndFitsTheWall)
{
	const ModelParams p = handParams();
	WallEvidence e;
	double sum = 0;
	std::vector<Shapelet> contacts;
	for (int i = 0; i <= 8; i++)  // both faces, small errors
	{
		const int side = i % 3 == 0 ? -1 : 1;
		contacts.push_back(contact(0.1 + 0.2 * i, side * (0.05 + 0.002 * (i % 4)), side * M_PI_2 + 0.01 * (i % 3), 0.3 + 0.01 * i));
	}
	for (const Shapelet& s : contacts) e.add(s, wall, p);
	EXPECT_EQ(e.count(), contacts.size());
	// At another pose (shifted, turned, another texture) the folded sum is eq. 22's sum, while
	// every contact lies within the extent.
	const Wall moved{-0.1, 0.01, 2.1, 0.03, 0.1, 0.35};
	for (const Shapelet& s : contacts) sum += logShapeletGivenWall(s, moved, p);
	EXPECT_NEAR(e.logLikelihood(moved, p), sum, 1e-6);
	// The fit is the minimiser: better than the true wall, and from the first to the last contact.
	const Wall fit = e.fit(0.1);
	EXPECT_GE(e.logLikelihood(fit, p), e.logLikelihood(wall, p) - 1e-9);
	EXPECT_NEAR(std::min(fit.x0, fit.x1), 0.1, 0.01);
	EXPECT_NEAR(std::max(fit.x0, fit.x1), 1.7, 0.01);
	EXPECT_NEAR((fit.y0 + fit.y1) / 2, 0.0, 0.005);
	// Round trip of the statistics.
	EXPECT_EQ(WallEvidence::fromStats(e.stats(), e.count()), e);
}

TEST(WallEvidence, EndCapContactsAreFrozenAndStretchTheExtent)
{
	const ModelParams p = handParams();
	WallEvidence e;
	std::vector<Shapelet> contacts;
	for (int i = 0; i <= 4; i++) contacts.push_back(contact(0.2 + 0.3 * i, 0.05 + 0.001 * i, M_PI_2, 0.3));
	contacts.push_back(contact(2.004, 0.01, 0.02, 0.32));  // on cap +2, past the last long-face contact
	double sum = 0;
	for (const Shapelet& s : contacts) e.add(s, wall, p), sum += logShapeletGivenWall(s, wall, p);
	EXPECT_EQ(e.count(), contacts.size());
	// At the pose they were folded at, the sum is eq. 22's, the cap's term included.
	EXPECT_NEAR(e.logLikelihood(wall, p), sum, 1e-6);
	EXPECT_GT(e.stats().back(), 0);  // the cap's frozen cost: 0.4^2 + 0.2^2
	EXPECT_NEAR(e.stats().back(), 0.16 + 0.04, 1e-9);
	// The fit's extent reaches the cap's contact; its line stays the long face's.
	const Wall fit = e.fit(0.1);
	EXPECT_NEAR(std::max(fit.x0, fit.x1), 2.004, 1e-3);
	EXPECT_NEAR((fit.y0 + fit.y1) / 2, 0.002, 0.003);
	EXPECT_EQ(WallEvidence::fromStats(e.stats(), e.count()), e);
	// The same contacts with the cap's first: the same sum, the same fitted line and extent.
	WallEvidence first;
	first.add(contacts.back(), wall, p);
	for (size_t i = 0; i + 1 < contacts.size(); i++) first.add(contacts[i], wall, p);
	EXPECT_NEAR(first.logLikelihood(wall, p), sum, 1e-6);
	const Wall again = first.fit(0.1);
	EXPECT_NEAR(std::max(again.x0, again.x1), 2.004, 1e-3);
	EXPECT_NEAR(std::min(again.x0, again.x1), 0.2, 1e-3);
	EXPECT_NEAR((again.y0 + again.y1) / 2, (fit.y0 + fit.y1) / 2, 1e-9);
}

TEST(WallEvidence, FitRecoversATurnedWall)
{
	const ModelParams p = handParams();
	const double a = 0.7, c = std::cos(a), s = std::sin(a);
	const Wall truth{1, 1, 1 + 3 * c, 1 + 3 * s, 0.1, 0.3};
	WallEvidence e;
	for (int i = 0; i <= 10; i++)  // on face -1 (to the right of the direction), exact normals
	{
		const double t = 0.3 * i;
		e.add(contact(1 + t * c + 0.05 * s, 1 + t * s - 0.05 * c, a - M_PI_2, 0.3), truth, p);
	}
	// The fit is the same slab, drawn from the first contact's face: its face +1 is the
	// contacts' face, so its direction is the truth's reversed.
	const Wall fit = e.fit(0.1);
	EXPECT_NEAR(std::hypot(fit.x0 - truth.x1, fit.y0 - truth.y1), 0, 1e-6);
	EXPECT_NEAR(std::hypot(fit.x1 - truth.x0, fit.y1 - truth.y0), 0, 1e-6);
	EXPECT_NEAR(fit.nearestFace(1 + 0.05 * s, 1 - 0.05 * c).across, 0, 1e-6);
}

// Manhattan walls (model keys manhattan_walls, wall_axis_deg): the fit's yaw is held to the
// axis or at right angles to it, the nearest to the free optimum; the offset is the best at it.
TEST(WallEvidence, FitHeldToAnAxisTurnsToItsNearestDirection)
{
	const ModelParams p = handParams();
	// 3 degrees off the x axis, 2 off the y axis (the yaw search skipped: every yaw it could
	// find is nearest the same direction), a diagonal, 43 and 47 degrees (searched: it decides)
	for (const double a : {0.05, M_PI_2 - 0.04, -0.6, 0.75, 0.82})
	{
		const double c = std::cos(a), s = std::sin(a);
		const Wall truth{1, 1, 1 + 2 * c, 1 + 2 * s, 0.1, 0.3};
		WallEvidence e;
		for (int i = 0; i <= 8; i++)
		{
			const double t = 0.25 * i;
			e.add(contact(1 + t * c - 0.05 * s, 1 + t * s + 0.05 * c, a + M_PI_2, 0.3), truth, p);
		}
		const Wall free = e.fit(0.1), held = e.fit(0.1, 0.0), turned = e.fit(0.1, 0.3);
		const auto yaw = [](const Wall& w) { return std::atan2(w.y1 - w.y0, w.x1 - w.x0); };
		EXPECT_NEAR(whiskermap::core::angleDiff(yaw(free), a, M_PI), 0, 1e-6) << a;
		const double nearest = std::round(a / M_PI_2) * M_PI_2, nearestTurned = 0.3 + std::round((a - 0.3) / M_PI_2) * M_PI_2;
		EXPECT_NEAR(whiskermap::core::angleDiff(yaw(held), nearest, M_PI), 0, 1e-12) << a;
		EXPECT_NEAR(whiskermap::core::angleDiff(yaw(turned), nearestTurned, M_PI), 0, 1e-12) << a;
		// The held wall passes through the contacts' mean (the closed-form offset at its yaw)
		// and scores worse than the free fit, which is the optimum.
		EXPECT_NEAR(held.nearestFace(1 + c - 0.05 * s, 1 + s + 0.05 * c).across, 0, 1e-6) << a;
		EXPECT_LT(e.logLikelihood(held, p), e.logLikelihood(free, p)) << a;
	}
}

TEST(ModelParams, WallKeysAreStrict)
{
	const auto parse = [](const std::string& extra) {
		mrpt::config::CConfigFileMemory cfg(
			"[m]\nsigma_r=0.01\nsigma_theta=0.087\nsigma_w=0.01\nsigma_tau=0.1\nc_T=1e-2\nc_L=1e-3\nc_S=1e-4\n"
			"alpha_L=7e3\nalpha_S=1e7\nepsilon=1e-2\ndelta=0.01\ntable_length=1\ntable_width=0.6\n"
			"leg_width=0.05\ntexture=0.7\nparent_gate=0.05\n" + extra);
		whiskermap::core::IniSection sec(cfg, "m", "test.ini");
		return ModelParams::fromIni(sec);
	};
	EXPECT_FALSE(parse("").walls);
	const ModelParams on = parse("walls=true\nc_W=1e-6\nwall_length_scale=3\nwall_thickness=0.12\n");
	EXPECT_TRUE(on.walls);
	EXPECT_DOUBLE_EQ(on.c_W, 1e-6);
	EXPECT_DOUBLE_EQ(on.wall_length_scale, 3);
	EXPECT_DOUBLE_EQ(on.wall_thickness, 0.12);
	EXPECT_FALSE(on == parse(""));
	EXPECT_THROW(parse("walls=yes please\n"), whiskermap::core::Error);
	EXPECT_THROW(parse("c_W=0\n"), whiskermap::core::Error);
	EXPECT_THROW(parse("wall_thickness=-1\n"), whiskermap::core::Error);
	EXPECT_FALSE(on.wallAxis());
	const ModelParams manhattan = parse("walls=true\nmanhattan_walls=true\nwall_axis_deg=30\n");
	ASSERT_TRUE(manhattan.wallAxis());
	EXPECT_NEAR(*manhattan.wallAxis(), M_PI / 6, 1e-15);
	EXPECT_FALSE(manhattan == parse("walls=true\nmanhattan_walls=true\n"));
	EXPECT_DOUBLE_EQ(*parse("manhattan_walls=true\n").wallAxis(), 0);
	EXPECT_THROW(parse("wall_axis_deg=91\n"), whiskermap::core::Error);
	EXPECT_THROW(parse("manhattan_walls=2\n"), whiskermap::core::Error);
}
