// What `hydrocoef derivatives` prints: a model (fit, show), the list, a
// deletion and an evaluation, as text for people and as JSON
// (include/hydrocoef/derivatives.hpp). Names are escaped for the terminal
// in text (escape::one_line) and are JSON strings in JSON.
#include "src/api/internal.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <utility>
#include <vector>

#include "hydrocoef/derivatives.hpp"
#include "src/api/derivatives_report.hpp"
#include "src/api/records_format.hpp"
#include "src/core/escape.hpp"

namespace hydrocoef {
inline namespace api {
namespace {

using records::optional_number;

std::string number(double value) { return std::isfinite(value) ? significant(value, 6) : std::string("n/a"); }

std::string variable_unit(const std::string& name) {
  if (name == "u" || name == "v" || name == "w" || name == "du") return "m/s";
  if (name == "p" || name == "q" || name == "r") return "rad/s";
  if (name == "alpha" || name == "beta" || name == "delta" || name.rfind("delta_", 0) == 0) return "rad";
  return "[" + name + "]";
}

nlohmann::json model_json(const DerivativeModel& model) {
  nlohmann::json out = {{"name", model.name},
                        {"body", model.body},
                        {"output", model.output},
                        {"unit", model.unit},
                        {"terms", model.terms},
                        {"template", model.model_template},
                        {"selection", model.selection},
                        {"candidates", model.candidates},
                        {"where", model.where},
                        {"form", model.form},
                        {"n", model.n},
                        {"weighting", model.weighting},
                        {"rmse", model.rmse},
                        {"r2", optional_number(model.r2)},
                        {"condition_number", model.condition_number},
                        {"chi2_reduced", optional_number(model.chi2_reduced)},
                        {"covariance_scale", model.covariance_scale},
                        {"interval_factor", optional_number(model.interval_factor)},
                        {"runs", model.runs},
                        {"warnings", model.warnings},
                        {"id", model.id},
                        {"stale", model.stale},
                        {"created_at", model.created_at}};
  out["coefficients"] = nlohmann::json::array();
  for (const auto& c : model.coefficients) {
    nlohmann::json item = {{"term", c.term},
                           {"value", c.value},
                           {"std_error", optional_number(c.std_error)},
                           {"interval_low", optional_number(c.interval_low)},
                           {"interval_high", optional_number(c.interval_high)},
                           {"vif", optional_number(c.vif)},
                           {"unit", c.unit}};
    if (!c.normalisation.empty()) item["normalisation"] = c.normalisation;
    out["coefficients"].push_back(std::move(item));
  }
  out["covariance"] = nlohmann::json::array();
  for (const double x : model.covariance) out["covariance"].push_back(optional_number(x));
  return out;
}

std::string pad(std::string text, std::size_t width) {
  if (text.size() < width) text.append(width - text.size(), ' ');
  return text;
}

}  // namespace

std::string derivative_output_unit(const std::string& output) {
  return std::string("XYZ").find(output) != std::string::npos ? "N" : "N m";
}

std::string derivative_coefficient_unit(const std::string& output, const Term& term) {
  const std::string unit = derivative_output_unit(output);
  const auto powers = term.powers();
  if (powers.empty()) return unit;
  // One factor per unit, its powers added: u*v is per (m/s)^2, v^2*r per ((m/s)^2 (rad/s)).
  std::vector<std::pair<std::string, int>> units;
  for (const auto& name : term.variables()) {  // canonical order: velocities, rates, then the rest
    const int power = powers.at(name);
    const std::string one = variable_unit(name);
    const auto same = std::find_if(units.begin(), units.end(), [&](const auto& u) { return u.first == one; });
    if (same == units.end())
      units.emplace_back(one, power);
    else
      same->second += power;
  }
  std::string below;
  for (const auto& [one, power] : units) {
    const bool bracket = one.find('/') != std::string::npos;
    below +=
        (below.empty() ? "" : " ") + (bracket ? "(" + one + ")" : one) + (power > 1 ? "^" + std::to_string(power) : "");
  }
  return unit + "/" + (units.size() > 1 ? "(" + below + ")" : below);
}

std::string DerivativeModel::text() const {
  std::string out = "derivative model '" + escape::one_line(name) + "' of body '" + escape::one_line(body) +
                    "': " + output + " [" + unit + "] = sum of " + std::to_string(coefficients.size()) + " terms, " +
                    std::to_string(n) + " runs" + (weighting == "uncertainty" ? " (weighted by 1/s^2)" : "") +
                    (where.empty() ? "" : " where " + escape::one_line(where)) + "\n";
  if (!model_template.empty()) out += "  template: " + model_template + "\n";
  if (!selection.empty())
    out += "  terms chosen by " + selection + " cross-validation from: " + escape::one_line(candidates) + "\n";
  out += "  form: " + form + (form == "dimensional" ? " (SI)" : " (non-dimensional)") + "\n";
  out += "  " + pad("term", 14) + pad("coefficient", 15) + pad("std error", 13) + pad("95 % interval", 28) +
         pad("VIF", 10) + "unit\n";
  for (const auto& c : coefficients)
    out += "  " + pad(escape::one_line(c.term), 14) + pad(number(c.value), 15) + pad(number(c.std_error), 13) +
           pad("[" + number(c.interval_low) + ", " + number(c.interval_high) + "]", 28) + pad(number(c.vif), 10) +
           c.unit + "\n";
  for (const auto& c : coefficients)
    if (!c.normalisation.empty()) out += "  " + escape::one_line(c.term) + ": " + c.normalisation + "\n";
  out += "  rmse = " + number(rmse) + " " + unit + " (SI), R^2 = " + number(r2) +
         ", condition number = " + number(condition_number);
  if (std::isfinite(chi2_reduced)) out += ", reduced chi^2 = " + number(chi2_reduced);
  out += "\n";
  for (const auto& w : warnings)
    out += "  warning (" + escape::one_line(w.substr(0, w.find(':'))) + ")" + escape::one_line(w.substr(w.find(':'))) +
           "\n";
  if (stale) out += "  stale: a force of its runs changed since it was fitted\n";
  out += id ? "  stored as model " + std::to_string(id) + "\n" : "  not stored\n";
  return out;
}

std::string DerivativeModel::json() const { return escape::json_text(model_json(*this), 2) + '\n'; }

std::string DerivativeModelList::text() const {
  if (models.empty()) return "no derivative models in " + escape::one_line(database) + "\n";
  std::string out;
  for (const auto& m : models)
    out += escape::one_line(m.name) + "  " + escape::one_line(m.body) + "  " + m.output + " = " +
           escape::one_line(m.terms) + "  n=" + std::to_string(m.n) + " rmse=" + number(m.rmse) + " " + m.unit +
           (m.warnings.empty() ? "" : "  warnings=" + std::to_string(m.warnings.size())) + (m.stale ? "  stale" : "") +
           "\n";
  return out;
}

std::string DerivativeModelList::json() const {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& m : models) out.push_back(model_json(m));
  return escape::json_text(out, 2) + '\n';
}

std::string DerivativeDeletion::text() const {
  return "deleted derivative model '" + escape::one_line(name) + "' (model " + std::to_string(id) + ") from " +
         escape::one_line(database) + "\n";
}

std::string DerivativeDeletion::json() const {
  return escape::json_text(nlohmann::json{{"database", database}, {"name", name}, {"id", id}}, 2) + '\n';
}

std::string DerivativeEvaluation::text() const {
  std::string point;
  for (const auto& [variable, x] : at) point += (point.empty() ? "" : ", ") + variable + "=" + number(x);
  return escape::one_line(name) + " at " + escape::one_line(point) + ": " + output + " = " + number(value) + " +/- " +
         number(std_error) + " " + unit + " (one sigma)" + (stale ? " (stale)" : "") + "\n";
}

std::string DerivativeEvaluation::json() const {
  nlohmann::json out = {{"name", name},   {"output", output}, {"unit", unit},
                        {"at", at},       {"value", value},   {"std_error", optional_number(std_error)},
                        {"basis", basis}, {"stale", stale}};
  return escape::json_text(out, 2) + '\n';
}

}  // namespace api
}  // namespace hydrocoef
