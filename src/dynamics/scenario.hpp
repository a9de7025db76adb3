// A simulation scenario read from a JSON file: initial state, piecewise-
// constant inputs (generalized force, thruster commands, current, disturbance
// parameters), duration, output rate and integrator.
//
// File format (JSON; // comments allowed; SI units; forces on the body in body
// axes about CO, NED for positions and the current):
//   {
//     "name": "yaw-0.0027",                      optional
//     "notes": "...",                            optional
//     "duration": 60.0,                          s, > 0
//     "output_rate": 10.0,                       Hz, > 0: rows of the trajectory
//     "integrator": {"method": "rk4", "step": 0.001}                       (default: rk4, 1 ms)
//                 | {"method": "dopri5", "rtol": 1e-9, "atol": 1e-12, "max_step": 0.1},
//     "initial": {"position": [x, y, z],  m NED, optional (0)
//                 "euler_deg": [phi, theta, psi] | "euler_rad": [...],  optional (0)
//                 "velocity": [u, v, w, p, q, r]},  m/s, rad/s, optional (0)
//     "segments": [                              in increasing "start"; the first at 0
//       {"start": 0.0,                           s
//        "tau": {"N": 0.0027},                   commanded force on the body: keys X..N [N, N m]
//        "thrusters": [0.1, -0.1, 0.1, -0.1] | {"port-fore": 0.1, ...},  thrust [N] by vehicle order or name
//        "current": [vx, vy, vz],                water velocity in NED [m/s]
//        "disturbances": {"current_v": 0.05}}    surface disturbance parameters [SI]
//     ]
//   }
// A segment holds from its start to the next one's (or the end); whatever a
// segment leaves out is zero during it. Thrust commands outside a thruster's
// limits are clamped (and reported by the simulation).
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "src/dynamics/rigid_body.hpp"

namespace hydrocoef {

struct ScenarioSegment {
  double start_s = 0.0;
  Vector6 tau_b = Vector6::Zero();                 ///< commanded generalized force on the body [N, N m]
  std::vector<double> thrust_N;                    ///< thrust per thruster in vehicle order [N] (an array)
  std::map<std::string, double> thrust_by_name_N;  ///< thrust by thruster name [N] (an object)
  Vector3 current_n = Vector3::Zero();             ///< [m/s]
  std::map<std::string, double> disturbances;
};

struct IntegratorSettings {
  enum class Method { Rk4, DormandPrince45 };
  Method method = Method::Rk4;
  double step_s = 1e-3;  ///< RK4 step
  double relative_tolerance = 1e-9;
  double absolute_tolerance = 1e-12;
  double max_step_s = 0.1;
};

struct Scenario {
  std::string name;
  std::string notes;
  std::string file;
  double duration_s = 0.0;
  double output_rate_Hz = 10.0;
  IntegratorSettings integrator;
  Vector3 initial_position_n = Vector3::Zero();
  Vector3 initial_euler_rad = Vector3::Zero();  ///< zyx (phi, theta, psi)
  Vector6 initial_nu_b = Vector6::Zero();
  std::vector<ScenarioSegment> segments;  ///< at least one; the first starts at 0
};

/// Parses a scenario (format in the file comment). InputError "FILE: key
/// 'PATH': found ..., expected ..." for a syntax error, a missing or unknown
/// key, a wrong type, a non-positive duration, rate or step, segments that do
/// not start at 0 or are not increasing, an unknown integrator method.
Scenario parse_scenario(std::string_view json_text, const std::string& file);
Scenario load_scenario(const std::filesystem::path& path);

}  // namespace hydrocoef
