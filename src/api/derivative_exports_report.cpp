// What `hydrocoef derivatives export` prints (DerivativeExportResult::text
// and json, include/hydrocoef/exports.hpp). Names are escaped for the
// terminal in text (escape::one_line) and are JSON strings in JSON.
#include "src/api/internal.hpp"

#include <nlohmann/json.hpp>

#include "hydrocoef/exports.hpp"
#include "src/core/escape.hpp"

namespace hydrocoef {
inline namespace api {

std::string DerivativeExportResult::text() const {
  std::string out = "wrote " + escape::one_line(file) + " (" + format + ", " + form + ", " + std::to_string(bytes) +
                    " bytes): " + std::to_string(models.size()) + (models.size() == 1 ? " model" : " models") +
                    " of body '" + escape::one_line(body) + "'\n";
  for (std::size_t k = 0; k < models.size(); ++k)
    out += "  " + outputs[k] + " = '" + escape::one_line(models[k]) + "': " + escape::one_line(terms[k]) + "\n";
  if (!function_name.empty()) {
    out += "  function [xdot, U] = " + function_name + "(x, ui), x = [u v w p q r]'";
    if (!inputs.empty()) {
      out += ", ui = [";
      for (std::size_t k = 0; k < inputs.size(); ++k) out += (k ? " " : "") + escape::one_line(inputs[k]);
      out += "]'";
    }
    out += "\n";
  }
  for (const auto& d : dropped) out += "  dropped: " + escape::one_line(d) + "\n";
  for (const auto& n : notes) out += "  note: " + escape::one_line(n) + "\n";
  return out;
}

std::string DerivativeExportResult::json() const {
  nlohmann::json doc = {{"database", database}, {"format", format}, {"form", form},
                        {"file", file},         {"body", body},     {"bytes", bytes},
                        {"dropped", dropped},   {"notes", notes},   {"function_name", function_name},
                        {"inputs", inputs}};
  doc["models"] = nlohmann::json::array();
  for (std::size_t k = 0; k < models.size(); ++k)
    doc["models"].push_back(
        {{"name", models[k]}, {"output", outputs[k]}, {"terms", terms[k]}, {"stale", bool(stale[k])}});
  return escape::json_text(doc, 2) + '\n';
}

}  // namespace api
}  // namespace hydrocoef
