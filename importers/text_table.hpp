// Line and field splitting for delimited text exports (CSV, tab- or
// semicolon-separated), shared by the text importers. Keeps 1-based line and
// column numbers so that every error can point into the file.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "src/core/error.hpp"

namespace hydrocoef {

struct TextField {
  std::string text;        ///< unquoted, surrounding blanks trimmed
  std::size_t column = 0;  ///< 1-based byte column where the field starts
};

struct TextLine {
  std::string_view text;   ///< without the line ending (LF or CRLF)
  std::size_t number = 0;  ///< 1-based
};

/// Splits a buffer into lines, accepting LF and CRLF endings, a missing final
/// newline and a leading UTF-8 byte-order mark.
std::vector<TextLine> split_lines(std::string_view bytes);

/// The most fields split_fields accepts on a line by default.
inline constexpr std::size_t kMaxTextFields = 4096;

/// The most bytes of one field split_fields accepts by default (a column
/// name with its unit, a number or a text cell is far shorter): a field
/// longer than this is refused before it is copied.
inline constexpr std::size_t kMaxTextFieldBytes = 65536;

/// Splits one line at `delimiter`; double-quoted fields may hold the delimiter
/// and doubled quotes (""). An unterminated quote, more than `max_fields`
/// fields (a data line longer than its header), or a field of more than
/// `max_field_bytes` bytes is an InputError at the line and column.
std::vector<TextField> split_fields(const TextLine& line, char delimiter, const std::string& file,
                                    std::size_t max_fields = kMaxTextFields,
                                    std::size_t max_field_bytes = kMaxTextFieldBytes);

/// Picks the delimiter of a header line: ',' if present outside quotes, else
/// tab, else ';'.
char detect_delimiter(std::string_view header);

/// Parses a whole field as a finite double (std::from_chars; a leading '+' is
/// allowed). Throws InputError at the field naming the column, what was found
/// and that a finite number was expected.
double parse_number(const TextField& field, const std::string& file, std::size_t line, std::string_view column_name);

}  // namespace hydrocoef
