// Batch evaluation (src/surface/batch_evaluation): every point equal, bit for
// bit, to CoefficientSurface::evaluate (and with_gradient) at that point, for
// every interpolation method, 1 to 6 axes, even and uneven breakpoints, every
// extrapolation policy, several outputs, strided and broadcast columns and
// any thread count; the first refused point in index order is the one
// reported, with the surface's message.
#include "src/surface/batch_evaluation.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/core/error.hpp"
#include "src/surface/rbf_surface.hpp"

namespace hydrocoef {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// A table of `axes` axes with `outputs` outputs of smooth non-separable values.
GridTable make_table(std::size_t axes, std::size_t outputs, Interpolation method, bool even, Extrapolation policy,
                     std::mt19937_64& random) {
  std::vector<GridAxis> grid;
  std::size_t nodes = 1;
  for (std::size_t a = 0; a < axes; ++a) {
    const std::size_t count = axes > 4 ? 3 : 4 + a;
    std::vector<double> x(count);
    for (std::size_t i = 0; i < count; ++i)
      x[i] = -0.5 + static_cast<double>(i) / static_cast<double>(count - 1) +
             (even || i == 0 || i + 1 == count ? 0.0 : 0.07 * std::sin(static_cast<double>(3 * i + a)));
    grid.push_back({"x" + std::to_string(a), x, policy});
    nodes *= count;
  }
  std::vector<std::string> names;
  for (std::size_t k = 0; k < outputs; ++k) names.push_back("F" + std::to_string(k));
  std::uniform_real_distribution<double> value(-2.0, 2.0);
  std::vector<double> values(nodes * outputs);
  for (auto& v : values) v = value(random);
  return GridTable(std::move(grid), std::move(names), std::move(values), method);
}

/// Points inside the ranges, some outside by up to 20 %, and the breakpoints themselves.
std::vector<double> make_points(const CoefficientSurface& s, std::size_t n, bool outside, std::mt19937_64& random) {
  const std::size_t axes = s.axis_count();
  std::vector<double> points(n * axes);
  std::uniform_real_distribution<double> unit(outside ? -0.2 : 0.0, outside ? 1.2 : 1.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t a = 0; a < axes; ++a) {
      const auto& x = s.grid()->axes()[a].breakpoints;
      points[i * axes + a] = i % 7 == 0 ? x[i % x.size()] : s.lower(a) + unit(random) * (s.upper(a) - s.lower(a));
    }
  return points;
}

/// Evaluates the interleaved points as a batch and compares with the point calls.
void expect_batch_equals_points(const CoefficientSurface& s, const std::vector<double>& points, bool gradient,
                                unsigned threads, const std::string& label) {
  const std::size_t axes = s.axis_count(), outputs = s.output_count(), n = points.size() / axes;
  std::vector<StridedInput> in;
  for (std::size_t a = 0; a < axes; ++a) in.push_back({points.data() + a, static_cast<std::ptrdiff_t>(axes)});
  std::vector<double> out(n * outputs, kNaN), grad(gradient ? n * outputs * axes : 0, kNaN);
  std::vector<StridedOutput> out_columns, grad_columns;
  for (std::size_t k = 0; k < outputs; ++k) out_columns.push_back({out.data() + k * n, 1});
  for (std::size_t g = 0; gradient && g < outputs * axes; ++g)
    grad_columns.push_back({grad.data() + g, static_cast<std::ptrdiff_t>(outputs * axes)});
  evaluate_batch(s, n, in, out_columns, grad_columns, threads);
  std::vector<double> expected(outputs), expected_gradient(outputs * axes);
  for (std::size_t i = 0; i < n; ++i) {
    const std::span<const double> point(points.data() + i * axes, axes);
    if (gradient)
      s.evaluate_with_gradient(point, expected, expected_gradient);
    else
      s.evaluate(point, expected);
    for (std::size_t k = 0; k < outputs; ++k)
      ASSERT_EQ(std::bit_cast<std::uint64_t>(out[k * n + i]), std::bit_cast<std::uint64_t>(expected[k]))
          << label << ": point " << i << " output " << k << ": " << out[k * n + i] << " vs " << expected[k];
    for (std::size_t g = 0; gradient && g < outputs * axes; ++g)
      ASSERT_EQ(grad[i * outputs * axes + g], expected_gradient[g]) << label << ": point " << i << " gradient " << g;
  }
}

TEST(BatchEvaluation, EqualsPointEvaluationBitForBitForEveryMethodAndAxisCount) {
  std::mt19937_64 random(11);
  for (const auto method : {Interpolation::Nearest, Interpolation::Linear, Interpolation::Pchip, Interpolation::Akima,
                            Interpolation::NaturalSpline})
    for (std::size_t axes = 1; axes <= kMaxGridAxes; ++axes)
      for (const bool even : {true, false})
        for (const std::size_t outputs : {std::size_t{1}, std::size_t{3}, std::size_t{6}}) {
          const CoefficientSurface s(make_table(axes, outputs, method, even, Extrapolation::Error, random));
          const std::string label = std::string(interpolation_name(method)) + ", " + std::to_string(axes) + " axes, " +
                                    (even ? "even" : "uneven") + ", " + std::to_string(outputs) + " outputs";
          const auto points = make_points(s, axes > 4 ? 300 : 2000, false, random);
          expect_batch_equals_points(s, points, false, 1, label);
          if (axes <= 3) expect_batch_equals_points(s, points, true, 2, label + ", gradient");
        }
}

TEST(BatchEvaluation, PointsOutsideFollowEachAxissPolicy) {
  std::mt19937_64 random(12);
  for (const auto policy : {Extrapolation::Clamp, Extrapolation::Linear, Extrapolation::Method})
    for (const auto method : {Interpolation::Linear, Interpolation::Pchip, Interpolation::NaturalSpline})
      for (std::size_t axes = 1; axes <= 3; ++axes) {
        const CoefficientSurface s(make_table(axes, 2, method, axes != 2, policy, random));
        const std::string label = std::string(extrapolation_name(policy)) + ", " +
                                  std::string(interpolation_name(method)) + ", " + std::to_string(axes) + " axes";
        expect_batch_equals_points(s, make_points(s, 20'000, true, random), false, 0, label);
      }
}

TEST(BatchEvaluation, RbfSurfacesGoThroughTheirOwnEvaluation) {
  std::mt19937_64 random(13);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> points, values;
  for (int i = 0; i < 40; ++i) {
    const double u = unit(random), v = unit(random);
    points.insert(points.end(), {u, v});
    values.push_back(std::sin(3 * u) * v);
  }
  RbfOptions options;
  options.axis_names = {"u", "v"};
  options.out_of_range = {RbfOutOfRange::Clamp, RbfOutOfRange::Clamp};
  const CoefficientSurface s(RbfSurface(2, points, 1, values, options), {"u", "v"}, {"X"});
  std::vector<double> queries;
  for (int i = 0; i < 3000; ++i) queries.insert(queries.end(), {unit(random) * 1.4 - 0.2, unit(random)});
  expect_batch_equals_points(s, queries, false, 2, "rbf");
  expect_batch_equals_points(s, queries, true, 1, "rbf, gradient");
}

TEST(BatchEvaluation, TheFirstRefusedPointIsReportedAndThePointsBeforeItWritten) {
  std::mt19937_64 random(14);
  const CoefficientSurface s(make_table(2, 1, Interpolation::Pchip, true, Extrapolation::Error, random));
  const std::size_t n = 100'000;
  std::vector<double> u(n, 0.1), v(n, 0.2), out(n, kNaN);
  u[77'777] = kNaN;
  v[50'001] = 0.9;  // outside [-0.5, 0.5]
  u[99'999] = 5.0;
  const StridedInput in[] = {{u.data(), 1}, {v.data(), 1}};
  const StridedOutput columns[] = {{out.data(), 1}};
  for (const unsigned threads : {1u, 2u, 4u}) {
    std::string message;
    try {
      evaluate_batch(s, n, in, columns, {}, threads);
      ADD_FAILURE() << "expected an InputError";
    } catch (const InputError& error) {
      message = error.what();
    }
    std::string expected;
    try {
      const double point[] = {0.1, 0.9};
      double value = 0.0;
      s.evaluate(point, std::span<double>(&value, 1));
    } catch (const InputError& error) {
      expected = error.what();
    }
    ASSERT_FALSE(expected.empty());
    EXPECT_EQ(message, "point 50001: " + expected) << threads << " threads";
    const double point[] = {0.1, 0.2};
    double value = 0.0;
    s.evaluate(point, std::span<double>(&value, 1));
    for (std::size_t i = 0; i < 50'001; ++i) ASSERT_EQ(out[i], value) << i;
  }
}

TEST(BatchEvaluation, BroadcastColumnsEmptyBatchesAndBadColumns) {
  std::mt19937_64 random(15);
  const CoefficientSurface s(make_table(2, 2, Interpolation::Linear, true, Extrapolation::Error, random));
  const double u = 0.125, v = -0.25;
  std::vector<double> out(3 * 10, kNaN);
  const StridedInput in[] = {{&u, 0}, {&v, 0}};
  const StridedOutput columns[] = {{out.data(), 3}, {out.data() + 1, 3}};  // interleaved, every third slot
  evaluate_batch(s, 10, in, columns, {}, 3);
  const double point[] = {u, v};
  double expected[2];
  s.evaluate(point, expected);
  for (std::size_t i = 0; i < 10; ++i) {
    EXPECT_EQ(out[3 * i], expected[0]);
    EXPECT_EQ(out[3 * i + 1], expected[1]);
    EXPECT_TRUE(std::isnan(out[3 * i + 2]));
  }
  // Nothing to do: no column is read.
  const StridedInput none[] = {{nullptr, 1}, {nullptr, 1}};
  const StridedOutput no_out[] = {{nullptr, 1}, {nullptr, 1}};
  EXPECT_NO_THROW(evaluate_batch(s, 0, none, no_out, {}));
  EXPECT_THROW(evaluate_batch(s, 1, none, no_out, {}), std::invalid_argument);
  EXPECT_THROW(evaluate_batch(s, 1, std::span(in, 1), columns, {}), std::invalid_argument);
  EXPECT_THROW(evaluate_batch(s, 1, in, columns, std::span(columns, 1)), std::invalid_argument);
}

}  // namespace
}  // namespace hydrocoef
