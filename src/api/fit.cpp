// Database::fit (include/hydrocoef/database.hpp): `hydrocoef fit` without its
// printing: the same library call (src/pipeline/fit_stored_runs).
#include "src/api/internal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hydrocoef {
inline namespace api {
std::vector<std::string> coefficient_units(const std::string& terms, const std::string& output,
                                           const std::string& variable) {
  const auto dof = force_index(output);
  const auto component = velocity_index(variable);
  if (!dof || !component) return {};
  try {
    std::vector<std::string> units;
    for (const DampingTerm term : parse_damping_terms(terms).terms)
      units.push_back(coefficient_unit(term, *dof, *component));
    return units;
  } catch (const InputError&) {
    return {};
  }
}

FitSummary Database::fit(const FitOptions& options) {
  FitRequest request;
  request.body = options.body;
  request.dof = options.output;
  request.terms = options.terms;
  request.loss = options.loss;
  request.where = options.where;
  request.exclude_runs = options.exclude_runs;
  request.mirror_planes = options.mirror;
  request.mirror_odd = options.mirror_odd;
  if (!options.name.empty()) request.name = options.name;
  request.store = options.store;
  request.taken = options.replace ? RunDatabase::NameTaken::Replace : RunDatabase::NameTaken::Refuse;
  const std::lock_guard lock(impl_->mutex);
  auto& store = options.store ? impl_->writable_store("fit") : impl_->open_store();
  const FitResult result = fit_stored_runs(store, request);
  const DampingLawSpec& spec = result.setup.spec;
  const DampingLawFit& law = result.fit;

  FitSummary out;
  for (const auto& warning : result.setup.warnings) out.warnings.push_back(warning.kind + ": " + warning.message);
  out.id = result.fit_id.value_or(0);
  out.name = result.name;
  out.body = options.body;
  out.output = options.output;
  out.variable = spec.variable;
  out.terms = format_damping_terms(spec);
  out.loss = law.loss;
  out.where = result.setup.selection;
  out.mirror = result.setup.mirror.text();
  out.sign_convention = std::string(to_string(result.setup.samples.sign));
  for (std::size_t k = 0; k < spec.terms.size(); ++k)
    out.coefficients.push_back({term_name(spec.terms[k], spec.variable), law.coefficients[k], law.std_errors[k],
                                result.setup.coefficient_units[k]});
  out.rmse = law.rmse;
  out.r2 = law.r2;
  out.n = law.n;
  out.runs = result.run_ids();
  return out;
}

}  // namespace api
}  // namespace hydrocoef
