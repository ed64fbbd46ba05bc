#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/smooth/ContactFactor.h>
#include <whiskermap/smooth/OdometryFactor.h>
#include <whiskermap/smooth/SameSolidFactor.h>
#include <whiskermap/smooth/TableShapeFactor.h>

#include <Eigen/Geometry>

using namespace whiskermap;
using smooth::ContactFactor;
using smooth::OdometryFactor;

namespace
{
/** Central differences of f at x, one column per parameter. */
template <int N, class F>
Eigen::Matrix<double, Eigen::Dynamic, N> numeric(F f, Eigen::Matrix<double, N, 1> x)
{
	const auto f0 = f(x);
	Eigen::Matrix<double, Eigen::Dynamic, N> J(f0.size(), N);
	for (int k = 0; k < N; k++)
	{
		auto a = x, b = x;
		a[k] += 1e-6, b[k] -= 1e-6;
		J.col(k) = (f(a) - f(b)) / 2e-6;
	}
	return J;
}

baseline::Contact contactAt(const Eigen::Vector2d& p, double normal)
{
	baseline::Contact c;
	c.p = p, c.normal = normal, c.shaft = p.normalized(), c.sigma_r = 0.003;
	return c;
}
}  // namespace

TEST(OdometryFactor, ZeroAtTheRecordedIncrementAndWhitenedByItsCovariance)
{
	const Eigen::Vector3d a(1, 2, 0.3), u(0.05, 0.01, 0.02);
	const Eigen::Rotation2Dd R(a[2]);
	const Eigen::Vector2d p = a.head<2>() + R * u.head<2>();
	const Eigen::Vector3d b(p.x(), p.y(), a[2] + u[2]);
	const OdometryFactor f(u, Eigen::Vector3d(0.01 * 0.01, 0.02 * 0.02, 0.001 * 0.001).asDiagonal());
	EXPECT_LT(f.residual(a, b).norm(), 1e-9);
	EXPECT_LT((f.end(a) - b).norm(), 1e-12);
	// 1 cm more along a's x axis is one std-dev (0.01 m, with the 0.1 mm floor in quadrature).
	const Eigen::Vector3d b2 = b + Eigen::Vector3d(std::cos(a[2]), std::sin(a[2]), 0) * 0.01;
	EXPECT_NEAR(f.residual(a, b2)[0], 0.01 / std::hypot(0.01, 1e-4), 1e-6);
	// An exact odometry (zero covariance) stays invertible: the floor.
	const OdometryFactor exact(u, Eigen::Matrix3d::Zero());
	EXPECT_TRUE(exact.sqrtInfo.allFinite());
	EXPECT_NEAR(exact.residual(a, b2).norm(), 0.01 / 1e-4, 1e-3);
}

TEST(OdometryFactor, JacobiansMatchCentralDifferences)
{
	Eigen::Matrix3d C;
	C << 4e-4, 1e-5, 0, 1e-5, 2e-4, 1e-6, 0, 1e-6, 3e-4;
	const OdometryFactor f(Eigen::Vector3d(0.05, -0.01, 0.1), C);
	const Eigen::Vector3d a(0.4, -0.2, 2.9), b(0.45, -0.17, -3.0);  // yaw across +-pi
	Eigen::Matrix3d Ja, Jb;
	f.residual(a, b, &Ja, &Jb);
	const auto na = numeric<3>([&](const Eigen::Vector3d& x) { return Eigen::VectorXd(f.residual(x, b)); }, a);
	const auto nb = numeric<3>([&](const Eigen::Vector3d& x) { return Eigen::VectorXd(f.residual(a, x)); }, b);
	EXPECT_LT((Ja - na).cwiseAbs().maxCoeff(), 1e-4 * Ja.cwiseAbs().maxCoeff());
	EXPECT_LT((Jb - nb).cwiseAbs().maxCoeff(), 1e-4 * Jb.cwiseAbs().maxCoeff());
}

TEST(SameSolidFactor, ALegIsZeroWhenTheShiftedCentresCoincide)
{
	const smooth::SameSolidFactor f{0, 1, Eigen::Vector2d(0.1, -0.05), 0.005};  // c_a - c_b
	EXPECT_EQ(f.dof(), 2);
	EXPECT_GT(f.residual(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()).norm(), 20);
	EXPECT_LT(f.residual(Eigen::Vector2d(-0.04, 0.02), Eigen::Vector2d(0.06, -0.03)).norm(), 1e-12);  // eq. S4
	EXPECT_NEAR(f.residual(Eigen::Vector2d(0.005, 0), Eigen::Vector2d(0.1, -0.05))[0], 1, 1e-12);  // one std-dev
}

TEST(SameSolidFactor, AWallIsHeldAcrossOnly)
{
	// Two pieces of a wall along x, 0.25 m apart across (y) and 1 m apart along it.
	const Eigen::Vector2d n(0, 1);
	smooth::SameSolidFactor f{0, 1, Eigen::Vector2d(-1, 0.25), 0.005};
	f.P = n * n.transpose();
	EXPECT_EQ(f.dof(), 1);
	EXPECT_NEAR(f.residual(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()).norm(), 50, 1e-9);
	EXPECT_LT(f.residual(Eigen::Vector2d(0.3, -0.25), Eigen::Vector2d::Zero()).norm(), 1e-12);  // eq. S5: along is free
	EXPECT_NEAR(f.residual(Eigen::Vector2d(0, -0.245), Eigen::Vector2d::Zero()).norm(), 1, 1e-9);
}

TEST(TableShapeFactor, HoldsTheLegsDistanceNotTheirDirection)
{
	const smooth::TableShapeFactor f{0, 1, Eigen::Vector2d(1.0, 0.6), 0.005};  // c_a - c_b: a table's diagonal
	const Eigen::Vector2d zero = Eigen::Vector2d::Zero();
	EXPECT_EQ(f.residual(zero, zero), 0);
	EXPECT_EQ(f.residual(Eigen::Vector2d(0.2, -0.1), Eigen::Vector2d(0.2, -0.1)), 0);  // moved together
	const double turn = 0.3;  // the table turned about leg b
	const Eigen::Vector2d turned = Eigen::Rotation2Dd(turn) * f.offset;
	EXPECT_NEAR(f.residual(turned - f.offset, zero), 0, 1e-12);
	// 5 mm farther apart along the diagonal is one std-dev (eq. S7).
	EXPECT_NEAR(f.residual(f.offset.normalized() * 0.005, zero), 1, 1e-12);
	EXPECT_NEAR(f.residual(zero, f.offset.normalized() * 0.005), -1, 1e-12);
	const Eigen::Vector2d da(0.01, -0.02), db(-0.03, 0.005);
	Eigen::RowVector2d J;
	f.residual(da, db, &J);
	const auto one = [](double r) { return Eigen::VectorXd::Constant(1, r); };
	const auto n = numeric<2>([&](const Eigen::Vector2d& x) { return one(f.residual(x, db)); }, da);
	const auto nb = numeric<2>([&](const Eigen::Vector2d& x) { return one(f.residual(da, x)); }, db);
	EXPECT_LT((J - n).cwiseAbs().maxCoeff(), 1e-4 * J.cwiseAbs().maxCoeff());
	EXPECT_LT((-J - nb).cwiseAbs().maxCoeff(), 1e-4 * J.cwiseAbs().maxCoeff());
}

TEST(ContactFactor, TiesAContactToTheFaceItTouches)
{
	// A 5 cm square leg at (1, 0), and a wall slab along y at x = 2 (its face at 1.95).
	const std::vector<world::Obstacle> solids = {
		world::Obstacle::rectangle({1, 0}, 0, 0.025, 0.025, 0.5, 0, 0),
		world::Obstacle::rectangle({2, 0}, M_PI / 2, 1, 0.05, 0.5)};
	const std::vector<size_t> groups = {0, 1};
	const std::vector<Eigen::Vector2d> shifts(2, Eigen::Vector2d::Zero());
	const Eigen::Vector3d pose(0.8, 0.1, -M_PI / 2);  // facing -y
	const Eigen::Rotation2Dd toRobot(-pose[2]);
	auto robotFrame = [&](const Eigen::Vector2d& w, double normal) {
		return contactAt(toRobot * (w - pose.head<2>()), normal - pose[2]);
	};
	// On the leg's -x face (x = 0.975), normal -x, 1 mm outside it.
	auto f = ContactFactor::associate(robotFrame({0.974, 0.01}, M_PI), 7, pose, solids, groups, shifts, 0.04, 0.8, 0.002);
	ASSERT_TRUE(f);
	EXPECT_EQ(f->pose, 7u);
	EXPECT_EQ(f->group, 0u);
	EXPECT_EQ(f->solid, 0u);
	EXPECT_NEAR(f->n.x(), -1, 1e-12);
	EXPECT_NEAR(f->residual(pose, shifts[0]) * f->sigma, 0.001, 1e-9);
	// The wall's face towards the robot (x = 1.95, normal -x).
	f = ContactFactor::associate(robotFrame({1.96, 0.5}, M_PI), 0, pose, solids, groups, shifts, 0.04, 0.8, 0.002);
	ASSERT_TRUE(f);
	EXPECT_EQ(f->group, 1u);
	EXPECT_EQ(f->solid, 1u);
	EXPECT_NEAR(f->residual(pose, shifts[1]) * f->sigma, -0.01, 1e-9);
	// Too far from every face, or a normal the face cannot have: no tie.
	EXPECT_FALSE(ContactFactor::associate(robotFrame({1.5, 0}, M_PI), 0, pose, solids, groups, shifts, 0.04, 0.8, 0.002));
	EXPECT_FALSE(ContactFactor::associate(robotFrame({0.974, 0.01}, 0), 0, pose, solids, groups, shifts, 0.04, 0.8, 0.002));
	// The group's shift moves the solid: shifted 10 cm along +x, the leg's face is at 1.075.
	std::vector<Eigen::Vector2d> moved = shifts;
	moved[0] = {0.1, 0};
	f = ContactFactor::associate(robotFrame({1.074, 0.01}, M_PI), 0, pose, solids, groups, moved, 0.04, 0.8, 0.002);
	ASSERT_TRUE(f);
	EXPECT_NEAR(f->residual(pose, moved[0]) * f->sigma, 0.001, 1e-9);
}

TEST(ContactFactor, SigmaIsTheReadingNoiseAcrossTheFaceAndJacobiansMatch)
{
	const std::vector<world::Obstacle> solids = {world::Obstacle::rectangle({1, 0}, 0.3, 0.025, 0.025, 0.5, 0, 0)};
	const Eigen::Vector3d pose(0.85, -0.05, 0.2);
	const Eigen::Vector2d w = Eigen::Vector2d(1, 0) + Eigen::Rotation2Dd(0.3) * Eigen::Vector2d(-0.026, 0.005);
	auto c = contactAt(Eigen::Rotation2Dd(-pose[2]) * (w - pose.head<2>()), 0.3 + M_PI - pose[2]);
	const auto f = ContactFactor::associate(c, 0, pose, solids, {0}, {Eigen::Vector2d::Zero()}, 0.04, 0.8, 0.002);
	ASSERT_TRUE(f);
	const double across = c.sigma_r * f->n.dot(Eigen::Rotation2Dd(pose[2]) * c.shaft);
	EXPECT_NEAR(f->sigma, std::hypot(across, 0.002), 1e-12);  // eq. S3
	const Eigen::Vector2d d(0.01, -0.02);
	Eigen::Vector3d Jx;
	Eigen::Vector2d Jd;
	f->residual(pose, d, &Jx, &Jd);
	const auto nx = numeric<3>([&](const Eigen::Vector3d& x) { return Eigen::VectorXd::Constant(1, f->residual(x, d)); }, pose);
	const auto nd = numeric<2>([&](const Eigen::Vector2d& x) { return Eigen::VectorXd::Constant(1, f->residual(pose, x)); }, d);
	EXPECT_LT((Jx.transpose() - nx).cwiseAbs().maxCoeff(), 1e-4 * Jx.cwiseAbs().maxCoeff());
	EXPECT_LT((Jd.transpose() - nd).cwiseAbs().maxCoeff(), 1e-4 * Jd.cwiseAbs().maxCoeff());
}
