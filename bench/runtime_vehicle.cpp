// libhydrocoef_runtime's vehicle: RK4 steps per second through the C API
// (hc_runtime_vehicle_step_rk4) of bench/simulate.cpp's model, a 2-D gridded
// surface (20 x 20) giving the damping of each of the six DOFs (six separate
// surfaces), linear or PCHIP, in a current; and one derivative. The same
// vehicle as BM_Rk4SixSurfaces* of bench_simulate, through the runtime file.
// Goal (issue 37): <= 1.5 us per step through the FMU built on this call.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/six_surface_vehicle.hpp"
#include "hydrocoef/runtime.h"
#include "src/dynamics/rigid_body.hpp"
#include "src/dynamics/vehicle_model.hpp"
#include "src/export/runtime_export.hpp"

namespace hydrocoef {
namespace {

struct Closer {
  void operator()(hc_runtime_model* model) const { hc_runtime_close(model); }
};
using Runtime = std::unique_ptr<hc_runtime_model, Closer>;

// bench_simulate's six-surface ASR-V-like vehicle as a runtime file, opened.
Runtime six_surface_runtime(Interpolation method) {
  const std::string bytes = bench::six_surface_runtime_bytes(method, {});
  hc_runtime_model* opened = nullptr;
  char err[256];
  if (hc_runtime_open_memory(bytes.data(), bytes.size(), &opened, err, sizeof err) != HC_RUNTIME_OK)
    throw std::runtime_error(err);
  return Runtime(opened);
}

// bench_simulate's inputs: a turning command in a current.
constexpr double kTau[6] = {0.5, 0.1, 0.0, 0.0, 0.0, 0.003};
constexpr double kCurrent[3] = {0.05, 0.02, 0.0};

void run_rk4(benchmark::State& state, Interpolation method) {
  const Runtime model = six_surface_runtime(method);
  const Quaternion4 q = quaternion_from_euler(Vector3(0.05, 0.02, 0.3));
  double x[13] = {0, 0, 0, q[0], q[1], q[2], q[3], 0, 0, 0, 0, 0, 0};
  double t = 0.0;
  const double h = 1e-3;
  char err[256];
  for (auto _ : state) {
    if (hc_runtime_vehicle_step_rk4(model.get(), x, kTau, kCurrent, nullptr, h, err, sizeof err) != HC_RUNTIME_OK) {
      state.SkipWithError(err);
      break;
    }
    t += h;
    benchmark::DoNotOptimize(x);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["vehicle_s"] = t;
}

void BM_RuntimeRk4SixSurfacesLinear(benchmark::State& state) { run_rk4(state, Interpolation::Linear); }
void BM_RuntimeRk4SixSurfacesPchip(benchmark::State& state) { run_rk4(state, Interpolation::Pchip); }

// One derivative (a quarter of an RK4 step).
void BM_RuntimeDerivativeSixSurfacesLinear(benchmark::State& state) {
  const Runtime model = six_surface_runtime(Interpolation::Linear);
  const Quaternion4 q = quaternion_from_euler(Vector3(0.05, 0.02, 0.3));
  const double x[13] = {0, 0, 0, q[0], q[1], q[2], q[3], 0.2, 0.05, 0.01, 0.02, 0.01, 0.1};
  double dx[13];
  for (auto _ : state) {
    (void)hc_runtime_vehicle_derivative(model.get(), x, kTau, kCurrent, nullptr, dx, nullptr, 0);
    benchmark::DoNotOptimize(dx);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

}  // namespace
}  // namespace hydrocoef

BENCHMARK(hydrocoef::BM_RuntimeRk4SixSurfacesLinear);
BENCHMARK(hydrocoef::BM_RuntimeRk4SixSurfacesPchip);
BENCHMARK(hydrocoef::BM_RuntimeDerivativeSixSurfacesLinear);
BENCHMARK_MAIN();
