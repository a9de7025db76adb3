#include "src/fit/physical_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "src/core/sign_convention.hpp"

namespace hydrocoef {
namespace {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

/// q(x) = a + b x + c x^2 on one side of 0: F·x = x^2 q(x) there.
struct SideQuadratic {
  double a = 0.0, b = 0.0, c = 0.0;
  double at(double x) const { return a + x * (b + c * x); }
};

/// The largest s x^2 q(x) over [lo, hi] (one side of 0) and where: at an
/// end or where its derivative x (2a + 3b x + 4c x^2) vanishes.
std::pair<double, double> largest_power(const SideQuadratic& q, double lo, double hi, double s) {
  std::vector<double> candidates{lo, hi};
  const double A = 4.0 * q.c, B = 3.0 * q.b, C = 2.0 * q.a;
  if (A != 0.0) {
    const double discriminant = B * B - 4.0 * A * C;
    if (discriminant >= 0.0) {
      const double root = std::sqrt(discriminant);
      candidates.push_back((-B + root) / (2.0 * A));
      candidates.push_back((-B - root) / (2.0 * A));
    }
  } else if (B != 0.0) {
    candidates.push_back(-C / B);
  }
  double best = -INFINITY, where = lo;
  for (const double x : candidates) {
    if (!(x >= lo && x <= hi)) continue;
    const double power = s * q.at(x) * x * x;
    if (power > best) best = power, where = x;
  }
  return {best, where};
}

}  // namespace

std::string_view law_problem_name(LawProblem problem) {
  switch (problem) {
    case LawProblem::EnergyProducing: return "energy-producing";
    case LawProblem::ForceAtRest: return "force-at-rest";
    case LawProblem::SignContradictsRuns: return "sign-contradicts-runs";
  }
  return "unknown";
}

std::vector<LawCheck> check_damping_law(const LawCheckInput& input) {
  std::vector<LawCheck> out;
  // On the body, damping opposes motion: F·x <= 0. An opposing-convention
  // law is the negative of the force on the body.
  const double s = sign_factor(input.sign, SignConvention::OnBody);
  const std::string& x_name = input.spec.variable;

  SideQuadratic positive, negative;
  double constant = 0.0, constant_error = NAN;
  for (std::size_t k = 0; k < input.spec.terms.size() && k < input.coefficients.size(); ++k) {
    const double c = input.coefficients[k];
    switch (input.spec.terms[k]) {
      case DampingTerm::Constant:
        constant = c;
        if (k < input.std_errors.size()) constant_error = input.std_errors[k];
        break;
      case DampingTerm::Linear: positive.a += c, negative.a += c; break;
      case DampingTerm::AbsLinear: positive.a += c, negative.a -= c; break;
      case DampingTerm::SignedQuadratic: positive.b += c, negative.b -= c; break;
      case DampingTerm::Quadratic: positive.b += c, negative.b += c; break;
      case DampingTerm::Cubic: positive.c += c, negative.c += c; break;
    }
  }

  // The scale of the power over the range, for a tolerance that ignores
  // round-off: |F·x| of each term at the range's ends.
  const double reach = std::max(std::abs(input.x_min), std::abs(input.x_max));
  double scale = 0.0;
  for (std::size_t k = 0; k < input.spec.terms.size() && k < input.coefficients.size(); ++k)
    if (input.spec.terms[k] != DampingTerm::Constant)
      scale = std::max(scale, std::abs(input.coefficients[k] * basis_value(input.spec.terms[k], reach) * reach));
  const double tolerance = 1e-12 * scale;

  double worst = -INFINITY, worst_x = 0.0;
  if (input.x_max > 0.0) {
    const auto [power, x] = largest_power(positive, std::max(0.0, input.x_min), input.x_max, s);
    if (power > worst) worst = power, worst_x = x;
  }
  if (input.x_min < 0.0) {
    const auto [power, x] = largest_power(negative, input.x_min, std::min(0.0, input.x_max), s);
    if (power > worst) worst = power, worst_x = x;
  }
  if (worst > tolerance && worst_x != 0.0) {
    out.push_back({LawProblem::EnergyProducing,
                   "the law feeds energy into the motion: F·" + x_name + " = " + number(worst) + " W" +
                       (x_name == "u" || x_name == "v" || x_name == "w" ? "" : " (N m rad/s)") + " > 0 at " + x_name +
                       " = " + number(worst_x) + " within the fitted range [" + number(input.x_min) + ", " +
                       number(input.x_max) + "]; a damping force must oppose the motion"});
  }

  if (constant != 0.0 && std::isfinite(constant_error) && std::abs(constant) > constant_error) {
    out.push_back({LawProblem::ForceAtRest, "the constant term " + number(constant) +
                                                " is larger than its standard error " + number(constant_error) +
                                                ": the law holds a force at rest (" + x_name + " = 0)"});
  }

  if (!input.x.empty() && input.x.size() == input.y.size()) {
    double power = 0.0, magnitude = 0.0;
    for (std::size_t i = 0; i < input.x.size(); ++i) {
      power += s * input.y[i] * input.x[i];
      magnitude += std::abs(input.y[i] * input.x[i]);
    }
    if (magnitude > 0.0 && power > 0.5 * magnitude) {
      out.push_back({LawProblem::SignContradictsRuns,
                     std::string("the runs' forces push along the motion (sum of F·") + x_name + " > 0) for the '" +
                         std::string(to_string(input.sign)) +
                         "' convention they are stored in; were they imported with the other --sign?"});
    }
  }
  return out;
}

}  // namespace hydrocoef
