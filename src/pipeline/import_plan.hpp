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
//     .cgns (surface exports); everything else (.json sidecars, READMEs) is
//     not data;
//   - twins are imported once: of X.vtp, X.vtu and X.vtk in one folder the
//     first in that order; a .vtm beside the folder of the same name that
//     holds its blocks (foamToVTK's layout) gives way to the files there;
//     moment.dat beside force.dat is read with it, not on its own; a force
//     history (OpenFOAM's force.dat, forces.dat, coefficient.dat) and surface
//     exports in one folder are two readings of one run: the history is
//     taken (its mean over the steady window, with its uncertainty) unless
//     surfaces are preferred.
// A file named on the command line is always imported, whatever the
// filters say.
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
  std::size_t excluded = 0;        ///< files the filters left out
  std::vector<std::string> notes;  ///< twins, partner files: one line each
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

/// Glob match of a path below the imported folder: a pattern without '/'
/// matches the file's name, one with '/' the whole relative path ('*' then
/// also crosses folders). '?', '*' and [...] as in the shell.
bool glob_matches(const std::string& pattern, const std::filesystem::path& relative);

}  // namespace hydrocoef
