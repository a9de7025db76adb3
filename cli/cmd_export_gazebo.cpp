// hydrocoef export-gazebo: a body's stored damping-law fits and an added-mass
// matrix as the hydrodynamics parameters of Gazebo's underwater plugins
// (uuv_simulator's fossen model or gz-sim's Hydrodynamics system).
#include <iostream>
#include <memory>
#include <tuple>

#include "cli/common.hpp"
#include "cli/gazebo_options.hpp"
#include "cli/gazebo_output.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/run_selection.hpp"
#include "src/export/export.hpp"
#include "src/export/gazebo_export.hpp"
#include "src/store/database.hpp"

namespace hydrocoef::cli {
namespace {

void run_export_gazebo(const GazeboArgs& args, const GlobalOptions& global) {
  GazeboWriteOptions options;
  options.flavor = parse_gazebo_flavor(args.flavor);
  if (options.flavor == GazeboFlavor::Uuv && (args.link || args.link_axes)) {
    throw InputError(std::string(args.link ? "--link" : "--link-axes") +
                     " applies to --flavor gz only; expected it with gz (uuv_simulator assumes an FLU link and "
                     "converts to FRD itself)");
  }
  if (args.link) options.link_name = *args.link;
  if (args.link_axes) options.link_axes = parse_gazebo_link_axes(*args.link_axes);

  GazeboRequest request;
  request.body = args.body;
  for (const std::string& choice : args.fits) request.fits.push_back(parse_text_assignment(choice, "--fit"));
  request.drop_constant = args.drop_constant;
  request.allow_missing = args.allow_missing;
  request.allow_unphysical = args.allow_unphysical;
  request.linearize_at = args.linearize_at;
  std::tie(request.added_mass, request.added_mass_source) = added_mass_from(args, global.database);

  RunDatabase database(global.database, RunDatabase::OpenMode::ReadOnly);
  // --where picks the fits made from that selection of runs (a filtered fit
  // or one level of a per-level fit), e.g. the model at one current.
  const auto fits =
      fits_made_from(database, args.body, parse_selection(args.selection.where, args.selection.exclude_runs));
  const GazeboCoefficients coefficients = gazebo_coefficients(fits, request);
  const std::vector<GazeboElement> elements = gazebo_elements(coefficients, options);
  write_gazebo(coefficients, options, args.output);

  print_gazebo_export(coefficients, elements, options, args.output, args.json);
}

}  // namespace

void add_export_gazebo_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<GazeboArgs>();
  auto* command = app.add_subcommand(
      "export-gazebo",
      "Write a body's damping-law fits and an added-mass matrix as Gazebo hydrodynamics parameters: uuv "
      "(uuv_simulator <hydrodynamic_model> fossen) or gz (gz-sim Hydrodynamics plugin). Laws a x + b x|x| only; "
      "on-body SNAME signs; a refused export writes nothing");
  command->add_option("body", args->body, "Body whose fits are exported")->required();
  command->add_option("--flavor", args->flavor, "uuv or gz")->required();
  command->add_option("-o,--output", args->output, "File to write (written whole or not at all)")->required();
  command->add_option("--fit", args->fits,
                      "DOF=FITNAME: the law for a force component (repeatable; several per DOF when in different "
                      "velocities, e.g. N=... in r and N=... in v). Default: the body's single fit of each DOF in "
                      "its own velocity");
  command->add_option("--added-mass", args->added_mass, "Diagonal added mass d1,...,d6 (kg x3, kg m^2 x3), positive");
  command->add_option("--added-mass-matrix", args->added_mass_matrix,
                      "File of 36 numbers, the 6x6 added mass row by row (kg, kg m, kg m^2; '#' comments)");
  command->add_option("--sphere-radius", args->sphere_radius,
                      "Added mass of a sphere of this radius [m]: 2/3 pi rho R^3 in each translation (needs --rho "
                      "and --added-mass-rotation)");
  command->add_option("--rho", args->rho, "Fluid density for --sphere-radius [kg/m^3]");
  command->add_option("--added-mass-from-database", args->added_mass_from_database,
                      "The added mass assembled from BODY's stored forced-oscillation runs (hydrocoef pmm; see "
                      "hydrocoef added-mass)");
  command->add_option("--same", args->same, "With --added-mass-from-database: DOF=DOF for a DOF no run moves");
  command->add_option("--added-mass-period", args->added_mass_period,
                      "With --added-mass-from-database: the period [s] of the runs to use, when they have several");
  command->add_option("--zero", args->zero, "With --added-mass-from-database: a DOF whose added mass is zero")
      ->delimiter(',');
  command->add_option("--added-mass-rotation", args->rotation,
                      "With --sphere-radius: rotational added mass a,b,c [kg m^2] (a sphere has none)");
  command->add_flag("--drop-constant", args->drop_constant,
                    "Drop a law's constant term '1' (a CFD bias) instead of refusing; reported in the output");
  command->add_flag("--allow-unphysical", args->allow_unphysical,
                    "Write laws that feed energy into the motion (a positive on-body damping coefficient) instead of "
                    "refusing them");
  command->add_flag("--allow-missing", args->allow_missing,
                    "Write 0 for a DOF without a law in its own velocity instead of refusing");
  command->add_option("--linearize-at", args->linearize_at,
                      "Forward speed U0 [m/s]: replace each b x|x| by its slope at (U0,0,0,0,0,0), i.e. add 2 b |U0| "
                      "to the linear term of laws in u; quadratic terms become 0");
  command->add_option("--link", args->link, "gz: <link_name> of the plugin (default base_link)");
  command->add_option("--link-axes", args->link_axes, "gz: axes of that link, flu (default) or frd");
  command->add_option("--where", args->selection.where,
                      "Use only the fits made from this selection of runs (as 'hydrocoef fits' shows it), e.g. "
                      "current_v=0.05 for the model at one current; repeatable, as fit --where");
  command->add_option("--exclude-run", args->selection.exclude_runs,
                      "With --where: the fits made with this run left out (repeatable)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_export_gazebo(*args, global); });
}

}  // namespace hydrocoef::cli
