// The pictures engineers judge damping data by, built from a run database as
// Figures (figure.hpp) ready to render: the ASR-V paper's force-velocity fits
// (Fig. 6, 9), coefficient curves over a disturbance (Fig. 7, 10), coefficient
// surfaces as curves or colour maps, simulated against measured velocity
// (Fig. 13, 14) and steady velocity against torque (Fig. 15).
//
// Units: SI as stored (velocity m/s or rad/s, force N or N m); every axis label
// names its unit and every force label its sign convention.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "src/dynamics/ensemble.hpp"
#include "src/dynamics/vehicle_model.hpp"
#include "src/fit/coefficient_curve.hpp"
#include "src/plot/figure.hpp"
#include "src/store/database.hpp"

namespace hydrocoef::plot {

/// The stored fits a fit plot draws: the fit named `name`, and the per-level
/// fits stored as "name[LEVEL=VALUE]" (src/fit/fit_names.hpp) by `hydrocoef fit --by` (one curve per
/// level). InputError when the database has no runs, no fits, or none of that
/// name (listing the names there are).
std::vector<FitRecord> fit_family(RunDatabase& database, const std::string& name);

/// The law of a stored fit at x [its force unit, in the fit's sign convention].
double evaluate_fit(const FitRecord& fit, double x);

/// Force against velocity: each fit's runs as points, its law as a curve over
/// the runs' range (101 points), the law and R² in the legend.
Figure fit_figure(RunDatabase& database, const std::string& name);

/// Coefficient curves across a disturbance from the per-level fits stored
/// under `base` ("base[by=value]", at least 2 levels): one panel per term, the
/// per-level values as points and the curve (kind, degree as
/// fit_coefficient_curves) over the levels' range (101 points).
Figure curves_figure(RunDatabase& database, const std::string& base, CurveKind kind, int degree);

/// A stored surface's output over its axes: 1 axis a curve, 2 axes a colour
/// map (81 x 81); the runs it was built from marked (forces on the body);
/// regions outside the surface's range shaded (a 1-D surface whose policy
/// extrapolates continues dashed there). InputError for a missing surface
/// (listing the names), an unknown output, or more than 2 axes.
Figure surface_figure(RunDatabase& database, const std::string& name, const std::optional<std::string>& output);

/// The standard deviation a stored surface states for an output
/// (CoefficientSurface::evaluate_with_standard_deviation: a GP's predictive
/// sd, or a grid or RBF surface's runs' uncertainty interpolated with its
/// leave-one-out RMS) over its range: 1 axis a curve (201 points), 2 axes a
/// colour map (81 x 81), with the runs it was built from marked (2 axes: at
/// their coordinates; 1 axis: on the curve). InputError for a missing surface,
/// an unknown output, more than 2 axes, or a surface that states no standard
/// deviation.
Figure surface_sigma_figure(RunDatabase& database, const std::string& name, const std::optional<std::string>& output);

/// Velocity component (u..r) against time from a trajectory CSV
/// (`hydrocoef simulate --out`), with a measured record (experiment.hpp's
/// CSV) overlaid as points when given.
Figure simulation_figure(const std::filesystem::path& trajectory,
                         const std::optional<std::filesystem::path>& experiment, const std::string& component);

/// Steady velocity against a constant force in one DOF, solved by the
/// equilibrium solver (attitude held, no current). The velocity drawn is the
/// DOF's own (N -> r, X -> u). InputError when a solve does not converge.
struct SteadyPoint {
  double tau = 0.0;       ///< N or N m
  double velocity = 0.0;  ///< m/s or rad/s
};
std::vector<SteadyPoint> steady_curve(const VehicleModel& model, std::size_t dof, const std::vector<double>& taus);
/// A band of the steady velocity over Monte Carlo draws of the damping
/// (src/dynamics/ensemble.hpp): between the first and the last percentile.
struct SteadyBandOptions {
  const DampingDraws& draws;
  EnsembleOptions options;
};
/// measured: optional points (force, velocity) drawn as markers; band:
/// optional, drawn behind the curve (InputError when a draw has no
/// equilibrium at one of the forces).
Figure steady_figure(const VehicleModel& model, std::size_t dof, const std::vector<double>& taus,
                     const std::vector<SteadyPoint>& measured, const std::string& vehicle_name,
                     const SteadyBandOptions* band = nullptr);

/// Reads measured steady points: CSV (comma, tab or semicolon), '#' comment
/// lines, one header line, then rows "force,velocity" in SI.
/// InputError "FILE:LINE: ..." for a malformed row.
std::vector<SteadyPoint> read_steady_points(const std::filesystem::path& path);

}  // namespace hydrocoef::plot
