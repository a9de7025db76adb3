// End-to-end tests of surface exports through the hydrocoef binary:
// integrate and import real OpenFOAM results, frames and run keys, sidecars,
// folders, and bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/backend_under_test.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/sqlite_dump.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::TempDir;

const std::string kSphere = HYDROCOEF_DATA_DIR "/openfoam-sphere/";

nlohmann::json case_info(const std::string& folder) {
  std::ifstream in(kSphere + folder + "/case.json");
  return nlohmann::json::parse(in);
}

TEST(CliSurface, IntegrateReproducesOpenFoamForcesInItsOwnAxes) {
  TempDir dir;
  const std::string file = kSphere + "full/u0.10_v0.05/u0.10_v0.05_sphere_t1000.vtp";
  const auto result = run_cli({"integrate", file, "--rho", "998.2", "--json"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto out = nlohmann::json::parse(result.out);
  const auto info = case_info("full/u0.10_v0.05");
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_NEAR(out["force"][c].get<double>(), info["openfoam_final_force_N"]["total"][c].get<double>(), 2e-6);
    EXPECT_NEAR(out["force_viscous"][c].get<double>(), info["openfoam_final_force_N"]["viscous"][c].get<double>(),
                2e-6);
    EXPECT_NEAR(out["moment"][c].get<double>(), info["openfoam_final_moment_Nm"]["total"][c].get<double>(), 2e-7);
  }
  EXPECT_EQ(out["faces"], 4024);
  EXPECT_EQ(out["closed"], true);
  EXPECT_EQ(out["normals_flipped"], true);
  EXPECT_EQ(out["pressure_array"], "p");
  EXPECT_EQ(out["pressure_kind"], "kinematic");
  EXPECT_EQ(out["shear_convention"], "on-fluid");
  EXPECT_NEAR(out["area"].get<double>(), 4 * 3.14159265358979 * 0.15 * 0.15, 0.03 * 0.2827);
  EXPECT_FALSE(test::database_exists(dir / "hydrocoef.db"));  // integrate stores nothing

  const auto text = run_cli({"integrate", file, "--rho", "998.2"}, dir.path());
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_NE(text.out.find("force viscous"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("closed"), std::string::npos) << text.out;
}

TEST(CliSurface, BodyAxesAndTheRunKeyFollowTheFlow) {
  // OpenFOAM: x along the stream, z up. Body: x forward into the stream, z
  // down, so body = (-x, y, -z) and the body moves at minus the stream.
  TempDir dir;
  const std::string file = kSphere + "full/u0.10_v0.05/u0.10_v0.05_sphere_t1000.vtp";
  const auto result = run_cli({"import", file, "--body", "sphere", "--rho", "998.2", "--nu", "1.004e-6", "--axes",
                               "-x,y,-z", "--flow", "0.1,0.05,0", "--json"},
                              dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto runs = nlohmann::json::parse(run_cli({"runs", "--json"}, dir.path()).out);
  ASSERT_EQ(runs.size(), 1u);
  const auto& run = runs[0];
  EXPECT_DOUBLE_EQ(run["u"].get<double>(), 0.1);    // forward, into the stream
  EXPECT_DOUBLE_EQ(run["v"].get<double>(), -0.05);  // the stream comes from +y: the body moves to -y
  const auto info = case_info("full/u0.10_v0.05");
  const auto& force = info["openfoam_final_force_N"]["total"];
  const auto& moment = info["openfoam_final_moment_Nm"]["total"];
  EXPECT_NEAR(run["forces"]["X"]["total"].get<double>(), -force[0].get<double>(), 2e-6);  // drag: X < 0
  EXPECT_LT(run["forces"]["X"]["total"].get<double>(), 0.0);
  EXPECT_NEAR(run["forces"]["Y"]["total"].get<double>(), force[1].get<double>(), 2e-6);
  EXPECT_NEAR(run["forces"]["Z"]["total"].get<double>(), -force[2].get<double>(), 2e-6);
  EXPECT_NEAR(run["forces"]["N"]["total"].get<double>(), -moment[2].get<double>(), 2e-7);
  EXPECT_NEAR(run["forces"]["X"]["viscous"].get<double>(), -info["openfoam_final_force_N"]["viscous"][0].get<double>(),
              2e-6);
  EXPECT_EQ(run["forces"]["X"]["sign_convention"], "on-body");
  EXPECT_DOUBLE_EQ(run["density"].get<double>(), 998.2);
}

TEST(CliSurface, AFolderWithSidecarsImportsInParallelInOneTransaction) {
  TempDir dir;
  const std::vector<std::pair<std::string, std::array<double, 2>>> cases = {{"u0.10_v0.00", {0.1, 0.0}},
                                                                            {"u0.10_v0.05", {0.1, 0.05}},
                                                                            {"u0.20_v0.10", {0.2, 0.1}},
                                                                            {"u0.30_v0.00", {0.3, 0.0}}};
  for (const auto& [name, flow] : cases) {
    const auto folder = dir / "sweep" / name;
    std::filesystem::create_directories(folder);
    std::filesystem::copy_file(kSphere + "full/" + name + "/" + name + "_sphere_t1000.vtp", folder / "sphere.vtp");
    std::ofstream(folder / "hydrocoef-run.json") << nlohmann::json{
        {"body", "sphere"},
        {"axes", "-x,y,-z"},
        {"flow", {flow[0], flow[1], 0.0}},
        {"rho", 998.2}}.dump();
  }
  const auto result = run_cli({"import", (dir / "sweep").string(), "--jobs", "2", "--json"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto out = nlohmann::json::parse(result.out);
  EXPECT_EQ(out["files"].size(), 4u);
  const auto runs = nlohmann::json::parse(run_cli({"runs", "--body", "sphere", "--json"}, dir.path()).out);
  ASSERT_EQ(runs.size(), 4u);
  for (const auto& [name, flow] : cases) {
    bool found = false;
    for (const auto& run : runs)
      found =
          found || (run["u"].get<double>() == flow[0] && run["v"].get<double>() == (flow[1] == 0.0 ? 0.0 : -flow[1]));
    EXPECT_TRUE(found) << name;
  }
  // Drag grows with speed: X at u = 0.3 is more negative than at u = 0.1.
  double x_slow = 0, x_fast = 0;
  for (const auto& run : runs) {
    if (run["u"] == 0.1 && run["v"] == 0.0) x_slow = run["forces"]["X"]["total"];
    if (run["u"] == 0.3) x_fast = run["forces"]["X"]["total"];
  }
  EXPECT_LT(x_fast, 3.0 * x_slow);

  // A folder with one bad file imports nothing.
  TempDir other;
  std::filesystem::create_directories(other / "sweep");
  std::filesystem::copy_file(kSphere + "full/u0.10_v0.00/u0.10_v0.00_sphere_t1000.vtp", other / "sweep" / "a.vtp");
  std::ofstream(other / "sweep" / "b.vtp") << "<VTKFile type=\"PolyData\"><PolyData><Piece NumberOfPoints=\"3\"";
  const auto bad = run_cli({"import", (other / "sweep").string(), "--rho", "998.2", "--set", "u=0.1"}, other.path());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("b.vtp"), std::string::npos) << bad.err;
  EXPECT_FALSE(test::database_exists(other / "hydrocoef.db"));
}

TEST(CliSurface, SameFileTwiceIsANoOpAndBadOptionsAreNamed) {
  TempDir dir;
  const std::string file = kSphere + "quarter/U0.1000/U0.1000_sphere_t145.vtp";
  ASSERT_EQ(run_cli({"import", file, "--rho", "998.2", "--set", "u=0.1"}, dir.path()).exit_code, 0);
  const auto before = test::dump_database(dir / "hydrocoef.db");
  const auto again = run_cli({"import", file, "--rho", "998.2", "--set", "u=0.1"}, dir.path());
  EXPECT_EQ(again.exit_code, 0);
  EXPECT_NE(again.out.find("already imported"), std::string::npos);
  EXPECT_EQ(test::dump_database(dir / "hydrocoef.db"), before);

  const auto no_rho = run_cli({"integrate", file}, dir.path());
  EXPECT_EQ(no_rho.exit_code, 2);
  EXPECT_NE(no_rho.err.find("--rho"), std::string::npos) << no_rho.err;
  EXPECT_NE(no_rho.err.find("U0.1000_sphere_t145.vtp"), std::string::npos) << no_rho.err;

  const auto missing = run_cli({"integrate", file, "--rho", "998.2", "--pressure", "Pressure"}, dir.path());
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("'Pressure' is not in the file"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("'wallShearStress'"), std::string::npos) << missing.err;

  const auto mirror = run_cli({"integrate", file, "--rho", "998.2", "--axes", "x,y,-z"}, dir.path());
  EXPECT_EQ(mirror.exit_code, 2);
  EXPECT_NE(mirror.err.find("mirror"), std::string::npos) << mirror.err;

  // The quarter sphere is open: reported, and oriented from its cone volume.
  const auto quarter = nlohmann::json::parse(run_cli({"integrate", file, "--rho", "998.2", "--json"}, dir.path()).out);
  EXPECT_EQ(quarter["closed"], false);
  EXPECT_GT(quarter["boundary_edges"].get<int>(), 0);
  EXPECT_GT(quarter["force"][0].get<double>(), 0.0);  // drag along the stream
}

}  // namespace
}  // namespace hydrocoef
