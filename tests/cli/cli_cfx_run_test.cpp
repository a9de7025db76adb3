// A CFX run imported as the solver left it: the case's settings from the CCL
// echoed in its solver output (STEM.out) and its forces from the cfx5mondata
// monitor CSV beside it (STEM*.csv), with sweep-wide flags only. The free
// stream of the CCL becomes the body velocity with the same frame that turns
// the monitors into body axes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::TempDir;

const std::filesystem::path kOut = HYDROCOEF_SOURCE_DIR "/tests/data/cfx/tow_u1.5_001.out";

void write_monitors(const std::filesystem::path& path) {
  std::ofstream(path) << "\"ACCUMULATED TIMESTEP\",\"USER POINT,Fx\",\"USER POINT,Fy\",\"USER POINT,Fz\"\n"
                         "1,1.20,0.11,0.02\n2,1.25,0.12,0.03\n3,1.26,0.13,0.04\n";
}

TEST(CliCfxRun, TheSolverOutputAndItsMonitorsGiveOneRunInBodyAxes) {
  TempDir dir;
  std::filesystem::create_directories(dir / "sweep");
  std::filesystem::copy_file(kOut, dir / "sweep" / "tow_u1.5_001.out");
  write_monitors(dir / "sweep" / "tow_u1.5_001_monitors.csv");
  // Named directly: the .out stands for its run.
  const auto result =
      run_cli({"import", "sweep/tow_u1.5_001.out", "--body", "hull", "--axes=-x,y,-z", "--json"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto runs = nlohmann::json::parse(run_cli({"runs", "--json"}, dir.path()).out);
  ASSERT_EQ(runs.size(), 1u);
  const auto& run = runs[0];
  // Free stream (1.5, 0.1, 0) m/s in CFD axes; the body moves at its negative; CFD -> body: (-x, y, -z).
  EXPECT_DOUBLE_EQ(run.at("u").get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(run.at("v").get<double>(), -0.1);
  EXPECT_DOUBLE_EQ(run.at("w").get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(run.at("density").get<double>(), 997.0);
  EXPECT_NEAR(run.at("kinematic_viscosity").get<double>(), 8.899e-4 / 997.0, 1e-18);
  // Drag opposes the motion: the monitor's +x force is -X in body axes.
  EXPECT_DOUBLE_EQ(run.at("forces").at("X").at("total").get<double>(), -1.26);
  EXPECT_DOUBLE_EQ(run.at("forces").at("Y").at("total").get<double>(), 0.13);
  EXPECT_DOUBLE_EQ(run.at("forces").at("Z").at("total").get<double>(), -0.04);
  // The provenance says where each setting came from: the .out's line.
  const auto shown = nlohmann::json::parse(run_cli({"runs", "show", std::to_string(run.at("id").get<int>()), "--json"},
                                                   dir.path())
                                               .out);
  const auto settings = shown.at("imports")[0].at("settings");
  EXPECT_EQ(settings.at("flow").at("source"), "case files") << settings.dump();
  EXPECT_NE(settings.at("flow").at("where").get<std::string>().find("tow_u1.5_001.out:72"), std::string::npos)
      << settings.dump();
  EXPECT_EQ(settings.at("axes").at("source"), "command line");

  // The same run from a folder walk: the monitor CSV takes the .out beside it (same bytes, same settings: nothing added).
  const auto again = run_cli({"import", "sweep", "--body", "hull", "--axes=-x,y,-z"}, dir.path());
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(nlohmann::json::parse(run_cli({"runs", "--json"}, dir.path()).out).size(), 1u);
}

TEST(CliCfxRun, ACaseFileWithoutItsMonitorsIsRefused) {
  TempDir dir;
  std::filesystem::copy_file(kOut, dir / "tow_u1.5_001.out");
  const auto result = run_cli({"import", "tow_u1.5_001.out", "--body", "hull"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("no monitor file beside it"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("cfx5mondata"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "hydrocoef.db") &&
               nlohmann::json::parse(run_cli({"runs", "--json"}, dir.path()).out).size() > 0);
}

TEST(CliCfxRun, ANormalSpeedWithoutADirectionIsRefusedAndTakesAGivenOne) {
  TempDir dir;
  std::string ccl;
  {
    std::ifstream in(kOut);
    ccl.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto at = ccl.find("Option = Cartesian Velocity Components");
  ASSERT_NE(at, std::string::npos);
  const auto end = ccl.find("W = 0 [m s^-1]", at);
  ccl.replace(at, end + 14 - at, "Option = Normal Speed\n           Normal Speed = 1.5 [m s^-1]");
  std::ofstream(dir / "run.out") << ccl;
  write_monitors(dir / "run.csv");
  const auto refused = run_cli({"import", "run.out", "--body", "hull", "--axes=-x,y,-z"}, dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("normal speed, 1.5 m/s"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--flow"), std::string::npos) << refused.err;
  const auto given = run_cli({"import", "run.out", "--body", "hull", "--axes=-x,y,-z", "--flow", "1.5,0,0"}, dir.path());
  ASSERT_EQ(given.exit_code, 0) << given.err;
  const auto runs = nlohmann::json::parse(run_cli({"runs", "--json"}, dir.path()).out);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_DOUBLE_EQ(runs[0].at("u").get<double>(), 1.5);
}

}  // namespace
}  // namespace hydrocoef
