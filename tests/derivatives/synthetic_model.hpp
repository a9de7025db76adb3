// Test support for the derivative-model tests: an Abkowitz-like sway force
// with thirteen cross-coupled terms over (u, v, r, delta), a seeded Latin
// hypercube of runs over given ranges, and runs generated from known
// coefficients with optional Gaussian noise of known sigma.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "src/derivatives/design_matrix.hpp"
#include "src/derivatives/terms.hpp"

namespace hydrocoef::test {

/// Y over (u, v, r, delta): linear, cubic and cross terms, x*|x| drag terms.
inline constexpr const char* kSwayTerms =
    "v, r, delta, v^3, v^2*r, v*r^2, r^3, u*v, u*r, u^2*delta, v*|v|, r*|r|, delta^3";
/// Its true coefficients [N over the term's unit], in kSwayTerms' order.
inline const std::vector<double> kSwayCoefficients = {-310.0, 95.0, 180.0, -420.0, 260.0, -150.0, -35.0,
                                                      -45.0,  21.0, 38.0,  -520.0, -60.0, -55.0};

/// A range per name: name -> (low, high).
using Ranges = std::map<std::string, std::pair<double, double>>;

/// The ranges of a captive test about u = 2 m/s: u 1.5..2.5 m/s, drift
/// v -0.5..0.5 m/s, yaw rate -0.3..0.3 rad/s, rudder -0.6..0.6 rad.
inline Ranges sway_ranges() {
  return {{"u", {1.5, 2.5}}, {"v", {-0.5, 0.5}}, {"r", {-0.3, 0.3}}, {"delta", {-0.6, 0.6}}};
}

/// n points of a Latin hypercube over the ranges: each name's range cut in n
/// strata, one point in each, the strata of different names paired by
/// independent seeded permutations.
inline std::vector<std::map<std::string, double>> latin_hypercube(const Ranges& ranges, std::size_t n,
                                                                  std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::map<std::string, double>> points(n);
  for (const auto& [name, range] : ranges) {
    std::vector<std::size_t> strata(n);
    for (std::size_t i = 0; i < n; ++i) strata[i] = i;
    std::shuffle(strata.begin(), strata.end(), random);
    for (std::size_t i = 0; i < n; ++i)
      points[i][name] = range.first + (range.second - range.first) * (static_cast<double>(strata[i]) + unit(random)) /
                                          static_cast<double>(n);
  }
  return points;
}

/// Runs at the points with output sum_k c_k t_k(point) plus Gaussian noise
/// of standard deviation sigma_of(point) (none when it returns 0); each run
/// states that sigma when state_sigma is true.
template <class SigmaOf>
std::vector<DerivativeRun> make_runs(const std::vector<Term>& terms, const std::vector<double>& coefficients,
                                     const std::vector<std::map<std::string, double>>& points, SigmaOf sigma_of,
                                     std::mt19937_64& random, bool state_sigma) {
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<DerivativeRun> runs;
  for (const auto& point : points) {
    DerivativeRun run;
    run.values = point;
    for (std::size_t k = 0; k < terms.size(); ++k) run.output += coefficients[k] * terms[k].evaluate(point);
    const double sigma = sigma_of(point);
    if (sigma > 0.0) run.output += sigma * normal(random);
    if (state_sigma) run.sigma = sigma;
    runs.push_back(std::move(run));
  }
  return runs;
}

/// Noise-free runs.
inline std::vector<DerivativeRun> exact_runs(const std::vector<Term>& terms, const std::vector<double>& coefficients,
                                             const std::vector<std::map<std::string, double>>& points) {
  std::mt19937_64 unused(0);
  return make_runs(
      terms, coefficients, points, [](const std::map<std::string, double>&) { return 0.0; }, unused, false);
}

}  // namespace hydrocoef::test
