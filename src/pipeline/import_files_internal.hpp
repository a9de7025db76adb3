// What the files of the import's reading (src/pipeline/import_files.hpp)
// share, not public: how one input's settings are applied, and the readers
// of force histories and CFX wall force summaries. The files:
//   input_format.cpp       the format an input is read as
//   input_settings.cpp     one input's settings as its reader applies them
//   history_input.cpp      a force history (OpenFOAM, CFX monitor, CSV) into
//                          body axes, and averaged into a run
//   cfx_summary_input.cpp  a CFX solver output's wall force summary into a run
//   read_input.cpp         one input read by its format's reader; every input
//                          on a pool of threads
//   import_files.cpp       a whole import: plan, read, check, store
#pragma once

#include <string>
#include <vector>

#include "src/core/run.hpp"
#include "src/history/force_history.hpp"
#include "src/pipeline/import_files.hpp"
#include "src/pipeline/run_settings.hpp"

namespace hydrocoef::reading {

/// One input's settings merged by precedence (the command line first, then
/// the input's own layers), its free stream checked as stated
/// (check_flow_stated).
RunSettings input_settings(const PlannedInput& input, const ImportRequest& request);

/// Refuses (or notes) settings an importer cannot apply: refused when the
/// user gave them for this file, noted when a shared folder sidecar did.
void settings_not_applicable(const RunSettings& settings, const std::vector<std::string>& names,
                             const std::string& what, std::vector<std::string>& notes);

/// A CFX inlet with a Normal Speed states the free stream's size, not its
/// direction: the run's velocity must come from another setting, and its
/// size is compared with the speed.
void check_flow_speed(const RunSettings& settings, const RunKey& key, const std::filesystem::path& file,
                      std::vector<std::string>& notes);

/// A case that states no free stream (a pressure-driven CFX case) or only
/// its size (a CFX inlet's Normal Speed) needs the run's velocity from
/// another source; checked once the settings are merged, so that the command
/// line, a sidecar, a manifest row or the name pattern completes the case.
void check_flow_stated(const RunSettings& settings, const std::filesystem::path& file);

Fluid fluid_of(const RunSettings& settings);
SignConvention sign_of(const RunSettings& settings);

/// The batch's settings as recorded with its import: their provenance, the
/// key that tells a re-import with other settings, the file's resolved path.
void record_settings(ImportBatch& batch, const RunSettings& settings, const std::string& format,
                     const std::filesystem::path& path);

/// A history's samples turned into the run's frame: moments about the
/// reference point, the mirror images of a half or quarter model added, then
/// rotated into body axes.
ForceHistory history_in_body_axes(ForceHistory history, const RunSettings& settings, const FrameTransform& frame,
                                  const Vec3& reference_point_b, std::vector<std::string>& notes);

/// A force-history input (format openfoam-forces, openfoam-case,
/// force-history or monitor) read, brought into body axes and averaged over
/// its steady window into one run.
ImportedInput read_history(const PlannedInput& input, const std::string& format, RunSettings settings,
                           const ImportRequest& request);

/// A CFX run from the wall force summary of its solver output (format cfx-out).
ImportedInput read_cfx_summary(const PlannedInput& input, RunSettings settings, const ImportRequest& request);

}  // namespace hydrocoef::reading
