// Test support: one CSV record (RFC 4180, one line) split into its fields,
// for tests that check a generated CSV has exactly the expected columns.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace hydrocoef::test {

/// The fields of one line; nullopt when it is not well-formed CSV (a quote
/// inside an unquoted field, text after a closing quote, an unclosed quote,
/// a carriage return).
inline std::optional<std::vector<std::string>> csv_record(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
        if (i + 1 < line.size() && line[i + 1] != ',') return std::nullopt;
      } else {
        fields.back() += c;
      }
    } else if (c == '"' && fields.back().empty()) {
      quoted = true;
    } else if (c == '"' || c == '\r') {
      return std::nullopt;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  if (quoted) return std::nullopt;
  return fields;
}

/// True when a spreadsheet would evaluate this (unquoted) cell as a formula:
/// it starts with '=', '+', '-', '@', tab or carriage return (OWASP).
inline bool formula_cell(const std::string& cell) {
  return !cell.empty() && std::string_view("=+-@\t\r").find(cell.front()) != std::string_view::npos;
}

/// True when the cell is a plain number, as a spreadsheet reads one: the whole
/// cell parses as a double (no quote before it, nothing after it).
inline bool number_cell(const std::string& cell) {
  if (cell.empty() || cell.front() == '\'') return false;
  std::size_t used = 0;
  try {
    (void)std::stod(cell, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == cell.size();
}

}  // namespace hydrocoef::test
