// The import of CFD results as a library call: what `hydrocoef import` does
// before it writes the database, for the CLI, the Python module and other
// programs alike.
//
//   plan:  the inputs expanded into files and case folders, each with its
//          settings layers (src/pipeline/import_plan.hpp);
//   read:  each input read on a pool of threads: its settings merged by
//          precedence (command line first, src/pipeline/run_settings.hpp),
//          the frame and the run key resolved once from them, the file read
//          by its importer, and the result turned into runs in body axes.
//
// What each kind of input becomes:
//   - a surface export (CFD-Post, VTK family): integrated pressure and shear
//     (src/pipeline/surface_run.hpp), one run;
//   - a force table: one run per row, keys from its columns;
//   - a force history (OpenFOAM's force files or function-object folder, a
//     CFX monitor file, any CSV of time and forces) and an OpenFOAM case
//     folder (its forces
//     function object's output): every sample's moments taken to the run's
//     reference point, mirrored for symmetry planes and turned into body
//     axes, then averaged over the statistically steady window with the
//     standard error of each component (src/history/history_analysis.hpp).
// One frame transform turns the key's velocity and the forces, whatever
// source each setting came from. A setting an importer cannot apply is
// refused when the command line or the file's own sidecar or manifest row
// gives it, and noted when it comes from a folder sidecar shared by other
// kinds of files.
//
// One file a stage: src/pipeline/import_files_internal.hpp lists them.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "importers/captive_table.hpp"
#include "importers/cfx_monitor.hpp"
#include "src/core/run.hpp"
#include "src/history/history_analysis.hpp"
#include "src/pipeline/import_plan.hpp"
#include "src/pipeline/run_settings.hpp"
#include "src/pipeline/surface_run.hpp"
#include "src/store/database.hpp"

namespace hydrocoef {

/// Options of the table, monitor and history readers, by column.
struct ColumnOptions {
  std::map<std::string, std::string> columns;    ///< component -> header (tables, histories)
  std::map<std::string, std::string> units;      ///< component -> unit for headers without one
  std::vector<std::string> disturbance_columns;  ///< tables: headers holding a disturbance
  std::vector<std::string> ignored_columns;      ///< tables: headers to skip
  std::map<std::string, std::string> monitors;   ///< monitors: component -> monitor
  std::size_t average_last = 1;                  ///< monitors: > 1 averages the last N iterations (window last:N)
};

struct ImportRequest {
  std::vector<std::filesystem::path> inputs;
  SettingsLayer command_line;  ///< source CommandLine
  ImportPlanOptions plan;
  std::string format = "auto";  ///< auto, table, monitor, cfdpost, vtk, history, captive-table
  ColumnOptions columns;
  /// Captive-test tables: the form, drift convention and reference values
  /// given as options (body, disturbances, fluid and sign come from each
  /// input's settings), and the stored reference data of the bodies by name.
  CaptiveTableOptions captive;
  std::map<std::string, CaptiveBodyReference> body_references;
  std::string default_body = "vehicle";
  /// Refuse a history or surface input whose velocity no setting gives
  /// (require_velocity); `integrate`, which stores nothing, reads without.
  bool require_velocity = true;
  unsigned jobs = 0;  ///< 0: every core
  /// Called after each input is read (from the reading threads, one at a
  /// time): inputs done, inputs in all, the input's path.
  std::function<void(std::size_t, std::size_t, const std::filesystem::path&)> progress;
};

/// One input read and turned into runs.
struct ImportedInput {
  PlannedInput input;
  std::string format;  ///< table, monitor, cfdpost, vtk, openfoam-forces, force-history, openfoam-case
  ImportBatch batch;   ///< the runs, in body axes, with provenance and settings
  RunSettings settings;
  std::optional<SurfaceRun> surface;
  std::optional<HistoryAnalysis> history;
  std::vector<std::string> notes;
  /// A captive-test table's normalisation and reference values, canonical:
  /// part of the import's identity (settings_key); "" for other formats.
  std::string captive_settings;
};

/// A force-history input before any averaging: every sample in body axes,
/// moments about the run's reference point, with what the reading decided.
/// What the forced-oscillation analysis (src/pipeline/pmm_runs) starts from.
struct BodyHistory {
  std::string format;    ///< openfoam-forces, force-history, openfoam-case, monitor
  ForceHistory history;  ///< body axes
  Provenance provenance;
  RunSettings settings;
  FrameTransform frame;
  Vec3 reference_b{};  ///< the moment reference point, body axes [m]
  RunKey key;          ///< the run's key from its settings (body, mean velocity, disturbances)
  std::vector<std::string> notes;
};

/// Reads one planned force-history input into body axes. InputError naming
/// the file for an input of another kind (a surface export, a table) or
/// anything read_input would refuse.
BodyHistory read_body_history(const PlannedInput& input, const ImportRequest& request);

/// Plans the request (see plan_import).
ImportPlan plan_request(const ImportRequest& request);

/// Reads one planned input. InputError naming the file for anything wrong
/// with it, its settings or its contents.
ImportedInput read_input(const PlannedInput& input, const ImportRequest& request);

/// Reads every planned input on `request.jobs` threads, results in plan
/// order. After all stop, the first error in plan order is rethrown.
std::vector<ImportedInput> read_inputs(const ImportPlan& plan, const ImportRequest& request);

/// The format an input will be read as: the requested one (checked; a
/// "captive-table" only when requested), or by
/// extension and first bytes: "cfdpost", "vtk", "monitor", "table",
/// "openfoam-forces" (OpenFOAM's force files, or a folder of them),
/// "force-history" (a table with a time or iteration column),
/// "openfoam-case".
std::string input_format(const PlannedInput& input, const std::string& requested);

/// A whole import: what was planned, read and stored, with the totals the
/// CLI and the Python module report.
struct ImportResult {
  ImportPlan plan;
  std::vector<ImportedInput> inputs;    ///< in plan order
  std::vector<ImportOutcome> outcomes;  ///< one per input, as stored
  /// The plan's and inputs' notes, each once, with how many gave it.
  std::vector<std::pair<std::string, std::size_t>> notes;
  std::size_t runs = 0, runs_created = 0, runs_extended = 0, already_imported = 0, replaced = 0;
  /// Wall-clock seconds: planning (folder walk, sidecars, case files), reading
  /// (parsing, integration, window analysis on every core), storing (the one
  /// transaction).
  double plan_s = 0.0, read_s = 0.0, store_s = 0.0;
};

/// Plans and reads every input (nothing is stored yet): a bad input is an
/// InputError before any database is touched.
ImportResult read_import(const ImportRequest& request);

/// Stores the runs read in one transaction and fills the outcomes, notes and
/// totals.
void store_import(RunDatabase& database, ImportResult& result, const ImportPolicy& options);

/// read_import, then store_import.
ImportResult import_into(RunDatabase& database, const ImportRequest& request, const ImportPolicy& options);

}  // namespace hydrocoef
