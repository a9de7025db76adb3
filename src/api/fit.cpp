// Fits (include/hydrocoef/database.hpp, records.hpp): `hydrocoef fit` (a law,
// per-level fits, refits) and `hydrocoef fits` (the list, a stored law
// evaluated with its standard error) without their printing: the same library
// calls (src/pipeline/fit_stored_runs). What they print is src/api/fit_report.cpp.
#include "src/api/internal.hpp"
#include "src/api/records_report.hpp"
#include "src/core/numbers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hydrocoef {
inline namespace api {
namespace {

std::optional<std::string> optional_text(const std::string& text) {
  return text.empty() ? std::nullopt : std::optional<std::string>(text);
}

FitRequest fit_request(const FitOptions& options) {
  FitRequest request;
  request.body = options.body;
  request.dof = options.output;
  request.terms = options.terms;
  request.loss = options.loss;
  request.where = options.where;
  request.exclude_runs = options.exclude_runs;
  request.mirror_planes = options.mirror;
  request.mirror_odd = options.mirror_odd;
  request.name = optional_text(options.name);
  request.store = options.store;
  request.taken = options.replace ? RunDatabase::NameTaken::Replace : RunDatabase::NameTaken::Refuse;
  request.weighted = options.weighted;
  return request;
}

/// The store a fit reads (and writes, when it stores).
RunDatabase& fit_store(Database::Impl& impl, bool store) {
  return store ? impl.writable_store("fit") : impl.open_store();
}

}  // namespace

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

void FitOptions::validate() const {
  if (refit &&
      (!output.empty() || !terms.empty() || !by.empty() || !where.empty() || !exclude_runs.empty() || !mirror.empty()))
    throw InputError(
        "--refit makes stored fits again as they were made; expected only --name, --body and --json with it");
}

FitSummary Database::fit(const FitOptions& options) {
  options.validate();
  if (!options.by.empty() || options.refit)
    throw std::invalid_argument(
        "hydrocoef::Database::fit: options.by and options.refit are for fit_by_level and "
        "refit_fits");
  const FitRequest request = fit_request(options);
  const std::lock_guard lock(impl_->mutex);
  const FitResult result = fit_stored_runs(fit_store(*impl_, options.store), request);
  return records::fit_summary(result, options.body, options.output, impl_->path);
}

LevelFits fit_by_level(Database& database, const FitOptions& options) {
  options.validate();
  if (options.refit) throw std::invalid_argument("hydrocoef::fit_by_level: options.refit is for refit_fits");
  if (options.by.empty())
    throw InputError("fit_by_level: expected the velocity component or disturbance whose levels are fitted (--by)");
  const LevelFitRequest request{fit_request(options), options.by, options.curve, options.strict};
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  return records::level_fits(fit_stored_runs_by_level(fit_store(impl, options.store), request), request, impl.path);
}

Refits refit_fits(Database& database, const FitOptions& options) {
  FitOptions refit = options;
  refit.refit = true;
  refit.validate();
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  const RefitResult result =
      refit_stored_fits(impl.writable_store("fit --refit"), optional_text(options.name), optional_text(options.body));
  Refits out;
  out.database = impl.path;
  for (const auto& record : result.previous) out.previous.push_back(records::fit_summary(record));
  for (const auto& record : result.made) out.made.push_back(records::fit_summary(record));
  return out;
}

FitList list_fits(const Database& database, const std::string& body) {
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  FitList out;
  out.database = impl.path;
  for (const FitRecord& record : impl.open_store().fits(optional_text(body)))
    out.fits.push_back(records::fit_summary(record));
  return out;
}

void FitEvaluationOptions::validate() const {
  if (name.empty()) throw InputError("fits evaluate: expected the name of a stored fit ('hydrocoef fits' lists them)");
  if (at.empty()) throw InputError("fits evaluate: expected at least one value of the law's velocity (--at)");
  for (const double x : at)
    if (!std::isfinite(x)) throw InputError("fits evaluate: --at: expected finite numbers");
}

FitEvaluation evaluate_fit(const Database& database, const FitEvaluationOptions& options) {
  options.validate();
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  auto& store = impl.open_store();
  const auto fits = store.fits();
  const auto found =
      std::find_if(fits.begin(), fits.end(), [&](const FitRecord& fit) { return fit.name == options.name; });
  if (found == fits.end()) {
    std::string names;
    for (const auto& fit : fits) names += (names.empty() ? "" : ", ") + fit.name;
    throw InputError(SourceLocation{impl.path}, "no fit '" + options.name + "'; expected one of: " +
                                                    (names.empty() ? std::string("(no fits stored)") : names));
  }
  const FitRecord& fit = *found;
  const DampingLawSpec spec = parse_damping_terms(fit.terms);
  const std::size_t k = spec.terms.size();
  const auto dof = force_index(fit.dof);
  const auto variable = velocity_index(spec.variable);
  if (fit.coefficients.size() != k || !dof || !variable)
    throw InputError(SourceLocation{impl.path}, "fit '" + fit.name + "': its terms '" + fit.terms + "' and " +
                                                    std::to_string(fit.coefficients.size()) +
                                                    " coefficients do not agree; expected one coefficient a term");
  const bool has_covariance = fit.covariance.size() == k * k;

  FitEvaluation out;
  out.name = fit.name;
  out.output = fit.dof;
  out.variable = spec.variable;
  out.sign_convention = std::string(to_string(fit.sign));
  out.unit = force_unit(*dof);
  out.variable_unit = velocity_unit(*variable);
  out.stale = fit.stale;
  for (const double x : options.at) {
    std::vector<double> basis(k);
    double value = 0.0;
    for (std::size_t i = 0; i < k; ++i) {
      basis[i] = basis_value(spec.terms[i], x);
      value += fit.coefficients[i].value * basis[i];
    }
    double variance = kNaN;
    if (has_covariance) {
      variance = 0.0;
      for (std::size_t i = 0; i < k; ++i)
        for (std::size_t j = 0; j < k; ++j) variance += basis[i] * fit.covariance[i * k + j] * basis[j];
    }
    out.at.push_back(x);
    out.value.push_back(value);
    // Round-off may leave a variance of a point where it vanishes a hair below zero.
    out.std_error.push_back(std::isnan(variance) ? kNaN : std::sqrt(std::max(variance, 0.0)));
  }
  // The range the law was fitted over: its runs still in the database (mirror images not counted).
  out.fitted_min = kNaN;
  out.fitted_max = kNaN;
  RunFilter filter;
  filter.body = fit.body;
  for (const StoredRun& run : store.runs(filter))
    if (std::find(fit.run_ids.begin(), fit.run_ids.end(), run.id) != fit.run_ids.end()) {
      const double x = run.key.nu_b[*variable];
      out.fitted_min = std::isnan(out.fitted_min) ? x : std::min(out.fitted_min, x);
      out.fitted_max = std::isnan(out.fitted_max) ? x : std::max(out.fitted_max, x);
    }
  return out;
}

}  // namespace api
}  // namespace hydrocoef
