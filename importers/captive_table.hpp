// The captive-test table importer: a delimited (comma, tab, semicolon) or
// blank-separated text table of captive model tests -- static drift, rudder
// angle, drift and rudder, circular motion (ITTC 7.5-02-06-02) -- whose
// forces are non-dimensional, one run per row:
//
//   # form = prime
//   # drift_convention = mmg
//   # length = 160.93
//   # density = 1025
//   test,U [m/s],beta [deg],delta [deg],r',X',Y',N'
//   static-drift,7.7175,4,0,0,-0.0012,0.0081,-0.0018
//
// Columns (by the name before any [unit]): test (static-drift, rudder,
// drift-rudder or circular-motion; optional), U or speed [a speed unit] or
// Fn (U = Fn sqrt(g L)), beta and delta [deg or rad, stated], r' (r L / U),
// and the forces X', Y' and moments K', N' (X'' ... in the bis form) in the
// form of the table: prime (SNAME 1950: 1/2 rho U^2 L^2, 1/2 rho U^2 L^3),
// bis (Norrbin 1971: m g, m g L) or mmg (1/2 rho U^2 L d, 1/2 rho U^2 L^2 d),
// U each row's own speed (src/derivatives/normalisation.hpp converts).
//
// Settings are comment lines before the header, `# NAME = VALUE` (SI):
// form, drift_convention (mmg: beta = atan2(-v, u), the bow turned to port
// of the track for beta > 0, as ITTC and MMG captive tests state it; fossen:
// beta = atan2(v, u)), length, speed, density (or rho), draft, mass, volume,
// gravity. An option given (CaptiveTableOptions) takes precedence over the
// file's line; the body's stored reference data (length, draft, volume)
// fill in what neither gives. Nothing is guessed: a value a column needs and
// nothing gives is an InputError naming the column.
//
// Each row becomes a run in body axes, SI: u = U cos beta, v = -U sin beta
// (mmg) or U sin beta (fossen), r = r' U / L, w = p = q = 0, the rudder angle
// the disturbance `delta` [rad], the forces dimensional and on the body.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "src/core/run.hpp"

namespace hydrocoef {

inline constexpr std::string_view kCaptiveTableImporter = "captive-table";
inline constexpr std::string_view kCaptiveTableImporterVersion = "1";

/// A reference value given from outside the file, with where it came from
/// for the notes and messages ("--length", "body set").
struct CaptiveValue {
  std::optional<double> value;
  std::string origin;
};

/// A body's stored reference data (`hydrocoef body set`) a table may use.
struct CaptiveBodyReference {
  std::optional<double> length;  ///< L [m]
  std::optional<double> draft;   ///< d [m]
  std::optional<double> volume;  ///< displaced volume [m^3]
};

struct CaptiveTableOptions {
  std::string body = "vehicle";
  std::optional<std::string> form;              ///< prime, bis or mmg (--form)
  std::optional<std::string> drift_convention;  ///< mmg or fossen (--drift-convention)
  /// Given values (SI), taking precedence over the file's settings lines.
  CaptiveValue length, speed, density, draft, mass, volume, gravity;
  /// The body's stored reference data: used when neither an option nor the file gives the value.
  CaptiveBodyReference body_reference;
  /// Disturbance parameters that hold for every row (--set NAME=VALUE), SI.
  std::map<std::string, double> disturbances;
  /// Header names to skip.
  std::vector<std::string> ignored_columns;
  std::optional<double> kinematic_viscosity;  ///< stored with each run [m^2/s]
  SignConvention sign = SignConvention::OnBody;
  std::array<double, 3> reference_point_b{};
};

/// A table read: its runs, and what was used to make them dimensional.
struct CaptiveTable {
  std::vector<ImportedRun> runs;
  /// One line for the import's notes: the form, each reference value with
  /// where it came from, the drift convention, the tests.
  std::string note;
  /// The same canonically ("form=prime L=160.93 ..."): with the bytes, what
  /// identifies the import (another length is another import).
  std::string settings_key;
};

/// Parses table text. `file` names the source in messages. Throws InputError
/// with file, line and column for: no header, an unknown or duplicated
/// column, a unit missing or of the wrong kind, an unknown or repeated
/// setting line, no form, a beta column without the drift convention, a
/// reference value a column needs that nothing gives, a row with the wrong
/// number of fields, a field that is not a finite number, a speed not above
/// zero, an unknown test type or a row that is not the test it names, two
/// rows with the same key, no force column, no data rows.
CaptiveTable parse_captive_table(std::string_view text, const std::string& file, const CaptiveTableOptions& options);

/// A file read: its runs with provenance (SHA-256 of the bytes), and the
/// table's note and settings key.
struct CaptiveTableFile {
  ImportBatch batch;
  std::string note;
  std::string settings_key;
};
CaptiveTableFile read_captive_table(const std::filesystem::path& file, const CaptiveTableOptions& options);

}  // namespace hydrocoef
