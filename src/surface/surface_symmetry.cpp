#include "src/surface/surface_symmetry.hpp"

#include <algorithm>
#include <stdexcept>

#include "src/core/error.hpp"
#include "src/core/text.hpp"

namespace hydrocoef {
namespace {

void check_signs(const std::vector<double>& signs, std::size_t expected, const char* what, std::size_t generator) {
  if (signs.size() != expected)
    throw InputError("surface symmetry: reflection " + std::to_string(generator + 1) + " has " +
                     std::to_string(signs.size()) + " " + what + " signs; expected " + std::to_string(expected));
  for (const double s : signs)
    if (s != 1.0 && s != -1.0)
      throw InputError("surface symmetry: reflection " + std::to_string(generator + 1) + " has a " + what +
                       " sign that is not +1 or -1; expected +1 or -1");
}

bool flips_any(const std::vector<double>& signs) {
  return std::any_of(signs.begin(), signs.end(), [](double s) { return s < 0.0; });
}

}  // namespace

SurfaceSymmetry::SurfaceSymmetry(std::size_t axes, std::size_t outputs, std::vector<SurfaceReflection> generators)
    : axes_(axes), outputs_(outputs) {
  std::vector<SurfaceReflection> moving, still;
  for (std::size_t j = 0; j < generators.size(); ++j) {
    auto& g = generators[j];
    check_signs(g.axis_signs, axes, "axis", j);
    check_signs(g.output_signs, outputs, "output", j);
    if (!flips_any(g.axis_signs) && !flips_any(g.output_signs)) continue;  // the identity here
    auto same = [&](const SurfaceReflection& other) {
      return other.axis_signs == g.axis_signs && other.output_signs == g.output_signs;
    };
    if (std::any_of(moving.begin(), moving.end(), same) || std::any_of(still.begin(), still.end(), same))
      throw InputError("surface symmetry: reflection " + std::to_string(j + 1) +
                       " repeats another; expected each plane once");
    (flips_any(g.axis_signs) ? moving : still).push_back(std::move(g));
  }
  if (moving.size() + still.size() > kMaxGenerators)
    throw InputError("surface symmetry: " + std::to_string(moving.size() + still.size()) +
                     " reflections; expected at most " + std::to_string(kMaxGenerators));
  moving_ = moving.size();
  generators_ = std::move(moving);
  for (auto& g : still) generators_.push_back(std::move(g));
}

void SurfaceSymmetry::reflect(std::size_t generator, std::span<const double> x, std::span<double> image) const {
  const auto& signs = generators_.at(generator).axis_signs;
  if (x.size() != axes_ || image.size() != axes_)
    throw std::invalid_argument("SurfaceSymmetry::reflect: a point of the wrong size");
  for (std::size_t a = 0; a < axes_; ++a) image[a] = signs[a] < 0.0 && x[a] != 0.0 ? -x[a] : x[a];
}

std::string SurfaceSymmetry::describe(const std::vector<std::string>& axis_names,
                                      const std::vector<std::string>& output_names) const {
  std::vector<std::string> parts;
  for (const auto& g : generators_) {
    std::vector<std::string> flipped, odd;
    for (std::size_t a = 0; a < g.axis_signs.size() && a < axis_names.size(); ++a)
      if (g.axis_signs[a] < 0.0) flipped.push_back(axis_names[a]);
    for (std::size_t k = 0; k < g.output_signs.size() && k < output_names.size(); ++k)
      if (g.output_signs[k] < 0.0) odd.push_back(output_names[k]);
    parts.push_back((flipped.empty() ? std::string("no axis") : join(flipped, ",")) +
                    " reflected: " + (odd.empty() ? std::string("all outputs even") : join(odd, ", ") + " odd"));
  }
  return join(parts, "; ");
}

}  // namespace hydrocoef
