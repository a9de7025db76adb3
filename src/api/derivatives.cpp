// Derivative models of several variables (include/hydrocoef/derivatives.hpp):
// `hydrocoef derivatives fit | list | show | delete | evaluate` without their
// printing. The fit selects the body's runs with the output as the other
// fit commands do (src/core/run_selection.hpp), makes each run a point of
// its velocity components and disturbances with its force on the body and
// its standard uncertainty, and calls the library core (src/derivatives/:
// terms, templates, term selection, the fit); the store keeps the result
// (src/store/derivative_store.hpp). What they print is derivatives_report.cpp.
#include "src/api/internal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hydrocoef/derivatives.hpp"
#include "src/api/derivatives_report.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/sign_convention.hpp"
#include "src/derivatives/derivative_fit.hpp"
#include "src/derivatives/model_templates.hpp"
#include "src/derivatives/normalisation.hpp"
#include "src/derivatives/term_selection.hpp"
#include "src/derivatives/terms.hpp"
#include "src/store/derivative_store.hpp"

namespace hydrocoef {
inline namespace api {
namespace {

double or_nan(const std::optional<double>& value) { return value.value_or(kNaN); }
std::optional<double> finite_or_empty(double value) {
  return std::isfinite(value) ? std::optional<double>(value) : std::nullopt;
}

/// 0 for leave-one-out, K for "kfold:K"; InputError otherwise.
std::size_t parse_folds(const std::string& select) {
  if (select == "loo") return 0;
  const std::string prefix = "kfold:";
  if (select.rfind(prefix, 0) == 0) {
    const std::string digits = select.substr(prefix.size());
    if (!digits.empty() && digits.size() <= 6 &&
        std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) {
      const auto k = static_cast<std::size_t>(std::stoul(digits));
      if (k >= 2) return k;
    }
  }
  throw InputError("--select '" + escape::one_line(select) + "': expected loo or kfold:K with K >= 2");
}

/// The body's runs with the output, kept by the selection, as the core's runs.
std::vector<DerivativeRun> gather_runs(RunDatabase& store, const DerivativeModelOptions& options, std::size_t dof,
                                       const RunSelection& selection, std::vector<std::int64_t>& run_ids) {
  RunFilter filter;
  filter.body = options.body;
  filter.with_force = dof;
  std::vector<DerivativeRun> out;
  for (const StoredRun& run : store.runs(filter)) {
    if (!selection.matches(run.key, run.id)) continue;
    DerivativeRun point;
    point.label = "run " + std::to_string(run.id);
    for (std::size_t c = 0; c < 6; ++c) point.values[std::string(kVelocityNames[c])] = run.key.nu_b[c];
    for (const auto& [name, value] : run.key.disturbances) point.values[name] = value;
    if (!std::isnan(options.u0)) point.values["du"] = run.key.nu_b[0] - options.u0;
    const StoredForce& force = *run.tau_b[dof];
    point.output = to_convention(force.value.total, force.sign, SignConvention::OnBody);
    const double sigma = force.standard_uncertainty();
    point.sigma = sigma > 0.0 ? sigma : kNaN;
    out.push_back(std::move(point));
    run_ids.push_back(run.id);
  }
  if (out.empty())
    throw InputError("no runs of body '" + escape::one_line(options.body) + "' with " + options.output +
                     (selection.empty() ? "" : " where " + selection.text()) + " in " + store.path().string());
  return out;
}

/// The stored model as the public result (dimensional).
DerivativeModel model_of(const DerivativeModelRecord& record, const std::string& database) {
  DerivativeModel out;
  out.database = database;
  out.name = record.name;
  out.body = record.body;
  out.output = record.output;
  out.terms = record.terms;
  out.model_template = record.model_template;
  out.selection = record.selection;
  out.candidates = record.candidates;
  out.where = record.run_filter;
  out.unit = derivative_output_unit(record.output);
  const std::vector<Term> terms = parse_terms(record.terms);
  if (terms.size() != record.coefficients.size())
    throw InputError(SourceLocation{database}, "table 'derivative_model', row " + std::to_string(record.id) +
                                                   ": terms '" + escape::one_line(record.terms) + "' and " +
                                                   std::to_string(record.coefficients.size()) +
                                                   " coefficients; expected one coefficient a term");
  for (std::size_t k = 0; k < terms.size(); ++k) {
    const auto& c = record.coefficients[k];
    DerivativeCoefficient coefficient;
    coefficient.term = terms[k].text();
    coefficient.unit = derivative_coefficient_unit(record.output, terms[k]);
    coefficient.value = c.value;
    coefficient.std_error = or_nan(c.std_error);
    coefficient.interval_low = or_nan(c.interval_low);
    coefficient.interval_high = or_nan(c.interval_high);
    coefficient.vif = or_nan(c.vif);
    out.coefficients.push_back(std::move(coefficient));
  }
  out.covariance = record.covariance;
  out.condition_number = record.condition_number;
  out.rmse = record.rmse;
  out.r2 = or_nan(record.r2);
  out.n = record.n;
  out.weighting = record.weighting;
  out.chi2_reduced = or_nan(record.chi2_reduced);
  out.covariance_scale = record.covariance_scale;
  out.interval_factor = or_nan(record.interval_factor);
  out.runs = record.run_ids;
  for (const auto& w : record.warnings) out.warnings.push_back(w.kind + ": " + w.message);
  out.id = record.id;
  out.stale = record.stale;
  out.created_at = record.created_at;
  return out;
}

const DerivativeModelRecord& find_model(const std::vector<DerivativeModelRecord>& models, const std::string& name,
                                        const std::string& database) {
  const auto found = std::find_if(models.begin(), models.end(), [&](const auto& m) { return m.name == name; });
  if (found != models.end()) return *found;
  std::string names;
  for (const auto& m : models) names += (names.empty() ? "'" : ", '") + escape::one_line(m.name) + "'";
  throw InputError(SourceLocation{database},
                   "no derivative model '" + escape::one_line(name) +
                       "'; expected one of: " + (names.empty() ? std::string("(no derivative models stored)") : names));
}

/// What a variable of a term is, for a normalisation; InputError when unknown.
QuantityKind variable_kind(const std::string& name, const std::string& term, const std::string& form) {
  if (name == "u" || name == "v" || name == "w" || name == "du") return QuantityKind::LinearVelocity;
  if (name == "p" || name == "q" || name == "r") return QuantityKind::AngularVelocity;
  if (name == "alpha" || name == "beta" || name == "delta" || name.rfind("delta_", 0) == 0) return QuantityKind::Angle;
  throw InputError("derivatives show --form " + form + ": term '" + term + "': no normalisation is known for '" + name +
                   "'; expected velocities u, v, w, du, rates p, q, r or angles alpha, beta, delta, delta_*");
}

/// Refuses a form whose reference values are not all given, naming the options to give.
void check_reference(const DerivativeShowOptions& o) {
  std::vector<std::string> missing;
  const auto need = [&](double value, const char* option) {
    if (std::isnan(value)) missing.emplace_back(option);
  };
  need(o.length, "--length");
  if (o.form == "prime" || o.form == "mmg") {
    need(o.speed, "--speed");
    need(o.density, "--density");
  }
  if (o.form == "mmg") need(o.draft, "--draft");
  if (o.form == "bis" && std::isnan(o.mass) && (std::isnan(o.density) || std::isnan(o.volume)))
    missing.emplace_back("--mass (or --density and --volume)");
  if (missing.empty()) return;
  std::string list;
  for (std::size_t i = 0; i < missing.size(); ++i)
    list += (i == 0 ? "" : i + 1 == missing.size() ? " and " : ", ") + missing[i];
  throw InputError("derivatives show --form " + o.form + ": the " + o.form +
                   " system needs reference values that are not given; give " + list);
}

/// The model's coefficients, intervals and covariance restated in the form.
void restate(DerivativeModel& model, const DerivativeShowOptions& o) {
  check_reference(o);
  const NormalisationSystem system = parse_normalisation_system(o.form);
  NormalisationReference reference;
  reference.length = finite_or_empty(o.length);
  reference.speed = finite_or_empty(o.speed);
  reference.density = finite_or_empty(o.density);
  reference.draft = finite_or_empty(o.draft);
  reference.mass = finite_or_empty(o.mass);
  reference.displaced_volume = finite_or_empty(o.volume);
  reference.gravity = o.gravity;
  const QuantityKind output =
      std::string("XYZ").find(model.output) != std::string::npos ? QuantityKind::Force : QuantityKind::Moment;
  const std::vector<Term> terms = parse_terms(model.terms);
  std::vector<double> scale;
  for (std::size_t k = 0; k < terms.size(); ++k) {
    DerivativeKind kind;
    kind.output = output;
    for (const auto& [name, power] : terms[k].powers())
      kind.factors.push_back({variable_kind(name, terms[k].text(), o.form), power});
    const NormalisationScale formula = derivative_scale(kind, system);
    std::string symbol = model.output + "_" + terms[k].text();
    std::erase(symbol, '*');
    const double s = scale_value(formula, system, reference, "the derivative " + symbol);
    auto& c = model.coefficients[k];
    c.value /= s;
    c.std_error /= s;
    c.interval_low /= s;
    c.interval_high /= s;
    c.unit = "1";
    c.normalisation = normalisation_text(formula, system, reference, symbol);
    scale.push_back(s);
  }
  const std::size_t m = scale.size();
  if (model.covariance.size() == m * m)
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j = 0; j < m; ++j) model.covariance[i * m + j] /= scale[i] * scale[j];
  model.form = o.form;
}

}  // namespace

void DerivativeModelOptions::validate() const {
  if (body.empty()) throw InputError("derivatives fit: expected the body whose runs are fitted (--body)");
  check_name(NameKind::Body, body, {}, "--body");
  if (output.empty()) throw InputError("derivatives fit: expected the force or moment fitted (--output X..N)");
  if (!force_index(output))
    throw InputError("--output '" + escape::one_line(output) + "': expected one of X Y Z K M N");
  if (terms.empty() == model_template.empty())
    throw InputError("derivatives fit: expected either --terms or --template (" +
                     std::string(terms.empty() ? "neither" : "both") + " given)");
  if (!select.empty()) parse_folds(select);
  parse_selection(where, exclude_runs);
  if (!name.empty()) check_name(NameKind::Fit, name, {}, "--name");
  if (!(vif_threshold > 1.0) || !std::isfinite(vif_threshold))
    throw InputError("--vif-threshold must be a finite number above 1, not " + shortest_number(vif_threshold));
  if (!std::isnan(u0) && !std::isfinite(u0))
    throw InputError("--u0 must be a finite speed [m/s], not " + shortest_number(u0));
}

DerivativeModel fit_derivative_model(Database& database, const DerivativeModelOptions& options) {
  options.validate();
  const std::size_t dof = *force_index(options.output);
  const std::vector<Term> candidates = options.model_template.empty()
                                           ? parse_terms(options.terms)
                                           : model_template_terms(options.model_template, options.output);
  const RunSelection selection = parse_selection(options.where, options.exclude_runs);
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  RunDatabase& store = options.store ? impl.writable_store("derivatives fit") : impl.open_store();
  std::vector<std::int64_t> run_ids;
  const std::vector<DerivativeRun> runs = gather_runs(store, options, dof, selection, run_ids);
  // du = u - U0 comes from --u0 (unless every run states a disturbance du).
  const bool runs_state_du = std::all_of(runs.begin(), runs.end(), [](const auto& r) { return r.values.count("du"); });
  if (std::isnan(options.u0) && !runs_state_du)
    for (const Term& term : candidates)
      for (const auto& variable : term.variables())
        if (variable == "du")
          throw InputError("derivatives fit: term '" + term.text() +
                           "' reads du = u - U0; expected the nominal speed with --u0 U0 [m/s]");

  std::vector<Term> terms = candidates;
  if (!options.select.empty()) {
    TermSelectionOptions chosen;
    chosen.folds = parse_folds(options.select);
    chosen.seed = options.seed;
    chosen.use_uncertainties = options.weighted;
    terms = select_terms(options.output, candidates, runs, chosen).chosen;
  }
  DerivativeFitOptions fit_options;
  fit_options.use_uncertainties = options.weighted;
  fit_options.vif_threshold = options.vif_threshold;
  const DerivativeFit fit = fit_derivatives(options.output, terms, runs, fit_options);

  DerivativeModelRecord record;
  const std::string listed = options.model_template.empty() ? format_terms(candidates) : options.model_template;
  record.name = options.name.empty() ? default_fit_name(options.body, options.output, listed, selection.text()) +
                                           (options.select.empty() ? "" : "[" + options.select + "]")
                                     : options.name;
  record.body = options.body;
  record.output = options.output;
  record.terms = format_terms(terms);
  record.model_template = options.model_template;
  record.selection = options.select;
  record.candidates = options.select.empty() ? "" : format_terms(candidates);
  record.run_filter = selection.text();
  record.weighting = fit.weighted ? "uncertainty" : "none";
  record.n = fit.n;
  record.rmse = fit.rmse;
  record.r2 = finite_or_empty(fit.r2);
  record.condition_number = fit.condition_number;
  record.chi2_reduced = finite_or_empty(fit.chi2_reduced);
  record.covariance_scale = fit.covariance_scale;
  record.interval_factor = finite_or_empty(fit.interval_factor);
  if (std::all_of(fit.covariance.begin(), fit.covariance.end(), [](double x) { return std::isfinite(x); }))
    record.covariance = fit.covariance;
  for (const auto& w : fit.warnings) record.warnings.push_back({w.kind, w.message});
  for (std::size_t k = 0; k < terms.size(); ++k)
    record.coefficients.push_back({terms[k].text(), fit.coefficients[k], finite_or_empty(fit.std_errors[k]),
                                   finite_or_empty(fit.interval_low[k]), finite_or_empty(fit.interval_high[k]),
                                   finite_or_empty(fit.vif[k])});
  record.run_ids = run_ids;
  std::sort(record.run_ids.begin(), record.run_ids.end());
  if (options.store && options.name.empty())
    check_name(NameKind::Fit, record.name, {}, "the default name (give a shorter one with --name)");
  if (options.store)
    record.id = store.save_derivative_model(
        record, options.replace ? RunDatabase::NameTaken::Replace : RunDatabase::NameTaken::Refuse);
  return model_of(record, impl.path);
}

DerivativeModelList list_derivative_models(const Database& database, const std::string& body) {
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  DerivativeModelList out;
  out.database = impl.path;
  for (const auto& record :
       impl.open_store().derivative_models(body.empty() ? std::nullopt : std::optional<std::string>(body)))
    out.models.push_back(model_of(record, impl.path));
  return out;
}

void DerivativeShowOptions::validate() const {
  if (name.empty())
    throw InputError("derivatives show: expected the name of a stored model ('hydrocoef derivatives list' lists them)");
  if (form != "dimensional" && form != "prime" && form != "bis" && form != "mmg")
    throw InputError("--form '" + escape::one_line(form) + "': expected dimensional, prime, bis or mmg");
  const std::array<std::pair<double, const char*>, 7> given{{{length, "--length"},
                                                             {speed, "--speed"},
                                                             {density, "--density"},
                                                             {draft, "--draft"},
                                                             {mass, "--mass"},
                                                             {volume, "--volume"},
                                                             {gravity, "--gravity"}}};
  for (const auto& [value, option] : given)
    if (!std::isnan(value) && !(std::isfinite(value) && value > 0.0))
      throw InputError(std::string(option) + " must be a finite number above 0, not " + shortest_number(value));
}

DerivativeModel show_derivative_model(const Database& database, const DerivativeShowOptions& options) {
  options.validate();
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  const auto models = impl.open_store().derivative_models();
  DerivativeModel out = model_of(find_model(models, options.name, impl.path), impl.path);
  if (options.form != "dimensional") restate(out, options);
  return out;
}

DerivativeDeletion delete_derivative_model(Database& database, const std::string& name) {
  if (name.empty())
    throw InputError(
        "derivatives delete: expected the name of a stored model ('hydrocoef derivatives list' lists them)");
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  auto& store = impl.writable_store("derivatives delete");
  const auto models = store.derivative_models();
  DerivativeDeletion out;
  out.database = impl.path;
  out.name = name;
  out.id = find_model(models, name, impl.path).id;
  store.delete_derivative_model(name);
  return out;
}

void DerivativeEvaluationOptions::validate() const {
  if (name.empty())
    throw InputError(
        "derivatives evaluate: expected the name of a stored model ('hydrocoef derivatives list' lists them)");
  if (at.empty()) throw InputError("derivatives evaluate: expected the point (--at NAME=VALUE, repeatable)");
  for (const auto& [variable, value] : at)
    if (!std::isfinite(value)) throw InputError("--at " + variable + ": expected a finite number");
}

DerivativeEvaluation evaluate_derivative_model(const Database& database, const DerivativeEvaluationOptions& options) {
  options.validate();
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  const auto models = impl.open_store().derivative_models();
  const DerivativeModelRecord& record = find_model(models, options.name, impl.path);
  const std::vector<Term> terms = parse_terms(record.terms);
  DerivativeEvaluation out;
  out.name = record.name;
  out.output = record.output;
  out.unit = derivative_output_unit(record.output);
  out.at = options.at;
  out.stale = record.stale;
  const std::size_t m = terms.size();
  for (std::size_t k = 0; k < m && k < record.coefficients.size(); ++k) {
    for (const auto& name : terms[k].variables())
      if (!options.at.count(name))
        throw InputError("derivatives evaluate '" + escape::one_line(record.name) + "': term '" + terms[k].text() +
                         "' needs " + name + "; expected --at " + name + "=VALUE");
    out.basis.push_back(terms[k].evaluate(options.at));
    out.value += record.coefficients[k].value * out.basis.back();
  }
  if (record.covariance.size() == m * m) {
    double variance = 0.0;
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j = 0; j < m; ++j) variance += out.basis[i] * record.covariance[i * m + j] * out.basis[j];
    // Round-off may leave a variance that vanishes a hair below zero.
    out.std_error = std::sqrt(std::max(variance, 0.0));
  }
  return out;
}

}  // namespace api
}  // namespace hydrocoef
