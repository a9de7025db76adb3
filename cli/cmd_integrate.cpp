// hydrocoef integrate: forces and moments of one surface export, printed and
// not stored.
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "cli/surface_options.hpp"

namespace hydrocoef::cli {
namespace {

struct IntegrateArgs {
  std::string file;
  std::string format = "auto";
  SurfaceArgs surface;
  bool json = false;
};

void run_integrate(const IntegrateArgs& args) {
  std::optional<std::filesystem::path> sidecar;
  SurfaceRunOptions options = surface_options_for(args.file, args.surface, sidecar);
  options.format = args.format;
  const SurfaceRun run = import_surface_run(args.file, options);
  if (args.json) {
    auto out = surface_run_json(run);
    out["sidecar"] = sidecar ? nlohmann::json(sidecar->string()) : nlohmann::json();
    std::cout << out.dump(2) << '\n';
    return;
  }
  std::cout << surface_run_text(run);
  if (sidecar) std::cout << "  run settings from " << sidecar->string() << '\n';
}

}  // namespace

void add_integrate_command(CLI::App& app) {
  auto args = std::make_shared<IntegrateArgs>();
  auto* command = app.add_subcommand(
      "integrate", "Integrate surface pressure and wall shear of one export into forces and moments (not stored)");
  command->add_option("file", args->file, "CFD-Post export (.csv/.txt) or VTK-family file (.vtk .vtp .vtu .vtm "
                                          ".case .cgns)")
      ->required();
  command->add_option("--format", args->format, "auto, cfdpost or vtk")->capture_default_str();
  add_surface_options(*command, args->surface);
  command->add_option("--body", args->surface.body, "Body name (for the run key shown)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args] { run_integrate(*args); });
}

}  // namespace hydrocoef::cli
