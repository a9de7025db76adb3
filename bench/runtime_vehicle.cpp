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

#include "hydrocoef/runtime.h"
#include "src/dynamics/rigid_body.hpp"
#include "src/dynamics/vehicle_model.hpp"
#include "src/export/runtime_export.hpp"

namespace hydrocoef {
namespace {

std::vector<double> breakpoints(double limit) {
  std::vector<double> b;
  for (int i = 0; i < 20; ++i) b.push_back(-limit + 2.0 * limit * i / 19.0);
  return b;
}

double velocity_limit(const std::string& name) { return name == "u" || name == "v" || name == "w" ? 1.0 : 2.0; }

// Damping on the body over (own velocity x, cross velocity y): -(k1 x + k2 x|x|)(1 + 0.3 y^2).
CoefficientSurface damping_surface(const std::string& x, const std::string& y, const std::string& output,
                                   Interpolation method) {
  std::vector<GridAxis> axes{{x, breakpoints(velocity_limit(x)), Extrapolation::Clamp},
                             {y, breakpoints(velocity_limit(y)), Extrapolation::Clamp}};
  std::vector<double> values;
  for (const double b : axes[1].breakpoints)
    for (const double a : axes[0].breakpoints)
      values.push_back(-(0.5 * a + 10.0 * a * std::abs(a)) * (1.0 + 0.3 * b * b));
  return CoefficientSurface(GridTable(axes, {output}, values, method));
}

constexpr std::array<std::array<const char*, 2>, 6> kAxes{
    {{"u", "v"}, {"v", "u"}, {"w", "u"}, {"p", "v"}, {"q", "w"}, {"r", "u"}}};

struct Closer {
  void operator()(hc_runtime_model* model) const { hc_runtime_close(model); }
};
using Runtime = std::unique_ptr<hc_runtime_model, Closer>;

// bench_simulate's six-surface ASR-V-like vehicle as a runtime file, opened.
Runtime six_surface_runtime(Interpolation method) {
  VehicleDescription v;
  v.mass_kg = 6.7;
  v.inertia_cg_b = Matrix3::Identity() * 0.0603;
  v.r_g_b = Vector3(0.0, 0.0, 0.02);
  v.buoyancy_N = v.mass_kg * v.gravity_m_s2;
  v.added_mass_b = sphere_added_mass(v.rho_kg_m3, 0.15);
  std::vector<std::pair<std::string, CoefficientSurface>> surfaces;
  for (std::size_t dof = 0; dof < 6; ++dof) {
    const std::string name = std::string("s") + kAxes[dof][0];
    surfaces.emplace_back(name, damping_surface(kAxes[dof][0], kAxes[dof][1], std::string(kForceNames[dof]), method));
    v.damping[dof] = {DofDamping::Kind::Surface, {}, {}, name, std::string(kForceNames[dof]), {},
                      SignConvention::OnBody};
  }
  const VehicleModel model(v, [surfaces](const std::string& name) {
    for (const auto& [n, s] : surfaces)
      if (n == name) return s;
    throw std::runtime_error("no surface " + name);
  });
  std::vector<RuntimeSurface> runtime;
  for (const auto& [name, surface] : surfaces) runtime.push_back(runtime_surface(name, surface, {}));
  const RuntimeVehicle vehicle{&model, {{"name", "bench"}}};
  const std::string bytes = runtime_file_bytes(runtime_model_texts({}, true), runtime, &vehicle);
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
