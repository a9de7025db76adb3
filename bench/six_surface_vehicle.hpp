// bench_simulate's vehicle, shared by the benchmarks that step it
// (bench/simulate.cpp, bench/runtime_vehicle.cpp, bench/fmu_vehicle.cpp): an ASR-V-like sphere
// (6.7 kg, neutrally buoyant, CG 2 cm below the centre, the sphere's added
// mass) whose six DOFs are each damped by a 2-D gridded surface (20 x 20)
// over its own velocity and a cross velocity: six separate surfaces, so six
// breakpoint searches per derivative. Inputs: a turning command in a
// current.
#pragma once

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "src/dynamics/rigid_body.hpp"
#include "src/dynamics/vehicle_model.hpp"
#include "src/export/runtime_export.hpp"

namespace hydrocoef::bench {

inline std::vector<double> breakpoints(double limit) {
  std::vector<double> b;
  for (int i = 0; i < 20; ++i) b.push_back(-limit + 2.0 * limit * i / 19.0);
  return b;
}

inline double velocity_limit(const std::string& name) { return name == "u" || name == "v" || name == "w" ? 1.0 : 2.0; }

// Damping on the body of DOF `dof` over (own velocity x, cross velocity y):
// -(k1 x + k2 x|x|)(1 + 0.3 y^2), outputs as many as `outputs` (output k
// the law over k + 1).
inline CoefficientSurface damping_surface(const std::string& x, const std::string& y, std::vector<std::string> outputs,
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

inline VehicleDescription asr_v_like() {
  VehicleDescription v;
  v.mass_kg = 6.7;
  v.inertia_cg_b = Matrix3::Identity() * 0.0603;
  v.r_g_b = Vector3(0.0, 0.0, 0.02);
  v.buoyancy_N = v.mass_kg * v.gravity_m_s2;
  v.added_mass_b = sphere_added_mass(v.rho_kg_m3, 0.15);
  return v;
}

// (own axis, cross axis) for X..N.
inline constexpr std::array<std::array<const char*, 2>, 6> kAxes{
    {{"u", "v"}, {"v", "u"}, {"w", "u"}, {"p", "v"}, {"q", "w"}, {"r", "u"}}};

// The vehicle's description and its six surfaces ("su", "sv", ... by name).
struct SixSurfaceVehicle {
  VehicleDescription description;
  std::vector<std::pair<std::string, CoefficientSurface>> surfaces;
};

inline SixSurfaceVehicle six_surface_vehicle(Interpolation method) {
  SixSurfaceVehicle out{asr_v_like(), {}};
  for (std::size_t dof = 0; dof < 6; ++dof) {
    const std::string name = std::string("s") + kAxes[dof][0];
    out.surfaces.emplace_back(name,
                              damping_surface(kAxes[dof][0], kAxes[dof][1], {std::string(kForceNames[dof])}, method));
    out.description.damping[dof] = {DofDamping::Kind::Surface, {}, {}, name, std::string(kForceNames[dof]), {},
                                    SignConvention::OnBody};
  }
  return out;
}

inline VehicleModel six_surface_model(const SixSurfaceVehicle& vehicle) {
  return VehicleModel(vehicle.description, [surfaces = vehicle.surfaces](const std::string& name) {
    for (const auto& [n, s] : surfaces)
      if (n == name) return s;
    throw std::runtime_error("no surface " + name);
  });
}

inline VehicleModel six_surface_model(Interpolation method) { return six_surface_model(six_surface_vehicle(method)); }

// A turning command in a current.
inline ModelInputs turning_inputs() {
  ModelInputs in;
  in.tau_b << 0.5, 0.1, 0.0, 0.0, 0.0, 0.003;
  in.current_n = Vector3(0.05, 0.02, 0.0);
  return in;
}

// The vehicle and its six surfaces as a runtime file (src/export/runtime_export.hpp), with the model's texts
// `given` (bench/runtime_vehicle.cpp, bench/fmu_vehicle.cpp).
inline std::string six_surface_runtime_bytes(Interpolation method, RuntimeTexts given) {
  const SixSurfaceVehicle vehicle_and_surfaces = six_surface_vehicle(method);
  const VehicleModel model = six_surface_model(vehicle_and_surfaces);
  std::vector<RuntimeSurface> runtime;
  for (const auto& [name, surface] : vehicle_and_surfaces.surfaces)
    runtime.push_back(runtime_surface(name, surface, {}));
  const RuntimeVehicle vehicle{&model, {{"name", "bench"}}};
  return runtime_file_bytes(runtime_model_texts(std::move(given), true), runtime, &vehicle);
}

}  // namespace hydrocoef::bench
