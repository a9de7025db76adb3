// hydrocoef derivatives export: stored derivative models as a CSV or JSON
// derivative set (dimensional, prime, bis or MMG), gz-sim Hydrodynamics
// parameters with cross terms, or a MATLAB function in the form of Fossen's
// MSS vessel models. The library reads, converts, writes and reports
// (hydrocoef::export_derivatives); this command parses, calls and prints.
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/exports.hpp"

namespace hydrocoef::cli {

void add_derivatives_export(CLI::App& derivatives, const GlobalOptions& global) {
  struct Args {
    hydrocoef::DerivativeExportOptions options;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  auto& o = args->options;
  auto* command = derivatives.add_subcommand(
      "export",
      "Write stored models for another tool: csv or json (one model; dimensional, prime, bis or mmg), gazebo (gz-sim "
      "Hydrodynamics, models of one body, one per output, cross terms) or matlab (a function NAME.m in the form of "
      "Fossen's MSS vessel models); SNAME signs on the body; a refused export writes nothing");
  command->add_option("names", o.names, "The stored models (hydrocoef derivatives list)")->required();
  command->add_option("--format", o.format, "csv, json, gazebo or matlab")->required();
  command->add_option("-o,--output", o.output, "File to write (written whole or not at all; matlab: NAME.m)")
      ->required();
  command->add_option("--form", o.form, "csv, json: dimensional (SI), prime (SNAME), bis (Norrbin) or mmg")
      ->capture_default_str();
  command->add_option("--length", o.length, "Reference length L [m] (prime, bis, mmg)");
  command->add_option("--speed", o.speed, "Reference speed U [m/s] (prime, mmg)");
  command->add_option("--density", o.density, "Water density rho [kg/m^3] (prime, mmg)");
  command->add_option("--draft", o.draft, "Draft d [m] (mmg)");
  command->add_option("--mass", o.mass, "Mass m [kg] (bis; else rho times --volume)");
  command->add_option("--volume", o.volume, "Displaced volume [m^3] (bis without --mass)");
  command->add_option("--gravity", o.gravity, "Acceleration of gravity g [m/s^2] (bis)")->capture_default_str();
  command->add_option("--link", o.link, "gazebo: <link_name> of the plugin (default base_link)");
  command->add_option("--link-axes", o.link_axes, "gazebo: axes of that link, flu (default) or frd");
  command->add_flag("--drop-unrepresentable", o.drop_unrepresentable,
                    "gazebo: leave out (and list) terms gz-sim cannot hold instead of refusing");
  command->add_option("--added-mass", o.added_mass,
                      "gazebo: diagonal added mass d1,...,d6 (kg x3, kg m^2 x3), positive (default 0, noted)");
  command->add_option("--added-mass-matrix", o.added_mass_matrix,
                      "gazebo: file of 36 numbers, the 6x6 added mass row by row (kg, kg m, kg m^2; '#' comments)");
  command->add_option("--mass-diagonal", o.mass_diagonal,
                      "matlab: diagonal of M = M_RB + M_A, d1,...,d6 (kg x3, kg m^2 x3)");
  command->add_option("--mass-matrix", o.mass_matrix,
                      "matlab: file of 36 numbers, M = M_RB + M_A row by row (kg, kg m, kg m^2; '#' comments)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] {
    args->options.validate();
    const auto database = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
    const auto result = hydrocoef::export_derivatives(database, args->options);
    std::cout << (args->json ? result.json() : result.text());
  });
}

}  // namespace hydrocoef::cli
