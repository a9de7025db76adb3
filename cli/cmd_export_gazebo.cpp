// hydrocoef export-gazebo: a body's stored damping-law fits and an added-mass
// matrix as the hydrodynamics parameters of Gazebo's underwater plugins
// (uuv_simulator's fossen model or gz-sim's Hydrodynamics system). The work
// and the printing are the library's (hydrocoef::export_gazebo).
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/exports.hpp"

namespace hydrocoef::cli {
namespace {

struct GazeboArgs {
  hydrocoef::GazeboExportOptions options;
  bool json = false;
};

void run_export_gazebo(const GazeboArgs& args, const GlobalOptions& global) {
  args.options.validate();
  const auto db = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
  const auto result = hydrocoef::export_gazebo(db, args.options);
  std::cout << (args.json ? result.json() : result.text());
}

}  // namespace

void add_export_gazebo_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<GazeboArgs>();
  auto& o = args->options;
  auto* command = app.add_subcommand(
      "export-gazebo",
      "Write a body's damping-law fits and an added-mass matrix as Gazebo hydrodynamics parameters: uuv "
      "(uuv_simulator <hydrodynamic_model> fossen) or gz (gz-sim Hydrodynamics plugin). Laws a x + b x|x| only; "
      "on-body SNAME signs; a refused export writes nothing");
  command->add_option("body", o.body, "Body whose fits are exported")->required();
  command->add_option("--flavor", o.flavor, "uuv or gz")->required();
  command->add_option("-o,--output", o.output, "File to write (written whole or not at all)")->required();
  command->add_option("--fit", o.fits,
                      "DOF=FITNAME: the law for a force component (repeatable; several per DOF when in different "
                      "velocities, e.g. N=... in r and N=... in v). Default: the body's single fit of each DOF in "
                      "its own velocity");
  command->add_option("--added-mass", o.added_mass, "Diagonal added mass d1,...,d6 (kg x3, kg m^2 x3), positive");
  command->add_option("--added-mass-matrix", o.added_mass_matrix,
                      "File of 36 numbers, the 6x6 added mass row by row (kg, kg m, kg m^2; '#' comments)");
  command->add_option("--sphere-radius", o.sphere_radius,
                      "Added mass of a sphere of this radius [m]: 2/3 pi rho R^3 in each translation (needs --rho "
                      "and --added-mass-rotation)");
  command->add_option("--rho", o.rho, "Fluid density for --sphere-radius [kg/m^3]");
  command->add_option("--added-mass-from-database", o.added_mass_from_database,
                      "The added mass assembled from BODY's stored forced-oscillation runs (hydrocoef pmm; see "
                      "hydrocoef added-mass)");
  command->add_option("--same", o.same, "With --added-mass-from-database: DOF=DOF for a DOF no run moves");
  command->add_option("--added-mass-period", o.added_mass_period,
                      "With --added-mass-from-database: the period [s] of the runs to use, when they have several");
  command->add_option("--zero", o.zero, "With --added-mass-from-database: a DOF whose added mass is zero")
      ->delimiter(',');
  command->add_option("--added-mass-rotation", o.added_mass_rotation,
                      "With --sphere-radius: rotational added mass a,b,c [kg m^2] (a sphere has none)");
  command->add_flag("--drop-constant", o.drop_constant,
                    "Drop a law's constant term '1' (a CFD bias) instead of refusing; reported in the output");
  command->add_flag("--allow-unphysical", o.allow_unphysical,
                    "Write laws that feed energy into the motion (a positive on-body damping coefficient) instead of "
                    "refusing them");
  command->add_flag("--allow-missing", o.allow_missing,
                    "Write 0 for a DOF without a law in its own velocity instead of refusing");
  command->add_option("--linearize-at", o.linearize_at,
                      "Forward speed U0 [m/s]: replace each b x|x| by its slope at (U0,0,0,0,0,0), i.e. add 2 b |U0| "
                      "to the linear term of laws in u; quadratic terms become 0");
  command->add_option("--link", o.link, "gz: <link_name> of the plugin (default base_link)");
  command->add_option("--link-axes", o.link_axes, "gz: axes of that link, flu (default) or frd");
  command->add_option("--where", o.where,
                      "Use only the fits made from this selection of runs (as 'hydrocoef fits' shows it), e.g. "
                      "current_v=0.05 for the model at one current; repeatable, as fit --where");
  command->add_option("--exclude-run", o.exclude_runs,
                      "With --where: the fits made with this run left out (repeatable)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_export_gazebo(*args, global); });
}

}  // namespace hydrocoef::cli
