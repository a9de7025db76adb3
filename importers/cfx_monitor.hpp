// The CFX monitor importer: the iteration history of force and torque
// monitors, as `cfx5mondata -out` writes it ("ACCUMULATED TIMESTEP" then
// quoted "CATEGORY,Name" headers, no units) or as the Solver Manager's
// "Export Plot Data" writes it (a preamble, then "Accumulated Timestep,
// Fx1 [N], Torque1 [J]"), reduced to one run's generalized force: the last
// iteration or the mean of the last N. The run's key, fluid and reference
// point come from the options, since a monitor file does not hold them. The
// spread and drift over the averaged window are returned beside the run so
// that a caller can judge convergence. Values are converted to SI; nothing
// here knows the database.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "src/core/run.hpp"
#include "src/history/force_history.hpp"

namespace hydrocoef {

inline constexpr std::string_view kCfxMonitorImporter = "cfx-monitor";
inline constexpr std::string_view kCfxMonitorImporterVersion = "1";

struct CfxMonitorOptions {
  /// The run the monitors belong to: body (non-empty), nu_b, disturbances (SI).
  RunKey key{"vehicle", {}, {}};
  Fluid fluid;
  std::array<double, 3> reference_point_b{};  ///< moment centre of the torque monitors [m], body axes
  /// Recorded with the run, as the force table does; values are taken as written.
  SignConvention sign = SignConvention::OnBody;
  /// Component (X Y Z K M N) -> monitor (--monitor X="USER POINT,Fx"). A
  /// monitor is named by its whole header ("Fx1 [N]"), its name without the
  /// unit ("Fx1") or the part after its category ("Fx" for "USER POINT,Fx",
  /// "Hull Fx" for "Monitor Point: Hull Fx [N]"). When any mapping is given
  /// only the mapped components are read; otherwise columns are recognised by
  /// name (see parse_cfx_monitor).
  std::map<std::string, std::string> monitors;
  /// Component -> unit, for columns without brackets (cfx5mondata writes
  /// none, and SI is assumed) or to override the brackets.
  std::map<std::string, std::string> units;
  /// How many of the last iterations to average; 1 takes the last value.
  std::size_t average_last = 1;
};

/// How a component behaved over the averaged window. All values are SI and
/// signed as the run's tau_b; a component without a monitor stays empty.
struct MonitorSummary {
  std::size_t iterations = 0;              ///< data rows in the file
  std::size_t first_iteration = 0;         ///< accumulated timestep of the first row
  std::size_t window_first_iteration = 0;  ///< accumulated timestep of the first averaged row
  std::size_t last_iteration = 0;          ///< accumulated timestep of the last row
  std::size_t window = 0;                  ///< rows averaged (= average_last)
  std::array<std::string, 6> columns;      ///< header of the monitor giving X..N, "" when none
  std::array<std::optional<double>, 6> mean;
  /// Population standard deviation over the window (0 for a window of 1).
  std::array<std::optional<double>, 6> std_dev;
  /// (last - first value of the window) / |mean|; empty when the mean is 0.
  std::array<std::optional<double>, 6> relative_change;
};

struct MonitorImport {
  ImportBatch batch;  ///< one run; tau_b holds the means
  MonitorSummary summary;
};

/// The monitors as a force history (src/history): one sample per iteration
/// (accumulated timestep, strictly increasing), the mapped or recognised
/// components in SI, in the case's axes, each sample with its line. Leading
/// rows where a monitor used has no value yet are left out (with a note); an
/// empty cell after that is refused. options.average_last > 1 only asks for
/// that many rows (the window itself is chosen by the history analysis). The
/// key, fluid, reference point and sign of the options are not used.
ForceHistory parse_cfx_monitor_history(std::string_view text, const std::string& file,
                                       const CfxMonitorOptions& options);
ForceHistory read_cfx_monitor_history(const std::filesystem::path& file, const CfxMonitorOptions& options);

/// Parses monitor text. `file` names the source in error messages and in the
/// provenance, whose SHA-256 is that of `text`.
///
/// The header is the first line starting with "Accumulated Timestep"
/// (case-insensitive, optionally quoted); lines before it are skipped. Without
/// a mapping, a column whose name ends in Fx, F x, F_x, Force X, force_x (X Y
/// Z) or Mx, Tx, Torque x, Moment x, torque_x (K M N), optionally followed by
/// digits, is recognised; a preceding letter or digit prevents it ("Hull Fx1"
/// is X, "HullFx" is not). Forces must be in a force unit, torques in a moment
/// unit ([J] is N m). Empty cells are allowed outside the averaged window and
/// in unused columns.
///
/// Throws InputError with file, line and column for: an empty file, binary
/// data, no header, no force or torque column (listing the columns), a mapped
/// monitor that does not exist (listing the columns) or that matches several,
/// two columns recognised as one component, a bad or wrong-kind unit, a row
/// with the wrong number of fields, an accumulated timestep that is not a
/// whole number, an empty cell, text or a non-finite value in a used column of
/// the window (a last line without its newline is reported as truncated),
/// fewer rows than average_last. Bad options (empty body, unknown component,
/// average_last 0) throw InputError without a location. Quoted file text in
/// messages is escaped to stay printable.
MonitorImport parse_cfx_monitor(std::string_view text, const std::string& file, const CfxMonitorOptions& options);

/// Reads and parses a file, with its provenance (SHA-256 of the bytes).
MonitorImport read_cfx_monitor(const std::filesystem::path& file, const CfxMonitorOptions& options);

/// True when the start of a file looks like a monitor export: one of its first
/// lines starts with "Accumulated Timestep". For format detection.
bool looks_like_cfx_monitor(std::string_view head);

}  // namespace hydrocoef
