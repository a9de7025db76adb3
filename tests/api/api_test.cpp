// The public C++ API (include/hydrocoef/) driven as a library user drives it:
// only the public headers, with the answers checked against exact table
// values and against what the hydrocoef CLI (the same library) prints for the
// same database.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hydrocoef/hydrocoef.hpp"
#include "tests/support/api_errors.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

using hydrocoef::test::cli_error;
using hydrocoef::test::error_of;

using hydrocoef::Database;
using hydrocoef::OpenMode;
using hydrocoef::test::run_cli;
using hydrocoef::test::TempDir;

const std::string kAsrV = std::string(HYDROCOEF_SOURCE_DIR) + "/examples/asr-v/";
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The ASR-V tables imported as examples/asr-v/run.sh imports them.
void import_asr_v(Database& db) {
  hydrocoef::ImportOptions surge;
  surge.body = "asr-v";
  surge.settings = {{"sign", "opposing"}, {"rho", "998.2"}, {"nu", "1.004e-6"}};
  const auto summary = db.import_files({kAsrV + "asr-v-surge-damping.csv"}, surge);
  ASSERT_EQ(summary.files.size(), 1u);
  EXPECT_EQ(summary.files[0].format, "table");
  EXPECT_EQ(summary.files[0].runs, 20u);
  EXPECT_EQ(summary.runs_created, 20u);
  hydrocoef::ImportOptions yaw = surge;
  yaw.settings["sign"] = "on-body";
  const auto second = db.import_files({kAsrV + "asr-v-yaw-damping.csv"}, yaw);
  EXPECT_EQ(second.runs_created, 19u);  // the run at rest is shared with the surge table
  EXPECT_EQ(second.runs_extended, 1u);
  const auto again = db.import_files({kAsrV + "asr-v-yaw-damping.csv"}, yaw);
  EXPECT_EQ(again.already_imported, 1u);
  EXPECT_EQ(again.runs_created, 0u);
}

/// A 2-D force table on a 6 x 5 grid: X = -10 u|u| - 2 v, Y = u - 5 v|v|.
std::string write_grid_table(const TempDir& dir) {
  const auto path = dir / "grid.csv";
  std::ofstream out(path);
  out << "u [m s^-1],v [m s^-1],X [N],Y [N]\n";
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 5; ++j) {
      const double u = 0.1 * i, v = 0.1 * (j - 2);
      out << u << "," << v << "," << -10 * u * std::abs(u) - 2 * v << "," << u - 5 * v * std::abs(v) << "\n";
    }
  return path.string();
}

class ApiTest : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = (dir_ / "api.db").string();
    auto db = Database::open(path_, OpenMode::Create);
    import_asr_v(db);
    hydrocoef::ImportOptions grid;
    grid.body = "grid";
    db.import_files({write_grid_table(dir_)}, grid);
    db.close();
    // Surfaces are built by the CLI (the library's build entry point is the CLI's for now).
    for (const auto& args :
         std::vector<std::vector<std::string>>{{"surface", "build", "asr-v-yaw", "--body", "asr-v", "--outputs", "N",
                                                "--axes", "r", "--method", "pchip", "--extrapolate", "linear"},
                                               {"surface", "build", "asr-v-surge", "--body", "asr-v", "--outputs", "X",
                                                "--axes", "u", "--method", "pchip", "--extrapolate", "linear"},
                                               {"surface", "build", "grid-linear", "--body", "grid", "--outputs", "X,Y",
                                                "--axes", "u,v", "--method", "linear"},
                                               {"surface", "build", "grid-pchip", "--body", "grid", "--outputs", "X,Y",
                                                "--axes", "u,v", "--method", "pchip"}}) {
      auto with_db = args;
      with_db.insert(with_db.begin(), {"--db", path_});
      const auto result = run_cli(with_db, dir_.path());
      ASSERT_EQ(result.exit_code, 0) << result.err;
    }
  }

  hydrocoef::test::CliResult cli(std::vector<std::string> args) {
    args.insert(args.begin(), {"--db", path_});
    return run_cli(args, dir_.path());
  }

  TempDir dir_;
  std::string path_;
};

TEST_F(ApiTest, RunsAreColumnsOfForcesOnTheBody) {
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  const auto runs = db.runs({}, "asr-v");
  ASSERT_EQ(runs.size(), 39u);
  std::size_t surge_at_01 = runs.size(), yaw_at_0116 = runs.size();
  for (std::size_t i = 0; i < runs.size(); ++i) {
    EXPECT_EQ(runs.body[i], "asr-v");
    if (std::abs(runs.velocity[0][i] - 0.10) < 1e-12) surge_at_01 = i;
    if (std::abs(runs.velocity[5][i] - 0.0116) < 1e-12) yaw_at_0116 = i;
    EXPECT_TRUE(std::isnan(runs.force_std_error[0][i]));  // tables hold no history
  }
  ASSERT_LT(surge_at_01, runs.size());
  ASSERT_LT(yaw_at_0116, runs.size());
  // The surge table prints magnitudes (positive opposes motion): on the body it is negative.
  EXPECT_EQ(runs.force[0][surge_at_01], -0.11278);
  EXPECT_TRUE(std::isnan(runs.force[5][surge_at_01]));
  EXPECT_EQ(runs.force[5][yaw_at_0116], -0.00015);
  EXPECT_TRUE(std::isnan(runs.force[0][yaw_at_0116]));
  EXPECT_NE(runs.source[surge_at_01].find("asr-v-surge-damping.csv"), std::string::npos);

  EXPECT_EQ(db.runs({"u>=0.3"}, "asr-v").size(), 5u);  // 0.30 ... 0.38
  EXPECT_EQ(db.runs({"u>=0.3"}, "asr-v", {runs.id[surge_at_01]}).size(), 5u);
  EXPECT_EQ(db.runs({}, "asr-v", {runs.id[surge_at_01]}).size(), 38u);
  EXPECT_EQ(db.runs().size(), 39u + 30u);
  // A clause that does not parse: the CLI's message.
  EXPECT_EQ(error_of([&] { db.runs({"u>=abc"}); }), cli_error(cli({"runs", "--where", "u>=abc"})));
}

TEST_F(ApiTest, FitGivesWhatTheCliGives) {
  auto db = Database::open(path_, OpenMode::ReadWrite);
  hydrocoef::FitOptions options;
  options.body = "asr-v";
  options.output = "X";
  options.terms = "1,u,u|u|";
  const auto fit = db.fit(options);
  EXPECT_EQ(fit.name, "asr-v:X(1,u,u|u|)");
  EXPECT_EQ(fit.sign_convention, "opposing");
  EXPECT_GT(fit.id, 0);
  ASSERT_EQ(fit.coefficients.size(), 3u);
  // README: X(u) = 0.000618201 + 0.0155077 u + 11.0364 u|u| (paper eq. 5).
  EXPECT_NEAR(fit.coefficients[0].value, 0.000618201, 1e-9);
  EXPECT_NEAR(fit.coefficients[1].value, 0.0155077, 1e-7);
  EXPECT_NEAR(fit.coefficients[2].value, 11.0364, 1e-4);
  EXPECT_EQ(fit.coefficients[2].term, "u|u|");
  EXPECT_EQ(fit.coefficients[2].unit, "N/(m/s)^2");
  EXPECT_EQ(fit.n, 20u);

  const auto cli_fit = cli({"fit", "--body", "asr-v", "--dof", "X", "--terms", "1,u,u|u|", "--no-store", "--json"});
  ASSERT_EQ(cli_fit.exit_code, 0) << cli_fit.err;
  const auto json = nlohmann::json::parse(cli_fit.out);
  for (const auto& c : fit.coefficients) {
    EXPECT_EQ(c.value, json["coefficients"][c.term].get<double>()) << c.term;
    EXPECT_EQ(c.std_error, json["std_errors"][c.term].get<double>()) << c.term;
    EXPECT_EQ(c.unit, json["units"][c.term].get<std::string>()) << c.term;
  }
  EXPECT_EQ(fit.rmse, json["rmse"].get<double>());
  EXPECT_EQ(fit.r2, json["r2"].get<double>());

  // Stored: listed, and its name is taken.
  const auto fits = db.fits("asr-v");
  ASSERT_EQ(fits.size(), 1u);
  EXPECT_EQ(fits[0].name, fit.name);
  EXPECT_EQ(fits[0].coefficients[1].value, fit.coefficients[1].value);
  EXPECT_EQ(fits[0].coefficients[1].unit, "N/(m/s)");
  EXPECT_NE(error_of([&] { db.fit(options); }).find("asr-v:X(1,u,u|u|)"), std::string::npos);
  options.replace = true;
  EXPECT_EQ(db.fit(options).coefficients[1].value, fit.coefficients[1].value);
  // No runs selected.
  options.where = {"u>5"};
  EXPECT_FALSE(error_of([&] { db.fit(options); }).empty());
}

TEST_F(ApiTest, SurfaceAnswersAsTheCliQuery) {
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  const auto infos = db.surfaces();
  ASSERT_EQ(infos.size(), 4u);
  EXPECT_EQ(infos[0].name, "asr-v-surge");
  EXPECT_EQ(infos[2].name, "grid-linear");
  EXPECT_EQ(infos[2].axes, (std::vector<std::string>{"u", "v"}));
  EXPECT_EQ(infos[2].run_count, 30u);
  EXPECT_EQ(infos[2].kind, "grid");

  const auto s = db.surface("grid-linear");
  EXPECT_EQ(s.axes(), (std::vector<std::string>{"u", "v"}));
  EXPECT_EQ(s.outputs(), (std::vector<std::string>{"X", "Y"}));
  EXPECT_EQ(s.axis_units(), (std::vector<std::string>{"m/s", "m/s"}));
  EXPECT_EQ(s.output_units(), (std::vector<std::string>{"N", "N"}));
  EXPECT_EQ(s.method(), "linear");
  EXPECT_EQ(s.lower(0), 0.0);
  EXPECT_EQ(s.upper(0), 0.5);
  EXPECT_EQ(s.out_of_range(1), "error");
  // At a node: the tabulated value.
  const auto node = s.evaluate({0.3, 0.1});
  EXPECT_NEAR(node[0], -10 * 0.09 - 0.2, 1e-12);
  EXPECT_NEAR(node[1], 0.3 - 0.05, 1e-12);
  // Between nodes: what `hydrocoef query --json` prints (shortest round-trip numbers: exact).
  for (const auto* name : {"grid-linear", "grid-pchip"}) {
    const auto surface = db.surface(name);
    const auto answer = surface.evaluate_with_gradient({0.234, -0.0567});
    const auto query = cli({"query", name, "u=0.234", "v=-0.0567", "--gradient", "--json"});
    ASSERT_EQ(query.exit_code, 0) << query.err;
    const auto json = nlohmann::json::parse(query.out);
    EXPECT_EQ(answer.values[0], json["values"]["X"].get<double>()) << name;
    EXPECT_EQ(answer.values[1], json["values"]["Y"].get<double>()) << name;
    EXPECT_EQ(answer.gradient[0 * 2 + 1], json["gradient"]["X"]["v"].get<double>()) << name;
    EXPECT_EQ(answer.gradient[1 * 2 + 0], json["gradient"]["Y"]["u"].get<double>()) << name;
  }
  // Out of range and unknown names: the CLI's messages.
  EXPECT_EQ(error_of([&] { s.evaluate({0.7, 0.0}); }), cli_error(cli({"query", "grid-linear", "u=0.7", "v=0"})));
  EXPECT_EQ(error_of([&] { db.surface("nope"); }), cli_error(cli({"query", "nope", "u=0.7"})));
  EXPECT_FALSE(error_of([&] { s.evaluate({0.1}); }).empty());
  EXPECT_NE(error_of([&] { s.evaluate({kNaN, 0.0}); }).find("'u'"), std::string::npos);
  // Extrapolated linearly beyond the runs, as built.
  EXPECT_EQ(db.surface("asr-v-yaw").out_of_range(0), "linear");
  EXPECT_NO_THROW(db.surface("asr-v-yaw").evaluate({0.5}));
}

TEST_F(ApiTest, AGridSurfaceStatesTheCliQuerysStandardDeviation) {
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  const auto s = db.surface("grid-pchip");
  ASSERT_TRUE(s.has_standard_deviation());
  const auto answer = s.evaluate_with_standard_deviation({0.234, -0.0567});
  const auto query = cli({"query", "grid-pchip", "u=0.234", "v=-0.0567", "--uncertainty", "--json"});
  ASSERT_EQ(query.exit_code, 0) << query.err;
  const auto json = nlohmann::json::parse(query.out);
  EXPECT_EQ(answer.standard_deviation[0], json["standard_deviation"]["X"].get<double>());
  EXPECT_EQ(answer.standard_deviation[1], json["standard_deviation"]["Y"].get<double>());
  // The runs state no uncertainty: the leave-one-out RMS alone, everywhere.
  const auto show = nlohmann::json::parse(cli({"surface", "show", "grid-pchip", "--json"}).out);
  EXPECT_EQ(answer.standard_deviation[0], show["quality"]["outputs"]["X"]["loo_rms"].get<double>());
  // The batch gives the same.
  const double u = 0.234, v = -0.0567;
  double x = 0, y = 0, sx = 0, sy = 0;
  s.evaluate_batch(1, {{&u, 1}, {&v, 1}}, {{&x, 1}, {&y, 1}}, {}, 1, {{&sx, 1}, {&sy, 1}});
  EXPECT_EQ(sx, answer.standard_deviation[0]);
  EXPECT_EQ(sy, answer.standard_deviation[1]);
}

TEST_F(ApiTest, BatchEqualsPointEvaluationOnStridedColumns) {
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  const auto s = db.surface("grid-pchip");
  const std::size_t n = 50'000;  // several chunks
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> u(0.0, 0.5), v(-0.2, 0.2);
  std::vector<double> points(2 * n);  // interleaved u, v: stride 2
  for (std::size_t i = 0; i < n; ++i) {
    points[2 * i] = u(random);
    points[2 * i + 1] = v(random);
  }
  for (const unsigned threads : {1u, 2u, 0u}) {
    std::vector<double> out(2 * n, kNaN), gradient(4 * n, kNaN);
    std::vector<hydrocoef::Column> gradient_columns;
    for (std::size_t g = 0; g < 4; ++g) gradient_columns.push_back({gradient.data() + g * n, 1});
    s.evaluate_batch(n, {{points.data(), 2}, {points.data() + 1, 2}}, {{out.data(), 2}, {out.data() + 1, 2}},
                     gradient_columns, threads);
    for (std::size_t i = 0; i < n; i += 997) {
      const auto expected = s.evaluate_with_gradient({points[2 * i], points[2 * i + 1]});
      ASSERT_EQ(out[2 * i], expected.values[0]) << i;
      ASSERT_EQ(out[2 * i + 1], expected.values[1]) << i;
      for (std::size_t g = 0; g < 4; ++g) ASSERT_EQ(gradient[g * n + i], expected.gradient[g]) << i;
    }
    EXPECT_EQ(out[2 * (n - 1)], s.evaluate({points[2 * (n - 1)], points[2 * (n - 1) + 1]})[0]);
  }
  // A constant column (stride 0) stands for every point.
  const double v0 = 0.05;
  std::vector<double> x(n), y(n);
  s.evaluate_batch(n, {{points.data(), 2}, {&v0, 0}}, {{x.data(), 1}, {y.data(), 1}}, {});
  EXPECT_EQ(x[123], s.evaluate({points[246], v0})[0]);
  EXPECT_THROW(s.evaluate_batch(n, {{points.data(), 2}}, {{x.data(), 1}, {y.data(), 1}}, {}), std::invalid_argument);
  EXPECT_THROW(s.evaluate_batch(n, {{points.data(), 2}, {&v0, 0}}, {{x.data(), 1}, {nullptr, 1}}, {}),
               std::invalid_argument);
}

TEST_F(ApiTest, BatchReportsTheFirstBadPointWithTheSurfacesMessage) {
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  const auto s = db.surface("grid-linear");
  const std::size_t n = 40'000;
  std::vector<double> u(n, 0.25), v(n, 0.0), x(n, kNaN), y(n, kNaN);
  u[31'000] = 0.9;  // outside u's [0, 0.5]
  u[38'000] = kNaN;
  v[20'001] = 1.0;  // the first bad point
  const auto message = error_of([&] {
    s.evaluate_batch(n, {{u.data(), 1}, {v.data(), 1}}, {{x.data(), 1}, {y.data(), 1}}, {}, 2);
  });
  EXPECT_EQ(message, "point 20001: " + error_of([&] { s.evaluate({0.25, 1.0}); }));
  EXPECT_EQ(message, "point 20001: " + cli_error(cli({"query", "grid-linear", "u=0.25", "v=1"})));
  // Every point before it was written.
  const double expected = s.evaluate({0.25, 0.0})[0];
  for (std::size_t i = 0; i < 20'001; ++i) ASSERT_EQ(x[i], expected) << i;
  v[20'001] = 0.0;
  EXPECT_EQ(error_of([&] {
              s.evaluate_batch(n, {{u.data(), 1}, {v.data(), 1}}, {{x.data(), 1}, {y.data(), 1}}, {});
            }).rfind("point 31000: ", 0),
            0u);
}

TEST_F(ApiTest, ClosedAndReadOnlyDatabasesRefuseWithAMessage) {
  auto db = Database::open(path_, OpenMode::ReadOnly);
  EXPECT_TRUE(db.read_only());
  hydrocoef::ImportOptions options;
  options.body = "x";
  EXPECT_NE(error_of([&] { db.import_files({kAsrV + "asr-v-surge-damping.csv"}, options); }).find("read-only"),
            std::string::npos);
  const auto surface = db.surface("asr-v-yaw");
  db.close();
  EXPECT_FALSE(db.is_open());
  EXPECT_EQ(error_of([&] { db.runs(); }), path_ + ": database is closed");
  EXPECT_EQ(error_of([&] { db.surface("asr-v-yaw"); }), path_ + ": database is closed");
  EXPECT_EQ(error_of([&] { db.fits(); }), path_ + ": database is closed");
  // A surface read before stays valid.
  EXPECT_TRUE(std::isfinite(surface.evaluate({0.1})[0]));
  db.close();  // twice is fine
  EXPECT_FALSE(error_of([&] { Database::open((dir_ / "missing.db").string(), OpenMode::ReadWrite); }).empty());
  // A bad setting names itself.
  auto writable = Database::open(path_, OpenMode::ReadWrite);
  options.settings = {{"density", "1000"}};
  EXPECT_NE(error_of([&] {
              writable.import_files({kAsrV + "asr-v-surge-damping.csv"}, options);
            }).find("unknown key 'density'"),
            std::string::npos);
}

/// The CLI's trajectory CSV as columns.
std::vector<std::vector<double>> read_csv_columns(const std::string& path, std::string& header) {
  std::ifstream in(path);
  std::getline(in, header);
  std::vector<std::vector<double>> columns;
  for (std::string line; std::getline(in, line);) {
    std::stringstream cells(line);
    std::size_t c = 0;
    for (std::string cell; std::getline(cells, cell, ','); ++c) {
      if (columns.size() <= c) columns.emplace_back();
      columns[c].push_back(std::stod(cell));
    }
  }
  return columns;
}

TEST_F(ApiTest, SimulateGivesTheCliTrajectory) {
  const std::string scenario = kAsrV + "scenario-yaw-0.0027.json";
  for (const auto* vehicle : {"vehicle.json", "vehicle-surfaces.json"}) {
    const auto trajectory = hydrocoef::simulate(kAsrV + vehicle, scenario, path_);
    const auto csv = (dir_ / "trajectory.csv").string();
    const auto result = cli({"simulate", "--vehicle", kAsrV + vehicle, "--scenario", scenario, "--out", csv});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    std::string header;
    const auto columns = read_csv_columns(csv, header);
    ASSERT_EQ(columns.size(), trajectory.columns.size());
    std::string names;
    for (std::size_t c = 0; c < trajectory.columns.size(); ++c)
      names += (c ? "," : "") + trajectory.columns[c] +
               (trajectory.units[c].empty() ? "" : " [" + trajectory.units[c] + "]");
    EXPECT_EQ(names, header);
    ASSERT_EQ(trajectory.rows, 601u);  // 60 s at 10 Hz, and t = 0
    for (std::size_t c = 0; c < columns.size(); ++c) {
      ASSERT_EQ(columns[c].size(), trajectory.rows);
      for (std::size_t r = 0; r < trajectory.rows; r += 50)
        ASSERT_EQ(columns[c][r], trajectory.values[c * trajectory.rows + r]) << trajectory.columns[c] << " row " << r;
    }
    EXPECT_GT(trajectory.column("r")[600], 0.1);  // the yaw rate rises to ~0.15 rad/s
  }
  // JSON text instead of a path, and a vehicle naming surfaces without a database.
  std::ifstream file(kAsrV + "vehicle.json");
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_EQ(hydrocoef::simulate(text, scenario).rows, 601u);
  EXPECT_NE(error_of([&] { hydrocoef::simulate(kAsrV + "vehicle-surfaces.json", scenario); }).find("asr-v-surge"),
            std::string::npos);
  EXPECT_EQ(error_of([&] { hydrocoef::simulate(kAsrV + "nope.json", scenario); }),
            cli_error(cli({"simulate", "--vehicle", kAsrV + "nope.json", "--scenario", scenario})));
}

TEST(ApiVersion, IsTheCliVersion) {
  TempDir dir;
  const auto result = run_cli({"--version"}, dir.path());
  EXPECT_EQ(result.out, std::string("hydrocoef ") + hydrocoef::kVersion + "\n");
  EXPECT_EQ(hydrocoef::kVersionMajor, std::stoi(hydrocoef::kVersion));
}

}  // namespace
