#include "src/export/derivative_export.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "src/core/atomic_file.hpp"
#include "src/core/covariance.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/run.hpp"

namespace hydrocoef {
namespace {

std::string set_context(const DerivativeSet& set) { return "derivative set '" + escape::one_line(set.name) + "'"; }

bool is_force(std::string_view output) { return output == "X" || output == "Y" || output == "Z"; }
bool is_moment(std::string_view output) { return output == "K" || output == "M" || output == "N"; }

QuantityKind variable_kind(const std::string& name) {
  if (name == "u" || name == "v" || name == "w" || name == "du") return QuantityKind::LinearVelocity;
  if (name == "p" || name == "q" || name == "r") return QuantityKind::AngularVelocity;
  return QuantityKind::Angle;
}

std::string_view kind_unit(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::LinearVelocity: return "m/s";
    case QuantityKind::AngularVelocity: return "rad/s";
    default: return "rad";
  }
}

}  // namespace

void check_derivative_set(const DerivativeSet& set) {
  const std::size_t m = set.terms.size();
  if (m == 0) throw InputError(set_context(set) + ": no terms, expected at least one");
  if (set.coefficients.size() != m)
    throw InputError(set_context(set) + ": found " + std::to_string(set.coefficients.size()) + " coefficients for " +
                     std::to_string(m) + " terms, expected one per term");
  if (!set.std_errors.empty() && set.std_errors.size() != m)
    throw InputError(set_context(set) + ": found " + std::to_string(set.std_errors.size()) + " standard errors for " +
                     std::to_string(m) + " terms, expected one per term");
  for (std::size_t k = 0; k < m; ++k) {
    if (!std::isfinite(set.coefficients[k]))
      throw InputError(set_context(set) + ": the coefficient of '" + set.terms[k].text() +
                       "' is not finite, expected a finite number");
    if (!set.std_errors.empty() && !(std::isfinite(set.std_errors[k]) && set.std_errors[k] >= 0.0))
      throw InputError(set_context(set) + ": the standard error of '" + set.terms[k].text() + "' is " +
                       shortest_number(set.std_errors[k]) + ", expected a finite number >= 0");
  }
  if (set.covariance.empty()) return;
  if (const auto problem = covariance_problem(set.covariance, m))
    throw InputError(set_context(set) + ": covariance: " + *problem);
  for (std::size_t k = 0; k < m && !set.std_errors.empty(); ++k) {
    const double from_covariance = std::sqrt(set.covariance[k * m + k]);
    if (std::abs(from_covariance - set.std_errors[k]) > 1e-12 * std::max(from_covariance, set.std_errors[k]))
      throw InputError(set_context(set) + ": the standard error of '" + set.terms[k].text() + "' is " +
                       shortest_number(set.std_errors[k]) + " but the covariance's diagonal gives " +
                       shortest_number(from_covariance) + ", expected them equal");
  }
}

std::vector<double> derivative_std_errors(const DerivativeSet& set) {
  if (!set.std_errors.empty() || set.covariance.empty()) return set.std_errors;
  const std::size_t m = set.terms.size();
  std::vector<double> out;
  for (std::size_t k = 0; k < m; ++k) out.push_back(std::sqrt(std::max(0.0, set.covariance[k * m + k])));
  return out;
}

DerivativeKind derivative_kind(std::string_view output, const Term& term) {
  DerivativeKind kind;
  if (is_force(output))
    kind.output = QuantityKind::Force;
  else if (is_moment(output))
    kind.output = QuantityKind::Moment;
  else
    throw InputError("output '" + escape::one_line(output) +
                     "' is neither a force nor a moment; expected X, Y, Z, K, M or N for a non-dimensional form");
  for (const auto& f : term.factors()) kind.factors.push_back({variable_kind(f.variable), f.power});
  return kind;
}

std::string derivative_unit(std::string_view output, const Term& term) {
  const std::string out = is_force(output) ? "N" : is_moment(output) ? "N m" : "1";
  if (term.is_constant()) return out;
  std::string denominator;
  for (const auto& f : term.factors()) {
    if (!denominator.empty()) denominator += ' ';
    denominator += "(" + std::string(kind_unit(variable_kind(f.variable))) + ")";
    if (f.power != 1) denominator += "^" + std::to_string(f.power);
  }
  // One factor needs no more brackets: N/(m/s), N/(m/s)^2.
  if (term.factors().size() == 1) return out + "/" + denominator;
  return out + "/(" + denominator + ")";
}

DerivativeNumbers derivative_numbers(const DerivativeSet& set, DerivativeForm form) {
  check_derivative_set(set);
  const std::size_t m = set.terms.size();
  DerivativeNumbers n;
  n.coefficients = set.coefficients;
  n.std_errors = derivative_std_errors(set);
  n.covariance = set.covariance;
  n.scales.assign(m, 1.0);
  if (form == DerivativeForm::Dimensional) return n;
  try {
    for (std::size_t k = 0; k < m; ++k) {
      const NormalisationScale scale = derivative_scale(derivative_kind(set.output, set.terms[k]), set.system);
      n.scales[k] = scale_value(scale, set.system, set.reference, "the coefficient of '" + set.terms[k].text() + "'");
      n.scale_texts.push_back(scale_text(scale));
    }
    const DerivativeKind output{derivative_kind(set.output, Term()).output, {}};
    n.normalisation = normalisation_text(derivative_scale(output, set.system), set.system, set.reference, set.output);
  } catch (const InputError& e) {
    throw InputError(set_context(set) + ": " + e.what());
  }
  for (std::size_t k = 0; k < m; ++k) {
    n.coefficients[k] /= n.scales[k];
    if (!n.std_errors.empty()) n.std_errors[k] /= n.scales[k];
  }
  for (std::size_t i = 0; i < m && !n.covariance.empty(); ++i)
    for (std::size_t j = 0; j < m; ++j) n.covariance[i * m + j] /= n.scales[i] * n.scales[j];
  return n;
}

std::string derivative_csv(const DerivativeSet& set, DerivativeForm form) {
  const DerivativeNumbers n = derivative_numbers(set, form);
  const bool nd = form == DerivativeForm::NonDimensional;
  const std::size_t m = set.terms.size();
  std::string out;
  out += "# " + escape::csv_comment("hydrocoef derivative set '" + set.name + "', output " + set.output) + "\n";
  out += "# " +
         escape::csv_comment("sign: " + std::string(to_string(set.sign)) +
                             (set.sign == SignConvention::OnBody
                                  ? " (SNAME: the force of the water on the body, damping negative)"
                                  : " (damping magnitudes: positive opposes motion)")) +
         "\n";
  out += "# body axes x forward, y starboard, z down\n";
  if (nd)
    out +=
        "# " +
        escape::csv_comment("non-dimensional: " + n.normalisation + "; each coefficient is the SI one over its scale") +
        "\n";
  else
    out += "# dimensional: SI units, the output's unit over the term's\n";
  out += std::string("output,term,coefficient,std_error,") + (nd ? "scale" : "unit");
  if (!n.covariance.empty())
    for (const auto& term : set.terms) out += "," + escape::csv_text("cov:" + term.text());
  out += "\n";
  for (std::size_t k = 0; k < m; ++k) {
    out += escape::csv_text(set.output) + "," + escape::csv_text(set.terms[k].text()) + ",";
    append_shortest_number(out, n.coefficients[k]);
    out += ",";
    if (!n.std_errors.empty()) append_shortest_number(out, n.std_errors[k]);
    out += "," + escape::csv_text(nd ? n.scale_texts[k] : derivative_unit(set.output, set.terms[k]));
    for (std::size_t j = 0; j < m && !n.covariance.empty(); ++j) {
      out += ",";
      append_shortest_number(out, n.covariance[k * m + j]);
    }
    out += "\n";
  }
  return out;
}

std::string derivative_json(const DerivativeSet& set, DerivativeForm form) {
  const DerivativeNumbers n = derivative_numbers(set, form);
  const bool nd = form == DerivativeForm::NonDimensional;
  const std::size_t m = set.terms.size();
  nlohmann::json doc;
  doc["format"] = "hydrocoef-derivative-set";
  doc["version"] = 1;
  doc["name"] = set.name;
  doc["output"] = set.output;
  doc["sign"] = std::string(to_string(set.sign));
  doc["axes"] = "body: x forward, y starboard, z down";
  doc["form"] = nd ? std::string(to_string(set.system)) : std::string("dimensional");
  if (nd) {
    nlohmann::json reference;
    const auto put = [&reference](const char* key, const std::optional<double>& value) {
      if (value) reference[key] = *value;
    };
    put("length", set.reference.length);
    put("speed", set.reference.speed);
    put("density", set.reference.density);
    put("draft", set.reference.draft);
    put("mass", set.reference.mass);
    put("displaced_volume", set.reference.displaced_volume);
    reference["gravity"] = set.reference.gravity;
    doc["normalisation"] = {
        {"system", std::string(to_string(set.system))}, {"text", n.normalisation}, {"reference", reference}};
  }
  doc["terms"] = format_terms(set.terms);
  doc["coefficients"] = n.coefficients;
  if (!n.std_errors.empty()) doc["std_errors"] = n.std_errors;
  if (!n.covariance.empty()) {
    nlohmann::json rows = nlohmann::json::array();
    for (std::size_t i = 0; i < m; ++i)
      rows.push_back(std::vector<double>(n.covariance.begin() + static_cast<std::ptrdiff_t>(i * m),
                                         n.covariance.begin() + static_cast<std::ptrdiff_t>((i + 1) * m)));
    doc["covariance"] = rows;
  }
  if (nd) {
    doc["scales"] = n.scale_texts;
  } else {
    std::vector<std::string> units;
    for (const auto& term : set.terms) units.push_back(derivative_unit(set.output, term));
    doc["units"] = units;
  }
  return escape::json_text(doc, 2) + "\n";
}

void write_derivative_export(const std::filesystem::path& path, const std::string& text) {
  write_file_atomically(path, text);
}

}  // namespace hydrocoef
