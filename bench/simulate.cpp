// Simulation speed of the lookup-table 6-DOF model: RK4 steps per second with
// a 2-D gridded surface (20 x 20) giving the damping of each of the six DOFs
// (six separate surfaces, so six breakpoint searches per derivative), linear
// or PCHIP; one derivative evaluation alone; and Dormand–Prince 5(4) steps
// per second on the same model.
// Goal: >= 1e6 RK4 steps/s (an hour of vehicle time at 1 kHz in under 4 s).
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "bench/six_surface_vehicle.hpp"
#include "src/dynamics/integrators.hpp"
#include "src/dynamics/rigid_body.hpp"
#include "src/dynamics/vehicle_model.hpp"

namespace hydrocoef {
namespace {

using bench::six_surface_model;
using bench::turning_inputs;

void run_rk4(benchmark::State& state, const VehicleModel& model) {
  const ModelInputs inputs = turning_inputs();
  StateVector x = make_state(Vector3::Zero(), quaternion_from_euler(Vector3(0.05, 0.02, 0.3)), Vector6::Zero());
  auto f = [&](double, const StateVector& s, StateVector& ds) { model.derivative(s, inputs, ds); };
  Rk4Workspace<StateVector> w;
  double t = 0.0;
  const double h = 1e-3;
  for (auto _ : state) {
    rk4_step(f, t, h, x, w);
    normalize_attitude(x);
    t += h;
    benchmark::DoNotOptimize(x.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["vehicle_s"] = t;
}

void BM_Rk4SixSurfacesLinear(benchmark::State& state) { run_rk4(state, six_surface_model(Interpolation::Linear)); }
void BM_Rk4SixSurfacesPchip(benchmark::State& state) { run_rk4(state, six_surface_model(Interpolation::Pchip)); }

// One evaluation of the model's derivative (a quarter of an RK4 step).
void BM_DerivativeSixSurfacesLinear(benchmark::State& state) {
  const VehicleModel model = six_surface_model(Interpolation::Linear);
  const ModelInputs inputs = turning_inputs();
  Vector6 nu;
  nu << 0.2, 0.05, 0.01, 0.02, 0.01, 0.1;
  const StateVector x = make_state(Vector3::Zero(), quaternion_from_euler(Vector3(0.05, 0.02, 0.3)), nu);
  StateVector dx;
  for (auto _ : state) {
    model.derivative(x, inputs, dx);
    benchmark::DoNotOptimize(dx.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

// One iteration: one hour of vehicle time at 1 kHz is 3.6e6 steps; here 1 s.
void BM_Rk4OneSecondAt1kHz(benchmark::State& state) {
  const VehicleModel model = six_surface_model(Interpolation::Linear);
  const ModelInputs inputs = turning_inputs();
  StateVector x = make_state(Vector3::Zero(), quaternion_from_euler(Vector3(0.05, 0.02, 0.3)), Vector6::Zero());
  auto f = [&](double, const StateVector& s, StateVector& ds) { model.derivative(s, inputs, ds); };
  Rk4Workspace<StateVector> w;
  for (auto _ : state) {
    for (int k = 0; k < 1000; ++k) {
      rk4_step(f, k * 1e-3, 1e-3, x, w);
      normalize_attitude(x);
    }
    benchmark::DoNotOptimize(x.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * 1000);
}

void BM_DormandPrinceSixSurfacesLinear(benchmark::State& state) {
  const VehicleModel model = six_surface_model(Interpolation::Linear);
  const ModelInputs inputs = turning_inputs();
  StateVector x = make_state(Vector3::Zero(), quaternion_from_euler(Vector3(0.05, 0.02, 0.3)), Vector6::Zero());
  auto f = [&](double, const StateVector& s, StateVector& ds) { model.derivative(s, inputs, ds); };
  AdaptiveOptions options;
  options.relative_tolerance = 1e-9;
  options.absolute_tolerance = 1e-12;
  options.max_step = 0.01;  // a 100 Hz control loop would not let steps grow beyond this
  DormandPrince45<StateVector> dp(options);
  double t = 0.0;
  for (auto _ : state) {
    dp.advance(f, t, t + 0.1, x);
    normalize_attitude(x);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(dp.stats().accepted));
  state.counters["evaluations_per_step"] =
      static_cast<double>(dp.stats().evaluations) / static_cast<double>(std::max<std::size_t>(1, dp.stats().accepted));
  state.counters["rejected"] = static_cast<double>(dp.stats().rejected);
  state.counters["vehicle_s"] = t;
}

}  // namespace
}  // namespace hydrocoef

BENCHMARK(hydrocoef::BM_Rk4SixSurfacesLinear);
BENCHMARK(hydrocoef::BM_Rk4SixSurfacesPchip);
BENCHMARK(hydrocoef::BM_DerivativeSixSurfacesLinear);
BENCHMARK(hydrocoef::BM_Rk4OneSecondAt1kHz);
BENCHMARK(hydrocoef::BM_DormandPrinceSixSurfacesLinear);
BENCHMARK_MAIN();
