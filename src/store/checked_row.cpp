#include "src/store/checked_row.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "src/core/error.hpp"

namespace hydrocoef::store {

std::string CheckedRow::found(int column) const {
  switch (statement_.column_type(column)) {
    case ColumnType::Null: return "NULL";
    case ColumnType::Integer: return "the integer " + std::to_string(statement_.get_int(column));
    case ColumnType::Float: {
      const double value = statement_.get_double(column);
      if (std::isnan(value)) return "NaN";
      if (std::isinf(value)) return value > 0 ? "+infinity" : "-infinity";
      return "the number " + std::to_string(value);
    }
    case ColumnType::Text:
      return "the text '" + printable_text(statement_.get_text(column), 40) + "'" +
             (statement_.column_bytes(column) > 40 ? " (" + std::to_string(statement_.column_bytes(column)) + " bytes)"
                                                   : std::string());
    case ColumnType::Blob: break;
  }
  return "a blob of " + std::to_string(statement_.column_bytes(column)) + " bytes";
}

void CheckedRow::fail(int column, std::string_view expected) const {
  const char* name = statement_.column_name(column);
  throw InputError(SourceLocation{database_}, "table '" + std::string(table_) + "', row " + std::to_string(row_) +
                                                  ", column '" + (name ? name : "?") + "': found " + found(column) +
                                                  "; expected " + std::string(expected));
}

void CheckedRow::fail_row(std::string_view message) const {
  throw InputError(SourceLocation{database_},
                   "table '" + std::string(table_) + "', row " + std::to_string(row_) + ": " + std::string(message));
}

double CheckedRow::real(int column) const {
  const ColumnType type = statement_.column_type(column);
  if (type != ColumnType::Float && type != ColumnType::Integer) fail(column, "a finite number");
  const double value = statement_.get_double(column);
  if (!std::isfinite(value)) fail(column, "a finite number");
  return value;
}

double CheckedRow::non_negative(int column) const {
  const double value = real(column);
  if (value < 0.0) fail(column, "a number >= 0");
  return value;
}

double CheckedRow::positive(int column) const {
  const double value = real(column);
  if (!(value > 0.0)) fail(column, "a number > 0");
  return value;
}

std::optional<double> CheckedRow::optional_real(int column) const {
  if (statement_.column_type(column) == ColumnType::Null) return std::nullopt;
  return real(column);
}

std::optional<double> CheckedRow::optional_positive(int column) const {
  if (statement_.column_type(column) == ColumnType::Null) return std::nullopt;
  return positive(column);
}

std::optional<double> CheckedRow::optional_non_negative(int column) const {
  if (statement_.column_type(column) == ColumnType::Null) return std::nullopt;
  return non_negative(column);
}

std::int64_t CheckedRow::integer(int column, std::int64_t min, std::int64_t max) const {
  if (statement_.column_type(column) != ColumnType::Integer)
    fail(column, "an integer from " + std::to_string(min) + " to " + std::to_string(max));
  const std::int64_t value = statement_.get_int(column);
  if (value < min || value > max) fail(column, "an integer from " + std::to_string(min) + " to " + std::to_string(max));
  return value;
}

std::string CheckedRow::text(int column, std::size_t max_bytes) const {
  if (statement_.column_type(column) != ColumnType::Text || statement_.column_bytes(column) > max_bytes)
    fail(column, "text of at most " + std::to_string(max_bytes) + " bytes");
  return statement_.get_text(column);
}

std::string CheckedRow::one_of(int column, const std::vector<std::string_view>& allowed) const {
  std::string list;
  for (const auto& option : allowed) list += (list.empty() ? "'" : ", '") + std::string(option) + "'";
  if (statement_.column_type(column) == ColumnType::Text && statement_.column_bytes(column) <= 64) {
    const std::string value = statement_.get_text(column);
    for (const auto& option : allowed)
      if (value == option) return value;
  }
  fail(column, "one of " + list);
}

std::string CheckedRow::name(int column, NameKind kind) const {
  const std::size_t most_bytes = 4 * max_name_characters(kind);
  const std::string value = text(column, most_bytes);
  if (const auto problem = name_problem(kind, value))
    fail(column,
         "a " + std::string(name_kind_text(kind)) + " name that follows the name rule (this one " + *problem + ")");
  return value;
}

std::vector<double> CheckedRow::doubles(int column, std::size_t max_count) const {
  if (statement_.column_type(column) != ColumnType::Blob) fail(column, "a blob of float64 values");
  const std::size_t bytes = statement_.column_bytes(column);
  if (bytes % sizeof(double) != 0 || bytes / sizeof(double) > max_count)
    fail(column, "a blob of at most " + std::to_string(max_count) + " float64 values (a multiple of 8 bytes)");
  std::vector<double> out = statement_.get_doubles(column);
  if (out.size() != bytes / sizeof(double)) fail(column, "a blob of float64 values");
  return out;
}

std::vector<double> CheckedRow::real_list(int column, std::size_t max_count) const {
  const std::string expected = "'' or a JSON list of at most " + std::to_string(max_count) + " finite numbers";
  const std::string content = text(column, 32 * max_count + 64);
  if (content.empty()) return {};
  const nlohmann::json list = nlohmann::json::parse(content, nullptr, false);
  if (list.is_discarded() || !list.is_array() || list.size() > max_count) fail(column, expected);
  std::vector<double> out;
  for (const auto& value : list) {
    if (!value.is_number() || !std::isfinite(value.get<double>())) fail(column, expected);
    out.push_back(value.get<double>());
  }
  return out;
}

}  // namespace hydrocoef::store
