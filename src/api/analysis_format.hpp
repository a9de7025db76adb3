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

namespace hydrocoef::analysis_format {

/// A number with `digits` significant digits (printf %g); "n/a" for NaN (an
/// undefined statistic), as the CLI prints numbers.
inline std::string significant(double value, int digits = 6) {
  if (std::isnan(value)) return "n/a";
  std::array<char, 48> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.*g", digits, value);
  return buffer.data();
}

/// The number, or null.
inline nlohmann::json optional_json(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json();
}

}  // namespace hydrocoef::analysis_format
