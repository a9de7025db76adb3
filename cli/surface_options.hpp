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
  std::string normals = "auto";
  std::string body;
  std::vector<std::string> set;
  bool no_sidecar = false;
};

/// Adds the surface options to a command.
void add_surface_options(CLI::App& command, SurfaceArgs& args);

/// Options for one file: defaults, then its sidecar (unless --no-sidecar),
/// then the command line. `sidecar` receives the sidecar's path if one was read.
SurfaceRunOptions surface_options_for(const std::filesystem::path& file, const SurfaceArgs& args,
                                      std::optional<std::filesystem::path>& sidecar);

/// Splits --set NAME=VALUE into body velocity (u..r) and disturbances.
void apply_set(const std::vector<std::string>& set, RunKey& key);

/// JSON and text forms of an integration result.
nlohmann::json surface_run_json(const SurfaceRun& run);
std::string surface_run_text(const SurfaceRun& run);

}  // namespace hydrocoef::cli
