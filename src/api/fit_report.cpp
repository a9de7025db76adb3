// What `hydrocoef fit` and `hydrocoef fits` print: the text and JSON of a
// fit, a per-level fit, a refit, the stored fits and a stored law evaluated.
#include "src/api/internal.hpp"
#include "src/api/records_format.hpp"
#include "src/api/records_report.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/sign_convention.hpp"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace hydrocoef {
namespace records {
namespace {

nlohmann::json warnings_json(const std::vector<FitWarning>& warnings) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& warning : warnings) out.push_back({{"kind", warning.kind}, {"message", warning.message}});
  return out;
}

void print_warnings(std::ostream& out, const std::vector<FitWarning>& warnings) {
  for (const auto& warning : warnings)
    out << "  warning (" << escape::one_line(warning.kind) << "): " << escape::one_line(warning.message) << '\n';
}

std::string fit_json(const FitResult& result, const std::string& body, const std::string& dof) {
  const FitSetup& setup = result.setup;
  const DampingLawSpec& spec = setup.spec;
  const DampingLawFit& fit = result.fit;
  nlohmann::json out = {{"name", result.name},
                        {"body", body},
                        {"dof", dof},
                        {"variable", spec.variable},
                        {"terms", format_damping_terms(spec)},
                        {"loss", fit.loss},
                        {"where", setup.selection},
                        {"sign_convention", std::string(to_string(setup.samples.sign))},
                        {"rmse", fit.rmse},
                        {"r2", optional_number(fit.r2)},
                        {"n", fit.n},
                        {"weighting", fit.weighted ? "uncertainty" : "none"},
                        {"chi2_reduced", optional_number(fit.chi2_reduced)},
                        {"covariance_scale", fit.covariance_scale},
                        {"covariance", fit.covariance},
                        {"runs", result.run_ids()},
                        {"mirror", setup.mirror.text()},
                        {"mirror_images", result.mirror_images()},
                        {"varying_conditions", result.varying_conditions},
                        {"stored", result.fit_id.has_value()}};
  out["warnings"] = warnings_json(setup.warnings);
  out["coefficients"] = nlohmann::json::object();
  out["std_errors"] = nlohmann::json::object();
  out["units"] = nlohmann::json::object();
  for (std::size_t k = 0; k < spec.terms.size(); ++k) {
    const std::string term = term_name(spec.terms[k], spec.variable);
    out["coefficients"][term] = fit.coefficients[k];
    out["std_errors"][term] = optional_number(fit.std_errors[k]);
    out["units"][term] = setup.coefficient_units[k];
  }
  if (result.fit_id) out["fit_id"] = *result.fit_id;
  return escape::json_text(out, 2) + '\n';
}

std::string fit_text(const FitResult& result, const std::string& dof, const std::string& database) {
  const FitSetup& setup = result.setup;
  const DampingLawSpec& spec = setup.spec;
  const DampingLawFit& fit = result.fit;
  const auto& samples = setup.samples;
  const std::size_t images = result.mirror_images();
  std::ostringstream out;
  std::ostringstream law;
  law << dof << "(" << spec.variable << ") =";
  for (std::size_t k = 0; k < spec.terms.size(); ++k) {
    const double c = fit.coefficients[k];
    law << (k == 0 ? (c < 0 ? " -" : " ") : (c < 0 ? " - " : " + ")) << significant(std::abs(c), 6);
    if (spec.terms[k] != DampingTerm::Constant) law << " " << term_name(spec.terms[k], spec.variable);
  }
  out << "fit " << escape::one_line(result.name) << "\n  " << escape::one_line(law.str()) << "\n  sign convention: "
      << (samples.sign == SignConvention::OnBody ? "force on the body (damping is negative)"
                                                 : "as tabulated, positive opposes motion")
      << "\n\n";
  out << std::left << "  " << std::setw(8) << "term" << std::setw(16) << "coefficient" << std::setw(14) << "std. error"
      << "unit\n";
  for (std::size_t k = 0; k < spec.terms.size(); ++k)
    out << "  " << std::setw(8) << term_name(spec.terms[k], spec.variable) << std::setw(16)
        << significant(fit.coefficients[k], 7) << std::setw(14)
        << (std::isfinite(fit.std_errors[k]) ? significant(fit.std_errors[k], 3) : "n/a")
        << escape::one_line(setup.coefficient_units[k]) << '\n';
  if (images > 0 || samples.images_skipped > 0)
    out << "\n  mirror " << escape::one_line(setup.mirror.text()) << ": " << samples.runs.size() << " runs and "
        << images << " mirror images (never stored as runs)"
        << (samples.images_skipped
                ? "; " + std::to_string(samples.images_skipped) + " images left out at the keys of measured runs"
                : std::string())
        << '\n';
  out << "\n  n = " << fit.n << " samples, RMSE = " << significant(fit.rmse, 4) << " " << force_unit(setup.dof)
      << ", R^2 = " << significant(fit.r2, 8)
      << (std::isnan(fit.r2) ? " (the force does not vary over these runs)" : "") << ", loss "
      << escape::one_line(fit.loss) << '\n';
  if (fit.weighted) {
    out << "  weighted by each run's uncertainty (1/s^2); reduced chi^2 = "
        << (std::isfinite(fit.chi2_reduced) ? significant(fit.chi2_reduced, 4) : std::string("n/a"));
    if (fit.covariance_scale > 1.0)
      out << ": the runs scatter about the law more than their uncertainties say, so the standard errors "
             "are the stated uncertainties' scaled by the Birge ratio sqrt(chi^2/(n-k)) = "
          << significant(std::sqrt(fit.covariance_scale), 4) << "\n";
    else
      out << " (expected about 1 if the runs scatter as their uncertainties say): standard errors from the "
             "stated uncertainties\n";
  }
  if (!result.varying_conditions.empty()) {
    std::string names;
    for (const auto& v : result.varying_conditions) names += (names.empty() ? "" : ", ") + v;
    out << "  note: the runs differ in " << escape::one_line(names)
        << "; add --where NAME=VALUE to fit one condition\n";
  }
  print_warnings(out, setup.warnings);
  if (result.fit_id) out << "  stored as fit " << *result.fit_id << " in " << escape::one_line(database) << '\n';
  return out.str();
}

/// A stored fit's object of `fits --json`, from the summary's public fields.
nlohmann::json stored_fit_json(const FitSummary& fit) {
  nlohmann::json item = {{"id", fit.id},
                         {"name", fit.name},
                         {"body", fit.body},
                         {"dof", fit.output},
                         {"variable", fit.variable},
                         {"terms", fit.terms},
                         {"loss", fit.loss},
                         {"where", fit.where},
                         {"sign_convention", fit.sign_convention},
                         {"n", fit.n},
                         {"rmse", fit.rmse},
                         {"r2", fit.r2},
                         {"created_at", fit.created_at},
                         {"runs", fit.runs},
                         {"stale", fit.stale},
                         {"mirror", fit.mirror},
                         {"weighting", fit.weighting},
                         {"chi2_reduced", optional_number(fit.chi2_reduced)},
                         {"covariance", fit.covariance}};
  item["coefficients"] = nlohmann::json::object();
  item["std_errors"] = nlohmann::json::object();
  for (const auto& c : fit.coefficients) {
    item["coefficients"][c.term] = c.value;
    item["std_errors"][c.term] = optional_number(c.std_error);
  }
  return item;
}

std::string stored_fit_text(const FitRecord& fit) {
  std::ostringstream out;
  out << fit.id << "  " << escape::one_line(fit.name) << "  [" << to_string(fit.sign) << ", n=" << fit.n
      << ", RMSE=" << significant(fit.rmse, 4) << ", R^2=" << significant(fit.r2, 8)
      << (fit.weighting == "none"
              ? std::string()
              : ", weighted, chi^2/dof=" + (fit.chi2_reduced ? significant(*fit.chi2_reduced, 3) : std::string("n/a")))
      << "]"
      << (fit.stale ? "  STALE: a force of its runs changed or was deleted since; fit --refit makes it again" : "")
      << "\n    from " << fit.run_ids.size() << (fit.run_ids.size() == 1 ? " run" : " runs")
      << (fit.run_filter.empty() ? "" : " where " + escape::one_line(fit.run_filter))
      << (fit.mirror.empty() ? "" : ", with mirror images (" + escape::one_line(fit.mirror) + ")") << "\n    ";
  for (const auto& c : fit.coefficients) out << escape::one_line(c.term) << "=" << significant(c.value, 7) << "  ";
  out << '\n';
  return out.str();
}

std::string level_json(const LevelFitResult& result, const LevelFitRequest& request) {
  const FitSetup& setup = result.setup;
  const DampingLawSpec& spec = setup.spec;
  const auto& fits = result.levels;
  const auto& curves = result.curves;
  nlohmann::json out = {{"name", result.base_name},
                        {"body", request.fit.body},
                        {"dof", request.fit.dof},
                        {"variable", spec.variable},
                        {"terms", format_damping_terms(spec)},
                        {"by", request.by},
                        {"curve", request.curve},
                        {"where", setup.selection},
                        {"sign_convention", std::string(to_string(setup.samples.sign))}};
  out["levels"] = nlohmann::json::array();
  for (std::size_t l = 0; l < fits.size(); ++l) {
    nlohmann::json item = {{"level", fits[l].level},
                           {"name", result.names[l]},
                           {"n", fits[l].fit.n},
                           {"rmse", fits[l].fit.rmse},
                           {"r2", optional_number(fits[l].fit.r2)},
                           {"stored", result.ids[l].has_value()}};
    for (std::size_t k = 0; k < spec.terms.size(); ++k) {
      const std::string term = term_name(spec.terms[k], spec.variable);
      item["coefficients"][term] = fits[l].fit.coefficients[k];
      item["std_errors"][term] = optional_number(fits[l].fit.std_errors[k]);
    }
    if (result.ids[l]) item["fit_id"] = *result.ids[l];
    out["levels"].push_back(item);
  }
  out["warnings"] = warnings_json(setup.warnings);
  out["skipped_levels"] = nlohmann::json::array();
  for (const auto& level : result.skipped)
    out["skipped_levels"].push_back({{"level", level.level}, {"runs", level.runs}, {"reason", level.reason}});
  out["curves"] = nlohmann::json::array();
  for (std::size_t k = 0; k < curves.size(); ++k)
    out["curves"].push_back({{"term", curves[k].term},
                             {"kind", curves[k].kind == CurveKind::Pchip ? "pchip" : "polynomial"},
                             {"degree", curves[k].degree},
                             {"polynomial", curves[k].polynomial},
                             {"levels", curves[k].levels},
                             {"values", curves[k].values},
                             {"rmse", curves[k].rmse},
                             {"unit", setup.coefficient_units[k]}});
  return escape::json_text(out, 2) + '\n';
}

std::string level_text(const LevelFitResult& result, const LevelFitRequest& request, const std::string& database) {
  const FitSetup& setup = result.setup;
  const DampingLawSpec& spec = setup.spec;
  const auto& fits = result.levels;
  const auto& curves = result.curves;
  const std::string& by = request.by;
  std::ostringstream out;
  out << "fit " << escape::one_line(result.base_name) << " at each level of " << escape::one_line(by) << " ("
      << fits.size() << " levels)\n\n  " << std::left << std::setw(12) << escape::one_line(by);
  for (std::size_t k = 0; k < spec.terms.size(); ++k) out << std::setw(16) << term_name(spec.terms[k], spec.variable);
  out << std::setw(6) << "n"
      << "R^2\n";
  for (const auto& level : fits) {
    out << "  " << std::setw(12) << significant(level.level, 6);
    for (double c : level.fit.coefficients) out << std::setw(16) << significant(c, 7);
    out << std::setw(6) << level.fit.n << significant(level.fit.r2, 6) << '\n';
  }
  out << "\n  coefficient curves over " << escape::one_line(by) << " (" << escape::one_line(request.curve) << "):\n";
  for (std::size_t k = 0; k < curves.size(); ++k) {
    out << "    " << std::setw(8) << escape::one_line(curves[k].term);
    if (curves[k].kind == CurveKind::Pchip) {
      out << "PCHIP through the " << curves[k].levels.size() << " per-level values";
    } else {
      for (std::size_t j = 0; j < curves[k].polynomial.size(); ++j) {
        const double c = curves[k].polynomial[j];
        out << (j == 0 ? (c < 0 ? "-" : "") : (c < 0 ? " - " : " + ")) << significant(std::abs(c), 6);
        if (j >= 1) out << " " << escape::one_line(by);
        if (j >= 2) out << "^" << j;
      }
      out << "   (RMSE " << significant(curves[k].rmse, 3) << ")";
    }
    out << "  [" << escape::one_line(setup.coefficient_units[k]) << "]\n";
  }
  for (const auto& level : result.skipped)
    out << "  note: level " << escape::one_line(by) << "=" << significant(level.level, 6)
        << " skipped: " << escape::one_line(level.reason) << " (--strict refuses the fit instead)\n";
  print_warnings(out, setup.warnings);
  if (request.fit.store)
    out << "  stored " << fits.size() << " per-level fits in " << escape::one_line(database) << '\n';
  return out.str();
}

std::vector<std::string> warning_texts(const std::vector<FitWarning>& warnings) {
  std::vector<std::string> out;
  for (const auto& warning : warnings) out.push_back(warning.kind + ": " + warning.message);
  return out;
}

}  // namespace

FitSummary fit_summary(const FitResult& result, const std::string& body, const std::string& output,
                       const std::string& database) {
  const DampingLawSpec& spec = result.setup.spec;
  const DampingLawFit& law = result.fit;
  FitSummary out;
  out.warnings = warning_texts(result.setup.warnings);
  out.id = result.fit_id.value_or(0);
  out.name = result.name;
  out.body = body;
  out.output = output;
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
  out.weighting = law.weighted ? "uncertainty" : "none";
  out.chi2_reduced = law.chi2_reduced;
  out.covariance_scale = law.covariance_scale;
  out.covariance = law.covariance;
  out.mirror_images = result.mirror_images();
  out.varying_conditions = result.varying_conditions;
  FitSummary::Access::set(out, fit_text(result, output, database), fit_json(result, body, output));
  return out;
}

FitSummary fit_summary(const FitRecord& record) {
  FitSummary fit;
  fit.name = record.name;
  fit.body = record.body;
  fit.output = record.dof;
  fit.variable = record.variable;
  fit.terms = record.terms;
  fit.loss = record.loss;
  fit.where = record.run_filter;
  fit.mirror = record.mirror;
  fit.sign_convention = std::string(to_string(record.sign));
  const auto units = coefficient_units(record.terms, record.dof, record.variable);
  for (std::size_t k = 0; k < record.coefficients.size(); ++k) {
    const auto& c = record.coefficients[k];
    fit.coefficients.push_back(
        {c.term, c.value, c.std_error.value_or(kNaN), k < units.size() ? units[k] : std::string()});
  }
  fit.rmse = record.rmse;
  fit.r2 = record.r2;
  fit.n = record.n;
  fit.runs = record.run_ids;
  fit.id = record.id;
  fit.stale = record.stale;
  fit.created_at = record.created_at;
  fit.weighting = record.weighting;
  fit.chi2_reduced = record.chi2_reduced.value_or(kNaN);
  fit.covariance = record.covariance;
  FitSummary::Access::set(fit, stored_fit_text(record), escape::json_text(stored_fit_json(fit), 2) + '\n');
  return fit;
}

LevelFits level_fits(const LevelFitResult& result, const LevelFitRequest& request, const std::string& database) {
  const FitSetup& setup = result.setup;
  const DampingLawSpec& spec = setup.spec;
  LevelFits out;
  out.name = result.base_name;
  out.body = request.fit.body;
  out.output = request.fit.dof;
  out.variable = spec.variable;
  out.terms = format_damping_terms(spec);
  out.by = request.by;
  out.curve = request.curve;
  out.where = setup.selection;
  out.sign_convention = std::string(to_string(setup.samples.sign));
  out.stored = request.fit.store;
  for (std::size_t l = 0; l < result.levels.size(); ++l) {
    const auto& level = result.levels[l];
    LevelFitSummary item;
    item.level = level.level;
    item.name = result.names[l];
    item.n = level.fit.n;
    item.rmse = level.fit.rmse;
    item.r2 = level.fit.r2;
    for (std::size_t k = 0; k < spec.terms.size(); ++k)
      item.coefficients.push_back({term_name(spec.terms[k], spec.variable), level.fit.coefficients[k],
                                   level.fit.std_errors[k], setup.coefficient_units[k]});
    item.id = result.ids[l].value_or(0);
    out.levels.push_back(std::move(item));
  }
  for (const auto& level : result.skipped) out.skipped.push_back({level.level, level.runs, level.reason});
  for (std::size_t k = 0; k < result.curves.size(); ++k) {
    const auto& c = result.curves[k];
    out.curves.push_back({c.term, c.kind == CurveKind::Pchip ? "pchip" : "polynomial", c.degree, c.polynomial, c.levels,
                          c.values, c.rmse, setup.coefficient_units[k]});
  }
  out.warnings = warning_texts(setup.warnings);
  LevelFits::Access::set(out, level_text(result, request, database), level_json(result, request));
  return out;
}

}  // namespace records

inline namespace api {

std::string FitSummary::text() const { return text_; }
std::string FitSummary::json() const { return json_; }
std::string LevelFits::text() const { return text_; }
std::string LevelFits::json() const { return json_; }

std::string Refits::json() const {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i = 0; i < made.size(); ++i) {
    nlohmann::json item = {{"name", made[i].name},
                           {"n", made[i].n},
                           {"runs", made[i].runs},
                           {"rmse", made[i].rmse},
                           {"r2", records::optional_number(made[i].r2)}};
    for (const auto& c : made[i].coefficients) item["coefficients"][c.term] = c.value;
    if (i < previous.size())
      for (const auto& c : previous[i].coefficients) item["previous_coefficients"][c.term] = c.value;
    out.push_back(item);
  }
  return escape::json_text(out, 2) + '\n';
}

std::string Refits::text() const {
  using records::significant;
  if (made.empty()) return "no stale fits in " + escape::one_line(database) + "; nothing to fit again\n";
  std::ostringstream out;
  for (std::size_t i = 0; i < made.size(); ++i) {
    const std::size_t was = i < previous.size() ? previous[i].runs.size() : 0;
    out << "fit " << escape::one_line(made[i].name) << " made again from " << made[i].runs.size() << " runs (was "
        << was << ")\n   ";
    for (std::size_t k = 0; k < made[i].coefficients.size(); ++k) {
      const auto& c = made[i].coefficients[k];
      out << " " << escape::one_line(c.term) << " = " << significant(c.value, 7);
      if (i < previous.size() && k < previous[i].coefficients.size())
        out << " (was " << significant(previous[i].coefficients[k].value, 7) << ")";
    }
    out << '\n';
  }
  out << made.size() << (made.size() == 1 ? " fit" : " fits") << " stored in " << escape::one_line(database) << '\n';
  return out.str();
}

std::string FitList::json() const {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& fit : fits) out.push_back(records::stored_fit_json(fit));
  return escape::json_text(out, 2) + '\n';
}

std::string FitList::text() const {
  if (fits.empty()) return "no fits in " + escape::one_line(database) + '\n';
  std::string out;
  for (const auto& fit : fits) out += fit.text();
  return out;
}

std::string FitEvaluation::json() const {
  nlohmann::json out = {{"name", name},
                        {"dof", output},
                        {"variable", variable},
                        {"sign_convention", sign_convention},
                        {"unit", unit},
                        {"variable_unit", variable_unit},
                        {"stale", stale},
                        {"fitted_range", {records::optional_number(fitted_min), records::optional_number(fitted_max)}},
                        {"at", at},
                        {"value", value}};
  out["std_error"] = nlohmann::json::array();
  for (const double s : std_error) out["std_error"].push_back(records::optional_number(s));
  return escape::json_text(out, 2) + '\n';
}

std::string FitEvaluation::text() const {
  using records::significant;
  std::ostringstream out;
  out << "fit " << escape::one_line(name) << ": " << output << "(" << variable << ") ["
      << (sign_convention == "opposing" ? "as tabulated, positive opposes motion" : "force on the body") << "]"
      << (stale ? "  STALE: a force of its runs changed or was deleted since; fit --refit makes it again" : "")
      << "\n\n  " << std::left << std::setw(16) << (variable + " [" + variable_unit + "]") << std::setw(16)
      << (output + " [" + unit + "]") << "std. error [" << unit << "]\n";
  bool extrapolated = false, no_covariance = false;
  for (std::size_t i = 0; i < at.size(); ++i) {
    const bool outside = !std::isnan(fitted_min) && (at[i] < fitted_min || at[i] > fitted_max);
    extrapolated = extrapolated || outside;
    no_covariance = no_covariance || std::isnan(std_error[i]);
    out << "  " << std::setw(16) << (significant(at[i], 6) + (outside ? "*" : "")) << std::setw(16)
        << significant(value[i], 7) << significant(std_error[i], 3) << '\n';
  }
  if (!std::isnan(fitted_min))
    out << "\n  fitted over " << variable << " = " << significant(fitted_min, 6) << " to " << significant(fitted_max, 6)
        << " " << variable_unit << (extrapolated ? "; * = outside it (extrapolated)" : "") << '\n';
  if (no_covariance)
    out << "  note: n/a: no covariance of the coefficients (a fit of an older hydrocoef: fit --refit makes it "
           "again with one; or as many runs as terms)\n";
  return out.str();
}

}  // namespace api
}  // namespace hydrocoef
