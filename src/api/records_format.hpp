// What the renderings of the records' results (src/api/*_report.cpp) share:
// numbers as the CLI has always printed them, and the JSON of a run key.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "src/core/run.hpp"

namespace hydrocoef::records {

/// A number in engineering style with `digits` significant digits; "n/a" for
/// NaN (an undefined statistic, such as R^2 of a constant force).
inline std::string significant(double value, int digits = 6) {
  if (std::isnan(value)) return "n/a";
  std::array<char, 48> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.*g", digits, value);
  return buffer.data();
}

/// A finite number, or null.
inline nlohmann::json optional_number(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json();
}

/// JSON of one run key: {"body", "u".."r", "disturbances"}.
inline nlohmann::json key_json(const RunKey& key) {
  nlohmann::json out;
  out["body"] = key.body;
  for (std::size_t i = 0; i < 6; ++i) out[std::string(kVelocityNames[i])] = key.nu_b[i];
  out["disturbances"] = nlohmann::json::object();
  for (const auto& [name, value] : key.disturbances) out["disturbances"][name] = value;
  return out;
}

}  // namespace hydrocoef::records
