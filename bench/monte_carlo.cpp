// Monte Carlo simulation speed: the ASR-V constant-torque yaw test
// (examples/asr-v/scenario-yaw-0.0027.json: 60 s, RK4 at 1 kHz) with its
// surge and yaw damping from GP surfaces fitted to the example's CFD tables,
// each trajectory a fresh posterior draw of both (DampingDraws: looked up as
// natural-spline tables), on every core: 1,000 trajectories are 60 M RK4
// steps (240 M derivative evaluations with two surface lookups each); RK4
// runs the draws 8 at a time in lock-step (simulate_lanes).
// Goal: 1,000 trajectories in <= 15 s on the 2-core machine.
// Also: the equilibrium's interval from 2,000 draws.
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "src/dynamics/damping_draws.hpp"
#include "src/dynamics/ensemble.hpp"
#include "src/dynamics/scenario.hpp"
#include "src/dynamics/vehicle.hpp"
#include "src/surface/gp_surfaces.hpp"

namespace hydrocoef {
namespace {

const std::string kExample = HYDROCOEF_SOURCE_DIR "/examples/asr-v/";

/// The two columns of an example damping table, the value times `sign`.
void read_table(const std::string& file, double sign, std::vector<double>& x, std::vector<double>& y) {
  std::ifstream in(kExample + file);
  std::string line;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line.front() == '#') continue;
    if (!header) {
      header = true;
      continue;
    }
    std::istringstream fields(line);
    std::string a, b;
    std::getline(fields, a, ',');
    std::getline(fields, b, ',');
    x.push_back(std::stod(a));
    y.push_back(sign * std::stod(b));
  }
}

CoefficientSurface gp_surface(const std::string& file, double sign, const std::string& axis,
                              const std::string& output) {
  std::vector<double> x, y;
  read_table(file, sign, x, y);
  GpOptions options;
  options.mean_degree = 2;
  GpSurfaces gp(1, x, 1, y, {}, options, {axis}, {RbfOutOfRange::Clamp});
  return CoefficientSurface(std::move(gp), {axis}, {output});
}

struct Setup {
  VehicleModel model;
  DampingDraws draws;
  Scenario scenario;
};

Setup& setup() {
  static Setup s = [] {
    // The surge table prints damping magnitudes (opposing), the yaw table the moment on the body.
    const CoefficientSurface surge = gp_surface("asr-v-surge-damping.csv", -1.0, "u", "X");
    const CoefficientSurface yaw = gp_surface("asr-v-yaw-damping.csv", 1.0, "r", "N");
    VehicleModel model(load_vehicle(kExample + "vehicle-surfaces.json"),
                       [&](const std::string& name) { return name == "asr-v-surge" ? surge : yaw; });
    DampingDraws draws(model.damping(), model.description().damping);
    return Setup{std::move(model), std::move(draws), load_scenario(kExample + "scenario-yaw-0.0027.json")};
  }();
  return s;
}

void BM_SampledYawTest(benchmark::State& state) {
  Setup& s = setup();
  EnsembleOptions options;
  options.samples = static_cast<std::size_t>(state.range(0));
  std::size_t steps = 0;
  double r_low = 0.0, r_high = 0.0;
  for (auto _ : state) {
    const TrajectoryBands bands = simulate_samples(s.model, s.draws, s.scenario, options);
    benchmark::DoNotOptimize(bands.values.data());
    const std::size_t r = bands.quantity_index("r"), last = bands.t_s.size() - 1;
    r_low = bands.value(r, 0, last);
    r_high = bands.value(r, 2, last);
    steps += options.samples * static_cast<std::size_t>(s.scenario.duration_s / s.scenario.integrator.step_s + 0.5);
  }
  state.counters["rk4_steps_per_s"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
  state.counters["r_p5_at_60s"] = r_low;
  state.counters["r_p95_at_60s"] = r_high;
}
BENCHMARK(BM_SampledYawTest)->Arg(100)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

void BM_SampledEquilibrium(benchmark::State& state) {
  Setup& s = setup();
  EnsembleOptions options;
  options.samples = static_cast<std::size_t>(state.range(0));
  options.percentiles = {2.5, 50.0, 97.5};
  EquilibriumInputs in;
  in.tau_b[5] = 0.0027;
  for (auto _ : state) {
    const EquilibriumSamples out = solve_equilibrium_samples(s.model, s.draws, in, options);
    benchmark::DoNotOptimize(out.mean.data());
    state.counters["r_p2.5"] = out.percentile_values[0][5];
    state.counters["r_p97.5"] = out.percentile_values[2][5];
  }
}
BENCHMARK(BM_SampledEquilibrium)->Arg(2000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace hydrocoef

BENCHMARK_MAIN();
