#include "src/surface/surface_checks.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/run.hpp"

namespace hydrocoef {
namespace {

constexpr std::size_t kMostPoints = 20000;
constexpr std::size_t kMostPerAxis = 41;

/// The velocity index of an output's own motion (X -> u ... N -> r).
std::optional<std::size_t> force_index_of(const std::string& output) {
  for (std::size_t i = 0; i < kForceNames.size(); ++i)
    if (output == kForceNames[i]) return i;
  return std::nullopt;
}

}  // namespace

std::optional<SurfaceProblem> dissipativity_problem(const CoefficientSurface& surface, std::size_t output,
                                                    std::size_t axis, double on_body) {
  const auto& axes = surface.axis_names();
  const auto& outputs = surface.output_names();
  const std::size_t d = axes.size();
  // Points per axis: at most kMostPerAxis, and at most kMostPoints in all.
  std::size_t per_axis = kMostPerAxis;
  while (per_axis > 2 && std::pow(static_cast<double>(per_axis), static_cast<double>(d)) > kMostPoints) --per_axis;
  std::size_t total = 1;
  for (std::size_t a = 0; a < d; ++a) total *= per_axis;
  double largest = 0.0, scale = 0.0, value_at = 0.0;
  std::vector<double> point(d), values(outputs.size()), where;
  for (std::size_t index = 0; index < total; ++index) {
    std::size_t rest = index;
    for (std::size_t a = 0; a < d; ++a) {
      const std::size_t i = rest % per_axis;
      const double t = static_cast<double>(i) / static_cast<double>(per_axis - 1);
      // The ends exactly (a sum can round past the upper end, which a surface
      // whose policy is error refuses).
      point[a] = i + 1 == per_axis
                     ? surface.upper(a)
                     : std::min(surface.upper(a), surface.lower(a) + (surface.upper(a) - surface.lower(a)) * t);
      rest /= per_axis;
    }
    surface.evaluate(point, values);
    const double power = on_body * values[output] * point[axis];
    scale = std::max(scale, std::abs(values[output]) * std::abs(point[axis]));
    if (power > largest) largest = power, where = point, value_at = values[output];
  }
  if (!(largest > 1e-9 * scale) || where.empty()) return std::nullopt;
  std::string at;
  for (std::size_t b = 0; b < d; ++b)
    at += (b ? ", " : "") + escape::one_line(axes[b]) + "=" + shortest_number(where[b]);
  return SurfaceProblem{outputs[output], axes[axis],
                        escape::one_line(outputs[output]) + " feeds energy into the motion along " +
                            escape::one_line(axes[axis]) + ": at " + at + " it is " + shortest_number(value_at) +
                            (on_body > 0.0 ? " (on the body)" : " (positive opposing the motion)") + ", power " +
                            shortest_number(largest) + " > 0 (a damping force opposes the motion)"};
}

std::vector<SurfaceProblem> dissipativity_problems(const CoefficientSurface& surface, double on_body) {
  std::vector<SurfaceProblem> out;
  const auto& axes = surface.axis_names();
  const auto& outputs = surface.output_names();
  for (std::size_t k = 0; k < outputs.size(); ++k)
    if (const auto dof = force_index_of(outputs[k]))
      for (std::size_t a = 0; a < axes.size(); ++a)
        if (axes[a] == kVelocityNames[*dof])
          if (auto problem = dissipativity_problem(surface, k, a, on_body)) out.push_back(std::move(*problem));
  return out;
}

}  // namespace hydrocoef
