// hydrocoef integrate: forces and moments of one surface export, printed and
// not stored, with the run key its settings give. The work is
// hydrocoef::integrate_surface (include/hydrocoef/integrate.hpp); this file
// parses the options and prints the result.
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "cli/surface_options.hpp"
#include "hydrocoef/integrate.hpp"

namespace hydrocoef::cli {
namespace {

struct IntegrateArgs {
  std::string file;
  ImportOptions options;
  bool json = false;
};

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
  command->add_option("--format", args->options.format, "auto, cfdpost or vtk")->capture_default_str();
  add_surface_options(*command, args->options);
  command->add_option("--body", args->options.body, "Body name (for the run key shown)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args] {
    const SurfaceIntegration result = integrate_surface(args->file, args->options);
    std::cout << (args->json ? result.json() : result.text());
  });
}

}  // namespace hydrocoef::cli
