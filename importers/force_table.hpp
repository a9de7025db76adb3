// The force-table importer: a delimited text table in which each row is one
// run and each column is a velocity component, a force or moment component
// or a disturbance parameter, with its unit in brackets as CFX writes it
// ("u [m s^-1]", "X [N]", "N [ N m ]", "r [deg s^-1]"). Lines starting with '#'
// are comments. Values are converted to SI; nothing here knows the database.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "src/core/run.hpp"

namespace hydrocoef {

inline constexpr std::string_view kForceTableImporter = "force-table";
inline constexpr std::string_view kForceTableImporterVersion = "1";

struct ForceTableOptions {
  std::string body = "vehicle";
  /// Disturbance parameters that hold for every row (--set NAME=VALUE), SI.
  std::map<std::string, double> disturbances;
  /// Body velocity for components the table has no column for (--set v=0.05), SI.
  std::array<double, 6> velocity_b{};
  /// Component (u..r, X..N) -> header name in the file, for files whose
  /// headers are not the SNAME letters (--column X=Drag).
  std::map<std::string, std::string> columns;
  /// Component -> unit, for headers without brackets or to override them.
  std::map<std::string, std::string> units;
  /// Header names whose values are disturbance parameters (a sweep column).
  std::vector<std::string> disturbance_columns;
  /// Header names to skip.
  std::vector<std::string> ignored_columns;
  SignConvention sign = SignConvention::OnBody;
  Fluid fluid;
  std::array<double, 3> reference_point_b{};
};

/// Parses table text. `file` names the source in error messages. Throws
/// InputError with file, line and column for: no header, an unknown or
/// duplicated column, a missing or wrong unit, a row with the wrong number of
/// fields, a field that is not a finite number, two rows with the same key,
/// no velocity or no force column, no data rows.
std::vector<ImportedRun> parse_force_table(std::string_view text, const std::string& file,
                                           const ForceTableOptions& options);

/// Reads and parses a file, with its provenance (SHA-256 of the bytes).
ImportBatch read_force_table(const std::filesystem::path& file, const ForceTableOptions& options);

}  // namespace hydrocoef
