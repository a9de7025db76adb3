// The imposed motion of a forced-oscillation case: OpenFOAM's solidBody
// dynamicMeshDict in its layouts (coefficients in a sub-dictionary or beside
// the function, the rotation in degrees), CFX's specified displacement in
// CEL (named expressions, pi, phase, negative amplitude), and what is
// refused (other motion functions, several bodies, non-harmonic CEL,
// boundaries that move differently), each with the file and line; and the
// motion turned into body axes (src/pmm/imposed_motion).
#include "importers/case_motion.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>

#include "src/core/error.hpp"
#include "src/loads/frame.hpp"
#include "src/pmm/imposed_motion.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

constexpr double kPi = std::numbers::pi;

std::filesystem::path write_case(const test::TempDir& dir, const std::string& dynamic_mesh_dict) {
  std::filesystem::create_directories(dir / "case/constant");
  std::ofstream(dir / "case/constant/dynamicMeshDict") << "FoamFile { version 2.0; format ascii; class dictionary; }\n"
                                                       << dynamic_mesh_dict;
  return dir / "case";
}

TEST(CaseMotion, OpenFoamLinearOscillationInItsLayouts) {
  test::TempDir dir;
  const auto in_coeffs = read_openfoam_motion(write_case(dir, R"(
dynamicFvMesh dynamicMotionSolverFvMesh;
motionSolver solidBody;
solidBodyCoeffs
{
  solidBodyMotionFunction oscillatingLinearMotion;
  oscillatingLinearMotionCoeffs { amplitude (0 0.02 0); omega 3.5; }
})"));
  ASSERT_TRUE(in_coeffs);
  EXPECT_FALSE(in_coeffs->rotation);
  EXPECT_EQ(in_coeffs->amplitude, (std::array<double, 3>{0, 0.02, 0}));
  EXPECT_EQ(in_coeffs->omega, 3.5);
  EXPECT_EQ(in_coeffs->phase, 0.0);
  EXPECT_NE(in_coeffs->where.find("dynamicMeshDict:7"), std::string::npos) << in_coeffs->where;
  const auto flat = read_openfoam_motion(write_case(dir, R"(
dynamicFvMesh dynamicMotionSolverFvMesh;
motionSolver solidBody;
solidBodyMotionFunction oscillatingLinearMotion;
amplitude (0.01 0 0);
omega 2;
phaseShift 0.25;
verticalShift (0 0 1);
)"));
  ASSERT_TRUE(flat);
  EXPECT_EQ(flat->amplitude[0], 0.01);
  EXPECT_EQ(flat->phase, 0.25);
}

TEST(CaseMotion, OpenFoamRotationIsInDegrees) {
  test::TempDir dir;
  const auto motion = read_openfoam_motion(write_case(dir, R"(
motionSolver solidBody;
solidBodyMotionFunction oscillatingRotatingMotion;
oscillatingRotatingMotionCoeffs { origin (0 0 0); amplitude (0 0 10); omega 1.5; }
)"));
  ASSERT_TRUE(motion);
  EXPECT_TRUE(motion->rotation);
  EXPECT_NEAR(motion->amplitude[2], 10.0 * kPi / 180.0, 1e-15);
  // A z-up case seen from a body with z down: yaw is about -z, a phase of pi.
  const HarmonicMotion yaw = body_motion(*motion, parse_axes("x,-y,-z"));
  EXPECT_EQ(yaw.dof, 5u);
  EXPECT_NEAR(yaw.amplitude, 10.0 * kPi / 180.0, 1e-15);
  EXPECT_NEAR(yaw.phase, kPi, 1e-15);
}

TEST(CaseMotion, OpenFoamRefusals) {
  test::TempDir dir;
  EXPECT_FALSE(read_openfoam_motion(dir.path()));  // no dynamicMeshDict
  EXPECT_FALSE(read_openfoam_motion(write_case(dir, "dynamicFvMesh staticFvMesh;\n")));
  test::expect_input_error(
      [&] {
        read_openfoam_motion(write_case(dir,
                                        "motionSolver solidBody;\nsolidBodyMotionFunction "
                                        "linearMotion;\nlinearMotionCoeffs { velocity (1 0 0); }\n"));
      },
      {"dynamicMeshDict:3", "linearMotion", "oscillatingLinearMotion"});
  test::expect_input_error(
      [&] {
        read_openfoam_motion(write_case(dir,
                                        "a { solidBodyMotionFunction oscillatingLinearMotion; amplitude (1 0 0); "
                                        "omega 1; }\nb { solidBodyMotionFunction oscillatingLinearMotion; }\n"));
      },
      {"dynamicMeshDict", "second solidBodyMotionFunction"});
  test::expect_input_error(
      [&] {
        read_openfoam_motion(
            write_case(dir, "motionSolver solidBody;\nsolidBodyMotionFunction oscillatingLinearMotion;\nomega 1;\n"));
      },
      {"dynamicMeshDict:3", "'amplitude'"});
}

TEST(CaseMotion, BodyAxesFoldTheDirectionIntoThePhaseAndRefuseCombinedMotion) {
  CaseOscillation motion;
  motion.amplitude = {0.03, 0, 0};
  motion.omega = 2.0;
  const HarmonicMotion surge = body_motion(motion, parse_axes("-x,y,-z"));
  EXPECT_EQ(surge.dof, 0u);
  EXPECT_EQ(surge.amplitude, 0.03);
  EXPECT_NEAR(surge.phase, kPi, 1e-15);
  // x(t) = -0.03 sin(2t) = 0.03 sin(2t + pi) at every t.
  for (const double t : {0.1, 0.7, 1.3}) EXPECT_NEAR(surge.displacement(t), -0.03 * std::sin(2.0 * t), 1e-15);
  motion.amplitude = {0.03, 0, 0.01};
  test::expect_input_error([&] { body_motion(motion, FrameTransform{}); }, {"several body axes"});
  test::expect_input_error([] { motion_from_options("twist", 1, 1, 0); }, {"--motion", "twist"});
  test::expect_input_error([] { motion_from_options("surge", 0.1, 0, 0); }, {"--period"});
}

CclDocument ccl(const std::string& expressions, const std::string& displacement) {
  return parse_ccl("LIBRARY:\n  CEL:\n    EXPRESSIONS:\n" + expressions +
                       "    END\n  END\nEND\nFLOW: Flow Analysis 1\n  DOMAIN: Default Domain\n    BOUNDARY: hull\n"
                       "      BOUNDARY CONDITIONS:\n        MESH MOTION:\n          Option = Specified Displacement\n"
                       "          DISPLACEMENT:\n            Option = Cartesian Components\n" +
                       displacement + "          END\n        END\n      END\n    END\n  END\nEND\n",
                   "case.ccl");
}

TEST(CaseMotion, CfxSpecifiedDisplacement) {
  const auto motion = cfx_motion(ccl("      Amp = 30 [mm]\n      Per = 2 [s]\n      omega = 2*pi/Per\n",
                                     "            Displacement X Component = 0 [m]\n"
                                     "            Displacement Y Component = Amp*sin(omega*t + 0.5)\n"
                                     "            Displacement Z Component = 0 [m]\n"));
  ASSERT_TRUE(motion);
  EXPECT_EQ(motion->amplitude[0], 0.0);
  EXPECT_NEAR(motion->amplitude[1], 0.03, 1e-15);
  EXPECT_NEAR(motion->omega, kPi, 1e-12);
  EXPECT_NEAR(motion->phase, 0.5, 1e-12);
  EXPECT_NE(motion->where.find("case.ccl:"), std::string::npos);
  // A negative amplitude is a phase of pi.
  const auto negative = cfx_motion(ccl("", "            Displacement X Component = -0.02 [m] * sin(3 [s^-1] * t)\n"));
  ASSERT_TRUE(negative);
  EXPECT_NEAR(negative->amplitude[0], 0.02, 1e-15);
  EXPECT_NEAR(negative->omega, 3.0, 1e-12);
  EXPECT_NEAR(std::abs(negative->phase), kPi, 1e-12);
  test::expect_input_error(
      [] { cfx_motion(ccl("", "            Displacement X Component = 0.02 [m] * sin(3 [s^-2] * t^2)\n")); },
      {"case.ccl:", "A*sin(omega*t + phi)"});
  test::expect_input_error([] { cfx_motion(ccl("", "            Displacement X Component = 0.02 [m]\n")); },
                           {"case.ccl:", "constant offset"});
  EXPECT_FALSE(cfx_motion(parse_ccl("FLOW: f\nEND\n", "plain.ccl")));
  // Expressions that double at every level are refused, not expanded 2^40 times.
  std::string doubling;
  for (int k = 0; k < 40; ++k)
    doubling += "      e" + std::to_string(k) + " = e" + std::to_string(k + 1) + " + e" + std::to_string(k + 1) + "\n";
  doubling += "      e40 = 1 [m]\n";
  test::expect_input_error(
      [&] { cfx_motion(ccl(doubling, "            Displacement X Component = e0*sin(2 [s^-1]*t)\n")); },
      {"case.ccl:", "64 kB"});
}

TEST(CaseMotion, CfxExpansionIsBoundedWhileItIsWrittenNotAfter) {
  // A wide level: e1 repeats e0 (40 kB written out) 20,000 times, in 100 kB
  // of CCL. Concatenated whole before the 64 kB check, that level was 800 MB
  // (a 216 KB file took 224 s, then all memory); written with the bound it
  // stops past 64 kB.
  std::string e0 = "      e0 = 1 [m]";
  for (int i = 0; i < 5000; ++i) e0 += " + 0 [m]";
  std::string e1 = "      e1 = e0";
  for (int i = 1; i < 20000; ++i) e1 += "+e0";
  test::expect_input_error(
      [&] { cfx_motion(ccl(e0 + "\n" + e1 + "\n", "            Displacement X Component = e1*sin(2 [s^-1]*t)\n")); },
      {"case.ccl:5:", "expands to more than 64 kB of CEL"});
  // Below the bound, a named expression used many times is written out once
  // and reads as before.
  const auto motion = cfx_motion(ccl("      A = 0.5 [mm] + 0.5 [mm]\n      B = A + A + A + A\n      w = 2*pi/(2 [s])\n",
                                     "            Displacement X Component = (B + B - B - B + B)*sin(w*t)\n"));
  ASSERT_TRUE(motion);
  EXPECT_NEAR(motion->amplitude[0], 0.004, 1e-15);
  EXPECT_NEAR(motion->omega, kPi, 1e-12);
  // A chain deeper than 64 references is refused as before.
  std::string chain;
  for (int k = 0; k < 70; ++k) chain += "      c" + std::to_string(k) + " = c" + std::to_string(k + 1) + "\n";
  chain += "      c70 = 1 [m]\n";
  test::expect_input_error(
      [&] { cfx_motion(ccl(chain, "            Displacement X Component = c0*sin(2 [s^-1]*t)\n")); },
      {"case.ccl:", "nested more than 64 deep"});
}

}  // namespace
}  // namespace hydrocoef
