// Where to run CFD next: the run keys that most reduce a Gaussian-process
// surface's largest predictive uncertainty inside given bounds. CFD runs
// cost hours each; choosing them where the surface knows least is worth more
// than any speed-up.
//
// Sequential maximum-variance design: among candidate points (a Halton
// sequence filling the bounds, plus the bounds' corners), take the one where
// the surface's standard deviation is largest, add it to the surface as a
// pseudo-run (its value is the current mean, so the mean does not change
// while the uncertainty around it falls; GpSurface::add_pseudo_run), and
// repeat. The variance of a GP does not depend on the values at the runs,
// only on where they are, so the pseudo-run stands exactly for the run to
// come until its result is known.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "src/surface/gp_surface.hpp"

namespace hydrocoef {

struct SuggestedRun {
  std::vector<double> point;        ///< one value per axis, in the axes' units
  double standard_deviation = 0.0;  ///< the surface's before this run was added
};

/// `count` run keys inside [lower, upper] (one bound per axis, lower < upper),
/// chosen from `candidates` points. InputError for bounds of the wrong size
/// or order, count 0 or above 1000, or candidates below count. When
/// largest_sd_after is given, it receives the largest standard deviation
/// over the candidates once every suggested run is added.
std::vector<SuggestedRun> suggest_gp_runs(const GpSurface& surface, const std::vector<double>& lower,
                                          const std::vector<double>& upper, std::size_t count,
                                          std::size_t candidates = 4096, double* largest_sd_after = nullptr);

/// What a design among given candidates takes into account besides the
/// surface's own runs.
struct DesignContext {
  /// The surface's mirror symmetries on its axes: per reflection, +1 or -1
  /// per axis. A run at x is also a run at each image s * x (the surface is
  /// rebuilt with the images beside the runs), so each chosen point is added
  /// as a pseudo-run together with its distinct images.
  std::vector<std::vector<double>> reflections;
  /// Runs asked for but not yet imported (point-major, dims each): added as
  /// pseudo-runs, with their images, before the first choice.
  std::vector<double> in_flight;
};

/// Sequential maximum variance among the given candidate points
/// (point-major, dims each; distinct), as suggest_gp_runs: `count` of them, no
/// candidate twice. InputError for count 0 or above 1000, fewer candidates
/// than count, or sizes that do not match the surface's dims.
std::vector<SuggestedRun> suggest_among_candidates(const GpSurface& surface, std::span<const double> candidates,
                                                   std::size_t count, const DesignContext& context = {},
                                                   double* largest_sd_after = nullptr);

/// The `count` points of the box [lower, upper] (its corners and a Halton
/// sequence, `candidates` points in all) where the surface's standard
/// deviation is largest, largest first: where a surface is least sure.
std::vector<SuggestedRun> largest_standard_deviations(const GpSurface& surface, const std::vector<double>& lower,
                                                      const std::vector<double>& upper, std::size_t count,
                                                      std::size_t candidates = 1024);

/// Point i of the Halton sequence in `dims` dimensions (bases 2, 3, 5, 7, 11,
/// 13), each coordinate in [0, 1).
std::vector<double> halton_point(std::size_t i, std::size_t dims);

}  // namespace hydrocoef
