// The EnSight Gold case file (.case) as VTK reads it: parse_case finds the
// geometry and the scalar and vector variables, checks the time sets and
// names the file each entry gives at the time step VTK reads, for
// ensight_check.cpp to walk before VTK reads them. With the text helpers and
// VTK's limits that the case file and the data files share. Internal to the
// VTK surface importer, not part of the public API.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "importers/vtk_reading_internal.hpp"
#include "src/mesh/surface_mesh.hpp"

namespace hydrocoef::vtk_detail::ensight {

constexpr std::size_t kMaxLineLength = 255;  // VTK reads EnSight lines into char[256]
constexpr long long kMaxPartNumber = 65536;  // VTK's limit, which it also uses to tell the byte order
constexpr long long kMaxCount = std::numeric_limits<std::int32_t>::max();

// Text helpers (ensight_case.cpp). Numbers are whole words: "+" allowed in
// front, nothing after.
std::vector<std::string> split_words(std::string_view text);
bool starts_with(std::string_view text, std::string_view prefix);
std::optional<long long> parse_integer(std::string_view text);
std::optional<double> parse_real(std::string_view text);
/// What a quoted excerpt of a file may show: printable, and short.
std::string excerpt(std::string_view text);

struct TimeSet {
  std::optional<long long> steps;
  std::vector<double> times;
  std::vector<long long> file_numbers;
  std::optional<long long> start;
  std::optional<long long> increment;
};

/// A scalar or vector variable per node or per element: the ones read.
struct Variable {
  std::string description;
  FieldAssociation association = FieldAssociation::Point;
  int components = 1;
  int time_set = 0;  // 0: none
  std::string pattern;
  std::size_t line = 0;
  fs::path file;              // the file at the time step read
  std::set<long long> parts;  // the parts the file gives values for
};

struct Case {
  std::string geometry_pattern;
  int geometry_time_set = 0;
  std::size_t geometry_line = 0;
  fs::path geometry_file;
  std::vector<Variable> variables;
  std::map<long long, TimeSet> time_sets;
  std::optional<double> last_time;
};

/// Reads the case file: the geometry and the variables read (with the file of
/// each at the last step of its time set) and the time sets. Throws InputError
/// naming the case file and line on anything VTK would misread or that is not
/// supported.
Case parse_case(const fs::path& case_file);

}  // namespace hydrocoef::vtk_detail::ensight
