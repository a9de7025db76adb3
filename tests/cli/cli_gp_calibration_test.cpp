// GP surfaces whose stated sd holds on real runs they have not seen
// (src/surface/gp_surface.hpp: a discrepancy sd estimated on top of each
// run's standard error, length scales bounded by a prior on the runs' span,
// the leave-one-out calibration and the few-run t factor). The data: twelve
// steady RANS runs of the sphere in a half domain over (u, v)
// (data/openfoam-sphere/converged/sweep), whose wakes swing from side to side
// so that each force is a window mean with a standard error that understates
// how far a run lands from its neighbours (the sway force of a bistable wake).
// - Every output's leave-one-out standardized residuals have RMS in [0.5, 2]
//   and none beyond 4 (surface show's calibration).
// - Built from every other run, the surface's new-run sd covers at least 80 %
//   of the other six runs (both outputs) within 2 sd (with each run's own
//   standard error).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::run_cli;
const fs::path kSweep = fs::path(HYDROCOEF_SOURCE_DIR) / "data/openfoam-sphere/converged/sweep";

class GpCalibration : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto r = run_cli({"import", kSweep.string(), "--body", "sphere", "--quiet"}, dir_.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    runs_ = json::parse(run_cli({"runs", "--json"}, dir_.path()).out);
    ASSERT_EQ(runs_.size(), 12u);
  }
  test::TempDir dir_;
  json runs_;
};

TEST_F(GpCalibration, LeaveOneOutResidualsAreThoseOfAStatedSdThatHolds) {
  const auto build = run_cli({"surface", "build", "sweep", "--body", "sphere", "--outputs", "X,Y", "--axes", "u,v",
                              "--method", "gp", "--json"},
                             dir_.path());
  ASSERT_EQ(build.exit_code, 0) << build.err;
  const json gp = json::parse(build.out)["gp"]["outputs"];
  for (const char* output : {"X", "Y"}) {
    SCOPED_TRACE(output);
    const double rms = gp[output]["loo_rms_z"], largest = gp[output]["loo_max_z"];
    std::cout << output << ": leave-one-out z RMS " << rms << ", largest " << largest << ", discrepancy sd "
              << gp[output]["discrepancy_sd"] << ", sd factor " << gp[output]["sd_factor"] << "\n";
    EXPECT_GE(rms, 0.5);
    EXPECT_LE(rms, 2.0);
    EXPECT_LE(largest, 4.0);
    EXPECT_TRUE(gp[output]["calibrated"].get<bool>());
  }
}

TEST_F(GpCalibration, HalfTheRunsPredictTheOtherHalfWithinTwoSd) {
  // Every other run (in the order of their keys) held out.
  std::vector<json> sorted(runs_.begin(), runs_.end());
  std::sort(sorted.begin(), sorted.end(), [](const json& a, const json& b) {
    return std::pair{a["u"].get<double>(), a["v"].get<double>()} <
           std::pair{b["u"].get<double>(), b["v"].get<double>()};
  });
  // Held-out runs at the range's ends are extrapolated to (the sd grows there).
  std::vector<std::string> args = {"surface", "build", "half",     "--body", "sphere",        "--outputs",  "X,Y",
                                   "--axes",  "u,v",   "--method", "gp",     "--extrapolate", "extrapolate"};
  std::vector<json> held_out;
  for (std::size_t i = 0; i < sorted.size(); ++i)
    if (i % 2 == 1) {
      held_out.push_back(sorted[i]);
      args.push_back("--exclude-run");
      args.push_back(std::to_string(sorted[i]["id"].get<int>()));
    }
  const auto build = run_cli(args, dir_.path());
  ASSERT_EQ(build.exit_code, 0) << build.err;
  std::size_t covered = 0, checked = 0;
  for (const auto& run : held_out) {
    const double u = run["u"], v = run["v"];
    const auto q = run_cli({"query", "half", "u=" + json(u).dump(), "v=" + json(v).dump(), "--uncertainty", "--json"},
                           dir_.path());
    ASSERT_EQ(q.exit_code, 0) << q.err;
    const json answer = json::parse(q.out);
    for (const char* output : {"X", "Y"}) {
      const double value = run["forces"][output]["total"];
      const double own = run["forces"][output]["standard_uncertainty"];
      const double sd = answer["new_run_standard_deviation"][output];
      const double mean = answer["values"][output];
      const double z = (value - mean) / std::sqrt(sd * sd + own * own);
      std::cout << output << " at u=" << u << " v=" << v << ": run " << value << ", surface " << mean << " +- " << sd
                << " (z = " << z << ")\n";
      covered += std::abs(z) <= 2.0 ? 1 : 0;
      ++checked;
    }
  }
  ASSERT_EQ(checked, 12u);
  EXPECT_GE(static_cast<double>(covered) / static_cast<double>(checked), 0.8) << covered << " of " << checked;
}

}  // namespace
}  // namespace hydrocoef
