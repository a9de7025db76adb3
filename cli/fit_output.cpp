// How the CLI shows fits: text and JSON of a fit, a per-level fit, a refit
// and the stored fits (hydrocoef fit, fits).
#include "cli/fit_output.hpp"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cli/common.hpp"
#include "src/core/escape.hpp"
#include "src/fit/physical_checks.hpp"

namespace hydrocoef::cli {
namespace {

nlohmann::json optional_number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

nlohmann::json warnings_json(const std::vector<FitWarning>& warnings) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& warning : warnings) out.push_back({{"kind", warning.kind}, {"message", warning.message}});
  return out;
}

void print_warnings(const std::vector<FitWarning>& warnings) {
  for (const auto& warning : warnings)
    std::cout << "  warning (" << escape::one_line(warning.kind) << "): " << escape::one_line(warning.message) << '\n';
}

}  // namespace

void print_fit(const FitResult& result, const std::string& dof, const std::string& body, const std::string& database,
               bool json) {
  const FitSetup& setup = result.setup;
  const DampingLawSpec& spec = setup.spec;
  const DampingLawFit& fit = result.fit;
  const std::string terms = format_damping_terms(spec);
  const auto& samples = setup.samples;
  const std::size_t images = result.mirror_images();
  if (json) {
    nlohmann::json out = {{"name", result.name},
                          {"body", body},
                          {"dof", dof},
                          {"variable", spec.variable},
                          {"terms", terms},
                          {"loss", fit.loss},
                          {"where", setup.selection},
                          {"sign_convention", std::string(to_string(samples.sign))},
                          {"rmse", fit.rmse},
                          {"r2", optional_number(fit.r2)},
                          {"n", fit.n},
                          {"weighting", fit.weighted ? "uncertainty" : "none"},
                          {"chi2_reduced", optional_number(fit.chi2_reduced)},
                          {"covariance_scale", fit.covariance_scale},
                          {"covariance", fit.covariance},
                          {"runs", result.run_ids()},
                          {"mirror", setup.mirror.text()},
                          {"mirror_images", images},
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
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  std::ostringstream law;
  law << dof << "(" << spec.variable << ") =";
  for (std::size_t k = 0; k < spec.terms.size(); ++k) {
    const double c = fit.coefficients[k];
    law << (k == 0 ? (c < 0 ? " -" : " ") : (c < 0 ? " - " : " + ")) << significant(std::abs(c), 6);
    if (spec.terms[k] != DampingTerm::Constant) law << " " << term_name(spec.terms[k], spec.variable);
  }
  std::cout << "fit " << escape::one_line(result.name) << "\n  " << escape::one_line(law.str())
            << "\n  sign convention: "
            << (samples.sign == SignConvention::OnBody ? "force on the body (damping is negative)"
                                                       : "as tabulated, positive opposes motion")
            << "\n\n";
  std::cout << std::left << "  " << std::setw(8) << "term" << std::setw(16) << "coefficient" << std::setw(14)
            << "std. error"
            << "unit\n";
  for (std::size_t k = 0; k < spec.terms.size(); ++k)
    std::cout << "  " << std::setw(8) << term_name(spec.terms[k], spec.variable) << std::setw(16)
              << significant(fit.coefficients[k], 7) << std::setw(14)
              << (std::isfinite(fit.std_errors[k]) ? significant(fit.std_errors[k], 3) : "n/a")
              << escape::one_line(setup.coefficient_units[k]) << '\n';
  if (images > 0 || samples.images_skipped > 0)
    std::cout << "\n  mirror " << escape::one_line(setup.mirror.text()) << ": " << samples.runs.size() << " runs and "
              << images << " mirror images (never stored as runs)"
              << (samples.images_skipped
                      ? "; " + std::to_string(samples.images_skipped) + " images left out at the keys of measured runs"
                      : std::string())
              << '\n';
  std::cout << "\n  n = " << fit.n << " samples, RMSE = " << significant(fit.rmse, 4) << " " << force_unit(setup.dof)
            << ", R^2 = " << significant(fit.r2, 8)
            << (std::isnan(fit.r2) ? " (the force does not vary over these runs)" : "") << ", loss "
            << escape::one_line(fit.loss) << '\n';
  if (fit.weighted) {
    std::cout << "  weighted by each run's uncertainty (1/s^2); reduced chi^2 = "
              << (std::isfinite(fit.chi2_reduced) ? significant(fit.chi2_reduced, 4) : std::string("n/a"));
    if (fit.covariance_scale > 1.0)
      std::cout << ": the runs scatter about the law more than their uncertainties say, so the standard errors "
                   "are the stated uncertainties' scaled by the Birge ratio sqrt(chi^2/(n-k)) = "
                << significant(std::sqrt(fit.covariance_scale), 4) << "\n";
    else
      std::cout << " (expected about 1 if the runs scatter as their uncertainties say): standard errors from the "
                   "stated uncertainties\n";
  }
  if (!result.varying_conditions.empty()) {
    std::string names;
    for (const auto& v : result.varying_conditions) names += (names.empty() ? "" : ", ") + v;
    std::cout << "  note: the runs differ in " << escape::one_line(names)
              << "; add --where NAME=VALUE to fit one condition\n";
  }
  print_warnings(setup.warnings);
  if (result.fit_id) std::cout << "  stored as fit " << *result.fit_id << " in " << escape::one_line(database) << '\n';
}

void print_level_fit(const LevelFitResult& result, const LevelFitRequest& request, const std::string& database,
                     bool json) {
  const FitSetup& setup = result.setup;
  const DampingLawSpec& spec = setup.spec;
  const auto& fits = result.levels;
  const auto& curves = result.curves;
  const std::string& by = request.by;
  if (json) {
    nlohmann::json out = {{"name", result.base_name},
                          {"body", request.fit.body},
                          {"dof", request.fit.dof},
                          {"variable", spec.variable},
                          {"terms", format_damping_terms(spec)},
                          {"by", by},
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
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  std::cout << "fit " << escape::one_line(result.base_name) << " at each level of " << escape::one_line(by) << " ("
            << fits.size() << " levels)\n\n  " << std::left << std::setw(12) << escape::one_line(by);
  for (std::size_t k = 0; k < spec.terms.size(); ++k)
    std::cout << std::setw(16) << term_name(spec.terms[k], spec.variable);
  std::cout << std::setw(6) << "n"
            << "R^2\n";
  for (const auto& level : fits) {
    std::cout << "  " << std::setw(12) << significant(level.level, 6);
    for (double c : level.fit.coefficients) std::cout << std::setw(16) << significant(c, 7);
    std::cout << std::setw(6) << level.fit.n << significant(level.fit.r2, 6) << '\n';
  }
  std::cout << "\n  coefficient curves over " << escape::one_line(by) << " (" << escape::one_line(request.curve)
            << "):\n";
  for (std::size_t k = 0; k < curves.size(); ++k) {
    std::cout << "    " << std::setw(8) << escape::one_line(curves[k].term);
    if (curves[k].kind == CurveKind::Pchip) {
      std::cout << "PCHIP through the " << curves[k].levels.size() << " per-level values";
    } else {
      for (std::size_t j = 0; j < curves[k].polynomial.size(); ++j) {
        const double c = curves[k].polynomial[j];
        std::cout << (j == 0 ? (c < 0 ? "-" : "") : (c < 0 ? " - " : " + ")) << significant(std::abs(c), 6);
        if (j >= 1) std::cout << " " << escape::one_line(by);
        if (j >= 2) std::cout << "^" << j;
      }
      std::cout << "   (RMSE " << significant(curves[k].rmse, 3) << ")";
    }
    std::cout << "  [" << escape::one_line(setup.coefficient_units[k]) << "]\n";
  }
  for (const auto& level : result.skipped)
    std::cout << "  note: level " << escape::one_line(by) << "=" << significant(level.level, 6)
              << " skipped: " << escape::one_line(level.reason) << " (--strict refuses the fit instead)\n";
  print_warnings(setup.warnings);
  if (request.fit.store)
    std::cout << "  stored " << fits.size() << " per-level fits in " << escape::one_line(database) << '\n';
}

void print_refit(const RefitResult& result, const std::string& database, bool json) {
  const auto& made = result.made;
  const auto& chosen = result.previous;
  if (json) {
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t i = 0; i < made.size(); ++i) {
      nlohmann::json item = {{"name", made[i].name},
                             {"n", made[i].n},
                             {"runs", made[i].run_ids},
                             {"rmse", made[i].rmse},
                             {"r2", optional_number(made[i].r2)}};
      for (const auto& c : made[i].coefficients) item["coefficients"][c.term] = c.value;
      for (const auto& c : chosen[i].coefficients) item["previous_coefficients"][c.term] = c.value;
      out.push_back(item);
    }
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  if (made.empty()) {
    std::cout << "no stale fits in " << escape::one_line(database) << "; nothing to fit again\n";
    return;
  }
  for (std::size_t i = 0; i < made.size(); ++i) {
    std::cout << "fit " << escape::one_line(made[i].name) << " made again from " << made[i].run_ids.size()
              << " runs (was " << chosen[i].run_ids.size() << ")\n   ";
    for (std::size_t k = 0; k < made[i].coefficients.size(); ++k) {
      const auto& c = made[i].coefficients[k];
      std::cout << " " << escape::one_line(c.term) << " = " << significant(c.value, 7);
      if (k < chosen[i].coefficients.size())
        std::cout << " (was " << significant(chosen[i].coefficients[k].value, 7) << ")";
    }
    std::cout << '\n';
  }
  std::cout << made.size() << (made.size() == 1 ? " fit" : " fits") << " stored in " << escape::one_line(database)
            << '\n';
}

void print_fits(const std::vector<FitRecord>& fits, const std::string& database, bool json) {
  if (json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& fit : fits) {
      nlohmann::json item = {{"id", fit.id},
                             {"name", fit.name},
                             {"body", fit.body},
                             {"dof", fit.dof},
                             {"variable", fit.variable},
                             {"terms", fit.terms},
                             {"loss", fit.loss},
                             {"where", fit.run_filter},
                             {"sign_convention", std::string(to_string(fit.sign))},
                             {"n", fit.n},
                             {"rmse", fit.rmse},
                             {"r2", fit.r2},
                             {"created_at", fit.created_at},
                             {"runs", fit.run_ids},
                             {"stale", fit.stale},
                             {"mirror", fit.mirror},
                             {"weighting", fit.weighting},
                             {"chi2_reduced", fit.chi2_reduced ? nlohmann::json(*fit.chi2_reduced) : nlohmann::json()},
                             {"covariance", fit.covariance}};
      item["coefficients"] = nlohmann::json::object();
      item["std_errors"] = nlohmann::json::object();
      for (const auto& c : fit.coefficients) {
        item["coefficients"][c.term] = c.value;
        item["std_errors"][c.term] = c.std_error ? nlohmann::json(*c.std_error) : nlohmann::json();
      }
      out.push_back(item);
    }
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  if (fits.empty()) {
    std::cout << "no fits in " << escape::one_line(database) << '\n';
    return;
  }
  for (const auto& fit : fits) {
    std::cout << fit.id << "  " << escape::one_line(fit.name) << "  [" << to_string(fit.sign) << ", n=" << fit.n
              << ", RMSE=" << significant(fit.rmse, 4) << ", R^2=" << significant(fit.r2, 8)
              << (fit.weighting == "none"
                      ? std::string()
                      : ", weighted, chi^2/dof=" +
                            (fit.chi2_reduced ? significant(*fit.chi2_reduced, 3) : std::string("n/a")))
              << "]"
              << (fit.stale ? "  STALE: a force of its runs changed or was deleted since; fit --refit makes it again"
                            : "")
              << "\n    from " << fit.run_ids.size() << (fit.run_ids.size() == 1 ? " run" : " runs")
              << (fit.run_filter.empty() ? "" : " where " + escape::one_line(fit.run_filter))
              << (fit.mirror.empty() ? "" : ", with mirror images (" + escape::one_line(fit.mirror) + ")") << "\n    ";
    for (const auto& c : fit.coefficients)
      std::cout << escape::one_line(c.term) << "=" << significant(c.value, 7) << "  ";
    std::cout << '\n';
  }
}

}  // namespace hydrocoef::cli
