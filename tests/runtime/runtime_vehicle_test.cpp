// libhydrocoef_runtime's vehicle is the C++ library's dynamics model, bit for
// bit: vehicles whose damping uses each kind (laws of every term, derivative
// models with cross terms and a disturbance, surfaces of several methods and
// policies with axes bound to velocities and to disturbances, two DOFs
// sharing one surface, opposing signs), written by runtime_file_bytes and
// opened through the C API. At 10^4 random states, with and without a
// current, hc_runtime_vehicle_derivative equals VehicleModel::derivative and
// hc_runtime_vehicle_forces equals VehicleModel::forces as bit patterns;
// stepping through hc_runtime_vehicle_step_rk4 as simulate steps gives
// simulate_model's trajectory bit for bit (the ASR-V pool test of
// examples/asr-v, and a vehicle of surfaces in a current with thrusters and a
// disturbance); a state a surface refuses gives the library's message and
// code, nothing written.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "hydrocoef/runtime.h"
#include "src/core/error.hpp"
#include "src/dynamics/scenario.hpp"
#include "src/dynamics/simulation.hpp"
#include "src/dynamics/vehicle.hpp"
#include "src/dynamics/vehicle_model.hpp"
#include "src/export/runtime_export.hpp"
#include "src/surface/coefficient_surface.hpp"
#include "src/surface/grid_table.hpp"
#include "tests/runtime/runtime_stepping.hpp"
#include "tests/support/same_bits.hpp"

namespace hydrocoef {
namespace {

using test::same_bits;

struct ModelCloser {
  void operator()(hc_runtime_model* model) const { hc_runtime_close(model); }
};
using Model = std::unique_ptr<hc_runtime_model, ModelCloser>;

using Surfaces = std::map<std::string, CoefficientSurface>;

// A surface over `axes` (name, limit, policy) with `outputs`: a damping-like
// value -(0.5 x + 10 x|x|)(1 + 0.3 y^2 + 0.1 z) of the first axis x, the
// second y and the third z, scaled per output, plus a wrinkle so that the
// cubic methods' slopes differ from linear's.
CoefficientSurface surface(const std::vector<std::tuple<std::string, double, Extrapolation>>& axes,
                           const std::vector<std::string>& outputs, Interpolation method) {
  std::vector<GridAxis> grid;
  std::size_t nodes = 1;
  for (const auto& [name, limit, policy] : axes) {
    std::vector<double> b;
    const std::size_t count = axes.size() == 1 ? 11 : (axes.size() == 2 ? 7 : 5);
    for (std::size_t i = 0; i < count; ++i) {
      const double t = static_cast<double>(i) / static_cast<double>(count - 1);
      b.push_back(-limit + 2.0 * limit * (t + (i == 1 ? 0.03 : 0.0)));
    }
    grid.push_back({name, b, policy});
    nodes *= b.size();
  }
  std::vector<double> values;
  for (std::size_t node = 0; node < nodes; ++node) {
    std::size_t rest = node;
    std::array<double, 3> x{};
    for (std::size_t a = 0; a < grid.size(); ++a) {
      x[a] = grid[a].breakpoints[rest % grid[a].breakpoints.size()];
      rest /= grid[a].breakpoints.size();
    }
    for (std::size_t k = 0; k < outputs.size(); ++k)
      values.push_back(-(0.5 * x[0] + 10.0 * x[0] * std::abs(x[0])) * (1.0 + 0.3 * x[1] * x[1] + 0.1 * x[2]) /
                           static_cast<double>(k + 1) +
                       0.01 * std::sin(7.0 * static_cast<double>(node + k)));
  }
  return CoefficientSurface(GridTable(grid, outputs, values, method));
}

// The vehicles: ASR-V's mass properties and thrusters with each kind of damping.
const char* kBody = R"({
  "name": "test vehicle",
  "mass": 6.7, "inertia": [[0.0603, 0.001, 0.0], [0.001, 0.07, 0.002], [0.0, 0.002, 0.065]],
  "center_of_gravity": [0.003, -0.001, 0.02], "center_of_buoyancy": [0.0, 0.001, -0.002],
  "buoyancy_force": 66.0,
  "added_mass": {"matrix": [[7.06, 0, 0.1, 0, 0.05, 0], [0, 7.5, 0, -0.1, 0, 0.02], [0.1, 0, 8.0, 0, 0, 0],
                            [0, -0.1, 0, 0.02, 0, 0], [0.05, 0, 0, 0, 0.03, 0], [0, 0.02, 0, 0, 0, 0.025]]},
  "thrusters": [
    {"name": "port", "position": [-0.06, -0.12, 0.05], "direction": [1, 0, 0], "min_thrust": -1.0, "max_thrust": 1.0},
    {"name": "starboard", "position": [-0.06, 0.12, 0.05], "direction": [0.96, 0.28, 0], "min_thrust": -1.0, "max_thrust": 1.0},
    {"name": "vertical", "position": [0.0, 0.0, -0.1], "direction": [0, 0, 1], "min_thrust": -2.0, "max_thrust": 2.0}
  ],
  "damping": )";

struct Vehicle {
  std::string name;
  std::string damping;  // the JSON object
  std::vector<std::string> surfaces;
};

const std::vector<Vehicle>& vehicles() {
  static const std::vector<Vehicle> all = {
      {"laws",
       R"({"X": {"law": {"1": 0.01, "u": -0.0155, "u|u|": -11.0365}, "sign": "on-body"},
           "Y": {"law": {"v": 0.02, "v^2": 1.5, "v^3": 4.0}, "sign": "opposing"},
           "Z": {"law": {"w": -0.5, "|w|": -0.2, "w^3": -3.0}, "sign": "on-body"},
           "K": {"law": {"p": -0.006, "p|p|": -0.077}, "sign": "on-body"},
           "M": {"law": {"1": -0.001, "q": -0.006, "q|q|": -0.077, "q^2": 0.01, "q^3": -0.02, "|q|": 0.003}, "sign": "on-body"},
           "N": {"law": {"r": 0.006, "r|r|": 0.0771}, "sign": "opposing"}})",
       {}},
      {"derivatives",
       R"({"X": {"derivatives": {"terms": "u, u*|u|, v^2, r^2, u*v*r", "coefficients": [-0.5, -11.0, -2.0, -0.3, 0.7]}, "sign": "on-body"},
           "Y": {"derivatives": {"terms": "v, r, v*|v|, u*v, u*r, v^2*r, wave", "coefficients": [-3.0, 0.2, -9.0, -1.1, 0.4, -0.5, 0.8]}, "sign": "on-body"},
           "Z": {"law": {"w": -0.5, "w|w|": -11.0}, "sign": "on-body"},
           "K": {"derivatives": {"terms": "p, p*|p|, wave*p", "coefficients": [0.006, 0.08, 0.01]}, "sign": "opposing"},
           "N": {"derivatives": {"terms": "r, r*|r|, v*r, u*r, wave^2, |v|*r", "coefficients": [-0.006, -0.077, -0.1, -0.02, 0.003, -0.05]}, "sign": "on-body"}})",
       {}},
      {"surfaces",
       R"({"X": {"surface": "sx", "output": "X", "axes": {"u": "u", "v": "v"}, "allow_unphysical": true, "sign": "on-body"},
           "Y": {"surface": "syn", "output": "Y", "axes": {"v": "v", "r": "r"}, "allow_unphysical": true, "sign": "on-body"},
           "N": {"surface": "syn", "output": "N", "axes": {"v": "v", "r": "r"}, "sign": "opposing", "allow_unphysical": true},
           "Z": {"surface": "sz", "output": "Z", "allow_unphysical": true, "sign": "on-body"},
           "K": {"surface": "sk", "output": "K", "axes": {"p": "p", "c": "current_v", "h": "wave"}, "allow_unphysical": true, "sign": "on-body"},
           "M": {"surface": "sm", "output": "M", "allow_unphysical": true, "sign": "on-body"}})",
       {"sx", "syn", "sz", "sk", "sm"}},
      {"mixed",
       R"({"X": {"surface": "sx", "output": "X", "axes": {"u": "u", "v": "v"}, "allow_unphysical": true, "sign": "on-body"},
           "Y": {"derivatives": {"terms": "v, v*|v|, u*v, wave", "coefficients": [-3.0, -9.0, -1.1, 0.2]}, "sign": "on-body"},
           "Z": {"law": {"w": -0.5, "w|w|": -11.0}, "sign": "on-body"},
           "M": {"surface": "sm", "output": "M", "allow_unphysical": true, "sign": "on-body"},
           "N": {"surface": "sn", "output": "N", "axes": {"r": "r", "u": "wave"}, "allow_unphysical": true, "sign": "on-body"}})",
       {"sx", "sm", "sn"}},
  };
  return all;
}

// The surfaces the vehicles read: linear, pchip, makima, natural spline and
// nearest; policies clamp, linear, method and error (on a wide range).
const Surfaces& surfaces() {
  static const Surfaces all = {
      {"sx",
       surface({{"u", 1.5, Extrapolation::Linear}, {"v", 0.8, Extrapolation::Clamp}}, {"X"}, Interpolation::Linear)},
      {"syn", surface({{"v", 1.0, Extrapolation::Method}, {"r", 1.5, Extrapolation::Linear}}, {"Y", "N", "K"},
                      Interpolation::Pchip)},
      {"sz", surface({{"w", 1.0, Extrapolation::Linear}}, {"Z"}, Interpolation::Pchip)},
      {"sk",
       surface({{"p", 2.0, Extrapolation::Clamp}, {"c", 0.5, Extrapolation::Clamp}, {"h", 1.0, Extrapolation::Linear}},
               {"K"}, Interpolation::NaturalSpline)},
      {"sm", surface({{"q", 4.0, Extrapolation::Error}}, {"M"}, Interpolation::Nearest)},
      {"sn",
       surface({{"r", 1.5, Extrapolation::Method}, {"u", 1.0, Extrapolation::Clamp}}, {"N"}, Interpolation::Akima)},
  };
  return all;
}

SurfaceResolver resolver() {
  return [](const std::string& name) {
    const auto it = surfaces().find(name);
    if (it == surfaces().end()) throw InputError("no surface " + name);
    return it->second;
  };
}

VehicleModel vehicle_model(const Vehicle& v) {
  return VehicleModel(parse_vehicle(std::string(kBody) + v.damping + "}", v.name + ".json"), resolver());
}

std::string file_bytes(const VehicleModel& model, const std::vector<std::string>& names) {
  std::vector<RuntimeSurface> runtime;
  for (const auto& name : names) runtime.push_back(runtime_surface(name, surfaces().at(name), {}));
  const RuntimeVehicle vehicle{&model, {{"name", model.description().name}, {"file", model.description().file}}};
  return runtime_file_bytes(runtime_model_texts({{"body", "test"}}, true), runtime, &vehicle);
}

Model open_bytes(const std::string& bytes) {
  hc_runtime_model* model = nullptr;
  char err[512] = "";
  EXPECT_EQ(hc_runtime_open_memory(bytes.data(), bytes.size(), &model, err, sizeof err), HC_RUNTIME_OK) << err;
  return Model(model);
}

// A random state: a position, an attitude of norm near 1 (as between the
// steps' normalisations), velocities in the surfaces' ranges and beyond.
StateVector random_state(std::mt19937_64& random) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  StateVector x;
  for (int i = 0; i < 3; ++i) x[i] = 10.0 * unit(random);
  Quaternion4 q(unit(random), unit(random), unit(random), unit(random));
  q /= q.norm();
  q *= 1.0 + 1e-6 * unit(random);
  x.segment<4>(3) = q;
  for (int i = 0; i < 3; ++i) x[7 + i] = 1.6 * unit(random);
  for (int i = 3; i < 6; ++i) x[7 + i] = 2.2 * unit(random);
  return x;
}

TEST(RuntimeVehicle, DerivativeAndForcesAreTheLibrarysBitForBit) {
  std::mt19937_64 random(37);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const Vehicle& v : vehicles()) {
    SCOPED_TRACE(v.name);
    const VehicleModel model = vehicle_model(v);
    const Model runtime = open_bytes(file_bytes(model, v.surfaces));
    ASSERT_TRUE(runtime);
    ASSERT_EQ(hc_runtime_has_vehicle(runtime.get()), 1);
    const auto& names = model.disturbance_names();
    ASSERT_EQ(hc_runtime_vehicle_disturbance_count(runtime.get()), names.size());
    for (std::size_t i = 0; i < names.size(); ++i)
      EXPECT_EQ(hc_runtime_vehicle_disturbance_name(runtime.get(), i), names[i]);
    EXPECT_STREQ(hc_runtime_vehicle_metadata(runtime.get(), "name"), "test vehicle");
    for (const auto& [key, fragment] :
         std::vector<std::pair<std::string, std::string>>{{"state", "quaternion, scalar first"},
                                                          {"inputs", "current_n, the water velocity in NED"},
                                                          {"equation", "forces on the body"}})
      EXPECT_NE(std::string(hc_runtime_vehicle_metadata(runtime.get(), key.c_str())).find(fragment), std::string::npos)
          << key;
    std::size_t mismatches = 0, refused = 0;
    for (int n = 0; n < 10000; ++n) {
      const StateVector x = random_state(random);
      ModelInputs inputs;
      for (int i = 0; i < 6; ++i) inputs.tau_b[i] = unit(random);
      if (n % 2 == 1) inputs.current_n = Vector3(0.4 * unit(random), 0.4 * unit(random), 0.1 * unit(random));
      std::vector<double> disturbances(names.size());
      for (double& d : disturbances) d = 1.2 * unit(random);
      inputs.disturbances = disturbances;
      StateVector expected;
      std::string library_error;
      try {
        model.derivative(x, inputs, expected);
      } catch (const InputError& e) {
        library_error = e.what();
      }
      double x_dot[13];
      char err[256] = "";
      const double* current = n % 4 == 0 ? nullptr : inputs.current_n.data();
      const int status = hc_runtime_vehicle_derivative(runtime.get(), x.data(), inputs.tau_b.data(), current,
                                                       disturbances.data(), x_dot, err, sizeof err);
      if (!library_error.empty()) {
        ++refused;
        EXPECT_EQ(status, HC_RUNTIME_E_OUTSIDE);
        EXPECT_EQ(err, library_error);
        continue;
      }
      ASSERT_EQ(status, HC_RUNTIME_OK) << err;
      for (int i = 0; i < 13; ++i) mismatches += !same_bits(x_dot[i], expected[i]);
      if (n % 10 == 0) {
        const ForceBreakdown f = model.forces(x, inputs);
        double breakdown[30];
        ASSERT_EQ(hc_runtime_vehicle_forces(runtime.get(), x.data(), inputs.tau_b.data(), inputs.current_n.data(),
                                            disturbances.data(), breakdown, err, sizeof err),
                  HC_RUNTIME_OK);
        for (int i = 0; i < 6; ++i) {
          mismatches += !same_bits(breakdown[i], f.control_b[i]);
          mismatches += !same_bits(breakdown[6 + i], f.damping_b[i]);
          mismatches += !same_bits(breakdown[12 + i], f.hydrostatic_b[i]);
          mismatches += !same_bits(breakdown[18 + i], f.coriolis_b[i]);
          mismatches += !same_bits(breakdown[24 + i], f.nu_r_b[i]);
        }
      }
    }
    EXPECT_EQ(mismatches, 0u);
    // Only the surface of policy "error" (q beyond 4 rad/s) refuses, and the random states stay inside.
    EXPECT_EQ(refused, 0u);
  }
}

// One model, four threads at once: each thread's derivatives are the
// library's (the model is read-only; the suite runs under ASan).
TEST(RuntimeVehicle, ThreadsShareOneModel) {
  const Vehicle& v = vehicles()[3];
  const VehicleModel model = vehicle_model(v);
  const Model runtime = open_bytes(file_bytes(model, v.surfaces));
  std::vector<StateVector> states;
  std::vector<StateVector> expected;
  std::mt19937_64 random(11);
  const std::vector<double> disturbances(model.disturbance_names().size(), 0.2);
  ModelInputs inputs;
  inputs.current_n = Vector3(0.1, -0.2, 0.0);
  inputs.disturbances = disturbances;
  for (int n = 0; n < 2000; ++n) {
    states.push_back(random_state(random));
    expected.emplace_back();
    model.derivative(states.back(), inputs, expected.back());
  }
  std::array<std::size_t, 4> mismatches{};
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < mismatches.size(); ++t)
    threads.emplace_back([&, t] {
      for (std::size_t n = t; n < states.size(); n += 1 + t % 2) {
        double x_dot[13];
        if (hc_runtime_vehicle_derivative(runtime.get(), states[n].data(), inputs.tau_b.data(), inputs.current_n.data(),
                                          disturbances.data(), x_dot, nullptr, 0) != HC_RUNTIME_OK) {
          ++mismatches[t];
          continue;
        }
        for (int i = 0; i < 13; ++i) mismatches[t] += !same_bits(x_dot[i], expected[n][i]);
      }
    });
  for (std::thread& thread : threads) thread.join();
  for (const std::size_t m : mismatches) EXPECT_EQ(m, 0u);
}

TEST(RuntimeVehicle, ThrustersAreTheLibrarys) {
  const VehicleModel model = vehicle_model(vehicles()[0]);
  const Model runtime = open_bytes(file_bytes(model, {}));
  ASSERT_EQ(hc_runtime_vehicle_thruster_count(runtime.get()), 3u);
  EXPECT_STREQ(hc_runtime_vehicle_thruster_name(runtime.get(), 1), "starboard");
  double lo = 0.0, hi = 0.0;
  ASSERT_EQ(hc_runtime_vehicle_thruster_limits(runtime.get(), 2, &lo, &hi), HC_RUNTIME_OK);
  EXPECT_EQ(lo, -2.0);
  EXPECT_EQ(hi, 2.0);
  EXPECT_EQ(hc_runtime_vehicle_thruster_limits(runtime.get(), 3, &lo, &hi), HC_RUNTIME_E_ARGUMENT);
  const std::vector<double> thrust = {0.3, -0.7, 1.1};
  const Vector6 expected = model.thrust_force(thrust);
  double tau[6];
  ASSERT_EQ(hc_runtime_vehicle_thrust_force(runtime.get(), thrust.data(), tau), HC_RUNTIME_OK);
  for (int i = 0; i < 6; ++i) EXPECT_TRUE(same_bits(tau[i], expected[i])) << i;
}

// A state outside a surface's "error" range: the library's refusal, as a
// code and its message, and nothing written; a NaN velocity likewise.
TEST(RuntimeVehicle, ARefusedStateGivesTheLibrarysMessage) {
  const VehicleModel model = vehicle_model(vehicles()[2]);
  const Model runtime = open_bytes(file_bytes(model, vehicles()[2].surfaces));
  std::vector<double> disturbances(model.disturbance_names().size(), 0.1);
  ModelInputs inputs;
  inputs.disturbances = disturbances;
  for (const double q : {4.5, std::nan(""), 0.1 + 4.0 * 1.25, 4.000000000000001, -123456.789, 1e22, -3e300,
                         -std::numeric_limits<double>::infinity(), 100000.0, -4.5}) {
    StateVector x = make_state(Vector3::Zero(), Quaternion4(1, 0, 0, 0), Vector6::Zero());
    x[state_index::kVelocity + 4] = q;
    std::string expected;
    try {
      StateVector unused;
      model.derivative(x, inputs, unused);
    } catch (const InputError& e) {
      expected = e.what();
    }
    ASSERT_FALSE(expected.empty());
    double x_dot[13];
    std::fill(std::begin(x_dot), std::end(x_dot), 42.0);
    char err[256] = "";
    const int status = hc_runtime_vehicle_derivative(runtime.get(), x.data(), inputs.tau_b.data(), nullptr,
                                                     disturbances.data(), x_dot, err, sizeof err);
    EXPECT_EQ(status, std::isfinite(q) ? HC_RUNTIME_E_OUTSIDE : HC_RUNTIME_E_NOT_FINITE);
    EXPECT_EQ(err, expected);
    for (const double value : x_dot) EXPECT_EQ(value, 42.0);
    StateVector stepped = x;
    EXPECT_EQ(hc_runtime_vehicle_step_rk4(runtime.get(), stepped.data(), inputs.tau_b.data(), nullptr,
                                          disturbances.data(), 0.01, err, sizeof err),
              status);
    for (int i = 0; i < 13; ++i) EXPECT_TRUE(same_bits(stepped[i], x[i]));
  }
  // Arguments: no disturbances for a vehicle that reads some; no vehicle in a file of surfaces.
  double x[13] = {0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0}, tau[6] = {}, x_dot[13];
  char err[256] = "";
  EXPECT_EQ(hc_runtime_vehicle_derivative(runtime.get(), x, tau, nullptr, nullptr, x_dot, err, sizeof err),
            HC_RUNTIME_E_ARGUMENT);
  EXPECT_NE(std::string(err).find("disturbances"), std::string::npos) << err;
  EXPECT_EQ(hc_runtime_vehicle_derivative(nullptr, x, tau, nullptr, nullptr, x_dot, err, sizeof err),
            HC_RUNTIME_E_ARGUMENT);
  const std::string plain =
      runtime_file_bytes(runtime_model_texts({}), {runtime_surface("sm", surfaces().at("sm"), {})});
  const Model surfaces_only = open_bytes(plain);
  EXPECT_EQ(hc_runtime_has_vehicle(surfaces_only.get()), 0);
  EXPECT_EQ(hc_runtime_vehicle_derivative(surfaces_only.get(), x, tau, nullptr, nullptr, x_dot, err, sizeof err),
            HC_RUNTIME_E_NO_VEHICLE);
  EXPECT_EQ(hc_runtime_vehicle_step_rk4(surfaces_only.get(), x, tau, nullptr, nullptr, 0.01, nullptr, 0),
            HC_RUNTIME_E_NO_VEHICLE);
}

TEST(RuntimeVehicle, AsrVPoolTestStepsAsSimulate) {
  VehicleDescription description = load_vehicle(HYDROCOEF_SOURCE_DIR "/examples/asr-v/vehicle.json");
  const VehicleModel model(std::move(description));
  const Model runtime = open_bytes(file_bytes(model, {}));
  Scenario scenario = load_scenario(HYDROCOEF_SOURCE_DIR "/examples/asr-v/scenario-yaw-0.0027.json");
  scenario.duration_s = 20.0;  // the yaw rate is near its root by then
  expect_simulate_bit_for_bit(model, runtime.get(), scenario);
}

TEST(RuntimeVehicle, SurfacesInACurrentStepAsSimulate) {
  for (const std::size_t which : {std::size_t{2}, std::size_t{3}, std::size_t{1}}) {
    const Vehicle& v = vehicles()[which];
    SCOPED_TRACE(v.name);
    const VehicleModel model = vehicle_model(v);
    const Model runtime = open_bytes(file_bytes(model, v.surfaces));
    const Scenario scenario = parse_scenario(R"({
      "duration": 3.0, "output_rate": 10.0, "integrator": {"method": "rk4", "step": 0.004},
      "initial": {"euler_deg": [3, -2, 20], "velocity": [0.3, 0.05, 0.0, 0.0, 0.01, 0.1]},
      "segments": [{"start": 0.0, "tau": {"N": 0.01, "Y": 0.05}, "thrusters": [0.4, 0.6, -0.3],
                    "current": [0.1, -0.05, 0.01], "disturbances": {"wave": 0.3}}]})",
                                             "current.json");
    expect_simulate_bit_for_bit(model, runtime.get(), scenario);
  }
}

}  // namespace
}  // namespace hydrocoef
