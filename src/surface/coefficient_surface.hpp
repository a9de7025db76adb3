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

namespace hydrocoef {

/// The unit of a velocity component or a force component by its name ("m/s"
/// for u, v, w; "rad/s" for p, q, r; "N" for X, Y, Z; "N m" for K, M, N), or
/// "" for any other name (disturbances carry theirs in the run key's docs).
std::string default_unit(std::string_view name);

class CoefficientSurface {
 public:
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

  /// Whether the surface states a standard deviation at a point (GP surfaces).
  bool has_standard_deviation() const noexcept { return gp_ != nullptr; }
  /// As evaluate, and standard_deviation[k]: that of output k (the surface's
  /// predictive standard deviation, in the output's unit); with a gradient
  /// buffer also the gradient, as evaluate_with_gradient, in the same pass.
  /// InputError for a surface without one (has_standard_deviation() false).
  void evaluate_with_standard_deviation(std::span<const double> point, std::span<double> out,
                                        std::span<double> standard_deviation, std::span<double> gradient = {}) const;

 private:
  /// Checks the names against the counts of a scattered surface ("an RBF",
  /// "a GP") and sets the units (default_unit where none are given).
  void set_units(const char* kind, std::size_t axes, std::size_t outputs, std::vector<std::string> axis_units,
                 std::vector<std::string> output_units);
  std::shared_ptr<const GridTable> grid_;
  std::shared_ptr<const RbfSurface> rbf_;
  std::shared_ptr<const GpSurfaces> gp_;
  std::vector<std::string> axis_names_;
  std::vector<std::string> output_names_;
  std::vector<std::string> axis_units_;
  std::vector<std::string> output_units_;
};

}  // namespace hydrocoef
