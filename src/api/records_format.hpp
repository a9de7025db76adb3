// What the renderings of the records' results (src/api/*_report.cpp) share:
// numbers as the CLI has always printed them, and the JSON of a run key.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "src/core/numbers.hpp"
#include "src/core/run.hpp"

namespace hydrocoef::records {

using hydrocoef::significant;  // src/core/numbers.hpp: numbers as the CLI prints them

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
