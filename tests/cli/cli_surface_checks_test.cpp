// Physical checks of coefficient surfaces (src/surface/surface_checks): a
// Y(u, v) surface whose sway force pushes along the sway motion (dY/dv > 0,
// which ran a simulated body away in sway without a word) is warned at build
// and in `surface show`, with where; the same table with the sign of a
// damping force is not; the check spans every method.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;

void write_table(const std::filesystem::path& file, double sway_slope) {
  std::ofstream out(file);
  out << "u [m s^-1],v [m s^-1],X [N],Y [N]\n";
  for (const double u : {0.0, 0.1, 0.2, 0.3})
    for (const double v : {-0.1, 0.0, 0.1})
      out << u << "," << v << "," << -11.0 * u * u << "," << sway_slope * v << "\n";
}

TEST(SurfaceChecks, ASurfaceThatFeedsEnergyIntoSwayIsWarnedAtBuildAndShow) {
  test::TempDir dir;
  write_table(dir / "bad.csv", 2.0);
  write_table(dir / "good.csv", -2.0);
  ASSERT_EQ(run_cli({"import", (dir / "bad.csv").string(), "--body", "bad", "--sign", "on-body"}, dir.path()).exit_code,
            0);
  ASSERT_EQ(
      run_cli({"import", (dir / "good.csv").string(), "--body", "good", "--sign", "on-body"}, dir.path()).exit_code, 0);
  for (const char* method : {"linear", "pchip", "rbf", "gp"}) {
    SCOPED_TRACE(method);
    const std::string name = std::string("bad-") + method;
    const auto bad =
        run_cli({"surface", "build", name, "--body", "bad", "--outputs", "X,Y", "--axes", "u,v", "--method", method},
                dir.path());
    ASSERT_EQ(bad.exit_code, 0) << bad.err;
    EXPECT_NE(bad.out.find("WARNING (energy-producing): Y feeds energy into the motion along v"), std::string::npos)
        << bad.out;
    EXPECT_EQ(bad.out.find("X feeds energy"), std::string::npos) << bad.out;  // X = -11 u^2 opposes u >= 0
    const auto show = run_cli({"surface", "show", name}, dir.path());
    EXPECT_NE(show.out.find("Y feeds energy into the motion along v"), std::string::npos) << show.out;
    const auto json = nlohmann::json::parse(run_cli({"surface", "show", name, "--json"}, dir.path()).out);
    ASSERT_TRUE(json["quality"].contains("physical"));
    EXPECT_EQ(json["quality"]["physical"].size(), 1u);
    const auto good = run_cli({"surface", "build", std::string("good-") + method, "--body", "good", "--outputs", "X,Y",
                               "--axes", "u,v", "--method", method},
                              dir.path());
    ASSERT_EQ(good.exit_code, 0) << good.err;
    EXPECT_EQ(good.out.find("WARNING (energy-producing)"), std::string::npos) << good.out;
  }
}

TEST(SurfaceChecks, AVehicleRefusesADampingSurfaceThatFeedsEnergyUnlessAllowed) {
  test::TempDir dir;
  write_table(dir / "bad.csv", 2.0);
  ASSERT_EQ(run_cli({"import", (dir / "bad.csv").string(), "--body", "bad", "--sign", "on-body"}, dir.path()).exit_code,
            0);
  ASSERT_EQ(run_cli({"surface", "build", "sway", "--body", "bad", "--outputs", "X,Y", "--axes", "u,v", "--method",
                     "linear", "--extrapolate", "clamp"},
                    dir.path())
                .exit_code,
            0);
  const auto vehicle =
      [&](const std::string& extra) {
        std::ofstream(dir / "vehicle.json")
            << R"({"name": "box", "gravity": 9.81, "rho": 998.2, "mass": 10, "inertia": [1, 1, 1],
  "center_of_gravity": [0, 0, 0], "center_of_buoyancy": [0, 0, 0], "neutrally_buoyant": true,
  "added_mass": {"sphere_radius": 0.15},
  "damping": {"X": {"law": {"u": -1, "u|u|": -10}, "sign": "on-body"},
              "Y": {"surface": "sway", "output": "Y", "axes": {"u": "u", "v": "v"}, "sign": "on-body")"
            << extra << R"(},
              "Z": {"law": {"w": -1}, "sign": "on-body"}, "K": {"law": {"p": -1}, "sign": "on-body"},
              "M": {"law": {"q": -1}, "sign": "on-body"}, "N": {"law": {"r": -1}, "sign": "on-body"}}})";
      };
  std::ofstream(dir / "scenario.json") << R"({"name": "drift", "duration": 1.0, "output_rate": 10.0,
  "integrator": {"method": "rk4", "step": 0.01},
  "initial": {"position": [0, 0, 0], "euler_deg": [0, 0, 0], "velocity": [0.1, 0.01, 0, 0, 0, 0]},
  "segments": [{"start": 0.0, "tau": {"X": 0.1}}]})";
  const std::vector<std::string> simulate = {"simulate",
                                             "--vehicle",
                                             (dir / "vehicle.json").string(),
                                             "--scenario",
                                             (dir / "scenario.json").string(),
                                             "--out",
                                             (dir / "out.csv").string()};
  vehicle("");
  const auto refused = run_cli(simulate, dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
  EXPECT_NE(refused.err.find("surface 'sway': Y feeds energy into the motion along v"), std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("allow_unphysical"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));
  vehicle(R"(, "allow_unphysical": true)");
  const auto allowed = run_cli(simulate, dir.path());
  EXPECT_EQ(allowed.exit_code, 0) << allowed.err;
  vehicle(R"(, "allow_unphysical": "yes")");
  const auto wrong = run_cli(simulate, dir.path());
  EXPECT_EQ(wrong.exit_code, 2);
  EXPECT_NE(wrong.err.find("expected true or false"), std::string::npos) << wrong.err;
}

}  // namespace
}  // namespace hydrocoef
