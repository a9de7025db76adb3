// End-to-end Monte Carlo: the ASR-V yaw law fitted and stored, named by a
// vehicle file ("fit": NAME), drawn by `equilibrium --samples` and
// `simulate --samples`. The equilibrium's spread is checked against the
// first-order propagation of the stored covariance (independent of the
// sampling code); the bands reach the trajectory CSV and the plot; what
// cannot be sampled fails with one line and exit code 2.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::TempDir;

const std::string kExample = HYDROCOEF_SOURCE_DIR "/examples/asr-v/";
const std::string kFit = "asr-v:N(1,r,r|r|)";

/// A database with the yaw table and its fit, and a vehicle file whose yaw
/// damping is that stored fit (everything else as the example's vehicle).
struct Fixture {
  TempDir dir;
  std::string db = (dir.path() / "runs.db").string();
  std::string vehicle = (dir.path() / "vehicle-fit.json").string();
  Fixture() {
    const auto imported = run_cli({"--db", db, "import", kExample + "asr-v-yaw-damping.csv", "--body", "asr-v",
                                   "--sign", "on-body", "--rho", "998.2", "--nu", "1.004e-6"},
                                  dir.path());
    EXPECT_EQ(imported.exit_code, 0) << imported.err;
    const auto fitted =
        run_cli({"--db", db, "fit", "--body", "asr-v", "--dof", "N", "--terms", "1,r,r|r|"}, dir.path());
    EXPECT_EQ(fitted.exit_code, 0) << fitted.err;
    std::ifstream in(kExample + "vehicle.json");
    nlohmann::json doc = nlohmann::json::parse(in, nullptr, true, true);
    doc["damping"]["N"] = {{"fit", kFit}};
    std::ofstream(vehicle) << doc.dump(2);
  }
  nlohmann::json stored_fit() const {
    const auto fits = run_cli({"--db", db, "fits", "--json"}, dir.path());
    EXPECT_EQ(fits.exit_code, 0) << fits.err;
    for (const auto& f : nlohmann::json::parse(fits.out))
      if (f.at("name") == kFit) return f;
    ADD_FAILURE() << "no stored fit " << kFit;
    return {};
  }
};

TEST(CliMonteCarlo, HelpNamesTheSamplingOptions) {
  TempDir dir;
  for (const std::string command : {"simulate", "equilibrium"}) {
    const auto help = run_cli({command, "--help"}, dir.path());
    EXPECT_EQ(help.exit_code, 0);
    for (const char* option : {"--samples", "--seed", "--percentiles"})
      EXPECT_NE(help.out.find(option), std::string::npos) << command << " " << option;
  }
}

// r solves c + a r + b r|r| + tau = 0; to first order its variance is
// g^T Sigma g with g = -dF/dtheta / (dF/dr), dF/dtheta = (1, r, r|r|).
TEST(CliMonteCarlo, EquilibriumSpreadIsTheFitCovariancePropagated) {
  Fixture f;
  const auto eq = run_cli({"--db", f.db, "equilibrium", "--vehicle", f.vehicle, "--tau", "N=0.0027", "--samples",
                           "1000", "--seed", "3", "--json"},
                          f.dir.path());
  ASSERT_EQ(eq.exit_code, 0) << eq.err;
  const auto out = nlohmann::json::parse(eq.out);
  const double r = out.at("velocity").at("r").get<double>();
  const auto& mc = out.at("monte_carlo");
  EXPECT_EQ(mc.at("used"), 1000);
  EXPECT_EQ(mc.at("failed"), 0);
  ASSERT_EQ(mc.at("drawn").size(), 1u);
  EXPECT_NE(mc.at("drawn")[0].get<std::string>().find(kFit), std::string::npos);

  const auto fit = f.stored_fit();
  const auto& c = fit.at("coefficients");
  const double a = c.at("r").get<double>(), b = c.at("r|r|").get<double>();
  const auto cov = fit.at("covariance").get<std::vector<double>>();
  ASSERT_EQ(cov.size(), 9u);
  const Eigen::Map<const Eigen::Matrix3d> sigma(cov.data());
  const Eigen::Vector3d g = -Eigen::Vector3d(1.0, r, r * std::abs(r)) / (a + 2.0 * b * std::abs(r));
  const double sd = std::sqrt(g.dot(sigma * g));
  ASSERT_GT(sd, 0.0);
  const double n = 1000.0;
  EXPECT_NEAR(mc.at("mean").at("r").get<double>(), r, 4.0 * sd / std::sqrt(n));
  // First order is exact to a few per cent here; the sample sd scatters ~2 %.
  EXPECT_NEAR(mc.at("standard_deviation").at("r").get<double>(), sd, 0.1 * sd);
  const double low = mc.at("velocity_percentiles").at("p2.5").at("r").get<double>();
  const double high = mc.at("velocity_percentiles").at("p97.5").at("r").get<double>();
  EXPECT_LT(low, r);
  EXPECT_GT(high, r);
  EXPECT_NEAR(high - low, 2.0 * 1.959964 * sd, 0.15 * (high - low));

  // The same seed gives the same draws; another seed others.
  const auto again = run_cli({"--db", f.db, "equilibrium", "--vehicle", f.vehicle, "--tau", "N=0.0027", "--samples",
                              "1000", "--seed", "3", "--json"},
                             f.dir.path());
  EXPECT_EQ(nlohmann::json::parse(again.out).at("monte_carlo").at("velocity_percentiles"),
            mc.at("velocity_percentiles"));
  const auto other = run_cli({"--db", f.db, "equilibrium", "--vehicle", f.vehicle, "--tau", "N=0.0027", "--samples",
                              "1000", "--seed", "4", "--json"},
                             f.dir.path());
  EXPECT_NE(nlohmann::json::parse(other.out).at("monte_carlo").at("velocity_percentiles"),
            mc.at("velocity_percentiles"));

  // The readable form names what was drawn and what was held.
  const auto text = run_cli(
      {"--db", f.db, "equilibrium", "--vehicle", f.vehicle, "--tau", "N=0.0027", "--samples", "50"}, f.dir.path());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("drawn: N: law 1,r,r|r|"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("held:  X: law u,u|u|"), std::string::npos) << text.out;
}

TEST(CliMonteCarlo, SimulateWritesBandsThatPlotDraws) {
  Fixture f;
  std::ofstream(f.dir.path() / "short.json") << R"({"duration": 4.0, "output_rate": 5.0,
    "integrator": {"method": "rk4", "step": 0.01},
    "initial": {"position": [0, 0, 0], "euler_deg": [0, 0, 0], "velocity": [0, 0, 0, 0, 0, 0]},
    "segments": [{"start": 0.0, "tau": {"N": 0.0027}}]})";
  const std::string csv = (f.dir.path() / "traj.csv").string();
  const auto sim =
      run_cli({"--db", f.db, "simulate", "--vehicle", f.vehicle, "--scenario", (f.dir.path() / "short.json").string(),
               "--samples", "12", "--percentiles", "10,50,90", "--out", csv, "--json"},
              f.dir.path());
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const auto out = nlohmann::json::parse(sim.out);
  const auto& final_r = out.at("monte_carlo").at("final").at("percentiles").at("r");
  EXPECT_LE(final_r.at("p10").get<double>(), final_r.at("p50").get<double>());
  EXPECT_LE(final_r.at("p50").get<double>(), final_r.at("p90").get<double>());
  EXPECT_LT(final_r.at("p10").get<double>(), final_r.at("p90").get<double>());
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  for (const char* column : {"r_p10 [rad s^-1]", "r_p50 [rad s^-1]", "r_p90 [rad s^-1]", "psi_p90 [rad]"})
    EXPECT_NE(header.find(column), std::string::npos) << column;

  const auto plot =
      run_cli({"plot", "simulation", "--trajectory", csv, "--component", "r", "-o", (f.dir.path() / "r.svg").string()},
              f.dir.path());
  ASSERT_EQ(plot.exit_code, 0) << plot.err;
  std::ifstream data(f.dir.path() / "r.dat");
  const std::string text((std::istreambuf_iterator<char>(data)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("p10-p90"), std::string::npos);
  EXPECT_NE(text.find("# x y_low y_high"), std::string::npos);
}

TEST(CliMonteCarlo, WhatCannotBeSampledFailsWithOneLine) {
  Fixture f;
  auto expect_one_line = [&](const std::vector<std::string>& args, const std::string& expected) {
    const auto r = run_cli(args, f.dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  };
  // The example vehicle's laws carry no covariance.
  expect_one_line(
      {"--db", f.db, "equilibrium", "--vehicle", kExample + "vehicle.json", "--tau", "N=0.0027", "--samples", "10"},
      "nothing in the vehicle's damping has an uncertainty");
  expect_one_line({"--db", f.db, "equilibrium", "--vehicle", f.vehicle, "--tau", "N=0.0027", "--samples", "10",
                   "--percentiles", "50,5"},
                  "expected increasing percentiles");
  expect_one_line({"--db", f.db, "equilibrium", "--vehicle", f.vehicle, "--tau", "N=0.0027", "--samples", "1"},
                  "--samples 1");
  // A fit that is not stored, and one of another DOF.
  std::ifstream in(f.vehicle);
  nlohmann::json doc = nlohmann::json::parse(in);
  doc["damping"]["N"] = {{"fit", "no-such-fit"}};
  std::ofstream(f.dir.path() / "missing.json") << doc.dump();
  expect_one_line(
      {"--db", f.db, "equilibrium", "--vehicle", (f.dir.path() / "missing.json").string(), "--tau", "N=0.0027"},
      "fits of N: " + kFit);
  doc["damping"].erase("N");
  doc["damping"]["K"] = {{"fit", kFit}};
  std::ofstream(f.dir.path() / "other-dof.json") << doc.dump();
  expect_one_line(
      {"--db", f.db, "equilibrium", "--vehicle", (f.dir.path() / "other-dof.json").string(), "--tau", "N=0.0027"},
      "expected a fit of K");
  // A covariance that is not one, given in the vehicle file.
  doc["damping"]["K"] = {{"law", {{"p", -0.006}}}, {"sign", "on-body"}, {"covariance", {{-1e-6}}}};
  std::ofstream(f.dir.path() / "bad-cov.json") << doc.dump();
  expect_one_line(
      {"--db", f.db, "equilibrium", "--vehicle", (f.dir.path() / "bad-cov.json").string(), "--tau", "N=0.0027"},
      "damping.K.covariance");
}

}  // namespace
}  // namespace hydrocoef
