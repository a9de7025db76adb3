// A measured trajectory (e.g. a pool test) compared with a simulation, as the
// ASR-V paper compares its constant-torque yaw tests: per velocity component
// the RMS error over the record, the steady-state error and the time to 63 %
// of the step response.
//
// Measured CSV: comma, tab or semicolon separated; '#' starts a comment line;
// one header line naming a time column "t" or "time" and any velocity
// components "u", "v", "w", "p", "q", "r", each with an optional unit in
// brackets ("t [s]", "r [deg s^-1]"; no unit means SI); other columns are
// ignored, except percentile bands "r_p5" of `simulate --samples`. Times are on the scenario's clock (t = 0 when the
// scenario starts) and must increase.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "src/dynamics/trajectory.hpp"

namespace hydrocoef {

struct MeasuredTrajectory {
  std::string file;
  std::vector<double> t_s;
  /// Per component u..r, SI; empty when the file has no such column.
  std::array<std::vector<double>, 6> nu_b;
  /// Percentile bands of a Monte Carlo simulation (columns such as "r_p5",
  /// src/dynamics/trajectory.hpp), per component u..r: (percentile, values),
  /// percentiles increasing; empty when the file has none.
  std::array<std::vector<std::pair<double, std::vector<double>>>, 6> bands_b;
};

/// InputError "FILE:LINE:COLUMN: ..." for a missing time or velocity column,
/// a unit of the wrong kind, a number that does not parse, a repeated column,
/// fewer than 2 rows or times that do not increase.
MeasuredTrajectory parse_measured_trajectory(std::string_view text, const std::string& file);
MeasuredTrajectory read_measured_trajectory(const std::filesystem::path& path);

struct ComparisonOptions {
  /// The steady state is the mean over the last fraction of the compared time span.
  double steady_fraction = 0.2;
};

/// Measured minus simulated, for one velocity component [m/s or rad/s].
struct ComponentComparison {
  std::string component;    ///< "u" .. "r"
  std::size_t samples = 0;  ///< measured rows inside the simulated time span
  double rms_error = 0.0;   ///< sqrt(mean((measured - simulated)^2)), simulation interpolated linearly
  double steady_measured = 0.0;
  double steady_simulated = 0.0;
  double steady_error = 0.0;  ///< steady_measured - steady_simulated
  /// Time from the first compared sample until the response first covers
  /// 1 - 1/e (63.2 %) of its change to the steady value [s]; NaN when it
  /// does not change or never gets there.
  double t63_measured_s = 0.0;
  double t63_simulated_s = 0.0;
};

/// Compares every component the measured record has. InputError when no
/// measured time falls inside the simulation's time span.
std::vector<ComponentComparison> compare_with_experiment(const MeasuredTrajectory& measured,
                                                         const std::vector<TrajectorySample>& simulated,
                                                         const ComparisonOptions& options = {});

/// The 63 % time of a sampled response (times increasing), measured from
/// times.front(), towards `steady`, with linear interpolation between
/// samples; NaN as above.
double time_to_63_percent(const std::vector<double>& times, const std::vector<double>& values, double steady);

}  // namespace hydrocoef
