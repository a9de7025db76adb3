// A coefficient surface as the rest of hydrocoef sees it: named axes (body
// velocity components "u".."r" or disturbance parameters such as "current_v")
// and named outputs ("X".."N" or any coefficient), each with its unit, over
// a gridded table (GridTable), a scattered-sample RBF (RbfSurface) or a
// Gaussian process (GpSurfaces, which also gives each value's standard
// deviation). Dynamics, export and the CLI query through this one type.
//
// Immutable after construction; copies share the underlying table, so a copy
// is cheap and every copy may be evaluated from any thread at once.
// Evaluation allocates nothing.
//
// Units: axis values in the axis's SI unit (m/s for u, v, w; rad/s for p, q,
// r; a disturbance's SI unit), outputs in their unit (N for X, Y, Z; N m for
// K, M, N), forces on the body (SignConvention::OnBody: damping is negative).
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "src/surface/gp_surfaces.hpp"
#include "src/surface/grid_table.hpp"
#include "src/surface/rbf_surface.hpp"
#include "src/surface/surface_symmetry.hpp"

namespace hydrocoef {

/// The unit of a velocity component or a force component by its name ("m/s"
/// for u, v, w; "rad/s" for p, q, r; "N" for X, Y, Z; "N m" for K, M, N), or
/// "" for any other name (disturbances carry theirs in the run key's docs).
std::string default_unit(std::string_view name);

class CoefficientSurface {
 public:
  /// The most outputs and axes a surface with a symmetry has.
  static constexpr std::size_t kMaxSymmetricOutputs = 6, kMaxSymmetricAxes = 6;

  enum class Kind { Grid, Rbf, Gp };

  /// A gridded surface. Axis and output names are the table's; units one per
  /// axis / output (empty vectors: default_unit of each name).
  CoefficientSurface(GridTable table, std::vector<std::string> axis_units = {},
                     std::vector<std::string> output_units = {});
  /// A scattered-sample surface over the named axes with the named outputs
  /// (sizes must match the RBF's; InputError otherwise).
  CoefficientSurface(RbfSurface rbf, std::vector<std::string> axis_names, std::vector<std::string> output_names,
                     std::vector<std::string> axis_units = {}, std::vector<std::string> output_units = {});
  /// A Gaussian-process surface over the named axes with the named outputs
  /// (sizes must match; InputError otherwise).
  CoefficientSurface(GpSurfaces gp, std::vector<std::string> axis_names, std::vector<std::string> output_names,
                     std::vector<std::string> axis_units = {}, std::vector<std::string> output_units = {});

  Kind kind() const noexcept { return grid_ ? Kind::Grid : rbf_ ? Kind::Rbf : Kind::Gp; }
  /// The table of a Grid surface, nullptr for Rbf.
  const GridTable* grid() const noexcept { return grid_.get(); }
  /// The RBF of an Rbf surface, nullptr for Grid.
  const RbfSurface* rbf() const noexcept { return rbf_.get(); }
  /// The Gaussian processes of a Gp surface, nullptr otherwise.
  const GpSurfaces* gp() const noexcept { return gp_.get(); }

  std::size_t axis_count() const noexcept { return axis_names_.size(); }
  std::size_t output_count() const noexcept { return output_names_.size(); }
  const std::vector<std::string>& axis_names() const noexcept { return axis_names_; }
  const std::vector<std::string>& output_names() const noexcept { return output_names_; }
  const std::vector<std::string>& axis_units() const noexcept { return axis_units_; }
  const std::vector<std::string>& output_units() const noexcept { return output_units_; }
  /// Position of an axis / output by name; InputError listing the names otherwise.
  std::size_t axis_index(std::string_view name) const;
  std::size_t output_index(std::string_view name) const;
  /// The range the surface was built over on an axis [axis unit]: first and
  /// last breakpoint, or the samples' range. std::out_of_range for a bad axis.
  double lower(std::size_t axis) const;
  double upper(std::size_t axis) const;
  /// The out-of-range policy of an axis as its lowercase name: for a grid
  /// extrapolation_name ("error", "clamp", "linear", "method"); for an RBF
  /// or a GP "error", "clamp" or "extrapolate".
  std::string out_of_range_name(std::size_t axis) const;
  /// The method: interpolation_name for a grid; "rbf" for an RBF; "gp".
  std::string method_name() const;

  /// out[k] = output k at point (axis order and units). Throws as
  /// GridTable::evaluate / RbfSurface::evaluate. Allocates nothing.
  void evaluate(std::span<const double> point, std::span<double> out) const;
  /// As evaluate, and gradient[k * axis_count() + a] = d output_k / d axis_a.
  void evaluate_with_gradient(std::span<const double> point, std::span<double> out, std::span<double> gradient) const;

  /// Whether the surface states a standard deviation at a point: GP
  /// surfaces, and grid and RBF surfaces given their runs' uncertainty
  /// (with_run_uncertainty; those built by this hydrocoef's surface build).
  bool has_standard_deviation() const noexcept { return gp_ != nullptr || !loo_sd_.empty(); }
  /// As evaluate, and standard_deviation[k]: that of output k, in the
  /// output's unit (a GP's predictive standard deviation; for a grid or an
  /// RBF surface the formula at with_run_uncertainty); with a gradient
  /// buffer also the gradient, as evaluate_with_gradient, in the same pass.
  /// InputError for a surface without one (has_standard_deviation() false).
  void evaluate_with_standard_deviation(std::span<const double> point, std::span<double> out,
                                        std::span<double> standard_deviation, std::span<double> gradient = {}) const;

  /// A grid or RBF surface's stated uncertainty. Per output k, at point x:
  ///     sd_k(x)^2 = s_k(x)^2 + loo_k^2,   s_k(x) = max(0, I[sigma_.k](x)),
  /// sigma_ik the standard uncertainty of run i's output k (its statistical
  /// standard error and any given at import, in quadrature:
  /// StoredForce::standard_uncertainty; 0 when neither is known), I[.] the
  /// surface's own interpolant through those numbers in place of the runs'
  /// values (the same breakpoints and method, or the same RBF kernel,
  /// polynomial, smoothing and scaling), and loo_k the surface's
  /// leave-one-out RMS error of output k (SurfaceQuality::loo_rms).
  /// The interpolants but PCHIP/makima are linear in their data,
  /// I[y](x) = sum_i a_i(x) y_i, so s_k(x) = |sum_i a_i(x) sigma_ik| is the
  /// propagated standard deviation when the runs' errors are fully
  /// correlated (one systematic error, as a mesh or model bias); for
  /// independent errors it would be sqrt(sum_i a_i^2 sigma_ik^2), which is
  /// no larger when every a_i >= 0 (nearest, linear): then s_k is an upper
  /// bound. loo_k stands for the interpolation error, taken as independent of
  /// the runs' errors and the same everywhere. Outside the runs' range the
  /// runs' part is that at the nearest point of the range (no extrapolation
  /// error is added).
  /// sigma: grid surfaces, the runs' uncertainty at every node in the
  /// table's values layout; RBF surfaces, an RbfSurface through the same
  /// samples with those uncertainties as values. loo: one finite value >= 0
  /// per output. InputError when they do not fit the surface; a GP surface
  /// has its own standard deviation (InputError).
  CoefficientSurface with_run_uncertainty(std::vector<double> sigma, std::vector<double> loo) const;
  CoefficientSurface with_run_uncertainty(RbfSurface sigma, std::vector<double> loo) const;
  /// The surface with a mirror symmetry imposed (src/surface/surface_symmetry.hpp
  /// has the projection): every value, gradient and standard deviation is
  /// then that of the projection, for every method. A GP's standard
  /// deviation is that of the projected latent function (0 for an odd
  /// output on its plane); a grid's or an RBF's runs' part is their
  /// uncertainties' interpolant projected the same way (fully correlated, as
  /// a run and its image are), its leave-one-out part unchanged. A grid's
  /// node values are made symmetric too where its breakpoints are symmetric
  /// about 0 on every reflected axis, so that its table, as exported, is the
  /// surface. InputError when the symmetry's axis and output counts are not
  /// the surface's, or for more than 6 outputs.
  CoefficientSurface with_symmetry(SurfaceSymmetry symmetry) const;
  /// The symmetry imposed (empty: none).
  const SurfaceSymmetry& symmetry() const noexcept { return symmetry_; }

  /// The parts of that uncertainty: per output loo_k (empty when none is
  /// stated), and the table or RBF of the runs' sigma (nullptr when none).
  const std::vector<double>& loo_standard_deviation() const noexcept { return loo_sd_; }
  const GridTable* run_uncertainty_grid() const noexcept { return sigma_grid_.get(); }
  const RbfSurface* run_uncertainty_rbf() const noexcept { return sigma_rbf_.get(); }

 private:
  /// The interpolant itself, without the symmetry.
  void evaluate_unprojected(std::span<const double> point, std::span<double> out, std::span<double> gradient) const;
  /// The runs' part of a grid's or an RBF's standard deviation, max(0, I[sigma](x)).
  void run_part(std::span<const double> point, std::span<double> part) const;
  /// The projection (symmetry_ not empty): values, and when the spans are
  /// not empty the standard deviation and the gradient.
  void evaluate_projected(std::span<const double> point, std::span<double> out, std::span<double> standard_deviation,
                          std::span<double> gradient) const;
  /// Checks the names against the counts of a scattered surface ("an RBF",
  /// "a GP") and sets the units (default_unit where none are given).
  void set_units(const char* kind, std::size_t axes, std::size_t outputs, std::vector<std::string> axis_units,
                 std::vector<std::string> output_units);
  std::shared_ptr<const GridTable> grid_;
  std::shared_ptr<const RbfSurface> rbf_;
  std::shared_ptr<const GpSurfaces> gp_;
  // with_run_uncertainty's parts (empty / nullptr without one).
  std::vector<double> loo_sd_;
  std::shared_ptr<const GridTable> sigma_grid_;
  std::shared_ptr<const RbfSurface> sigma_rbf_;
  SurfaceSymmetry symmetry_;
  std::vector<std::string> axis_names_;
  std::vector<std::string> output_names_;
  std::vector<std::string> axis_units_;
  std::vector<std::string> output_units_;
};

}  // namespace hydrocoef
