// hydrocoef integrate: forces and moments of one surface export, printed and
// not stored, with the run key its settings give.
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "cli/surface_options.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/pipeline/import_files.hpp"

namespace hydrocoef::cli {
namespace {

struct IntegrateArgs {
  std::string file;
  std::string format = "auto";
  SurfaceArgs surface;
  bool json = false;
};

void run_integrate(const IntegrateArgs& args) {
  ImportRequest request;
  request.inputs = {args.file};
  request.command_line = command_line_settings(args.surface);
  request.format = args.format;
  request.plan.use_sidecars = !args.surface.no_sidecar;
  request.require_velocity = false;  // nothing is stored: the key is shown as the settings give it
  const ImportPlan plan = plan_request(request);
  const ImportedInput input = read_input(plan.inputs.front(), request);
  if (!input.surface)
    throw InputError(SourceLocation{args.file}, "is a " + input.format +
                                                    ", not a surface export; expected a CFD-Post "
                                                    "export or a VTK-family file (import reads the others)");
  const auto& key = input.surface->batch.runs.front().key;
  if (args.json) {
    auto out = surface_run_json(*input.surface);
    out["key"] = key_json(key);
    out["settings"] = nlohmann::json::parse(input.batch.source.settings.empty() ? "{}" : input.batch.source.settings);
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  std::cout << surface_run_text(*input.surface);
  std::cout << "  run key: " << escape::one_line(describe(key)) << '\n';
  for (const auto& [name, setting] : input.settings.values)
    if (setting.origin.source != SettingSource::CommandLine)
      std::cout << "  setting " << escape::one_line(name) << " from " << escape::one_line(setting.origin.where) << '\n';
}

}  // namespace

void add_integrate_command(CLI::App& app) {
  auto args = std::make_shared<IntegrateArgs>();
  auto* command = app.add_subcommand(
      "integrate", "Integrate surface pressure and wall shear of one export into forces and moments (not stored)");
  command
      ->add_option("file", args->file,
                   "CFD-Post export (.csv/.txt) or VTK-family file (.vtk .vtp .vtu .vtm "
                   ".case .cgns)")
      ->required();
  command->add_option("--format", args->format, "auto, cfdpost or vtk")->capture_default_str();
  add_surface_options(*command, args->surface);
  command->add_option("--body", args->surface.body, "Body name (for the run key shown)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args] { run_integrate(*args); });
}

}  // namespace hydrocoef::cli
