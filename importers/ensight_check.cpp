// EnSight Gold through VTK, each file checked first: the walk of the geometry
// and variable files (the case file: ensight_case.cpp) and read_ensight.
//
// VTK 9.1's EnSight Gold readers do not look for the end of a file: a
// truncated geometry or variable file makes them read on past it, which ends in
// a segmentation fault or, worse, in parts silently cut short, and a variable
// file that names a part the geometry lacks makes them use a null block. So
// before VTK reads a case, the importer walks every file VTK is going to read
// (the geometry and the scalar and vector variables, at the time step read)
// and checks that it is complete and consistent with the geometry; afterwards
// it checks the parts VTK made against what it found. The walk follows the
// EnSight Gold format as VTK reads it: ASCII files line by line (one value per
// line, one element per line, lines of at most 255 characters), binary files
// as "C Binary" or "Fortran Binary" with 80-character strings, 32-bit integers
// and 32-bit floats.
#include "importers/ensight_check.hpp"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDataArraySelection.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkDataSetAttributes.h>
#include <vtkGenericEnSightReader.h>
#include <vtkIdList.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

#include "importers/ensight_case.hpp"
#include "src/core/error.hpp"
#include "src/core/text.hpp"

namespace hydrocoef::vtk_detail {
namespace ensight {
namespace {

/// The sum of counts already checked to be positive.
std::size_t sum(const std::vector<long long>& counts) {
  return std::accumulate(counts.begin(), counts.end(), std::size_t{0},
                         [](std::size_t total, long long count) { return total + static_cast<std::size_t>(count); });
}

// --- the data files

/// An element section of a part: its type and number of elements.
struct Section {
  std::string type;
  std::size_t count = 0;
};

struct PartShape {
  long long number = 0;
  std::string description;
  std::size_t nodes = 0;
  std::vector<Section> sections;
  std::size_t cells = 0;  // VTK makes one cell of every element

  std::size_t count_of(const std::string& type) const {
    return std::accumulate(
        sections.begin(), sections.end(), std::size_t{0},
        [&type](std::size_t sum, const Section& section) { return section.type == type ? sum + section.count : sum; });
  }
};

enum class Encoding { Ascii, CBinary, FortranBinary };

struct Geometry {
  std::string file_name;  // for messages
  Encoding encoding = Encoding::Ascii;
  bool big_endian = false;
  std::vector<PartShape> parts;

  const PartShape* find(long long number) const {
    const auto found =
        std::find_if(parts.begin(), parts.end(), [number](const PartShape& part) { return part.number == number; });
    return found == parts.end() ? nullptr : &*found;
  }
};

/// Nodes per element of the element types VTK reads (0: per element, as in
/// nsided and nfaced), or -1 for anything else.
int nodes_per_element(std::string_view type) {
  static const std::map<std::string_view, int> table{
      {"point", 1},    {"bar2", 2},   {"bar3", 3},     {"tria3", 3},    {"tria6", 6},      {"quad4", 4},
      {"quad8", 8},    {"tetra4", 4}, {"tetra10", 10}, {"pyramid5", 5}, {"pyramid13", 13}, {"penta6", 6},
      {"penta15", 15}, {"hexa8", 8},  {"hexa20", 20},  {"nsided", 0},   {"nfaced", 0}};
  const auto found = table.find(type);
  return found == table.end() ? -1 : found->second;
}

/// An ASCII EnSight file read as VTK reads it: line by line, blank lines and
/// lines starting with '#' skipped where VTK skips them. Its last line must
/// end with a line end.
class AsciiFile {
 public:
  explicit AsciiFile(fs::path path) : path_(std::move(path)), in_(path_, std::ios::binary) {
    if (!in_) throw InputError(SourceLocation{path_.string()}, "cannot be opened for reading");
  }

  /// What the messages say the file is at (e.g. "part 2 ('fin')").
  void set_context(std::string context) { context_ = std::move(context); }

  /// True when only blank lines and comments are left.
  bool at_end() { return !fill_data_line(); }
  /// The next line that is not blank and not a comment, trimmed.
  std::string text(const std::string& expected) {
    if (!fill_data_line()) throw ends(expected);
    std::string line = std::move(*pending_);
    pending_.reset();
    return line;
  }
  /// The file's own description lines: the first is read as a data line, the
  /// second as it is, as VTK does.
  void descriptions() {
    text("a description line");
    raw_line("a second description line");
  }
  long long integer(const std::string& expected) {
    const std::string line = text(expected);
    const auto value = parse_integer(line);
    if (!value) throw found(line, expected + " (an integer)");
    return *value;
  }
  /// `rows` lines of `per_row` integers each, every one in [low, high].
  void integers(std::size_t rows, std::size_t per_row, long long low, long long high, const std::string& expected) {
    for (std::size_t row = 0; row < rows; ++row) integer_row(per_row, low, high, expected);
  }
  /// A line per entry of `per_row`, holding that many integers in [low, high].
  void integer_rows(const std::vector<long long>& per_row, long long low, long long high, const std::string& expected) {
    for (const long long count : per_row) integer_row(static_cast<std::size_t>(count), low, high, expected);
  }
  /// `count` lines of one integer each, in [low, high].
  std::vector<long long> counts(std::size_t count, long long low, long long high, const std::string& expected) {
    std::vector<long long> values;
    for (std::size_t i = 0; i < count; ++i) {
      const long long value = integer(expected);
      if (value < low || value > high) throw out_of_range(value, low, high, expected);
      values.push_back(value);
    }
    return values;
  }
  /// `count` lines of one real number each.
  void reals(std::size_t count, const std::string& expected) {
    for (std::size_t i = 0; i < count; ++i) {
      const std::string line = text(expected);
      if (!parse_real(line)) throw found(line, expected + " (a number, one per line)");
    }
  }
  void extents() {
    for (int i = 0; i < 3; ++i) text("an extents line");
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(SourceLocation{path_.string(), line_}, prefix() + message);
  }

 private:
  std::string prefix() const { return context_.empty() ? std::string() : context_ + ": "; }

  bool read_line(std::string& line) {
    if (!std::getline(in_, line)) return false;
    ++line_;
    if (line.size() > kMaxLineLength)
      fail("line of " + std::to_string(line.size()) + " characters; VTK's EnSight reader reads at most " +
           std::to_string(kMaxLineLength));
    // EnSight writers end every line; a file cut inside a number ("1.25e+00"
    // cut to "1.2") would otherwise read as a valid one.
    if (in_.eof() && !trim(line).empty()) fail("the last line has no line end: the file is cut short");
    return true;
  }
  bool fill_data_line() {
    if (pending_) return true;
    std::string line;
    while (read_line(line)) {
      if (line.empty() || line.front() == '#') continue;
      std::string trimmed(trim(line));
      if (trimmed.empty()) continue;
      pending_ = std::move(trimmed);
      return true;
    }
    return false;
  }
  void raw_line(const std::string& expected) {
    if (pending_) {
      pending_.reset();
      return;
    }
    std::string line;
    if (!read_line(line)) throw ends(expected);
  }
  void integer_row(std::size_t count, long long low, long long high, const std::string& expected) {
    const std::string line = text(expected);
    const std::string_view rest(line);
    std::size_t words = 0;
    std::size_t i = 0;
    while (i < rest.size()) {
      while (i < rest.size() && std::isspace(static_cast<unsigned char>(rest[i])) != 0) ++i;
      const std::size_t start = i;
      while (i < rest.size() && std::isspace(static_cast<unsigned char>(rest[i])) == 0) ++i;
      if (i == start) break;
      const std::string_view word = rest.substr(start, i - start);
      const auto value = parse_integer(word);
      if (!value) throw found(std::string(word), expected + " (an integer)");
      if (*value < low || *value > high) throw out_of_range(*value, low, high, expected);
      ++words;
    }
    if (words != count) throw found(line, std::to_string(count) + " integers on one line (" + expected + ")");
  }
  InputError ends(const std::string& expected) const {
    return InputError(SourceLocation{path_.string(), line_},
                      prefix() + "the file ends where " + expected + " was expected (truncated?)");
  }
  InputError found(const std::string& text, const std::string& expected) const {
    return InputError(SourceLocation{path_.string(), line_},
                      prefix() + "found " + excerpt(text) + "; expected " + expected);
  }
  InputError out_of_range(long long value, long long low, long long high, const std::string& expected) const {
    return InputError(SourceLocation{path_.string(), line_}, prefix() + "found " + std::to_string(value) +
                                                                 "; expected " + expected + " in " +
                                                                 std::to_string(low) + ".." + std::to_string(high));
  }

  fs::path path_;
  std::ifstream in_;
  std::size_t line_ = 0;
  std::optional<std::string> pending_;
  std::string context_;
};

/// A binary EnSight file: "C Binary" (items one after the other) or "Fortran
/// Binary" (each item a record between two 32-bit lengths), 80-character
/// strings, 32-bit integers and floats in one byte order.
class BinaryFile {
 public:
  BinaryFile(fs::path path, Encoding encoding, std::optional<bool> big_endian)
      : path_(std::move(path)),
        in_(path_, std::ios::binary),
        fortran_(encoding == Encoding::FortranBinary),
        big_endian_(big_endian) {
    if (!in_) throw InputError(SourceLocation{path_.string()}, "cannot be opened for reading");
    std::error_code error;
    size_ = std::filesystem::file_size(path_, error);
    if (error) throw InputError(SourceLocation{path_.string()}, "cannot be read: " + error.message());
  }

  void set_context(std::string context) { context_ = std::move(context); }
  std::optional<bool> big_endian() const { return big_endian_; }

  bool at_end() const { return position_ >= size_; }
  /// An 80-character string, up to its first NUL, trimmed.
  std::string text(const std::string& expected) {
    std::array<char, 80> buffer{};
    begin_record(buffer.size(), expected);
    read(buffer.data(), buffer.size());
    end_record(buffer.size(), expected);
    const auto end = std::find(buffer.begin(), buffer.end(), '\0');
    return std::string(trim(std::string_view(buffer.data(), static_cast<std::size_t>(end - buffer.begin()))));
  }
  /// The format line and the file's two description lines.
  void descriptions() {
    text("the format line");
    text("a description line");
    text("a second description line");
  }
  /// A 32-bit integer. The first one a C binary geometry file holds is a part
  /// number, which tells its byte order as VTK tells it: little-endian if
  /// that reads as 0..65536.
  long long integer(const std::string& expected) {
    std::array<unsigned char, 4> bytes{};
    begin_record(4, expected);
    read(reinterpret_cast<char*>(bytes.data()), 4);
    end_record(4, expected);
    if (!big_endian_) {
      const long long little = decode(bytes.data(), false);
      big_endian_ = !(little >= 0 && little <= kMaxPartNumber);
    }
    return decode(bytes.data(), *big_endian_);
  }
  /// `rows` x `per_row` integers in one record, every one in [low, high].
  void integers(std::size_t rows, std::size_t per_row, long long low, long long high, const std::string& expected) {
    scan_integers(rows * per_row, low, high, expected, nullptr);
  }
  void integer_rows(const std::vector<long long>& per_row, long long low, long long high, const std::string& expected) {
    scan_integers(sum(per_row), low, high, expected, nullptr);
  }
  std::vector<long long> counts(std::size_t count, long long low, long long high, const std::string& expected) {
    std::vector<long long> values;
    scan_integers(count, low, high, expected, &values);
    return values;
  }
  /// `count` floats in one record; their values do not matter here.
  void reals(std::size_t count, const std::string& expected) {
    const std::uint64_t bytes = 4 * static_cast<std::uint64_t>(count);
    begin_record(bytes, expected);
    position_ += bytes;
    in_.seekg(static_cast<std::streamoff>(position_));
    end_record(bytes, expected);
  }
  void extents() { reals(6, "the extents"); }
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(SourceLocation{path_.string()},
                     prefix() + message + " (at byte " + std::to_string(position_) + ")");
  }

 private:
  std::string prefix() const { return context_.empty() ? std::string() : context_ + ": "; }

  static long long decode(const unsigned char* bytes, bool big_endian) {
    std::uint32_t value = 0;
    for (int i = 0; i < 4; ++i) {
      const int shift = big_endian ? 8 * (3 - i) : 8 * i;
      value |= static_cast<std::uint32_t>(bytes[i]) << shift;
    }
    return static_cast<std::int32_t>(value);
  }
  void read(char* into, std::size_t bytes) {
    if (position_ + bytes > size_) fail_end("data");
    in_.read(into, static_cast<std::streamsize>(bytes));
    if (!in_) fail("read error");
    position_ += bytes;
  }
  [[noreturn]] void fail_end(const std::string& expected) const {
    fail("the file ends where " + expected + " was expected (truncated?)");
  }
  /// Checks that `bytes` bytes of `expected` follow and, in a Fortran file,
  /// reads the record's leading length.
  void begin_record(std::uint64_t bytes, const std::string& expected) {
    if (fortran_) {
      if (position_ + 4 > size_) fail_end(expected);
      std::array<unsigned char, 4> marker{};
      read(reinterpret_cast<char*>(marker.data()), 4);
      const long long length = decode(marker.data(), big_endian_.value_or(false));
      if (length < 0 || static_cast<std::uint64_t>(length) != bytes)
        fail("a Fortran record of " + std::to_string(length) + " bytes where " + expected + " (" +
             std::to_string(bytes) + " bytes) was expected");
    }
    if (position_ + bytes > size_) fail_end(expected);
  }
  void end_record(std::uint64_t bytes, const std::string& expected) {
    if (!fortran_) return;
    if (position_ + 4 > size_) fail_end("the end of a Fortran record of " + expected);
    std::array<unsigned char, 4> marker{};
    read(reinterpret_cast<char*>(marker.data()), 4);
    const long long length = decode(marker.data(), big_endian_.value_or(false));
    if (length < 0 || static_cast<std::uint64_t>(length) != bytes)
      fail("a Fortran record of " + expected + " ends with the length " + std::to_string(length) + "; expected " +
           std::to_string(bytes));
  }
  void scan_integers(std::size_t count, long long low, long long high, const std::string& expected,
                     std::vector<long long>* values) {
    const std::uint64_t bytes = 4 * static_cast<std::uint64_t>(count);
    begin_record(bytes, expected);
    if (values != nullptr) values->reserve(count);
    const bool big = big_endian_.value_or(false);
    std::vector<unsigned char> chunk;
    std::size_t left = count;
    while (left > 0) {
      const std::size_t n = std::min<std::size_t>(left, 1 << 16);
      chunk.resize(4 * n);
      read(reinterpret_cast<char*>(chunk.data()), chunk.size());
      for (std::size_t i = 0; i < n; ++i) {
        const long long value = decode(chunk.data() + 4 * i, big);
        if (value < low || value > high)
          fail("found " + std::to_string(value) + "; expected " + expected + " in " + std::to_string(low) + ".." +
               std::to_string(high));
        if (values != nullptr) values->push_back(value);
      }
      left -= n;
    }
    end_record(bytes, expected);
  }

  fs::path path_;
  std::ifstream in_;
  std::uint64_t size_ = 0;
  std::uint64_t position_ = 0;
  bool fortran_ = false;
  std::optional<bool> big_endian_;
  std::string context_;
};

/// How the geometry file is written, told from its first bytes as VTK tells
/// it: "<x> Binary" in the first 80 bytes (or in the first record of a
/// Fortran file) means binary, anything else ASCII.
std::pair<Encoding, std::optional<bool>> detect_encoding(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::array<char, 84> head{};
  in.read(head.data(), head.size());
  const auto got = static_cast<std::size_t>(in.gcount());
  const auto holds_binary = [](std::string_view text) {
    const auto words = split_words(text.substr(0, text.find('\0')));
    return words.size() >= 2 && starts_with(words[1], "Binary");
  };
  if (got >= 84) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(head.data());
    const bool little = bytes[0] == 80 && bytes[1] == 0 && bytes[2] == 0 && bytes[3] == 0;
    const bool big = bytes[0] == 0 && bytes[1] == 0 && bytes[2] == 0 && bytes[3] == 80;
    if ((little || big) && holds_binary(std::string_view(head.data() + 4, 80))) return {Encoding::FortranBinary, big};
  }
  if (holds_binary(std::string_view(head.data(), std::min<std::size_t>(got, 80)))) return {Encoding::CBinary, {}};
  return {Encoding::Ascii, false};
}

std::string part_context(const PartShape& part) {
  return "part " + std::to_string(part.number) +
         (part.description.empty() ? "" : " (" + in_quotes(part.description) + ")");
}

/// Walks a geometry file; fails on anything VTK would misread.
template <typename File>
std::vector<PartShape> scan_geometry(File& file) {
  file.descriptions();
  const auto id_line = [&file](const char* what) {
    const std::string line = file.text(std::string("'") + what + " id <off|given|assign|ignore>'");
    const auto words = split_words(line);
    if (words.size() < 3 || words[0] != what || words[1] != "id")
      file.fail("found " + excerpt(line) + "; expected '" + what + " id <off|given|assign|ignore>'");
    return words[2] == "given" || words[2] == "ignore";
  };
  const bool node_ids = id_line("node");
  const bool element_ids = id_line("element");

  std::vector<PartShape> parts;
  const auto next_keyword = [&file](const char* expected) -> std::optional<std::string> {
    if (file.at_end()) return std::nullopt;
    return file.text(expected);
  };
  std::optional<std::string> keyword = next_keyword("'extents' or 'part'");
  if (keyword && starts_with(*keyword, "extents")) {
    file.extents();
    keyword = next_keyword("'part'");
  }
  while (keyword) {
    if (!starts_with(*keyword, "part")) file.fail("found " + excerpt(*keyword) + "; expected 'part'");
    PartShape part;
    part.number = file.integer("a part number");
    if (part.number < 1 || part.number > kMaxPartNumber)
      file.fail("part number " + std::to_string(part.number) + "; expected 1.." + std::to_string(kMaxPartNumber));
    for (const auto& other : parts)
      if (other.number == part.number) file.fail("part " + std::to_string(part.number) + " appears twice");
    part.description = file.text("a part description");
    file.set_context(part_context(part));
    const std::string coordinates = file.text("'coordinates'");
    if (starts_with(coordinates, "block"))
      file.fail("structured ('block') parts are not supported; expected 'coordinates'");
    if (!starts_with(coordinates, "coordinates"))
      file.fail("found " + excerpt(coordinates) + "; expected 'coordinates'");
    const long long nodes = file.integer("the number of nodes");
    if (nodes < 0 || nodes > kMaxCount) file.fail("number of nodes " + std::to_string(nodes) + " is out of range");
    part.nodes = static_cast<std::size_t>(nodes);
    if (node_ids) file.integers(part.nodes, 1, std::numeric_limits<std::int32_t>::min(), kMaxCount, "a node id");
    for (const char* axis : {"an x coordinate", "a y coordinate", "a z coordinate"}) file.reals(part.nodes, axis);

    keyword = next_keyword("an element type or 'part'");
    while (keyword && !starts_with(*keyword, "part")) {
      const std::string type = split_words(*keyword).front();
      if (starts_with(type, "g_")) file.fail("ghost elements (" + in_quotes(type) + ") are not supported");
      const int per_element = nodes_per_element(type);
      if (per_element < 0) file.fail("found " + excerpt(*keyword) + "; expected an element type or 'part'");
      const long long elements = file.integer("the number of " + type + " elements");
      if (elements < 0 || elements > kMaxCount)
        file.fail("number of " + type + " elements " + std::to_string(elements) + " is out of range");
      const auto count = static_cast<std::size_t>(elements);
      if (element_ids) file.integers(count, 1, std::numeric_limits<std::int32_t>::min(), kMaxCount, "an element id");
      const std::string connectivity = "a node index of a " + type + " element";
      if (type == "nsided") {
        const auto sizes = file.counts(count, 3, kMaxCount, "the number of nodes of an nsided element");
        file.integer_rows(sizes, 1, nodes, connectivity);
      } else if (type == "nfaced") {
        const auto faces = file.counts(count, 1, kMaxCount, "the number of faces of an nfaced element");
        const auto sizes = file.counts(sum(faces), 3, kMaxCount, "the number of nodes of an nfaced face");
        file.integer_rows(sizes, 1, nodes, connectivity);
      } else {
        file.integers(count, static_cast<std::size_t>(per_element), 1, nodes, connectivity);
      }
      part.sections.push_back({type, count});
      part.cells += count;
      keyword = next_keyword("an element type or 'part'");
    }
    file.set_context("");
    parts.push_back(std::move(part));
  }
  return parts;
}

/// Walks a variable file against the geometry; records the parts it covers.
template <typename File>
void scan_variable(File& file, Variable& variable, const Geometry& geometry) {
  const std::string values = variable.components == 1 ? "a value" : "a vector component";
  file.text("the description line");
  const auto next_keyword = [&file](const char* expected) -> std::optional<std::string> {
    if (file.at_end()) return std::nullopt;
    return file.text(expected);
  };
  const auto check_plain = [&file](const std::string& keyword) {
    const auto words = split_words(keyword);
    for (std::size_t i = 1; i < words.size(); ++i)
      if (words[i] == "undef" || words[i] == "partial")
        file.fail("'" + words[i] + "' values are not supported; expected a value for every node or element");
  };
  std::optional<std::string> keyword = next_keyword("'part'");
  // A file cut after its description would otherwise pass as one that
  // gives no values anywhere.
  if (!keyword) file.fail("no 'part' after the description line; expected values for at least one part (truncated?)");
  while (keyword) {
    if (!starts_with(*keyword, "part")) file.fail("found " + excerpt(*keyword) + "; expected 'part'");
    const long long number = file.integer("a part number");
    const PartShape* part = geometry.find(number);
    if (part == nullptr) {
      std::string known;
      for (const auto& other : geometry.parts) known += (known.empty() ? "" : ", ") + std::to_string(other.number);
      file.fail("part " + std::to_string(number) + " is not in " + geometry.file_name + ", which has part" +
                (geometry.parts.size() == 1 ? " " : "s ") + (known.empty() ? "none" : known));
    }
    if (variable.parts.count(number) > 0) file.fail("part " + std::to_string(number) + " appears twice");
    file.set_context(part_context(*part));
    // VTK reads nothing more of a part without nodes or elements.
    const std::string in_geometry = " in " + geometry.file_name;
    if (variable.association == FieldAssociation::Point) {
      if (part->nodes == 0 && !file.at_end()) {
        const std::string next = file.text("'part'");
        if (!starts_with(next, "part")) file.fail("values for nodes, but the part has none" + in_geometry);
        keyword = next;
        file.set_context("");
        continue;
      }
      if (part->nodes > 0) {
        const std::string coordinates = file.text("'coordinates'");
        if (!starts_with(coordinates, "coordinates"))
          file.fail("found " + excerpt(coordinates) + "; expected 'coordinates'");
        check_plain(coordinates);
        for (int c = 0; c < variable.components; ++c) file.reals(part->nodes, values);
        variable.parts.insert(number);
      }
      keyword = next_keyword("'part'");
    } else {
      keyword = next_keyword("an element type or 'part'");
      if (part->cells == 0 && keyword && !starts_with(*keyword, "part"))
        file.fail("values for " + excerpt(*keyword) + " elements, but the part has none" + in_geometry);
      if (part->cells > 0) {
        // VTK leaves the values of elements the file skips undefined.
        std::set<std::string> types;
        std::size_t covered = 0;
        while (keyword && !starts_with(*keyword, "part")) {
          check_plain(*keyword);
          const std::string type = split_words(*keyword).front();
          if (nodes_per_element(type) < 0) file.fail("found " + excerpt(*keyword) + "; expected an element type");
          const std::size_t count = part->count_of(type);
          if (count == 0) file.fail("values for " + type + " elements, which the part does not have" + in_geometry);
          if (!types.insert(type).second) file.fail("values for " + type + " elements appear twice");
          for (int c = 0; c < variable.components; ++c) file.reals(count, values);
          covered += count;
          keyword = next_keyword("an element type or 'part'");
        }
        if (covered != part->cells)
          file.fail("values for " + std::to_string(covered) + " of the part's " + std::to_string(part->cells) +
                    " elements" + in_geometry + "; expected all of them");
        variable.parts.insert(number);
      }
    }
    file.set_context("");
  }
}

Geometry check_geometry(const fs::path& path) {
  std::error_code error;
  if (!fs::is_regular_file(path, error))
    throw InputError(SourceLocation{path.string()}, "geometry file not found (named by the case file)");
  Geometry geometry;
  geometry.file_name = path.filename().string();
  std::optional<bool> big_endian;
  std::tie(geometry.encoding, big_endian) = detect_encoding(path);
  if (geometry.encoding == Encoding::Ascii) {
    AsciiFile file(path);
    geometry.parts = scan_geometry(file);
  } else {
    BinaryFile file(path, geometry.encoding, big_endian);
    geometry.parts = scan_geometry(file);
    geometry.big_endian = file.big_endian().value_or(false);
  }
  if (geometry.parts.empty()) throw InputError(SourceLocation{path.string()}, "no parts; expected at least one 'part'");
  return geometry;
}

void check_variable(Variable& variable, const Geometry& geometry, const fs::path& case_file) {
  std::error_code error;
  if (!fs::is_regular_file(variable.file, error))
    throw InputError(SourceLocation{variable.file.string()},
                     "file of variable " + in_quotes(variable.description) + " not found (named by " +
                         case_file.filename().string() + ":" + std::to_string(variable.line) + ")");
  if (geometry.encoding == Encoding::Ascii) {
    AsciiFile file(variable.file);
    scan_variable(file, variable, geometry);
  } else {
    BinaryFile file(variable.file, geometry.encoding, geometry.big_endian);
    scan_variable(file, variable, geometry);
  }
}

/// VTK 9.1's ASCII reader stores the nodes of an nsided element in reverse
/// order (its binary reader does not), which turns the face inside out: put
/// them back in the file's order.
void restore_nsided_order(vtkDataSet* data, const PartShape& part) {
  auto* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (grid == nullptr) return;
  vtkNew<vtkIdList> ids;
  vtkIdType first = 0;
  for (const auto& section : part.sections) {
    const auto count = static_cast<vtkIdType>(section.count);
    if (section.type == "nsided") {
      for (vtkIdType cell = first; cell < first + count; ++cell) {
        if (grid->GetCellType(cell) != VTK_POLYGON) continue;
        grid->GetCellPoints(cell, ids);
        std::vector<vtkIdType> points(ids->GetPointer(0), ids->GetPointer(0) + ids->GetNumberOfIds());
        std::reverse(points.begin(), points.end());
        grid->ReplaceCell(cell, static_cast<int>(points.size()), points.data());
      }
    }
    first += count;
  }
}

/// The parts VTK made, checked against the geometry and variable files, as
/// leaves named by their descriptions.
std::vector<Leaf> checked_parts(vtkDataObject* output, const Case& spec, const Geometry& geometry,
                                const fs::path& case_file) {
  const SourceLocation where{case_file.string()};
  auto* blocks = vtkMultiBlockDataSet::SafeDownCast(output);
  if (blocks == nullptr || blocks->GetNumberOfBlocks() != geometry.parts.size())
    throw InputError(where, "VTK read " + std::to_string(blocks == nullptr ? 0 : blocks->GetNumberOfBlocks()) +
                                " parts; the geometry file " + spec.geometry_file.filename().string() + " has " +
                                std::to_string(geometry.parts.size()));
  std::vector<Leaf> leaves;
  for (unsigned int i = 0; i < blocks->GetNumberOfBlocks(); ++i) {
    const PartShape& part = geometry.parts[i];
    auto* data = vtkDataSet::SafeDownCast(blocks->GetBlock(i));
    const auto points = data == nullptr ? 0 : static_cast<std::size_t>(data->GetNumberOfPoints());
    const auto cells = data == nullptr ? 0 : static_cast<std::size_t>(data->GetNumberOfCells());
    if (points != part.nodes || cells != part.cells)
      throw InputError(where, part_context(part) + ": VTK read " + std::to_string(points) + " nodes and " +
                                  std::to_string(cells) + " elements; the geometry file has " +
                                  std::to_string(part.nodes) + " and " + std::to_string(part.cells));
    for (const auto& variable : spec.variables) {
      if (variable.parts.count(part.number) == 0) continue;
      const bool per_node = variable.association == FieldAssociation::Point;
      vtkDataSetAttributes* attributes = per_node ? static_cast<vtkDataSetAttributes*>(data->GetPointData())
                                                  : static_cast<vtkDataSetAttributes*>(data->GetCellData());
      vtkDataArray* array = attributes->GetArray(variable.description.c_str());
      const auto expected = static_cast<vtkIdType>(per_node ? part.nodes : part.cells);
      if (array == nullptr || array->GetNumberOfComponents() != variable.components ||
          array->GetNumberOfTuples() != expected)
        throw InputError(where, part_context(part) + ": VTK did not read variable " + in_quotes(variable.description) +
                                    " from " + variable.file.filename().string());
    }
    if (geometry.encoding == Encoding::Ascii) restore_nsided_order(data, part);
    const std::string name = part.description.empty() ? "part" + std::to_string(part.number) : part.description;
    leaves.push_back({name, data});
  }
  return leaves;
}

}  // namespace
}  // namespace ensight

FileContents read_ensight(const fs::path& case_file, const ScopedVtkMessageCapture& capture) {
  ensight::Case spec = ensight::parse_case(case_file);
  const ensight::Geometry geometry = ensight::check_geometry(spec.geometry_file);
  for (auto& variable : spec.variables) ensight::check_variable(variable, geometry, case_file);

  vtkNew<vtkGenericEnSightReader> reader;
  reader->SetCaseFileName(case_file.string().c_str());
  reader->UpdateInformation();
  throw_if_vtk_failed(reader, false, capture, case_file, "EnSight Gold", true);
  // Only the variables checked above: VTK would read the others (tensors,
  // complex values) as carelessly as the rest.
  reader->GetPointDataArraySelection()->DisableAllArrays();
  reader->GetCellDataArraySelection()->DisableAllArrays();
  for (const auto& variable : spec.variables)
    (variable.association == FieldAssociation::Point ? reader->GetPointDataArraySelection()
                                                     : reader->GetCellDataArraySelection())
        ->EnableArray(variable.description.c_str());
  // The last time of all time sets: VTK then reads each file at the last step
  // of its own time set.
  if (spec.last_time)
    reader->UpdateTimeStep(*spec.last_time);
  else
    reader->Update();

  FileContents contents;
  contents.object = reader->GetOutputDataObject(0);
  throw_if_vtk_failed(reader, contents.object == nullptr, capture, case_file, "EnSight Gold", true);
  contents.leaves = ensight::checked_parts(contents.object, spec, geometry, case_file);
  return contents;
}

}  // namespace hydrocoef::vtk_detail
