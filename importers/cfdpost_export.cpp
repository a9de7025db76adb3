#include "importers/cfdpost_export.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <limits>
#include <memory>
#include <tuple>
#include <utility>

#include "src/core/error.hpp"
#include "src/core/file_bytes.hpp"
#include "src/core/huge_pages.hpp"
#include "src/core/names.hpp"
#include "src/core/text.hpp"
#include "src/core/units.hpp"
#include "src/mesh/duplicate_faces.hpp"

namespace hydrocoef {
namespace {

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
constexpr std::string_view kNameTag = "[Name]";
constexpr std::string_view kDataTag = "[Data]";
constexpr std::string_view kFacesTag = "[Faces]";
constexpr std::string_view kLinesTag = "[Lines]";
constexpr std::string_view kNullToken = "null";
constexpr std::string_view kNodeNumber = "Node Number";
constexpr std::array<std::string_view, 3> kCoordinateNames = {"X", "Y", "Z"};

// Blanks within a line (a \r left by CRLF line ends included).
constexpr std::string_view kBlanks = " \t\r";
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Quoted for a message, shortened, with every byte that is not printable
// ASCII written as \xNN, so that binary input still gives a one-line,
// printable error.
std::string shown(std::string_view text, std::size_t limit = 60) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(std::min(text.size(), limit) + 8);
  out += '\'';
  for (std::size_t i = 0; i < text.size() && i < limit; ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte >= 0x20 && byte < 0x7f) {
      out += static_cast<char>(byte);
    } else if (byte == '\t') {
      out += "\\t";
    } else {
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 0x0f];
    }
  }
  if (text.size() > limit) out += "...";
  out += '\'';
  return out;
}

std::string join_shown(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& name : names) {
    if (!out.empty()) out += ", ";
    out += shown(name, 200);
  }
  return out;
}

std::string block_label(const std::string& name) { return "block " + shown(name, 200); }

// ---------------------------------------------------------------------------
// Layout: where the blocks and their sections are. Found by walking the lines
// once (memchr per line) before any number is parsed, so that the values can
// be written straight into arrays of the right size and unselected blocks are
// never parsed.

struct Section {
  const char* begin = nullptr;  // first byte of the first row
  const char* end = nullptr;    // one past the line ending of the last row
  std::size_t first_line = 0;   // 1-based line of the first row
  std::size_t rows = 0;
};

struct Block {
  std::string name;
  std::size_t name_line = 0;
  std::string_view header;
  std::size_t header_line = 0;
  Section data;
  bool has_faces = false;
  Section faces;
};

class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : pos_(text.data()), end_(text.data() + text.size()) {}

  bool at_end() const { return pos_ == end_; }
  std::size_t line() const { return line_; }  // number of the line take() returns next

  /// The next line without its ending; moves past it.
  std::string_view take() {
    const char* newline = static_cast<const char*>(std::memchr(pos_, '\n', static_cast<std::size_t>(end_ - pos_)));
    const char* stop = newline != nullptr ? newline : end_;
    std::string_view text(pos_, static_cast<std::size_t>(stop - pos_));
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    pos_ = newline != nullptr ? newline + 1 : end_;
    ++line_;
    return text;
  }

  void skip_blank_lines() {
    while (!at_end()) {
      const LineCursor saved = *this;
      if (!trim(take(), kBlanks).empty()) {
        *this = saved;
        return;
      }
    }
  }

  /// Takes rows up to (not including) a blank line, a tag line or the end.
  Section take_section() {
    Section section{pos_, pos_, line_, 0};
    while (!at_end()) {
      const LineCursor saved = *this;
      const std::string_view text = take();
      // Rows start with a digit or a sign; only look closer when they do not.
      if (text.empty() || text.front() == '[' || is_blank(text.front())) {
        const std::string_view trimmed = trim(text, kBlanks);
        if (trimmed.empty() || trimmed.front() == '[') {
          *this = saved;
          break;
        }
      }
      ++section.rows;
      section.end = pos_;
    }
    return section;
  }

 private:
  const char* pos_;
  const char* end_;
  std::size_t line_ = 1;
};

bool is_tag(std::string_view trimmed) { return !trimmed.empty() && trimmed.front() == '['; }

std::string_view without_byte_order_mark(std::string_view text) {
  if (text.starts_with(kByteOrderMark)) text.remove_prefix(kByteOrderMark.size());
  return text;
}

std::vector<Block> scan_blocks(std::string_view text, const std::string& file) {
  if (text.empty())
    throw InputError(SourceLocation{file}, "empty file; expected a CFD-Post Generic export starting with '[Name]'");
  LineCursor cursor(without_byte_order_mark(text));
  cursor.skip_blank_lines();
  if (cursor.at_end())
    throw InputError(SourceLocation{file},
                     "only blank lines; expected a CFD-Post Generic export starting with '[Name]'");

  std::vector<Block> blocks;
  while (true) {
    cursor.skip_blank_lines();
    if (cursor.at_end()) break;
    const std::size_t tag_line = cursor.line();
    const std::string_view tag = cursor.take();
    if (trim(tag, kBlanks) != kNameTag) {
      if (blocks.empty())
        throw InputError(
            SourceLocation{file, tag_line, 1},
            "found " + shown(tag) + ", expected '[Name]' (the first line of a CFD-Post Generic export, File > Export)");
      const std::string expected =
          blocks.back().has_faces ? "'[Name]' of the next block" : "'[Faces]', '[Lines]' or '[Name]'";
      throw InputError(SourceLocation{file, tag_line, 1},
                       "after " + block_label(blocks.back().name) + ": found " + shown(tag) + ", expected " + expected);
    }

    Block block;
    block.name_line = cursor.line();
    const std::string_view name = cursor.at_end() ? std::string_view{} : trim(cursor.take(), kBlanks);
    if (name.empty() || is_tag(name))
      throw InputError(SourceLocation{file, block.name_line, 1},
                       "found " + (name.empty() ? std::string("nothing") : shown(name)) + " after '[Name]' on line " +
                           std::to_string(tag_line) + ", expected a location name");
    // A location name goes into messages, --location and the run's record:
    // the name rule applies (src/core/names.hpp).
    block.name = std::string(check_name(NameKind::Field, name, SourceLocation{file, tag_line + 1, 0}, "the location"));

    cursor.skip_blank_lines();
    if (cursor.at_end())
      throw InputError(SourceLocation{file, block.name_line},
                       block_label(block.name) + ": the file ends after the location name; expected '[Data]'");
    const std::size_t data_line = cursor.line();
    const std::string_view data_tag = cursor.take();
    if (trim(data_tag, kBlanks) != kDataTag)
      throw InputError(SourceLocation{file, data_line, 1},
                       block_label(block.name) + ": found " + shown(data_tag) + ", expected '[Data]'");

    block.header_line = cursor.line();
    const std::string_view header = cursor.at_end() ? std::string_view{} : cursor.take();
    if (trim(header, kBlanks).empty() || is_tag(trim(header, kBlanks)))
      throw InputError(SourceLocation{file, data_line, 1},
                       block_label(block.name) +
                           ": '[Data]' without a header line; expected column names such as "
                           "'X [ m ], Y [ m ], Z [ m ], Pressure [ Pa ]' on the next line (Include Header = On)");
    block.header = header;
    block.data = cursor.take_section();

    // Connectivity sections, each at most once.
    bool has_lines = false;
    while (true) {
      cursor.skip_blank_lines();
      if (cursor.at_end()) break;
      const LineCursor saved = cursor;
      const std::size_t section_line = cursor.line();
      const std::string_view section_tag = trim(cursor.take(), kBlanks);
      const bool faces = section_tag == kFacesTag;
      if (!faces && section_tag != kLinesTag) {
        cursor = saved;
        break;
      }
      if ((faces && block.has_faces) || (!faces && has_lines))
        throw InputError(SourceLocation{file, section_line, 1},
                         block_label(block.name) + ": second " + shown(section_tag) +
                             " section; expected one per block (or a new '[Name]' block)");
      const Section section = cursor.take_section();
      if (faces) {
        block.has_faces = true;
        block.faces = section;
      } else {
        has_lines = true;  // polylines have no area: nothing to integrate
      }
    }
    blocks.push_back(std::move(block));
  }
  return blocks;
}

std::vector<std::string> distinct_names(const std::vector<Block>& blocks) {
  std::vector<std::string> names;
  for (const auto& block : blocks)
    if (std::find(names.begin(), names.end(), block.name) == names.end()) names.push_back(block.name);
  return names;
}

// ---------------------------------------------------------------------------
// Header: what each column is and how its values reach SI.

enum class Role : std::uint8_t { Coordinate, Field, Skip, Duplicate };

struct Column {
  std::string header;  // as written, trimmed
  std::string name;
  std::string unit_text;
  std::size_t column = 0;  // 1-based byte column in the header line
  Role role = Role::Field;
  std::size_t target = 0;  // coordinate 0..2, mesh field index, or the column duplicated
  Dimension dimension;
  // value_si = divide ? value / factor : value * factor. Dividing by 1000 for
  // "mm" rounds once, where multiplying by the inexact 1e-3 would not.
  double factor = 1.0;
  bool divide = false;
};

struct Header {
  char separator = ',';
  std::vector<Column> columns;
};

double to_si(const Column& column, double value) {
  return column.divide ? value / column.factor : value * column.factor;
}

bool parses_as_number(std::string_view text) {
  double value = 0.0;
  if (text.starts_with('+')) text.remove_prefix(1);
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return end == text.data() + text.size() && !text.empty() &&
         (ec == std::errc{} || ec == std::errc::result_out_of_range);
}

Header parse_header(const Block& block, const std::string& file) {
  Header header;
  header.separator = block.header.find('\t') != std::string_view::npos ? '\t' : ',';
  const std::string_view text = block.header;
  std::size_t start = 0;
  while (true) {
    std::size_t stop = text.find(header.separator, start);
    if (stop == std::string_view::npos) stop = text.size();
    const std::string_view raw = text.substr(start, stop - start);
    const std::string_view field = trim(raw, kBlanks);
    Column column;
    column.header = std::string(field);
    column.column = start + static_cast<std::size_t>(field.empty() ? 0 : field.data() - raw.data()) + 1;
    const SourceLocation where{file, block.header_line, column.column};
    if (field.empty())
      throw InputError(where, block_label(block.name) + ": empty column name in the header; expected 'Name [ unit ]'");
    if (header.columns.empty() && (parses_as_number(field) || field == kNullToken))
      throw InputError(where, block_label(block.name) + ": found numbers (" + shown(field) +
                                  ") where the header should be; expected column names after '[Data]' "
                                  "(export with Include Header = On)");
    const NameAndUnit split = split_name_and_unit(field);
    column.name = split.name;
    column.unit_text = split.unit;
    if (column.name.empty())
      throw InputError(where, block_label(block.name) + ": column " + shown(field) +
                                  " has a unit but no name; expected 'Name [ unit ]'");
    Unit unit;
    try {
      unit = parse_unit(split.unit);
    } catch (const InputError& error) {
      throw InputError(where, block_label(block.name) + ", column " + shown(field) + ": " + error.what());
    }
    column.dimension = unit.dimension;
    const double inverse = 1.0 / unit.scale;
    if (unit.scale < 1.0 && std::abs(inverse - std::round(inverse)) < 1e-9 * inverse) {
      column.divide = true;
      column.factor = std::round(inverse);
    } else {
      column.factor = unit.scale;
    }

    const auto first = std::find_if(header.columns.begin(), header.columns.end(),
                                    [&](const Column& c) { return c.name == column.name; });
    const auto coordinate = std::find(kCoordinateNames.begin(), kCoordinateNames.end(), column.name);
    if (first != header.columns.end()) {
      if (first->unit_text != column.unit_text)
        throw InputError(where, block_label(block.name) + ": column " + shown(field) + " repeats " +
                                    shown(first->header) + " (column " + std::to_string(first->column) +
                                    ") with another unit; expected a repeated column to be identical");
      column.role = Role::Duplicate;
      column.target = static_cast<std::size_t>(first - header.columns.begin());
    } else if (column.name == kNodeNumber) {
      column.role = Role::Skip;  // faces refer to row order, not to node numbers
    } else if (coordinate != kCoordinateNames.end()) {
      if (!split.has_unit || unit.dimension != kLength)
        throw InputError(where,
                         block_label(block.name) + ", column " + shown(field) + ": found " +
                             (split.has_unit ? "unit " + shown(unit.text) + " (" + si_unit_name(unit.dimension) + ")"
                                             : std::string("no unit")) +
                             ", expected a length such as '" + column.name + " [ m ]' or '" + column.name + " [ mm ]'");
      column.role = Role::Coordinate;
      column.target = static_cast<std::size_t>(coordinate - kCoordinateNames.begin());
    } else {
      column.role = Role::Field;
    }
    header.columns.push_back(std::move(column));
    if (stop == text.size()) break;
    start = stop + 1;
  }
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const bool found = std::any_of(header.columns.begin(), header.columns.end(),
                                   [&](const Column& c) { return c.role == Role::Coordinate && c.target == axis; });
    if (!found)
      throw InputError(SourceLocation{file, block.header_line, 1},
                       block_label(block.name) + ": no " + shown(kCoordinateNames[axis]) +
                           " column in the header; expected coordinates X, Y, Z with a length unit "
                           "(Export Geometry = On, Spatial Variables = X,Y,Z)");
  }
  return header;
}

std::string si_unit_or_empty(const Dimension& dimension) {
  return dimension == kDimensionless ? std::string() : si_unit_name(dimension);
}

// ---------------------------------------------------------------------------
// Values. Rows and faces are parsed straight from the section's bytes: the
// line end is only looked for when something is wrong, so a short line costs
// no extra scan.

// Where the line holding `p` ends: at its '\n' or the section's end, before a
// '\r' that precedes it.
const char* line_end_from(const char* p, const char* end) {
  const char* newline = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
  const char* eol = newline != nullptr ? newline : end;
  if (eol > p && eol[-1] == '\r') --eol;
  return eol;
}

bool at_line_end(const char* p, const char* end) {
  return p == end || *p == '\n' || (*p == '\r' && (p + 1 == end || p[1] == '\n'));
}

const char* past_line_end(const char* p, const char* end) {
  if (p < end && *p == '\r') ++p;
  if (p < end && *p == '\n') ++p;
  return p;
}

struct RowContext {
  const std::string* file;
  const Block* block;
  const Header* header;
  std::size_t line;
  const char* line_begin;
  const char* end;  // of the section
};

std::size_t column_of(const RowContext& row, const char* at) {
  return static_cast<std::size_t>(at - row.line_begin) + 1;
}

[[noreturn]] void fail_field_count(const RowContext& row) {
  const char* const eol = line_end_from(row.line_begin, row.end);
  const std::string_view text(row.line_begin, static_cast<std::size_t>(eol - row.line_begin));
  // An empty last field (a row cut right after a separator) is not counted.
  const std::size_t separators = static_cast<std::size_t>(std::count(text.begin(), text.end(), row.header->separator));
  const std::size_t last = text.rfind(row.header->separator);
  const bool empty_last = last != std::string_view::npos && trim(text.substr(last + 1), kBlanks).empty();
  const std::size_t found = separators + (empty_last ? 0 : 1);
  const std::size_t expected = row.header->columns.size();
  throw InputError(SourceLocation{*row.file, row.line, 1},
                   block_label(row.block->name) + ": found " + std::to_string(found) + " fields, expected " +
                       std::to_string(expected) + " as in the header on line " +
                       std::to_string(row.block->header_line) +
                       (found < expected ? " (a truncated file ends with a short row)" : ""));
}

// The rare cases from_chars does not settle: the null token, a leading '+',
// underflow, and the errors. `field_end` is set past the field's text.
double parse_unusual_value(const RowContext& row, std::size_t c, const char* begin, const char*& field_end) {
  const char* const eol = line_end_from(begin, row.end);
  const char* stop =
      static_cast<const char*>(std::memchr(begin, row.header->separator, static_cast<std::size_t>(eol - begin)));
  if (stop == nullptr) stop = eol;
  std::string_view text(begin, static_cast<std::size_t>(stop - begin));
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  field_end = text.data() + text.size();
  if (text == kNullToken) return std::numeric_limits<double>::quiet_NaN();

  const Column& column = row.header->columns[c];
  const SourceLocation where{*row.file, row.line, column_of(row, begin)};
  const std::string context = block_label(row.block->name) + ", column " + shown(column.header) + ": ";
  if (text.empty()) throw InputError(where, context + "empty field; expected a number or 'null'");
  std::string_view digits = text;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+') digits.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (end == digits.data() + digits.size()) {
    if (ec == std::errc{} && std::isfinite(value)) return value;
    if (ec == std::errc::result_out_of_range) {
      // from_chars says out of range both for values below the smallest
      // double, which are zero here, and for overflow, which is an error.
      const double magnitude = std::strtod(std::string(digits).c_str(), nullptr);
      if (magnitude == 0.0) return std::signbit(magnitude) ? -0.0 : 0.0;
      throw InputError(where, context + "found " + shown(text) + ", expected a finite number within +-1.8e308");
    }
    if (ec == std::errc{})
      throw InputError(where, context + "found " + shown(text) + ", expected a finite number or 'null'");
  }
  throw InputError(where, context + "found " + shown(text) + ", expected a number or 'null'");
}

// Parses the data row at row.line_begin into `values` (as written, not yet
// SI) and where each field starts into `starts` (for messages). Returns where
// the line ends.
const char* parse_row(const RowContext& row, double* values, const char** starts) {
  const char separator = row.header->separator;
  const std::size_t count = row.header->columns.size();
  const char* const end = row.end;
  const auto blank = [separator](char ch) { return ch == ' ' || (ch == '\t' && separator != '\t'); };
  const char* p = row.line_begin;
  for (std::size_t c = 0; c < count; ++c) {
    while (p < end && blank(*p)) ++p;
    const char* const begin = p;
    starts[c] = begin;
    double value = 0.0;
    const auto [stop, ec] = std::from_chars(p, end, value);
    p = stop;
    if (ec != std::errc{} || !std::isfinite(value)) {
      if (at_line_end(begin, end)) fail_field_count(row);
      value = parse_unusual_value(row, c, begin, p);
    }
    while (p < end && blank(*p)) ++p;
    values[c] = value;
    if (c + 1 < count) {
      if (p < end && *p == separator) {
        ++p;
        continue;
      }
      if (at_line_end(p, end)) fail_field_count(row);
      const char* ignored = nullptr;
      parse_unusual_value(row, c, begin, ignored);  // throws: text after a number
      fail_field_count(row);
    }
    if (at_line_end(p, end)) return p;
    if (*p == separator) {
      // A separator after the last field is harmless; another field is not.
      const char* const eol = line_end_from(p, end);
      if (trim(std::string_view(p + 1, static_cast<std::size_t>(eol - p - 1)), kBlanks).empty()) return eol;
      fail_field_count(row);
    }
    const char* ignored = nullptr;
    parse_unusual_value(row, c, begin, ignored);
    fail_field_count(row);
  }
  return p;
}

std::string_view field_text(const Header& header, const char* begin, const char* end) {
  const std::string_view rest(begin, static_cast<std::size_t>(line_end_from(begin, end) - begin));
  return trim(rest.substr(0, rest.find(header.separator)), kBlanks);
}

bool same_value(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

void parse_nodes(const Block& block, const Header& header, const std::string& file, SurfaceMesh& mesh) {
  const std::size_t count = header.columns.size();
  std::vector<double> values(count);
  std::vector<const char*> starts(count);
  std::vector<std::vector<double>*> destination(count, nullptr);
  for (std::size_t c = 0; c < count; ++c)
    if (header.columns[c].role == Role::Field) destination[c] = &mesh.fields[header.columns[c].target].values;

  RowContext row{&file, &block, &header, block.data.first_line, block.data.begin, block.data.end};
  for (std::size_t r = 0; r < block.data.rows; ++r, ++row.line) {
    const char* const eol = parse_row(row, values.data(), starts.data());
    std::array<double, 3> xyz{};
    for (std::size_t c = 0; c < count; ++c) {
      const Column& column = header.columns[c];
      if (column.role == Role::Skip) continue;
      if (column.role == Role::Duplicate) {
        if (!same_value(values[c], values[column.target]))
          throw InputError(SourceLocation{file, row.line, column_of(row, starts[c])},
                           block_label(block.name) + ": column " + shown(column.header) + " (column " +
                               std::to_string(c + 1) + ") differs from the first " + shown(column.name) +
                               " column (column " + std::to_string(column.target + 1) +
                               "); expected a repeated column to hold the same values");
        continue;
      }
      const double si = to_si(column, values[c]);
      if (std::isinf(si))
        throw InputError(SourceLocation{file, row.line, column_of(row, starts[c])},
                         block_label(block.name) + ", column " + shown(column.header) + ": " +
                             shown(field_text(header, starts[c], block.data.end)) +
                             " overflows when converted to SI; expected a finite value");
      if (column.role == Role::Coordinate)
        xyz[column.target] = si;
      else
        destination[c]->push_back(si);
    }
    mesh.points_xyz.insert(mesh.points_xyz.end(), xyz.begin(), xyz.end());
    row.line_begin = past_line_end(eol, block.data.end);
  }
}

std::string index_range(std::size_t nodes) {
  return nodes == 0 ? std::string("none: the block has no nodes") : "0.." + std::to_string(nodes - 1);
}

void parse_faces(const Block& block, const std::string& file, std::uint32_t point_offset, std::uint32_t location,
                 SurfaceMesh& mesh) {
  const std::size_t nodes = block.data.rows;
  const char* const end = block.faces.end;
  const char* p = block.faces.begin;
  std::size_t line = block.faces.first_line;
  const auto blank = [](char ch) { return ch == ' ' || ch == '\t'; };
  const auto digit = [](char ch) { return static_cast<unsigned char>(ch - '0') < 10; };
  constexpr std::ptrdiff_t kMaxDigits = 10;  // 4294967295
  for (std::size_t f = 0; f < block.faces.rows; ++f, ++line) {
    const char* const line_begin = p;
    const auto where = [&](const char* at) {
      return SourceLocation{file, line, static_cast<std::size_t>(at - line_begin) + 1};
    };
    const auto face_label = [&] { return block_label(block.name) + ", face " + std::to_string(f + 1) + ": "; };
    std::size_t count = 0;
    while (true) {
      while (p < end && blank(*p)) ++p;
      if (at_line_end(p, end)) break;
      const char* const begin = p;
      std::uint64_t index = 0;
      while (p < end && digit(*p) && p - begin <= kMaxDigits)
        index = 10 * index + static_cast<std::uint64_t>(*p++ - '0');
      const char* const after_number = p;
      while (p < end && blank(*p)) ++p;
      const bool separated = at_line_end(p, end) || *p == ',' || p != after_number;
      if (after_number == begin || after_number - begin > kMaxDigits || !separated) {
        const char* stop = begin;
        while (!at_line_end(stop, end) && *stop != ',' && !blank(*stop)) ++stop;
        throw InputError(where(begin), face_label() + "found " +
                                           shown(std::string_view(begin, static_cast<std::size_t>(stop - begin))) +
                                           ", expected a 0-based node index (" + index_range(nodes) + ")");
      }
      if (index >= nodes)
        throw InputError(where(begin), face_label() + "index " + std::to_string(index) +
                                           " is out of range; the block has " + std::to_string(nodes) +
                                           " nodes, expected " + index_range(nodes));
      if (mesh.face_indices.size() == std::numeric_limits<std::uint32_t>::max())
        throw InputError(where(begin), "more than 4294967295 face indices; expected fewer (32-bit offsets)");
      mesh.face_indices.push_back(static_cast<std::uint32_t>(index) + point_offset);
      ++count;
      if (p < end && *p == ',') {
        ++p;
        while (p < end && blank(*p)) ++p;
        if (at_line_end(p, end))
          throw InputError(where(p), face_label() + "the line ends with ','; expected another node index");
      }
    }
    if (count < 3)
      throw InputError(SourceLocation{file, line, 1}, face_label() + "found " + std::to_string(count) +
                                                          (count == 1 ? " node index" : " node indices") +
                                                          ", expected at least 3");
    mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.face_indices.size()));
    mesh.face_location.push_back(location);
    p = past_line_end(p, end);
  }
}

// Makes sure every kept block holds the arrays of the first one, with units of
// the same kind, and points its field columns at the mesh's arrays.
void bind_fields(const std::vector<const Block*>& blocks, std::vector<Header>& headers, const std::string& file,
                 SurfaceMesh& mesh) {
  for (auto& column : headers.front().columns) {
    if (column.role != Role::Field) continue;
    column.target = mesh.fields.size();
    FieldArray field;
    field.name = column.name;
    field.association = FieldAssociation::Point;
    field.components = 1;
    field.unit = si_unit_or_empty(column.dimension);
    mesh.fields.push_back(std::move(field));
  }
  const Header& reference = headers.front();
  for (std::size_t b = 1; b < blocks.size(); ++b) {
    for (auto& column : headers[b].columns) {
      if (column.role != Role::Field) continue;
      const auto match = std::find_if(reference.columns.begin(), reference.columns.end(),
                                      [&](const Column& c) { return c.role == Role::Field && c.name == column.name; });
      if (match == reference.columns.end())
        throw InputError(SourceLocation{file, blocks[b]->header_line, column.column},
                         "array " + shown(column.name, 200) + " is in " + block_label(blocks[b]->name) + " but " +
                             block_label(blocks.front()->name) + " (header on line " +
                             std::to_string(blocks.front()->header_line) +
                             ") lacks it; expected every selected block to hold the same arrays (select "
                             "locations exported with the same variables)");
      if (match->dimension != column.dimension)
        throw InputError(SourceLocation{file, blocks[b]->header_line, column.column},
                         block_label(blocks[b]->name) + ", column " + shown(column.header) + ": unit is " +
                             si_unit_name(column.dimension) + " but in " + block_label(blocks.front()->name) +
                             " it is " + si_unit_name(match->dimension) + "; expected the same kind of unit");
      column.target = match->target;
    }
    for (const auto& wanted : reference.columns) {
      if (wanted.role != Role::Field) continue;
      const bool present = std::any_of(headers[b].columns.begin(), headers[b].columns.end(),
                                       [&](const Column& c) { return c.role == Role::Field && c.name == wanted.name; });
      if (!present)
        throw InputError(SourceLocation{file, blocks[b]->header_line, 1},
                         "array " + shown(wanted.name, 200) + " is in " + block_label(blocks.front()->name) + " but " +
                             block_label(blocks[b]->name) +
                             " (this header) lacks it; expected every selected block to hold the same arrays "
                             "(select locations exported with the same variables)");
    }
  }
}

}  // namespace

SurfaceMesh parse_cfdpost_export(std::string_view text, const std::string& file, const CfdPostOptions& options) {
  const std::vector<Block> blocks = scan_blocks(text, file);
  const std::vector<std::string> available = distinct_names(blocks);
  for (const auto& wanted : options.locations)
    if (std::find(available.begin(), available.end(), wanted) == available.end())
      throw InputError(SourceLocation{file},
                       "unknown location " + shown(wanted, 200) + "; the file has " + join_shown(available));

  std::vector<const Block*> kept;
  for (const auto& block : blocks)
    if (options.locations.empty() ||
        std::find(options.locations.begin(), options.locations.end(), block.name) != options.locations.end())
      kept.push_back(&block);

  SurfaceMesh mesh;
  for (const Block* block : kept)
    if (std::find(mesh.location_names.begin(), mesh.location_names.end(), block->name) == mesh.location_names.end())
      mesh.location_names.push_back(block->name);

  std::vector<Header> headers;
  headers.reserve(kept.size());
  std::transform(kept.begin(), kept.end(), std::back_inserter(headers),
                 [&](const Block* block) { return parse_header(*block, file); });
  bind_fields(kept, headers, file, mesh);

  std::size_t points = 0, faces = 0;
  for (const Block* block : kept) {
    points += block->data.rows;
    if (block->has_faces) faces += block->faces.rows;
  }
  if (points > std::numeric_limits<std::uint32_t>::max())
    throw InputError(SourceLocation{file},
                     "found " + std::to_string(points) + " nodes, expected at most 4294967295 (32-bit face indices)");
  // Exact sizes from the layout scan: no reallocation, and no zero fill of
  // memory that is written once anyway.
  reserve_with_huge_pages(mesh.points_xyz, 3 * points);
  for (auto& field : mesh.fields) reserve_with_huge_pages(field.values, points);
  reserve_with_huge_pages(mesh.face_offsets, faces + 1);
  reserve_with_huge_pages(mesh.face_location, faces);
  reserve_with_huge_pages(mesh.face_indices, 3 * faces);  // triangles; quads grow it once

  std::size_t offset = 0;
  std::vector<std::pair<std::size_t, const Block*>> first_faces;  // the first face of each block with faces
  for (std::size_t b = 0; b < kept.size(); ++b) {
    const Block& block = *kept[b];
    parse_nodes(block, headers[b], file, mesh);
    if (block.has_faces) {
      const auto location = static_cast<std::uint32_t>(
          std::find(mesh.location_names.begin(), mesh.location_names.end(), block.name) - mesh.location_names.begin());
      first_faces.emplace_back(mesh.face_count(), &block);
      parse_faces(block, file, static_cast<std::uint32_t>(offset), location, mesh);
    }
    offset += block.data.rows;
  }
  if (const auto twice = find_duplicate_face(mesh)) {
    // The block of a face, its number there (from 1) and its line.
    const auto place = [&first_faces](std::size_t face) {
      auto it = std::prev(std::upper_bound(first_faces.begin(), first_faces.end(), face,
                                           [](std::size_t f, const auto& entry) { return f < entry.first; }));
      const std::size_t number = face - it->first;
      return std::make_tuple(it->second, number + 1, it->second->faces.first_line + number);
    };
    const auto [block, number, line] = place(twice->second);
    const auto [first_block, first_number, first_line] = place(twice->first);
    throw InputError(SourceLocation{file, line, 1}, block_label(block->name) + ", face " + std::to_string(number) +
                                                        ": the nodes of face " + std::to_string(first_number) + " of " +
                                                        block_label(first_block->name) + " (line " +
                                                        std::to_string(first_line) +
                                                        ") again, in the same or another order; expected each face "
                                                        "once (a face listed twice counts twice in the forces)");
  }
  // Checked last so that a file cut inside its data says so first.
  if (std::none_of(kept.begin(), kept.end(), [](const Block* block) { return block->has_faces; }))
    throw InputError(
        SourceLocation{file},
        "no [Faces] section in " +
            (options.locations.empty() ? std::string("the file") : "locations " + join_shown(options.locations)) +
            ": export with Export Connectivity = On");
  return mesh;
}

SurfaceMesh read_cfdpost_export(const std::filesystem::path& file, const CfdPostOptions& options) {
  const FileBytes bytes(file);
  return parse_cfdpost_export(bytes.view(), file.string(), options);
}

bool looks_like_cfdpost_export(std::string_view head) {
  LineCursor cursor(without_byte_order_mark(head));
  cursor.skip_blank_lines();
  return !cursor.at_end() && trim(cursor.take(), kBlanks) == kNameTag;
}

std::vector<std::string> list_cfdpost_locations(std::string_view text, const std::string& file) {
  return distinct_names(scan_blocks(text, file));
}

}  // namespace hydrocoef
