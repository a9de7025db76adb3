// The dynamics and plotting operations of the public API
// (include/hydrocoef/simulation.hpp, plot.hpp) against the CLI on the same
// database: `simulate` with Monte Carlo bands and a comparison with a measured
// record, `equilibrium` with its distribution over the draws, the plots. Each
// is driven through the API and through the CLI; the numbers of the public
// fields must be the numbers `--json` prints, and json() must be what the CLI
// prints apart from the wall-clock times. Options are refused by validate()
// with the CLI's message.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "hydrocoef/hydrocoef.hpp"
#include "tests/support/api_errors.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

using hydrocoef::test::cli_error;
using hydrocoef::test::error_of;

using hydrocoef::test::run_cli;
using hydrocoef::test::TempDir;

const std::string kAsrV = std::string(HYDROCOEF_SOURCE_DIR) + "/examples/asr-v/";
const std::string kFit = "asr-v:N(1,r,r|r|)";
const char* const kVelocity[] = {"u", "v", "w", "p", "q", "r"};
const char* const kForce[] = {"X", "Y", "Z", "K", "M", "N"};

/// The document without its wall-clock times (the one thing two runs differ in).
nlohmann::json without_wall_times(nlohmann::json doc) {
  if (doc.is_object()) {
    doc.erase("wall_time_s");
    for (auto& [key, value] : doc.items()) value = without_wall_times(value);
  }
  return doc;
}

/// The ASR-V yaw table imported and its law fitted through the API, and a
/// vehicle whose yaw damping is that stored fit (it has a covariance to draw from).
class SimulationApiTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto db = hydrocoef::Database::open(db_, hydrocoef::OpenMode::Create);
    hydrocoef::ImportOptions yaw;
    yaw.body = "asr-v";
    yaw.settings = {{"sign", "on-body"}, {"rho", "998.2"}, {"nu", "1.004e-6"}};
    db.import_files({kAsrV + "asr-v-yaw-damping.csv"}, yaw);
    hydrocoef::FitOptions fit;
    fit.body = "asr-v";
    fit.output = "N";
    fit.terms = "1,r,r|r|";
    ASSERT_EQ(db.fit(fit).name, kFit);
    db.close();
    std::ifstream in(kAsrV + "vehicle.json");
    nlohmann::json doc = nlohmann::json::parse(in, nullptr, true, true);
    doc["damping"]["N"] = {{"fit", kFit}};
    std::ofstream(vehicle_) << doc.dump(2);
    std::ifstream scenario_in(kAsrV + "scenario-yaw-0.0027.json");
    nlohmann::json scenario = nlohmann::json::parse(scenario_in, nullptr, true, true);
    scenario["duration"] = 4.0;
    std::ofstream(scenario_) << scenario.dump(2);
  }

  hydrocoef::test::CliResult cli(std::vector<std::string> args) {
    args.insert(args.begin(), {"--db", db_});
    return run_cli(args, dir_.path());
  }

  TempDir dir_;
  std::string db_ = (dir_ / "runs.db").string();
  std::string vehicle_ = (dir_ / "vehicle-fit.json").string();
  std::string scenario_ = (dir_ / "short.json").string();
};

TEST_F(SimulationApiTest, SimulateWithSamplesGivesTheCliNumbers) {
  // A measured record to compare with: the nominal run itself, written by the CLI.
  const std::string measured = (dir_ / "measured.csv").string();
  ASSERT_EQ(cli({"simulate", "--vehicle", vehicle_, "--scenario", scenario_, "--out", measured}).exit_code, 0);

  hydrocoef::SimulateOptions options;
  options.vehicle = vehicle_;
  options.scenario = scenario_;
  options.database = db_;
  options.experiment = measured;
  options.trajectory_csv = (dir_ / "api.csv").string();
  options.sampling.samples = 12;
  options.sampling.seed = 7;
  options.sampling.percentiles = {10, 50, 90};
  std::size_t progress_calls = 0;
  options.sampling.progress = [&](std::size_t, std::size_t) { ++progress_calls; };
  const hydrocoef::SimulationOutcome outcome = hydrocoef::simulate(options);
  EXPECT_EQ(progress_calls, 12u);

  const auto result =
      cli({"simulate", "--vehicle", vehicle_, "--scenario", scenario_, "--experiment", measured, "--out",
           (dir_ / "cli.csv").string(), "--samples", "12", "--seed", "7", "--percentiles", "10,50,90", "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  nlohmann::json from_cli = nlohmann::json::parse(result.out);
  nlohmann::json from_api = nlohmann::json::parse(outcome.json());
  from_cli.erase("trajectory");  // the CSVs' names differ
  from_api.erase("trajectory");
  EXPECT_EQ(without_wall_times(from_api), without_wall_times(from_cli));

  // The public fields hold the numbers the document prints.
  EXPECT_EQ(outcome.steps, from_cli.at("steps").get<std::size_t>());
  EXPECT_EQ(outcome.evaluations, from_cli.at("evaluations").get<std::size_t>());
  const auto& final_state = from_cli.at("final");
  const std::size_t last = outcome.trajectory.rows - 1;
  EXPECT_EQ(outcome.trajectory.column("t")[last], final_state.at("t").get<double>());
  for (const char* name : kVelocity)
    EXPECT_EQ(outcome.trajectory.column(name)[last], final_state.at("velocity").at(name).get<double>()) << name;
  ASSERT_EQ(outcome.comparison.size(), from_cli.at("comparison").size());
  for (std::size_t i = 0; i < outcome.comparison.size(); ++i) {
    EXPECT_EQ(outcome.comparison[i].component, from_cli["comparison"][i].at("component").get<std::string>());
    EXPECT_EQ(outcome.comparison[i].rms_error, from_cli["comparison"][i].at("rms_error").get<double>());
    EXPECT_EQ(outcome.comparison[i].rms_error, 0.0);  // the record is the nominal run
  }
  ASSERT_TRUE(outcome.sampled);
  const auto& mc = from_cli.at("monte_carlo");
  EXPECT_EQ(outcome.monte_carlo.used, mc.at("used").get<std::size_t>());
  EXPECT_EQ(outcome.monte_carlo.seed, 7u);
  EXPECT_EQ(outcome.monte_carlo.drawn, mc.at("drawn").get<std::vector<std::string>>());
  const std::size_t times = outcome.band_t_s.size(), percentiles = outcome.monte_carlo.percentiles.size();
  ASSERT_EQ(percentiles, 3u);
  for (std::size_t q = 0; q < outcome.band_quantities.size(); ++q)
    for (std::size_t j = 0; j < percentiles; ++j) {
      const std::string label = std::vector<std::string>{"p10", "p50", "p90"}[j];
      EXPECT_EQ(outcome.band_values[(q * percentiles + j) * times + times - 1],
                mc.at("final").at("percentiles").at(outcome.band_quantities[q]).at(label).get<double>())
          << outcome.band_quantities[q] << " " << label;
    }
  // The yaw rate's band is a band: the draws differ.
  std::size_t r = 0;
  while (outcome.band_quantities[r] != "r") ++r;
  EXPECT_LT(outcome.band_values[(r * percentiles + 0) * times + times - 1],
            outcome.band_values[(r * percentiles + 2) * times + times - 1]);
  EXPECT_EQ(outcome.measured_inside_band.at("r"), mc.at("measured_inside_band").at("r").get<double>());

  // The CSVs both wrote hold the same numbers.
  std::ifstream api_csv(options.trajectory_csv), cli_csv(dir_ / "cli.csv");
  std::stringstream a, b;
  a << api_csv.rdbuf();
  b << cli_csv.rdbuf();
  EXPECT_EQ(a.str(), b.str());
}

TEST_F(SimulationApiTest, EquilibriumWithSamplesGivesTheCliNumbers) {
  hydrocoef::EquilibriumOptions options;
  options.vehicle = vehicle_;
  options.database = db_;
  options.tau = {{"N", 0.0027}};
  options.current = {{"v", 0.01}};
  options.attitude_deg = {0.0, 0.0, 30.0};
  options.sampling.samples = 40;
  options.sampling.seed = 3;
  const hydrocoef::EquilibriumOutcome outcome = hydrocoef::equilibrium(options);
  const auto result = cli({"equilibrium", "--vehicle", vehicle_, "--tau", "N=0.0027", "--current", "v=0.01",
                           "--attitude-deg", "0,0,30", "--samples", "40", "--seed", "3", "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json from_cli = nlohmann::json::parse(result.out);
  EXPECT_EQ(without_wall_times(nlohmann::json::parse(outcome.json())), without_wall_times(from_cli));
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(outcome.velocity[i], from_cli.at("velocity").at(kVelocity[i]).get<double>()) << kVelocity[i];
    EXPECT_EQ(outcome.relative_velocity[i], from_cli.at("relative_velocity").at(kVelocity[i]).get<double>());
    EXPECT_EQ(outcome.damping[i], from_cli.at("damping").at(kForce[i]).get<double>()) << kForce[i];
    EXPECT_EQ(outcome.mean[i], from_cli.at("monte_carlo").at("mean").at(kVelocity[i]).get<double>());
    EXPECT_EQ(outcome.standard_deviation[i],
              from_cli.at("monte_carlo").at("standard_deviation").at(kVelocity[i]).get<double>());
    EXPECT_EQ(outcome.velocity_percentiles[0][i],
              from_cli.at("monte_carlo").at("velocity_percentiles").at("p2.5").at(kVelocity[i]).get<double>());
  }
  // Steady yaw: damping balances the moment applied.
  EXPECT_NEAR(outcome.damping[5], -0.0027, 1e-9);
  EXPECT_GT(outcome.standard_deviation[5], 0.0);
  EXPECT_EQ(outcome.monte_carlo.percentiles, (std::vector<double>{2.5, 50.0, 97.5}));
  // The text is the CLI's text but for the wall time.
  const auto text = cli({"equilibrium", "--vehicle", vehicle_, "--tau", "N=0.0027"});
  options.sampling.samples = 0;
  options.current.clear();
  options.attitude_deg = {0.0, 0.0, 0.0};
  EXPECT_EQ(hydrocoef::equilibrium(options).text(), text.out);
}

TEST_F(SimulationApiTest, BadOptionsAreRefusedWithTheCliMessage) {
  hydrocoef::SimulateOptions simulate;
  simulate.vehicle = vehicle_;
  simulate.scenario = scenario_;
  simulate.database = db_;
  simulate.steady_fraction = 0.0;
  EXPECT_EQ(error_of([&] { simulate.validate(); }),
            cli_error(cli({"simulate", "--vehicle", vehicle_, "--scenario", scenario_, "--steady-fraction", "0"})));
  simulate.steady_fraction = 0.2;
  simulate.sampling.samples = 1;
  EXPECT_EQ(error_of([&] { hydrocoef::simulate(simulate); }),
            cli_error(cli({"simulate", "--vehicle", vehicle_, "--scenario", scenario_, "--samples", "1"})));
  simulate.sampling.samples = 5;
  simulate.sampling.percentiles = {50, 10};
  EXPECT_EQ(error_of([&] { simulate.validate(); }),
            cli_error(cli({"simulate", "--vehicle", vehicle_, "--scenario", scenario_, "--samples", "5",
                           "--percentiles", "50,10"})));

  hydrocoef::EquilibriumOptions eq;
  eq.vehicle = vehicle_;
  eq.database = db_;
  eq.tau = {{"Q", 1.0}};
  EXPECT_EQ(error_of([&] { eq.validate(); }), cli_error(cli({"equilibrium", "--vehicle", vehicle_, "--tau", "Q=1"})));
  eq.tau = {{"N", 0.0027}};
  eq.current = {{"p", 0.5}};
  EXPECT_EQ(error_of([&] { eq.validate(); }),
            cli_error(cli({"equilibrium", "--vehicle", vehicle_, "--tau", "N=0.0027", "--current", "p=0.5"})));
  eq.current.clear();
  eq.disturbances = {{"current_v", 0.1}};
  EXPECT_EQ(
      error_of([&] { hydrocoef::equilibrium(eq); }),
      cli_error(cli({"equilibrium", "--vehicle", vehicle_, "--tau", "N=0.0027", "--disturbance", "current_v=0.1"})));
  // The example's laws carry no covariance: nothing to draw.
  eq.disturbances.clear();
  eq.vehicle = kAsrV + "vehicle.json";
  eq.sampling.samples = 10;
  EXPECT_EQ(
      error_of([&] { hydrocoef::equilibrium(eq); }),
      cli_error(cli({"equilibrium", "--vehicle", kAsrV + "vehicle.json", "--tau", "N=0.0027", "--samples", "10"})));
}

TEST_F(SimulationApiTest, PlotsWriteWhatTheCliWrites) {
  auto db = hydrocoef::Database::open(db_, hydrocoef::OpenMode::ReadOnly);
  hydrocoef::ImageOptions image;
  image.image = (dir_ / "api-fit.svg").string();
  const hydrocoef::PlotFiles files = hydrocoef::plot_fit(db, kFit, image);
  const auto result = cli({"plot", "fit", kFit, "-o", (dir_ / "cli-fit.svg").string(), "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json from_cli = nlohmann::json::parse(result.out);
  EXPECT_EQ(files.format, "svg");
  EXPECT_EQ(files.title, from_cli.at("title").get<std::string>());
  ASSERT_EQ(files.series.size(), from_cli.at("series").size());
  for (std::size_t i = 0; i < files.series.size(); ++i)
    EXPECT_EQ(files.series[i].points, from_cli["series"][i].at("points").get<std::size_t>());
  std::ifstream api_data(files.data), cli_data(from_cli.at("data").get<std::string>());
  std::stringstream a, b;
  a << api_data.rdbuf();
  b << cli_data.rdbuf();
  EXPECT_FALSE(a.str().empty());
  EXPECT_EQ(a.str(), b.str());

  // The steady curve, through the equilibrium solver, with its band over the draws.
  hydrocoef::SteadyPlotOptions steady;
  steady.vehicle = vehicle_;
  steady.database = db_;
  steady.tau_from = 0.001;
  steady.tau_to = 0.004;
  steady.count = 4;
  steady.sampling.samples = 20;
  image.image = (dir_ / "api-steady.svg").string();
  const auto steady_files = hydrocoef::plot_steady(steady, image);
  const auto steady_cli = cli({"plot", "steady", "--vehicle", vehicle_, "--tau-from", "0.001", "--tau-to", "0.004",
                               "--count", "4", "--samples", "20", "-o", (dir_ / "cli-steady.svg").string()});
  ASSERT_EQ(steady_cli.exit_code, 0) << steady_cli.err;
  std::ifstream api_steady(steady_files.data), cli_steady(dir_ / "cli-steady.dat");
  std::stringstream c, d;
  c << api_steady.rdbuf();
  d << cli_steady.rdbuf();
  EXPECT_EQ(c.str(), d.str());

  // Refusals with the CLI's words.
  image.size = "wide";
  EXPECT_EQ(error_of([&] { image.validate(); }), cli_error(cli({"plot", "fit", kFit, "--size", "wide"})));
  steady.tau_to = 0.0;
  EXPECT_EQ(error_of([&] { steady.validate(); }),
            cli_error(cli({"plot", "steady", "--vehicle", vehicle_, "--tau-from", "0.001", "--tau-to", "0"})));
  EXPECT_EQ(error_of([&] { hydrocoef::plot_history(db, 999, {}); }), cli_error(cli({"plot", "history", "999"})));
}

}  // namespace
