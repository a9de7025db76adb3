// What the reports of include/hydrocoef/analysis.hpp share
// (src/api/analysis_*_report.cpp): numbers as the command line prints them,
// and JSON pieces. In a namespace of their own: other reports may have
// helpers of the same name.
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "src/core/numbers.hpp"

namespace hydrocoef::analysis_format {

using hydrocoef::significant;  // src/core/numbers.hpp: numbers as the CLI prints them

/// The number, or null.
inline nlohmann::json optional_json(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json();
}

}  // namespace hydrocoef::analysis_format
