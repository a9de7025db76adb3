// Monte Carlo over a vehicle's damping uncertainty: N draws of the damping
// model (src/dynamics/damping_draws.hpp: per-trajectory parameter draws,
// not per-step noise), each simulated or solved for its equilibrium on every
// core, summarised by percentiles.
//
// Percentiles are NumPy's default ("linear"): the value at rank
// p/100 (n - 1) of the n sorted values, interpolated linearly between the
// two nearest order statistics. Angles are unwrapped in time within each
// trajectory first (a yaw angle that passes pi keeps growing), so that a
// band of a turning vehicle does not jump between -pi and pi.
//
// A draw whose trajectory or equilibrium fails (a surface left outside its
// range under policy "error", a state that leaves the finite numbers, no
// equilibrium) is counted and its first messages kept; the bands are those
// of the draws that succeeded, and the result says how many did not.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "src/dynamics/damping_draws.hpp"
#include "src/dynamics/equilibrium.hpp"
#include "src/dynamics/scenario.hpp"
#include "src/dynamics/trajectory.hpp"
#include "src/dynamics/vehicle_model.hpp"

namespace hydrocoef {

struct EnsembleOptions {
  std::size_t samples = 1000;  ///< draws, >= 2
  std::uint64_t seed = 1;
  /// Percentiles to report, in (0, 100), increasing.
  std::vector<double> percentiles = {5.0, 50.0, 95.0};
  unsigned threads = 0;  ///< 0: one per core
};

/// Checks the options (InputError naming the option: "--samples", "--percentiles").
void check_ensemble_options(const EnsembleOptions& options);

/// Percentile p (0..100) of `sorted` (increasing, non-empty), as the file
/// comment says.
double percentile_of_sorted(std::span<const double> sorted, double p);

/// The most numbers a set of trajectories may hold in memory (draws x
/// output samples x 12): 512 MB.
inline constexpr double kMaxEnsembleValues = 6.4e7;

/// progress(done, total) after each finished draw (from any thread, one call at a time).
using EnsembleProgress = std::function<void(std::size_t done, std::size_t total)>;

/// Simulates `options.samples` draws of the model's damping on the
/// scenario. InputError for options out of range, a scenario whose draws
/// would not fit kMaxEnsembleValues, or when every draw fails (with the first
/// failure's message).
TrajectoryBands simulate_samples(const VehicleModel& model, const DampingDraws& draws, const Scenario& scenario,
                                 const EnsembleOptions& options, const EnsembleProgress& progress = {});

/// The share (0..1) of measured values of a quantity (e.g. "r") that lie
/// inside the band between the lowest and the highest percentile, the band
/// interpolated linearly to the measured times; only times inside the
/// simulated span count. NaN when none do, or with fewer than 2 percentiles.
double share_inside_band(const TrajectoryBands& bands, std::string_view quantity, std::span<const double> t_s,
                         std::span<const double> values);

/// The steady velocity's distribution over the draws.
struct EquilibriumSamples {
  std::vector<double> percentiles;
  std::vector<Vector6> percentile_values;  ///< one per percentile
  Vector6 mean = Vector6::Zero();
  Vector6 standard_deviation = Vector6::Zero();  ///< sample standard deviation (n - 1)
  std::size_t samples = 0;                       ///< draws that reached an equilibrium
  EnsembleFailures failures;
};

/// Solves the equilibrium of `options.samples` draws. InputError as
/// simulate_samples.
EquilibriumSamples solve_equilibrium_samples(const VehicleModel& model, const DampingDraws& draws,
                                             const EquilibriumInputs& inputs, const EnsembleOptions& options,
                                             const EnsembleProgress& progress = {});

}  // namespace hydrocoef
