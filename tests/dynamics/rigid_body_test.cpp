// Mass matrices and Coriolis–centripetal forces: the cross-product matrix,
// Fossen's M_RB with the parallel-axis inertia, the sphere's added mass, the
// skew-symmetry of C(nu) for any symmetric M, C_RB nu against the Newton–Euler
// velocity terms written out independently, and the Munk moment of C_A.
#include "src/dynamics/rigid_body.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

Matrix6 random_spd(std::mt19937& rng) {
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  Matrix6 a;
  for (Eigen::Index i = 0; i < 36; ++i) a(i / 6, i % 6) = d(rng);
  return a * a.transpose() + 0.5 * Matrix6::Identity();
}

Vector6 random_nu(std::mt19937& rng) {
  std::uniform_real_distribution<double> d(-2.0, 2.0);
  Vector6 v;
  for (Eigen::Index i = 0; i < 6; ++i) v[i] = d(rng);
  return v;
}

TEST(Skew, IsTheCrossProduct) {
  const Vector3 a(0.3, -1.2, 2.5), b(-0.7, 0.4, 1.1);
  EXPECT_LT((skew(a) * b - a.cross(b)).norm(), 1e-15);
  EXPECT_LT((skew(a) + skew(a).transpose()).norm(), 1e-15);
}

TEST(RigidBodyMass, FossenBlocksAndParallelAxes) {
  const double m = 6.7;
  Matrix3 ig;
  ig << 0.06, 0.002, -0.001, 0.002, 0.07, 0.003, -0.001, 0.003, 0.08;
  const Vector3 rg(0.01, -0.02, 0.03);
  const Matrix6 mrb = rigid_body_mass_matrix(m, ig, rg);
  EXPECT_LT((mrb - mrb.transpose()).norm(), 1e-15);
  EXPECT_LT((mrb.topLeftCorner<3, 3>() - m * Matrix3::Identity()).norm(), 1e-15);
  // Off-diagonal block: m S(r_g) acting on omega gives m r_g x omega.
  const Vector3 w(0.3, 0.2, -0.5);
  EXPECT_LT((mrb.bottomLeftCorner<3, 3>() * w - m * rg.cross(w)).norm(), 1e-14);
  // Parallel axes, written out: I_o = I_g + m (|r|^2 I - r r^T).
  const Matrix3 io = ig + m * (rg.squaredNorm() * Matrix3::Identity() - rg * rg.transpose());
  EXPECT_LT((mrb.bottomRightCorner<3, 3>() - io).norm(), 1e-14);
  EXPECT_TRUE(symmetric_positive_definite(mrb));
}

TEST(SphereAddedMass, HalfTheDisplacedMassInTranslationOnly) {
  const Matrix6 ma = sphere_added_mass(998.2, 0.15);
  const double displaced = 998.2 * 4.0 / 3.0 * std::numbers::pi * 0.15 * 0.15 * 0.15;
  for (Eigen::Index i = 0; i < 3; ++i) EXPECT_NEAR(ma(i, i), 0.5 * displaced, 1e-12);
  EXPECT_EQ(ma.bottomRightCorner(3, 3).norm(), 0.0);
  EXPECT_EQ((ma - Matrix6(ma.diagonal().asDiagonal())).norm(), 0.0);
}

TEST(SphereAddedMass, RotationalEntriesAsGivenAndBadSizesRefused) {
  const Matrix6 ma = sphere_added_mass(1000.0, 0.1, Vector3(0.01, 0.02, 0.03));
  EXPECT_TRUE((ma.topLeftCorner<3, 3>() == sphere_added_mass(1000.0, 0.1).topLeftCorner<3, 3>()));
  EXPECT_EQ(ma(3, 3), 0.01);
  EXPECT_EQ(ma(4, 4), 0.02);
  EXPECT_EQ(ma(5, 5), 0.03);
  EXPECT_EQ((ma - Matrix6(ma.diagonal().asDiagonal())).norm(), 0.0);
  for (const double bad : {0.0, -0.1, std::numeric_limits<double>::infinity(), std::nan("")}) {
    EXPECT_THROW(sphere_added_mass(1000.0, bad), InputError) << bad;
    EXPECT_THROW(sphere_added_mass(bad, 0.1), InputError) << bad;
  }
}

TEST(Coriolis, SkewSymmetricAndDoesNoWorkForAnySymmetricMass) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    const Matrix6 m = random_spd(rng);
    const Vector6 nu = random_nu(rng);
    const Matrix6 c = coriolis_matrix(m, nu);
    EXPECT_LT((c + c.transpose()).cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_NEAR(nu.dot(c * nu), 0.0, 1e-12);
    EXPECT_LT((coriolis_force(m, nu) - c * nu).cwiseAbs().maxCoeff(), 1e-13);
    // The power of C(nu) nu on any other velocity need not vanish, only on nu itself.
  }
}

TEST(Coriolis, RigidBodyTermsEqualNewtonEuler) {
  // Newton–Euler about CO (Fossen eq. 3.28-3.29), velocity terms only:
  //   m (w x v + w x (w x r_g))   and   w x (I_o w) + m r_g x (w x v).
  std::mt19937 rng(11);
  const double m = 3.2;
  Matrix3 ig;
  ig << 0.5, 0.04, -0.02, 0.04, 0.7, 0.05, -0.02, 0.05, 0.9;
  const Vector3 rg(0.05, -0.03, 0.08);
  const Matrix6 mrb = rigid_body_mass_matrix(m, ig, rg);
  const Matrix3 io = mrb.bottomRightCorner<3, 3>();
  for (int trial = 0; trial < 20; ++trial) {
    const Vector6 nu = random_nu(rng);
    const Vector3 v = nu.head<3>(), w = nu.tail<3>();
    Vector6 expected;
    expected.head<3>() = m * (w.cross(v) + w.cross(w.cross(rg)));
    expected.tail<3>() = w.cross(io * w) + m * rg.cross(w.cross(v));
    EXPECT_LT((coriolis_force(mrb, nu) - expected).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(Coriolis, AddedMassGivesTheMunkMoment) {
  // Translational added mass a1 = -X_udot, a2 = -Y_vdot: moving at (u, v) the
  // fluid exerts the Munk moment N = (a1 - a2) u v on the body (Fossen
  // section 6.3.2), so C_A nu, which sits on the left-hand side, has -N.
  Matrix6 ma = Matrix6::Zero();
  ma.diagonal() << 2.0, 5.0, 7.0, 0.0, 0.0, 0.0;
  const double u = 0.4, v = -0.3;
  Vector6 nu = Vector6::Zero();
  nu << u, v, 0, 0, 0, 0;
  const Vector6 c_nu = coriolis_force(ma, nu);
  EXPECT_NEAR(c_nu[5], -(2.0 - 5.0) * u * v, 1e-15);
  EXPECT_NEAR(c_nu.head<5>().norm(), 0.0, 1e-15);
  // A sphere (equal a_i) has no Munk moment.
  EXPECT_NEAR(coriolis_force(sphere_added_mass(1000.0, 0.1), nu).norm(), 0.0, 1e-15);
}

TEST(SymmetricPositiveDefinite, RejectsAsymmetricAndIndefinite) {
  Matrix6 m = Matrix6::Identity();
  EXPECT_TRUE(symmetric_positive_definite(m));
  m(0, 1) = 0.1;
  EXPECT_FALSE(symmetric_positive_definite(m));
  m = Matrix6::Identity();
  m(3, 3) = -0.1;
  EXPECT_FALSE(symmetric_positive_definite(m));
  m = Matrix6::Identity();
  m(2, 2) = 0.0;
  EXPECT_FALSE(symmetric_positive_definite(m));
}

}  // namespace
}  // namespace hydrocoef
