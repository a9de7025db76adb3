// Fast reading of the data rows of a text time history (one sample per line,
// the same count of numbers on every line), shared by the OpenFOAM force-file
// reader and the generic history table reader. Large histories (10^6 rows,
// hundreds of MB) are split at line boundaries and parsed on every core with
// std::from_chars; nothing is allocated per value. A bad row stops the parse
// and is then diagnosed on its own, so the error names file:line:column,
// what was found and what was expected, whichever thread met it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hydrocoef::history_text {

struct RowSyntax {
  std::size_t columns = 0;  ///< fields per row (numbers and skipped fields)
  /// ',' ';' or '\t' separate fields (blanks around them allowed, a field may
  /// be double-quoted); 0: runs of blanks separate them.
  char delimiter = 0;
  /// '(' and ')' may group numbers (OpenFOAM writes "(x y z)"); they must
  /// balance on each row and carry no other meaning. Whitespace rows only.
  bool parentheses = false;
  /// Fields not parsed (text columns of a table); empty: parse every field.
  std::vector<bool> skip;
  /// Names of the columns for messages ("total_x", "Fx [N]"); may be empty.
  std::vector<std::string> names;
  /// Every row, the last included, must end with a line end. Solvers always
  /// write one, so a last row without it was cut short (its last number may
  /// be cut too); tables from other tools often omit the final one.
  bool require_line_end = false;
};

struct RowOptions {
  /// A last row cut short without its line end (a run stopped while writing)
  /// is dropped and reported in ParsedRows::dropped_last_row instead of
  /// refused.
  bool drop_incomplete_last_row = false;
  unsigned threads = 0;  ///< 0: std::thread::hardware_concurrency()
};

struct ParsedRows {
  std::size_t columns = 0;    ///< numbers per row: the parsed (not skipped) fields
  std::vector<double> values; ///< row-major, `columns` per row; skipped fields left out
  std::vector<std::uint32_t> lines;  ///< 1-based line of each row
  bool dropped_last_row = false;
  std::size_t rows() const { return lines.size(); }
};

/// Parses the rows of `data`, which starts at line `first_line` of `file`
/// (for messages). Blank lines and lines whose first non-blank character is
/// '#' are skipped. Throws InputError naming file:line:column for: a field
/// that is not a number ("found 'abc', expected a number in column 3
/// 'total_z'"), a value that is not finite, too few or too many fields, an
/// unbalanced parenthesis, an empty or unterminated quoted field, a last row
/// cut short (unless dropped), a file of more than 2^32 - 1 lines.
ParsedRows parse_rows(std::string_view data, std::size_t first_line, const RowSyntax& syntax, const std::string& file,
                      const RowOptions& options = {});

/// Text as quoted in messages: printable, cut after 40 characters.
std::string quoted(std::string_view text);

}  // namespace hydrocoef::history_text
