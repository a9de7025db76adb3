#include "src/uncertainty/gci.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "src/core/error.hpp"

namespace hydrocoef {

std::string_view grid_convergence_name(GridConvergence kind) {
  switch (kind) {
    case GridConvergence::Monotonic: return "monotonic";
    case GridConvergence::Oscillatory: return "oscillatory";
    case GridConvergence::Converged: return "converged";
    case GridConvergence::NotFound: return "not found";
  }
  return "unknown";
}

double GciResult::uncertainty(double phi1) const { return gci_fine * std::abs(phi1); }

double representative_cell_size(double cells, double volume, int dimension) {
  if (!(cells >= 1.0) || !std::isfinite(cells) || !(volume > 0.0) || !std::isfinite(volume) || dimension < 1 ||
      dimension > 3)
    throw InputError("representative cell size: expected at least 1 cell, a positive volume and dimension 1, 2 or 3");
  return std::pow(volume / cells, 1.0 / dimension);
}

GciResult grid_convergence_index(const std::array<double, 3>& h, const std::array<double, 3>& phi,
                                 double safety_factor) {
  for (std::size_t i = 0; i < 3; ++i)
    if (!(h[i] > 0.0) || !std::isfinite(h[i]) || !std::isfinite(phi[i]))
      throw InputError("grid convergence: cell sizes must be finite and positive, values finite");
  if (!(h[0] < h[1] && h[1] < h[2]))
    throw InputError("grid convergence: expected cell sizes from the finest to the coarsest mesh (h1 < h2 < h3)");
  GciResult out;
  out.r21 = h[1] / h[0];
  out.r32 = h[2] / h[1];
  if (out.r21 < 1.3 || out.r32 < 1.3)
    out.note = "refinement ratios below 1.3 (Celik et al. recommend more, so that discretization error stands out)";
  const double e21 = phi[1] - phi[0], e32 = phi[2] - phi[1];
  const double scale = std::max({std::abs(phi[0]), std::abs(phi[1]), std::abs(phi[2]), 1e-300});
  const double round_off = 64 * std::numeric_limits<double>::epsilon() * scale;
  if (std::abs(e21) <= round_off) {
    out.convergence = GridConvergence::Converged;
    out.extrapolated = out.extrapolated32 = phi[0];
    out.note = "the two finest meshes agree to round-off: no discretization error can be estimated from them";
    return out;
  }
  if (std::abs(e32) <= round_off) {
    out.convergence = GridConvergence::NotFound;
    out.note = "the two coarsest meshes agree but the finest differs: no apparent order";
    return out;
  }
  const double s = (e32 / e21) > 0 ? 1.0 : -1.0;
  const double log_ratio = std::log(std::abs(e32 / e21));
  const double ln_r21 = std::log(out.r21);
  // Fixed-point iteration of step 3, started from q = 0 (equal ratios).
  double p = std::abs(log_ratio) / ln_r21;
  bool found = false;
  for (int k = 1; k <= 1000; ++k) {
    const double a = std::pow(out.r21, p) - s, b = std::pow(out.r32, p) - s;
    if (!(a > 0.0 && b > 0.0)) break;  // q(p) undefined: the iteration left its domain
    const double next = std::abs(log_ratio + std::log(a / b)) / ln_r21;
    out.iterations = k;
    if (!std::isfinite(next)) break;
    if (std::abs(next - p) <= 1e-14 * std::max(1.0, next)) {
      p = next;
      found = true;
      break;
    }
    p = next;
  }
  if (!found || p <= 0.0) {
    out.convergence = GridConvergence::NotFound;
    out.note = "the apparent order did not converge (the levels are not in the asymptotic range)";
    return out;
  }
  out.convergence = s > 0 ? GridConvergence::Monotonic : GridConvergence::Oscillatory;
  out.apparent_order = p;
  const double r21p = std::pow(out.r21, p), r32p = std::pow(out.r32, p);
  out.extrapolated = (r21p * phi[0] - phi[1]) / (r21p - 1.0);
  out.extrapolated32 = (r32p * phi[1] - phi[2]) / (r32p - 1.0);
  out.relative_error = std::abs(e21 / phi[0]);
  out.extrapolated_relative_error = std::abs((out.extrapolated - phi[0]) / out.extrapolated);
  out.gci_fine = safety_factor * out.relative_error / (r21p - 1.0);
  out.gci_medium = safety_factor * std::abs(e32 / phi[1]) / (r32p - 1.0);
  out.asymptotic_ratio = out.gci_medium / (r21p * out.gci_fine);
  return out;
}

}  // namespace hydrocoef
