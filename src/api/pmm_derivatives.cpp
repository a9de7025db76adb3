// Sway and yaw derivatives from stored pure sway and pure yaw runs
// (include/hydrocoef/pmm_derivatives.hpp): `hydrocoef derivatives pmm`
// without its printing. The derivatives are src/pmm/pmm_derivatives, the
// prime form src/derivatives/normalisation; the text and JSON are
// src/api/pmm_derivatives_report.cpp.
#include "src/api/internal.hpp"

#include <cmath>
#include <numbers>

#include "hydrocoef/pmm_derivatives.hpp"
#include "src/core/numbers.hpp"
#include "src/derivatives/normalisation.hpp"
#include "src/pmm/imposed_motion.hpp"
#include "src/pmm/pmm_derivatives.hpp"
#include "src/store/body_reference.hpp"

namespace hydrocoef {
inline namespace api {
namespace {

void check_positive(const std::optional<double>& value, const char* option, const char* unit) {
  if (value && !(std::isfinite(*value) && *value > 0.0))
    throw InputError(std::string(option) + " " + shortest_number(*value) + ": expected a finite number > 0 (" + unit +
                     ")");
}

bool same_value(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }

/// The density of the runs: the one every run that states one states; none
/// when no run does. InputError when they differ.
std::optional<double> runs_density(const std::string& body, const std::vector<PmmRecord>& records,
                                   const PmmDerivativeSet& set) {
  std::optional<double> out;
  for (const auto& run : set.runs)
    for (const auto& record : records)
      if (record.id == run.id && record.body == body && record.rho) {
        if (out && !same_value(*out, *record.rho))
          throw InputError("body '" + printable_text(body, 80) + "': the sway and yaw runs state densities " +
                           shortest_number(*out) + " and " + shortest_number(*record.rho) +
                           " kg/m^3; expected one (give --density)");
        out = record.rho;
      }
  return out;
}

PmmDerivative derivative_of(std::size_t dof, std::size_t k, const PmmEstimate& estimate) {
  PmmDerivative d;
  d.name = pmm_derivative_name(dof, k);
  d.value = estimate.value;
  d.std_error = estimate.std_error;
  d.unit = pmm_derivative_unit(dof, k);
  d.source = pmm_derivative_source(dof, k);
  return d;
}

/// The prime form of a group's derivatives where L, rho (and U > 0 for a
/// velocity derivative) are known; InputError naming what is missing when
/// the prime form is required.
void add_prime(PmmFrequencyDerivatives& row, const PmmDerivatives& result, bool required) {
  const auto refuse = [&](const std::string& missing) {
    throw InputError("derivatives pmm --prime: the " + row.motion + " runs at U = " + shortest_number(row.speed) +
                     " m/s, omega = " + significant(row.omega, 6) + " rad/s have no " + missing);
  };
  if (required) {
    if (!result.length)
      refuse("reference length L; give --length or store it with `hydrocoef body set " +
             printable_text(result.body, 80) + " --length L`");
    if (!result.density) refuse("density rho; give --density or import the runs with --rho");
    if (!(row.speed > 0.0))
      refuse(
          "forward speed (U > 0) for omega' = omega L / U and the prime velocity derivatives; give --speed or "
          "runs with a u key");
  }
  if (!result.length) return;
  if (row.speed > 0.0) row.omega_prime = row.omega * *result.length / row.speed;
  if (!result.density) return;
  NormalisationReference reference;
  reference.length = result.length;
  reference.density = result.density;
  if (row.speed > 0.0) reference.speed = row.speed;
  const std::size_t dof = row.dof == "sway" ? kPmmSway : kPmmYaw;
  for (std::size_t k = 0; k < row.derivatives.size(); ++k) {
    const bool velocity = k % 2 == 0;
    if (velocity && !(row.speed > 0.0)) continue;
    PmmDerivative& d = row.derivatives[k];
    const NormalisationScale scale = derivative_scale(pmm_derivative_kind(dof, k), NormalisationSystem::Prime);
    const double s = scale_value(scale, NormalisationSystem::Prime, reference, "the derivative " + d.name);
    d.prime = d.value / s;
    d.prime_std_error = d.std_error / s;
    d.normalisation = normalisation_text(scale, NormalisationSystem::Prime, reference, d.name);
  }
}

}  // namespace

void PmmDerivativeOptions::validate() const {
  if (body.empty()) throw InputError("derivatives pmm: expected the body whose sway and yaw runs to analyse (BODY)");
  check_name(NameKind::Body, body, {}, "BODY");
  if (speed && !std::isfinite(*speed))
    throw InputError("--speed " + shortest_number(*speed) + ": expected a finite forward speed U (m/s)");
  check_positive(length, "--length", "m");
  check_positive(density, "--density", "kg/m^3");
}

PmmDerivatives pmm_derivatives(const Database& database, const PmmDerivativeOptions& options) {
  options.validate();
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  RunDatabase& store = impl.open_store();
  const std::vector<PmmRecord> records = store.pmm_records(options.body, false);
  const PmmDerivativeSet set = pmm_derivative_set(options.body, records, options.runs, options.speed);

  PmmDerivatives out;
  out.body = options.body;
  out.other_runs = set.other_runs;
  if (options.length) {
    out.length = options.length;
    out.length_from = "--length";
  } else {
    for (const auto& reference : store.body_references(options.body))
      if (reference.body == options.body && reference.length) {
        out.length = reference.length;
        out.length_from = "body reference";
      }
  }
  if (options.density) {
    out.density = options.density;
    out.density_from = "--density";
  } else {
    out.density = runs_density(options.body, records, set);
    if (out.density) out.density_from = "the runs";
  }

  for (const auto& run : set.runs) {
    PmmDerivativeRun r;
    r.id = run.id;
    r.dof = std::string(dof_name(run.dof));
    r.speed = run.speed;
    r.amplitude = run.amplitude;
    r.omega = run.omega;
    r.source_path = run.source_path;
    for (std::size_t k = 0; k < kPmmDerivativeCount; ++k)
      r.derivatives.push_back(derivative_of(run.dof, k, run.derivatives[k]));
    out.runs.push_back(std::move(r));
  }
  for (const auto& group : set.groups) {
    PmmFrequencyDerivatives row;
    row.dof = std::string(dof_name(group.dof));
    row.motion = group.dof == kPmmSway ? "pure sway" : "pure yaw";
    row.speed = group.speed;
    row.omega = group.omega;
    row.period = 2.0 * std::numbers::pi / group.omega;
    row.runs = group.record_ids.size();
    row.amplitude_min = group.amplitude_min;
    row.amplitude_max = group.amplitude_max;
    row.amplitude_unit = group.dof == kPmmSway ? "m" : "rad";
    row.pmm_runs = group.record_ids;
    for (std::size_t k = 0; k < kPmmDerivativeCount; ++k)
      row.derivatives.push_back(derivative_of(group.dof, k, group.derivatives[k]));
    add_prime(row, out, options.prime);
    out.sets.push_back(std::move(row));
  }

  if (set.other_runs)
    out.notes.push_back(std::to_string(set.other_runs) +
                        (set.other_runs == 1 ? " run of another DOF left out" : " runs of other DOFs left out"));
  bool yaw_at_speed = false;
  for (const auto& row : out.sets) yaw_at_speed = yaw_at_speed || (row.dof == "yaw" && row.speed != 0.0);
  if (yaw_at_speed)
    out.notes.push_back(
        "yaw runs at forward speed are taken as pure yaw (v = 0 along the path); a body turned "
        "about its origin in a fixed stream also has v = -U psi, which is not separated");
  if (!out.length)
    out.notes.push_back("no reference length: no omega' or prime form (give --length or `hydrocoef body set " +
                        printable_text(out.body, 80) + " --length L`)");
  else if (!out.density)
    out.notes.push_back("no density: no prime form (give --density or import the runs with --rho)");
  return out;
}

}  // namespace api
}  // namespace hydrocoef
