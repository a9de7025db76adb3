// Gridded lookup surfaces: what each method reproduces exactly, agreement with
// SciPy (pchip, natural spline) and with an exact rational transcription of
// MATLAB's makima in 1-D, the tensor-product construction on separable data,
// PCHIP's monotonicity, exact gradients, every extrapolation policy, the
// validation messages, many outputs at once and concurrent evaluation.
//
// What a method reproduces (the tests check exactly this, and no more):
//  - Linear reproduces every multilinear function (sum of c_S prod_{a in S} x_a).
//  - PCHIP, makima and the natural spline reproduce every multilinear function
//    too: each 1-D slope rule is exact on linear data, so the nodal slopes
//    and mixed derivatives are exact, and a cubic Hermite piece with exact
//    slopes reproduces a linear function.
//  - None of the three cubic methods reproduces a general cubic, or even a
//    quadratic: PCHIP's harmonic mean gives 2i - 1/(2i) instead of 2i for x^2
//    at x = i on a unit grid, makima gives 2i - 1/(i+1), and a natural spline
//    has s'' = 0 at both ends, which a cubic polynomial has only if it is
//    linear (its s'' is linear and would vanish twice). What the natural
//    spline does reproduce is any natural cubic spline on its breakpoints, and
//    tensor products of them; the test builds one from the truncated-power
//    basis, independently of the spline equations.
#include "src/surface/grid_table.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <new>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "src/core/error.hpp"

#include "tests/support/count_allocations.hpp"

namespace hydrocoef {
namespace {

constexpr std::array<Interpolation, 5> kAllMethods = {Interpolation::Nearest, Interpolation::Linear,
                                                      Interpolation::Pchip, Interpolation::Akima,
                                                      Interpolation::NaturalSpline};
constexpr std::array<Interpolation, 3> kCubicMethods = {Interpolation::Pchip, Interpolation::Akima,
                                                        Interpolation::NaturalSpline};

using Point = std::vector<double>;
using Function = std::function<std::vector<double>(const Point&)>;

std::string method_label(Interpolation method) { return std::string(interpolation_name(method)); }

// Node values laid out as the constructor documents: outputs fastest, then axis 0, 1, ...
std::vector<double> tabulate(const std::vector<std::vector<double>>& breakpoints, std::size_t n_out,
                             const Function& f) {
  std::size_t nodes = 1;
  for (const auto& x : breakpoints) nodes *= x.size();
  std::vector<double> values(nodes * n_out);
  Point point(breakpoints.size());
  for (std::size_t node = 0; node < nodes; ++node) {
    std::size_t rest = node;
    for (std::size_t a = 0; a < breakpoints.size(); ++a) {
      point[a] = breakpoints[a][rest % breakpoints[a].size()];
      rest /= breakpoints[a].size();
    }
    const std::vector<double> y = f(point);
    for (std::size_t k = 0; k < n_out; ++k) values[node * n_out + k] = y[k];
  }
  return values;
}

std::vector<GridAxis> make_axes(const std::vector<std::vector<double>>& breakpoints,
                                Extrapolation policy = Extrapolation::Error) {
  std::vector<GridAxis> axes;
  const std::array<const char*, 6> names = {"u", "v", "w", "p", "q", "r"};
  for (std::size_t a = 0; a < breakpoints.size(); ++a) axes.push_back({names[a], breakpoints[a], policy});
  return axes;
}

std::vector<std::string> output_names(std::size_t count) {
  const std::array<const char*, 6> six = {"X", "Y", "Z", "K", "M", "N"};
  std::vector<std::string> names;
  for (std::size_t k = 0; k < count; ++k) names.push_back(k < 6 ? six[k] : "C" + std::to_string(k));
  return names;
}

GridTable make_table(const std::vector<std::vector<double>>& breakpoints, std::size_t n_out, const Function& f,
                     Interpolation method, Extrapolation policy = Extrapolation::Error) {
  return GridTable(make_axes(breakpoints, policy), output_names(n_out), tabulate(breakpoints, n_out, f), method);
}

std::vector<double> evenly_spaced(double lo, double hi, std::size_t count) {
  std::vector<double> x(count);
  for (std::size_t i = 0; i < count; ++i)
    x[i] = lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(count - 1);
  return x;
}

std::vector<double> unevenly_spaced(double lo, double hi, std::size_t count, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> gap(0.3, 1.7);
  std::vector<double> widths(count - 1);
  for (double& g : widths) g = gap(rng);
  double total = 0.0;
  for (double g : widths) total += g;
  std::vector<double> x(count);
  x[0] = lo;
  for (std::size_t i = 1; i < count; ++i) x[i] = x[i - 1] + (hi - lo) * widths[i - 1] / total;
  x[count - 1] = hi;
  return x;
}

Point random_point(const std::vector<std::vector<double>>& breakpoints, std::mt19937_64& rng) {
  Point point;
  for (const auto& x : breakpoints) point.push_back(std::uniform_real_distribution<double>(x.front(), x.back())(rng));
  return point;
}

std::vector<double> evaluate(const GridTable& table, const Point& point) {
  std::vector<double> out(table.output_count());
  table.evaluate(point, out);
  return out;
}

struct ValueAndGradient {
  std::vector<double> value;
  std::vector<double> gradient;
};

ValueAndGradient evaluate_with_gradient(const GridTable& table, const Point& point) {
  ValueAndGradient result{std::vector<double>(table.output_count()),
                          std::vector<double>(table.output_count() * table.axis_count())};
  table.evaluate_with_gradient(point, result.value, result.gradient);
  return result;
}

// A multilinear function with every cross term: f = sum_S c_S prod_{a in S} x_a, one coefficient set per output.
struct Multilinear {
  std::size_t axes;
  std::vector<std::vector<double>> coefficients;  // [output][subset]

  Multilinear(std::size_t axis_count, std::size_t n_out, std::mt19937_64& rng) : axes(axis_count) {
    std::uniform_real_distribution<double> c(-2.0, 2.0);
    coefficients.assign(n_out, std::vector<double>(std::size_t{1} << axis_count));
    for (auto& row : coefficients) {
      for (double& value : row) value = c(rng);
    }
  }
  std::vector<double> operator()(const Point& x) const {
    std::vector<double> f(coefficients.size(), 0.0);
    for (std::size_t k = 0; k < f.size(); ++k) {
      for (std::size_t s = 0; s < coefficients[k].size(); ++s) {
        double term = coefficients[k][s];
        for (std::size_t a = 0; a < axes; ++a) {
          if ((s >> a) & 1U) term *= x[a];
        }
        f[k] += term;
      }
    }
    return f;
  }
  // d f_k / d x_a.
  double derivative(const Point& x, std::size_t k, std::size_t axis) const {
    double sum = 0.0;
    for (std::size_t s = 0; s < coefficients[k].size(); ++s) {
      if (((s >> axis) & 1U) == 0) continue;
      double term = coefficients[k][s];
      for (std::size_t a = 0; a < axes; ++a) {
        if (a != axis && ((s >> a) & 1U)) term *= x[a];
      }
      sum += term;
    }
    return sum;
  }
};

// ---------------------------------------------------------------- reproduction

TEST(GridTable, LinearReproducesMultilinearFunctionsWithExactGradient) {
  std::mt19937_64 rng(11);
  for (std::size_t n : {1U, 2U, 3U, 5U}) {
    for (bool even : {true, false}) {
      std::vector<std::vector<double>> breakpoints;
      for (std::size_t a = 0; a < n; ++a) {
        const std::size_t count = 2 + (a + 3) % 4;  // 5, 2, 3, 4, 5 ...
        breakpoints.push_back(even ? evenly_spaced(-1.0 - 0.5 * static_cast<double>(a), 2.0, count)
                                   : unevenly_spaced(-1.0 - 0.5 * static_cast<double>(a), 2.0, count, rng));
      }
      const Multilinear f(n, 2, rng);
      const GridTable table = make_table(breakpoints, 2, f, Interpolation::Linear);
      for (std::size_t a = 0; a < n; ++a) EXPECT_EQ(table.evenly_spaced(a), even || breakpoints[a].size() == 2);
      for (int trial = 0; trial < 300; ++trial) {
        const Point x = random_point(breakpoints, rng);
        const ValueAndGradient got = evaluate_with_gradient(table, x);
        const std::vector<double> expected = f(x);
        for (std::size_t k = 0; k < 2; ++k) {
          ASSERT_NEAR(got.value[k], expected[k], 1e-12) << n << "-D, even " << even;
          for (std::size_t a = 0; a < n; ++a) {
            ASSERT_NEAR(got.gradient[k * n + a], f.derivative(x, k, a), 1e-12) << n << "-D axis " << a;
          }
        }
      }
    }
  }
}

TEST(GridTable, CubicMethodsReproduceMultilinearFunctions) {
  std::mt19937_64 rng(12);
  for (Interpolation method : kCubicMethods) {
    for (std::size_t n : {1U, 2U, 3U, 4U, 6U}) {
      std::vector<std::vector<double>> breakpoints;
      for (std::size_t a = 0; a < n; ++a) {
        const std::size_t count = n == 6 ? 3 : 3 + a;
        breakpoints.push_back(a % 2 == 0 ? unevenly_spaced(-2.0, 1.5, count, rng) : evenly_spaced(0.0, 3.0, count));
      }
      const Multilinear f(n, 3, rng);
      const GridTable table = make_table(breakpoints, 3, f, method);
      const int trials = n == 6 ? 20 : 200;
      for (int trial = 0; trial < trials; ++trial) {
        const Point x = random_point(breakpoints, rng);
        const ValueAndGradient got = evaluate_with_gradient(table, x);
        const std::vector<double> expected = f(x);
        for (std::size_t k = 0; k < 3; ++k) {
          ASSERT_NEAR(got.value[k], expected[k], 1e-12) << method_label(method) << " " << n << "-D";
          for (std::size_t a = 0; a < n; ++a) {
            ASSERT_NEAR(got.gradient[k * n + a], f.derivative(x, k, a), 1e-11) << method_label(method) << " axis " << a;
          }
        }
      }
    }
  }
}

// A natural cubic spline on knots x built from the truncated-power basis:
// s(x) = a + b x + sum_k c_k (x - x_k)_+^3. s'' = 6 sum_k c_k (x - x_k)_+ is 0
// at x_0, and 0 at and beyond the last knot when sum c_k = 0 and sum c_k x_k = 0.
struct NaturalSplineFunction {
  std::vector<double> knots;
  double a = 0.0;
  double b = 0.0;
  std::vector<double> c;

  NaturalSplineFunction(std::vector<double> x, std::mt19937_64& rng) : knots(std::move(x)), c(knots.size(), 0.0) {
    std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
    a = coefficient(rng);
    b = coefficient(rng);
    const std::size_t n = knots.size();
    // Free c_1 .. c_{n-3}; c_{n-2}, c_{n-1} solve the two conditions.
    double sum = 0.0;
    double moment = 0.0;
    for (std::size_t k = 1; k + 2 < n; ++k) {
      c[k] = coefficient(rng);
      sum += c[k];
      moment += c[k] * knots[k];
    }
    const double p = knots[n - 2];
    const double q = knots[n - 1];
    // c_p + c_q = -sum, c_p p + c_q q = -moment.
    c[n - 1] = (-moment + p * sum) / (q - p);
    c[n - 2] = -sum - c[n - 1];
  }
  double operator()(double x) const {
    double s = a + b * x;
    for (std::size_t k = 0; k < knots.size(); ++k) {
      const double r = std::max(0.0, x - knots[k]);
      s += c[k] * r * r * r;
    }
    return s;
  }
  double derivative(double x) const {
    double s = b;
    for (std::size_t k = 0; k < knots.size(); ++k) {
      const double r = std::max(0.0, x - knots[k]);
      s += 3.0 * c[k] * r * r;
    }
    return s;
  }
};

TEST(GridTable, NaturalSplineReproducesNaturalSplineFunctionsAndTheirTensorProducts) {
  std::mt19937_64 rng(13);
  const std::vector<double> x = unevenly_spaced(-1.0, 2.0, 7, rng);
  const std::vector<double> y = evenly_spaced(0.0, 1.0, 5);
  const NaturalSplineFunction sx(x, rng);
  const NaturalSplineFunction sy(y, rng);
  const NaturalSplineFunction tx(x, rng);
  // The construction really is a natural spline with curvature: s'' vanishes at both ends but not inside.
  ASSERT_GT(std::abs(sx(x[3]) - 0.5 * (sx(x[2]) + sx(x[4]))), 1e-3);

  const GridTable line = make_table(
      {x}, 1, [&](const Point& p) { return std::vector<double>{sx(p[0])}; }, Interpolation::NaturalSpline);
  // f(x, y) = sx(x) sy(y) + tx(x) lies in the tensor-product space of natural splines.
  const GridTable surface = make_table(
      {x, y}, 1, [&](const Point& p) { return std::vector<double>{sx(p[0]) * sy(p[1]) + tx(p[0])}; },
      Interpolation::NaturalSpline);
  for (int trial = 0; trial < 300; ++trial) {
    const Point p = random_point({x, y}, rng);
    const ValueAndGradient one = evaluate_with_gradient(line, {p[0]});
    EXPECT_NEAR(one.value[0], sx(p[0]), 1e-12);
    EXPECT_NEAR(one.gradient[0], sx.derivative(p[0]), 1e-11);
    const ValueAndGradient two = evaluate_with_gradient(surface, p);
    EXPECT_NEAR(two.value[0], sx(p[0]) * sy(p[1]) + tx(p[0]), 1e-12);
    EXPECT_NEAR(two.gradient[0], sx.derivative(p[0]) * sy(p[1]) + tx.derivative(p[0]), 1e-11);
    EXPECT_NEAR(two.gradient[1], sx(p[0]) * sy.derivative(p[1]), 1e-11);
  }
}

TEST(GridTable, NoCubicMethodReproducesAQuadratic) {
  // Documents the limit stated at the top of this file: x^2 on 0..6 is not reproduced between breakpoints.
  const std::vector<double> x = evenly_spaced(0.0, 6.0, 7);
  for (Interpolation method : kCubicMethods) {
    const GridTable table = make_table(
        {x}, 1, [](const Point& p) { return std::vector<double>{p[0] * p[0]}; }, method);
    EXPECT_GT(std::abs(table.evaluate_one(std::vector<double>{2.5}, 0) - 6.25), 1e-3) << method_label(method);
  }
}

TEST(GridTable, ValuesAtBreakpointsAreTheTableExactlyForEveryMethod) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> value(-5.0, 5.0);
  const std::vector<std::vector<double>> breakpoints = {
      unevenly_spaced(-1.0, 1.0, 5, rng), evenly_spaced(0.0, 0.38, 20), {0.1, 0.2, 0.7}};
  std::size_t nodes = 1;
  for (const auto& x : breakpoints) nodes *= x.size();
  std::vector<double> values(nodes * 2);
  for (double& v : values) v = value(rng);
  for (Interpolation method : kAllMethods) {
    const GridTable table(make_axes(breakpoints), output_names(2), values, method);
    for (std::size_t node = 0; node < nodes; ++node) {
      const std::size_t i0 = node % 5;
      const std::size_t i1 = (node / 5) % 20;
      const std::size_t i2 = node / 100;
      const Point p = {breakpoints[0][i0], breakpoints[1][i1], breakpoints[2][i2]};
      const std::vector<double> got = evaluate(table, p);
      ASSERT_EQ(got[0], values[node * 2]) << method_label(method) << " node " << node;
      ASSERT_EQ(got[1], values[node * 2 + 1]) << method_label(method) << " node " << node;
    }
  }
}

// ------------------------------------------------------ 1-D against references

// Uneven 1-D data and queries (some beyond both ends); the reference numbers
// come from SciPy 1.10 (PchipInterpolator; CubicSpline with bc_type="natural")
// and from MATLAB's makima.m transcribed into exact rational arithmetic
// (Python fractions). "linear" is f(b) + (x - b) f'(b) with the reference's f and f'.
const std::vector<double> kX = {0, 0.5, 1.2, 2.0, 2.3, 3.1, 4.0};
const std::vector<double> kY = {0.3, -0.1, 0.8, 1.9, 1.7, 0.4, 0.6};
const std::vector<double> kQuery = {-0.6, -0.2, 0.25, 0.9, 1.5, 2.15, 2.7, 3.5, 3.99, 4.3, 5.0};

struct Reference {
  Interpolation method;
  std::vector<double> value;  // own polynomial continued beyond the ends
  std::vector<double> slope;
  std::vector<double> linear_extrapolation;
};

std::vector<Reference> references() {
  return {
      {Interpolation::Pchip,
       {2.0365142857142864, 0.71106666666666674, -0.0043154761904762307, 0.31569564593987487, 1.3036565061475411,
        1.833341968911917, 0.96108808290155379, 0.41755829903978053, 0.59340713305898496, 0.87407407407407378,
        2.2817558299039775},
       {-4.2187619047619069, -2.4526666666666674, -0.78273809523809523, 1.6724179133011519, 1.8298539959016389,
        -0.77772020725388635, -2.2152202072538847, 0.13168724279835384, 0.65193415637860086, 1.1851851851851845,
        2.9711934156378592},
       {1.3014285714285716, 0.63380952380952382, -0.0043154761904762307, 0.31569564593987487, 1.3036565061475411,
        1.833341968911917, 0.96108808290155379, 0.41755829903978053, 0.59340713305898496, 0.79999999999999971,
        1.2666666666666662}},
      {Interpolation::NaturalSpline,
       {0.66777674531319919, 0.53141479843705508, 0.020295983887215346, 0.25634025938159399, 1.3771831538384343,
        1.8484944233291556, 1.0227407099543435, 0.27872640248734626, 0.59169882785861316, 0.82879201331928498,
        0.67961196359260345},
       {0.61129244530370652, -1.0210458046861226, -0.90627202148371289, 1.5519881953789061, 1.7707585392811853,
        -0.6901407664632172, -1.8724928360496502, 0.2672570407368382, 0.82996709807696867, 0.6275355888537697,
        -1.4215486535612722},
       {1.0350528515609108, 0.54501761718697028, 0.020295983887215346, 0.25634025938159399, 1.3771831538384343,
        1.8484944233291556, 1.0227407099543435, 0.27872640248734626, 0.59169882785861316, 0.84905768165086226,
        1.4301922721695415}},
      {
          Interpolation::Akima,
          {0.043732458860004771, 0.51660734557595989, -0.032138758049129502, 0.36929942542669708, 1.2650280422363207,
           1.8631311772842014, 1.0231426965016481, 0.29204950232299109, 0.59142787235953664, 0.8618579069532748,
           1.1175748033960895},
          {3.6042735511566897, -0.63194109229668494, -1.0374836036250894, 1.4480101436463826, 1.6484298904798402,
           -0.85536070436658573, -1.9391294478844565, 0.23430228972538994, 0.85499527821228738, 0.83661948733474623,
           -0.37672419713840394},
          {},  // filled below from the end values and slopes
      },
  };
}

TEST(GridTable, OneDimensionalCubicsMatchReferenceImplementations) {
  for (const Reference& reference : references()) {
    for (Extrapolation policy : {Extrapolation::Method, Extrapolation::Linear, Extrapolation::Clamp}) {
      const GridTable table({GridAxis{"u", kX, policy}}, {"X"}, kY, reference.method);
      // The end values and slopes, for the Linear and Clamp expectations.
      const ValueAndGradient lo = evaluate_with_gradient(table, {kX.front()});
      const ValueAndGradient hi = evaluate_with_gradient(table, {kX.back()});
      for (std::size_t i = 0; i < kQuery.size(); ++i) {
        const double x = kQuery[i];
        const bool inside = x >= kX.front() && x <= kX.back();
        const ValueAndGradient got = evaluate_with_gradient(table, {x});
        double expected = reference.value[i];
        double expected_slope = reference.slope[i];
        if (!inside && policy == Extrapolation::Clamp) {
          expected = x < kX.front() ? kY.front() : kY.back();
          expected_slope = 0.0;
        } else if (!inside && policy == Extrapolation::Linear) {
          // The end slope is the reference's slope at the end breakpoint, checked by the Method case.
          const ValueAndGradient& end = x < kX.front() ? lo : hi;
          expected = end.value[0] + (x - (x < kX.front() ? kX.front() : kX.back())) * end.gradient[0];
          expected_slope = end.gradient[0];
          if (!reference.linear_extrapolation.empty()) {
            EXPECT_NEAR(got.value[0], reference.linear_extrapolation[i], 1e-13);
          }
        }
        EXPECT_NEAR(got.value[0], expected, 1e-13) << method_label(reference.method) << " x = " << x;
        EXPECT_NEAR(got.gradient[0], expected_slope, 1e-12) << method_label(reference.method) << " x = " << x;
      }
    }
  }
}

TEST(GridTable, EndSlopesMatchReferences) {
  // Slopes at the breakpoints (SciPy, and exact makima), which fix the Linear extrapolation.
  const std::vector<std::pair<Interpolation, std::vector<double>>> slopes = {
      {Interpolation::Pchip,
       {-1.6690476190476193, 0, 1.3278688524590163, 0, -0.88911917098445614, 0, 0.66666666666666641}},
      {Interpolation::NaturalSpline,
       {-1.2250880859348514, 0.050176171869702635, 1.9714205524770771, 0.026873843981844291, -1.2663107781289773,
        -0.99371787767241715, 0.83019227216954139}},
      {Interpolation::Akima,
       {-1.3821428571428571, 0.7320772716432149, 1.3297215572634498, 0.55247043918918914, -1.1310276217228465,
        -0.86245458673932784, 0.859375}}};
  for (const auto& [method, expected] : slopes) {
    const GridTable table({GridAxis{"u", kX, Extrapolation::Error}}, {"X"}, kY, method);
    for (std::size_t i = 0; i < kX.size(); ++i) {
      // The derivative at a breakpoint is the same from either cell (C1), so the one reported is the slope.
      EXPECT_NEAR(evaluate_with_gradient(table, {kX[i]}).gradient[0], expected[i], 1e-12)
          << method_label(method) << " breakpoint " << i;
    }
  }
}

TEST(GridTable, MakimaKeepsFlatDataFlatAndDoesNotOvershootAStep) {
  // All four secants around nodes 1..4 of a step contain two zeros on one side, which makes makima's slope 0 there.
  const std::vector<double> x = {0, 1, 2, 3, 4, 5};
  const std::vector<double> y = {0, 0, 0, 1, 1, 1};
  const GridTable table({GridAxis{"u", x}}, {"X"}, y, Interpolation::Akima);
  for (int i = 0; i <= 500; ++i) {
    const double q = 5.0 * i / 500.0;
    const double f = table.evaluate_one(std::vector<double>{q}, 0);
    if (q <= 2.0) {
      EXPECT_EQ(f, 0.0) << q;
    }
    if (q >= 3.0) {
      EXPECT_EQ(f, 1.0) << q;
    }
    EXPECT_GE(f, 0.0);
    EXPECT_LE(f, 1.0);
  }
}

// --------------------------------------------------------- tensor construction

TEST(GridTable, SeparableDataGivesTheProductAndSumOfOneDimensionalInterpolants) {
  // Each 1-D slope rule is homogeneous (scaling the data scales the slopes), so
  // on data g(x) h(y) the derivatives and the cross derivative factor, and the
  // 2-D interpolant is exactly G(x) H(y), G and H the 1-D interpolants; on
  // g(x) + h(y) it is G(x) + H(y). This checks the mixed-derivative machinery
  // for the nonlinear rules (pchip, makima) against the 1-D results above.
  std::mt19937_64 rng(15);
  const std::vector<double> x = kX;
  const std::vector<double> y = unevenly_spaced(-1.0, 1.0, 6, rng);
  auto g = [](double v) { return std::sin(2.0 * v) + 0.3 * v; };
  auto h = [](double v) { return 1.5 + v * v * v - v; };
  for (Interpolation method : kCubicMethods) {
    const GridTable gx = make_table(
        {x}, 1, [&](const Point& p) { return std::vector<double>{g(p[0])}; }, method);
    const GridTable hy = make_table(
        {y}, 1, [&](const Point& p) { return std::vector<double>{h(p[0])}; }, method);
    const GridTable product = make_table(
        {x, y}, 2,
        [&](const Point& p) {
          return std::vector<double>{g(p[0]) * h(p[1]), g(p[0]) + h(p[1])};
        },
        method);
    for (int trial = 0; trial < 300; ++trial) {
      const Point p = random_point({x, y}, rng);
      const ValueAndGradient a = evaluate_with_gradient(gx, {p[0]});
      const ValueAndGradient b = evaluate_with_gradient(hy, {p[1]});
      const ValueAndGradient got = evaluate_with_gradient(product, p);
      EXPECT_NEAR(got.value[0], a.value[0] * b.value[0], 1e-12) << method_label(method);
      EXPECT_NEAR(got.value[1], a.value[0] + b.value[0], 1e-12) << method_label(method);
      EXPECT_NEAR(got.gradient[0], a.gradient[0] * b.value[0], 1e-11) << method_label(method);
      EXPECT_NEAR(got.gradient[1], a.value[0] * b.gradient[0], 1e-11) << method_label(method);
      EXPECT_NEAR(got.gradient[2], a.gradient[0], 1e-11) << method_label(method);
      EXPECT_NEAR(got.gradient[3], b.gradient[0], 1e-11) << method_label(method);
    }
  }
}

TEST(GridTable, CrossDerivativesApplyTheSlopeRuleAlongTheHigherAxisToTheLowerAxisSlopes) {
  // The documented construction on general (non-separable) data: the nodal
  // d/du come from the 1-D rule along u, and d2/du dv from the 1-D rule along v
  // applied to those d/du. On a grid line u = u_i the surface's d/du is then
  // the cubic Hermite in v of the nodal d/du and d2/du dv, which is exactly
  // the 1-D interpolant (same method) through the nodal d/du along v.
  std::mt19937_64 rng(25);
  const std::vector<double> u = unevenly_spaced(0.0, 2.0, 6, rng);
  const std::vector<double> v = unevenly_spaced(-1.0, 1.0, 5, rng);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  std::vector<double> values(u.size() * v.size());
  for (double& value : values) value = noise(rng);
  for (Interpolation method : kCubicMethods) {
    const GridTable table(make_axes({u, v}), {"X"}, values, method);
    // Nodal d/du from 1-D tables along u, row by row.
    std::vector<std::vector<double>> slope_u(u.size(), std::vector<double>(v.size()));
    for (std::size_t j = 0; j < v.size(); ++j) {
      const GridTable row({GridAxis{"u", u}}, {"X"},
                          std::vector<double>(values.begin() + static_cast<std::ptrdiff_t>(j * u.size()),
                                              values.begin() + static_cast<std::ptrdiff_t>((j + 1) * u.size())),
                          method);
      for (std::size_t i = 0; i < u.size(); ++i) slope_u[i][j] = evaluate_with_gradient(row, {u[i]}).gradient[0];
    }
    for (std::size_t i = 0; i < u.size(); ++i) {
      const GridTable column({GridAxis{"v", v}}, {"dX/du"}, slope_u[i], method);
      for (int trial = 0; trial < 20; ++trial) {
        const double q = std::uniform_real_distribution<double>(v.front(), v.back())(rng);
        EXPECT_NEAR(evaluate_with_gradient(table, {u[i], q}).gradient[0],
                    column.evaluate_one(std::vector<double>{q}, 0), 1e-12)
            << method_label(method) << " at u[" << i << "], v = " << q;
      }
    }
  }
}

// ------------------------------------------------------------- PCHIP monotone

// Samples f densely over every cell of a 1-D table and checks it never moves
// against the data's direction and stays within each cell's end values.
void expect_monotone_between_breakpoints(const std::function<double(double)>& f, const std::vector<double>& x,
                                         const std::vector<double>& y, const std::string& what) {
  double previous = f(x.front());
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    const double low = std::min(y[i], y[i + 1]);
    const double high = std::max(y[i], y[i + 1]);
    for (int j = 0; j <= 200; ++j) {
      const double q = x[i] + (x[i + 1] - x[i]) * j / 200.0;
      const double v = f(q);
      // A flat cell evaluates y (h00 + h01), which may differ from y in the last bit: allow 4 ulps.
      const double rounding = 4.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(v));
      ASSERT_GE(v, previous - rounding) << what << " at " << q;
      ASSERT_GE(v, low - rounding) << what << " overshoot below at " << q;
      ASSERT_LE(v, high + rounding) << what << " overshoot above at " << q;
      previous = v;
    }
  }
}

TEST(GridTable, PchipIsMonotoneOnMonotoneOneDimensionalData) {
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> rise(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<double> x = unevenly_spaced(0.0, 10.0, 12, rng);
    std::vector<double> y(x.size(), 0.0);
    for (std::size_t i = 1; i < y.size(); ++i) {
      // Increments from tiny to large, with flat runs.
      const double r = rise(rng);
      y[i] = y[i - 1] + (r < 0.25 ? 0.0 : std::pow(10.0, 4.0 * r - 2.0));
    }
    const GridTable table({GridAxis{"u", x}}, {"X"}, y, Interpolation::Pchip);
    expect_monotone_between_breakpoints([&](double q) { return table.evaluate_one(std::vector<double>{q}, 0); }, x, y,
                                        "trial " + std::to_string(trial));
  }
  // A step: no overshoot either side, flat parts stay exactly flat.
  const std::vector<double> x = {0, 1, 2, 3, 4, 5};
  const std::vector<double> y = {0, 0, 0, 1, 1, 1};
  const GridTable step({GridAxis{"u", x}}, {"X"}, y, Interpolation::Pchip);
  expect_monotone_between_breakpoints([&](double q) { return step.evaluate_one(std::vector<double>{q}, 0); }, x, y,
                                      "step");
  EXPECT_EQ(step.evaluate_one(std::vector<double>{1.5}, 0), 0.0);
  EXPECT_EQ(step.evaluate_one(std::vector<double>{3.5}, 0), 1.0);
}

TEST(GridTable, PchipIsMonotoneAlongEachAxisOfTwoDimensionalData) {
  // On the grid lines of the other axis the surface is the 1-D pchip of that
  // line, so any data monotone along an axis stays monotone there (checked on
  // random data increasing in u and decreasing in v). Between grid lines the
  // tensor product keeps monotonicity for separable data (sum or product of
  // positive monotone 1-D data: the surface is the sum or product of
  // monotone 1-D pchips), which is checked on a dense 2-D sample; for general
  // monotone 2-D data it is not guaranteed (nor by successive 1-D pchip).
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> step(0.0, 1.0);
  const std::vector<double> u = unevenly_spaced(0.0, 2.0, 8, rng);
  const std::vector<double> v = unevenly_spaced(-1.0, 1.0, 6, rng);
  std::vector<double> values(u.size() * v.size());
  for (std::size_t j = 0; j < v.size(); ++j) {
    for (std::size_t i = 0; i < u.size(); ++i) {
      const double left = i > 0 ? values[j * u.size() + i - 1] : 0.0;
      const double below = j > 0 ? values[(j - 1) * u.size() + i] : 0.0;
      // Increasing in u, decreasing in v (each step keeps both orders).
      values[j * u.size() + i] = (i > 0 ? left : below - 2.0) + step(rng) * step(rng);
      if (j > 0) values[j * u.size() + i] = std::min(values[j * u.size() + i], below - 0.01);
      if (i > 0 && j > 0) values[j * u.size() + i] = std::max(values[j * u.size() + i], left);
    }
  }
  // Sanity of the construction.
  for (std::size_t j = 0; j < v.size(); ++j) {
    for (std::size_t i = 0; i < u.size(); ++i) {
      if (i > 0) {
        ASSERT_GE(values[j * u.size() + i], values[j * u.size() + i - 1]);
      }
      if (j > 0) {
        ASSERT_LE(values[j * u.size() + i], values[(j - 1) * u.size() + i]);
      }
    }
  }
  const GridTable table(make_axes({u, v}), {"X"}, values, Interpolation::Pchip);
  for (std::size_t j = 0; j < v.size(); ++j) {
    std::vector<double> line(u.size());
    for (std::size_t i = 0; i < u.size(); ++i) line[i] = values[j * u.size() + i];
    expect_monotone_between_breakpoints(
        [&](double q) {
          return table.evaluate_one(std::vector<double>{q, v[j]}, 0);
        },
        u, line, "along u at v[" + std::to_string(j) + "]");
  }
  for (std::size_t i = 0; i < u.size(); ++i) {
    std::vector<double> line(v.size());
    for (std::size_t j = 0; j < v.size(); ++j) line[j] = -values[j * u.size() + i];
    expect_monotone_between_breakpoints(
        [&](double q) {
          return -table.evaluate_one(std::vector<double>{u[i], q}, 0);
        },
        v, line, "along v at u[" + std::to_string(i) + "]");
  }

  // Separable monotone data between grid lines: g increasing with a flat run and a jump, h increasing and positive.
  const std::vector<double> gx = {0.0, 0.0, 0.1, 0.2, 2.0, 2.1, 2.1, 5.0};
  const std::vector<double> hy = {1.0, 1.5, 1.6, 4.0, 4.1, 9.0};
  const GridTable separable = make_table(
      {u, v}, 2,
      [&](const Point& p) {
        const auto i = static_cast<std::size_t>(std::find(u.begin(), u.end(), p[0]) - u.begin());
        const auto j = static_cast<std::size_t>(std::find(v.begin(), v.end(), p[1]) - v.begin());
        return std::vector<double>{gx[i] + hy[j], (gx[i] + 0.5) * hy[j]};
      },
      Interpolation::Pchip);
  for (int a = 0; a <= 120; ++a) {
    for (int b = 0; b <= 120; ++b) {
      const Point p = {u.front() + (u.back() - u.front()) * a / 120.0, v.front() + (v.back() - v.front()) * b / 120.0};
      const ValueAndGradient got = evaluate_with_gradient(separable, p);
      for (std::size_t k = 0; k < 2; ++k) {
        ASSERT_GE(got.gradient[k * 2 + 0], -1e-12) << "output " << k << " at " << p[0] << ", " << p[1];
        ASSERT_GE(got.gradient[k * 2 + 1], -1e-12) << "output " << k << " at " << p[0] << ", " << p[1];
      }
    }
  }
}

// ---------------------------------------------------------------- gradients

TEST(GridTable, GradientMatchesCentralDifferences) {
  std::mt19937_64 rng(18);
  for (Interpolation method : kCubicMethods) {
    for (std::size_t n : {1U, 2U, 3U}) {
      std::vector<std::vector<double>> breakpoints;
      for (std::size_t a = 0; a < n; ++a) breakpoints.push_back(unevenly_spaced(-1.0, 2.0, 5 + a, rng));
      const GridTable table = make_table(
          breakpoints, 2,
          [](const Point& p) {
            double s = 0.0;
            double c = 1.0;
            for (std::size_t a = 0; a < p.size(); ++a) {
              s += std::sin(1.3 * p[a] + 0.2 * static_cast<double>(a));
              c *= std::cos(0.7 * p[a]);
            }
            return std::vector<double>{s * c, std::exp(0.4 * s)};
          },
          method);
      for (int trial = 0; trial < 200; ++trial) {
        const Point x = random_point(breakpoints, rng);
        const ValueAndGradient got = evaluate_with_gradient(table, x);
        EXPECT_EQ(got.value, evaluate(table, x));
        for (std::size_t a = 0; a < n; ++a) {
          const double step = 1e-6;
          Point plus = x;
          Point minus = x;
          plus[a] = std::min(x[a] + step, breakpoints[a].back());
          minus[a] = std::max(x[a] - step, breakpoints[a].front());
          const std::vector<double> fp = evaluate(table, plus);
          const std::vector<double> fm = evaluate(table, minus);
          for (std::size_t k = 0; k < 2; ++k) {
            const double difference = (fp[k] - fm[k]) / (plus[a] - minus[a]);
            EXPECT_NEAR(got.gradient[k * n + a], difference, 2e-6 * (1.0 + std::abs(difference)))
                << method_label(method) << " " << n << "-D axis " << a;
          }
        }
      }
    }
  }
}

TEST(GridTable, LinearGradientIsTheSlopeOfTheCellAQueryIsIn) {
  // At a breakpoint the upper cell's slope (the lower's at the last one), just
  // below it the lower cell's: checks that locating a point by direct index on
  // an evenly spaced axis lands in the same cell as a search would, even where
  // rounding in (x - x0) / step puts the index one off.
  std::vector<std::vector<double>> grids = {evenly_spaced(0.0, 0.38, 20), evenly_spaced(-1.0, 2.3, 34),
                                            evenly_spaced(0.1, 0.7, 7)};
  std::vector<double> decimal;  // as a CSV would give them: 0, 0.02, 0.04, ... parsed, not computed
  for (int i = 0; i <= 19; ++i)
    decimal.push_back(std::stod("0." + std::string(i < 5 ? "0" : "") + std::to_string(2 * i)));
  grids.push_back(decimal);
  for (const std::vector<double>& x : grids) {
    std::vector<double> y(x.size());
    for (std::size_t i = 0; i < y.size(); ++i)
      y[i] = static_cast<double>(i * i % 7);  // slopes change at every breakpoint
    const GridTable table({GridAxis{"u", x}}, {"X"}, y, Interpolation::Linear);
    ASSERT_TRUE(table.evenly_spaced(0));
    auto slope = [&](std::size_t cell) { return (y[cell + 1] - y[cell]) / (x[cell + 1] - x[cell]); };
    for (std::size_t i = 0; i < x.size(); ++i) {
      const ValueAndGradient at = evaluate_with_gradient(table, {x[i]});
      EXPECT_EQ(at.value[0], y[i]);
      EXPECT_DOUBLE_EQ(at.gradient[0], slope(std::min(i, x.size() - 2))) << "at breakpoint " << i << " = " << x[i];
      if (i > 0) {
        const double below = std::nextafter(x[i], -1e9);
        EXPECT_DOUBLE_EQ(evaluate_with_gradient(table, {below}).gradient[0], slope(i - 1))
            << "just below breakpoint " << i << " = " << x[i];
      }
    }
  }
}

TEST(GridTable, NearestPicksTheNearestBreakpointAndHasZeroGradient) {
  const std::vector<double> u = {0.0, 1.0, 3.0};
  const std::vector<double> v = {-1.0, 1.0};
  // value = 10 i + j for node (i, j)
  const GridTable table(make_axes({u, v}, Extrapolation::Linear), {"X"}, {0, 10, 20, 1, 11, 21},
                        Interpolation::Nearest);
  const std::vector<std::pair<Point, double>> cases = {
      {{0.2, -0.9}, 0}, {{0.6, -0.9}, 10}, {{0.5, 0.0}, 11},  // ties go to the upper breakpoint
      {{1.9, 0.5}, 11}, {{2.1, 0.5}, 21},  {{3.0, 1.0}, 21}, {{-5.0, 7.0}, 1}, {{9.0, -7.0}, 20}};
  for (const auto& [p, expected] : cases) {
    const ValueAndGradient got = evaluate_with_gradient(table, p);
    EXPECT_EQ(got.value[0], expected) << p[0] << ", " << p[1];
    EXPECT_EQ(got.gradient, (std::vector<double>{0.0, 0.0}));
  }
}

// ------------------------------------------------------------- extrapolation

TEST(GridTable, ErrorPolicyNamesAxisValueAndRange) {
  const std::vector<double> u = evenly_spaced(0.0, 0.38, 20);
  const std::vector<double> r = {-0.5, 0.0, 0.5};
  for (Interpolation method : kAllMethods) {
    const GridTable table = make_table(
        {u, r}, 1, [](const Point& p) { return std::vector<double>{p[0] + p[1]}; }, method);
    try {
      (void)table.evaluate_one(std::vector<double>{0.45, 0.0}, 0);
      ADD_FAILURE() << "expected an InputError";
    } catch (const InputError& error) {
      EXPECT_EQ(std::string(error.what()),
                "axis 'u' = 0.45 is outside [0, 0.38]; expected a value in range (or an extrapolation policy)");
    }
    try {
      std::vector<double> out(1);
      std::vector<double> gradient(2);
      table.evaluate_with_gradient(std::vector<double>{0.1, -0.75}, out, gradient);
      ADD_FAILURE() << "expected an InputError";
    } catch (const InputError& error) {
      EXPECT_EQ(std::string(error.what()),
                "axis 'v' = -0.75 is outside [-0.5, 0.5]; expected a value in range (or an extrapolation policy)");
    }
    // The ends themselves are in range.
    EXPECT_NO_THROW((void)table.evaluate_one(std::vector<double>{0.38, -0.5}, 0));
    EXPECT_NO_THROW((void)table.evaluate_one(std::vector<double>{0.0, 0.5}, 0));
  }
}

TEST(GridTable, PoliciesApplyPerAxis) {
  std::vector<GridAxis> axes = make_axes({{0.0, 1.0, 2.0}, {0.0, 1.0, 2.0}});
  axes[0].extrapolation = Extrapolation::Clamp;  // u clamps, v refuses
  const GridTable table(axes, {"X"},
                        tabulate({{0.0, 1.0, 2.0}, {0.0, 1.0, 2.0}}, 1,
                                 [](const Point& p) { return std::vector<double>{p[0] + 2.0 * p[1]}; }),
                        Interpolation::Linear);
  EXPECT_DOUBLE_EQ(table.evaluate_one(std::vector<double>{5.0, 1.5}, 0), 5.0);
  EXPECT_DOUBLE_EQ(table.evaluate_one(std::vector<double>{-5.0, 1.5}, 0), 3.0);
  EXPECT_THROW((void)table.evaluate_one(std::vector<double>{0.5, 2.5}, 0), InputError);
}

TEST(GridTable, ClampHoldsTheEndValueWithZeroGradientAlongThatAxis) {
  std::mt19937_64 rng(19);
  const std::vector<double> u = unevenly_spaced(0.0, 1.0, 6, rng);
  const std::vector<double> v = evenly_spaced(-1.0, 1.0, 5);
  auto f = [](const Point& p) { return std::vector<double>{std::sin(3.0 * p[0]) * std::exp(p[1])}; };
  for (Interpolation method : kAllMethods) {
    const GridTable table = make_table({u, v}, 1, f, method, Extrapolation::Clamp);
    for (double y : {-0.93, 0.1, 0.77}) {
      for (double x : {-0.4, 1.3}) {
        const double end = x < 0.0 ? 0.0 : 1.0;
        const ValueAndGradient outside = evaluate_with_gradient(table, {x, y});
        const ValueAndGradient at_end = evaluate_with_gradient(table, {end, y});
        EXPECT_EQ(outside.value[0], at_end.value[0]) << method_label(method);
        EXPECT_EQ(outside.gradient[0], 0.0) << method_label(method);
        EXPECT_EQ(outside.gradient[1], at_end.gradient[1]) << method_label(method);
      }
    }
    // Both axes outside: the corner value.
    EXPECT_EQ(table.evaluate_one(std::vector<double>{2.0, -3.0}, 0), f({1.0, -1.0})[0]) << method_label(method);
  }
}

TEST(GridTable, LinearAndMethodPoliciesContinueMultilinearFunctionsExactlyOnEverySide) {
  // Every method except Nearest reproduces a multilinear function, whose end
  // slopes and end polynomials are its own: both policies continue it
  // exactly, on either side of each axis and with several axes outside at once.
  std::mt19937_64 rng(20);
  const std::vector<std::vector<double>> breakpoints = {unevenly_spaced(0.0, 1.0, 5, rng), evenly_spaced(-2.0, 2.0, 4)};
  const Multilinear f(2, 1, rng);
  const std::vector<Point> points = {{-0.7, 0.3},  {1.6, 0.3}, {0.4, -3.5}, {0.4, 2.9},
                                     {-0.2, -2.5}, {1.2, 3.0}, {-0.3, 2.2}, {1.9, -4.0}};
  for (Interpolation method :
       {Interpolation::Linear, Interpolation::Pchip, Interpolation::Akima, Interpolation::NaturalSpline}) {
    for (Extrapolation policy : {Extrapolation::Linear, Extrapolation::Method}) {
      const GridTable table = make_table(breakpoints, 1, f, method, policy);
      for (const Point& p : points) {
        const ValueAndGradient got = evaluate_with_gradient(table, p);
        // Far outside, values reach ~20: the bounds are relative.
        const double value = f(p)[0];
        const double du = f.derivative(p, 0, 0);
        const double dv = f.derivative(p, 0, 1);
        EXPECT_NEAR(got.value[0], value, 1e-12 * (1.0 + std::abs(value)))
            << method_label(method) << " " << p[0] << ", " << p[1];
        EXPECT_NEAR(got.gradient[0], du, 1e-11 * (1.0 + std::abs(du))) << method_label(method);
        EXPECT_NEAR(got.gradient[1], dv, 1e-11 * (1.0 + std::abs(dv))) << method_label(method);
      }
    }
  }
}

TEST(GridTable, LinearPolicyOnCurvedSurfacesUsesTheEndValueAndSlopeAlongTheOutsideAxis) {
  // For a curved surface, u beyond its range: f(u, v) = f(b, v) + (u - b) df/du(b, v)
  // for every v; the 1-D reference test checks the end slopes themselves.
  std::mt19937_64 rng(21);
  const std::vector<double> u = unevenly_spaced(0.0, 1.0, 6, rng);
  const std::vector<double> v = unevenly_spaced(-1.0, 1.0, 5, rng);
  auto f = [](const Point& p) { return std::vector<double>{std::sin(3.0 * p[0]) * std::exp(p[1]) + p[1] * p[1]}; };
  for (Interpolation method : kCubicMethods) {
    const GridTable table = make_table({u, v}, 1, f, method, Extrapolation::Linear);
    const GridTable method_policy = make_table({u, v}, 1, f, method, Extrapolation::Method);
    for (double y : {-0.93, 0.1, 0.77}) {
      for (double x : {-0.4, 1.3}) {
        const double end = x < 0.0 ? 0.0 : 1.0;
        const ValueAndGradient at_end = evaluate_with_gradient(table, {end, y});
        const ValueAndGradient outside = evaluate_with_gradient(table, {x, y});
        EXPECT_NEAR(outside.value[0], at_end.value[0] + (x - end) * at_end.gradient[0], 1e-13) << method_label(method);
        EXPECT_NEAR(outside.gradient[0], at_end.gradient[0], 1e-13) << method_label(method);
        const double along_v = (evaluate(table, {x, y + 1e-6})[0] - evaluate(table, {x, y - 1e-6})[0]) / 2e-6;
        EXPECT_NEAR(outside.gradient[1], along_v, 1e-6) << method_label(method);
        // The end cubic continued bends away from the tangent (these data are curved).
        EXPECT_GT(std::abs(evaluate(method_policy, {x, y})[0] - outside.value[0]), 1e-4) << method_label(method);
      }
    }
  }
}

TEST(GridTable, NonFiniteQueriesAndWrongSizesThrow) {
  const GridTable table = make_table(
      {{0.0, 1.0, 2.0}, {0.0, 1.0}}, 2,
      [](const Point& p) {
        return std::vector<double>{p[0], p[1]};
      },
      Interpolation::Linear, Extrapolation::Clamp);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> out(2);
  try {
    table.evaluate(std::vector<double>{0.5, nan}, out);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), "axis 'v' = nan is not a number; expected a finite value");
  }
  EXPECT_THROW(table.evaluate(std::vector<double>{-inf, 0.5}, out), InputError);
  EXPECT_THROW((void)table.evaluate_one(std::vector<double>{nan, 0.5}, 1), InputError);
  try {
    table.evaluate(std::vector<double>{0.5}, out);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), "a query point has 1 coordinates; expected 2 (one per axis)");
  }
  std::vector<double> short_out(1);
  EXPECT_THROW(table.evaluate(std::vector<double>{0.5, 0.5}, short_out), std::invalid_argument);
  std::vector<double> gradient(3);
  EXPECT_THROW(table.evaluate_with_gradient(std::vector<double>{0.5, 0.5}, out, gradient), std::invalid_argument);
  EXPECT_THROW((void)table.evaluate_one(std::vector<double>{0.5, 0.5}, 2), std::out_of_range);
  EXPECT_EQ(table.output_index("Y"), 1U);
  EXPECT_THROW((void)table.output_index("N"), InputError);
}

// ------------------------------------------------------------- construction

void expect_construction_error(std::vector<GridAxis> axes, std::vector<std::string> outputs, std::vector<double> values,
                               Interpolation method, const std::string& expected) {
  try {
    const GridTable table(std::move(axes), std::move(outputs), std::move(values), method);
    ADD_FAILURE() << "expected an InputError: " << expected;
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), expected);
  }
}

TEST(GridTable, ConstructionValidatesItsInput) {
  const std::vector<double> three = {0.0, 1.0, 2.0};
  expect_construction_error({}, {"X"}, {}, Interpolation::Linear, "a grid table has 0 axes; expected 1 to 6");
  {
    std::vector<GridAxis> seven = make_axes(std::vector<std::vector<double>>(6, three));
    seven.push_back({"s", three});
    expect_construction_error(seven, {"X"}, std::vector<double>(2187, 0.0), Interpolation::Linear,
                              "a grid table has 7 axes; expected 1 to 6");
  }
  expect_construction_error({GridAxis{"", three}}, {"X"}, {0, 0, 0}, Interpolation::Linear,
                            "axis 0 has an empty name; expected a name");
  expect_construction_error({GridAxis{"u", three}, GridAxis{"u", three}}, {"X"}, std::vector<double>(9),
                            Interpolation::Linear, "axis name 'u' is used by axes 0 and 1; expected unique axis names");
  expect_construction_error({GridAxis{"u", {1.0}}}, {"X"}, {0}, Interpolation::Linear,
                            "axis 'u' has 1 breakpoints; expected at least 2 for linear interpolation");
  expect_construction_error({GridAxis{"u", {0.0, 1.0}}}, {"X"}, {0, 1}, Interpolation::Pchip,
                            "axis 'u' has 2 breakpoints; expected at least 3 for pchip interpolation "
                            "(cubic methods need 3)");
  expect_construction_error({GridAxis{"u", {0.0, 1.0}}}, {"X"}, {0, 1}, Interpolation::Akima,
                            "axis 'u' has 2 breakpoints; expected at least 3 for makima interpolation "
                            "(cubic methods need 3)");
  expect_construction_error({GridAxis{"v", {0.0, 0.5, 0.5, 1.0}}}, {"X"}, {0, 1, 2, 3}, Interpolation::Linear,
                            "axis 'v' breakpoint 2 (0.5) is not greater than breakpoint 1 (0.5); expected strictly "
                            "increasing breakpoints");
  expect_construction_error({GridAxis{"v", {0.0, 2.0, 1.0}}}, {"X"}, {0, 1, 2}, Interpolation::Nearest,
                            "axis 'v' breakpoint 2 (1) is not greater than breakpoint 1 (2); expected strictly "
                            "increasing breakpoints");
  expect_construction_error({GridAxis{"v", {0.0, std::numeric_limits<double>::quiet_NaN(), 1.0}}}, {"X"}, {0, 1, 2},
                            Interpolation::Linear, "axis 'v' breakpoint 1 is nan; expected a finite number");
  expect_construction_error({GridAxis{"u", three}}, {}, {}, Interpolation::Linear,
                            "a grid table has no outputs; expected at least one output name");
  expect_construction_error({GridAxis{"u", three}}, {"X", ""}, std::vector<double>(6), Interpolation::Linear,
                            "output 1 has an empty name; expected a name");
  expect_construction_error({GridAxis{"u", three}}, {"X", "X"}, std::vector<double>(6), Interpolation::Linear,
                            "output name 'X' is used by outputs 0 and 1; expected unique output names");
  expect_construction_error({GridAxis{"u", three}, GridAxis{"v", {0.0, 1.0}}}, {"X", "Y"}, std::vector<double>(11),
                            Interpolation::Linear, "a grid table has 11 values; expected 12 (3 x 2 nodes x 2 outputs)");
}

TEST(GridTable, ConstructionRejectsNonFiniteValuesNamingOutputAndNode) {
  const std::vector<double> three = {0.0, 1.0, 2.0};
  std::vector<double> values(18, 1.0);
  values[9] = std::numeric_limits<double>::infinity();  // node 4 = (u[1], v[1]), output 1 "Y"
  expect_construction_error(
      {GridAxis{"u", three}, GridAxis{"v", three}}, {"X", "Y"}, values, Interpolation::NaturalSpline,
      "value of output 'Y' at node (u[1], v[1]) (values index 9) is inf; expected a finite number");
  values[9] = 1.0;
  values[16] = std::numeric_limits<double>::quiet_NaN();  // node 8 = (u[2], v[2]), output 0 "X"
  expect_construction_error({GridAxis{"u", three}, GridAxis{"v", three}}, {"X", "Y"}, values, Interpolation::Linear,
                            "value of output 'X' at node (u[2], v[2]) (values index 16) is nan; expected a finite "
                            "number");
}

TEST(GridTable, NamesRoundTrip) {
  for (Interpolation method : kAllMethods) EXPECT_EQ(parse_interpolation(interpolation_name(method)), method);
  for (Extrapolation policy :
       {Extrapolation::Error, Extrapolation::Clamp, Extrapolation::Linear, Extrapolation::Method}) {
    EXPECT_EQ(parse_extrapolation(extrapolation_name(policy)), policy);
  }
  EXPECT_THROW((void)parse_interpolation("cubic"), InputError);
  EXPECT_THROW((void)parse_extrapolation("wrap"), InputError);
}

// ------------------------------------------------------------ outputs, threads

TEST(GridTable, ManyOutputsAtOnceEqualSingleOutputTables) {
  std::mt19937_64 rng(22);
  const std::vector<std::vector<double>> breakpoints = {unevenly_spaced(0.0, 1.0, 6, rng), evenly_spaced(-1.0, 1.0, 5),
                                                        unevenly_spaced(2.0, 3.0, 4, rng)};
  std::uniform_real_distribution<double> value(-3.0, 3.0);
  for (std::size_t n_out : {6U, 11U}) {
    std::vector<std::vector<double>> per_output(n_out);
    std::vector<double> all(6 * 5 * 4 * n_out);
    for (std::size_t i = 0; i < all.size(); ++i) {
      all[i] = value(rng);
      per_output[i % n_out].push_back(all[i]);
    }
    for (Interpolation method : kAllMethods) {
      const GridTable combined(make_axes(breakpoints, Extrapolation::Method), output_names(n_out), all, method);
      std::vector<GridTable> singles;
      for (std::size_t k = 0; k < n_out; ++k) {
        singles.emplace_back(make_axes(breakpoints, Extrapolation::Method), std::vector<std::string>{"C"},
                             per_output[k], method);
      }
      for (int trial = 0; trial < 100; ++trial) {
        Point p = random_point(breakpoints, rng);
        if (trial % 10 == 0) p[1] = 1.4;  // also beyond the grid
        const ValueAndGradient got = evaluate_with_gradient(combined, p);
        for (std::size_t k = 0; k < n_out; ++k) {
          const ValueAndGradient single = evaluate_with_gradient(singles[k], p);
          ASSERT_DOUBLE_EQ(got.value[k], single.value[0]) << method_label(method) << " output " << k;
          ASSERT_DOUBLE_EQ(combined.evaluate_one(p, k), single.value[0]) << method_label(method);
          for (std::size_t a = 0; a < 3; ++a) {
            ASSERT_DOUBLE_EQ(got.gradient[k * 3 + a], single.gradient[a]) << method_label(method) << " axis " << a;
          }
        }
      }
    }
  }
}

TEST(GridTable, EvaluationAllocatesNothing) {
  std::mt19937_64 rng(26);
  const std::vector<std::vector<double>> breakpoints = {unevenly_spaced(0.0, 1.0, 6, rng), evenly_spaced(-1.0, 1.0, 5),
                                                        unevenly_spaced(2.0, 3.0, 4, rng)};
  std::vector<Point> points;
  for (int i = 0; i < 200; ++i) points.push_back(random_point(breakpoints, rng));
  points.push_back({1.5, -1.2, 2.5});  // beyond the grid on two axes
  for (Interpolation method : kAllMethods) {
    std::vector<GridAxis> axes = make_axes(breakpoints, Extrapolation::Linear);
    axes[1].extrapolation = Extrapolation::Clamp;
    const GridTable table(axes, output_names(6), std::vector<double>(6 * 5 * 4 * 6, 0.5), method);
    std::vector<double> out(6);
    std::vector<double> gradient(18);
    double sum = 0.0;
    const std::size_t before = test::allocation_count();
    for (const Point& p : points) {
      table.evaluate(p, out);
      table.evaluate_with_gradient(p, out, gradient);
      sum += table.evaluate_one(p, 3) + out[0] + gradient[17];
    }
    EXPECT_EQ(test::allocation_count() - before, 0u) << method_label(method);
    EXPECT_TRUE(std::isfinite(sum));
  }
}

TEST(GridTable, ConcurrentEvaluationMatchesSerial) {
  std::mt19937_64 rng(23);
  const std::vector<std::vector<double>> breakpoints = {unevenly_spaced(0.0, 1.0, 8, rng), evenly_spaced(-1.0, 1.0, 7),
                                                        unevenly_spaced(2.0, 3.0, 5, rng)};
  const Multilinear seed(3, 6, rng);
  const GridTable table = make_table(
      breakpoints, 6,
      [&](const Point& p) {
        std::vector<double> f = seed(p);
        for (double& v : f) v = std::sin(v);
        return f;
      },
      Interpolation::Pchip);
  std::vector<Point> points;
  for (int i = 0; i < 4000; ++i) points.push_back(random_point(breakpoints, rng));
  std::vector<double> serial(points.size() * 24);
  for (std::size_t i = 0; i < points.size(); ++i) {
    table.evaluate_with_gradient(points[i], std::span<double>(serial).subspan(i * 24, 6),
                                 std::span<double>(serial).subspan(i * 24 + 6, 18));
  }
  std::vector<double> first(serial.size());
  std::vector<double> second(serial.size());
  auto work = [&](std::vector<double>& result, bool reverse) {
    for (int repeat = 0; repeat < 5; ++repeat) {
      for (std::size_t j = 0; j < points.size(); ++j) {
        const std::size_t i = reverse ? points.size() - 1 - j : j;
        table.evaluate_with_gradient(points[i], std::span<double>(result).subspan(i * 24, 6),
                                     std::span<double>(result).subspan(i * 24 + 6, 18));
      }
    }
  };
  std::thread a(work, std::ref(first), false);
  std::thread b(work, std::ref(second), true);
  a.join();
  b.join();
  EXPECT_EQ(first, serial);
  EXPECT_EQ(second, serial);
}

TEST(GridTable, EvenSpacingIsDetected) {
  std::mt19937_64 rng(24);
  const GridTable table({GridAxis{"u", evenly_spaced(0.0, 0.38, 20)}, GridAxis{"v", unevenly_spaced(0.0, 1.0, 5, rng)},
                         GridAxis{"r", {-0.3, -0.1, 0.1, 0.3}}},
                        {"X"}, std::vector<double>(400, 1.0), Interpolation::Linear);
  EXPECT_TRUE(table.evenly_spaced(0));
  EXPECT_FALSE(table.evenly_spaced(1));
  EXPECT_TRUE(table.evenly_spaced(2));
}

// body(x, method, policy) for a one-axis table's breakpoints x on [-1, 2],
// evenly and unevenly spaced, with every method and extrapolation policy.
template <class Body>
void for_each_one_axis_case(std::mt19937_64& rng, Body&& body) {
  for (const bool even : {true, false}) {
    const std::vector<double> x = even ? evenly_spaced(-1.0, 2.0, 13) : unevenly_spaced(-1.0, 2.0, 13, rng);
    for (Interpolation method : kAllMethods) {
      for (Extrapolation policy :
           {Extrapolation::Error, Extrapolation::Clamp, Extrapolation::Linear, Extrapolation::Method}) {
        SCOPED_TRACE(method_label(method) + (even ? " even" : " uneven"));
        body(x, method, policy);
      }
    }
  }
}

// The dynamics' one-axis path gives evaluate()'s numbers bit for bit: every
// method, even and uneven breakpoints, several outputs, inside, on
// breakpoints and beyond the ends under every policy; a NaN or a point
// outside an `error` axis throws as evaluate does, and so does a table of two axes.
TEST(GridTable, OneAxisPathGivesEvaluatesNumbers) {
  std::mt19937_64 rng(11);
  const auto f = [](const Point& p) {
    return std::vector<double>{std::sin(3.0 * p[0]) - 0.2 * p[0], p[0] * std::abs(p[0]), -0.0 * p[0], 2.0};
  };
  for_each_one_axis_case(rng, [&](const std::vector<double>& x, Interpolation method, Extrapolation policy) {
    const GridTable table = make_table({x}, 4, f, method, policy);
    std::vector<double> points = x;  // every breakpoint, then random points inside and beyond
    for (int i = 0; i < 200; ++i) points.push_back(std::uniform_real_distribution<double>(-1.5, 2.5)(rng));
    for (const double p : points) {
      std::array<double, 4> fast{};
      if (policy == Extrapolation::Error && (p < x.front() || p > x.back())) {
        EXPECT_THROW(table.evaluate_one_axis(p, fast.data()), InputError);
        continue;
      }
      table.evaluate_one_axis(p, fast.data());
      const std::vector<double> general = evaluate(table, {p});
      for (std::size_t k = 0; k < 4; ++k) {
        EXPECT_EQ(std::bit_cast<std::uint64_t>(fast[k]), std::bit_cast<std::uint64_t>(general[k]))
            << "x = " << p << ", output " << k << ": " << fast[k] << " vs " << general[k];
      }
    }
    std::array<double, 4> out{};
    EXPECT_THROW(table.evaluate_one_axis(std::numeric_limits<double>::quiet_NaN(), out.data()), InputError);
  });
  const GridTable two_axes = make_table(
      {{0.0, 1.0}, {0.0, 1.0}}, 1, [](const Point& p) { return std::vector<double>{p[0] + p[1]}; },
      Interpolation::Linear);
  double out = 0.0;
  EXPECT_THROW(two_axes.evaluate_one_axis(0.5, &out), InputError);
}

// evaluate_unchecked (the dynamics model's path, a kernel compiled for each
// axis count and method) gives evaluate()'s numbers bit for bit for every
// axis count, method and policy, at the breakpoints, inside and beyond the
// axes, and throws where evaluate throws.
TEST(GridTable, UncheckedPathGivesEvaluatesNumbersForEveryAxisCount) {
  std::mt19937_64 rng(23);
  for (std::size_t n = 1; n <= kMaxGridAxes; ++n) {
    std::vector<std::vector<double>> breakpoints;
    for (std::size_t a = 0; a < n; ++a)
      breakpoints.push_back(a % 2 == 0 ? evenly_spaced(-1.0, 2.0, n <= 3 ? 6 : 3)
                                       : unevenly_spaced(-1.0, 2.0, n <= 3 ? 6 : 3, rng));
    const auto f = [](const Point& p) {
      double product = 1.0, sum = 0.0;
      for (const double x : p) {
        product *= 1.0 + 0.3 * x;
        sum += std::sin(2.0 * x);
      }
      return std::vector<double>{product, sum, -0.0 * sum};
    };
    for (Interpolation method : kAllMethods) {
      for (Extrapolation policy :
           {Extrapolation::Error, Extrapolation::Clamp, Extrapolation::Linear, Extrapolation::Method}) {
        SCOPED_TRACE(std::to_string(n) + " axes, " + method_label(method));
        const GridTable table = make_table(breakpoints, 3, f, method, policy);
        for (int i = 0; i < 100; ++i) {
          Point p(n);
          bool outside = false;
          for (std::size_t a = 0; a < n; ++a) {
            // A breakpoint now and then, otherwise a random point in or beyond the axis.
            p[a] = i % 5 == 0 ? breakpoints[a][static_cast<std::size_t>(i) % breakpoints[a].size()]
                              : std::uniform_real_distribution<double>(-1.5, 2.5)(rng);
            outside = outside || p[a] < -1.0 || p[a] > 2.0;
          }
          std::array<double, 3> fast{};
          if (policy == Extrapolation::Error && outside) {
            EXPECT_THROW(table.evaluate_unchecked(p.data(), fast.data()), InputError);
            continue;
          }
          table.evaluate_unchecked(p.data(), fast.data());
          const std::vector<double> general = evaluate(table, p);
          for (std::size_t k = 0; k < 3; ++k)
            EXPECT_EQ(std::bit_cast<std::uint64_t>(fast[k]), std::bit_cast<std::uint64_t>(general[k]))
                << "point " << i << ", output " << k << ": " << fast[k] << " vs " << general[k];
        }
        Point nan(n, 0.5);
        nan[n - 1] = std::numeric_limits<double>::quiet_NaN();
        std::array<double, 3> out{};
        EXPECT_THROW(table.evaluate_unchecked(nan.data(), out.data()), InputError);
      }
    }
  }
}

// Tables on one axis with other numbers (the draws of one surface) looked up
// together: every lane's numbers are its own table's evaluate(), bit for bit,
// inside the axis, beyond it under every policy, at the breakpoints.
TEST(GridTable, LanesOnASharedAxisGiveEachTablesOwnNumbers) {
  constexpr std::size_t kN = 8;
  std::mt19937_64 rng(12);
  for_each_one_axis_case(rng, [&](const std::vector<double>& x, Interpolation method, Extrapolation policy) {
    std::vector<GridTable> tables;
    for (std::size_t l = 0; l < kN; ++l) {
      const double scale = 1.0 + 0.1 * static_cast<double>(l);
      tables.push_back(make_table(
          {x}, 2,
          [&](const Point& p) {
            return std::vector<double>{scale * std::sin(3.0 * p[0]), p[0] * std::abs(p[0]) - scale};
          },
          method, policy));
    }
    std::array<const GridTable*, kN> lanes;
    for (std::size_t l = 0; l < kN; ++l) {
      lanes[l] = &tables[l];
      EXPECT_TRUE(tables[0].shares_axis(tables[l]));
    }
    for (int round = 0; round < 60; ++round) {
      // Inside only, then some lanes beyond either end.
      const double spread = round < 30 ? 0.0 : 0.6;
      std::array<double, kN> values;
      for (double& v : values) v = std::uniform_real_distribution<double>(-1.0 - spread, 2.0 + spread)(rng);
      if (round % 10 == 0)
        for (std::size_t l = 0; l < kN; ++l) values[l] = x[(static_cast<std::size_t>(round) + l) % x.size()];
      const bool outside = std::any_of(values.begin(), values.end(), [&](double v) { return v < -1.0 || v > 2.0; });
      std::array<double, 2 * kN> out{};
      if (policy == Extrapolation::Error && outside) {
        EXPECT_THROW(GridTable::evaluate_one_axis_lanes<kN>(lanes, values.data(), out.data()), InputError);
        continue;
      }
      GridTable::evaluate_one_axis_lanes<kN>(lanes, values.data(), out.data());
      for (std::size_t l = 0; l < kN; ++l) {
        const std::vector<double> own = evaluate(tables[l], {values[l]});
        for (std::size_t k = 0; k < 2; ++k)
          EXPECT_EQ(std::bit_cast<std::uint64_t>(out[k * kN + l]), std::bit_cast<std::uint64_t>(own[k]))
              << "lane " << l << " at " << values[l] << ", output " << k;
      }
    }
    std::array<double, kN> values;
    values.fill(0.5);
    values[3] = std::numeric_limits<double>::quiet_NaN();
    std::array<double, 2 * kN> out{};
    EXPECT_THROW(GridTable::evaluate_one_axis_lanes<kN>(lanes, values.data(), out.data()), InputError);
  });
  // Another axis, method, policy or output count is not shared.
  const auto g = [](const Point& p) { return std::vector<double>{p[0]}; };
  const GridTable base = make_table({{0.0, 1.0, 2.0}}, 1, g, Interpolation::Linear, Extrapolation::Clamp);
  EXPECT_FALSE(base.shares_axis(make_table({{0.0, 1.0, 2.5}}, 1, g, Interpolation::Linear, Extrapolation::Clamp)));
  EXPECT_FALSE(base.shares_axis(make_table({{0.0, 1.0, 2.0}}, 1, g, Interpolation::Pchip, Extrapolation::Clamp)));
  EXPECT_FALSE(base.shares_axis(make_table({{0.0, 1.0, 2.0}}, 1, g, Interpolation::Linear, Extrapolation::Linear)));
  EXPECT_FALSE(base.shares_axis(make_table(
      {{0.0, 1.0, 2.0}}, 2,
      [](const Point& p) {
        return std::vector<double>{p[0], 1.0};
      },
      Interpolation::Linear, Extrapolation::Clamp)));
  EXPECT_TRUE(base.shares_axis(make_table(
      {{0.0, 1.0, 2.0}}, 1, [](const Point& p) { return std::vector<double>{-p[0]}; }, Interpolation::Linear,
      Extrapolation::Clamp)));
}

}  // namespace
}  // namespace hydrocoef
