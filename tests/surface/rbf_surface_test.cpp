// RBF surfaces over scattered samples: exact interpolation, polynomial
// reproduction, accuracy on smooth analytic functions at fresh points,
// gradients against finite differences, leave-one-out errors against
// brute-force refits, smoothing of noisy data, unit invariance of the axis
// scaling, grid resampling with far-from-data reporting, range policies, an
// allocation-free and thread-safe evaluation, and the errors.
#include "src/surface/rbf_surface.hpp"

#include <gtest/gtest.h>

#include "tests/support/expect_input_error.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <memory>
#include <new>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "src/core/error.hpp"

#include "tests/support/count_allocations.hpp"

namespace hydrocoef {
namespace {

// Radical inverse of index in base: the Halton sequence's coordinate.
double halton(std::size_t index, std::size_t base) {
  double result = 0.0;
  double fraction = 1.0 / static_cast<double>(base);
  while (index > 0) {
    result += fraction * static_cast<double>(index % base);
    index /= base;
    fraction /= static_cast<double>(base);
  }
  return result;
}

// count points in [lo, hi]^axes from the Halton sequence with the given bases,
// starting at index first (sample-major).
std::vector<double> halton_points(std::size_t count, const std::vector<std::size_t>& bases, double lo, double hi,
                                  std::size_t first = 1) {
  std::vector<double> points;
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t base : bases) points.push_back(lo + (hi - lo) * halton(first + i, base));
  return points;
}

using Function = std::function<std::vector<double>(const double*)>;

std::vector<double> sample(const std::vector<double>& points, std::size_t axes, const Function& f) {
  std::vector<double> values;
  for (std::size_t i = 0; i < points.size() / axes; ++i)
    for (double value : f(&points[i * axes])) values.push_back(value);
  return values;
}

std::vector<double> eval(const RbfSurface& surface, std::vector<double> point) {
  std::vector<double> out(surface.output_count());
  surface.evaluate(point, out);
  return out;
}

using test::expect_input_error;

// sin(3u) cos(2v) + u v on [0, 1]^2 and a second output, so that two outputs share one factorization.
std::vector<double> smooth_pair(const double* x) {
  return {std::sin(3.0 * x[0]) * std::cos(2.0 * x[1]) + x[0] * x[1], std::exp(-x[0]) + x[1] * x[1]};
}

struct KernelCase {
  RbfKernel kernel;
  int degree;
  const char* name;
};

void PrintTo(const KernelCase& c, std::ostream* out) { *out << c.name; }

class RbfKernels : public ::testing::TestWithParam<KernelCase> {};

INSTANTIATE_TEST_SUITE_P(All, RbfKernels,
                         ::testing::Values(KernelCase{RbfKernel::Cubic, 1, "cubic1"},
                                           KernelCase{RbfKernel::Cubic, 2, "cubic2"},
                                           KernelCase{RbfKernel::ThinPlate, 1, "thinplate1"},
                                           KernelCase{RbfKernel::ThinPlate, 2, "thinplate2"},
                                           KernelCase{RbfKernel::Linear, 0, "linear0"},
                                           KernelCase{RbfKernel::Linear, 1, "linear1"}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST_P(RbfKernels, InterpolatesTheSamplesWithoutSmoothing) {
  for (std::size_t axes : {1u, 2u, 3u}) {
    const std::vector<std::size_t> bases = {2, 3, 5};
    const std::vector<double> points =
        halton_points(60, std::vector<std::size_t>(bases.begin(), bases.begin() + static_cast<long>(axes)), -1.0, 2.0);
    const auto f = [axes](const double* x) {
      double s = 0.0;
      for (std::size_t a = 0; a < axes; ++a) s += std::sin(1.7 * x[a] + static_cast<double>(a));
      return std::vector<double>{s, std::exp(0.3 * x[0]) - 4.0};
    };
    const std::vector<double> values = sample(points, axes, f);
    RbfOptions options;
    options.kernel = GetParam().kernel;
    options.polynomial_degree = GetParam().degree;
    const RbfSurface surface(axes, points, 2, values, options);
    double largest = 0.0;
    for (double v : values) largest = std::max(largest, std::abs(v));
    for (std::size_t i = 0; i < surface.sample_count(); ++i) {
      const auto out = eval(
          surface, {points.begin() + static_cast<long>(i * axes), points.begin() + static_cast<long>((i + 1) * axes)});
      for (std::size_t k = 0; k < 2; ++k)
        EXPECT_NEAR(out[k], values[i * 2 + k], 1e-10 * largest) << axes << " axes, sample " << i << " output " << k;
    }
  }
}

TEST_P(RbfKernels, GradientMatchesCentralDifferences) {
  const std::vector<double> points = halton_points(80, {2, 3}, 0.0, 1.0);
  // Axes of different sizes (u in m/s, r in rad/s over a wider range) so that the chain rule through the scaling
  // counts.
  std::vector<double> scaled_points = points;
  for (std::size_t i = 0; i < scaled_points.size(); i += 2) scaled_points[i + 1] *= 4.0;
  const std::vector<double> values = sample(scaled_points, 2, [](const double* x) {
    return std::vector<double>{std::sin(3.0 * x[0]) * std::cos(0.5 * x[1]), x[0] * x[1] * x[1]};
  });
  RbfOptions options;
  options.kernel = GetParam().kernel;
  options.polynomial_degree = GetParam().degree;
  const RbfSurface surface(2, scaled_points, 2, values, options);
  const std::vector<double> queries = halton_points(20, {5, 7}, 0.05, 0.95);
  for (std::size_t q = 0; q < 20; ++q) {
    std::vector<double> point = {queries[2 * q], 4.0 * queries[2 * q + 1]};
    std::vector<double> out(2);
    std::vector<double> gradient(4);
    surface.evaluate_with_gradient(point, out, gradient);
    EXPECT_EQ(out, eval(surface, point));
    for (std::size_t a = 0; a < 2; ++a) {
      const double h = 1e-6 * surface.length_scale(a);
      std::vector<double> plus = point;
      std::vector<double> minus = point;
      plus[a] += h;
      minus[a] -= h;
      const auto up = eval(surface, plus);
      const auto down = eval(surface, minus);
      for (std::size_t k = 0; k < 2; ++k) {
        const double difference = (up[k] - down[k]) / (2.0 * h);
        EXPECT_NEAR(gradient[k * 2 + a], difference, 1e-6 * (1.0 + std::abs(difference)))
            << "query " << q << " output " << k << " axis " << a;
      }
    }
  }
}

TEST_P(RbfKernels, LeaveOneOutErrorsEqualBruteForceRefits) {
  for (double smoothing : {0.0, 1e-3}) {
    const std::size_t n = 30;
    std::vector<double> points = halton_points(n, {2, 3}, 0.0, 1.0);
    for (std::size_t i = 0; i < n; ++i) points[2 * i] = -1.0 + 3.0 * points[2 * i];  // u in [-1, 2]
    const std::vector<double> values = sample(points, 2, smooth_pair);
    RbfOptions options;
    options.kernel = GetParam().kernel;
    options.polynomial_degree = GetParam().degree;
    options.smoothing = smoothing;
    const RbfSurface surface(2, points, 2, values, options);
    const RbfCrossValidation& cv = surface.cross_validation();
    ASSERT_EQ(cv.errors.size(), n * 2);
    EXPECT_EQ(cv.undefined_count, 0u);

    // Refit without sample i, keeping the full surface's scaling (leaving a
    // sample out may shrink the range) and letting it extrapolate to x_i.
    RbfOptions refit_options = options;
    refit_options.length_scales = {surface.length_scale(0), surface.length_scale(1)};
    refit_options.out_of_range = {RbfOutOfRange::Extrapolate, RbfOutOfRange::Extrapolate};
    std::vector<double> max_abs(2, 0.0);
    std::vector<double> sum_squares(2, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      std::vector<double> others_points;
      std::vector<double> others_values;
      for (std::size_t l = 0; l < n; ++l) {
        if (l == i) continue;
        others_points.insert(others_points.end(), {points[2 * l], points[2 * l + 1]});
        others_values.insert(others_values.end(), {values[2 * l], values[2 * l + 1]});
      }
      const RbfSurface refit(2, others_points, 2, others_values, refit_options);
      const auto predicted = eval(refit, {points[2 * i], points[2 * i + 1]});
      for (std::size_t k = 0; k < 2; ++k) {
        const double expected = values[2 * i + k] - predicted[k];
        EXPECT_NEAR(cv.errors[2 * i + k], expected, 1e-8 * (1.0 + std::abs(expected)))
            << "smoothing " << smoothing << " sample " << i << " output " << k;
        max_abs[k] = std::max(max_abs[k], std::abs(expected));
        sum_squares[k] += expected * expected;
      }
    }
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_NEAR(cv.max_abs[k], max_abs[k], 1e-8 * max_abs[k]);
      EXPECT_NEAR(cv.rms[k], std::sqrt(sum_squares[k] / static_cast<double>(n)), 1e-8 * max_abs[k]);
      EXPECT_GT(cv.max_abs[k], 0.0);
    }
  }
}

TEST(RbfSurface, LeaveOneOutIsUndefinedForASampleThePolynomialNeeds) {
  // Four samples on the line v = 0 and one off it: without that one, the
  // others cannot determine a degree-1 polynomial in (u, v).
  const std::vector<double> points = {0.0, 0.0, 0.3, 0.0, 0.7, 0.0, 1.0, 0.0, 0.4, 1.0};
  const std::vector<double> values = {1.0, 2.0, 0.5, 3.0, 4.0};
  const RbfSurface surface(2, points, 1, values);
  const RbfCrossValidation& cv = surface.cross_validation();
  EXPECT_EQ(cv.undefined_count, 1u);
  EXPECT_TRUE(std::isnan(cv.errors[4]));
  for (std::size_t i = 0; i < 4; ++i) {
    ASSERT_TRUE(std::isfinite(cv.errors[i])) << i;
    std::vector<double> others_points;
    std::vector<double> others_values;
    for (std::size_t l = 0; l < 5; ++l) {
      if (l == i) continue;
      others_points.insert(others_points.end(), {points[2 * l], points[2 * l + 1]});
      others_values.push_back(values[l]);
    }
    RbfOptions refit_options;
    refit_options.length_scales = {surface.length_scale(0), surface.length_scale(1)};
    refit_options.out_of_range = {RbfOutOfRange::Extrapolate, RbfOutOfRange::Extrapolate};
    const RbfSurface refit(2, others_points, 1, others_values, refit_options);
    EXPECT_NEAR(cv.errors[i], values[i] - eval(refit, {points[2 * i], points[2 * i + 1]})[0], 1e-9) << i;
  }
}

TEST(RbfSurface, ReproducesLinearAndQuadraticFunctionsEverywhere) {
  const std::vector<double> points = halton_points(40, {2, 3, 5}, -0.5, 0.5);
  const auto linear = [](const double* x) { return std::vector<double>{2.0 + 3.0 * x[0] - 4.0 * x[1] + 0.5 * x[2]}; };
  const auto quadratic = [](const double* x) {
    return std::vector<double>{1.0 - x[0] + 2.0 * x[1] * x[2] + 3.0 * x[0] * x[0] - x[2] * x[2]};
  };
  RbfOptions options;
  options.out_of_range.assign(3, RbfOutOfRange::Extrapolate);
  const RbfSurface surface(3, points, 1, sample(points, 3, linear), options);
  options.polynomial_degree = 2;
  options.kernel = RbfKernel::ThinPlate;
  const RbfSurface quadratic_surface(3, points, 1, sample(points, 3, quadratic), options);
  // Inside and well outside the samples' box.
  const std::vector<double> queries = halton_points(200, {7, 11, 13}, -1.5, 1.5);
  for (std::size_t q = 0; q < 200; ++q) {
    const std::vector<double> point(queries.begin() + static_cast<long>(3 * q),
                                    queries.begin() + static_cast<long>(3 * q + 3));
    std::vector<double> out(1);
    std::vector<double> gradient(3);
    surface.evaluate_with_gradient(point, out, gradient);
    EXPECT_NEAR(out[0], linear(point.data())[0], 1e-10) << q;
    EXPECT_NEAR(gradient[0], 3.0, 1e-9);
    EXPECT_NEAR(gradient[1], -4.0, 1e-9);
    EXPECT_NEAR(gradient[2], 0.5, 1e-9);
    EXPECT_NEAR(eval(quadratic_surface, point)[0], quadratic(point.data())[0], 1e-9) << q;
  }
}

// 200 quasi-random samples (Halton, bases 2 and 3) on the unit square, the 4
// corners among them as a CFD sweep would include its envelope's corners.
std::vector<double> sweep_200() {
  std::vector<double> points = {0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0};
  const std::vector<double> inner = halton_points(196, {2, 3}, 0.0, 1.0);
  points.insert(points.end(), inner.begin(), inner.end());
  return points;
}

// Maps unit-square points onto [u0, u1] x [v0, v1].
std::vector<double> stretched(std::vector<double> points, double u0, double u1, double v0, double v1) {
  for (std::size_t i = 0; i < points.size(); i += 2) {
    points[i] = u0 + (u1 - u0) * points[i];
    points[i + 1] = v0 + (v1 - v0) * points[i + 1];
  }
  return points;
}

struct FreshErrors {
  double max = 0.0;       // over all fresh points
  double interior = 0.0;  // over fresh points in the middle 80 % of each axis
  double rms = 0.0;
};

// Errors at 1000 fresh points (Halton, bases 5 and 7) of the box [u0, u1] x [v0, v1].
FreshErrors errors_at_fresh_points(const RbfSurface& surface, const Function& f, double u0, double u1, double v0,
                                   double v1) {
  const std::vector<double> fresh = halton_points(1000, {5, 7}, 0.0, 1.0);
  FreshErrors errors;
  double sum_squares = 0.0;
  for (std::size_t q = 0; q < 1000; ++q) {
    const double su = fresh[2 * q];
    const double sv = fresh[2 * q + 1];
    const std::vector<double> point = {u0 + (u1 - u0) * su, v0 + (v1 - v0) * sv};
    const double error = std::abs(eval(surface, point)[0] - f(point.data())[0]);
    errors.max = std::max(errors.max, error);
    if (su > 0.1 && su < 0.9 && sv > 0.1 && sv < 0.9) errors.interior = std::max(errors.interior, error);
    sum_squares += error * error;
  }
  errors.rms = std::sqrt(sum_squares / 1000.0);
  return errors;
}

double value_range(const std::vector<double>& values) {
  return *std::max_element(values.begin(), values.end()) - *std::min_element(values.begin(), values.end());
}

// Measured with these samples and points (max / range, interior max / range):
// cubic deg 1: 6.2e-3, 1.0e-3; cubic deg 2: 6.5e-3, 1.1e-3; thin-plate deg 1:
// 1.5e-2, 2.2e-3; linear deg 0: 4.6e-2, 8.3e-3. The largest errors sit on the
// edges of the square, as usual for polyharmonic splines; the bounds below
// leave about 1.5x margin.
TEST(RbfSurfaceAccuracy, SmoothFunctionFrom200ScatteredSamples) {
  const auto f = [](const double* x) {
    return std::vector<double>{std::sin(3.0 * x[0]) * std::cos(2.0 * x[1]) + x[0] * x[1]};
  };
  const std::vector<double> points = sweep_200();
  const std::vector<double> values = sample(points, 2, f);
  const double range = value_range(values);
  struct Bound {
    KernelCase kernel;
    double max;
    double interior;
  };
  for (const Bound& bound :
       {Bound{{RbfKernel::Cubic, 1, "cubic1"}, 1e-2, 1.5e-3}, Bound{{RbfKernel::Cubic, 2, "cubic2"}, 1e-2, 1.6e-3},
        Bound{{RbfKernel::ThinPlate, 1, "thinplate1"}, 2.3e-2, 3.3e-3},
        Bound{{RbfKernel::Linear, 0, "linear0"}, 7e-2, 1.3e-2}}) {
    RbfOptions options;
    options.kernel = bound.kernel.kernel;
    options.polynomial_degree = bound.kernel.degree;
    const RbfSurface surface(2, points, 1, values, options);
    const FreshErrors errors = errors_at_fresh_points(surface, f, 0.0, 1.0, 0.0, 1.0);
    EXPECT_LT(errors.max, bound.max * range) << bound.kernel.name;
    EXPECT_LT(errors.interior, bound.interior * range) << bound.kernel.name;
  }
  // The default (cubic, degree 1) in absolute terms: range 1.03, RMS measured 5.4e-4.
  const RbfSurface surface(2, points, 1, values);
  EXPECT_LT(errors_at_fresh_points(surface, f, 0.0, 1.0, 0.0, 1.0).rms, 1e-3);
}

// X = -(a u + b u|u|)(1 + c v^2): surge damping growing with a sway current,
// u in [-1.5, 1.5] m/s, v in [-0.2, 0.2] m/s. Measured max error / range with
// the default cubic kernel: 3.9e-3 scaled; 1.24e-2 with length scales of 1 m/s
// on both axes, where v hardly counts in distances.
TEST(RbfSurfaceAccuracy, DampingLikeFunctionOverAxesOfDifferentSize) {
  const double a = 0.5;
  const double b = 11.0;
  const double c = 20.0;
  const auto f = [&](const double* x) {
    return std::vector<double>{-(a * x[0] + b * x[0] * std::abs(x[0])) * (1.0 + c * x[1] * x[1])};
  };
  const std::vector<double> points = stretched(sweep_200(), -1.5, 1.5, -0.2, 0.2);
  const std::vector<double> values = sample(points, 2, f);
  const double range = value_range(values);
  const RbfSurface surface(2, points, 1, values);
  const FreshErrors scaled = errors_at_fresh_points(surface, f, -1.5, 1.5, -0.2, 0.2);
  EXPECT_LT(scaled.max, 6e-3 * range);

  RbfOptions unscaled_options;
  unscaled_options.length_scales = {1.0, 1.0};
  const RbfSurface unscaled(2, points, 1, values, unscaled_options);
  const FreshErrors plain = errors_at_fresh_points(unscaled, f, -1.5, 1.5, -0.2, 0.2);
  EXPECT_LT(scaled.max, 0.5 * plain.max);
  EXPECT_LT(scaled.rms, 0.6 * plain.rms);
}

// With the default scaling the surface does not depend on the unit an axis is
// given in: u in m/s or in mm/s, r in rad/s or deg/s.
TEST(RbfSurface, AxisUnitsDoNotChangeTheSurface) {
  const std::vector<double> points = stretched(sweep_200(), -1.0, 1.0, -0.5, 0.5);
  const std::vector<double> values = sample(points, 2, smooth_pair);
  std::vector<double> other_units = points;
  const double mm_per_m = 1000.0;
  const double deg_per_rad = 180.0 / std::numbers::pi;
  for (std::size_t i = 0; i < other_units.size(); i += 2) {
    other_units[i] *= mm_per_m;
    other_units[i + 1] *= deg_per_rad;
  }
  const RbfSurface si(2, points, 2, values);
  const RbfSurface converted(2, other_units, 2, values);
  EXPECT_NEAR(converted.length_scale(0), mm_per_m * si.length_scale(0), 1e-9);
  const std::vector<double> queries = stretched(halton_points(50, {5, 7}, 0.0, 1.0), -0.95, 0.95, -0.45, 0.45);
  for (std::size_t q = 0; q < 50; ++q) {
    const std::vector<double> point = {queries[2 * q], queries[2 * q + 1]};
    const auto expected = eval(si, point);
    const auto found = eval(converted, {point[0] * mm_per_m, point[1] * deg_per_rad});
    for (std::size_t k = 0; k < 2; ++k) EXPECT_NEAR(found[k], expected[k], 1e-9) << q;
    // Gradients convert by the chain rule.
    std::vector<double> out(2);
    std::vector<double> g_si(4);
    std::vector<double> g_converted(4);
    si.evaluate_with_gradient(point, out, g_si);
    converted.evaluate_with_gradient(std::vector<double>{point[0] * mm_per_m, point[1] * deg_per_rad}, out,
                                     g_converted);
    EXPECT_NEAR(g_converted[0] * mm_per_m, g_si[0], 1e-8);
    EXPECT_NEAR(g_converted[1] * deg_per_rad, g_si[1], 1e-8);
  }
}

// Noise uniform in [-0.05, 0.05] on the smooth function; measured RMS error
// against the truth at 1000 fresh points: 0.030 interpolating, 0.012 with
// lambda = 3e-3. Leave-one-out RMS: 0.043 and 0.033.
TEST(RbfSurface, SmoothingPullsNoisyDataTowardTheTruth) {
  const auto f = [](const double* x) {
    return std::vector<double>{std::sin(3.0 * x[0]) * std::cos(2.0 * x[1]) + x[0] * x[1]};
  };
  const std::vector<double> points = sweep_200();
  std::vector<double> values = sample(points, 2, f);
  std::mt19937 generator(12345);
  for (double& value : values) value += 0.1 * (static_cast<double>(generator()) / 4294967296.0 - 0.5);

  const RbfSurface interpolating(2, points, 1, values);
  RbfOptions options;
  options.smoothing = 3e-3;
  const RbfSurface smoothed(2, points, 1, values, options);
  const double interpolating_rms = errors_at_fresh_points(interpolating, f, 0.0, 1.0, 0.0, 1.0).rms;
  const double smoothed_rms = errors_at_fresh_points(smoothed, f, 0.0, 1.0, 0.0, 1.0).rms;
  EXPECT_GT(interpolating_rms, 0.025);
  EXPECT_LT(smoothed_rms, 0.5 * interpolating_rms);
  EXPECT_LT(smoothed.cross_validation().rms[0], 0.85 * interpolating.cross_validation().rms[0]);

  // The smoothed surface no longer passes through the noisy samples.
  double misfit = 0.0;
  for (std::size_t i = 0; i < 200; ++i)
    misfit += std::pow(eval(smoothed, {points[2 * i], points[2 * i + 1]})[0] - values[i], 2);
  EXPECT_GT(std::sqrt(misfit / 200.0), 0.01);
}

TEST(RbfSurface, ResamplesOntoAGridWithFarFromDataReport) {
  // Samples fill u in [0, 0.4] (a 5 x 6 grid) plus two at u = 1, so that the
  // range is [0, 1] on both axes and scaled units are the axis units here.
  std::vector<double> points;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 6; ++j) points.insert(points.end(), {0.1 * i, 0.2 * j});
  points.insert(points.end(), {1.0, 0.0, 1.0, 1.0});
  const std::vector<double> values = sample(points, 2, smooth_pair);
  const RbfSurface surface(2, points, 2, values);
  ASSERT_DOUBLE_EQ(surface.length_scale(0), 1.0);
  ASSERT_DOUBLE_EQ(surface.length_scale(1), 1.0);

  const std::vector<double> u = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
  const std::vector<double> v = {0.0, 0.25, 0.5, 0.75, 1.0};
  const RbfGrid grid = surface.resample({u, v}, 0.25);
  ASSERT_EQ(grid.values.size(), 11u * 5u * 2u);
  ASSERT_EQ(grid.nearest_sample_distance.size(), 55u);
  std::vector<std::size_t> expected_far;
  for (std::size_t j = 0; j < v.size(); ++j) {
    for (std::size_t i = 0; i < u.size(); ++i) {
      const std::size_t g = i + u.size() * j;  // axis 0 fastest
      const auto expected = eval(surface, {u[i], v[j]});
      EXPECT_EQ(grid.values[g * 2 + 0], expected[0]) << i << "," << j;  // outputs fastest
      EXPECT_EQ(grid.values[g * 2 + 1], expected[1]) << i << "," << j;
      double nearest = 1e300;
      for (std::size_t s = 0; s < points.size(); s += 2)
        nearest = std::min(nearest, std::hypot(u[i] - points[s], v[j] - points[s + 1]));
      EXPECT_NEAR(grid.nearest_sample_distance[g], nearest, 1e-12) << i << "," << j;
      if (nearest > 0.25) expected_far.push_back(g);
    }
  }
  EXPECT_EQ(grid.far_from_data, expected_far);
  // Spot checks by hand: (0.7, 0.5) is 0.316 from (0.4, 0.4); (0.5, 0.5) is 0.141 from (0.4, 0.4) or (0.4, 0.6).
  const auto is_far = [&](std::size_t i, std::size_t j) {
    return std::find(grid.far_from_data.begin(), grid.far_from_data.end(), i + 11 * j) != grid.far_from_data.end();
  };
  EXPECT_TRUE(is_far(7, 2));
  EXPECT_NEAR(grid.nearest_sample_distance[7 + 11 * 2], std::sqrt(0.1), 1e-12);
  EXPECT_FALSE(is_far(5, 2));
  EXPECT_FALSE(is_far(10, 0));  // a sample sits there
  EXPECT_EQ(grid.nearest_sample_distance[10], 0.0);
  EXPECT_GT(grid.far_from_data.size(), 10u);
  EXPECT_LT(grid.far_from_data.size(), 30u);

  // A threshold of 0 lists every grid point that is not a sample.
  const RbfGrid strict = surface.resample({u, v}, 0.0);
  std::size_t at_samples = 0;
  for (double distance : strict.nearest_sample_distance) at_samples += distance == 0.0;
  EXPECT_EQ(strict.far_from_data.size(), 55u - at_samples);

  // Breakpoints outside the samples' range follow the axis policy (Error by default).
  expect_input_error([&] { (void)surface.resample({{-0.1, 0.5}, v}, 0.25); }, {"axis 0", "-0.1", "[0, 1]"});
  expect_input_error([&] { (void)surface.resample({u, {0.5, 0.25}}, 0.25); }, {"axis 1", "0.5", "0.25", "increasing"});
  expect_input_error([&] { (void)surface.resample({u}, 0.25); }, {"1 axes", "2"});
  expect_input_error([&] { (void)surface.resample({u, {}}, 0.25); }, {"no breakpoints", "axis 1"});
  expect_input_error([&] { (void)surface.resample({u, v}, -1.0); }, {"threshold", "-1"});
}

TEST(RbfSurface, OutOfRangePolicies) {
  const std::vector<double> points = stretched(sweep_200(), -1.0, 1.0, 0.0, 2.0);
  const std::vector<double> values = sample(points, 2, smooth_pair);
  RbfOptions options;
  options.axis_names = {"u", "r"};
  options.out_of_range = {RbfOutOfRange::Clamp, RbfOutOfRange::Error};
  const RbfSurface surface(2, points, 2, values, options);
  EXPECT_EQ(surface.lower(0), -1.0);
  EXPECT_EQ(surface.upper(1), 2.0);
  EXPECT_EQ(surface.out_of_range(0), RbfOutOfRange::Clamp);
  EXPECT_THROW((void)surface.lower(2), std::out_of_range);

  // Clamp: beyond the range the surface is its value at the nearest end, flat along that axis.
  std::vector<double> out(2);
  std::vector<double> gradient(4);
  surface.evaluate_with_gradient(std::vector<double>{1.7, 0.5}, out, gradient);
  EXPECT_EQ(out, eval(surface, {1.0, 0.5}));
  EXPECT_EQ(gradient[0], 0.0);
  EXPECT_EQ(gradient[2], 0.0);
  EXPECT_NE(gradient[1], 0.0);
  EXPECT_EQ(eval(surface, {-1e300, 0.5}), eval(surface, {-1.0, 0.5}));
  expect_input_error(
      [&] {
        (void)eval(surface, {-std::numeric_limits<double>::infinity(), 0.5});
      },
      {"axis 'u'", "-inf", "finite"});

  // Error names the axis, the value and the range.
  expect_input_error([&] { (void)eval(surface, {0.0, 2.5}); }, {"axis 'r'", "2.5", "[0, 2]"});
  expect_input_error([&] { (void)eval(surface, {0.0, -0.001}); }, {"axis 'r'", "-0.001", "[0, 2]"});
  expect_input_error([&] { (void)eval(surface, {std::nan(""), 1.0}); }, {"axis 'u'", "nan", "finite"});

  // Extrapolate: the RBF as it stands, continuing smoothly past the range.
  options.out_of_range = {RbfOutOfRange::Extrapolate, RbfOutOfRange::Extrapolate};
  const RbfSurface extrapolating(2, points, 2, values, options);
  EXPECT_EQ(eval(extrapolating, {0.3, 0.7}), eval(surface, {0.3, 0.7}));
  const auto beyond = eval(extrapolating, {1.05, 0.5});
  EXPECT_NE(beyond, eval(extrapolating, {1.0, 0.5}));
  EXPECT_NEAR(beyond[0], eval(extrapolating, {1.0, 0.5})[0], 0.5);
  expect_input_error(
      [&] {
        (void)eval(extrapolating, {std::numeric_limits<double>::infinity(), 1.0});
      },
      {"axis 'u'", "inf"});
}

TEST(RbfSurface, EvaluationAllocatesNothingAndIsThreadSafe) {
  const std::vector<double> points = sweep_200();
  const std::vector<double> values = sample(points, 2, smooth_pair);
  RbfOptions options;
  options.polynomial_degree = 2;
  const RbfSurface surface(2, points, 2, values, options);
  const std::vector<double> queries = halton_points(400, {5, 7}, 0.0, 1.0);
  std::vector<double> serial(800);
  for (std::size_t q = 0; q < 400; ++q)
    surface.evaluate(std::span<const double>(&queries[2 * q], 2), std::span<double>(&serial[2 * q], 2));

  std::array<double, 2> out{};
  std::array<double, 4> gradient{};
  const std::size_t before = test::allocation_count();
  for (std::size_t q = 0; q < 400; ++q) {
    surface.evaluate(std::span<const double>(&queries[2 * q], 2), out);
    surface.evaluate_with_gradient(std::span<const double>(&queries[2 * q], 2), out, gradient);
  }
  EXPECT_EQ(test::allocation_count(), before);
  // The counter does see allocations (so the check above is not vacuous).
  const auto probe = std::make_unique<std::vector<double>>(8);
  EXPECT_GT(test::allocation_count(), before);

  std::vector<std::vector<double>> results(4, std::vector<double>(800));
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (int repeat = 0; repeat < 5; ++repeat)
        for (std::size_t q = 0; q < 400; ++q)
          surface.evaluate(std::span<const double>(&queries[2 * q], 2), std::span<double>(&results[t][2 * q], 2));
    });
  for (auto& thread : threads) thread.join();
  for (const auto& result : results) EXPECT_EQ(result, serial);
}

TEST(RbfSurfaceErrors, TooFewSamplesForThePolynomial) {
  const std::vector<double> points = {0.0, 0.0, 1.0, 1.0};
  expect_input_error(
      [&] {
        RbfSurface(2, points, 1, std::vector<double>{1.0, 2.0});
      },
      {"3 polynomial terms", "at least", "found 2"});
  RbfOptions quadratic;
  quadratic.polynomial_degree = 2;
  const std::vector<double> five = halton_points(5, {2, 3}, 0.0, 1.0);
  expect_input_error([&] { RbfSurface(2, five, 1, std::vector<double>(5, 1.0), quadratic); },
                     {"6 polynomial terms", "found 5"});
}

TEST(RbfSurfaceErrors, SamplesNotPoisedForThePolynomial) {
  // All on the line v = 2u - 1: a plane through them is not unique.
  std::vector<double> points;
  for (int i = 0; i < 10; ++i) points.insert(points.end(), {0.1 * i, 0.2 * i - 1.0});
  RbfOptions options;
  options.axis_names = {"u", "v"};
  expect_input_error([&] { RbfSurface(2, points, 1, std::vector<double>(10, 1.0), options); },
                     {"do not determine a degree-1 polynomial", "axis 'u', axis 'v'", "rank 2", "line"});
  // In 3-D, all in one plane.
  std::vector<double> planar = halton_points(20, {2, 3, 5}, 0.0, 1.0);
  for (std::size_t i = 0; i < 20; ++i) planar[3 * i + 2] = planar[3 * i] + planar[3 * i + 1];
  expect_input_error([&] { RbfSurface(3, planar, 1, std::vector<double>(20, 1.0)); }, {"rank 3", "plane"});
  // Degree 2 with every sample on a circle.
  std::vector<double> circle;
  for (int i = 0; i < 12; ++i) circle.insert(circle.end(), {std::cos(0.5 * i), std::sin(0.5 * i)});
  RbfOptions quadratic;
  quadratic.polynomial_degree = 2;
  expect_input_error([&] { RbfSurface(2, circle, 1, std::vector<double>(12, 1.0), quadratic); },
                     {"degree-2", "rank 5", "circle"});
  // The same points are fine for degree 1.
  EXPECT_NO_THROW(RbfSurface(2, circle, 1, std::vector<double>(12, 1.0)));
}

TEST(RbfSurfaceErrors, DuplicateAndNearlyDuplicatePoints) {
  std::vector<double> points = halton_points(10, {2, 3}, 0.0, 1.0);
  points[2 * 7] = points[2 * 2];
  points[2 * 7 + 1] = points[2 * 2 + 1];
  RbfOptions options;
  options.axis_names = {"u", "r"};
  expect_input_error([&] { RbfSurface(2, points, 1, std::vector<double>(10, 1.0), options); },
                     {"samples 2 and 7", "same point", "axis 'u' = 0.75"});
  points[2 * 7] += 1e-15;  // numerically the same point: the system is singular
  std::vector<double> values(10, 1.0);
  values[7] = 2.0;
  expect_input_error([&] { RbfSurface(2, points, 1, values, options); },
                     {"numerically singular", "closest samples are 2 and 7"});
  // Smoothing makes the near-duplicates harmless.
  options.smoothing = 1e-6;
  EXPECT_NO_THROW(RbfSurface(2, points, 1, values, options));
}

TEST(RbfSurfaceErrors, NonFiniteAndMisshapenInput) {
  std::vector<double> points = halton_points(10, {2, 3}, 0.0, 1.0);
  std::vector<double> values(20, 1.0);
  values[2 * 3 + 1] = std::nan("");
  expect_input_error([&] { RbfSurface(2, points, 2, values); }, {"sample 3", "output 1", "nan", "finite"});
  values[2 * 3 + 1] = 1.0;
  points[2 * 4 + 1] = std::numeric_limits<double>::infinity();
  expect_input_error([&] { RbfSurface(2, points, 2, values); }, {"sample 4", "axis 1", "inf"});
  points[2 * 4 + 1] = 0.5;

  expect_input_error([&] { RbfSurface(2, std::vector<double>(19, 0.5), 1, values); }, {"19 coordinates", "2 axes"});
  expect_input_error([&] { RbfSurface(2, points, 3, values); }, {"20 values", "10 samples", "3 outputs", "30"});
  expect_input_error([&] { RbfSurface(0, points, 1, values); }, {"0 axes", "1 to 6"});
  expect_input_error([&] { RbfSurface(7, std::vector<double>(70, 0.0), 1, values); }, {"7 axes", "1 to 6"});
  expect_input_error([&] { RbfSurface(2, points, 0, values); }, {"0 outputs"});

  // An axis that does not vary.
  std::vector<double> flat = points;
  for (std::size_t i = 0; i < 10; ++i) flat[2 * i + 1] = 0.05;
  expect_input_error([&] { RbfSurface(2, flat, 2, values); }, {"axis 1", "same value 0.05", "10 samples"});

  const auto with = [&](auto change) {
    RbfOptions options;
    change(options);
    return options;
  };
  expect_input_error([&] { RbfSurface(2, points, 2, values, with([](RbfOptions& o) { o.polynomial_degree = 3; })); },
                     {"degree 3", "0, 1 or 2"});
  expect_input_error([&] { RbfSurface(2, points, 2, values, with([](RbfOptions& o) { o.polynomial_degree = 0; })); },
                     {"degree 0", "cubic", "degree >= 1"});
  expect_input_error(
      [&] {
        RbfSurface(2, points, 2, values, with([](RbfOptions& o) {
                     o.kernel = RbfKernel::ThinPlate;
                     o.polynomial_degree = 0;
                   }));
      },
      {"degree 0", "thin-plate", "degree >= 1"});
  expect_input_error([&] { RbfSurface(2, points, 2, values, with([](RbfOptions& o) { o.smoothing = -1.0; })); },
                     {"smoothing -1", ">= 0"});
  expect_input_error([&] { RbfSurface(2, points, 2, values, with([](RbfOptions& o) { o.length_scales = {1.0}; })); },
                     {"1 length scales", "2 axes"});
  expect_input_error(
      [&] {
        RbfSurface(2, points, 2, values, with([](RbfOptions& o) { o.length_scales = {1.0, 0.0}; }));
      },
      {"length scale 0", "axis 1", "> 0"});
  expect_input_error([&] { RbfSurface(2, points, 2, values, with([](RbfOptions& o) { o.axis_names = {"u"}; })); },
                     {"1 axis names", "2 axes"});
  expect_input_error(
      [&] { RbfSurface(2, points, 2, values, with([](RbfOptions& o) { o.out_of_range = {RbfOutOfRange::Clamp}; })); },
      {"1 out-of-range policies", "2 axes"});

  const RbfSurface surface(2, points, 2, values);
  std::vector<double> out(2);
  std::vector<double> gradient(4);
  expect_input_error([&] { surface.evaluate(std::vector<double>{0.5}, out); }, {"1 coordinates", "2 axes"});
  // Wrong-sized output buffers are the caller's bug, not bad input (as for GridTable).
  EXPECT_THROW(surface.evaluate(std::vector<double>{0.5, 0.5}, std::span<double>(out.data(), 1)),
               std::invalid_argument);
  EXPECT_THROW(
      surface.evaluate_with_gradient(std::vector<double>{0.5, 0.5}, out, std::span<double>(gradient.data(), 2)),
      std::invalid_argument);
  expect_input_error(
      [&] {
        (void)surface.nearest_sample_distance(std::vector<double>{std::nan(""), 0.5});
      },
      {"axis 0", "nan"});
}

}  // namespace
}  // namespace hydrocoef
