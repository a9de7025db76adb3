#include "src/surface/coefficient_surface.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "src/core/error.hpp"
#include "src/core/run.hpp"
#include "src/core/text.hpp"

namespace hydrocoef {
namespace {

std::vector<std::string> units_or_default(std::vector<std::string> units, const std::vector<std::string>& names,
                                          const char* what) {
  if (units.empty()) {
    for (const auto& name : names) units.push_back(default_unit(name));
    return units;
  }
  if (units.size() != names.size())
    throw InputError(std::string("a surface has ") + std::to_string(names.size()) + " " + what + "s but " +
                     std::to_string(units.size()) + " " + what + " units; expected one unit per " + what);
  return units;
}

std::size_t find_name(const std::vector<std::string>& names, std::string_view name, const char* what) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return i;
  const std::string plural = std::string_view(what) == "axis" ? "axes" : std::string(what) + "s";
  throw InputError(std::string("the surface has no ") + what + " '" + std::string(name) + "'; its " +
                   (names.size() == 1 ? std::string(what) + " is " : plural + " are ") + join(names, ", "));
}

}  // namespace

std::string default_unit(std::string_view name) {
  if (const auto v = velocity_index(name)) return *v < 3 ? "m/s" : "rad/s";
  if (const auto f = force_index(name)) return *f < 3 ? "N" : "N m";
  return "";
}

CoefficientSurface::CoefficientSurface(GridTable table, std::vector<std::string> axis_units,
                                       std::vector<std::string> output_units) {
  for (const auto& axis : table.axes()) axis_names_.push_back(axis.name);
  output_names_ = table.outputs();
  axis_units_ = units_or_default(std::move(axis_units), axis_names_, "axis");
  output_units_ = units_or_default(std::move(output_units), output_names_, "output");
  grid_ = std::make_shared<const GridTable>(std::move(table));
}

CoefficientSurface::CoefficientSurface(RbfSurface rbf, std::vector<std::string> axis_names,
                                       std::vector<std::string> output_names, std::vector<std::string> axis_units,
                                       std::vector<std::string> output_units)
    : axis_names_(std::move(axis_names)), output_names_(std::move(output_names)) {
  set_units("an RBF", rbf.axis_count(), rbf.output_count(), std::move(axis_units), std::move(output_units));
  rbf_ = std::make_shared<const RbfSurface>(std::move(rbf));
}

CoefficientSurface::CoefficientSurface(GpSurfaces gp, std::vector<std::string> axis_names,
                                       std::vector<std::string> output_names, std::vector<std::string> axis_units,
                                       std::vector<std::string> output_units)
    : axis_names_(std::move(axis_names)), output_names_(std::move(output_names)) {
  set_units("a GP", gp.axis_count(), gp.output_count(), std::move(axis_units), std::move(output_units));
  gp_ = std::make_shared<const GpSurfaces>(std::move(gp));
}

void CoefficientSurface::set_units(const char* kind, std::size_t axes, std::size_t outputs,
                                   std::vector<std::string> axis_units, std::vector<std::string> output_units) {
  if (axis_names_.size() != axes || output_names_.size() != outputs)
    throw InputError(std::string(kind) + " surface of " + std::to_string(axes) + " axes and " +
                     std::to_string(outputs) + " outputs was given " + std::to_string(axis_names_.size()) +
                     " axis names and " + std::to_string(output_names_.size()) + " output names; expected as many");
  axis_units_ = units_or_default(std::move(axis_units), axis_names_, "axis");
  output_units_ = units_or_default(std::move(output_units), output_names_, "output");
}

std::size_t CoefficientSurface::axis_index(std::string_view name) const { return find_name(axis_names_, name, "axis"); }

std::size_t CoefficientSurface::output_index(std::string_view name) const {
  return find_name(output_names_, name, "output");
}

double CoefficientSurface::lower(std::size_t axis) const {
  if (axis >= axis_count()) throw std::out_of_range("CoefficientSurface::lower: axis out of range");
  return grid_ ? grid_->axes()[axis].breakpoints.front() : rbf_ ? rbf_->lower(axis) : gp_->lower(axis);
}

double CoefficientSurface::upper(std::size_t axis) const {
  if (axis >= axis_count()) throw std::out_of_range("CoefficientSurface::upper: axis out of range");
  return grid_ ? grid_->axes()[axis].breakpoints.back() : rbf_ ? rbf_->upper(axis) : gp_->upper(axis);
}

std::string CoefficientSurface::out_of_range_name(std::size_t axis) const {
  if (axis >= axis_count()) throw std::out_of_range("CoefficientSurface::out_of_range_name: axis out of range");
  if (grid_) return std::string(extrapolation_name(grid_->axes()[axis].extrapolation));
  switch (rbf_ ? rbf_->out_of_range(axis) : gp_->out_of_range(axis)) {
    case RbfOutOfRange::Error: return "error";
    case RbfOutOfRange::Clamp: return "clamp";
    case RbfOutOfRange::Extrapolate: return "extrapolate";
  }
  return "error";
}

std::string CoefficientSurface::method_name() const {
  return grid_ ? std::string(interpolation_name(grid_->method())) : std::string(rbf_ ? "rbf" : "gp");
}

void CoefficientSurface::evaluate(std::span<const double> point, std::span<double> out) const {
  if (grid_)
    grid_->evaluate(point, out);
  else if (rbf_)
    rbf_->evaluate(point, out);
  else
    gp_->evaluate(point, out);
}

void CoefficientSurface::evaluate_with_gradient(std::span<const double> point, std::span<double> out,
                                                std::span<double> gradient) const {
  if (grid_)
    grid_->evaluate_with_gradient(point, out, gradient);
  else if (rbf_)
    rbf_->evaluate_with_gradient(point, out, gradient);
  else
    gp_->evaluate(point, out, {}, gradient);
}

void CoefficientSurface::evaluate_with_standard_deviation(std::span<const double> point, std::span<double> out,
                                                          std::span<double> standard_deviation,
                                                          std::span<double> gradient) const {
  if (gp_) {
    gp_->evaluate(point, out, standard_deviation, gradient);
    return;
  }
  if (loo_sd_.empty())
    throw InputError("the surface (method '" + method_name() +
                     "') states no standard deviation at a point (it was stored without its runs' uncertainty: "
                     "rebuild it with hydrocoef surface rebuild); expected a GP surface or a grid or RBF surface "
                     "built by this hydrocoef");
  if (standard_deviation.size() != output_count())
    throw std::invalid_argument(
        "CoefficientSurface::evaluate_with_standard_deviation: one standard deviation per "
        "output expected");
  if (gradient.empty())
    evaluate(point, out);
  else
    evaluate_with_gradient(point, out, gradient);
  // The runs' part: their uncertainties through the surface's own
  // interpolant, clamped to the runs' range (see with_run_uncertainty).
  if (sigma_grid_)
    sigma_grid_->evaluate(point, standard_deviation);
  else
    sigma_rbf_->evaluate(point, standard_deviation);
  for (std::size_t k = 0; k < standard_deviation.size(); ++k)
    standard_deviation[k] = std::hypot(std::max(0.0, standard_deviation[k]), loo_sd_[k]);
}

namespace {

std::vector<double> checked_loo(std::vector<double> loo, std::size_t outputs) {
  if (loo.size() != outputs)
    throw InputError("a surface's uncertainty has " + std::to_string(loo.size()) + " leave-one-out figures for " +
                     std::to_string(outputs) + " outputs; expected one per output");
  for (const double x : loo)
    if (!std::isfinite(x) || x < 0.0)
      throw InputError("a surface's leave-one-out standard deviation is " + std::to_string(x) +
                       "; expected a finite number >= 0");
  return loo;
}

}  // namespace

CoefficientSurface CoefficientSurface::with_run_uncertainty(std::vector<double> sigma, std::vector<double> loo) const {
  if (!grid_)
    throw InputError("the runs' uncertainty as one number per node needs a grid surface; this one's method is '" +
                     method_name() + "'");
  if (sigma.size() != grid_->values().size())
    throw InputError("a grid surface's run uncertainty has " + std::to_string(sigma.size()) + " numbers; expected " +
                     std::to_string(grid_->values().size()) + " (one per node and output)");
  for (const double x : sigma)
    if (!std::isfinite(x) || x < 0.0)
      throw InputError("a run's standard uncertainty is " + std::to_string(x) + "; expected a finite number >= 0");
  CoefficientSurface out = *this;
  out.loo_sd_ = checked_loo(std::move(loo), output_count());
  // The same breakpoints and method; clamped outside the range.
  std::vector<GridAxis> axes = grid_->axes();
  for (auto& axis : axes) axis.extrapolation = Extrapolation::Clamp;
  out.sigma_grid_ =
      std::make_shared<const GridTable>(std::move(axes), grid_->outputs(), std::move(sigma), grid_->method());
  out.sigma_rbf_.reset();
  return out;
}

CoefficientSurface CoefficientSurface::with_run_uncertainty(RbfSurface sigma, std::vector<double> loo) const {
  if (!rbf_)
    throw InputError("the runs' uncertainty as an RBF needs an RBF surface; this one's method is '" + method_name() +
                     "'");
  if (sigma.axis_count() != rbf_->axis_count() || sigma.output_count() != rbf_->output_count() ||
      sigma.sample_count() != rbf_->sample_count())
    throw InputError("an RBF surface's run uncertainty has " + std::to_string(sigma.sample_count()) + " samples of " +
                     std::to_string(sigma.output_count()) + " outputs; expected the surface's " +
                     std::to_string(rbf_->sample_count()) + " of " + std::to_string(rbf_->output_count()));
  for (std::size_t a = 0; a < sigma.axis_count(); ++a)
    if (sigma.out_of_range(a) != RbfOutOfRange::Clamp)
      throw InputError("an RBF surface's run uncertainty must be clamped outside the runs' range on every axis");
  CoefficientSurface out = *this;
  out.loo_sd_ = checked_loo(std::move(loo), output_count());
  out.sigma_rbf_ = std::make_shared<const RbfSurface>(std::move(sigma));
  out.sigma_grid_.reset();
  return out;
}

}  // namespace hydrocoef
