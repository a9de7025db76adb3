// Any table of time (or iteration) and forces as a ForceHistory: a CSV,
// semicolon- or tab-separated export, or columns separated by blanks, from
// whatever wrote it (a solver's monitor export, a spreadsheet, a script).
//
// The header is the first line that is neither blank nor a '#' comment; when
// that line already holds numbers, the last comment line before it is the
// header (as in "# Time Fx Fy Fz"). Its delimiter (',' else tab else ';' else
// blanks) is that of every row. Header cells are "Name" or "Name [unit]" with
// CFX-style units ("Fx [kN]", "Mz [N m]", "Torque [J]", "Time [ms]"),
// converted to SI and checked against the column's kind.
//
// Columns are recognised by name (case, blanks, '_' and '-' ignored):
// - the abscissa: time, t, flow time, physical time, solution time (time, in
//   s unless a unit says otherwise) or iteration, iter, step, time step,
//   timestep, accumulated time step, outer iteration (iterations);
// - forces and moments in the source's axes: Fx Fy Fz, Force X, Mx My Mz,
//   Moment X, Tx, Torque X, each optionally with a part before or after it
//   (Fx pressure, pressure_Fx, Fx_viscous, total Fx);
// - or SNAME body-axis letters X Y Z K M N (upper case, with an optional
//   part): the frame then says the components are already in body axes.
// Mixing the two namings is refused. Other columns are left out, with a note
// naming them. A mapping (options.columns) replaces recognition: then only
// the mapped components are read.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "src/history/force_history.hpp"

namespace hydrocoef {

inline constexpr std::string_view kForceHistoryCsvImporter = "force-history-csv";
inline constexpr std::string_view kForceHistoryCsvImporterVersion = "1";

struct ForceHistoryCsvOptions {
  /// Component -> column: keys "Fx".."Mz" or "X".."N", optionally with a part
  /// ("Fx:pressure", "N:viscous"; total when none); values a whole header
  /// ("Drag [N]") or its name without the unit ("Drag").
  std::map<std::string, std::string> columns;
  /// The abscissa's header (whole or without its unit), when its name is not
  /// one of those recognised.
  std::optional<std::string> abscissa_column;
  /// Time or iteration, overriding what the column's name says.
  std::optional<HistoryAbscissa> abscissa;
  /// Units for headers without brackets: keys as in `columns`, or "time";
  /// SI is assumed (with a note) otherwise.
  std::map<std::string, std::string> units;
  bool drop_incomplete_last_row = false;
  bool compute_sha256 = true;  ///< read_force_history_csv only
  unsigned threads = 0;        ///< 0: every core
};

/// Parses a table's text; `file` names it in messages and in the history.
/// Throws InputError with file, line and column for: no header, no abscissa
/// column or several, no force or moment column (listing the columns), a
/// mapped column that does not exist or matches twice, two columns for one
/// component, mixed namings, a unit that is unknown or of the wrong kind, a
/// row that is not numbers or has the wrong count, an abscissa that does not
/// increase, no rows.
ForceHistory parse_force_history_csv(std::string_view text, const std::string& file,
                                     const ForceHistoryCsvOptions& options = {});

/// Reads and parses a file, with its SHA-256.
ForceHistory read_force_history_csv(const std::filesystem::path& file, const ForceHistoryCsvOptions& options = {});

}  // namespace hydrocoef
