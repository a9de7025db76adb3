// The added mass export-gazebo is given (cli/gazebo_options.hpp).
#include "cli/gazebo_options.hpp"

#include "cli/pmm_output.hpp"
#include "src/pmm/added_mass_assembly.hpp"

#include <charconv>
#include <cmath>

#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/core/text.hpp"
#include "src/dynamics/rigid_body.hpp"
#include "src/export/export.hpp"
#include "src/export/gazebo_export.hpp"

namespace hydrocoef::cli {
namespace {

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

}  // namespace

std::pair<Matrix6, std::string> added_mass_from(const GazeboArgs& args, const std::string& database) {
  const int sources = int(args.added_mass.has_value()) + int(args.added_mass_matrix.has_value()) +
                      int(args.sphere_radius.has_value()) + int(args.added_mass_from_database.has_value());
  if (sources != 1) {
    throw InputError(std::string(sources == 0 ? "no added mass given" : "more than one added mass given") +
                     "; expected exactly one of --added-mass d1,...,d6, --added-mass-matrix FILE, --sphere-radius "
                     "R --rho RHO --added-mass-rotation a,b,c or --added-mass-from-database BODY");
  }
  if ((!args.same.empty() || !args.zero.empty() || args.added_mass_period) && !args.added_mass_from_database)
    throw InputError(
        "--same, --zero and --added-mass-period apply to --added-mass-from-database only; expected it with them");
  if (args.added_mass_from_database) {
    RunDatabase db(database, RunDatabase::OpenMode::ReadOnly);
    AddedMassOptions options = parse_added_mass_options(args.same, args.zero);
    options.period = args.added_mass_period;
    const AddedMassAssembly assembly = assemble_added_mass(
        *args.added_mass_from_database, db.pmm_records(*args.added_mass_from_database, false), options);
    if (!assembly.missing.empty()) {
      std::string list;
      for (const auto& m : assembly.missing) list += (list.empty() ? "" : "; ") + m;
      throw InputError("--added-mass-from-database " + printable_text(*args.added_mass_from_database, 80) +
                       ": the stored runs lack " + list + "; expected runs of those DOFs, or --same/--zero for them");
    }
    return {assembly.added_mass, "assembled from " + std::to_string(assembly.records) +
                                     " forced-oscillation runs of body '" + *args.added_mass_from_database + "'"};
  }
  if (args.rho && !args.sphere_radius) throw InputError("--rho applies to --sphere-radius only; expected both");
  if (args.rotation && !args.sphere_radius)
    throw InputError(
        "--added-mass-rotation applies to --sphere-radius only; expected both (or give the whole "
        "diagonal with --added-mass)");
  if (args.added_mass) {
    const auto d = parse_numbers(*args.added_mass, 6, "--added-mass",
                                 "six numbers Xu' Yv' Zw' (kg) Kp' Mq' Nr' (kg m^2), comma-separated");
    return {added_mass_diagonal({d[0], d[1], d[2], d[3], d[4], d[5]}),
            "diagonal " + *args.added_mass + " (kg x3, kg m^2 x3)"};
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

}  // namespace hydrocoef::cli
