// The domain plots against numbers computed here independently: the fitted
// curves against a least-squares fit done in the test, per-level curves and
// coefficient curves against the generating law, a linear surface against
// hand interpolation, a sigma map against the stated uncertainty and the
// stored leave-one-out RMS, steady yaw rates against the quadratic's root.
#include "src/plot/plots.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "src/core/error.hpp"
#include "src/dynamics/vehicle.hpp"
#include "tests/support/plot_data.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef::plot {
namespace {

using test::PlotBlocks;
using test::run_cli;
using test::TempDir;

PlotBlocks read_blocks(const std::filesystem::path& path) { return test::read_plot_blocks(path); }

void write(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

const std::string kExamples = std::string(HYDROCOEF_SOURCE_DIR) + "/examples/asr-v/";

/// The ASR-V surge table (opposing) read back here: u and X.
std::pair<std::vector<double>, std::vector<double>> surge_table() {
  std::ifstream in(kExamples + "asr-v-surge-damping.csv");
  std::string line;
  std::vector<double> u, x;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'u') continue;
    const auto comma = line.find(',');
    u.push_back(std::stod(line.substr(0, comma)));
    x.push_back(std::stod(line.substr(comma + 1)));
  }
  return {u, x};
}

TEST(Plots, FitPlotHoldsTheRunsAndTheLawFittedIndependently) {
  TempDir dir;
  ASSERT_EQ(
      run_cli({"import", kExamples + "asr-v-surge-damping.csv", "--body", "asr-v", "--sign", "opposing"}, dir.path())
          .exit_code,
      0);
  ASSERT_EQ(run_cli({"fit", "--body", "asr-v", "--dof", "X", "--terms", "1,u,u|u|"}, dir.path()).exit_code, 0);
  RunDatabase database(dir / "hydrocoef.db", RunDatabase::OpenMode::MustExist);
  const Figure figure = fit_figure(database, "asr-v:X(1,u,u|u|)");
  const auto files = render(figure, dir / "fit.png");
  const auto blocks = read_blocks(files.data);
  ASSERT_EQ(blocks.size(), 2u);

  // Runs: the table's values as printed (the fit keeps the opposing
  // convention).
  const auto [u, x] = surge_table();
  ASSERT_EQ(blocks[0].second.size(), u.size());
  for (std::size_t i = 0; i < u.size(); ++i) {
    EXPECT_NEAR(blocks[0].second[i][0], u[i], 1e-15);
    EXPECT_NEAR(blocks[0].second[i][1], x[i], 1e-15);
  }
  // Curve: ordinary least squares of [1, u, u|u|] solved here.
  Eigen::MatrixXd a(static_cast<Eigen::Index>(u.size()), 3);
  Eigen::VectorXd b(static_cast<Eigen::Index>(u.size()));
  for (std::size_t i = 0; i < u.size(); ++i) {
    const auto r = static_cast<Eigen::Index>(i);
    a(r, 0) = 1.0;
    a(r, 1) = u[i];
    a(r, 2) = u[i] * std::abs(u[i]);
    b(r) = x[i];
  }
  const Eigen::VectorXd c = a.colPivHouseholderQr().solve(b);
  EXPECT_NEAR(c(2), 11.0364, 1e-3);  // the README's figure
  const auto& curve = blocks[1].second;
  ASSERT_EQ(curve.size(), 101u);
  EXPECT_NEAR(curve.front()[0], 0.0, 1e-15);
  EXPECT_NEAR(curve.back()[0], u.back(), 1e-15);
  for (const auto& row : curve)
    EXPECT_NEAR(row[1], c(0) + c(1) * row[0] + c(2) * row[0] * std::abs(row[0]), 1e-9) << "at u = " << row[0];
  // The legend names the law and R².
  const auto at = blocks[1].first.find("u|u|, R² = ");
  ASSERT_NE(at, std::string::npos) << blocks[1].first;
  const Eigen::VectorXd residual = a * c - b;
  const double ss_tot = (b.array() - b.mean()).square().sum();
  EXPECT_NEAR(std::stod(blocks[1].first.substr(at + 12)), 1.0 - residual.squaredNorm() / ss_tot, 1e-8)
      << blocks[1].first;
  EXPECT_NE(figure.panels[0].y_label.find("opposing"), std::string::npos);
}

class SweepTest : public ::testing::Test {
 protected:
  // X = a(c) u + b(c) u|u| with a = 0.1 + 2 c^2, b = 11 + 5 c, on a full
  // u x current_v grid: each level's law is exact.
  void SetUp() override {
    std::ostringstream table;
    table.precision(17);
    table << "u [m s^-1],current_v [m s^-1],X [N]\n";
    for (double c : levels)
      for (double u : speeds) table << u << "," << c << "," << law(u, c) << "\n";
    write(dir / "sweep.csv", table.str());
    ASSERT_EQ(run_cli({"import", "sweep.csv", "--body", "b", "--disturbance", "current_v"}, dir.path()).exit_code, 0);
  }
  static double law(double u, double c) { return (0.1 + 2 * c * c) * u + (11 + 5 * c) * u * std::abs(u); }
  TempDir dir;
  const std::vector<double> levels{0.0, 0.05, 0.1, 0.2};
  const std::vector<double> speeds{-0.2, 0.05, 0.1, 0.2, 0.3};
};

TEST_F(SweepTest, PerLevelFitsDrawOneCurvePerLevelAndCoefficientCurves) {
  ASSERT_EQ(
      run_cli({"fit", "--body", "b", "--dof", "X", "--terms", "u,u|u|", "--by", "current_v"}, dir.path()).exit_code, 0);
  RunDatabase database(dir / "hydrocoef.db", RunDatabase::OpenMode::MustExist);
  const auto files = render(fit_figure(database, "b:X(u,u|u|)"), dir / "levels.svg");
  const auto blocks = read_blocks(files.data);
  ASSERT_EQ(blocks.size(), 2 * levels.size());
  for (std::size_t l = 0; l < levels.size(); ++l) {
    const auto& points = blocks[2 * l];
    const auto& curve = blocks[2 * l + 1];
    const std::vector<std::string> labels{"current_v=0:", "current_v=0.05:", "current_v=0.1:", "current_v=0.2:"};
    EXPECT_EQ(points.first.rfind(labels[l], 0), 0u) << points.first;
    ASSERT_EQ(points.second.size(), speeds.size());
    for (const auto& row : points.second) EXPECT_NEAR(row[1], law(row[0], levels[l]), 1e-12);
    for (const auto& row : curve.second) EXPECT_NEAR(row[1], law(row[0], levels[l]), 1e-9) << "level " << levels[l];
  }
  EXPECT_NE(test::read_text(files.image).find("<svg"), std::string::npos);

  // Coefficient curves: per-level values are a and b at each level; a
  // degree-2 polynomial recovers a(c) and b(c) between the levels.
  const auto curves = render(curves_figure(database, "b:X(u,u|u|)", CurveKind::Polynomial, 2), dir / "curves.png");
  const auto cb = read_blocks(curves.data);
  ASSERT_EQ(cb.size(), 4u);
  for (std::size_t l = 0; l < levels.size(); ++l) {
    EXPECT_NEAR(cb[0].second[l][1], 0.1 + 2 * levels[l] * levels[l], 1e-9);
    EXPECT_NEAR(cb[2].second[l][1], 11 + 5 * levels[l], 1e-9);
  }
  ASSERT_EQ(cb[1].second.size(), 101u);
  for (const auto& row : cb[1].second) EXPECT_NEAR(row[1], 0.1 + 2 * row[0] * row[0], 1e-7);
  for (const auto& row : cb[3].second) EXPECT_NEAR(row[1], 11 + 5 * row[0], 1e-6);

  // Curves need per-level fits.
  ASSERT_EQ(
      run_cli({"fit", "--body", "b", "--dof", "X", "--terms", "u,u|u|", "--name", "pooled"}, dir.path()).exit_code, 0);
  EXPECT_NE(error_of([&] { curves_figure(database, "pooled", CurveKind::Pchip, 3); }).find("expected at least 2"),
            std::string::npos);
}

TEST_F(SweepTest, TwoAxisSurfaceIsAColourMapWithRunsAndShadedOutOfRange) {
  ASSERT_EQ(run_cli({"surface", "build", "s2", "--body", "b", "--outputs", "X", "--axes", "u,current_v", "--method",
                     "linear"},
                    dir.path())
                .exit_code,
            0);
  RunDatabase database(dir / "hydrocoef.db", RunDatabase::OpenMode::MustExist);
  const Figure figure = surface_figure(database, "s2", std::nullopt);
  const auto files = render(figure, dir / "s2.png");
  const auto blocks = read_blocks(files.data);
  ASSERT_EQ(blocks.size(), 2u);
  const auto& map = blocks[0].second;
  ASSERT_EQ(map.size(), 81u * 81u);
  // Bilinear interpolation of the runs, done here.
  auto bracket = [](const std::vector<double>& xs, double v) {
    std::size_t i = 0;
    while (i + 2 < xs.size() && v > xs[i + 1]) ++i;
    return std::pair{i, (v - xs[i]) / (xs[i + 1] - xs[i])};
  };
  std::vector<double> sorted_speeds = speeds;
  std::sort(sorted_speeds.begin(), sorted_speeds.end());
  for (std::size_t k = 0; k < map.size(); k += 97) {
    const double u = map[k][0], c = map[k][1];
    const auto [i, s] = bracket(sorted_speeds, u);
    const auto [j, t] = bracket(levels, c);
    const double expected =
        (1 - s) * (1 - t) * law(sorted_speeds[i], levels[j]) + s * (1 - t) * law(sorted_speeds[i + 1], levels[j]) +
        (1 - s) * t * law(sorted_speeds[i], levels[j + 1]) + s * t * law(sorted_speeds[i + 1], levels[j + 1]);
    EXPECT_NEAR(map[k][2], expected, 1e-9) << "at u = " << u << ", current_v = " << c;
  }
  // The runs at their coordinates, all of them.
  EXPECT_EQ(blocks[1].second.size(), levels.size() * speeds.size());
  // The frame outside the range is shaded.
  EXPECT_EQ(figure.panels[0].shaded.size(), 4u);
  EXPECT_LT((*figure.panels[0].x_range)[0], -0.2);
  EXPECT_GT((*figure.panels[0].y_range)[1], 0.2);
  EXPECT_NE(test::read_text(files.script).find("outside the surface'.\"'\".'s range"), std::string::npos);
}

TEST(Plots, OneAxisSurfaceCurveMatchesLinearInterpolationAndContinuesWhereThePolicyAllows) {
  TempDir dir;
  ASSERT_EQ(
      run_cli({"import", kExamples + "asr-v-surge-damping.csv", "--body", "asr-v", "--sign", "opposing"}, dir.path())
          .exit_code,
      0);
  ASSERT_EQ(run_cli({"surface", "build", "lin", "--body", "asr-v", "--outputs", "X", "--axes", "u", "--method",
                     "linear", "--extrapolate", "linear"},
                    dir.path())
                .exit_code,
            0);
  ASSERT_EQ(
      run_cli({"surface", "build", "strict", "--body", "asr-v", "--outputs", "X", "--axes", "u"}, dir.path()).exit_code,
      0);
  RunDatabase database(dir / "hydrocoef.db", RunDatabase::OpenMode::MustExist);
  const auto [u, x] = surge_table();
  const auto blocks = read_blocks(render(surface_figure(database, "lin", std::string("X")), dir / "lin.svg").data);
  ASSERT_EQ(blocks.size(), 4u);  // curve, continuation below, above, runs
  for (const auto& row : blocks[0].second) {
    std::size_t i = 0;
    while (i + 2 < u.size() && row[0] > u[i + 1]) ++i;
    const double s = (row[0] - u[i]) / (u[i + 1] - u[i]);
    EXPECT_NEAR(row[1], -((1 - s) * x[i] + s * x[i + 1]), 1e-12) << "at u = " << row[0];  // on the body
  }
  EXPECT_LT(blocks[1].second.front()[0], 0.0);
  EXPECT_GT(blocks[2].second.back()[0], u.back());
  ASSERT_EQ(blocks[3].second.size(), u.size());
  for (std::size_t i = 0; i < u.size(); ++i) EXPECT_NEAR(blocks[3].second[i][1], -x[i], 1e-15);
  // Policy "error": no continuation, only the shading.
  const auto strict = surface_figure(database, "strict", std::nullopt);
  ASSERT_EQ(strict.panels[0].series.size(), 2u);
  EXPECT_EQ(strict.panels[0].shaded.size(), 2u);
}

TEST(Plots, MissingThingsAreClearErrors) {
  TempDir dir;
  {
    RunDatabase empty(dir / "empty.db");
    EXPECT_NE(error_of([&] { fit_figure(empty, "x"); }).find("has no runs"), std::string::npos);
    EXPECT_NE(error_of([&] { surface_figure(empty, "nope", std::nullopt); }).find("nope"), std::string::npos);
  }
  ASSERT_EQ(
      run_cli({"import", kExamples + "asr-v-surge-damping.csv", "--body", "asr-v", "--sign", "opposing"}, dir.path())
          .exit_code,
      0);
  RunDatabase database(dir / "hydrocoef.db", RunDatabase::OpenMode::MustExist);
  EXPECT_NE(error_of([&] { fit_figure(database, "x"); }).find("has no fits"), std::string::npos);
  ASSERT_EQ(run_cli({"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u|u|"}, dir.path()).exit_code, 0);
  ASSERT_EQ(
      run_cli({"surface", "build", "s", "--body", "asr-v", "--outputs", "X", "--axes", "u"}, dir.path()).exit_code, 0);
  const std::string missing_fit = error_of([&] { fit_figure(database, "asr-v:N(r)"); });
  EXPECT_NE(missing_fit.find("no fit 'asr-v:N(r)'"), std::string::npos) << missing_fit;
  EXPECT_NE(missing_fit.find("asr-v:X(u,u|u|)"), std::string::npos) << missing_fit;  // names what exists
  const std::string missing_surface = error_of([&] { surface_figure(database, "nope", std::nullopt); });
  EXPECT_NE(missing_surface.find("nope"), std::string::npos);
  EXPECT_NE(missing_surface.find("s"), std::string::npos);
  EXPECT_NE(error_of([&] { surface_figure(database, "s", std::string("N")); }), "(no error)");
}

TEST(Plots, SimulationAgainstExperimentAndSteadyYawRate) {
  TempDir dir;
  write(dir / "traj.csv", "t [s],u [m s^-1],r [rad s^-1]\n0,0,0\n1,0,0.1\n2,0,0.14\n3,0,0.15\n");
  write(dir / "measured.csv", "# pool test\nt [s],r [deg s^-1]\n0.5,2.0\n2.5,8.0\n");
  const auto files = render(simulation_figure(dir / "traj.csv", dir / "measured.csv", "r"), dir / "sim.png");
  const auto blocks = read_blocks(files.data);
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].second[2], (std::vector<double>{2.0, 0.14}));
  EXPECT_NEAR(blocks[1].second[1][1], 8.0 * std::numbers::pi / 180.0,
              1e-15);  // measured, converted to rad/s
  EXPECT_NE(error_of([&] { simulation_figure(dir / "traj.csv", std::nullopt, "x"); }).find("u, v, w"),
            std::string::npos);
  EXPECT_NE(error_of([&] { simulation_figure(dir / "traj.csv", std::nullopt, "q"); }).find("no column q"),
            std::string::npos);

  // Steady yaw rate of the ASR-V model: tau + N(r) = 0 with the vehicle's law
  // N = c0 + c1 r + c2 r|r| (on the body), solved here as a quadratic.
  const VehicleModel model(load_vehicle(kExamples + "vehicle.json"));
  const std::vector<double> taus{0.0027, 0.0036, 0.0045};
  write(dir / "points.csv", "tau [N m],r [rad s^-1]\n0.0027,0.15\n0.0045,0.21\n");
  const auto measured = read_steady_points(dir / "points.csv");
  ASSERT_EQ(measured.size(), 2u);
  const auto steady = render(steady_figure(model, 5, taus, measured, "asr-v"), dir / "steady.svg");
  const auto sb = read_blocks(steady.data);
  ASSERT_GE(sb.size(), 2u);
  const double c0 = 1.89812e-05, c1 = -0.00607516, c2 = -0.0771371;
  for (std::size_t i = 0; i < taus.size(); ++i) {
    const double q = taus[i] + c0;  // -c2 r^2 - c1 r = q
    const double r = (c1 + std::sqrt(c1 * c1 - 4 * c2 * q)) / (-2 * c2);
    EXPECT_NEAR(sb[0].second[i][1], r, 1e-9) << "tau " << taus[i];
  }
  EXPECT_NEAR(sb[0].second[0][1], 0.15245, 1e-5);  // the README's figure
  EXPECT_EQ(sb.back().second[1], (std::vector<double>{0.0045, 0.21}));
  write(dir / "bad.csv", "tau,r\n0.1,abc\n");
  EXPECT_NE(error_of([&] { read_steady_points(dir / "bad.csv"); }).find("bad.csv:2"), std::string::npos);
}

}  // namespace
}  // namespace hydrocoef::plot

namespace hydrocoef::plot {
namespace {

// Runs of a stated uncertainty 0.01 N on a u x current_v grid: a linear
// surface's stated sd is that uncertainty interpolated (0.01 everywhere) and
// its leave-one-out RMS, in quadrature; the sigma map is that number at
// every point, the RMS read from the surface's stored quality.
TEST(Plots, SigmaMapIsTheStatedStandardDeviationOverTheRange) {
  TempDir dir;
  std::ostringstream table;
  table.precision(17);
  table << "u [m s^-1],current_v [m s^-1],X [N]\n";
  for (double c : {0.0, 0.1, 0.2})
    for (double u : {-0.2, 0.1, 0.2, 0.3})
      table << u << "," << c << "," << (0.1 + c) * u + 11 * u * std::abs(u) << "\n";
  write(dir / "sweep.csv", table.str());
  ASSERT_EQ(run_cli({"import", "sweep.csv", "--body", "b", "--disturbance", "current_v", "--uncertainty", "X=0.01"},
                    dir.path())
                .exit_code,
            0);
  ASSERT_EQ(run_cli({"surface", "build", "s2", "--body", "b", "--outputs", "X", "--axes", "u,current_v", "--method",
                     "linear"},
                    dir.path())
                .exit_code,
            0);
  RunDatabase database(dir / "hydrocoef.db", RunDatabase::OpenMode::MustExist);
  const auto quality = nlohmann::json::parse(database.surface("s2").quality);
  const double loo = quality["outputs"]["X"]["loo_rms"];
  ASSERT_GT(loo, 0.0);
  const Figure figure = surface_sigma_figure(database, "s2", std::nullopt);
  ASSERT_EQ(figure.panels.size(), 1u);
  EXPECT_NE(figure.panels[0].title.find("runs' uncertainty interpolated"), std::string::npos);
  const auto blocks = read_blocks(render(figure, dir / "sigma.svg").data);
  ASSERT_EQ(blocks.size(), 2u);  // the map, the runs
  ASSERT_EQ(blocks[0].second.size(), 81u * 81u);
  for (const auto& row : blocks[0].second)
    EXPECT_NEAR(row[2], std::hypot(0.01, loo), 1e-12) << row[0] << ", " << row[1];
  EXPECT_EQ(blocks[1].second.size(), 12u);
  // A missing surface is named.
  EXPECT_NE(error_of([&] { surface_sigma_figure(database, "nope", std::nullopt); }).find("nope"), std::string::npos);
}

}  // namespace
}  // namespace hydrocoef::plot
