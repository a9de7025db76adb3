// hydrocoef/runtime.hpp, the C++ wrapper over libhydrocoef_runtime: its
// values, gradients and sigma equal the C API's bit for bit at 1,000 random
// states per surface of a file written as runtime_evaluate_test.cpp writes
// them; opening a missing or a tampered file throws with the C library's
// message; a span of the wrong size throws before the C library is called,
// and a point the C library refuses throws with the status's name.
#include "hydrocoef/runtime.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/export/runtime_export.hpp"
#include "src/surface/coefficient_surface.hpp"
#include "src/surface/grid_table.hpp"
#include "tests/support/same_bits.hpp"

namespace hydrocoef {
namespace {

using test::same_bits;

using runtime::Model;

// A surface of two outputs over `n` axes (even breakpoints on [-1, 1]) with
// a runs' sigma.
CoefficientSurface make_surface(std::size_t n, Interpolation method, Extrapolation policy, std::mt19937_64& random) {
  std::vector<GridAxis> axes;
  std::size_t nodes = 1;
  for (std::size_t a = 0; a < n; ++a) {
    std::vector<double> breakpoints;
    for (int i = 0; i < 5; ++i) breakpoints.push_back(-1.0 + 0.5 * i + (i == 2 ? 0.1 * static_cast<double>(a) : 0.0));
    axes.push_back({std::string(1, "uvwpqr"[a]), breakpoints, policy});
    nodes *= breakpoints.size();
  }
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  std::vector<double> values, sigma;
  for (std::size_t node = 0; node < 2 * nodes; ++node) {
    values.push_back(100.0 * noise(random));
    sigma.push_back(1.0 + std::abs(noise(random)));
  }
  GridTable table(axes, {"X", "N"}, values, method);
  return CoefficientSurface(table).with_run_uncertainty(sigma, {0.5, 1.5});
}

std::string file_bytes() {
  std::mt19937_64 random(37);
  // A RuntimeSurface points into its CoefficientSurface: these outlive runtime_file_bytes.
  const std::vector<CoefficientSurface> tables = {
      make_surface(2, Interpolation::Linear, Extrapolation::Linear, random),
      make_surface(3, Interpolation::Pchip, Extrapolation::Clamp, random),
      make_surface(1, Interpolation::NaturalSpline, Extrapolation::Error, random)};
  const std::vector<RuntimeSurface> surfaces = {runtime_surface("linear2", tables[0], {}),
                                                runtime_surface("pchip3", tables[1], {}),
                                                runtime_surface("spline1", tables[2], {})};
  return runtime_file_bytes(runtime_model_texts({{"body", "test"}}), surfaces);
}

TEST(RuntimeWrapper, EqualsTheCApiBitForBit) {
  const std::string bytes = file_bytes();
  const Model model = Model::from_memory(bytes);
  hc_runtime_model* c_model = nullptr;
  ASSERT_EQ(hc_runtime_open_memory(bytes.data(), bytes.size(), &c_model, nullptr, 0), HC_RUNTIME_OK);
  ASSERT_EQ(model.surface_count(), 3u);
  EXPECT_EQ(model.surface_names(), (std::vector<std::string>{"linear2", "pchip3", "spline1"}));
  EXPECT_EQ(model.surface_index("pchip3"), 1u);
  EXPECT_EQ(model.axis_names(1), (std::vector<std::string>{"u", "v", "w"}));
  EXPECT_EQ(model.output_names(0), (std::vector<std::string>{"X", "N"}));
  EXPECT_EQ(model.method(1), "pchip");
  EXPECT_THROW((void)model.surface_index("nothing"), std::out_of_range);
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> coordinate(-0.99, 0.99);
  std::size_t compared = 0;
  for (std::size_t s = 0; s < model.surface_count(); ++s) {
    const std::size_t n = model.axis_count(s), n_out = model.output_count(s);
    std::vector<double> x(n), values(n_out), gradients(n * n_out), sigma(n_out);
    std::vector<double> c_values(n_out), c_gradients(n * n_out), c_sigma(n_out);
    for (int i = 0; i < 1000; ++i) {
      for (double& v : x) v = coordinate(random);
      model.evaluate(s, x, values, gradients, sigma);
      ASSERT_EQ(hc_runtime_evaluate(c_model, s, x.data(), c_values.data(), c_gradients.data(), c_sigma.data()),
                HC_RUNTIME_OK);
      for (std::size_t k = 0; k < n_out; ++k) {
        ASSERT_TRUE(same_bits(values[k], c_values[k])) << "surface " << s << " point " << i;
        ASSERT_TRUE(same_bits(sigma[k], c_sigma[k])) << "surface " << s << " point " << i;
      }
      for (std::size_t j = 0; j < n * n_out; ++j) ASSERT_TRUE(same_bits(gradients[j], c_gradients[j]));
      // Values alone.
      model.evaluate(s, x, values);
      for (std::size_t k = 0; k < n_out; ++k) ASSERT_TRUE(same_bits(values[k], c_values[k]));
      ++compared;
    }
  }
  EXPECT_EQ(compared, 3000u);
  hc_runtime_close(c_model);
}

// The message of the C library for `bytes` (or for the file at `path`).
std::string c_message(const std::string& bytes, const char* path = nullptr) {
  hc_runtime_model* model = nullptr;
  char err[512] = "";
  const int status = path != nullptr ? hc_runtime_open(path, &model, err, sizeof err)
                                     : hc_runtime_open_memory(bytes.data(), bytes.size(), &model, err, sizeof err);
  EXPECT_NE(status, HC_RUNTIME_OK);
  hc_runtime_close(model);
  return err;
}

TEST(RuntimeWrapper, AMissingFileThrowsWithTheCMessage) {
  const char* path = "/nonexistent/runtime_wrapper_test.hcrt";
  const std::string expected = c_message("", path);
  ASSERT_NE(expected.find("runtime_wrapper_test.hcrt"), std::string::npos) << expected;
  try {
    (void)Model::open(path);
    FAIL() << "opened a missing file";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()), expected);
  }
}

TEST(RuntimeWrapper, ATamperedFileThrowsWithTheCMessage) {
  std::string bytes = file_bytes();
  bytes[bytes.size() - 9] = static_cast<char>(bytes[bytes.size() - 9] ^ 0x01);
  const std::string expected = c_message(bytes);
  ASSERT_FALSE(expected.empty());
  try {
    (void)Model::from_memory(bytes);
    FAIL() << "opened a tampered file";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()), expected);
  }
}

TEST(RuntimeWrapper, AWrongSpanSizeThrowsAndARefusedPointNamesTheStatus) {
  const Model model = Model::from_memory(file_bytes());
  std::vector<double> x(2, 0.1), values(2), gradients(4), sigma(2);
  EXPECT_THROW(model.evaluate(0, std::vector<double>(3, 0.1), values), std::invalid_argument);
  std::vector<double> short_values(1);
  EXPECT_THROW(model.evaluate(0, x, short_values), std::invalid_argument);
  std::vector<double> short_gradients(3);
  EXPECT_THROW(model.evaluate(0, x, values, short_gradients), std::invalid_argument);
  std::vector<double> long_sigma(3);
  EXPECT_THROW(model.evaluate(0, x, values, gradients, long_sigma), std::invalid_argument);
  EXPECT_THROW(model.evaluate(7, x, values), std::out_of_range);
  EXPECT_NO_THROW(model.evaluate(0, x, values, gradients, sigma));
  // spline1's policy is "error": 1.5 is outside [-1, 1].
  const std::vector<double> outside{1.5};
  try {
    model.evaluate(2, outside, values);
    FAIL() << "evaluated outside an axis whose policy is error";
  } catch (const std::runtime_error& error) {
    const std::string what = error.what();
    EXPECT_EQ(what.rfind("HC_RUNTIME_E_OUTSIDE: ", 0), 0u) << what;
    EXPECT_NE(what.find("is outside ["), std::string::npos) << what;
  }
  // The vehicle functions check their spans too, and refuse a file without a vehicle.
  std::vector<double> state(13, 0.0), tau(6, 0.0);
  state[3] = 1.0;
  EXPECT_THROW(model.vehicle_step_rk4(std::span(state).first(12), tau, {}, {}, 0.01), std::invalid_argument);
  try {
    model.vehicle_step_rk4(state, tau, {}, {}, 0.01);
    FAIL() << "stepped a file without a vehicle";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()).rfind("HC_RUNTIME_E_NO_VEHICLE", 0), 0u) << error.what();
  }
}

TEST(RuntimeWrapper, AMovedFromModelIsEmptyAndTheMovedToOneWorks) {
  Model a = Model::from_memory(file_bytes());
  Model b = std::move(a);
  EXPECT_EQ(a.get(), nullptr);  // NOLINT(bugprone-use-after-move): the state after a move is the point
  EXPECT_THROW((void)a.surface_count(), std::logic_error);
  EXPECT_EQ(b.surface_count(), 3u);
}

}  // namespace
}  // namespace hydrocoef
