// A simulated trajectory as rows of time, pose, velocity and the forces of the
// equation of motion, and its CSV form.
//
// CSV (one header line, then one row per sample; comma-separated; units in
// brackets as the force-table importer reads them):
//   t [s]; x_n, y_n, z_n [m] (CO in NED); phi, theta, psi [rad] (zyx Euler);
//   q_eta, q_eps1, q_eps2, q_eps3 (body-to-NED quaternion); u, v, w [m s^-1],
//   p, q, r [rad s^-1] (body velocity over ground); u_r ... r_r (relative to
//   the water); then X..N of each force term on the body (SNAME: damping is
//   negative), [N] and [N m]: *_control, *_damping, *_hydrostatic, *_coriolis.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "src/dynamics/vehicle_model.hpp"

namespace hydrocoef {

struct TrajectorySample {
  double t_s = 0.0;
  Vector3 p_n = Vector3::Zero();
  Quaternion4 q_nb = Quaternion4(1.0, 0.0, 0.0, 0.0);
  Vector3 euler_rad = Vector3::Zero();
  Vector6 nu_b = Vector6::Zero();
  ForceBreakdown forces;  ///< includes nu_r_b
};

/// The draws that failed: how many, and the first few messages ("draw 17: ...").
struct EnsembleFailures {
  std::size_t count = 0;
  std::vector<std::string> first;
};

/// Percentile bands of every state component over time.
struct TrajectoryBands {
  std::vector<double> t_s;
  /// x_n y_n z_n [m], phi theta psi [rad] (zyx Euler, unwrapped in time),
  /// u v w [m s^-1], p q r [rad s^-1]: as in the trajectory CSV.
  std::vector<std::string> quantities;
  std::vector<std::string> units;
  std::vector<double> percentiles;
  /// Percentile j of quantity q at time k: values[(q * percentiles + j) * times + k].
  std::vector<double> values;
  std::size_t samples = 0;  ///< trajectories that reached the end
  EnsembleFailures failures;

  double value(std::size_t quantity, std::size_t percentile, std::size_t time) const {
    return values[(quantity * percentiles.size() + percentile) * t_s.size() + time];
  }
  /// Index of a quantity by name; InputError listing them otherwise.
  std::size_t quantity_index(std::string_view name) const;
};

/// The sample of state x at time t under inputs (forces evaluated there).
TrajectorySample make_sample(const VehicleModel& model, double t_s, const StateVector& x, const ModelInputs& inputs);

/// The header line (without newline).
std::string trajectory_csv_header();
/// Writes the header and one row per sample, numbers in shortest round-trip
/// form; with bands (at the samples' times), their columns after the others.
void write_trajectory_csv(std::ostream& out, const std::vector<TrajectorySample>& samples,
                          const TrajectoryBands* bands = nullptr);
/// As above into a file; InputError naming the file when it cannot be written.
void write_trajectory_csv(const std::filesystem::path& path, const std::vector<TrajectorySample>& samples,
                          const TrajectoryBands* bands = nullptr);
/// "r_p5": the CSV column name of percentile P of a quantity.
std::string band_column(std::string_view quantity, double percentile);

}  // namespace hydrocoef
