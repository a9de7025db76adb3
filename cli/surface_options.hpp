// Command-line options shared by the commands that read surface exports
// (integrate, import): which arrays, their kind and units, frames, and the
// run key. Registered once here so both commands spell them the same way.
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "src/pipeline/run_settings.hpp"
#include "src/pipeline/surface_run.hpp"

namespace hydrocoef::cli {

struct SurfaceArgs {
  std::vector<std::string> locations;
  std::optional<std::string> pressure;
  std::optional<std::string> shear;
  std::optional<std::string> pressure_kind;
  std::optional<std::string> shear_convention;
  std::optional<double> rho;
  std::optional<double> nu;
  std::optional<double> p_ref;
  std::optional<std::string> ref_point;
  std::optional<std::string> length_unit;
  std::optional<std::string> pressure_unit;
  std::optional<std::string> axes;
  std::optional<std::string> origin;
  std::optional<std::string> flow;
  std::optional<std::string> normals;
  std::optional<std::string> symmetry;
  std::optional<std::string> window;
  std::string body;
  std::vector<std::string> set;
  std::vector<std::string> uncertainty;  ///< "X=0.01", "N=2%"
  bool no_sidecar = false;
  bool at_rest = false;  ///< the body is at rest: no velocity setting is expected
};

/// Adds the surface options to a command.
void add_surface_options(CLI::App& command, SurfaceArgs& args);

/// The command line's settings layer (src/pipeline/run_settings.hpp): each
/// option given becomes the setting of the same meaning, remembered as coming
/// from that option. InputError for a malformed value, naming the option.
SettingsLayer command_line_settings(const SurfaceArgs& args);

/// JSON and text forms of an integration result.
nlohmann::json surface_run_json(const SurfaceRun& run);
std::string surface_run_text(const SurfaceRun& run);

}  // namespace hydrocoef::cli
