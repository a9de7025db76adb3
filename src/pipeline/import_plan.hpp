// What an import will read, decided before any CFD data is read: the inputs
// expanded into files and solver case folders, filtered by --include and
// --exclude, twins reduced to one, and for each the settings layers that
// apply to it (its sidecar, its manifest row, the folder sidecars up to the
// imported folder, the name pattern), in the order of precedence of
// src/pipeline/run_settings.hpp. The command line's layer and the case
// files' layer are added by the reader.
//
// Folder walks:
//   - a folder holding system/controlDict and constant/ is an OpenFOAM case:
//     it is imported as one input and not walked further;
//   - files are taken by extension: .csv .txt .tsv .dat (tables, monitors,
//     CFD-Post exports, force histories), .vtp .vtu .vtk .vtm .case .encas
//     .cgns (surface exports); sidecars, the manifest and CFX case files give
//     settings; everything else is not CFD data, and neither are files users
//     keep beside their data under a data extension: documentation (README,
//     SOURCE, NOTES, LICENSE ...), logs (log.*, *.log) and OpenFOAM
//     function-object outputs other than forces (solverInfo.dat, yPlus.dat,
//     wallShearStress.dat, residuals.dat ...). Those are skipped, all of them
//     listed in one note of the plan;
//   - a CFX solver output file (.out) with no data file of its run beside it
//     (monitors, exports) and holding the solver's wall force and moment
//     summary is a run of its own, read from that summary;
//   - --include and --exclude filter the data files first; twins and
//     partners are then paired among the files left;
//   - twins are imported once: of X.vtp, X.vtu and X.vtk in one folder the
//     first in that order; a .vtm beside the folder of the same name that
//     holds its blocks (foamToVTK's layout) gives way to the files there;
//     moment.dat beside force.dat is read with it, not on its own; a force
//     history (OpenFOAM's force.dat, forces.dat, coefficient.dat) and surface
//     exports in one folder are two readings of one run: the history is
//     taken (its mean over the steady window, with its uncertainty) unless
//     surfaces are preferred. In an OpenFOAM case folder, likewise, the
//     surface export that foamToVTK left under the case's VTK/ (its latest
//     time) is taken instead of postProcessing's forces when surfaces are
//     preferred.
// A file named on the command line is always imported, whatever the
// filters say, and so is the run of a CFX .out named on it: its monitors
// beside it, or its own wall force summary when there are none. The name
// pattern applies to inputs named on the command line as to folder
// contents, matched on the path as given.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "src/pipeline/run_settings.hpp"
#include "src/pipeline/sweep_keys.hpp"

namespace hydrocoef {

enum class InputKind {
  File,          ///< one file
  OpenFoamCase,  ///< a case folder as OpenFOAM left it
};

struct PlannedInput {
  std::filesystem::path path;
  /// The path below the imported folder, for patterns and messages ("" for
  /// an input named directly).
  std::filesystem::path relative;
  InputKind kind = InputKind::File;
  /// Layers in order of precedence, highest first: file sidecar, manifest
  /// row, folder sidecars (nearest first), case files (OpenFOAM cases), name
  /// pattern.
  std::vector<SettingsLayer> layers;
};

struct ImportPlanOptions {
  std::vector<std::string> include;  ///< globs; a file must match one (when any are given)
  std::vector<std::string> exclude;  ///< globs; a file matching one is left out
  const Manifest* manifest = nullptr;
  const NamePattern* key_pattern = nullptr;
  bool use_sidecars = true;
  bool prefer_surfaces = false;  ///< of a history and surface exports in one folder, take the surfaces
};

struct ImportPlan {
  std::vector<PlannedInput> inputs;
  std::size_t excluded = 0;  ///< files the filters left out
  /// Files of the imported folders that are not CFD data (see above),
  /// relative to their imported folder; one note lists them.
  std::vector<std::filesystem::path> skipped;
  std::vector<std::string> notes;  ///< twins, partner files, skipped files: one line each
};

/// Plans the import of files and folders. InputError naming the path for an
/// input that does not exist, a folder that yields nothing to import (with
/// the filters in the message), or a malformed sidecar.
ImportPlan plan_import(const std::vector<std::filesystem::path>& inputs, const ImportPlanOptions& options);

/// True for the names OpenFOAM gives its force histories: force.dat,
/// forces.dat, coefficient.dat and the restart names force_<time>.dat ...
bool is_force_history_name(const std::filesystem::path& file);

/// True for a folder OpenFOAM would run: system/controlDict and constant/.
bool is_openfoam_case(const std::filesystem::path& folder);

/// True for files users keep beside CFD data under a data extension that are
/// not CFD data: documentation (README*, SOURCE, NOTES, LICENSE, PROVENANCE,
/// CHANGELOG ...), logs (log.*, *.log) and OpenFOAM function-object outputs
/// other than forces (solverInfo, yPlus, wallShearStress, residuals,
/// fieldMinMax, surfaceFieldValue, volFieldValue ..., with or without a
/// restart time in the name).
bool is_not_cfd_data(const std::filesystem::path& file);

/// The surface export foamToVTK left in an OpenFOAM case folder: of
/// VTK/<name>_<time>.vtm the one of the latest time, or the one surface file
/// of its blocks' folder when it holds one. Empty when the case has none or
/// several that cannot be told apart (the reason in `why`).
std::optional<std::filesystem::path> case_surface_export(const std::filesystem::path& case_folder, std::string& why);

/// Glob match of a path below the imported folder: a pattern without '/'
/// matches the file's name, one with '/' the whole relative path ('*' then
/// also crosses folders). '?', '*' and [...] as in the shell.
bool glob_matches(const std::string& pattern, const std::filesystem::path& relative);

}  // namespace hydrocoef
