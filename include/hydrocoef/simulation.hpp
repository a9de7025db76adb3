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

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
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

/// Monte Carlo over the damping's uncertainty: each draw holds one sample of
/// the uncertain damping (laws from their covariance, GP surfaces from their
/// posterior) for the whole run. The options --samples, --seed,
/// --percentiles and --threads of `hydrocoef simulate` and `equilibrium`.
struct SamplingOptions {
  std::size_t samples = 0;          ///< draws; 0: no Monte Carlo, else at least 2
  std::uint64_t seed = 1;           ///< the same seed gives the same draws
  std::vector<double> percentiles;  ///< in (0, 100), increasing; empty: the operation's default
  unsigned threads = 0;             ///< 0: one per core
  /// Called after each finished draw (from any thread, one call at a time); may be empty.
  std::function<void(std::size_t done, std::size_t total)> progress;
};

/// What a Monte Carlo run drew and how it went.
struct MonteCarloSummary {
  std::size_t requested = 0;                ///< draws asked for
  std::size_t used = 0;                     ///< draws that reached the end
  std::size_t failed = 0;                   ///< draws that did not (the statistics are of the others)
  std::vector<std::string> first_failures;  ///< the first few failures' messages
  std::uint64_t seed = 0;
  std::vector<double> percentiles;
  std::vector<std::string> drawn;  ///< what was drawn ("law X of fit ...: 3 coefficients")
  std::vector<std::string> held;   ///< what was held at its nominal value, and why
  std::vector<std::string> notes;
  double wall_time_s = 0.0;
};

/// `hydrocoef simulate`'s options.
struct SimulateOptions {
  std::string vehicle;   ///< a vehicle JSON file, or the JSON text
  std::string scenario;  ///< a scenario JSON file, or the JSON text
  /// Where stored fits and surfaces the vehicle names are read from (a path
  /// or a postgresql:// URL, as --db); "" : none (naming one is an InputError).
  std::string database;
  std::string trajectory_csv;    ///< write the trajectory here ("" : not written); with samples, the bands too
  std::string experiment;        ///< a measured trajectory CSV to compare with ("" : none)
  double steady_fraction = 0.2;  ///< share of the compared record, at its end, taken as steady state: (0, 1]
  SamplingOptions sampling;      ///< percentiles default 5, 50, 95
  /// Called as the nominal run advances (simulated time, duration) [s]; may be empty.
  std::function<void(double t_s, double duration_s)> progress;

  /// InputError naming the option (as the CLI's --steady-fraction, --samples, --percentiles) when one is bad.
  void validate() const;
};

/// The simulated and measured record of one velocity component compared
/// (measured - simulated).
struct ExperimentComparison {
  std::string component;  ///< u..r
  std::size_t samples = 0;
  double rms_error = 0.0;  ///< [component unit]
  double steady_measured = 0.0;
  double steady_simulated = 0.0;
  double steady_error = 0.0;
  double t63_measured_s = 0.0;   ///< time to 63 % of the steady change; NaN when not reached
  double t63_simulated_s = 0.0;  ///< NaN when not reached
};

/// What `hydrocoef simulate` ran and got.
struct HYDROCOEF_EXPORT SimulationOutcome {
  Trajectory trajectory;  ///< the nominal run
  std::size_t steps = 0;
  std::size_t rejected_steps = 0;                ///< Dormand-Prince steps refused by the error control
  std::size_t evaluations = 0;                   ///< evaluations of the equations of motion
  double wall_time_s = 0.0;                      ///< of the nominal run
  std::vector<ExperimentComparison> comparison;  ///< empty without an experiment

  /// Monte Carlo (samples > 0): the bands of x_n y_n z_n [m], phi theta psi
  /// [rad], u v w [m/s], p q r [rad/s] over time.
  bool sampled = false;
  MonteCarloSummary monte_carlo;
  std::vector<double> band_t_s;              ///< the bands' times [s]
  std::vector<std::string> band_quantities;  ///< x_n ... r
  std::vector<std::string> band_units;
  /// Percentile j of quantity q at time k: band_values[(q * percentiles + j) * band_t_s.size() + k].
  std::vector<double> band_values;
  /// With an experiment: the share of each measured velocity component inside the outer band (NaN: undefined).
  std::map<std::string, double> measured_inside_band;

  /// What `hydrocoef simulate` prints; with json(), what `--json` prints.
  std::string text() const;
  std::string json() const;

  struct Access;  ///< the library's own

 private:
  std::string text_;
  std::string json_;
};

/// Runs a scenario as `hydrocoef simulate` does: the nominal trajectory, the
/// comparison with a measured one, the Monte Carlo bands. InputError as
/// simulate() above, or for a bad option (validate()).
HYDROCOEF_EXPORT SimulationOutcome simulate(const SimulateOptions& options);

/// `hydrocoef equilibrium`'s options: a constant force on the body, the attitude held.
struct EquilibriumOptions {
  std::string vehicle;   ///< a vehicle JSON file, or the JSON text
  std::string database;  ///< as SimulateOptions::database
  /// Force on the body by component, X Y Z [N], K M N [N m], in body axes (absent: 0).
  std::map<std::string, double> tau;
  /// Water velocity u, v, w [m/s] in body axes (absent: 0).
  std::map<std::string, double> current;
  /// Disturbance parameters the vehicle's surfaces read [SI] (absent: 0).
  std::map<std::string, double> disturbances;
  std::array<double, 3> attitude_deg{0.0, 0.0, 0.0};  ///< roll, pitch, yaw held [deg]
  SamplingOptions sampling;                           ///< percentiles default 2.5, 50, 97.5 (the 95 % interval)

  /// InputError naming the option (--tau, --current, --attitude-deg, --samples, ...) when one is bad.
  void validate() const;
};

/// The steady state `hydrocoef equilibrium` finds. Arrays in u..r / X..N order.
struct HYDROCOEF_EXPORT EquilibriumOutcome {
  std::array<double, 6> tau{};                ///< the force applied [N, N m]
  std::array<double, 6> velocity{};           ///< over ground, body axes [m/s, rad/s]
  std::array<double, 6> relative_velocity{};  ///< relative to the water
  std::array<double, 6> damping{};            ///< damping force there [N, N m]
  std::array<double, 6> residual{};           ///< what is left of the balance [N, N m]
  std::size_t iterations = 0;
  double continuation_s = 0.0;  ///< > 0 when it started from where a simulation of this long got to

  /// Monte Carlo (samples > 0): the steady velocity over the draws.
  bool sampled = false;
  MonteCarloSummary monte_carlo;
  std::array<double, 6> mean{};
  std::array<double, 6> standard_deviation{};               ///< sample standard deviation (n - 1)
  std::vector<std::array<double, 6>> velocity_percentiles;  ///< one per monte_carlo.percentiles entry

  std::string text() const;
  std::string json() const;

  struct Access;  ///< the library's own

 private:
  std::string text_;
  std::string json_;
};

/// Solves the steady velocity as `hydrocoef equilibrium` does. InputError for
/// a bad option, a file that cannot be read, a disturbance the vehicle's
/// surfaces do not read, or a force no steady state balances.
HYDROCOEF_EXPORT EquilibriumOutcome equilibrium(const EquilibriumOptions& options);

}  // namespace api
}  // namespace hydrocoef
