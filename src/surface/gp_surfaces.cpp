#include "src/surface/gp_surfaces.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "src/core/error.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef {
namespace {

constexpr std::size_t kMaxAxes = 6;

std::string label(const std::vector<std::string>& names, std::size_t axis) {
  return axis < names.size() && !names[axis].empty() ? names[axis] : "axis " + std::to_string(axis);
}

}  // namespace

GpSurfaces::GpSurfaces(std::size_t axes, std::span<const double> x, std::size_t outputs, std::span<const double> y,
                       std::span<const double> noise_sd, const GpOptions& options, std::vector<std::string> axis_names,
                       std::vector<RbfOutOfRange> out_of_range)
    : axis_names_(std::move(axis_names)), policy_(std::move(out_of_range)) {
  if (axes == 0 || axes > kMaxAxes || outputs == 0 || outputs > 6)
    throw InputError("GP surface: " + std::to_string(axes) + " axes and " + std::to_string(outputs) +
                     " outputs; expected 1 to 6 of each");
  if (x.size() % axes != 0 || y.size() != x.size() / axes * outputs ||
      (!noise_sd.empty() && noise_sd.size() != y.size()))
    throw InputError("GP surface: " + std::to_string(x.size()) + " coordinates, " + std::to_string(y.size()) +
                     " values and " + std::to_string(noise_sd.size()) + " uncertainties do not make runs of " +
                     std::to_string(axes) + " axes and " + std::to_string(outputs) + " outputs");
  const std::size_t n = x.size() / axes;
  if (n > kMaxSamples)
    throw InputError("GP surface: " + std::to_string(n) + " runs; at most " + std::to_string(kMaxSamples) +
                     " are supported (dense O(n^3) solve)");
  if (policy_.empty()) policy_.assign(axes, RbfOutOfRange::Error);
  lower_.assign(axes, INFINITY);
  upper_.assign(axes, -INFINITY);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t a = 0; a < axes; ++a) {
      lower_[a] = std::min(lower_[a], x[i * axes + a]);
      upper_[a] = std::max(upper_[a], x[i * axes + a]);
    }
  std::vector<double> column(n), noise(noise_sd.empty() ? 0 : n);
  for (std::size_t k = 0; k < outputs; ++k) {
    for (std::size_t i = 0; i < n; ++i) column[i] = y[i * outputs + k];
    for (std::size_t i = 0; i < noise.size(); ++i) noise[i] = noise_sd[i * outputs + k];
    try {
      outputs_.push_back(GpSurface::fit(x, axes, column, noise, options));
    } catch (const InputError& error) {
      throw InputError("output " + std::to_string(k) + ": " + error.what());
    }
  }
  check();
}

GpSurfaces::GpSurfaces(std::vector<GpSurface> outputs, std::vector<double> lower, std::vector<double> upper,
                       std::vector<std::string> axis_names, std::vector<RbfOutOfRange> out_of_range)
    : outputs_(std::move(outputs)),
      lower_(std::move(lower)),
      upper_(std::move(upper)),
      axis_names_(std::move(axis_names)),
      policy_(std::move(out_of_range)) {
  check();
}

void GpSurfaces::check() const {
  const std::size_t d = lower_.size();
  if (outputs_.empty() || outputs_.size() > 6 || d == 0 || d > kMaxAxes)
    throw InputError("GP surface: " + std::to_string(outputs_.size()) + " outputs over " + std::to_string(d) +
                     " axes; expected 1 to 6 of each");
  if (upper_.size() != d || policy_.size() != d || axis_names_.size() != d)
    throw InputError("GP surface: ranges, policies and names do not give one per axis");
  for (std::size_t a = 0; a < d; ++a)
    if (!std::isfinite(lower_[a]) || !std::isfinite(upper_[a]) || !(upper_[a] > lower_[a]))
      throw InputError("GP surface: the range of " + label(axis_names_, a) +
                       " is not two finite numbers, lower < upper");
  for (const GpSurface& output : outputs_)
    if (output.dims() != d || output.samples() != outputs_.front().samples())
      throw InputError("GP surface: its outputs are not over the same " + std::to_string(d) + " axes and runs");
}

void GpSurfaces::place(std::span<const double> point, double* x, bool* clamped) const {
  const std::size_t d = axis_count();
  for (std::size_t a = 0; a < d; ++a) {
    x[a] = point[a];
    clamped[a] = false;
    if (!std::isfinite(x[a]))
      throw InputError("GP query has " + label(axis_names_, a) + " = " + shortest_number(x[a]) +
                       "; expected a finite value");
    if (x[a] >= lower_[a] && x[a] <= upper_[a]) continue;
    switch (policy_[a]) {
      case RbfOutOfRange::Error:
        throw InputError("GP query " + label(axis_names_, a) + " = " + shortest_number(x[a]) +
                         " is outside the runs' range [" + shortest_number(lower_[a]) + ", " +
                         shortest_number(upper_[a]) +
                         "]; expected a value within it (or --extrapolate clamp or extrapolate for that axis)");
      case RbfOutOfRange::Clamp:
        x[a] = std::clamp(x[a], lower_[a], upper_[a]);
        clamped[a] = true;
        break;
      case RbfOutOfRange::Extrapolate: break;
    }
  }
}

GpSurface::Workspace& GpSurfaces::workspace() const {
  // One workspace per thread, grown to the largest surface it has served.
  thread_local std::optional<GpSurface::Workspace> workspace;
  if (!workspace || workspace->capacity() < sample_count()) workspace.emplace(outputs_.front());
  return *workspace;
}

void GpSurfaces::combination_standard_deviation(std::span<const double> points, std::size_t count,
                                                std::span<const double> coefficients,
                                                std::span<double> standard_deviation) const {
  constexpr std::size_t kMaxPoints = 8;
  const std::size_t d = axis_count(), k_count = output_count();
  if (count == 0 || count > kMaxPoints || points.size() != count * d || coefficients.size() != count * k_count ||
      standard_deviation.size() != k_count)
    throw std::invalid_argument("GpSurfaces::combination_standard_deviation: buffers of the wrong size");
  std::array<double, kMaxPoints * kMaxAxes> x{};
  std::array<bool, kMaxAxes> clamped{};
  for (std::size_t j = 0; j < count; ++j) place(points.subspan(j * d, d), x.data() + j * d, clamped.data());
  auto& ws = workspace();
  std::array<double, kMaxPoints> c{};
  for (std::size_t k = 0; k < k_count; ++k) {
    for (std::size_t j = 0; j < count; ++j) c[j] = coefficients[j * k_count + k];
    standard_deviation[k] = outputs_[k].combination_sd(x.data(), c.data(), count, ws);
  }
}

void GpSurfaces::evaluate(std::span<const double> point, std::span<double> out, std::span<double> standard_deviation,
                          std::span<double> gradient) const {
  const std::size_t d = axis_count(), k_count = output_count();
  if (point.size() != d)
    throw InputError("GP query point has " + std::to_string(point.size()) + " coordinates; the surface has " +
                     std::to_string(d) + " axes");
  if (out.size() != k_count || (!standard_deviation.empty() && standard_deviation.size() != k_count) ||
      (!gradient.empty() && gradient.size() != k_count * d))
    throw std::invalid_argument("GpSurfaces::evaluate: output buffers of the wrong size");
  std::array<double, kMaxAxes> x{};
  std::array<bool, kMaxAxes> clamped{};
  place(point, x.data(), clamped.data());
  GpSurface::Workspace& ws = workspace();
  std::array<double, kMaxAxes> slope{};
  for (std::size_t k = 0; k < k_count; ++k) {
    double sd = 0.0;
    out[k] = outputs_[k].evaluate(x.data(), ws, standard_deviation.empty() ? nullptr : &sd,
                                  gradient.empty() ? nullptr : slope.data());
    if (!standard_deviation.empty()) standard_deviation[k] = sd;
    if (!gradient.empty())
      for (std::size_t a = 0; a < d; ++a) gradient[k * d + a] = clamped[a] ? 0.0 : slope[a];
  }
}

}  // namespace hydrocoef
