// What `hydrocoef scale` prints (ResistanceScalingResult::text and json,
// include/hydrocoef/scaling.hpp): the method with its sources, the wave
// statement and form factor, the assumptions in words, then the table of
// the points at both scales (and, for a stored law, its coefficients at both
// scales). Names are escaped for the terminal in text and are JSON strings
// in JSON.
#include "src/api/internal.hpp"

#include <nlohmann/json.hpp>

#include "hydrocoef/scaling.hpp"
#include "src/api/records_format.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/text.hpp"

namespace hydrocoef {
inline namespace api {
namespace {

std::string cell(double value, std::size_t width) {
  std::string text = significant(value, 7);
  if (text.size() < width) text.insert(0, width - text.size(), ' ');
  return text + " ";
}

std::string header(const std::string& text, std::size_t width) {
  return (text.size() < width ? std::string(width - text.size(), ' ') : std::string()) + text + " ";
}

}  // namespace

std::string ResistanceScalingResult::text() const {
  std::string out = "scaling: " + method + "\n";
  out += "  wave resistance: " + wave + "\n";
  out += "  form factor: " + escape::one_line(form_factor) + "\n";
  out +=
      "  forces: " + sign + (sign == "on-body" ? " (X on the body, R = -X)" : " (resistance magnitudes, R = X)") + "\n";
  for (const auto& a : assumptions) out += "  assumption: " + escape::one_line(a) + "\n";
  if (!fit.empty()) {
    out += "law '" + escape::one_line(fit) + "' X(u) = " + escape::one_line(terms) + ":\n";
    const std::vector<std::string_view> names = split(terms, ',');
    for (std::size_t k = 0; k < coefficients_from.size(); ++k)
      out += "  " + (k < names.size() ? escape::one_line(names[k]) : std::to_string(k + 1)) + ": " +
             significant(coefficients_from[k], 7) + " at scale 1 -> " + significant(coefficients_to[k], 7) +
             " at scale 2" + (k < units.size() ? " " + units[k] : std::string()) + "\n";
    out += "  largest relative deviation of the refitted law from the scaled points: " +
           significant(max_relative_deviation, 3) + "\n";
  }
  const std::size_t w = 13;
  out += header("U1 [m/s]", w) + header("X1 [N]", w) + header("Fn1", w) + header("Re1", w) + header("C_F1", w) +
         header("C_T1", w) + header("U2 [m/s]", w) + header("Fn2", w) + header("Re2", w) + header("C_F2", w) +
         header("C_T2", w) + header("R2 [N]", w) + header("X2 [N]", w);
  out.back() = '\n';
  for (const auto& p : points) {
    out += cell(p.speed_from, w) + cell(p.force_from, w) + cell(p.froude_from, w) + cell(p.reynolds_from, w) +
           cell(p.friction_from, w) + cell(p.total_from, w) + cell(p.speed_to, w) + cell(p.froude_to, w) +
           cell(p.reynolds_to, w) + cell(p.friction_to, w) + cell(p.total_to, w) + cell(p.resistance_to, w) +
           cell(p.force_to, w);
    out.back() = '\n';  // no space at the end of a line
  }
  return out;
}

std::string ResistanceScalingResult::json() const {
  using records::optional_number;
  nlohmann::json doc = {{"method", method},
                        {"sign", sign},
                        {"wave", wave},
                        {"one_plus_k", one_plus_k},
                        {"form_factor_method", form_factor_method},
                        {"prohaska_slope", optional_number(prohaska_slope)},
                        {"form_factor", form_factor},
                        {"assumptions", assumptions}};
  doc["points"] = nlohmann::json::array();
  for (const auto& p : points)
    doc["points"].push_back({{"speed_from", p.speed_from},
                             {"speed_to", p.speed_to},
                             {"force_from", p.force_from},
                             {"force_to", p.force_to},
                             {"resistance_from", p.resistance_from},
                             {"resistance_to", p.resistance_to},
                             {"froude_from", p.froude_from},
                             {"froude_to", p.froude_to},
                             {"reynolds_from", p.reynolds_from},
                             {"reynolds_to", p.reynolds_to},
                             {"friction_from", p.friction_from},
                             {"friction_to", p.friction_to},
                             {"wave", p.wave},
                             {"residual", p.residual},
                             {"total_from", p.total_from},
                             {"total_to", p.total_to}});
  if (!fit.empty())
    doc["law"] = {{"fit", fit},
                  {"terms", terms},
                  {"units", units},
                  {"coefficients_from", coefficients_from},
                  {"coefficients_to", coefficients_to},
                  {"max_relative_deviation", max_relative_deviation}};
  return escape::json_text(doc, 2) + '\n';
}

}  // namespace api
}  // namespace hydrocoef
