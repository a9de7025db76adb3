#include "src/surface/gp_design.hpp"

#include <algorithm>
#include <cmath>

#include "src/core/error.hpp"

namespace hydrocoef {

std::vector<double> halton_point(std::size_t i, std::size_t dims) {
  static constexpr unsigned kBases[6] = {2, 3, 5, 7, 11, 13};
  std::vector<double> out(dims);
  for (std::size_t a = 0; a < dims && a < 6; ++a) {
    double f = 1.0, r = 0.0;
    for (std::size_t k = i + 1; k > 0; k /= kBases[a]) {
      f /= kBases[a];
      r += f * static_cast<double>(k % kBases[a]);
    }
    out[a] = r;
  }
  return out;
}

namespace {

/// Candidates: the corners of the box, then a Halton sequence through it
/// (point-major, `count` points).
std::vector<double> candidate_points(const std::vector<double>& lower, const std::vector<double>& upper,
                                     std::size_t count) {
  const std::size_t d = lower.size();
  std::vector<double> points;
  const std::size_t corners = std::size_t{1} << d;
  for (std::size_t c = 0; c < corners && c < count; ++c)
    for (std::size_t a = 0; a < d; ++a) points.push_back((c >> a) & 1 ? upper[a] : lower[a]);
  for (std::size_t i = 0; points.size() < count * d; ++i) {
    const auto h = halton_point(i, d);
    for (std::size_t a = 0; a < d; ++a) points.push_back(lower[a] + h[a] * (upper[a] - lower[a]));
  }
  return points;
}

void check_box(const GpSurface& surface, const std::vector<double>& lower, const std::vector<double>& upper) {
  const std::size_t d = surface.dims();
  if (lower.size() != d || upper.size() != d)
    throw InputError("suggest: " + std::to_string(lower.size()) + " bounds for a surface of " + std::to_string(d) +
                     " axes");
  for (std::size_t a = 0; a < d; ++a)
    if (!std::isfinite(lower[a]) || !std::isfinite(upper[a]) || !(lower[a] < upper[a]))
      throw InputError("suggest: the bounds of axis " + std::to_string(a) + " must be finite with lower < upper");
}

}  // namespace

std::vector<SuggestedRun> largest_standard_deviations(const GpSurface& surface, const std::vector<double>& lower,
                                                      const std::vector<double>& upper, std::size_t count,
                                                      std::size_t candidates) {
  check_box(surface, lower, upper);
  const std::size_t d = surface.dims();
  candidates = std::max(candidates, count);
  const std::vector<double> points = candidate_points(lower, upper, candidates);
  GpSurface::Workspace workspace(surface);
  std::vector<SuggestedRun> all;
  for (std::size_t c = 0; c < candidates; ++c) {
    double sd = 0.0;
    surface.evaluate(&points[c * d], workspace, &sd);
    all.push_back({std::vector<double>(points.begin() + static_cast<std::ptrdiff_t>(c * d),
                                       points.begin() + static_cast<std::ptrdiff_t>((c + 1) * d)),
                   sd});
  }
  const std::size_t keep = std::min(count, all.size());
  std::partial_sort(
      all.begin(), all.begin() + static_cast<std::ptrdiff_t>(keep), all.end(),
      [](const SuggestedRun& a, const SuggestedRun& b) { return a.standard_deviation > b.standard_deviation; });
  all.resize(keep);
  return all;
}

namespace {

/// Adds x and its distinct images under the reflections as pseudo-runs.
void add_with_images(GpSurface& design, const double* x, const std::vector<std::vector<double>>& reflections) {
  const std::size_t d = design.dims();
  std::vector<std::vector<double>> added{std::vector<double>(x, x + d)};
  design.add_pseudo_run(x);
  for (const auto& signs : reflections) {
    std::vector<double> image(d);
    for (std::size_t a = 0; a < d; ++a) image[a] = signs[a] * x[a];
    // A point on the mirror plane is its own image: a second run there adds nothing.
    if (std::find(added.begin(), added.end(), image) != added.end()) continue;
    design.add_pseudo_run(image.data());
    added.push_back(std::move(image));
  }
}

}  // namespace

std::vector<SuggestedRun> suggest_among_candidates(const GpSurface& surface, std::span<const double> candidates,
                                                   std::size_t count, const DesignContext& context,
                                                   double* largest_sd_after) {
  const std::size_t d = surface.dims();
  if (count == 0 || count > 1000) throw InputError("suggest: count must be 1 to 1000");
  if (candidates.size() % d != 0 || context.in_flight.size() % d != 0)
    throw InputError("suggest: candidate points of " + std::to_string(d) + " coordinates expected");
  for (const auto& signs : context.reflections)
    if (signs.size() != d) throw InputError("suggest: a reflection of " + std::to_string(d) + " signs expected");
  const std::size_t n = candidates.size() / d;
  if (n < count) throw InputError("suggest: fewer candidate points than runs asked for");

  GpSurface design = surface;
  for (std::size_t i = 0; i < context.in_flight.size(); i += d)
    add_with_images(design, &context.in_flight[i], context.reflections);
  std::vector<bool> taken(n, false);
  std::vector<SuggestedRun> out;
  for (std::size_t k = 0; k < count; ++k) {
    GpSurface::Workspace workspace(design);
    double best = -1.0;
    std::size_t best_index = 0;
    for (std::size_t c = 0; c < n; ++c) {
      if (taken[c]) continue;
      double sd = 0.0;
      design.evaluate(&candidates[c * d], workspace, &sd);
      if (sd > best) best = sd, best_index = c;
    }
    taken[best_index] = true;
    const double* x = &candidates[best_index * d];
    out.push_back({std::vector<double>(x, x + d), best});
    add_with_images(design, x, context.reflections);
  }
  if (largest_sd_after) {
    GpSurface::Workspace workspace(design);
    *largest_sd_after = 0.0;
    for (std::size_t c = 0; c < n; ++c) {
      double sd = 0.0;
      design.evaluate(&candidates[c * d], workspace, &sd);
      *largest_sd_after = std::max(*largest_sd_after, sd);
    }
  }
  return out;
}

std::vector<SuggestedRun> suggest_gp_runs(const GpSurface& surface, const std::vector<double>& lower,
                                          const std::vector<double>& upper, std::size_t count, std::size_t candidates,
                                          double* largest_sd_after) {
  check_box(surface, lower, upper);
  if (count == 0 || count > 1000) throw InputError("suggest: count must be 1 to 1000");
  if (candidates < count) throw InputError("suggest: fewer candidate points than runs asked for");
  const std::vector<double> points = candidate_points(lower, upper, candidates);
  return suggest_among_candidates(surface, points, count, {}, largest_sd_after);
}

}  // namespace hydrocoef
