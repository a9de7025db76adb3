// A body symmetric about its xz-plane, driven in surge alone, does not drift
// sideways when its damping comes from a surface built with --mirror v: the
// side force and yaw moment are exactly 0 on the plane v = r = 0 although
// the CFD run there carries a small side force (its mesh is not symmetric).
// The same runs without the mirror, written out on both sides, drift: the
// check would fail without the imposed symmetry.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;

double surge(double u, double v) { return -2.0 * u - 10.0 * u * std::abs(u) - 4.0 * v * v; }
double sway(double u, double v) { return v == 0.0 ? -0.0068 : -3.0 * v - 20.0 * v * std::abs(v) - 0.5 * u * v; }

void write_runs(const std::filesystem::path& file, bool both_sides) {
  std::ofstream out(file);
  out << "u [m s^-1],v [m s^-1],X [N],Y [N]\n";
  for (const double u : {0.0, 0.1, 0.2, 0.3})
    for (const double v : {0.0, 0.05, 0.1}) {
      out << u << "," << v << "," << surge(u, v) << "," << sway(u, v) << "\n";
      if (both_sides && v != 0.0) out << u << "," << -v << "," << surge(u, -v) << "," << -sway(u, v) << "\n";
    }
}

/// The largest |v| [m/s] and |y_n| [m] of a trajectory CSV.
std::pair<double, double> largest_sway(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  double v_max = 0.0, y_max = 0.0;
  while (std::getline(in, line)) {
    std::vector<double> cells;
    std::stringstream row(line);
    std::string cell;
    while (std::getline(row, cell, ',')) cells.push_back(std::stod(cell));
    y_max = std::max(y_max, std::abs(cells.at(2)));
    v_max = std::max(v_max, std::abs(cells.at(12)));
  }
  return {v_max, y_max};
}

std::pair<double, double> simulate_surge(const test::TempDir& dir, const std::string& db, const std::string& surface) {
  std::ofstream(dir / "vehicle.json")
      << R"({"name": "box", "gravity": 9.81, "rho": 998.2, "mass": 10, "inertia": [1, 1, 1],
  "center_of_gravity": [0, 0, 0], "center_of_buoyancy": [0, 0, 0], "neutrally_buoyant": true,
  "added_mass": {"sphere_radius": 0.15},
  "damping": {"X": {"surface": ")"
      << surface << R"(", "output": "X", "axes": {"u": "u", "v": "v"}, "sign": "on-body"},
              "Y": {"surface": ")"
      << surface << R"(", "output": "Y", "axes": {"u": "u", "v": "v"}, "sign": "on-body"},
              "Z": {"law": {"w": -1}, "sign": "on-body"}, "K": {"law": {"p": -1}, "sign": "on-body"},
              "M": {"law": {"q": -1}, "sign": "on-body"}, "N": {"law": {"r": -1}, "sign": "on-body"}}})";
  std::ofstream(dir / "scenario.json") << R"({"name": "surge", "duration": 5.0, "output_rate": 10.0,
  "integrator": {"method": "rk4", "step": 0.01},
  "initial": {"position": [0, 0, 0], "euler_deg": [0, 0, 0], "velocity": [0.1, 0, 0, 0, 0, 0]},
  "segments": [{"start": 0.0, "tau": {"X": 0.3}}]})";
  const auto run = run_cli({"--db", db, "simulate", "--vehicle", (dir / "vehicle.json").string(), "--scenario",
                            (dir / "scenario.json").string(), "--out", (dir / (surface + ".csv")).string()},
                           dir.path());
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return largest_sway(dir / (surface + ".csv"));
}

TEST(SurfaceSymmetryCli, ABodyDrivenInSurgeAloneDoesNotDriftSidewaysOnAMirroredSurface) {
  test::TempDir dir;
  write_runs(dir / "half.csv", false);
  write_runs(dir / "whole.csv", true);
  ASSERT_EQ(
      run_cli({"--db", "half.db", "import", "half.csv", "--body", "b", "--sign", "on-body"}, dir.path()).exit_code, 0);
  ASSERT_EQ(
      run_cli({"--db", "whole.db", "import", "whole.csv", "--body", "b", "--sign", "on-body"}, dir.path()).exit_code,
      0);
  for (const char* method : {"linear", "gp"}) {
    SCOPED_TRACE(method);
    const std::string name = std::string("mirrored-") + method;
    const auto built = run_cli({"--db", "half.db", "surface", "build", name, "--body", "b", "--outputs", "X,Y",
                                "--axes", "u,v", "--method", method, "--mirror", "v", "--extrapolate", "clamp"},
                               dir.path());
    ASSERT_EQ(built.exit_code, 0) << built.err;
    EXPECT_NE(built.out.find("v reflected: Y odd"), std::string::npos) << built.out;
    const auto query = run_cli({"--db", "half.db", "query", name, "u=0.2", "v=0", "--json"}, dir.path());
    ASSERT_EQ(query.exit_code, 0) << query.err;
    EXPECT_EQ(nlohmann::json::parse(query.out).at("values").at("Y").get<double>(), 0.0) << query.out;
    const auto [v_max, y_max] = simulate_surge(dir, "half.db", name);
    EXPECT_EQ(v_max, 0.0);
    EXPECT_EQ(y_max, 0.0);
  }
  // Without the mirror the run on the plane pushes the body sideways.
  ASSERT_EQ(run_cli({"--db", "whole.db", "surface", "build", "plain", "--body", "b", "--outputs", "X,Y", "--axes",
                     "u,v", "--method", "linear", "--extrapolate", "clamp"},
                    dir.path())
                .exit_code,
            0);
  const auto [v_max, y_max] = simulate_surge(dir, "whole.db", "plain");
  EXPECT_GT(v_max, 1e-4);
  EXPECT_GT(y_max, 1e-4);
}

}  // namespace
}  // namespace hydrocoef
