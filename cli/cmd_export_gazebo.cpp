// hydrocoef export-gazebo: a body's stored damping-law fits and an added-mass
// matrix as the hydrodynamics parameters of Gazebo's underwater plugins
// (uuv_simulator's fossen model or gz-sim's Hydrodynamics system).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <memory>
#include <tuple>

#include "cli/common.hpp"
#include "cli/gazebo_output.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/run_selection.hpp"
#include "src/core/text.hpp"
#include "src/dynamics/rigid_body.hpp"
#include "src/export/export.hpp"
#include "src/export/gazebo_export.hpp"
#include "src/store/database.hpp"

namespace hydrocoef::cli {
namespace {

struct GazeboArgs {
  std::string body;
  std::string flavor;
  std::string output;
  std::vector<std::string> fits;
  std::optional<std::string> added_mass;
  std::optional<std::string> added_mass_matrix;
  std::optional<double> sphere_radius;
  std::optional<double> rho;
  std::optional<std::string> rotation;
  bool drop_constant = false;
  bool allow_missing = false;
  bool allow_unphysical = false;
  std::optional<double> linearize_at;
  std::optional<std::string> link;
  std::optional<std::string> link_axes;
  SelectionArgs selection;
  bool json = false;
};

std::vector<double> parse_numbers(const std::string& text, std::size_t count, const std::string& option,
                                  const std::string& what) {
  std::vector<double> out;
  for (const std::string_view item : split(text, ',')) {
    double value = 0.0;
    const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), value);
    if (item.empty() || ec != std::errc() || end != item.data() + item.size() || !std::isfinite(value))
      throw InputError(option + " '" + text + "': found '" + std::string(item) + "', expected " + what);
    out.push_back(value);
  }
  if (out.size() != count)
    throw InputError(option + " '" + text + "': " + std::to_string(out.size()) + " numbers; expected " + what);
  return out;
}

// The added-mass matrix from exactly one of the three ways to give it.
std::pair<Matrix6, std::string> added_mass_from(const GazeboArgs& args) {
  const int sources = int(args.added_mass.has_value()) + int(args.added_mass_matrix.has_value()) +
                      int(args.sphere_radius.has_value());
  if (sources != 1) {
    throw InputError(std::string(sources == 0 ? "no added mass given" : "more than one added mass given") +
                     "; expected exactly one of --added-mass d1,...,d6, --added-mass-matrix FILE or --sphere-radius "
                     "R --rho RHO --added-mass-rotation a,b,c");
  }
  if (args.rho && !args.sphere_radius) throw InputError("--rho applies to --sphere-radius only; expected both");
  if (args.rotation && !args.sphere_radius)
    throw InputError("--added-mass-rotation applies to --sphere-radius only; expected both (or give the whole "
                     "diagonal with --added-mass)");
  if (args.added_mass) {
    const auto d = parse_numbers(*args.added_mass, 6, "--added-mass",
                                 "six numbers Xu' Yv' Zw' (kg) Kp' Mq' Nr' (kg m^2), comma-separated");
    return {added_mass_diagonal({d[0], d[1], d[2], d[3], d[4], d[5]}), "diagonal " + *args.added_mass +
                                                                           " (kg x3, kg m^2 x3)"};
  }
  if (args.added_mass_matrix) {
    return {read_added_mass_matrix(*args.added_mass_matrix),
            "6x6 matrix from '" + *args.added_mass_matrix + "' (kg, kg m, kg m^2)"};
  }
  if (!args.rho) throw InputError("--sphere-radius needs --rho RHO (fluid density, kg/m^3)");
  std::optional<Vector3> rotation;
  std::string rotation_text;
  if (args.rotation) {
    const auto r = parse_numbers(*args.rotation, 3, "--added-mass-rotation", "three numbers a,b,c in kg m^2");
    rotation = Vector3(r[0], r[1], r[2]);
    rotation_text = ", rotation " + *args.rotation + " kg m^2 as given";
  }
  const Matrix6 ma = sphere_added_mass(*args.rho, *args.sphere_radius, rotation);
  return {ma, "sphere of radius " + shortest_number(*args.sphere_radius) + " m in fluid of density " +
                  shortest_number(*args.rho) + " kg/m^3: 2/3 pi rho R^3 = " + significant(ma(0, 0)) +
                  " kg in each translation" + rotation_text};
}

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
  std::tie(request.added_mass, request.added_mass_source) = added_mass_from(args);

  Database database(global.database, Database::OpenMode::ReadOnly);
  // --where picks the fits made from that selection of runs (a filtered fit
  // or one level of a per-level fit), e.g. the model at one current.
  const auto fits = fits_made_from(database, args.body, parse_selection(args.selection.where, args.selection.exclude_runs));
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
