// hydrocoef's coefficients against OpenFOAM's own: the quarter-domain sphere
// run of data/openfoam-sphere/forcecoeffs/M1-U0.1000 (made by
// scripts/make-forcecoeffs-sphere-case.sh) carries the coefficients
// OpenFOAM's forceCoeffs function object wrote for its final state (Aref =
// pi R^2 / 4, the quarter sphere's frontal area; lRef 0.3; magUInf 0.1;
// rhoInf 998.2). The run imported as a user would (its case folder, body axes
// -x, y, -z) and given the same reference by `body set` has, from `runs
// --coefficients`, C_X = -Cd, C_Y = Cs, C_Z = -Cl, C_K = -CmRoll, C_M = CmPitch
// and C_N = -CmYaw: OpenFOAM's drag along +x, side force along +y, lift along
// +z, moments about (0 0 0) over lRef; body axes are (-x, y, -z) of the case's,
// forces on the body.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/coefficient_dat.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
const fs::path kCase = fs::path(HYDROCOEF_SOURCE_DIR) / "data/openfoam-sphere/forcecoeffs/M1-U0.1000";

/// The last row of forceCoeffs' coefficient.dat, by its header's column names.
std::map<std::string, double> last_coefficients() {
  fs::path file;
  for (const auto& entry : fs::recursive_directory_iterator(kCase / "postProcessing" / "forceCoeffs"))
    if (entry.path().filename().string().rfind("coefficient", 0) == 0) file = entry.path();
  return test::last_coefficient_row(file);
}

TEST(CliForceCoeffs, CoefficientsAreOpenFoamsForTheSameRun) {
  const auto openfoam = last_coefficients();
  ASSERT_TRUE(openfoam.count("Cd") && openfoam.count("Cs") && openfoam.count("Cl")) << kCase;
  test::TempDir dir;
  const auto run = [&](const std::vector<std::string>& args) {
    const auto result = test::run_cli(args, dir.path());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return result.out;
  };
  run({"import", kCase.string(), "--body", "quarter-sphere", "--axes=-x,y,-z", "--quiet"});
  run({"body", "set", "quarter-sphere", "--length", "0.3", "--area", "quarter-frontal=0.01767145867644259"});
  const auto table = nlohmann::json::parse(run({"runs", "--coefficients", "--json"}));
  ASSERT_EQ(table["runs"].size(), 1u);
  const auto& c = table["runs"][0]["coefficients"];
  EXPECT_EQ(table["runs"][0]["speed"], 0.1);
  // OpenFOAM wrote its files with 10 to 11 significant digits.
  const auto near = [](double ours, double theirs) {
    return std::abs(ours - theirs) <= 1e-7 * std::abs(theirs) + 1e-12;
  };
  EXPECT_PRED2(near, c["C_X"].get<double>(), -openfoam.at("Cd"));
  EXPECT_PRED2(near, c["C_Y"].get<double>(), openfoam.at("Cs"));
  EXPECT_PRED2(near, c["C_Z"].get<double>(), -openfoam.at("Cl"));
  // Moments are small differences of large terms: forceCoeffs recomputed them from the fields as written
  // (10 digits), the run's moment.dat from the fields in memory.
  const auto near_moment = [](double ours, double theirs) {
    return std::abs(ours - theirs) <= 1e-6 * std::abs(theirs) + 1e-9;
  };
  EXPECT_PRED2(near_moment, c["C_K"].get<double>(), -openfoam.at("CmRoll"));
  EXPECT_PRED2(near_moment, c["C_M"].get<double>(), openfoam.at("CmPitch"));
  EXPECT_PRED2(near_moment, c["C_N"].get<double>(), -openfoam.at("CmYaw"));
  EXPECT_GT(openfoam.at("Cd"), 0.2);  // the coarse wall-function model's drag (data/openfoam-sphere/README.md)
}

}  // namespace
}  // namespace hydrocoef
