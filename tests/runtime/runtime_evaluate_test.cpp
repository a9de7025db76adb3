// libhydrocoef_runtime evaluates what the C++ library evaluates, bit for
// bit: tables of every method and extrapolation policy, 1 to 4 axes, even
// and uneven breakpoints, written by runtime_file_bytes and opened through
// the C API, at 10^4 random points each inside and beyond the axes: values,
// gradients and standard deviations compare equal as bit patterns, and a
// point GridTable refuses the runtime refuses with the matching code.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "hydrocoef/runtime.h"
#include "src/core/error.hpp"
#include "src/export/runtime_export.hpp"
#include "src/surface/coefficient_surface.hpp"
#include "src/surface/grid_table.hpp"
#include "tests/support/same_bits.hpp"

namespace hydrocoef {
namespace {

using test::same_bits;

struct ModelCloser {
  void operator()(hc_runtime_model* model) const { hc_runtime_close(model); }
};
using Model = std::unique_ptr<hc_runtime_model, ModelCloser>;

Model open_bytes(const std::string& bytes) {
  hc_runtime_model* model = nullptr;
  char err[512] = "";
  const int status = hc_runtime_open_memory(bytes.data(), bytes.size(), &model, err, sizeof err);
  EXPECT_EQ(status, HC_RUNTIME_OK) << err;
  return Model(model);
}

constexpr std::array<Interpolation, 5> kMethods = {Interpolation::Nearest, Interpolation::Linear, Interpolation::Pchip,
                                                   Interpolation::Akima, Interpolation::NaturalSpline};
constexpr std::array<Extrapolation, 4> kPolicies = {Extrapolation::Error, Extrapolation::Clamp, Extrapolation::Linear,
                                                    Extrapolation::Method};

// Breakpoints of axis a: even on axes 0 and 2, uneven on 1 and 3.
std::vector<double> breakpoints(std::size_t a, std::size_t axes) {
  const std::size_t count = axes <= 2 ? 7 : (axes == 3 ? 5 : 4);
  std::vector<double> x(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double t = static_cast<double>(i);
    x[i] = a % 2 == 0 ? -1.0 + 0.35 * t : -0.8 + 0.3 * t + 0.07 * t * t - (i == 1 ? 0.05 : 0.0);
  }
  return x;
}

struct Case {
  GridTable table;
  CoefficientSurface surface;
};

// A table of two outputs (three for 1-D) over `axes` axes, values with
// structure (monotone pieces, a kink, sign changes) and a runs' sigma.
Case make_case(Interpolation method, const std::vector<Extrapolation>& policies, std::mt19937_64& random) {
  const std::size_t n = policies.size();
  std::vector<GridAxis> axes;
  std::size_t nodes = 1;
  for (std::size_t a = 0; a < n; ++a) {
    axes.push_back({std::string(1, "uvwpqr"[a]), breakpoints(a, n), policies[a]});
    nodes *= axes.back().breakpoints.size();
  }
  const std::vector<std::string> outputs =
      n == 1 ? std::vector<std::string>{"X", "Y", "N"} : std::vector<std::string>{"X", "N"};
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  std::vector<double> values, sigma;
  for (std::size_t node = 0; node < nodes; ++node) {
    std::size_t rest = node;
    double smooth = 0.0;
    for (std::size_t a = 0; a < n; ++a) {
      const double x = axes[a].breakpoints[rest % axes[a].breakpoints.size()];
      rest /= axes[a].breakpoints.size();
      smooth += (static_cast<double>(a) + 1.0) * x * std::abs(x) - 0.3 * x;
    }
    for (std::size_t k = 0; k < outputs.size(); ++k) {
      values.push_back(static_cast<double>(k + 1) * 120.0 * smooth + 15.0 * noise(random));
      sigma.push_back(2.0 + std::abs(noise(random)));
    }
  }
  GridTable table(axes, outputs, values, method);
  std::vector<double> loo(outputs.size());
  for (std::size_t k = 0; k < loo.size(); ++k) loo[k] = 0.5 + static_cast<double>(k);
  CoefficientSurface surface = CoefficientSurface(table).with_run_uncertainty(sigma, loo);
  return {std::move(table), std::move(surface)};
}

// A coordinate on axis a: inside, on a breakpoint, at an end, or beyond.
double coordinate(const GridAxis& axis, std::mt19937_64& random) {
  const double lo = axis.breakpoints.front(), hi = axis.breakpoints.back(), range = hi - lo;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double kind = unit(random);
  if (kind < 0.6) return lo + range * unit(random);
  if (kind < 0.75)
    return axis
        .breakpoints[static_cast<std::size_t>(unit(random) * 0.999 * static_cast<double>(axis.breakpoints.size()))];
  if (kind < 0.8) return unit(random) < 0.5 ? lo : hi;
  return unit(random) < 0.5 ? lo - 0.6 * range * unit(random) : hi + 0.6 * range * unit(random);
}

// Evaluates `points` random points both ways; adds to `refused` those the library refused.
void compare(const Case& c, const hc_runtime_model* model, std::size_t index, std::size_t points,
             std::mt19937_64& random, std::size_t& refused) {
  const std::size_t n = c.table.axis_count(), n_out = c.table.output_count();
  std::vector<double> x(n), value(n_out), gradient(n * n_out), sd(n_out);
  std::vector<double> r_value(n_out), r_gradient(n * n_out), r_sd(n_out), r_plain(n_out);
  for (std::size_t i = 0; i < points; ++i) {
    for (std::size_t a = 0; a < n; ++a) x[a] = coordinate(c.table.axes()[a], random);
    bool library_refused = false;
    try {
      c.surface.evaluate_with_standard_deviation(x, value, sd, gradient);
    } catch (const InputError&) {
      library_refused = true;
    }
    const int status = hc_runtime_evaluate(model, index, x.data(), r_value.data(), r_gradient.data(), r_sd.data());
    if (library_refused) {
      ++refused;
      EXPECT_EQ(status, HC_RUNTIME_E_OUTSIDE) << "point " << i;
      char err[256];
      EXPECT_EQ(hc_runtime_check_point(model, index, x.data(), err, sizeof err), HC_RUNTIME_E_OUTSIDE);
      EXPECT_NE(std::string(err).find("is outside ["), std::string::npos) << err;
      continue;
    }
    ASSERT_EQ(status, HC_RUNTIME_OK) << "point " << i;
    // Values alone (no gradient buffer) are GridTable::evaluate's.
    ASSERT_EQ(hc_runtime_evaluate(model, index, x.data(), r_plain.data(), nullptr, nullptr), HC_RUNTIME_OK);
    std::vector<double> plain(n_out);
    c.table.evaluate(x, plain);
    for (std::size_t k = 0; k < n_out; ++k) {
      ASSERT_TRUE(same_bits(value[k], r_value[k]))
          << "point " << i << " output " << k << ": " << value[k] << " vs " << r_value[k];
      ASSERT_TRUE(same_bits(plain[k], r_plain[k])) << "point " << i << " output " << k;
      ASSERT_TRUE(same_bits(sd[k], r_sd[k])) << "point " << i << " sigma " << k << ": " << sd[k] << " vs " << r_sd[k];
    }
    for (std::size_t j = 0; j < n * n_out; ++j)
      ASSERT_TRUE(same_bits(gradient[j], r_gradient[j]))
          << "point " << i << " gradient " << j << ": " << gradient[j] << " vs " << r_gradient[j];
  }
}

class RuntimeEvaluate : public ::testing::TestWithParam<Interpolation> {};

TEST_P(RuntimeEvaluate, EqualsTheLibraryBitForBitUnderEveryPolicyOnOneToFourAxes) {
  const Interpolation method = GetParam();
  std::mt19937_64 random(20261128u + static_cast<unsigned>(method));
  std::vector<Case> cases;
  std::vector<RuntimeSurface> surfaces;
  for (std::size_t n = 1; n <= 4; ++n) {
    for (const Extrapolation policy : kPolicies) cases.push_back(make_case(method, std::vector(n, policy), random));
    // Mixed policies, one per axis in turn.
    std::vector<Extrapolation> mixed(n);
    for (std::size_t a = 0; a < n; ++a) mixed[a] = kPolicies[(a + n) % kPolicies.size()];
    cases.push_back(make_case(method, mixed, random));
  }
  for (std::size_t i = 0; i < cases.size(); ++i)
    surfaces.push_back(runtime_surface("s" + std::to_string(i), cases[i].surface, {{"case", std::to_string(i)}}));
  const std::string bytes = runtime_file_bytes(runtime_model_texts({{"body", "test"}}), surfaces);
  const Model model = open_bytes(bytes);
  ASSERT_NE(model, nullptr);
  ASSERT_EQ(hc_runtime_surface_count(model.get()), cases.size());
  std::size_t refused = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE("surface " + std::to_string(i) + ", " + std::to_string(cases[i].table.axis_count()) + " axes");
    compare(cases[i], model.get(), i, 10000, random, refused);
  }
  // The error policy refused points (so the refusals were compared too).
  EXPECT_GT(refused, 1000u);
}

INSTANTIATE_TEST_SUITE_P(AllMethods, RuntimeEvaluate, ::testing::ValuesIn(kMethods), [](const auto& info) {
  std::string name(interpolation_name(info.param));
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
});

TEST(RuntimeEvaluate, NanAndInfinityAreRefusedAndNothingIsWritten) {
  std::mt19937_64 random(7);
  const Case c = make_case(Interpolation::Pchip, {Extrapolation::Linear, Extrapolation::Clamp}, random);
  const Model model = open_bytes(runtime_file_bytes(runtime_model_texts({}), {runtime_surface("s", c.surface, {})}));
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()}) {
    const double x[2] = {0.1, bad};
    double values[2] = {123.0, 456.0};
    EXPECT_EQ(hc_runtime_evaluate(model.get(), 0, x, values, nullptr, nullptr), HC_RUNTIME_E_NOT_FINITE);
    EXPECT_EQ(values[0], 123.0);
    EXPECT_EQ(values[1], 456.0);
    char err[256];
    EXPECT_EQ(hc_runtime_check_point(model.get(), 0, x, err, sizeof err), HC_RUNTIME_E_NOT_FINITE);
    EXPECT_NE(std::string(err).find("axis 'v'"), std::string::npos) << err;
  }
}

TEST(RuntimeEvaluate, QueriesDescribeTheSurfacesAndTheModel) {
  std::mt19937_64 random(11);
  const Case with = make_case(Interpolation::Akima, {Extrapolation::Method, Extrapolation::Error}, random);
  const GridTable plain({{"u", {0.0, 1.0, 2.0}, Extrapolation::Clamp}}, {"X"}, {1.0, 2.0, 4.0}, Interpolation::Linear);
  const CoefficientSurface plain_surface(plain);
  const Model model = open_bytes(runtime_file_bytes(
      runtime_model_texts({{"body", "asr-v"}, {"database", "runs.db"}}),
      {runtime_surface("yaw", with.surface, {{"runs", "1,2,3"}}), runtime_surface("surge", plain_surface, {})}));
  const hc_runtime_model* m = model.get();
  EXPECT_EQ(hc_runtime_abi_version(), HC_RUNTIME_ABI_VERSION);
  EXPECT_STREQ(hc_runtime_metadata(m, "body"), "asr-v");
  EXPECT_STREQ(hc_runtime_metadata(m, "database"), "runs.db");
  EXPECT_NE(std::string(hc_runtime_metadata(m, "frame")).find("FRD"), std::string::npos);
  EXPECT_NE(std::string(hc_runtime_metadata(m, "sign_convention")).find("on-body"), std::string::npos);
  EXPECT_EQ(hc_runtime_metadata(m, "no such key"), nullptr);
  ASSERT_EQ(hc_runtime_surface_count(m), 2u);
  std::size_t index = 99;
  EXPECT_EQ(hc_runtime_surface_index(m, "surge", &index), HC_RUNTIME_OK);
  EXPECT_EQ(index, 1u);
  EXPECT_EQ(hc_runtime_surface_index(m, "sway", &index), HC_RUNTIME_E_NOT_FOUND);
  EXPECT_STREQ(hc_runtime_surface_name(m, 0), "yaw");
  EXPECT_STREQ(hc_runtime_surface_method(m, 0), "makima");
  EXPECT_STREQ(hc_runtime_surface_method(m, 1), "linear");
  EXPECT_STREQ(hc_runtime_surface_metadata(m, 0, "runs"), "1,2,3");
  EXPECT_EQ(hc_runtime_surface_has_sigma(m, 0), 1);
  EXPECT_EQ(hc_runtime_surface_has_sigma(m, 1), 0);
  EXPECT_EQ(hc_runtime_axis_count(m, 0), 2u);
  EXPECT_EQ(hc_runtime_output_count(m, 0), 2u);
  EXPECT_STREQ(hc_runtime_axis_name(m, 0, 1), "v");
  EXPECT_STREQ(hc_runtime_axis_unit(m, 0, 1), "m/s");
  EXPECT_STREQ(hc_runtime_axis_extrapolation(m, 0, 0), "method");
  EXPECT_STREQ(hc_runtime_axis_extrapolation(m, 0, 1), "error");
  EXPECT_STREQ(hc_runtime_output_name(m, 0, 1), "N");
  EXPECT_STREQ(hc_runtime_output_unit(m, 0, 1), "N m");
  std::size_t count = 0;
  const double* x = hc_runtime_axis_breakpoints(m, 0, 1, &count);
  ASSERT_EQ(count, with.table.axes()[1].breakpoints.size());
  for (std::size_t i = 0; i < count; ++i) EXPECT_TRUE(same_bits(x[i], with.table.axes()[1].breakpoints[i]));
  // Out-of-range indexes and NULLs: NULL, 0 or HC_RUNTIME_E_ARGUMENT, never a crash.
  EXPECT_EQ(hc_runtime_surface_name(m, 2), nullptr);
  EXPECT_EQ(hc_runtime_axis_name(m, 0, 2), nullptr);
  EXPECT_EQ(hc_runtime_output_unit(m, 1, 1), nullptr);
  EXPECT_EQ(hc_runtime_axis_count(m, 5), 0u);
  EXPECT_EQ(hc_runtime_axis_breakpoints(m, 0, 6, &count), nullptr);
  EXPECT_EQ(count, 0u);
  const double point[2] = {0.0, 0.0};
  double out[2], sd[2];
  EXPECT_EQ(hc_runtime_evaluate(m, 2, point, out, nullptr, nullptr), HC_RUNTIME_E_ARGUMENT);
  EXPECT_EQ(hc_runtime_evaluate(m, 0, nullptr, out, nullptr, nullptr), HC_RUNTIME_E_ARGUMENT);
  EXPECT_EQ(hc_runtime_evaluate(nullptr, 0, point, out, nullptr, nullptr), HC_RUNTIME_E_ARGUMENT);
  EXPECT_EQ(hc_runtime_evaluate(m, 1, point, out, nullptr, sd), HC_RUNTIME_E_NO_SIGMA);
  EXPECT_STREQ(hc_runtime_status_name(HC_RUNTIME_E_HASH), "HC_RUNTIME_E_HASH");
  EXPECT_STREQ(hc_runtime_status_name(1234), "unknown status");
  hc_runtime_close(nullptr);
}

TEST(RuntimeExport, RefusesWhatTheFileCannotHoldInOneLine) {
  const GridTable table({{"u", {0.0, 1.0, 2.0}, Extrapolation::Clamp}}, {"X"}, {1.0, 2.0, 4.0}, Interpolation::Linear);
  const CoefficientSurface surface(table);
  try {
    (void)runtime_file_bytes(runtime_model_texts({}),
                             {runtime_surface("a", surface, {}), runtime_surface("a", surface, {})});
    FAIL() << "two surfaces of one name were written";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), "surface 'a' is given twice; expected each surface once");
  }
  RuntimeSurface bad = runtime_surface("b", surface, {});
  bad.axis_units.clear();
  EXPECT_THROW((void)runtime_file_bytes(runtime_model_texts({}), {bad}), InputError);
}

}  // namespace
}  // namespace hydrocoef
