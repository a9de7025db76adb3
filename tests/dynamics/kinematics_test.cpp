// Quaternion kinematics: the rotation matrix against Eigen's angle-axis
// composition of the zyx Euler angles, Euler round trips including the
// gimbal-lock pitch, the rate equation integrated for a constant rotation
// against the exact rotation, and the norm feedback.
#include "src/dynamics/kinematics.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>

namespace hydrocoef {
namespace {

Matrix3 zyx(const Vector3& e) {
  return (Eigen::AngleAxisd(e[2], Vector3::UnitZ()) * Eigen::AngleAxisd(e[1], Vector3::UnitY()) *
          Eigen::AngleAxisd(e[0], Vector3::UnitX()))
      .toRotationMatrix();
}

TEST(Kinematics, RotationMatrixIsZyxEuler) {
  for (const Vector3& e : {Vector3(0.1, -0.4, 2.0), Vector3(-2.5, 1.2, -0.3), Vector3(0.0, 0.0, 0.0)}) {
    const Quaternion4 q = quaternion_from_euler(e);
    EXPECT_NEAR(q.norm(), 1.0, 1e-15);
    const Matrix3 r = rotation_body_to_ned(q);
    EXPECT_LT((r - zyx(e)).cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_LT((r.transpose() * r - Matrix3::Identity()).cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_NEAR(r.determinant(), 1.0, 1e-14);
    EXPECT_LT((euler_from_quaternion(q) - e).cwiseAbs().maxCoeff(), 1e-13);
  }
}

TEST(Kinematics, NoGimbalLockAtNinetyDegreesPitch) {
  // Euler rates are singular at theta = 90 deg; the quaternion is not.
  const Vector3 e(0.3, std::numbers::pi / 2, -0.2);
  const Quaternion4 q = quaternion_from_euler(e);
  EXPECT_LT((rotation_body_to_ned(q) - zyx(e)).cwiseAbs().maxCoeff(), 1e-14);
  // The rate is finite and keeps the norm.
  const Quaternion4 dq = quaternion_rate(q, Vector3(0.4, -0.7, 1.1), 0.0);
  EXPECT_TRUE(dq.allFinite());
  EXPECT_NEAR(q.dot(dq), 0.0, 1e-15);
}

TEST(Kinematics, ConstantRateIntegratesToTheExactRotation) {
  // q' = 1/2 T(q) w with constant body rate w: R(t) = R(0) exp(S(w) t).
  const Vector3 w(0.3, -0.5, 0.8);
  const Vector3 e0(0.2, 0.1, -0.4);
  Quaternion4 q = quaternion_from_euler(e0);
  const double h = 1e-3;
  const int steps = 5000;
  for (int i = 0; i < steps; ++i) {  // RK4 by hand
    const Quaternion4 k1 = quaternion_rate(q, w, 0.0);
    const Quaternion4 k2 = quaternion_rate(q + 0.5 * h * k1, w, 0.0);
    const Quaternion4 k3 = quaternion_rate(q + 0.5 * h * k2, w, 0.0);
    const Quaternion4 k4 = quaternion_rate(q + h * k3, w, 0.0);
    q += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  const double t = h * steps;
  const Matrix3 expected = zyx(e0) * Eigen::AngleAxisd(w.norm() * t, w.normalized()).toRotationMatrix();
  EXPECT_LT((rotation_body_to_ned(q / q.norm()) - expected).cwiseAbs().maxCoeff(), 1e-11);
  EXPECT_NEAR(q.norm(), 1.0, 1e-11);
}

TEST(Kinematics, NormFeedbackPullsTowardsUnitNorm) {
  Quaternion4 q = 1.01 * quaternion_from_euler(Vector3(0.1, 0.2, 0.3));
  const Vector3 w(0.0, 0.0, 0.0);
  // With no rotation the feedback alone acts: d|q|^2/dt = gain (1 - |q|^2) |q|^2.
  const Quaternion4 dq = quaternion_rate(q, w, 2.0);
  EXPECT_LT(q.dot(dq), 0.0);
  for (int i = 0; i < 20000; ++i) q += 1e-3 * quaternion_rate(q, w, 2.0);
  EXPECT_NEAR(q.norm(), 1.0, 1e-12);
  EXPECT_LT((euler_from_quaternion(q / q.norm()) - Vector3(0.1, 0.2, 0.3)).norm(), 1e-14);
}

}  // namespace
}  // namespace hydrocoef

namespace hydrocoef {
namespace {

TEST(Kinematics, RotationOfAnyNormEqualsThatOfTheUnitQuaternion) {
  const Quaternion4 unit = quaternion_from_euler(Vector3(0.3, -1.1, 2.9));
  for (const double scale : {1.0, 1.0 + 1e-9, 0.97, 3.7}) {
    const Matrix3 r = rotation_body_to_ned_any_norm(scale * unit);
    EXPECT_LT((r - rotation_body_to_ned(unit)).cwiseAbs().maxCoeff(), 1e-15) << scale;
    EXPECT_LT((r * r.transpose() - Matrix3::Identity()).cwiseAbs().maxCoeff(), 1e-15) << scale;
  }
}

}  // namespace
}  // namespace hydrocoef
