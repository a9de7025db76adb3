#include "src/fit/coefficient_curve.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <string>
#include <utility>

#include "src/core/dense_decompositions.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/surface/pchip.hpp"

namespace hydrocoef {
namespace {

struct Interval {
  std::size_t k;  // levels[k] <= level <= levels[k + 1]
  double h;
  double t;  // (level - levels[k]) / h, in [0, 1]
};

Interval locate(const std::vector<double>& levels, double level) {
  const auto above = std::upper_bound(levels.begin(), levels.end(), level);
  std::size_t k = static_cast<std::size_t>(above - levels.begin());
  k = std::clamp<std::size_t>(k, 1, levels.size() - 1) - 1;
  const double h = levels[k + 1] - levels[k];
  return {k, h, (level - levels[k]) / h};
}

void check_level(const CoefficientCurve& curve, double level) {
  const std::size_t needed = curve.kind == CurveKind::Pchip ? 2 : 1;
  if (curve.levels.size() < needed || curve.values.size() != curve.levels.size() ||
      (curve.kind == CurveKind::Polynomial && curve.polynomial.empty()))
    throw InputError("coefficient curve '" + curve.term + "' has " + std::to_string(curve.levels.size()) + " levels, " +
                     std::to_string(curve.values.size()) + " values and " + std::to_string(curve.polynomial.size()) +
                     " polynomial coefficients; expected a curve from fit_coefficient_curves");
  if (!(level >= curve.levels.front() && level <= curve.levels.back()))
    throw InputError("coefficient curve '" + curve.term + "' evaluated at disturbance level " + shortest_number(level) +
                     ", outside its fitted levels [" + shortest_number(curve.levels.front()) + ", " +
                     shortest_number(curve.levels.back()) +
                     "]; expected a level within that range (curves do not "
                     "extrapolate)");
}

std::vector<double> fit_polynomial(const std::vector<double>& levels, const std::vector<double>& values, int degree,
                                   const std::string& term) {
  const auto rows = static_cast<Eigen::Index>(levels.size());
  const auto cols = static_cast<Eigen::Index>(degree + 1);
  Eigen::MatrixXd design(rows, cols);
  for (Eigen::Index i = 0; i < rows; ++i) {
    double power = 1.0;
    for (Eigen::Index j = 0; j < cols; ++j) {
      design(i, j) = power;
      power *= levels[static_cast<std::size_t>(i)];
    }
  }
  // Scaled to unit-norm columns: level^j spans very different sizes for small or large levels.
  const Eigen::VectorXd column_norm = design.colwise().norm().transpose();
  const Eigen::VectorXd column_scale = (column_norm.array() > 0.0).select(column_norm, 1.0);
  const Eigen::MatrixXd scaled = design * column_scale.cwiseInverse().asDiagonal();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr = col_piv_householder_qr(scaled);
  qr.setThreshold(1e-12);
  if (qr.rank() < cols)
    throw InputError("coefficient curve '" + term + "': a degree-" + std::to_string(degree) +
                     " polynomial is not determined by the levels (rank " + std::to_string(qr.rank()) + " of " +
                     std::to_string(cols) + "); expected levels spread further apart, or a lower degree");
  const Eigen::Map<const Eigen::VectorXd> observed(values.data(), rows);
  const Eigen::VectorXd solution = qr.solve(observed);
  std::vector<double> polynomial(static_cast<std::size_t>(cols));
  for (Eigen::Index j = 0; j < cols; ++j) polynomial[static_cast<std::size_t>(j)] = solution(j) / column_scale(j);
  return polynomial;
}

}  // namespace

std::vector<LevelFit> fit_per_level(const DampingLawSpec& spec, std::span<const double> x, std::span<const double> y,
                                    std::span<const double> disturbance, const LossOptions& options,
                                    std::vector<SkippedLevel>* skipped) {
  if (x.size() != y.size() || x.size() != disturbance.size())
    throw InputError("per-level fit got " + std::to_string(x.size()) + " velocity values, " + std::to_string(y.size()) +
                     " force values and " + std::to_string(disturbance.size()) +
                     " disturbance values; expected one of each per run");
  const std::size_t n = x.size();
  if (n == 0) throw InputError("per-level fit got no runs; expected runs at two or more disturbance levels");
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(x[i]) || !std::isfinite(y[i]) || !std::isfinite(disturbance[i]))
      throw InputError("run " + std::to_string(i + 1) + " of " + std::to_string(n) + " has " + spec.variable + " = " +
                       shortest_number(x[i]) + ", force = " + shortest_number(y[i]) +
                       ", disturbance = " + shortest_number(disturbance[i]) + "; expected finite values");

  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return disturbance[a] < disturbance[b]; });

  std::vector<LevelFit> fits;
  std::vector<double> level_x;
  std::vector<double> level_y;
  for (std::size_t begin = 0; begin < n;) {
    const double level = disturbance[order[begin]] + 0.0;  // + 0.0 turns -0 into 0
    std::size_t end = begin;
    level_x.clear();
    level_y.clear();
    while (end < n && disturbance[order[end]] == level) {
      level_x.push_back(x[order[end]]);
      level_y.push_back(y[order[end]]);
      ++end;
    }
    const std::string runs = std::to_string(level_x.size()) + (level_x.size() == 1 ? " run" : " runs");
    begin = end;
    if (level_x.size() < spec.terms.size()) {
      const std::string why = runs + "; the damping law '" + format_damping_terms(spec) + "' has " +
                              std::to_string(spec.terms.size()) + " terms and needs at least " +
                              std::to_string(spec.terms.size()) + " runs at each level";
      if (!skipped) throw InputError("disturbance level " + shortest_number(level) + " has " + why);
      skipped->push_back({level, level_x.size(), why});
      continue;
    }
    try {
      fits.push_back({level, fit_damping_law(spec, level_x, level_y, options)});
    } catch (const InputError& error) {
      if (!skipped)
        throw InputError("at disturbance level " + shortest_number(level) + " (" + runs + "): " + error.what());
      skipped->push_back({level, level_x.size(), runs + ": " + error.what()});
    }
  }
  return fits;
}

std::vector<CoefficientCurve> fit_coefficient_curves(const std::vector<LevelFit>& levels, CurveKind kind, int degree) {
  if (kind == CurveKind::Polynomial && degree < 0)
    throw InputError("coefficient curve degree " + std::to_string(degree) + "; expected a degree >= 0");
  const std::size_t needed = kind == CurveKind::Pchip ? 2 : static_cast<std::size_t>(degree) + 1;
  const std::string what =
      kind == CurveKind::Pchip ? std::string("a PCHIP curve") : "a degree-" + std::to_string(degree) + " polynomial";
  if (levels.size() < needed)
    throw InputError(what + " needs at least " + std::to_string(needed) + " disturbance levels, found " +
                     std::to_string(levels.size()) + "; expected runs at more levels" +
                     (kind == CurveKind::Polynomial ? std::string(", or a lower degree") : std::string()));

  for (const LevelFit& entry : levels)
    if (!std::isfinite(entry.level))
      throw InputError("a per-level fit has disturbance level " + shortest_number(entry.level) +
                       "; expected a finite level");
  std::vector<std::size_t> order(levels.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return levels[a].level < levels[b].level; });

  const DampingLawSpec& spec = levels[order.front()].fit.spec;
  const std::string law = format_damping_terms(spec);
  for (std::size_t s = 0; s < order.size(); ++s) {
    const LevelFit& entry = levels[order[s]];
    if (s > 0 && entry.level == levels[order[s - 1]].level)
      throw InputError("disturbance level " + shortest_number(entry.level) +
                       " appears twice among the per-level fits; expected one fit per level");
    if (entry.fit.spec.variable != spec.variable || entry.fit.spec.terms != spec.terms)
      throw InputError("the fit at disturbance level " + shortest_number(entry.level) + " is of the law '" +
                       format_damping_terms(entry.fit.spec) + "' but the others are of '" + law +
                       "'; expected one law at every level");
    if (entry.fit.coefficients.size() != spec.terms.size())
      throw InputError("the fit at disturbance level " + shortest_number(entry.level) + " has " +
                       std::to_string(entry.fit.coefficients.size()) + " coefficients for " +
                       std::to_string(spec.terms.size()) + " terms; expected one per term");
    for (std::size_t j = 0; j < spec.terms.size(); ++j)
      if (!std::isfinite(entry.fit.coefficients[j]))
        throw InputError("coefficient of '" + term_name(spec.terms[j], spec.variable) + "' at disturbance level " +
                         shortest_number(entry.level) + " is " + shortest_number(entry.fit.coefficients[j]) +
                         "; expected a finite value");
  }

  std::vector<CoefficientCurve> curves;
  for (std::size_t j = 0; j < spec.terms.size(); ++j) {
    CoefficientCurve curve;
    curve.term = term_name(spec.terms[j], spec.variable);
    curve.kind = kind;
    curve.degree = kind == CurveKind::Pchip ? 3 : degree;
    for (std::size_t index : order) {
      curve.levels.push_back(levels[index].level);
      curve.values.push_back(levels[index].fit.coefficients[j]);
    }
    if (kind == CurveKind::Polynomial) {
      curve.polynomial = fit_polynomial(curve.levels, curve.values, degree, curve.term);
      double ssr = 0.0;
      for (std::size_t i = 0; i < curve.levels.size(); ++i) {
        const double residual = curve.evaluate(curve.levels[i]) - curve.values[i];
        ssr += residual * residual;
      }
      curve.rmse = std::sqrt(ssr / static_cast<double>(curve.levels.size()));
    }
    curves.push_back(std::move(curve));
  }
  return curves;
}

double CoefficientCurve::evaluate(double level) const {
  check_level(*this, level);
  if (kind == CurveKind::Polynomial) {
    // Horner, from the highest power down.
    return std::accumulate(polynomial.rbegin(), polynomial.rend(), 0.0,
                           [level](double sum, double coefficient) { return sum * level + coefficient; });
  }
  const Interval at = locate(levels, level);
  const double t = at.t;
  const double h00 = (1.0 + 2.0 * t) * (1.0 - t) * (1.0 - t);
  const double h10 = t * (1.0 - t) * (1.0 - t);
  const double h01 = t * t * (3.0 - 2.0 * t);
  const double h11 = t * t * (t - 1.0);
  return h00 * values[at.k] + h10 * at.h * pchip_slope(levels, values, at.k) + h01 * values[at.k + 1] +
         h11 * at.h * pchip_slope(levels, values, at.k + 1);
}

double CoefficientCurve::derivative(double level) const {
  check_level(*this, level);
  if (kind == CurveKind::Polynomial) {
    double slope = 0.0;
    for (std::size_t j = polynomial.size(); j-- > 1;) slope = slope * level + static_cast<double>(j) * polynomial[j];
    return slope;
  }
  const Interval at = locate(levels, level);
  const double t = at.t;
  const double d00 = 6.0 * t * (t - 1.0);
  const double d10 = (1.0 - t) * (1.0 - 3.0 * t);
  const double d01 = -d00;
  const double d11 = t * (3.0 * t - 2.0);
  return (d00 * values[at.k] + d01 * values[at.k + 1]) / at.h + d10 * pchip_slope(levels, values, at.k) +
         d11 * pchip_slope(levels, values, at.k + 1);
}

}  // namespace hydrocoef
