// Derivative exports, scaling and stored derivative models in a vehicle
// through the public API, against the CLI on the same database:
// - export_derivatives writes, for csv (prime), json, gazebo and matlab, the
//   bytes `hydrocoef derivatives export` writes, and its json() is the
//   CLI's --json; validate() refuses each bad option with the CLI's message;
//   the database is left byte-identical;
// - scale_surge_resistance gives the CLI's `scale --json` for points and for
//   a stored surge law;
// - fit_derivative_model with u0 (--u0) fits terms in du = u - U0 as the CLI
//   does, and refuses them without it;
// - a vehicle whose sway and yaw damping name stored models ("derivatives":
//   {"model": NAME}) simulates bit-identically to the same vehicle with the
//   models' terms, coefficients and covariance written inline (nominal run
//   and Monte Carlo bands), and naming a model that is not stored, or one of
//   another output, is refused naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "hydrocoef/hydrocoef.hpp"
#include "tests/support/api_errors.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

using hydrocoef::Database;
using hydrocoef::OpenMode;
using hydrocoef::test::cli_error;
using hydrocoef::test::error_of;
using hydrocoef::test::read_bytes;
using hydrocoef::test::run_cli;
using hydrocoef::test::TempDir;

class DerivativeExportsApiTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::ofstream out(dir_ / "runs.csv");
    out << std::setprecision(17) << "u [m s^-1],v [m s^-1],r [rad s^-1],X [N],Y [N],N [N m]\n";
    int i = 0;
    for (const double u : {0.5, 1.0, 1.5, 2.0})
      for (const double v : {-0.2, -0.1, 0.0, 0.1, 0.2})
        for (const double r : {-0.1, -0.04, 0.0, 0.05, 0.1}) {
          const double e = 0.01 * std::sin(1.7 * ++i);
          out << u << "," << v << "," << r << "," << -2 * u - 12 * u * std::abs(u) + e << ","
              << -40 * v + 5 * r - 150 * v * std::abs(v) - 8 * u * v + e << ","
              << -6 * v - 9 * r - 30 * r * std::abs(r) - 3 * u * r + 0.3 * e << "\n";
        }
    out.close();
    path_ = (dir_ / "d.db").string();
    ASSERT_EQ(run_cli({"--db", path_, "import", "runs.csv", "--body", "b", "--sign", "on-body"}, dir_.path()).exit_code,
              0);
    for (const auto& [output, terms, name] : std::vector<std::array<std::string, 3>>{
             {"X", "u, u*|u|", "surge"}, {"Y", "v, r, v*|v|, u*v", "sway"}, {"N", "v, r, r*|r|, u*r", "yaw"}})
      ASSERT_EQ(run_cli({"--db", path_, "derivatives", "fit", "--body", "b", "--output", output, "--terms", terms,
                         "--name", name},
                        dir_.path())
                    .exit_code,
                0);
    ASSERT_EQ(run_cli({"--db", path_, "fit", "--body", "b", "--dof", "X", "--terms", "u,u|u|", "--where", "v=0",
                       "--where", "r=0", "--name", "surge-law"},
                      dir_.path())
                  .exit_code,
              0);
  }
  hydrocoef::test::CliResult cli(std::vector<std::string> args) {
    args.insert(args.begin(), {"--db", path_});
    return run_cli(args, dir_.path());
  }
  TempDir dir_;
  std::string path_;
};

TEST_F(DerivativeExportsApiTest, EveryFormatWritesTheCliBytesAndReport) {
  const std::string before = read_bytes(path_);
  struct Case {
    std::vector<std::string> cli;
    std::function<void(hydrocoef::DerivativeExportOptions&)> api;
    std::string file;
  };
  const std::vector<Case> cases{
      {{"sway", "--format", "csv", "--form", "prime", "--length", "2", "--speed", "1.5", "--density", "1025"},
       [](auto& o) {
         o.names = {"sway"};
         o.format = "csv";
         o.form = "prime";
         o.length = 2;
         o.speed = 1.5;
         o.density = 1025;
       },
       "sway.csv"},
      {{"yaw", "--format", "json"},
       [](auto& o) {
         o.names = {"yaw"};
         o.format = "json";
       },
       "yaw.json"},
      {{"surge", "sway", "yaw", "--format", "gazebo", "--link-axes", "frd"},
       [](auto& o) {
         o.names = {"surge", "sway", "yaw"};
         o.format = "gazebo";
         o.link_axes = "frd";
       },
       "b.sdf"},
      {{"surge", "sway", "yaw", "--format", "matlab", "--mass-diagonal", "30,40,40,1,2,2"},
       [](auto& o) {
         o.names = {"surge", "sway", "yaw"};
         o.format = "matlab";
         o.mass_diagonal = "30,40,40,1,2,2";
       },
       "b.m"}};
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  for (const auto& c : cases) {
    const std::string file = (dir_ / c.file).string();
    hydrocoef::DerivativeExportOptions options;
    c.api(options);
    options.output = file;
    const auto api = hydrocoef::export_derivatives(db, options);
    const std::string api_bytes = read_bytes(file);
    EXPECT_EQ(api.content, api_bytes);
    EXPECT_EQ(api.bytes, api_bytes.size());
    std::filesystem::remove(file);
    std::vector<std::string> args{"derivatives", "export"};
    args.insert(args.end(), c.cli.begin(), c.cli.end());
    args.insert(args.end(), {"-o", file, "--json"});
    const auto written = cli(args);
    ASSERT_EQ(written.exit_code, 0) << written.err;
    EXPECT_EQ(read_bytes(file), api_bytes) << c.file;
    EXPECT_EQ(written.out, api.json()) << c.file;
    args.pop_back();
    EXPECT_EQ(cli(args).out, api.text()) << c.file;
  }
  EXPECT_EQ(read_bytes(path_), before);
}

TEST_F(DerivativeExportsApiTest, ValidateRefusesWithTheCliMessage) {
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  const auto same = [&](std::vector<std::string> args,
                        const std::function<void(hydrocoef::DerivativeExportOptions&)>& set) {
    hydrocoef::DerivativeExportOptions options;
    options.names = {"sway"};
    options.output = (dir_ / "x.out").string();
    set(options);
    args.insert(args.begin(), {"derivatives", "export"});
    args.insert(args.end(), {"-o", options.output});
    EXPECT_EQ(error_of([&] { hydrocoef::export_derivatives(db, options); }), cli_error(cli(args)));
  };
  same({"sway", "--format", "pdf"}, [](auto& o) { o.format = "pdf"; });
  same({"sway", "yaw", "--format", "json"}, [](auto& o) {
    o.names = {"sway", "yaw"};
    o.format = "json";
  });
  same({"sway", "--format", "csv", "--form", "bis", "--length", "2"}, [](auto& o) {
    o.format = "csv";
    o.form = "bis";
    o.length = 2;
  });
  same({"sway", "--format", "csv", "--length", "-1"}, [](auto& o) {
    o.format = "csv";
    o.length = -1;
  });
  same({"sway", "--format", "matlab"}, [](auto& o) { o.format = "matlab"; });
  same({"sway", "--format", "gazebo", "--mass-matrix", "m.txt"}, [](auto& o) {
    o.format = "gazebo";
    o.mass_matrix = "m.txt";
  });
  same({"sway", "--format", "gazebo", "--link-axes", "nwu"}, [](auto& o) {
    o.format = "gazebo";
    o.link_axes = "nwu";
  });
  EXPECT_FALSE(std::filesystem::exists(dir_ / "x.out"));
}

TEST_F(DerivativeExportsApiTest, ScalingGivesTheCliNumbers) {
  const std::vector<std::string> scales{
      "--from-length", "5",      "--from-area",   "4",    "--from-viscosity", "1.13902e-6", "--from-density", "999.1",
      "--to-length",   "125",    "--to-area",     "2500", "--to-viscosity",   "1.18831e-6", "--to-density",   "1025.9",
      "--wave",        "froude", "--form-factor", "1.15"};
  hydrocoef::ResistanceScalingOptions options;
  options.from_length = 5;
  options.from_area = 4;
  options.from_viscosity = 1.13902e-6;
  options.from_density = 999.1;
  options.to_length = 125;
  options.to_area = 2500;
  options.to_viscosity = 1.18831e-6;
  options.to_density = 1025.9;
  options.wave = "froude";
  options.form_factor = "1.15";
  options.speeds = {1.0, 1.5};
  options.forces = {-14.0, -30.0};
  std::vector<std::string> args{"scale", "--point", "1,-14", "--point", "1.5,-30", "--json"};
  args.insert(args.end(), scales.begin(), scales.end());
  const auto points = cli(args);
  ASSERT_EQ(points.exit_code, 0) << points.err;
  EXPECT_EQ(hydrocoef::scale_surge_resistance(options).json(), points.out);

  const auto db = Database::open(path_, OpenMode::ReadOnly);
  options.speeds.clear();
  options.forces.clear();
  options.fit = "surge-law";
  options.sample_speeds = {0.5, 1.0, 1.5, 2.0};
  args = {"scale", "--fit", "surge-law", "--speeds", "0.5,1,1.5,2", "--json"};
  args.insert(args.end(), scales.begin(), scales.end());
  const auto law = cli(args);
  ASSERT_EQ(law.exit_code, 0) << law.err;
  const auto api = hydrocoef::scale_surge_resistance(db, options);
  EXPECT_EQ(api.json(), law.out);
  ASSERT_EQ(api.coefficients_to.size(), 2u);
  EXPECT_LT(api.coefficients_to[1], 0.0);
  // Without a database a stored fit cannot be read.
  EXPECT_NE(error_of([&] { hydrocoef::scale_surge_resistance(options); }).find("--fit 'surge-law'"), std::string::npos);
  // validate() is the CLI's check.
  options.wave.clear();
  args.erase(std::find(args.begin(), args.end(), "--wave"), std::find(args.begin(), args.end(), "--wave") + 2);
  EXPECT_EQ(error_of([&] { hydrocoef::scale_surge_resistance(db, options); }), cli_error(cli(args)));
}

// --u0 U0 gives each run du = u - U0 (the Abkowitz template's surge variable):
// X = -2 u - 12 u|u| about U0 = 1 is -14 - 26 du - 12 du^2 over these runs (u > 0).
TEST_F(DerivativeExportsApiTest, U0GivesDuAsTheCliDoes) {
  const auto fitted = cli({"derivatives", "fit", "--body", "b", "--output", "X", "--terms", "1, du, du^2", "--u0", "1",
                           "--no-store", "--json"});
  ASSERT_EQ(fitted.exit_code, 0) << fitted.err;
  const auto theirs = nlohmann::json::parse(fitted.out);
  auto db = Database::open(path_, OpenMode::ReadOnly);
  hydrocoef::DerivativeModelOptions options;
  options.body = "b";
  options.output = "X";
  options.terms = "1, du, du^2";
  options.u0 = 1.0;
  options.store = false;
  const auto ours = hydrocoef::fit_derivative_model(db, options);
  EXPECT_EQ(ours.json(), fitted.out);
  ASSERT_EQ(ours.coefficients.size(), 3u);
  EXPECT_NEAR(ours.coefficients[0].value, -14.0, 0.01);
  EXPECT_NEAR(ours.coefficients[1].value, -26.0, 0.01);
  EXPECT_NEAR(ours.coefficients[2].value, -12.0, 0.01);
  EXPECT_EQ(theirs.at("terms"), "1, du, du^2");
  // Without U0 a term in du is refused naming --u0, as the CLI refuses it.
  options.u0 = std::numeric_limits<double>::quiet_NaN();
  const std::string message = error_of([&] { hydrocoef::fit_derivative_model(db, options); });
  EXPECT_EQ(message, "derivatives fit: term 'du' reads du = u - U0; expected the nominal speed with --u0 U0 [m/s]");
  EXPECT_EQ(
      message,
      cli_error(cli({"derivatives", "fit", "--body", "b", "--output", "X", "--terms", "1, du, du^2", "--no-store"})));
  options.u0 = std::numeric_limits<double>::infinity();
  EXPECT_EQ(error_of([&] { hydrocoef::fit_derivative_model(db, options); }),
            "--u0 must be a finite speed [m/s], not inf");
}

std::string numbers(const nlohmann::json& list) {
  std::ostringstream out;
  out << std::setprecision(17) << "[";
  for (std::size_t k = 0; k < list.size(); ++k) out << (k ? ", " : "") << list[k].get<double>();
  return out.str() + "]";
}

std::string inline_derivatives(const nlohmann::json& model) {
  const std::size_t m = model.at("coefficients").size();
  nlohmann::json values = nlohmann::json::array();
  for (const auto& c : model.at("coefficients")) values.push_back(c.at("value"));
  std::string covariance = "[";
  for (std::size_t i = 0; i < m; ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (std::size_t j = 0; j < m; ++j) row.push_back(model.at("covariance")[i * m + j]);
    covariance += (i ? ", " : "") + numbers(row);
  }
  return R"({"terms": ")" + model.at("terms").get<std::string>() + R"(", "coefficients": )" + numbers(values) +
         R"(, "covariance": )" + covariance + "]}";
}

std::string vehicle(const std::string& sway, const std::string& yaw, bool inline_form) {
  const std::string sign = inline_form ? R"(, "sign": "on-body")" : "";
  return R"({"mass": 40, "inertia": [1, 4, 4], "center_of_gravity": [0, 0, 0.02], "neutrally_buoyant": true,
  "added_mass": {"diagonal": [4, 30, 30, 0.1, 2, 2]},
  "damping": {"X": {"law": {"u": -2, "u|u|": -12}, "sign": "on-body"},
              "Y": {"derivatives": )" +
         sway + sign + R"(}, "N": {"derivatives": )" + yaw + sign + "}}}\n";
}

TEST_F(DerivativeExportsApiTest, AVehicleNamingStoredModelsSimulatesAsTheInlineForm) {
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  hydrocoef::DerivativeShowOptions show;
  show.name = "sway";
  const auto sway = nlohmann::json::parse(hydrocoef::show_derivative_model(db, show).json());
  show.name = "yaw";
  const auto yaw = nlohmann::json::parse(hydrocoef::show_derivative_model(db, show).json());
  const std::string scenario = R"({"duration": 6, "output_rate": 10, "integrator": {"method": "rk4", "step": 0.01},
    "initial": {"position": [0, 0, 0], "euler_deg": [0, 0, 0], "velocity": [0.8, 0, 0, 0, 0, 0]},
    "segments": [{"start": 0, "tau": {"X": 10, "Y": 2, "N": 0.5}}]})"
                               "\n";
  std::ofstream(dir_ / "scenario.json") << scenario;

  hydrocoef::SimulateOptions named;
  named.vehicle = vehicle(R"({"model": "sway"})", R"({"model": "yaw"})", false);
  named.scenario = (dir_ / "scenario.json").string();
  named.database = path_;
  named.sampling.samples = 16;
  named.sampling.seed = 5;
  named.sampling.threads = 1;
  hydrocoef::SimulateOptions given = named;
  given.vehicle = vehicle(inline_derivatives(sway), inline_derivatives(yaw), true);
  const auto a = hydrocoef::simulate(named);
  const auto b = hydrocoef::simulate(given);
  ASSERT_GT(a.trajectory.rows, 10u);
  EXPECT_EQ(a.trajectory.values, b.trajectory.values);  // bit-identical
  EXPECT_EQ(a.band_values, b.band_values);
  EXPECT_FALSE(a.band_values.empty());
  // The damping did act: the sway velocity and yaw rate moved off zero.
  EXPECT_NE(a.trajectory.column("v")[a.trajectory.rows - 1], 0.0);

  hydrocoef::SimulateOptions missing = named;
  missing.sampling.samples = 0;
  missing.vehicle = vehicle(R"({"model": "nosuch"})", R"({"model": "yaw"})", false);
  const std::string message = error_of([&] { hydrocoef::simulate(missing); });
  EXPECT_NE(message.find("key 'damping.Y.derivatives.model': found \"nosuch\", expected a derivative model stored in"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("(models of Y: sway)"), std::string::npos) << message;
  missing.vehicle = vehicle(R"({"model": "yaw"})", R"({"model": "yaw"})", false);
  EXPECT_NE(error_of([&] {
              hydrocoef::simulate(missing);
            }).find("the derivative model \"yaw\" is of N, expected a model of Y"),
            std::string::npos);
  missing.vehicle = vehicle(R"({"model": "sway"})", R"({"model": "yaw"})", false);
  missing.database.clear();
  EXPECT_NE(error_of([&] { hydrocoef::simulate(missing); }).find("names a stored model, but no database was given"),
            std::string::npos);
  // A stored model brings its own sign.
  missing.database = path_;
  missing.vehicle = vehicle(R"({"model": "sway"})", R"({"model": "yaw"})", true);
  EXPECT_NE(error_of([&] { hydrocoef::simulate(missing); }).find("brings its own terms, sign and covariance"),
            std::string::npos);
}

}  // namespace
