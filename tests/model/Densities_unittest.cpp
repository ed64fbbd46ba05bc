#include <gtest/gtest.h>
#include <whiskermap/model/Densities.h>

#include <cmath>

using namespace whiskermap::model;

namespace
{
ModelParams handParams()
{
	ModelParams p;
	p.sigma_r = 0.01;
	p.sigma_theta = 0.1;
	p.sigma_w = 0.01;
	p.sigma_tau = 0.1;
	p.alpha_L = std::exp(2.0);
	p.alpha_S = std::exp(3.0);
	p.c_T = 0.5;
	p.c_L = 0.25;
	p.c_S = 0.125;
	p.delta = 0.05;
	p.table_length = 1.0;
	p.table_width = 0.6;
	return p;
}
const Table table{2, 1, 0, 0.05, 0.5};

// A leg of `table` exactly at corner i, fully matching it.
Leg legAtCorner(int i, const ModelParams& p)
{
	Leg l;
	tableCorner(table, i, p, l.x, l.y);
	l.theta = table.theta;
	l.wx = l.wy = table.leg_width;
	l.texture = table.texture;
	return l;
}
}  // namespace

TEST(Densities, LogSumExp)
{
	EXPECT_NEAR(logSumExp(std::log(2.0), std::log(3.0)), std::log(5.0), 1e-12);
	EXPECT_NEAR(logSumExp(-1000, -1000), -1000 + std::log(2.0), 1e-9);  // no underflow
	EXPECT_NEAR(logSumExp(800, 0), 800, 1e-9);  // no overflow
	EXPECT_EQ(logSumExp(-INFINITY, 1.5), 1.5);
	EXPECT_NEAR(logNoisyOr(std::log(0.2), std::log(0.3)), std::log(0.5), 1e-12);  // eq. 12
}

TEST(Densities, PriorsNullCausesAndCell)
{
	const ModelParams p = handParams();
	EXPECT_NEAR(logTablePrior(p), std::log(0.5), 1e-12);  // eq. 4
	EXPECT_NEAR(logLegNull(p), std::log(0.25), 1e-12);  // eq. 8
	EXPECT_NEAR(logShapeletNull(p), std::log(0.125), 1e-12);  // eq. 9
	EXPECT_NEAR(logCell(std::log(7.0), p), std::log(0.001 * 7.0), 1e-12);  // (2*0.05)^3 * 7, eq. 19
}

TEST(Densities, TableCorners)
{
	const ModelParams p = handParams();
	double x, y;
	tableCorner(table, 0, p, x, y);
	EXPECT_NEAR(x, 2.5, 1e-12);
	EXPECT_NEAR(y, 1.3, 1e-12);
	tableCorner(table, 2, p, x, y);
	EXPECT_NEAR(x, 1.5, 1e-12);
	EXPECT_NEAR(y, 0.7, 1e-12);
	Table turned = table;
	turned.theta = M_PI_2;  // corner 0 (+0.5, +0.3) goes to (-0.3, +0.5)
	tableCorner(turned, 0, p, x, y);
	EXPECT_NEAR(x, 1.7, 1e-12);
	EXPECT_NEAR(y, 1.5, 1e-12);
}

TEST(Densities, LegAtItsCornerScoresAlpha)
{
	const ModelParams p = handParams();
	for (int i = 0; i < 4; i++)
	{
		const LegFit f = logLegGivenTable(legAtCorner(i, p), table, p);
		EXPECT_EQ(f.corner, i);
		EXPECT_NEAR(f.logDensity, 2.0, 1e-9);  // log alpha_L, Delta = 0
	}
}

TEST(Densities, LegGivenTableByHand)
{
	const ModelParams p = handParams();
	Leg l = legAtCorner(3, p);
	l.x += 0.01;  // 1 sigma_r off: +1
	l.y -= 0.02;  // 2 sigma_r off: +4
	l.wx += 0.01;  // +1
	l.texture -= 0.2;  // +4
	const LegFit f = logLegGivenTable(l, table, p);  // eqs. 5-6
	EXPECT_EQ(f.corner, 3);
	EXPECT_NEAR(f.logDensity, 2.0 - 10.0, 1e-9);
	// eq. 6's position term is sigma_corner's alone: half of it, and 1 + 4 becomes 4 + 16
	ModelParams tight = p;
	tight.sigma_corner = p.sigma_r / 2;
	tight.sigma_r = 1;  // eq. 7's noise plays no part
	EXPECT_NEAR(logLegGivenTable(l, table, tight).logDensity, 2.0 - 25.0, 1e-9);
}

TEST(Densities, LegAngleComparedModuloNinetyDegrees)
{
	const ModelParams p = handParams();
	Leg l = legAtCorner(1, p);
	for (const double turn : {0.0, M_PI_2, M_PI, -M_PI_2, 3 * M_PI_2, 2 * M_PI})
	{
		l.theta = table.theta + turn + 0.1;  // 1 sigma_theta off, whatever the quarter turn
		EXPECT_NEAR(logLegGivenTable(l, table, p).logDensity, 2.0 - 1.0, 1e-9) << turn;
	}
	Table t2 = table;
	t2.theta = M_PI;  // a table turned by 180 degrees is the same table
	l = legAtCorner(1, p);
	EXPECT_NEAR(logLegGivenTable(l, t2, p).logDensity, 2.0, 1e-9);
	EXPECT_EQ(logLegGivenTable(l, t2, p).corner, 3);
}

TEST(Densities, ShapeletGivenLegByHand)
{
	const ModelParams p = handParams();
	Leg l{0, 0, 0, 0.1, 0.1, 0.5, NONE, -1};
	whiskermap::obs::Shapelet s;
	s.x = 0.07;  // 2 cm outside the +x face: (0.02 / 0.01)^2 = 4
	s.y = 0.0;
	s.normal = 0.1;  // face normal 0: 1
	s.texture = 0.6;  // 1
	EXPECT_NEAR(logShapeletGivenLeg(s, l, p), 3.0 - 6.0, 1e-9);  // eq. 7
	s.x = 0.05;  // on the face, exact normal and texture
	s.normal = 0;
	s.texture = 0.5;
	EXPECT_NEAR(logShapeletGivenLeg(s, l, p), 3.0, 1e-9);
	// On the -y face with the -y normal, the leg turned by a quarter turn: same score.
	s = {0.0, -0.05, -M_PI_2, 0.5, 0};
	l.theta = M_PI_2;
	EXPECT_NEAR(logShapeletGivenLeg(s, l, p), 3.0, 1e-9);
	// A normal pointing into the leg: the best face is the opposite one (+y, normal pi/2),
	// 0.1 m away: (0.1 / 0.01)^2 = 100, less than the pi error on its own face.
	s.normal = M_PI_2;
	EXPECT_NEAR(logShapeletGivenLeg(s, l, p), 3.0 - 100.0, 1e-6);
	// Just past a corner of the leg, on the bisector's wrong side: the face its normal names
	// counts (distance 0.1 mm past the corner along +x, normal of the -y face), not the
	// nearest face by position (+x, a quarter turn off: (pi/2 / 0.1)^2 = 247).
	s = {0.0501, -0.05, -M_PI_2, 0.5, 0};
	l.theta = 0;
	EXPECT_NEAR(logShapeletGivenLeg(s, l, p), 3.0 - std::pow(0.0001 / 0.01, 2), 1e-9);
	// Angle wraps: -pi + 0.05 against pi (the -x face) is 0.05 apart.
	s = {-0.05, 0.0, -M_PI + 0.05, 0.5, 0};
	l.theta = 0;
	EXPECT_NEAR(logShapeletGivenLeg(s, l, p), 3.0 - 0.25, 1e-9);
}

// Shaft noise (doc/model.md): a contact's distance across a face with outward normal u has
// variance v = sigma_r^2 (u . shaft)^2 + sigma_across^2, and its density gains
// log(sigma_r / sqrt(v)); without a known shaft, eq. 7 as written.
TEST(Densities, ShapeletGivenLegWithShaftNoiseByHand)
{
	ModelParams p = handParams();
	p.shaft_noise = true;
	p.sigma_across = 0.002;
	const Leg l{0, 0, 0, 0.1, 0.1, 0.5, NONE, -1};
	const auto gain = [](double v) { return 0.5 * std::log(1e-4 / v); };
	whiskermap::obs::Shapelet s{0.07, 0.0, 0.0, 0.5, 0};  // 2 cm outside the +x face
	EXPECT_NEAR(logShapeletGivenLeg(s, l, p), 3.0 - 4.0, 1e-9);  // no shaft: (0.02 / 0.01)^2
	s.shaft_x = 1;  // across the face: v = 1e-4 + 4e-6
	EXPECT_NEAR(logShapeletGivenLeg(s, l, p), 3.0 - 4e-4 / 1.04e-4 + gain(1.04e-4), 1e-9);
	s.shaft_x = 0.5, s.shaft_y = std::sqrt(0.75);  // 60 degrees off the normal: 2.5e-5 + 4e-6
	EXPECT_NEAR(logShapeletGivenLeg(s, l, p), 3.0 - 4e-4 / 2.9e-5 + gain(2.9e-5), 1e-9);
	s.shaft_x = 0, s.shaft_y = 1;  // along the face: sigma_across alone, (0.02 / 0.002)^2
	EXPECT_NEAR(logShapeletGivenLeg(s, l, p), 3.0 - 100.0 + gain(4e-6), 1e-9);
	EXPECT_NEAR(contactVariance(s, 0, 1, p), 1.04e-4, 1e-15);
	// Past the +y end of the +x face by 1 cm, shaft along x: the excess along y has variance
	// sigma_across^2: (0.01 / 0.002)^2 = 25 (the +y face, 1 cm off across the shaft, has the
	// normal a quarter turn off).
	s = {0.05, 0.06, 0.0, 0.5, 0, 1, 0};
	EXPECT_NEAR(logShapeletGivenLeg(s, l, p), 3.0 - 25.0 + gain(1.04e-4), 1e-9);
	p.shaft_noise = false;  // the paper's eq. 7 ignores the shaft: (0.01 / 0.01)^2
	EXPECT_NEAR(logShapeletGivenLeg(s, l, p), 3.0 - 1.0, 1e-9);
	EXPECT_NEAR(contactVariance(s, 1, 0, p), 1e-4, 1e-15);
}

// Where a class's leg width is inferred (eq. 26), eq. 7 carries its normaliser along the face:
// a contact's position along a face of length w has density 1 / (w + sqrt(pi) sigma_r), taken
// relative to the model's leg_width. Without it a wider leg explains contacts along its faces
// for free (the integral below grows with w) and inferred leg widths come out too wide.
TEST(Densities, ShapeletGivenLegNormalisedAlongTheFaceWhereLegWidthsVary)
{
	ModelParams p = handParams();
	p.leg_width = 0.05;
	const Leg wide{0, 0, 0, 0.1, 0.1, 0.5, NONE, -1};
	const whiskermap::obs::Shapelet onFace{0.05, 0.0, 0.0, 0.5, 0};
	EXPECT_NEAR(logShapeletGivenLeg(onFace, wide, p), 3.0, 1e-9);  // no class varies: the paper's
	ObjectClass cls;
	cls.length = 1.0, cls.width = 0.6, cls.leg_width = 0.05, cls.texture = 0.5, cls.prior = 1;
	cls.texture_sigma = 0.1;
	p.classes = {cls};
	EXPECT_NEAR(logShapeletGivenLeg(onFace, wide, p), 3.0, 1e-9);  // only textures vary: the paper's
	p.classes[0].leg_width_sigma = 0.01;
	const double end = std::sqrt(M_PI) * 0.01;
	EXPECT_NEAR(logShapeletGivenLeg(onFace, wide, p), 3.0 - std::log((0.1 + end) / (0.05 + end)), 1e-9);
	EXPECT_NEAR(alongFaceNormaliser(0.05, 1e-4, p), 0.0, 1e-15);
	// The density integrates along the face line to the same for every width.
	const auto alongFace = [&](double w)
	{
		const Leg l{0, 0, 0, w, w, 0.5, NONE, -1};
		double sum = 0;
		for (double y = -0.3; y <= 0.3; y += 1e-5)
			sum += std::exp(logShapeletGivenLeg({w / 2, y, 0.0, 0.5, 0}, l, p)) * 1e-5;
		return sum;
	};
	const double narrow = alongFace(0.03), nominal = alongFace(0.05), broad = alongFace(0.12);
	EXPECT_NEAR(narrow / nominal, 1.0, 1e-4);
	EXPECT_NEAR(broad / nominal, 1.0, 1e-4);
	EXPECT_NEAR(nominal, std::exp(3.0) * (0.05 + end), 1e-4 * nominal);
}

// Object classes (issue 11): eq. 4 with the class prior, the corners (eqs. 5-6) and the
// footprint (eq. 16) at the class's size, eq. 6's leg width against the class's. Hand values.
TEST(Densities, TheClassSetsPriorCornersFootprintAndLegWidth)
{
	ModelParams p;  // c_T = 1e-2, sigma_w = 0.01, alpha_L = 7e3
	ObjectClass table, chair;
	table.prior = 0.75;
	chair.name = chair.label = "chair", chair.length = chair.width = 0.42, chair.leg_width = 0.03, chair.texture = 0.5;
	chair.prior = 0.25;
	const ModelParams none = p;
	p.classes = {table, chair};
	Table t{1, 2, 0, 0.03, 0.5};
	t.cls = 1;
	EXPECT_NEAR(logTablePrior(t, p), -4.605170186 - 1.386294361, 1e-9);  // log 1e-2 + log 0.25
	EXPECT_EQ(logTablePrior(t, none), logTablePrior(none));  // no catalogue: exactly c_T
	double x = 0, y = 0;
	tableCorner(t, 0, p, x, y);
	EXPECT_NEAR(x, 1.21, 1e-12);
	EXPECT_NEAR(y, 2.21, 1e-12);
	tableCorner(t, 2, p, x, y);
	EXPECT_NEAR(x, 0.79, 1e-12);
	EXPECT_NEAR(y, 1.79, 1e-12);
	EXPECT_NEAR(tableRect(t, p).hx, 0.21, 1e-12);
	Leg l;
	l.x = 1.21, l.y = 2.21, l.theta = 0, l.wx = l.wy = 0.03, l.texture = 0.5;
	EXPECT_NEAR(logLegGivenTable(l, t, p).logDensity, std::log(7e3), 1e-9);  // at its corner: Delta = 0
	l.wx = l.wy = 0.05;  // a 5 cm leg under a 3 cm chair: 2 (0.02 / 0.01)^2 = 8 nats
	EXPECT_NEAR(logLegGivenTable(l, t, p).logDensity, std::log(7e3) - 8, 1e-9);
	t.cls = 0;  // the same pose as a 1.0 x 0.6 table
	tableCorner(t, 0, p, x, y);
	EXPECT_NEAR(x, 1.5, 1e-12);
	EXPECT_NEAR(y, 2.3, 1e-12);
	EXPECT_NEAR(logTablePrior(t, p), -4.605170186 + std::log(0.75), 1e-9);
}
