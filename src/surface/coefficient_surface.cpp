#include "src/surface/coefficient_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
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
  if (const auto v = velocity_index(name)) return velocity_unit(*v);
  if (const auto f = force_index(name)) return force_unit(*f);
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

void CoefficientSurface::evaluate_unprojected(std::span<const double> point, std::span<double> out,
                                              std::span<double> gradient) const {
  if (gradient.empty()) {
    if (grid_)
      grid_->evaluate(point, out);
    else if (rbf_)
      rbf_->evaluate(point, out);
    else
      gp_->evaluate(point, out);
    return;
  }
  if (grid_)
    grid_->evaluate_with_gradient(point, out, gradient);
  else if (rbf_)
    rbf_->evaluate_with_gradient(point, out, gradient);
  else
    gp_->evaluate(point, out, {}, gradient);
}

void CoefficientSurface::run_part(std::span<const double> point, std::span<double> part) const {
  // Their uncertainties through the surface's own interpolant, clamped to
  // the runs' range (see with_run_uncertainty).
  if (sigma_grid_)
    sigma_grid_->evaluate(point, part);
  else
    sigma_rbf_->evaluate(point, part);
  for (double& x : part) x = std::max(0.0, x);
}

void CoefficientSurface::evaluate(std::span<const double> point, std::span<double> out) const {
  if (symmetry_.empty())
    evaluate_unprojected(point, out, {});
  else
    evaluate_projected(point, out, {}, {});
}

void CoefficientSurface::evaluate_with_gradient(std::span<const double> point, std::span<double> out,
                                                std::span<double> gradient) const {
  if (symmetry_.empty())
    evaluate_unprojected(point, out, gradient);
  else
    evaluate_projected(point, out, {}, gradient);
}

void CoefficientSurface::evaluate_with_standard_deviation(std::span<const double> point, std::span<double> out,
                                                          std::span<double> standard_deviation,
                                                          std::span<double> gradient) const {
  if (!gp_ && loo_sd_.empty())
    throw InputError("the surface (method '" + method_name() +
                     "') states no standard deviation at a point (it was stored without its runs' uncertainty: "
                     "rebuild it with hydrocoef surface rebuild); expected a GP surface or a grid or RBF surface "
                     "built by this hydrocoef");
  if (standard_deviation.size() != output_count())
    throw std::invalid_argument(
        "CoefficientSurface::evaluate_with_standard_deviation: one standard deviation per "
        "output expected");
  if (!symmetry_.empty()) {
    evaluate_projected(point, out, standard_deviation, gradient);
    return;
  }
  if (gp_) {
    gp_->evaluate(point, out, standard_deviation, gradient);
    return;
  }
  evaluate_unprojected(point, out, gradient);
  run_part(point, standard_deviation);
  for (std::size_t k = 0; k < standard_deviation.size(); ++k)
    standard_deviation[k] = std::hypot(standard_deviation[k], loo_sd_[k]);
}

void CoefficientSurface::evaluate_projected(std::span<const double> point, std::span<double> out,
                                            std::span<double> standard_deviation, std::span<double> gradient) const {
  constexpr std::size_t kImages = std::size_t{1} << SurfaceSymmetry::kMaxGenerators;
  const std::size_t d = axis_count(), n_out = output_count(), moving = symmetry_.moving_count();
  const std::size_t images = std::size_t{1} << moving;
  if (point.size() != d || out.size() != n_out || (!gradient.empty() && gradient.size() != n_out * d))
    throw std::invalid_argument("CoefficientSurface::evaluate: buffers of the wrong size");
  const bool with_gradient = !gradient.empty(), with_sd = !standard_deviation.empty();
  const auto& generators = symmetry_.generators();
  // Image m is g^m x: generator j applied where bit j of m is set.
  std::array<std::array<double, kMaxSymmetricAxes>, kImages> x;
  std::array<std::array<double, kMaxSymmetricOutputs>, kImages> value, part;
  std::array<std::array<double, kMaxSymmetricOutputs * kMaxSymmetricAxes>, kImages> slope;
  for (std::size_t a = 0; a < d; ++a) x[0][a] = point[a];
  for (std::size_t m = 1; m < images; ++m) {
    const std::size_t j = static_cast<std::size_t>(__builtin_ctzll(m));
    symmetry_.reflect(j, std::span<const double>(x[m & (m - 1)].data(), d), std::span<double>(x[m].data(), d));
  }
  for (std::size_t m = 0; m < images; ++m) {
    const std::span<const double> at(x[m].data(), d);
    evaluate_unprojected(at, std::span<double>(value[m].data(), n_out),
                         with_gradient ? std::span<double>(slope[m].data(), n_out * d) : std::span<double>());
    if (with_sd && !gp_) run_part(at, std::span<double>(part[m].data(), n_out));
  }
  // Nested halves, one generator at a time (the file comment of
  // surface_symmetry.hpp): after step j, image m (bits 0..j clear) holds
  // F_j at g^m x.
  for (std::size_t j = 0; j < moving; ++j) {
    const std::size_t step = std::size_t{1} << j;
    const auto& s = generators[j].output_signs;
    const auto& flip = generators[j].axis_signs;
    for (std::size_t m = 0; m < images; m += 2 * step)
      for (std::size_t k = 0; k < n_out; ++k) {
        value[m][k] = 0.5 * (value[m][k] + s[k] * value[m + step][k]);
        if (with_sd && !gp_) part[m][k] = 0.5 * (part[m][k] + s[k] * part[m + step][k]);
        if (with_gradient)
          for (std::size_t a = 0; a < d; ++a)
            slope[m][k * d + a] = 0.5 * (slope[m][k * d + a] + s[k] * flip[a] * slope[m + step][k * d + a]);
      }
  }
  // Generators that move no axis: an output odd under one is 0.
  std::array<bool, kMaxSymmetricOutputs> zero{};
  for (std::size_t j = moving; j < generators.size(); ++j)
    for (std::size_t k = 0; k < n_out; ++k) zero[k] = zero[k] || generators[j].output_signs[k] < 0.0;
  for (std::size_t k = 0; k < n_out; ++k) {
    out[k] = zero[k] ? 0.0 : value[0][k];
    if (with_gradient)
      for (std::size_t a = 0; a < d; ++a) gradient[k * d + a] = zero[k] ? 0.0 : slope[0][k * d + a];
  }
  if (!with_sd) return;
  if (gp_) {
    // The projection's coefficient of image m, output k: the product of
    // the output signs of the generators in m, over the number of images.
    std::array<double, kImages * kMaxSymmetricOutputs> c{};
    for (std::size_t m = 0; m < images; ++m)
      for (std::size_t k = 0; k < n_out; ++k) {
        double sign = 1.0;
        for (std::size_t j = 0; j < moving; ++j)
          if (m & (std::size_t{1} << j)) sign *= generators[j].output_signs[k];
        c[m * n_out + k] = sign / static_cast<double>(images);
      }
    std::array<double, kImages * kMaxSymmetricAxes> flat{};
    for (std::size_t m = 0; m < images; ++m)
      for (std::size_t a = 0; a < d; ++a) flat[m * d + a] = x[m][a];
    gp_->combination_standard_deviation(std::span<const double>(flat.data(), images * d), images,
                                        std::span<const double>(c.data(), images * n_out), standard_deviation);
    for (std::size_t k = 0; k < n_out; ++k)
      if (zero[k]) standard_deviation[k] = 0.0;
    return;
  }
  for (std::size_t k = 0; k < n_out; ++k)
    standard_deviation[k] = zero[k] ? 0.0 : std::hypot(std::abs(part[0][k]), loo_sd_[k]);
}

namespace {

/// The node values of a table projected as the surface is (the same nested
/// halves over the nodes' mirror images); nullopt when a reflected axis's
/// breakpoints are not symmetric about 0.
std::optional<std::vector<double>> symmetric_values(const GridTable& table, const SurfaceSymmetry& symmetry) {
  const auto& axes = table.axes();
  const std::size_t d = axes.size(), n_out = table.output_count(), moving = symmetry.moving_count();
  const auto& generators = symmetry.generators();
  for (std::size_t j = 0; j < moving; ++j)
    for (std::size_t a = 0; a < d; ++a) {
      if (generators[j].axis_signs[a] > 0.0) continue;
      const auto& b = axes[a].breakpoints;
      for (std::size_t i = 0; i < b.size(); ++i)
        if (b[i] != -b[b.size() - 1 - i]) return std::nullopt;
    }
  const std::size_t images = std::size_t{1} << moving;
  std::vector<std::size_t> stride(d, 1);
  for (std::size_t a = 1; a < d; ++a) stride[a] = stride[a - 1] * axes[a - 1].breakpoints.size();
  const auto& values = table.values();
  std::vector<double> out(values.size());
  std::vector<std::size_t> index(d);
  std::vector<std::vector<double>> v(images, std::vector<double>(n_out));
  for (std::size_t node = 0; node < table.node_count(); ++node) {
    std::size_t rest = node;
    for (std::size_t a = d; a-- > 0;) {
      index[a] = rest / stride[a];
      rest %= stride[a];
    }
    for (std::size_t m = 0; m < images; ++m) {
      std::size_t image = 0;
      for (std::size_t a = 0; a < d; ++a) {
        bool flipped = false;
        for (std::size_t j = 0; j < moving; ++j)
          if ((m & (std::size_t{1} << j)) && generators[j].axis_signs[a] < 0.0) flipped = !flipped;
        const std::size_t i = flipped ? axes[a].breakpoints.size() - 1 - index[a] : index[a];
        image += i * stride[a];
      }
      for (std::size_t k = 0; k < n_out; ++k) v[m][k] = values[image * n_out + k];
    }
    for (std::size_t j = 0; j < moving; ++j) {
      const std::size_t step = std::size_t{1} << j;
      for (std::size_t m = 0; m < images; m += 2 * step)
        for (std::size_t k = 0; k < n_out; ++k)
          v[m][k] = 0.5 * (v[m][k] + generators[j].output_signs[k] * v[m + step][k]);
    }
    for (std::size_t k = 0; k < n_out; ++k) {
      bool zero = false;
      for (std::size_t j = moving; j < generators.size(); ++j) zero = zero || generators[j].output_signs[k] < 0.0;
      out[node * n_out + k] = zero ? 0.0 : v[0][k];
    }
  }
  return out;
}

}  // namespace

CoefficientSurface CoefficientSurface::with_symmetry(SurfaceSymmetry symmetry) const {
  if (symmetry.empty()) {
    CoefficientSurface out = *this;
    out.symmetry_ = {};
    return out;
  }
  if (symmetry.axis_count() != axis_count() || symmetry.output_count() != output_count())
    throw InputError("a symmetry over " + std::to_string(symmetry.axis_count()) + " axes and " +
                     std::to_string(symmetry.output_count()) + " outputs was given to a surface of " +
                     std::to_string(axis_count()) + " axes and " + std::to_string(output_count()) +
                     " outputs; expected the surface's counts");
  if (output_count() > kMaxSymmetricOutputs || axis_count() > kMaxSymmetricAxes)
    throw InputError("a symmetry is imposed on surfaces of at most " + std::to_string(kMaxSymmetricOutputs) +
                     " outputs and " + std::to_string(kMaxSymmetricAxes) + " axes; this one has " +
                     std::to_string(output_count()) + " outputs");
  CoefficientSurface out = *this;
  if (grid_)
    if (auto values = symmetric_values(*grid_, symmetry))
      out.grid_ =
          std::make_shared<const GridTable>(grid_->axes(), grid_->outputs(), std::move(*values), grid_->method());
  out.symmetry_ = std::move(symmetry);
  return out;
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
