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
#include <filesystem>
#include <functional>
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

/// The default bound of RowOptions::max_line_bytes: 1 MiB.
inline constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;

struct RowOptions {
  /// A last row cut short without its line end (a run stopped while writing)
  /// is dropped and reported in ParsedRows::dropped_last_row instead of
  /// refused.
  bool drop_incomplete_last_row = false;
  unsigned threads = 0;  ///< 0: std::thread::hardware_concurrency()
  /// parse_file_rows: bytes read at a time (the header must fit in the first
  /// block). Smaller blocks only for tests of the block boundaries.
  std::size_t block_bytes = std::size_t{32} << 20;
  /// parse_file_rows: the most bytes of a line carried from one block to the
  /// next (a row of 4096 numbers is about 100 kB). A line still without its
  /// end past this is refused as soon as it is seen, so a file of one 2 GB
  /// line costs a block, not the line twice over.
  std::size_t max_line_bytes = kMaxLineBytes;
};

/// Where the numbers go: one vector per parsed (not skipped) field, in field
/// order; nullptr where a field is checked but not kept. Each vector is
/// resized to the number of rows and filled; `lines`, when given, receives
/// the 1-based line of every row.
struct RowSink {
  std::vector<std::vector<double>*> columns;
  std::vector<std::uint32_t>* lines = nullptr;
};

struct ParsedRows {
  std::size_t rows = 0;
  bool dropped_last_row = false;
};

/// Parses the rows of `data`, which starts at line `first_line` of `file`
/// (for messages), into `sink`. Blank lines and lines whose first non-blank
/// character is '#' are skipped. Throws InputError naming file:line:column
/// for: a field that is not a number ("found 'abc', expected a number in
/// column 3 'total_z'"), a value that is not finite, too few or too many
/// fields, an unbalanced parenthesis, an empty or unterminated quoted field, a
/// last row cut short (unless dropped), a file of more than 2^32 - 1 lines.
///
/// Two passes over the bytes, both on every core: the line ends of each chunk
/// are counted (which sizes the output), then each chunk parses straight into
/// its rows of the output columns. Nothing is allocated per row.
ParsedRows parse_rows(std::string_view data, std::size_t first_line, const RowSyntax& syntax, const std::string& file,
                      const RowSink& sink, const RowOptions& options = {});

/// How a file's rows are laid out, as its header says: where they start and
/// how to read them.
struct FileLayout {
  std::size_t data_offset = 0;  ///< byte where the rows start (after the header)
  std::size_t first_line = 1;   ///< the file line at data_offset
  RowSyntax syntax;
  RowSink sink;
};

struct StreamedRows {
  ParsedRows rows;
  std::string sha256;            ///< of every byte of the file; empty unless asked
  std::uint64_t size_bytes = 0;  ///< bytes read
};

/// Reads a file in blocks of options.block_bytes into one reused buffer:
/// `layout` gets the first block (or the whole file when it is smaller) and
/// returns where the rows start and where they go; then every block's whole
/// lines are parsed as parse_rows does (on every core), with the SHA-256 of
/// the bytes computed beside the parse when asked. Memory: one block, not the
/// file. Throws InputError naming the file when it does not exist, is a
/// directory, cannot be read, when the header does not end in the first
/// block or a line runs on past options.max_line_bytes, and what parse_rows
/// throws.
StreamedRows parse_file_rows(const std::filesystem::path& path,
                             const std::function<FileLayout(std::string_view head)>& layout,
                             const RowOptions& options = {}, bool compute_sha256 = false);

/// The number parser of the rows, for tests: a finite number at `begin`
/// (decimal or scientific, optional sign), read as std::from_chars reads it
/// (the same double, bit for bit; a leading '+' is allowed too). Returns the
/// end of the number, or nullptr when there is none or it is not finite.
const char* read_finite_number(const char* begin, const char* end, double& value);

/// Text as quoted in messages: printable, cut after 40 characters.
std::string quoted_text(std::string_view text);

}  // namespace hydrocoef::history_text
