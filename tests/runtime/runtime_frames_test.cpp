// runtime/include/hydrocoef/runtime_frames.h: the axes conversions between
// hydrocoef (NED world, FRD body) and gz-sim/ROS (ENU world, FLU body),
// checked against the rotation matrices they stand for, known attitudes and
// the dynamics model's own rotation; and the header compiled as C99.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>

#include "hydrocoef/runtime_frames.h"
#include "src/dynamics/kinematics.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

// The change of world axes NED -> ENU and of body axes FLU -> FRD as matrices.
const Matrix3 kNedToEnu = (Matrix3() << 0, 1, 0, 1, 0, 0, 0, 0, -1).finished();
const Matrix3 kFluToFrd = Vector3(1, -1, -1).asDiagonal();

Quaternion4 random_attitude(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Quaternion4 q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q / q.norm();
}

Vector3 random_vector(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  return Vector3(u(rng), u(rng), u(rng));
}

Quaternion4 enu_attitude(const Quaternion4& q_nb) {
  Quaternion4 out;
  hc_frames_ned_enu_attitude(q_nb.data(), out.data());
  return out;
}

TEST(RuntimeFrames, VectorChangesAreTheMatricesAndTheirOwnInverses) {
  const double ned[3] = {1.5, -2.0, 3.25};
  double enu[3], back[3];
  hc_frames_ned_enu_vector(ned, enu);
  EXPECT_EQ(Vector3(enu[0], enu[1], enu[2]), kNedToEnu * Vector3(1.5, -2.0, 3.25));
  EXPECT_EQ(enu[0], -2.0);   // east
  EXPECT_EQ(enu[1], 1.5);    // north
  EXPECT_EQ(enu[2], -3.25);  // up = -down
  hc_frames_ned_enu_vector(enu, back);
  EXPECT_EQ(Vector3(back[0], back[1], back[2]), Vector3(1.5, -2.0, 3.25));

  const double twist_frd[6] = {1.0, 0.2, -0.3, 0.04, -0.05, 0.06};
  double twist_flu[6], twist_back[6];
  hc_frames_frd_flu_6(twist_frd, twist_flu);
  const double expected[6] = {1.0, -0.2, 0.3, 0.04, 0.05, -0.06};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(twist_flu[i], expected[i]) << i;
  hc_frames_frd_flu_6(twist_flu, twist_back);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(twist_back[i], twist_frd[i]) << i;
}

TEST(RuntimeFrames, TheAttitudeIsTheRotationOfBothAxesChanges) {
  // R(q_enu_flu) = (NED -> ENU) R(q_nb) (FLU -> FRD) at random attitudes,
  // the result a unit quaternion, and the change its own inverse.
  std::mt19937_64 rng(20261128);
  for (int i = 0; i < 1000; ++i) {
    const Quaternion4 q_nb = random_attitude(rng);
    const Quaternion4 q_enu = enu_attitude(q_nb);
    EXPECT_NEAR(q_enu.norm(), 1.0, 1e-15);
    const Matrix3 expected = kNedToEnu * rotation_body_to_ned(q_nb) * kFluToFrd;
    EXPECT_LT((rotation_body_to_ned(q_enu) - expected).cwiseAbs().maxCoeff(), 4e-15) << i;
    EXPECT_LT((enu_attitude(q_enu) - q_nb).cwiseAbs().maxCoeff(), 4e-15) << i;
  }
}

TEST(RuntimeFrames, KnownAttitudes) {
  // Level and heading north: in ENU a quarter turn to the left of east.
  const double s = std::sqrt(0.5);
  EXPECT_LT((enu_attitude(Quaternion4(1, 0, 0, 0)) - Quaternion4(s, 0, 0, s)).cwiseAbs().maxCoeff(), 1e-16);
  // Heading east (yaw +90 degrees in NED, clockwise seen from above): the
  // ENU body axes are the world's, the identity (up to the quaternion's sign).
  const Quaternion4 east = enu_attitude(quaternion_from_euler(Vector3(0.0, 0.0, M_PI / 2)));
  EXPECT_NEAR(std::abs(east[0]), 1.0, 1e-15);
  // Nose up 10 degrees (positive pitch in NED/FRD): the FLU nose points up
  // in ENU (z > 0), so that pitch is negative about FLU's left-pointing y.
  const Quaternion4 up = enu_attitude(quaternion_from_euler(Vector3(0.0, 0.17453292519943295, 0.0)));
  const Vector3 nose = rotation_body_to_ned(up) * Vector3::UnitX();
  EXPECT_NEAR(nose.z(), std::sin(0.17453292519943295), 1e-15);
  // Starboard roll (right side down, positive roll in FRD): FLU's left axis
  // (y) points up in ENU.
  const Quaternion4 roll = enu_attitude(quaternion_from_euler(Vector3(0.2, 0.0, 0.0)));
  EXPECT_NEAR((rotation_body_to_ned(roll) * Vector3::UnitY()).z(), std::sin(0.2), 1e-15);
}

TEST(RuntimeFrames, RotationsAreTheDynamicsModelsAndWorldBodyChangesInvertEachOther) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 1000; ++i) {
    const Quaternion4 q_nb = random_attitude(rng);
    const Vector3 v = random_vector(rng);
    Vector3 rotated, back;
    hc_frames_rotate(q_nb.data(), v.data(), rotated.data());
    EXPECT_LT((rotated - rotation_body_to_ned(q_nb) * v).cwiseAbs().maxCoeff(), 1e-13) << i;
    hc_frames_rotate_back(q_nb.data(), v.data(), back.data());
    EXPECT_LT((back - rotation_body_to_ned(q_nb).transpose() * v).cwiseAbs().maxCoeff(), 1e-13) << i;

    // A body force FRD into ENU world axes through the simulator's attitude
    // equals the force in NED world axes written in ENU.
    const Quaternion4 q_enu = enu_attitude(q_nb);
    Vector3 world_enu, body_frd;
    hc_frames_body_frd_to_world_enu(q_enu.data(), v.data(), world_enu.data());
    EXPECT_LT((world_enu - kNedToEnu * (rotation_body_to_ned(q_nb) * v)).cwiseAbs().maxCoeff(), 1e-13) << i;
    hc_frames_world_enu_to_body_frd(q_enu.data(), world_enu.data(), body_frd.data());
    EXPECT_LT((body_frd - v).cwiseAbs().maxCoeff(), 1e-13) << i;
  }
}

TEST(RuntimeFrames, TheHeaderIsPedanticC99) {
  if (!std::filesystem::exists(HYDROCOEF_C_COMPILER)) GTEST_SKIP() << "no C compiler at " << HYDROCOEF_C_COMPILER;
  test::TempDir dir;
  {
    std::ofstream program(dir / "frames.c");
    program << "#include <hydrocoef/runtime_frames.h>\n"
               "int main(void) {\n"
               "  const double q[4] = {1.0, 0.0, 0.0, 0.0}, v[3] = {1.0, 2.0, 3.0};\n"
               "  double out[4], w[3];\n"
               "  hc_frames_ned_enu_attitude(q, out);\n"
               "  hc_frames_body_frd_to_world_enu(out, v, w);\n"
               "  return w[0] == -2.0 ? 0 : 1;\n"
               "}\n";
  }
  const std::string command =
      test::shell_quote(HYDROCOEF_C_COMPILER) + " -std=c99 -pedantic -Wall -Wextra -Werror -fsyntax-only -I" +
      test::shell_quote(std::string(HYDROCOEF_SOURCE_DIR) + "/runtime/include") + " " +
      test::shell_quote((dir / "frames.c").string()) + " 2>" + test::shell_quote((dir / "log").string());
  EXPECT_EQ(std::system(command.c_str()), 0) << test::read_text(dir / "log");
}

}  // namespace
}  // namespace hydrocoef
