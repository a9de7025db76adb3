#include "importers/text_table.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>

#include "src/core/text.hpp"

namespace hydrocoef {

std::vector<TextLine> split_lines(std::string_view bytes) {
  std::vector<TextLine> lines;
  if (bytes.starts_with("\xEF\xBB\xBF")) bytes.remove_prefix(3);  // UTF-8 byte-order mark, as spreadsheets write
  std::size_t start = 0;
  std::size_t number = 1;
  while (start < bytes.size()) {
    auto end = bytes.find('\n', start);
    if (end == std::string_view::npos) end = bytes.size();
    auto text = bytes.substr(start, end - start);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    lines.push_back({text, number++});
    start = end + 1;
  }
  return lines;
}

std::vector<TextField> split_fields(const TextLine& line, char delimiter, const std::string& file,
                                    std::size_t max_fields, std::size_t max_field_bytes) {
  std::vector<TextField> fields;
  const std::string_view text = line.text;
  // A field is bounded as the count of fields is: a line of one 2 GB field
  // is refused before the field is copied (it cost three times its size).
  const auto too_long = [&](std::size_t start) {
    return InputError(SourceLocation{file, line.number, start + 1},
                      "a field of more than " + std::to_string(max_field_bytes) + " bytes; expected at most " +
                          std::to_string(max_field_bytes) + " bytes per field");
  };
  std::size_t i = 0;
  while (true) {
    // Memory stays a small multiple of the line's useful content: a line of
    // millions of empty fields is refused before they are stored.
    if (fields.size() == max_fields)
      throw InputError(SourceLocation{file, line.number, i + 1}, "more than " + std::to_string(max_fields) +
                                                                     " fields on the line; expected at most " +
                                                                     std::to_string(max_fields));
    TextField field;
    std::size_t start = i;
    while (start < text.size() && (text[start] == ' ' || text[start] == '\t') && text[start] != delimiter) ++start;
    field.column = start + 1;
    if (start < text.size() && text[start] == '"') {
      std::size_t j = start + 1;
      bool closed = false;
      while (j < text.size()) {
        if (text[j] == '"') {
          if (j + 1 < text.size() && text[j + 1] == '"') {
            if (field.text.size() == max_field_bytes) throw too_long(start);
            field.text += '"';
            j += 2;
            continue;
          }
          closed = true;
          ++j;
          break;
        }
        if (field.text.size() == max_field_bytes) throw too_long(start);
        field.text += text[j++];
      }
      if (!closed)
        throw InputError(SourceLocation{file, line.number, start + 1},
                         "unterminated quoted field; expected a closing '\"'");
      while (j < text.size() && text[j] != delimiter) {
        if (text[j] != ' ' && text[j] != '\t')
          throw InputError(SourceLocation{file, line.number, j + 1},
                           "text after a closing quote; expected the delimiter or the end of the line");
        ++j;
      }
      i = j;
    } else {
      std::size_t j = start;
      while (j < text.size() && text[j] != delimiter) ++j;
      const std::string_view content = trim(text.substr(start, j - start), kSpaceTab);
      if (content.size() > max_field_bytes) throw too_long(start);
      field.text = std::string(content);
      i = j;
    }
    fields.push_back(std::move(field));
    if (i >= text.size()) break;
    ++i;  // skip the delimiter
  }
  return fields;
}

char detect_delimiter(std::string_view header) {
  // Only delimiters outside double quotes count: "X, total [N]" is one name.
  bool quoted = false;
  bool comma = false, tab = false, semicolon = false;
  for (const char c : header) {
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    comma = comma || c == ',';
    tab = tab || c == '\t';
    semicolon = semicolon || c == ';';
  }
  if (comma) return ',';
  if (tab) return '\t';
  if (semicolon) return ';';
  return ',';
}

double parse_number(const TextField& field, const std::string& file, std::size_t line, std::string_view column_name) {
  std::string_view text = field.text;
  const SourceLocation where{file, line, field.column};
  const std::string context = "column '" + printable_text(column_name, 60) + "': ";
  if (text.empty()) throw InputError(where, context + "empty field; expected a number");
  if (text.size() > 1 && text.front() == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range && end == text.data() + text.size()) {
    // from_chars reports underflow and overflow alike; a value below the
    // smallest double is zero for every purpose here, an overflow is an error.
    const double magnitude = std::strtod(std::string(text).c_str(), nullptr);
    if (magnitude == 0.0) return 0.0;
    throw InputError(
        where, context + "found '" + printable_text(field.text, 40) + "', expected a finite number within +-1.8e308");
  }
  if (ec != std::errc{} || end != text.data() + text.size())
    throw InputError(where, context + "found '" + printable_text(field.text, 40) + "', expected a number");
  if (!std::isfinite(value))
    throw InputError(where, context + "found '" + printable_text(field.text, 40) + "', expected a finite number");
  return value;
}

}  // namespace hydrocoef
