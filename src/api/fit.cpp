// Database::fit (include/hydrocoef/database.hpp): `hydrocoef fit` without its
// printing. The runs, their mirror images and the stored record come from
// src/pipeline/fit_runs; the law from src/fit.
#include "src/api/internal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hydrocoef::api {
namespace {

std::string coefficient_unit(DampingTerm term, std::size_t dof, std::size_t component) {
  const std::string force = dof < 3 ? "N" : "N m";
  const int power = term_power(term);
  if (power == 0) return force;
  std::string out = force + "/(" + (component < 3 ? "m/s" : "rad/s") + ")";
  if (power > 1) out += "^" + std::to_string(power);
  return out;
}

}  // namespace

std::vector<std::string> coefficient_units(const std::string& terms, const std::string& output,
                                           const std::string& variable) {
  const auto dof = force_index(output);
  const auto component = velocity_index(variable);
  if (!dof || !component) return {};
  try {
    std::vector<std::string> units;
    for (const DampingTerm term : parse_damping_terms(terms).terms) units.push_back(coefficient_unit(term, *dof, *component));
    return units;
  } catch (const InputError&) {
    return {};
  }
}

FitSummary Database::fit(const api::FitOptions& options) {
  if (options.body.empty() || options.output.empty() || options.terms.empty())
    throw InputError("fit: body, output and terms are required");
  const auto dof = force_index(options.output);
  if (!dof) throw InputError("fit output '" + options.output + "': expected one of X Y Z K M N");
  const DampingLawSpec spec = parse_damping_terms(options.terms);
  const api_internal::LawFitOptions loss = parse_loss(options.loss);
  const std::size_t variable = *velocity_index(spec.variable);
  if (!options.name.empty()) check_name(NameKind::Fit, options.name, {}, "the fit's name");
  check_name(NameKind::Body, options.body, {}, "the fit's body");
  const MirrorSpec mirror = make_mirror_spec(options.mirror, options.mirror_odd);
  const RunSelection selection = parse_selection(options.where, options.exclude_runs);

  const std::lock_guard lock(impl_->mutex);
  auto& store = options.store ? impl_->writable_store("fit") : impl_->open_store();
  const FitSamples samples = gather_fit_samples(store, options.body, *dof, variable, selection, mirror);
  const DampingLawFit law = fit_damping_law(spec, samples.x, samples.y, loss);
  const std::string terms = format_damping_terms(spec);
  const std::string name =
      options.name.empty() ? default_fit_name(options.body, options.output, terms, selection.text()) : options.name;

  FitSummary out;
  // The physical checks `fit` warns about (src/fit/physical_checks), and unconverged runs.
  LawCheckInput check;
  check.spec = spec;
  check.coefficients = law.coefficients;
  check.std_errors = law.std_errors;
  check.sign = samples.sign;
  check.x_min = *std::min_element(samples.x.begin(), samples.x.end());
  check.x_max = *std::max_element(samples.x.begin(), samples.x.end());
  check.x = samples.x;
  check.y = samples.y;
  for (const auto& problem : check_damping_law(check))
    out.warnings.push_back(std::string(law_problem_name(problem.problem)) + ": " + problem.message);
  if (const std::string unconverged = unconverged_runs_warning(samples.runs, *dof); !unconverged.empty())
    out.warnings.push_back("unconverged-runs: " + unconverged);

  if (options.store)
    out.id = store.save_fit(
        make_fit_record(name, options.body, *dof, spec, law, selection.text(), mirror, samples, samples.run_ids),
        options.replace ? api_internal::StoreDatabase::NameTaken::Replace
                        : api_internal::StoreDatabase::NameTaken::Refuse);

  out.name = name;
  out.body = options.body;
  out.output = options.output;
  out.variable = spec.variable;
  out.terms = terms;
  out.loss = law.loss;
  out.where = selection.text();
  out.mirror = mirror.text();
  out.sign_convention = std::string(to_string(samples.sign));
  for (std::size_t k = 0; k < spec.terms.size(); ++k)
    out.coefficients.push_back({term_name(spec.terms[k], spec.variable), law.coefficients[k], law.std_errors[k],
                                coefficient_unit(spec.terms[k], *dof, variable)});
  out.rmse = law.rmse;
  out.r2 = law.r2;
  out.n = law.n;
  for (const auto& run : samples.runs) out.runs.push_back(run.id);
  return out;
}

}  // namespace hydrocoef::api
