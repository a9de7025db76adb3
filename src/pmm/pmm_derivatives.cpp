#include "src/pmm/pmm_derivatives.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/pmm/added_mass_assembly.hpp"
#include "src/pmm/imposed_motion.hpp"

namespace hydrocoef {

namespace {

constexpr std::size_t kY = 1;  // force component Y
constexpr std::size_t kN = 5;  // moment component N

void check_dof(std::size_t dof) {
  if (dof != kPmmSway && dof != kPmmYaw)
    throw std::invalid_argument("hydrocoef::pmm derivatives: DOF " + std::to_string(dof) + " is not sway or yaw");
}

std::size_t output_of(std::size_t k) { return k < 2 ? kY : kN; }
bool acceleration(std::size_t k) { return k % 2 == 1; }

std::string run_name(const PmmRecord& record) {
  return "pmm run " + std::to_string(record.id) + " (" + printable_text(record.source_path, 120) + ")";
}

bool same_value(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }

}  // namespace

std::string pmm_derivative_name(std::size_t dof, std::size_t k) {
  check_dof(dof);
  const std::string variable = dof == kPmmSway ? "v" : "r";
  return std::string(output_of(k) == kY ? "Y_" : "N_") + variable + (acceleration(k) ? "dot" : "");
}

std::string pmm_derivative_unit(std::size_t dof, std::size_t k) {
  check_dof(dof);
  // Force or moment per m/s, m/s^2, rad/s or rad/s^2; an acceleration derivative as a mass.
  const int rotations = int(output_of(k) == kN) + int(dof == kPmmYaw);
  if (acceleration(k)) return rotations == 0 ? "kg" : rotations == 1 ? "kg m" : "kg m^2";
  return rotations == 0 ? "N s/m" : rotations == 1 ? "N s" : "N m s";
}

DerivativeKind pmm_derivative_kind(std::size_t dof, std::size_t k) {
  check_dof(dof);
  DerivativeKind kind;
  kind.output = output_of(k) == kY ? QuantityKind::Force : QuantityKind::Moment;
  QuantityKind variable = QuantityKind::LinearVelocity;
  if (dof == kPmmSway)
    variable = acceleration(k) ? QuantityKind::LinearAcceleration : QuantityKind::LinearVelocity;
  else
    variable = acceleration(k) ? QuantityKind::AngularAcceleration : QuantityKind::AngularVelocity;
  kind.factors.push_back({variable, 1});
  return kind;
}

std::string pmm_derivative_source(std::size_t dof, std::size_t k) {
  check_dof(dof);
  return std::string(acceleration(k) ? "-M_A[" : "-D[") + std::string(dof_name(output_of(k))) + "][" +
         std::string(dof_name(dof)) + "]";
}

PmmRunDerivatives pmm_run_derivatives(const PmmRecord& record, std::optional<double> speed) {
  if (record.dof != kPmmSway && record.dof != kPmmYaw)
    throw InputError(run_name(record) + " of body '" + printable_text(record.body, 80) + "' moves " +
                     std::string(record.dof < 6 ? dof_name(record.dof) : "no DOF") +
                     "; expected a sway (pure sway) or yaw (pure yaw) oscillation");
  PmmRunDerivatives out;
  out.id = record.id;
  out.dof = record.dof;
  out.amplitude = record.amplitude;
  out.omega = record.omega;
  out.speed = speed.value_or(record.nu_b[0]);
  out.source_path = record.source_path;
  for (const std::size_t component : {kY, kN}) {
    const auto found = std::find_if(record.coefficients.begin(), record.coefficients.end(),
                                    [&](const PmmCoefficient& c) { return c.component == component; });
    if (found == record.coefficients.end())
      throw InputError(run_name(record) + ": its history has no " + std::string(component == kY ? "Y" : "N") +
                       "; expected the sway force Y and the yaw moment N of a " + std::string(dof_name(record.dof)) +
                       " run");
    const std::size_t k = component == kY ? 0 : 2;
    // F = -M_A x'' - D x' (Fossen) against F = X_x x' + X_xdot x'' (SNAME derivatives).
    out.derivatives[k] = {-found->damping, found->damping_se};
    out.derivatives[k + 1] = {-found->added_mass, found->added_mass_se};
  }
  return out;
}

PmmDerivativeSet pmm_derivative_set(const std::string& body, const std::vector<PmmRecord>& records,
                                    const std::vector<std::int64_t>& ids, std::optional<double> speed) {
  if (speed && !std::isfinite(*speed))
    throw InputError("speed " + shortest_number(*speed) + ": expected a finite forward speed U (m/s)");
  PmmDerivativeSet out;
  out.body = body;
  std::vector<const PmmRecord*> chosen;
  std::map<std::string, std::size_t> others;  // DOF name -> runs
  for (const PmmRecord& record : records) {
    if (record.body != body) continue;
    const bool wanted = ids.empty() || std::find(ids.begin(), ids.end(), record.id) != ids.end();
    if (!wanted) continue;
    if (record.dof == kPmmSway || record.dof == kPmmYaw) {
      chosen.push_back(&record);
    } else if (!ids.empty()) {
      (void)pmm_run_derivatives(record, speed);  // refused, naming the run and what it moves
    } else {
      ++out.other_runs;
      ++others[std::string(record.dof < 6 ? dof_name(record.dof) : "unknown")];
    }
  }
  for (const std::int64_t id : ids)
    if (std::none_of(chosen.begin(), chosen.end(), [&](const PmmRecord* r) { return r->id == id; }))
      throw InputError("pmm run " + std::to_string(id) + ": not a stored forced-oscillation run of body '" +
                       printable_text(body, 80) + "'; expected one `hydrocoef pmm-runs --body` lists");
  if (chosen.empty()) {
    if (others.empty())
      throw InputError("body '" + printable_text(body, 80) +
                       "' has no stored forced-oscillation runs; expected pure sway or pure yaw runs (hydrocoef pmm "
                       "... --body BODY)");
    std::string moved;
    for (const auto& [name, n] : others) moved += (moved.empty() ? "" : ", ") + std::to_string(n) + " " + name;
    throw InputError("body '" + printable_text(body, 80) + "' has no sway or yaw forced-oscillation runs (it has " +
                     moved + "); expected pure sway or pure yaw runs for the sway and yaw derivatives");
  }
  for (const PmmRecord* record : chosen) out.runs.push_back(pmm_run_derivatives(*record, speed));

  // Groups: sway before yaw, then by speed and frequency (each equal to 1e-9).
  std::vector<std::vector<std::size_t>> members;
  for (std::size_t n = 0; n < out.runs.size(); ++n) {
    const PmmRunDerivatives& run = out.runs[n];
    std::size_t g = 0;
    for (; g < out.groups.size(); ++g) {
      const PmmDerivativeGroup& group = out.groups[g];
      if (group.dof == run.dof && same_value(group.speed, run.speed) && same_value(group.omega, run.omega)) break;
    }
    if (g == out.groups.size()) {
      PmmDerivativeGroup group;
      group.dof = run.dof;
      group.speed = run.speed;
      group.omega = run.omega;
      group.amplitude_min = group.amplitude_max = run.amplitude;
      out.groups.push_back(group);
      members.emplace_back();
    }
    PmmDerivativeGroup& group = out.groups[g];
    group.amplitude_min = std::min(group.amplitude_min, run.amplitude);
    group.amplitude_max = std::max(group.amplitude_max, run.amplitude);
    group.record_ids.push_back(run.id);
    members[g].push_back(n);
  }
  for (std::size_t g = 0; g < out.groups.size(); ++g)
    for (std::size_t k = 0; k < kPmmDerivativeCount; ++k) {
      std::vector<double> values, errors;
      for (const std::size_t n : members[g]) {
        values.push_back(out.runs[n].derivatives[k].value);
        errors.push_back(out.runs[n].derivatives[k].std_error);
      }
      const auto [value, error] = combine_pmm_estimates(values, errors);
      out.groups[g].derivatives[k] = {value, error};
    }
  std::stable_sort(out.groups.begin(), out.groups.end(), [](const PmmDerivativeGroup& a, const PmmDerivativeGroup& b) {
    return std::tie(a.dof, a.speed, a.omega) < std::tie(b.dof, b.speed, b.omega);
  });
  return out;
}

}  // namespace hydrocoef
