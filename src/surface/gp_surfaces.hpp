// A Gaussian-process coefficient surface of several outputs: one GpSurface
// (src/surface/gp_surface.hpp: kernel, polynomial mean, REML hyperparameters,
// per-run noise) per output, all over the same runs, with the runs' range on
// each axis and what a query outside it does. This is what CoefficientSurface
// holds for the method "gp".
//
// Each output has its own hyperparameters (a yaw moment and a surge force
// vary on different length scales). The standard deviation returned is that
// of the latent function (the surface), not of a new CFD run: the runs' own
// noise is not added.
//
// Evaluation is const and thread-safe; the scratch space of a query lives in
// a per-thread buffer that grows once to the surface's run count, so after a
// thread's first query nothing is allocated.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "src/surface/gp_surface.hpp"
#include "src/surface/rbf_surface.hpp"

namespace hydrocoef {

class GpSurfaces {
 public:
  /// Runs a GP surface is built from at most (dense O(n^3) solve).
  static constexpr std::size_t kMaxSamples = 5000;

  /// Fits one GP per output. `x`: axes values per run (run-major, axis units);
  /// `y`: outputs values per run (run-major); `noise_sd`: the standard
  /// uncertainty of each value in the layout of y (empty: none). The range
  /// of each axis is the runs' range. InputError as GpSurface::fit (naming the
  /// output), or for sizes that do not match.
  GpSurfaces(std::size_t axes, std::span<const double> x, std::size_t outputs, std::span<const double> y,
             std::span<const double> noise_sd, const GpOptions& options, std::vector<std::string> axis_names,
             std::vector<RbfOutOfRange> out_of_range);

  /// From stored parts: one surface per output over `axis_names`, the range
  /// [lower, upper] per axis and its policy. InputError when they disagree
  /// (axis or sample counts, a range that is not lower < upper).
  GpSurfaces(std::vector<GpSurface> outputs, std::vector<double> lower, std::vector<double> upper,
             std::vector<std::string> axis_names, std::vector<RbfOutOfRange> out_of_range);

  std::size_t axis_count() const noexcept { return lower_.size(); }
  std::size_t output_count() const noexcept { return outputs_.size(); }
  std::size_t sample_count() const noexcept { return outputs_.front().samples(); }
  const GpSurface& output(std::size_t k) const { return outputs_.at(k); }
  double lower(std::size_t axis) const { return lower_.at(axis); }
  double upper(std::size_t axis) const { return upper_.at(axis); }
  RbfOutOfRange out_of_range(std::size_t axis) const { return policy_.at(axis); }
  GpKernel kernel() const { return outputs_.front().state().kernel; }
  int mean_degree() const { return outputs_.front().state().mean_degree; }

  /// out[k]: the mean of output k at `point` (axis order and units).
  /// standard_deviation (empty, or one per output): its standard deviation.
  /// gradient (empty, or outputs x axes, output-major): d mean_k / d axis_a;
  /// 0 along an axis clamped by its policy. InputError for a point of the
  /// wrong size, a coordinate that is not finite, or outside the range on an
  /// axis whose policy is error.
  void evaluate(std::span<const double> point, std::span<double> out, std::span<double> standard_deviation = {},
                std::span<double> gradient = {}) const;

  /// Per output k, the standard deviation of sum_j c_jk f_k(x_j) (the
  /// latent functions at `count` <= 8 points jointly: GpSurface::
  /// combination_sd): `points` count x axes, point-major, each placed as
  /// evaluate places it (clamped or refused by the axes' policies);
  /// `coefficients` count x outputs, point-major.
  void combination_standard_deviation(std::span<const double> points, std::size_t count,
                                      std::span<const double> coefficients, std::span<double> standard_deviation) const;

 private:
  void check() const;
  /// x = point, clamped where an axis's policy says so (clamped[a] set) or
  /// InputError as evaluate says.
  void place(std::span<const double> point, double* x, bool* clamped) const;
  /// This thread's scratch space, grown to this surface's run count.
  GpSurface::Workspace& workspace() const;
  std::vector<GpSurface> outputs_;
  std::vector<double> lower_, upper_;
  std::vector<std::string> axis_names_;
  std::vector<RbfOutOfRange> policy_;
};

}  // namespace hydrocoef
