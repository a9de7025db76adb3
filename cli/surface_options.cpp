#include "cli/surface_options.hpp"

#include <sstream>

#include "cli/common.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/names.hpp"
#include "src/core/text.hpp"
#include "src/loads/symmetry.hpp"
#include "src/pipeline/given_uncertainty.hpp"

#include <cmath>

namespace hydrocoef::cli {

void add_surface_options(CLI::App& command, SurfaceArgs& args) {
  command.add_option("--location", args.locations,
                     "Patch, block, zone or [Name] to integrate (repeatable; default all)");
  command.add_option("--pressure", args.pressure, "Pressure array (default: Pressure, or OpenFOAM's p)");
  command.add_option("--shear", args.shear,
                     "Wall shear: a vector array or three comma-separated arrays; 'none' for no viscous part "
                     "(default: Wall Shear X,Y,Z or wallShearStress)");
  command.add_option("--pressure-kind", args.pressure_kind,
                     "static (Pa) or kinematic (m^2 s^-2, times --rho); default kinematic for OpenFOAM's p");
  command.add_option("--shear-convention", args.shear_convention,
                     "on-wall (fluid's shear on the wall, CFX) or on-fluid (stress on the fluid, OpenFOAM "
                     "wallShearStress); default by array name");
  command.add_option("--rho", args.rho, "Fluid density [kg m^-3]");
  command.add_option("--nu", args.nu, "Fluid kinematic viscosity [m^2 s^-1]");
  command.add_option("--p-ref", args.p_ref, "Pressure subtracted before integrating [Pa]");
  command.add_option("--ref-point", args.ref_point, "Moment reference point x,y,z [m], body axes (default 0,0,0)");
  command.add_option("--length-unit", args.length_unit, "Length unit of a file that does not say (e.g. mm)");
  command.add_option("--pressure-unit", args.pressure_unit, "Pressure unit of a file that does not say (e.g. kPa)");
  command.add_option("--axes", args.axes,
                     "Body axes in CFD axes, e.g. -x,y,-z (body x = -CFD x ...); a rotation (default x,y,z)");
  command.add_option("--origin", args.origin, "Body origin in CFD coordinates x,y,z [m] (default 0,0,0)");
  command.add_option("--flow", args.flow,
                     "Free-stream velocity in CFD axes x,y,z [m/s]: sets u,v,w to the body velocity it "
                     "stands for (the negative, in body axes)");
  command.add_option("--normals", args.normals, "auto (make outward; the default), as-given or flip");
  command.add_option("--symmetry", args.symmetry,
                     "Planes of symmetry of a half or quarter model in CFD coordinates, e.g. y=0 or y=0,z=0: the "
                     "whole body's loads");
  command.add_option("--window", args.window,
                     "Force histories: auto (the statistically steady part, MSER-5; the default), T0:T1 or last:N");
  command
      .add_option("--uncertainty", args.uncertainty,
                  "Standard uncertainty of force components, COMPONENT=VALUE (N or N m) or COMPONENT=PERCENT% of "
                  "each value, e.g. X=0.01,N=2%: stored with the runs, combined with a history's standard error, "
                  "used by weighted fits and GP surfaces")
      ->delimiter(',');
  command.add_option("--set", args.set,
                     "Run key: velocity (u v w [m/s], p q r [rad/s], body axes) or disturbance, NAME=VALUE "
                     "(repeatable)");
  command.add_flag("--at-rest", args.at_rest,
                   "The body is at rest (u = v = w = p = q = r = 0): a run whose velocity no file, sidecar or option "
                   "gives is otherwise refused");
  command.add_flag(
      "--no-sidecar", args.no_sidecar,
      "Ignore sidecar files (FILE.json beside a file, hydrocoef-run.json in its folder and the folders above)");
}

SettingsLayer command_line_settings(const SurfaceArgs& args) {
  SettingsLayer layer;
  layer.origin = SettingOrigin{SettingSource::CommandLine, "command line"};
  const auto set_text = [&](const char* name, const std::optional<std::string>& value, const char* option) {
    if (value) layer.set(name, *value, option);
  };
  const auto set_number = [&](const char* name, const std::optional<double>& value, const char* option) {
    if (!value) return;
    if (!std::isfinite(*value)) throw InputError(std::string(option) + ": expected a finite number");
    layer.set(name, *value, option);
  };
  const auto set_triple = [&](const char* name, const std::optional<std::string>& value, const char* option) {
    if (!value) return;
    const auto xyz = parse_triple(*value, option);
    layer.set(name, std::vector<double>(xyz.begin(), xyz.end()), option);
  };
  if (!args.body.empty()) layer.set("body", std::string(check_name(NameKind::Body, args.body, {}, "--body")), "--body");
  if (!args.locations.empty()) {
    for (const auto& name : args.locations) check_name(NameKind::Field, name, {}, "--location");
    layer.set("locations", args.locations, "--location");
  }
  set_text("pressure", args.pressure, "--pressure");
  if (args.shear) {
    std::vector<std::string> names;
    std::stringstream list(*args.shear);
    for (std::string name; std::getline(list, name, ',');) names.push_back(name);
    if (names.size() != 1 && names.size() != 3)
      throw InputError("--shear '" + *args.shear + "': expected one vector array, three arrays x,y,z, or none");
    layer.set("shear", names, "--shear");
  }
  set_text("pressure_kind", args.pressure_kind, "--pressure-kind");
  set_text("shear_convention", args.shear_convention, "--shear-convention");
  set_number("rho", args.rho, "--rho");
  set_number("nu", args.nu, "--nu");
  set_number("p_ref", args.p_ref, "--p-ref");
  set_triple("ref_point", args.ref_point, "--ref-point");
  set_text("length_unit", args.length_unit, "--length-unit");
  set_text("pressure_unit", args.pressure_unit, "--pressure-unit");
  if (args.axes) {
    parse_axes(*args.axes);  // refused here, naming the option, rather than later
    layer.set("axes", *args.axes, "--axes");
  }
  set_triple("origin", args.origin, "--origin");
  set_triple("flow", args.flow, "--flow");
  set_text("normals", args.normals, "--normals");
  if (args.symmetry) {
    parse_symmetry(*args.symmetry);
    layer.set("symmetry", *args.symmetry, "--symmetry");
  }
  set_text("window", args.window, "--window");
  if (!args.uncertainty.empty()) {
    const std::string text = join(args.uncertainty, ",");
    (void)parse_given_uncertainty(text, "--uncertainty");  // refused here, naming the option
    layer.set("uncertainty", text, "--uncertainty");
  }
  if (args.at_rest) layer.set("at_rest", std::string("yes"), "--at-rest");
  for (const auto& text : args.set) {
    const auto [name, value] = parse_assignment(text, "--set");
    if (velocity_index(name)) {
      layer.set(name, value, "--set");
    } else {
      check_name(NameKind::Parameter, name, {}, "--set");
      layer.set("disturbance." + name, value, "--set");
    }
  }
  return layer;
}

nlohmann::json surface_run_json(const SurfaceRun& run) {
  const auto& l = run.loads_b;
  const auto& g = l.geometry;
  const auto& key = run.batch.runs.front().key;
  return {{"file", run.batch.source.path},
          {"format", run.format},
          {"key", key_json(key)},
          {"frame", "body axes (x forward, y starboard, z down); forces on the body"},
          {"axes", run.batch.runs.front().surface->axes},
          {"reference_point", l.reference_point},
          {"force_pressure", l.force_pressure},
          {"force_viscous", l.force_viscous},
          {"force", l.force()},
          {"moment_pressure", l.moment_pressure},
          {"moment_viscous", l.moment_viscous},
          {"moment", l.moment()},
          {"area", g.area},
          {"faces", g.faces},
          {"triangles", g.triangles},
          {"quads", g.quads},
          {"polygons", g.polygons},
          {"closed", g.closed},
          {"boundary_edges", g.boundary_edges},
          {"degenerate_faces", g.degenerate_faces},
          {"signed_volume", g.signed_volume},
          {"normals_flipped", g.normals_flipped},
          {"integral_n_dA", g.integral_n_dA},
          {"integral_x_cross_n_dA", g.integral_x_cross_n_dA},
          {"pressure_array", run.pressure_array},
          {"shear_array", run.shear_array},
          {"pressure_kind", run.pressure_kind == PressureKind::Static ? "static" : "kinematic"},
          {"shear_convention", run.shear_convention == ShearConvention::OnWall ? "on-wall" : "on-fluid"},
          {"warnings", run.warnings}};
}

std::string surface_run_text(const SurfaceRun& run) {
  const auto& l = run.loads_b;
  const auto& g = l.geometry;
  std::ostringstream out;
  auto row = [&](const char* name, const Vec3& v, const char* unit) {
    out << "  " << std::left << std::setw(18) << name;
    for (const double x : v) out << std::right << std::setw(15) << significant(x, 7);
    out << "  " << unit << '\n';
  };
  // The path, array names and axes come from the file and its sidecar: one printable line each.
  out << escape::one_line(run.batch.source.path) << " (" << escape::one_line(run.format) << "; pressure '"
      << escape::one_line(run.pressure_array) << "' "
      << (run.pressure_kind == PressureKind::Static ? "static" : "kinematic") << ", shear '"
      << (run.shear_array.empty() ? "none" : escape::one_line(run.shear_array)) << "' "
      << (run.shear_convention == ShearConvention::OnWall ? "on-wall" : "on-fluid") << ")\n";
  out << "  body axes (" << escape::one_line(run.batch.runs.front().surface->axes) << "), moments about ("
      << significant(l.reference_point[0]) << ", " << significant(l.reference_point[1]) << ", "
      << significant(l.reference_point[2]) << ") m; forces on the body\n";
  out << "  " << std::setw(18) << "" << std::right << std::setw(15) << "x" << std::setw(15) << "y" << std::setw(15)
      << "z" << '\n';
  row("force pressure", l.force_pressure, "N");
  row("force viscous", l.force_viscous, "N");
  row("force", l.force(), "N  (X Y Z)");
  row("moment pressure", l.moment_pressure, "N m");
  row("moment viscous", l.moment_viscous, "N m");
  row("moment", l.moment(), "N m  (K M N)");
  out << "  surface: " << g.faces << " faces (" << g.triangles << " tri, " << g.quads << " quad, " << g.polygons
      << " poly), area " << significant(g.area, 7) << " m^2, " << (g.closed ? "closed" : "open") << " ("
      << g.boundary_edges << " boundary edges), volume " << significant(g.signed_volume, 7) << " m^3"
      << (g.normals_flipped ? ", normals flipped to outward" : "") << '\n';
  for (const auto& w : run.warnings) out << "  note: " << escape::one_line(w) << '\n';
  return out.str();
}

}  // namespace hydrocoef::cli
