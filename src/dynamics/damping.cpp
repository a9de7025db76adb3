#include "src/dynamics/damping.hpp"

#include "src/surface/surface_checks.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "src/core/error.hpp"
#include "src/core/sign_convention.hpp"

namespace hydrocoef {
namespace {

// The shared kernel's law codes are DampingTerm's values.
static_assert(static_cast<int>(DampingTerm::Constant) == HC_DAMPING_CONSTANT &&
              static_cast<int>(DampingTerm::Linear) == HC_DAMPING_LINEAR &&
              static_cast<int>(DampingTerm::SignedQuadratic) == HC_DAMPING_SIGNED_QUADRATIC &&
              static_cast<int>(DampingTerm::Quadratic) == HC_DAMPING_QUADRATIC &&
              static_cast<int>(DampingTerm::Cubic) == HC_DAMPING_CUBIC &&
              static_cast<int>(DampingTerm::AbsLinear) == HC_DAMPING_ABS_LINEAR);

std::string dof_context(std::size_t dof) { return "damping of " + std::string(kForceNames[dof]); }

// The source name bound to each axis of a surface: the explicit binding or
// the axis's own name.
std::vector<std::string> axis_bindings(const CoefficientSurface& surface, const DofDamping& damping, std::size_t dof) {
  for (const auto& [axis, source] : damping.axis_sources) {
    const auto& names = surface.axis_names();
    if (std::find(names.begin(), names.end(), axis) == names.end()) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      throw InputError(dof_context(dof) + ": surface '" + damping.surface + "' has no axis '" + axis +
                       "' (its axes: " + list + ")");
    }
    if (source.empty()) throw InputError(dof_context(dof) + ": axis '" + axis + "' is bound to an empty name");
  }
  std::vector<std::string> out;
  for (const auto& axis : surface.axis_names()) {
    const auto it = damping.axis_sources.find(axis);
    out.push_back(it == damping.axis_sources.end() ? axis : it->second);
  }
  return out;
}

// Checks a derivative model of `dof` (terms, coefficients, covariance, the
// names it reads); throws InputError naming the DOF.
void check_derivatives(const DofDamping& d, std::size_t dof) {
  if (d.terms.empty() || d.terms.size() > DampingModel::kMaxDerivativeTerms)
    throw InputError(dof_context(dof) + ": found " + std::to_string(d.terms.size()) +
                     " derivative terms, expected 1 to " + std::to_string(DampingModel::kMaxDerivativeTerms));
  if (d.coefficients.size() != d.terms.size())
    throw InputError(dof_context(dof) + ": found " + std::to_string(d.coefficients.size()) + " coefficients for " +
                     std::to_string(d.terms.size()) + " terms, expected one per term");
  for (std::size_t k = 0; k < d.terms.size(); ++k) {
    if (!std::isfinite(d.coefficients[k]))
      throw InputError(dof_context(dof) + ": the coefficient of '" + d.terms[k].text() +
                       "' is not finite, expected a finite number");
    for (const auto& f : d.terms[k].factors())
      if (f.variable == "alpha" || f.variable == "beta" || f.variable == "du")
        throw InputError(dof_context(dof) + ": term '" + d.terms[k].text() + "' reads '" + f.variable +
                         "', which the dynamics model does not supply; expected terms in u, v, w, p, q, r and "
                         "disturbance parameters");
  }
  if (!d.covariance.empty())
    if (const auto problem = covariance_problem(d.covariance, d.coefficients.size()))
      throw InputError(dof_context(dof) + ": covariance: " + *problem);
}

// The value of a factor |x|^power (negated when odd and x < 0) and its
// derivative power |x|^(power - 1) (times sign(x) when even; 0 for |x| at
// x = 0, its mean slope there).
double factor_value(int power, bool odd, double x) { return hc_damping_factor_value(power, odd ? 1 : 0, x); }
double factor_slope(int power, bool odd, double x) {
  const double magnitude = std::abs(x);
  double out = static_cast<double>(power);
  for (int k = 1; k < power; ++k) out *= magnitude;
  if (odd) return out;
  return x > 0.0 ? out : x < 0.0 ? -out : 0.0;
}

}  // namespace

double DampingModel::Derivatives::value(const double* nu_r_b, std::span<const double> disturbances) const {
  // The shared kernel (runtime/src/damping_kernel.h).
  return hc_damping_derivatives_value(coefficients.data(), coefficients.size(), begin.data(), factors.data(), nu_r_b,
                                      disturbances.data());
}

DampingModel::DampingModel(const DampingSpec& spec, const SurfaceResolver& resolver) {
  // Pass 1: laws, and the surfaces with their bindings.
  struct Pending {
    std::size_t dof;
    CoefficientSurface surface;
    std::vector<std::string> bindings;
  };
  std::vector<Pending> pending;
  std::map<std::string, CoefficientSurface> resolved;
  std::set<std::string> disturbances;
  for (std::size_t dof = 0; dof < 6; ++dof) {
    const DofDamping& d = spec[dof];
    switch (d.kind) {
      case DofDamping::Kind::None: break;
      case DofDamping::Kind::Law: {
        if (!d.fit.empty() && d.law.terms.empty())
          throw InputError(dof_context(dof) + ": the stored fit '" + d.fit +
                           "' is needed but no run database was given to read it from");
        const auto variable = velocity_index(d.law.variable);
        if (!variable || d.law.terms.empty() || d.law.terms.size() > 6)
          throw InputError(dof_context(dof) + ": a law needs 1 to 6 terms of one velocity component u, v, w, p, q, r");
        if (d.coefficients.size() != d.law.terms.size())
          throw InputError(dof_context(dof) + ": found " + std::to_string(d.coefficients.size()) +
                           " coefficients for " + std::to_string(d.law.terms.size()) + " terms, expected one per term");
        if (!d.covariance.empty())
          if (const auto problem = covariance_problem(d.covariance, d.coefficients.size()))
            throw InputError(dof_context(dof) + ": covariance: " + *problem);
        Law law;
        law.dof = dof;
        law.variable = *variable;
        law.count = d.law.terms.size();
        for (std::size_t k = 0; k < law.count; ++k) {
          law.terms[k] = d.law.terms[k];
          law.coefficients[k] = to_on_body(d.coefficients[k], d.sign);
          law.codes[k] = static_cast<int>(law.terms[k]);
        }
        laws_.push_back(law);
        damped_[dof] = true;
        break;
      }
      case DofDamping::Kind::Derivatives: {
        check_derivatives(d, dof);
        for (const auto& name : term_variables(d.terms))
          if (!velocity_index(name)) disturbances.insert(name);
        damped_[dof] = true;
        break;
      }
      case DofDamping::Kind::Surface: {
        if (!resolver)
          throw InputError(dof_context(dof) + ": surface '" + d.surface +
                           "' is needed but no surface source was given (a run database)");
        auto it = resolved.find(d.surface);
        if (it == resolved.end()) {
          try {
            it = resolved.emplace(d.surface, resolver(d.surface)).first;
          } catch (const InputError& e) {
            throw InputError(dof_context(dof) + ": " + e.what());
          }
        }
        const CoefficientSurface& surface = it->second;
        if (surface.axis_count() > kMaxAxes || surface.output_count() > kMaxOutputs)
          throw InputError(dof_context(dof) + ": surface '" + d.surface + "' has " +
                           std::to_string(surface.axis_count()) + " axes and " +
                           std::to_string(surface.output_count()) + " outputs; at most " + std::to_string(kMaxAxes) +
                           " and " + std::to_string(kMaxOutputs) + " are supported for damping");
        try {
          (void)surface.output_index(d.output);
        } catch (const InputError& e) {
          throw InputError(dof_context(dof) + ": surface '" + d.surface + "': " + e.what());
        }
        auto bindings = axis_bindings(surface, d, dof);
        // The output against the axis bound to this DOF's own velocity must
        // take energy out of that motion.
        if (!d.allow_unphysical)
          for (std::size_t a = 0; a < bindings.size(); ++a)
            if (bindings[a] == kVelocityNames[dof])
              if (const auto problem = dissipativity_problem(surface, surface.output_index(d.output), a,
                                                             d.sign == SignConvention::OnBody ? 1.0 : -1.0))
                throw InputError(dof_context(dof) + ": surface '" + d.surface + "': " + problem->message +
                                 "; expected damping that takes energy out of the motion (\"allow_unphysical\": "
                                 "true uses it anyway)");
        for (const auto& b : bindings)
          if (!velocity_index(b)) disturbances.insert(b);
        pending.push_back({dof, surface, std::move(bindings)});
        damped_[dof] = true;
        break;
      }
    }
  }
  disturbance_names_.assign(disturbances.begin(), disturbances.end());
  const auto source_of = [&](const std::string& name) -> std::size_t {
    if (const auto v = velocity_index(name)) return *v;
    const auto pos = std::lower_bound(disturbance_names_.begin(), disturbance_names_.end(), name);
    return 6 + static_cast<std::size_t>(pos - disturbance_names_.begin());
  };

  // The derivative models, their names resolved once.
  for (std::size_t dof = 0; dof < 6; ++dof) {
    const DofDamping& d = spec[dof];
    if (d.kind != DofDamping::Kind::Derivatives) continue;
    Derivatives m;
    m.dof = dof;
    m.text = format_terms(d.terms);
    m.begin.push_back(0);
    for (std::size_t k = 0; k < d.terms.size(); ++k) {
      m.coefficients.push_back(to_on_body(d.coefficients[k], d.sign));
      for (const auto& f : d.terms[k].factors()) m.factors.push_back({source_of(f.variable), f.power, f.odd ? 1 : 0});
      m.begin.push_back(m.factors.size());
    }
    derivatives_.push_back(std::move(m));
  }

  // Pass 2: one lookup per (surface, bindings); each DOF adds its output.
  for (const auto& p : pending) {
    const DofDamping& d = spec[p.dof];
    std::string key = d.surface;
    for (const auto& b : p.bindings) key += "|" + b;
    auto lookup = std::find_if(lookups_.begin(), lookups_.end(), [&](const Lookup& l) { return l.key == key; });
    if (lookup == lookups_.end()) {
      Lookup l{p.surface, key, d.surface};
      l.axis_count = p.bindings.size();
      for (std::size_t a = 0; a < p.bindings.size(); ++a) l.source[a] = source_of(p.bindings[a]);
      lookups_.push_back(std::move(l));
      lookup = std::prev(lookups_.end());
    }
    lookup->output[lookup->used] = p.surface.output_index(d.output);
    lookup->dof[lookup->used] = p.dof;
    lookup->sign[lookup->used] = sign_factor(d.sign, SignConvention::OnBody);
    ++lookup->used;
  }
}

void DampingModel::look_up(const Lookup& l, const double* nu_r_b, std::span<const double> disturbances, double* out) {
  std::array<double, kMaxAxes> point;  // written before it is read (hot path)
  for (std::size_t a = 0; a < l.axis_count; ++a)
    point[a] = l.source[a] < 6 ? nu_r_b[l.source[a]] : disturbances[l.source[a] - 6];
  // A table without symmetry projection is evaluated without the span checks
  // (the axis count was checked when the model was built): a table of one
  // axis (a draw of a GP surface, a 1-D CFD table) by its one-axis path, any
  // other by the kernel compiled for its axis count.
  const GridTable* grid = l.surface.grid();
  if (grid && l.surface.symmetry().empty()) {
    if (l.axis_count == 1)
      grid->evaluate_one_axis(point[0], out);
    else
      grid->evaluate_unchecked(point.data(), out);
  } else
    l.surface.evaluate(std::span<const double>(point.data(), l.axis_count),
                       std::span<double>(out, l.surface.output_count()));
}

std::array<DampingModel::DofLayout, 6> DampingModel::layout() const {
  std::array<DofLayout, 6> out;
  for (const Law& law : laws_) {
    DofLayout& d = out[law.dof];
    d.kind = DofDamping::Kind::Law;
    d.variable = law.variable;
    d.codes.assign(law.codes.begin(), law.codes.begin() + static_cast<std::ptrdiff_t>(law.count));
    d.coefficients.assign(law.coefficients.begin(), law.coefficients.begin() + static_cast<std::ptrdiff_t>(law.count));
  }
  for (const Derivatives& m : derivatives_) {
    DofLayout& d = out[m.dof];
    d.kind = DofDamping::Kind::Derivatives;
    d.coefficients = m.coefficients;
    d.begin = m.begin;
    d.factors = m.factors;
  }
  for (const Lookup& l : lookups_)
    for (std::size_t k = 0; k < l.used; ++k) {
      DofLayout& d = out[l.dof[k]];
      d.kind = DofDamping::Kind::Surface;
      d.surface = l.name;
      d.output = l.output[k];
      d.sign = l.sign[k];
      d.sources.assign(l.source.begin(), l.source.begin() + static_cast<std::ptrdiff_t>(l.axis_count));
    }
  return out;
}

Vector6 DampingModel::evaluate(const Vector6& nu_r_b, std::span<const double> disturbances) const {
  Vector6 tau = Vector6::Zero();
  add(nu_r_b.data(), disturbances, tau.data());
  return tau;
}

void DampingModel::add(const double* nu_r_b, std::span<const double> disturbances, double* tau) const {
  // The shared kernel's law (runtime/src/damping_kernel.h): damping_law_value's arithmetic.
  for (const Law& law : laws_)
    tau[law.dof] += hc_damping_law_value(law.codes.data(), law.coefficients.data(), law.count, &nu_r_b[law.variable]);
  for (const Derivatives& m : derivatives_) tau[m.dof] += m.value(nu_r_b, disturbances);
  std::array<double, kMaxOutputs> out;  // written before it is read (hot path)
  for (const Lookup& l : lookups_) {
    look_up(l, nu_r_b, disturbances, out.data());
    for (std::size_t k = 0; k < l.used; ++k) tau[l.dof[k]] += l.sign[k] * out[l.output[k]];
  }
}

Vector6 DampingModel::evaluate_with_jacobian(const Vector6& nu_r_b, std::span<const double> disturbances,
                                             Matrix6& jacobian) const {
  Vector6 tau = Vector6::Zero();
  jacobian.setZero();
  for (const Law& law : laws_) {
    const auto dof = static_cast<Eigen::Index>(law.dof);
    const auto variable = static_cast<Eigen::Index>(law.variable);
    const double x = nu_r_b[variable];
    tau[dof] +=
        damping_law_value(std::span(law.terms.data(), law.count), std::span(law.coefficients.data(), law.count), x);
    // d/dx of 1, x, x|x|, x^2, x^3, |x| (0 for |x| at x = 0: its mean slope there).
    const double magnitude = std::abs(x);
    const std::array<double, 6> slope = {0.0,     1.0,         2.0 * magnitude,
                                         2.0 * x, 3.0 * x * x, x > 0.0 ? 1.0 : x < 0.0 ? -1.0 : 0.0};
    for (std::size_t k = 0; k < law.count; ++k)
      jacobian(dof, variable) += law.coefficients[k] * slope[static_cast<std::size_t>(law.terms[k])];
  }
  for (const Derivatives& m : derivatives_) {
    const auto dof = static_cast<Eigen::Index>(m.dof);
    tau[dof] += m.value(nu_r_b.data(), disturbances);
    const auto x = [&](const Factor& f) {
      return f.source < 6 ? nu_r_b[static_cast<Eigen::Index>(f.source)] : disturbances[f.source - 6];
    };
    // d term / d x_i: the factor's slope times the other factors' values
    // (each name appears once in a term).
    for (std::size_t k = 0; k < m.coefficients.size(); ++k)
      for (std::size_t i = m.begin[k]; i < m.begin[k + 1]; ++i) {
        if (m.factors[i].source >= 6) continue;
        double slope = factor_slope(m.factors[i].power, m.factors[i].odd, x(m.factors[i]));
        for (std::size_t j = m.begin[k]; j < m.begin[k + 1]; ++j)
          if (j != i) slope *= factor_value(m.factors[j].power, m.factors[j].odd, x(m.factors[j]));
        jacobian(dof, static_cast<Eigen::Index>(m.factors[i].source)) += m.coefficients[k] * slope;
      }
  }
  std::array<double, kMaxOutputs> out{};
  std::array<double, kMaxOutputs * kMaxAxes> gradient{};
  std::array<double, kMaxAxes> point{};
  for (const Lookup& l : lookups_) {
    for (std::size_t a = 0; a < l.axis_count; ++a)
      point[a] = l.source[a] < 6 ? nu_r_b[static_cast<Eigen::Index>(l.source[a])] : disturbances[l.source[a] - 6];
    const std::size_t outputs = l.surface.output_count();
    l.surface.evaluate_with_gradient(std::span<const double>(point.data(), l.axis_count),
                                     std::span<double>(out.data(), outputs),
                                     std::span<double>(gradient.data(), outputs * l.axis_count));
    for (std::size_t k = 0; k < l.used; ++k) {
      const auto dof = static_cast<Eigen::Index>(l.dof[k]);
      tau[dof] += l.sign[k] * out[l.output[k]];
      for (std::size_t a = 0; a < l.axis_count; ++a)
        if (l.source[a] < 6)
          jacobian(dof, static_cast<Eigen::Index>(l.source[a])) += l.sign[k] * gradient[l.output[k] * l.axis_count + a];
    }
  }
  return tau;
}

}  // namespace hydrocoef
