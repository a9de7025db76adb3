// libFuzzer target: runtime files (runtime/src/runtime_file.c) opened by
// libhydrocoef_runtime. Each input is opened as it is (the header and the
// content hash answer first) and again with its header's size and hash made
// right (so the sections' own checks answer). Opening must give a code and a
// one-line message, or a model whose every surface evaluates (inside, at,
// beyond the axes, NaN) and whose vehicle, if it holds one, steps without a
// sanitizer report.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "hydrocoef/runtime.h"
#include "runtime/src/xxh64.h"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

void put_u64(std::string& bytes, std::size_t at, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) bytes[at + static_cast<std::size_t>(i)] = static_cast<char>((value >> (8 * i)) & 0xffu);
}

void exercise(const hc_runtime_model* model) {
  for (std::size_t s = 0; s < hc_runtime_surface_count(model); ++s) {
    const std::size_t n = hc_runtime_axis_count(model, s), n_out = hc_runtime_output_count(model, s);
    if (n < 1 || n > HC_RUNTIME_MAX_AXES || n_out < 1) hydrocoef::fuzz::finding("an opened surface's counts");
    if (hc_runtime_surface_name(model, s) == nullptr || hc_runtime_surface_method(model, s) == nullptr)
      hydrocoef::fuzz::finding("an opened surface without a name or a method");
    std::size_t index = 0;
    if (hc_runtime_surface_index(model, hc_runtime_surface_name(model, s), &index) != HC_RUNTIME_OK || index != s)
      hydrocoef::fuzz::finding("a surface not found by its own name");
    std::vector<double> x(n), values(n_out), gradients(n * n_out), sigma(n_out);
    const bool has_sigma = hc_runtime_surface_has_sigma(model, s) != 0;
    for (const double where : {-0.25, 0.0, 0.5, 1.0, 1.75, std::numeric_limits<double>::quiet_NaN()}) {
      for (std::size_t a = 0; a < n; ++a) {
        std::size_t count = 0;
        const double* points = hc_runtime_axis_breakpoints(model, s, a, &count);
        if (points == nullptr || count < 2) hydrocoef::fuzz::finding("an opened axis without breakpoints");
        x[a] = points[0] + where * (points[count - 1] - points[0]);
        (void)hc_runtime_axis_name(model, s, a);
        (void)hc_runtime_axis_extrapolation(model, s, a);
      }
      const int status =
          hc_runtime_evaluate(model, s, x.data(), values.data(), gradients.data(), has_sigma ? sigma.data() : nullptr);
      char err[256];
      if (status != HC_RUNTIME_OK && hc_runtime_check_point(model, s, x.data(), err, sizeof err) != status)
        hydrocoef::fuzz::finding("evaluate and check_point disagree");
    }
  }
}

// A vehicle: its derivative, forces and an RK4 step at rest and moving, in a
// current, give a status and (on an error) a message, never a sanitizer report.
void exercise_vehicle(const hc_runtime_model* model) {
  if (!hc_runtime_has_vehicle(model)) return;
  const std::size_t disturbances = hc_runtime_vehicle_disturbance_count(model);
  for (std::size_t i = 0; i < disturbances; ++i)
    if (hc_runtime_vehicle_disturbance_name(model, i) == nullptr)
      hydrocoef::fuzz::finding("a disturbance without a name");
  std::vector<double> values(disturbances + 1, 0.25), thrust(hc_runtime_vehicle_thruster_count(model) + 1, 0.5);
  double tau[6] = {0.1, 0.0, 0.0, 0.0, 0.0, 0.01}, x_dot[13], breakdown[30];
  (void)hc_runtime_vehicle_thrust_force(model, thrust.data(), tau);
  const double current[3] = {0.1, -0.05, 0.0};
  for (const double speed : {0.0, 0.3, std::numeric_limits<double>::quiet_NaN()}) {
    double x[13] = {0, 0, 0, 1, 0, 0, 0, speed, speed, speed, speed, speed, speed};
    char err[256];
    (void)hc_runtime_vehicle_derivative(model, x, tau, current, values.data(), x_dot, err, sizeof err);
    (void)hc_runtime_vehicle_forces(model, x, tau, nullptr, values.data(), breakdown, err, sizeof err);
    const int status = hc_runtime_vehicle_step_rk4(model, x, tau, current, values.data(), 0.01, err, sizeof err);
    if (status != HC_RUNTIME_OK && strnlen(err, sizeof err) == 0)
      hydrocoef::fuzz::finding("a refused step without a message");
  }
}

void open_and_check(const std::string& bytes) {
  hc_runtime_model* model = nullptr;
  char err[512];
  std::memset(err, 'x', sizeof err);
  const int status = hc_runtime_open_memory(bytes.data(), bytes.size(), &model, err, sizeof err);
  if (status == HC_RUNTIME_OK) {
    if (model == nullptr) hydrocoef::fuzz::finding("HC_RUNTIME_OK without a model");
    exercise(model);
    exercise_vehicle(model);
    hc_runtime_close(model);
    return;
  }
  if (model != nullptr) hydrocoef::fuzz::finding("an error with a model");
  const std::size_t length = strnlen(err, sizeof err);
  if (length == 0 || length == sizeof err) hydrocoef::fuzz::finding("an error without a terminated message");
  if (std::memchr(err, '\n', length) != nullptr) hydrocoef::fuzz::finding("a message of several lines", err);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
  open_and_check(bytes);
  if (bytes.size() >= 64) {
    put_u64(bytes, 16, bytes.size());
    put_u64(bytes, 24, hc_xxh64(bytes.data() + 64, bytes.size() - 64, 0));
    open_and_check(bytes);
  }
  return 0;
}
