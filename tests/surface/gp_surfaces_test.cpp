// GP coefficient surfaces of several outputs (src/surface/gp_surfaces.hpp)
// through CoefficientSurface and the database record
// (src/surface/stored_gp_surface.hpp): each output is the GP of its own
// column, the runs' range and its policies hold, the stored state comes back
// bit for bit, and damaged records are refused.
#include "src/surface/gp_surfaces.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "src/core/error.hpp"
#include "src/surface/coefficient_surface.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef {
namespace {

struct Runs {
  std::vector<double> x, y;  // x: (u, v) per run; y: (X, N) per run
};

double force_x(double u, double v) { return -20.0 * u * std::abs(u) + 3.0 * v * v - 0.5; }
double moment_n(double u, double v) { return std::sin(4.0 * v) * (1.0 + u); }

Runs scattered(std::size_t n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(0.0, 0.5), v(-0.2, 0.2);
  Runs runs;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = u(random), b = v(random);
    runs.x.insert(runs.x.end(), {a, b});
    runs.y.insert(runs.y.end(), {force_x(a, b), moment_n(a, b)});
  }
  return runs;
}

CoefficientSurface gp_surface(const Runs& runs, std::vector<RbfOutOfRange> policies = {}) {
  GpOptions options;
  options.starts = 3;
  return CoefficientSurface(GpSurfaces(2, runs.x, 2, runs.y, {}, options, {"u", "v"}, std::move(policies)), {"u", "v"},
                            {"X", "N"});
}

TEST(GpSurfaces, EachOutputIsTheProcessOfItsOwnColumn) {
  const Runs runs = scattered(30, 3);
  const CoefficientSurface surface = gp_surface(runs);
  ASSERT_EQ(surface.kind(), CoefficientSurface::Kind::Gp);
  EXPECT_EQ(surface.method_name(), "gp");
  EXPECT_TRUE(surface.has_standard_deviation());
  GpOptions options;
  options.starts = 3;
  for (std::size_t k = 0; k < 2; ++k) {
    std::vector<double> column;
    for (std::size_t i = 0; i < 30; ++i) column.push_back(runs.y[i * 2 + k]);
    const GpSurface alone = GpSurface::fit(runs.x, 2, column, {}, options);
    GpSurface::Workspace workspace(alone);
    for (const auto& point : std::vector<std::array<double, 2>>{{0.1, 0.05}, {0.33, -0.12}, {0.25, 0.0}}) {
      std::array<double, 2> out{}, sd{};
      surface.evaluate_with_standard_deviation(point, out, sd);
      double alone_sd = 0.0;
      EXPECT_EQ(out[k], alone.evaluate(point.data(), workspace, &alone_sd));
      EXPECT_EQ(sd[k], alone_sd);
    }
  }
}

TEST(GpSurfaces, InterpolatesItsRunsAndIsSureThere) {
  const Runs runs = scattered(30, 4);
  const CoefficientSurface surface = gp_surface(runs);
  double spread = 0.0;
  for (std::size_t i = 0; i < 30; ++i) spread = std::max(spread, std::abs(runs.y[i * 2]));
  for (std::size_t i = 0; i < 30; ++i) {
    std::array<double, 2> out{}, sd{};
    surface.evaluate_with_standard_deviation(std::span<const double>(&runs.x[i * 2], 2), out, sd);
    // Exact but for the jitter on the diagonal (gp_surface.hpp).
    EXPECT_NEAR(out[0], runs.y[i * 2], 3e-5 * spread);
    EXPECT_LT(sd[0], 1e-3 * spread);
  }
  // In a corner of the range, away from the runs, it is less sure than at them.
  std::array<double, 2> out{}, sd{};
  surface.evaluate_with_standard_deviation(std::array<double, 2>{surface.lower(0), surface.upper(1)}, out, sd);
  EXPECT_GT(sd[0], 1e-3 * spread);
}

TEST(GpSurfaces, RangePoliciesHold) {
  const Runs runs = scattered(25, 5);
  const CoefficientSurface error = gp_surface(runs);
  std::array<double, 2> out{};
  std::array<double, 4> g4{};
  try {
    error.evaluate(std::array<double, 2>{0.9, 0.0}, out);
    FAIL() << "a point outside the runs' range was answered";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("u = 0.9 is outside the runs' range"), std::string::npos) << e.what();
  }
  EXPECT_THROW(error.evaluate(std::array<double, 2>{std::nan(""), 0.0}, out), InputError);

  const CoefficientSurface clamp = gp_surface(runs, {RbfOutOfRange::Clamp, RbfOutOfRange::Error});
  const double top = clamp.upper(0);
  std::array<double, 2> at_top{}, beyond{};
  clamp.evaluate(std::array<double, 2>{top, 0.01}, at_top);
  clamp.evaluate_with_gradient(std::array<double, 2>{top + 1.0, 0.01}, beyond, g4);
  EXPECT_EQ(beyond[0], at_top[0]);
  EXPECT_EQ(g4[0], 0.0);  // dX/du: clamped
  EXPECT_NE(g4[1], 0.0);  // dX/dv: not

  const CoefficientSurface extrapolate = gp_surface(runs, {RbfOutOfRange::Extrapolate, RbfOutOfRange::Extrapolate});
  std::array<double, 2> far{}, sd{};
  extrapolate.evaluate_with_standard_deviation(std::array<double, 2>{3.0, 0.0}, far, sd);
  EXPECT_TRUE(std::isfinite(far[0]));
  std::array<double, 2> near_out{}, near_sd{};
  extrapolate.evaluate_with_standard_deviation(std::array<double, 2>{0.25, 0.0}, near_out, near_sd);
  EXPECT_GT(sd[0], 10.0 * near_sd[0]);  // far from every run it says so
}

TEST(GpSurfaces, GradientIsTheMeansSlope) {
  const CoefficientSurface surface = gp_surface(scattered(30, 6));
  const std::array<double, 2> point{0.2, 0.03};
  std::array<double, 2> out{};
  std::array<double, 4> gradient{};
  surface.evaluate_with_gradient(point, out, gradient);
  const double h = 1e-4;  // central differences: error ~ h^2, and the mean's rounding / h stays small
  for (std::size_t a = 0; a < 2; ++a) {
    std::array<double, 2> up = point, down = point, out_up{}, out_down{};
    up[a] += h;
    down[a] -= h;
    surface.evaluate(up, out_up);
    surface.evaluate(down, out_down);
    for (std::size_t k = 0; k < 2; ++k)
      EXPECT_NEAR(gradient[k * 2 + a], (out_up[k] - out_down[k]) / (2 * h),
                  1e-5 * (1.0 + std::abs(gradient[k * 2 + a])))
          << k << "," << a;
  }
}

TEST(GpSurfaces, GridsAndRbfsStateNoStandardDeviation) {
  const GridTable table({{"u", {0.0, 1.0}, Extrapolation::Error}}, {"X"}, {1.0, 2.0}, Interpolation::Linear);
  const CoefficientSurface grid(table);
  EXPECT_FALSE(grid.has_standard_deviation());
  std::array<double, 1> out{}, sd{};
  EXPECT_THROW(grid.evaluate_with_standard_deviation(std::array<double, 1>{0.5}, out, sd), InputError);
}

TEST(StoredGpSurface, ComesBackBitForBitWithoutANewFit) {
  const CoefficientSurface surface = gp_surface(scattered(40, 7), {RbfOutOfRange::Clamp, RbfOutOfRange::Extrapolate});
  SurfaceRecord record = record_from_surface(surface);
  record.name = "gp";
  EXPECT_EQ(record.kind, "gp");
  EXPECT_EQ(record.method, "matern52");
  const CoefficientSurface back = surface_from_record(record);
  ASSERT_EQ(back.kind(), CoefficientSurface::Kind::Gp);
  EXPECT_EQ(back.out_of_range_name(0), "clamp");
  EXPECT_EQ(back.out_of_range_name(1), "extrapolate");
  std::mt19937 random(1);
  std::uniform_real_distribution<double> u(-0.1, 0.6), v(-0.3, 0.3);
  for (int i = 0; i < 50; ++i) {
    const std::array<double, 2> point{u(random), v(random)};
    std::array<double, 2> a{}, b{}, sa{}, sb{};
    surface.evaluate_with_standard_deviation(point, a, sa);
    back.evaluate_with_standard_deviation(point, b, sb);
    EXPECT_EQ(a, b);
    EXPECT_EQ(sa, sb);
  }
}

TEST(StoredGpSurface, DamagedRecordsAreRefusedNamingTheSurface) {
  const SurfaceRecord good = [] {
    SurfaceRecord r = record_from_surface(gp_surface(scattered(12, 8)));
    r.name = "wake";
    return r;
  }();
  const auto refused = [](SurfaceRecord record, const std::string& expected) {
    try {
      (void)surface_from_record(record);
      ADD_FAILURE() << "accepted; expected " << expected;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("surface 'wake'"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  const auto with_definition = [&](auto change) {
    SurfaceRecord r = good;
    auto definition = nlohmann::json::parse(r.definition);
    change(definition);
    r.definition = definition.dump();
    return r;
  };
  SurfaceRecord short_data = good;
  short_data.data.pop_back();
  refused(short_data, "numbers; expected");
  SurfaceRecord nan_data = good;
  nan_data.data[3] = std::nan("");
  refused(nan_data, "not finite");
  SurfaceRecord method = good;
  method.method = "squared-exponential";
  refused(method, "is not its GP kernel");
  refused(with_definition([](auto& d) { d["gp"]["samples"] = 100000; }), "'samples' is not a whole number");
  refused(with_definition([](auto& d) { d["gp"]["samples"] = -1; }), "'samples' is not a whole number");
  refused(with_definition([](auto& d) { d.erase("gp"); }), "no 'gp'");
  refused(with_definition([](auto& d) { d["gp"]["outputs"].erase(1); }), "one entry per output");
  refused(with_definition([](auto& d) { d["gp"]["lower"][0] = 9.0; }), "lower < upper");
  refused(with_definition([](auto& d) { d["gp"]["outputs"][0]["sigma"] = -1.0; }), "positive");
  refused(with_definition([](auto& d) { d["gp"]["outputs"][0]["beta"] = nlohmann::json::array(); }), "'beta'");
  refused(with_definition([](auto& d) { d["gp"]["kernel"] = "cubic"; }), "expected matern52 or squared-exponential");
  refused(with_definition([](auto& d) { d["axes"][0]["extrapolation"] = "linear"; }),
          "expected error, clamp or extrapolate");
  // The factor's diagonal must stay positive.
  SurfaceRecord negative = good;
  const std::size_t n = 12;
  negative.data[2 * n + n] = -1.0;  // L_00 of output 0: after the points (2n) and alpha (n)
  refused(negative, "non-positive diagonal");
}

}  // namespace
}  // namespace hydrocoef
