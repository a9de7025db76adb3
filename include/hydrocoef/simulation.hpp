// The 6-DOF lookup-table dynamics model of a vehicle run through a scenario,
// as `hydrocoef simulate` runs it (Fossen 2011, eq. 6.1 with current: rigid
// body, added mass, damping from fitted laws or lookup surfaces, restoring
// forces; RK4 or Dormand-Prince). The vehicle and scenario file formats are
// described in the README and in examples/asr-v/.
//
// Frames and units: position of the body origin CO in NED (north, east, down)
// [m]; attitude as zyx Euler angles phi, theta, psi [rad] and as the
// body-to-NED quaternion; body velocity over ground u, v, w [m/s], p, q, r
// [rad/s] in body axes (x forward, y starboard, z down), and relative to the
// water (u_r ... r_r); forces of each term of the equation of motion on the
// body, in body axes about CO: X, Y, Z [N], K, M, N [N m] (a damping force is
// negative along the motion).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "hydrocoef/error.hpp"
#include "hydrocoef/export.hpp"

namespace hydrocoef {
inline namespace api {

/// A simulated trajectory: the columns of the CSV `hydrocoef simulate --out`
/// writes, in its order, as numbers.
struct HYDROCOEF_EXPORT Trajectory {
  /// Column names, the CSV header's without the units: t, x_n, y_n, z_n, phi,
  /// theta, psi, q_eta, q_eps1, q_eps2, q_eps3, u, v, w, p, q, r, u_r, v_r,
  /// w_r, p_r, q_r, r_r, then X_control ... N_control, X_damping ...
  /// N_damping, X_hydrostatic ... N_hydrostatic, X_coriolis ... N_coriolis.
  std::vector<std::string> columns;
  /// The unit of each column as the CSV header gives it ("s", "m", "rad",
  /// "m s^-1", "rad s^-1", "N", "N m"; "" for the quaternion).
  std::vector<std::string> units;
  std::size_t rows = 0;  ///< samples: t = 0, 1/output_rate, ..., and the end
  /// Column-major: values[c * rows + r] is column c at sample r.
  std::vector<double> values;
  /// What a user should know (a thrust command clamped to its limits, ...).
  std::vector<std::string> notes;

  /// The first value of a column; std::out_of_range naming the column when there is none of that name.
  const double* column(std::string_view name) const;
};

/// Runs a scenario on a vehicle. `vehicle_json` and `scenario_json` are each
/// a path to a JSON file, or the JSON text itself (a text whose first
/// non-blank character is '{', or that holds a newline). Surfaces the
/// vehicle's damping names are read from `database` (opened read-only, only
/// when one is named; "" : none, and a surface named is an InputError).
/// InputError for a file that cannot be read or parsed, a surface that is
/// missing or queried outside its range under policy "error", or a scenario
/// the integrator cannot run.
HYDROCOEF_EXPORT Trajectory simulate(const std::string& vehicle_json, const std::string& scenario_json,
                                     const std::string& database = "");

}  // namespace api
}  // namespace hydrocoef
