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

#include "src/dynamics/integrators.hpp"
#include "src/dynamics/rigid_body.hpp"
#include "src/dynamics/vehicle_model.hpp"

namespace hydrocoef {
namespace {

std::vector<double> breakpoints(double limit) {
  std::vector<double> b;
  for (int i = 0; i < 20; ++i) b.push_back(-limit + 2.0 * limit * i / 19.0);
  return b;
}

double velocity_limit(const std::string& name) { return name == "u" || name == "v" || name == "w" ? 1.0 : 2.0; }

// Damping on the body of DOF `dof` over (own velocity x, cross velocity y):
// -(k1 x + k2 x|x|)(1 + 0.3 y^2), outputs as many as `outputs` (all the same law).
CoefficientSurface damping_surface(const std::string& x, const std::string& y, std::vector<std::string> outputs,
                                   Interpolation method) {
  std::vector<GridAxis> axes{{x, breakpoints(velocity_limit(x)), Extrapolation::Clamp},
                             {y, breakpoints(velocity_limit(y)), Extrapolation::Clamp}};
  std::vector<double> values;
  for (const double b : axes[1].breakpoints)
    for (const double a : axes[0].breakpoints)
      for (std::size_t k = 0; k < outputs.size(); ++k)
        values.push_back(-(0.5 * a + 10.0 * a * std::abs(a)) * (1.0 + 0.3 * b * b) / static_cast<double>(k + 1));
  return CoefficientSurface(GridTable(axes, std::move(outputs), values, method));
}

VehicleDescription asr_v_like() {
  VehicleDescription v;
  v.mass_kg = 6.7;
  v.inertia_cg_b = Matrix3::Identity() * 0.0603;
  v.r_g_b = Vector3(0.0, 0.0, 0.02);
  v.buoyancy_N = v.mass_kg * v.gravity_m_s2;
  v.added_mass_b = sphere_added_mass(v.rho_kg_m3, 0.15);
  return v;
}

// (own axis, cross axis) for X..N.
constexpr std::array<std::array<const char*, 2>, 6> kAxes{
    {{"u", "v"}, {"v", "u"}, {"w", "u"}, {"p", "v"}, {"q", "w"}, {"r", "u"}}};

VehicleModel six_surface_model(Interpolation method) {
  VehicleDescription v = asr_v_like();
  std::vector<std::pair<std::string, CoefficientSurface>> surfaces;
  for (std::size_t dof = 0; dof < 6; ++dof) {
    const std::string name = std::string("s") + kAxes[dof][0];
    surfaces.emplace_back(name, damping_surface(kAxes[dof][0], kAxes[dof][1], {std::string(kForceNames[dof])}, method));
    v.damping[dof] = {DofDamping::Kind::Surface, {}, {}, name, std::string(kForceNames[dof]), {},
                      SignConvention::OnBody};
  }
  return VehicleModel(v, [surfaces](const std::string& name) {
    for (const auto& [n, s] : surfaces)
      if (n == name) return s;
    throw std::runtime_error("no surface " + name);
  });
}

ModelInputs turning_inputs() {
  ModelInputs in;
  in.tau_b << 0.5, 0.1, 0.0, 0.0, 0.0, 0.003;
  in.current_n = Vector3(0.05, 0.02, 0.0);
  return in;
}

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
