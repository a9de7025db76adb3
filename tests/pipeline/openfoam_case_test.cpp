// What an OpenFOAM case folder says about its run (src/pipeline/openfoam_case,
// src/pipeline/openfoam_convergence), on the repository's real sphere cases
// and on copies of one with its files changed:
// - the free stream from every place users keep it: an inlet found by its
//   boundary-condition type under any name, 0/U.orig, forceCoeffs' magUInf
//   and dragDir alone; a contradiction refused naming both places; nothing
//   found said with where it looked;
// - convergence: the quarter runs met their residualControl at their last
//   iteration (converged), the full-domain runs ran to endTime without it; a
//   transient scheme; a pattern hydrocoef does not read.
#include "src/pipeline/openfoam_case.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "src/pipeline/openfoam_convergence.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
const fs::path kSphere = fs::path(HYDROCOEF_DATA_DIR) / "openfoam-sphere";

/// A copy of the quarter case U0.1000 (system, constant, 0, postProcessing).
fs::path copy_case(const test::TempDir& dir) {
  const fs::path to = dir / "case";
  fs::copy(kSphere / "quarter-cases/U0.1000", to, fs::copy_options::recursive);
  return to;
}

std::string velocity_file(const std::string& patches) {
  return "FoamFile { version 2.0; format ascii; class volVectorField; object U; }\n"
         "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\nboundaryField\n{\n" +
         patches + "}\n";
}

std::vector<double> flow_of(const OpenFoamCaseSettings& s) {
  const auto found = s.layer.values.find("flow");
  if (found == s.layer.values.end()) return {};
  return std::get<std::vector<double>>(found->second.value);
}

TEST(OpenFoamCase, TheFreeStreamOfAnInletIsFoundByItsTypeUnderAnyName) {
  test::TempDir dir;
  const fs::path c = copy_case(dir);
  test::write_bytes(c / "0/U", velocity_file("    XMin { type fixedValue; value uniform (0.25 0.05 0); }\n"
                                             "    XMax { type inletOutlet; inletValue uniform (0 0 0); }\n"
                                             "    sphere { type fixedValue; value uniform (0 0 0); }\n"));
  const auto s = openfoam_case_settings(c);
  EXPECT_EQ(flow_of(s), (std::vector<double>{0.25, 0.05, 0.0}));
  EXPECT_EQ(s.layer.values.at("flow").origin.where, (c / "0/U").string() + ":6");
  // uniformFixedValue's constant form, under another name.
  test::write_bytes(c / "0/U",
                    velocity_file("    left { type uniformFixedValue; uniformValue constant (0.3 0 0); }\n"));
  EXPECT_EQ(flow_of(openfoam_case_settings(c)), (std::vector<double>{0.3, 0.0, 0.0}));
  // Two inflows that differ: refused naming both.
  test::write_bytes(c / "0/U", velocity_file("    a { type fixedValue; value uniform (0.3 0 0); }\n"
                                             "    b { type fixedValue; value uniform (0.2 0 0); }\n"));
  test::expect_input_error([&] { openfoam_case_settings(c); }, {"patches 'a'", "'b'", "--flow"});
}

TEST(OpenFoamCase, UOrigIsReadWhenZeroHoldsNoVelocity) {
  test::TempDir dir;
  const fs::path c = copy_case(dir);
  fs::rename(c / "0/U", c / "0/U.orig");
  EXPECT_EQ(flow_of(openfoam_case_settings(c)), (std::vector<double>{0.1, 0.0, 0.0}));
  fs::create_directories(c / "0.orig");
  fs::rename(c / "0/U.orig", c / "0.orig/U");
  EXPECT_EQ(flow_of(openfoam_case_settings(c)), (std::vector<double>{0.1, 0.0, 0.0}));
}

const char* kForceCoeffs =
    "FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }\n"
    "application simpleFoam;\n"
    "functions\n{\n    coeffs\n    {\n        type forceCoeffs;\n        patches (sphere);\n"
    "        rho rhoInf;\n        rhoInf 998.2;\n        CofR (0 0 0);\n        liftDir (0 1 0);\n"
    "        dragDir (0.8 0.6 0);\n        pitchAxis (0 0 1);\n        magUInf %s;\n        lRef 0.3;\n"
    "        Aref 0.0707;\n    }\n}\n";

std::string control_dict(const char* speed) {
  char text[1024];
  std::snprintf(text, sizeof text, kForceCoeffs, speed);
  return text;
}

TEST(OpenFoamCase, ForceCoeffsGiveTheFreeStreamOrContradictTheVelocityFile) {
  test::TempDir dir;
  const fs::path c = copy_case(dir);
  fs::remove(c / "0/U");
  test::write_bytes(c / "system/controlDict", control_dict("0.5"));
  const auto s = openfoam_case_settings(c);
  const auto flow = flow_of(s);
  ASSERT_EQ(flow.size(), 3u);
  EXPECT_NEAR(flow[0], 0.4, 1e-15);
  EXPECT_NEAR(flow[1], 0.3, 1e-15);
  EXPECT_EQ(flow[2], 0.0);
  EXPECT_NE(s.layer.values.at("flow").origin.where.find("controlDict:15"), std::string::npos);
  // With 0/U stating (0.4 0.3 0): they agree.
  test::write_bytes(c / "0/U",
                    velocity_file("    in { type freestreamVelocity; freestreamValue uniform (0.4 0.3 0); }\n"));
  EXPECT_EQ(flow_of(openfoam_case_settings(c)), (std::vector<double>{0.4, 0.3, 0.0}));
  // magUInf 0.6 contradicts it: refused naming both places.
  test::write_bytes(c / "system/controlDict", control_dict("0.6"));
  test::expect_input_error([&] { openfoam_case_settings(c); },
                           {"contradicts forceCoeffs' magUInf 0.6", (c / "0/U").string() + ":6", "controlDict:15"});
}

TEST(OpenFoamCase, WhereTheFreeStreamWasLookedForIsSaid) {
  test::TempDir dir;
  const fs::path c = copy_case(dir);
  test::write_bytes(c / "0/U", velocity_file("    in { type flowRateInletVelocity; volumetricFlowRate 0.1; }\n"
                                             "    sphere { type noSlip; }\n"));
  EXPECT_TRUE(flow_of(openfoam_case_settings(c)).empty());
  const std::string looked = openfoam_free_stream_search(c);
  EXPECT_NE(looked.find((c / "0/U").string() + ": no patch with a free stream"), std::string::npos) << looked;
  EXPECT_NE(looked.find("flowRateInletVelocity"), std::string::npos) << looked;
  EXPECT_NE(looked.find("forceCoeffs"), std::string::npos) << looked;
  fs::remove_all(c / "0");
  EXPECT_NE(openfoam_free_stream_search(c).find("no velocity file"), std::string::npos);
}

TEST(OpenFoamConvergence, TheQuarterRunsMetTheirResidualControlAtTheirLastIteration) {
  for (const auto& [name, last] : {std::pair{"U0.1000", 145.0}, std::pair{"U0.3000", 141.0}}) {
    SCOPED_TRACE(name);
    const fs::path c = kSphere / "quarter-cases" / name;
    std::vector<std::string> notes;
    const ConvergenceEvidence e = openfoam_convergence_evidence(c, last, notes);
    EXPECT_EQ(e.solver, SolverKind::Steady);
    EXPECT_EQ(e.solver_source, (c / "system/fvSchemes").string() + ":13: ddtSchemes default steadyState");
    EXPECT_TRUE(e.criteria_stated);
    EXPECT_NE(e.criteria_source.find("fvSolution:44"), std::string::npos) << e.criteria_source;
    EXPECT_NE(e.criteria_source.find("(k|omega) 1e-04"), std::string::npos) << e.criteria_source;
    ASSERT_TRUE(e.criteria_met_at);
    EXPECT_EQ(*e.criteria_met_at, last);
    EXPECT_GT(e.residual_rate, 0.8);
    EXPECT_LT(e.residual_rate, 1.0);
    EXPECT_TRUE(notes.empty());
    // The force record ending elsewhere is not the end the criteria held at.
    const ConvergenceEvidence later = openfoam_convergence_evidence(c, last + 10, notes);
    EXPECT_FALSE(later.criteria_met_at);
    EXPECT_NE(later.criteria_missed.find("the residuals end at iteration"), std::string::npos);
  }
}

TEST(OpenFoamConvergence, TheFullDomainRunsRanToEndTimeWithoutMeetingIt) {
  std::vector<std::string> notes;
  const ConvergenceEvidence e = openfoam_convergence_evidence(kSphere / "cases/u0.10_v0.00", 1000.0, notes);
  EXPECT_EQ(e.solver, SolverKind::Steady);
  EXPECT_FALSE(e.criteria_met_at);
  EXPECT_NE(e.criteria_missed.find("U 0.0001145752674"), std::string::npos) << e.criteria_missed;
  EXPECT_NE(e.criteria_missed.find("(tolerance 1e-04)"), std::string::npos) << e.criteria_missed;
}

TEST(OpenFoamConvergence, TransientSchemesAndUnreadPatterns) {
  test::TempDir dir;
  const fs::path c = copy_case(dir);
  std::vector<std::string> notes;
  test::write_bytes(c / "system/fvSchemes", "ddtSchemes { default Euler; }\n");
  EXPECT_EQ(openfoam_convergence_evidence(c, 145, notes).solver, SolverKind::Transient);
  test::write_bytes(c / "system/fvSchemes", "ddtSchemes { default steadyState; }\n");
  test::write_bytes(c / "system/fvSolution",
                    "SIMPLE\n{\n  residualControl\n  {\n    p 1e-4;\n    \"[kK]\" 1e-4;\n  }\n}\n");
  const ConvergenceEvidence e = openfoam_convergence_evidence(c, 145, notes);
  EXPECT_FALSE(e.criteria_met_at);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes.front().find("pattern [kK] is not understood"), std::string::npos) << notes.front();
  // Words, alternations and .* are read: ".*" covers every field.
  notes.clear();
  test::write_bytes(c / "system/fvSolution", "SIMPLE { residualControl { \".*\" 1e-4; } }\n");
  EXPECT_TRUE(openfoam_convergence_evidence(c, 145, notes).criteria_met_at);
  test::write_bytes(c / "system/fvSolution", "SIMPLE { residualControl { \"(p|U)\" 1e-4; k 1e-5; } }\n");
  const ConvergenceEvidence strict = openfoam_convergence_evidence(c, 145, notes);
  EXPECT_FALSE(strict.criteria_met_at);
  EXPECT_NE(strict.criteria_missed.find("k 9.485164266e-05 (tolerance 1e-05)"), std::string::npos)
      << strict.criteria_missed;
  EXPECT_TRUE(notes.empty());
}

}  // namespace
}  // namespace hydrocoef
