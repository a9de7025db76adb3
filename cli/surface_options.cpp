#include "cli/surface_options.hpp"

#include <sstream>

#include "cli/common.hpp"
#include "src/core/error.hpp"

namespace hydrocoef::cli {

void add_surface_options(CLI::App& command, SurfaceArgs& args) {
  command.add_option("--location", args.locations, "Patch, block, zone or [Name] to integrate (repeatable; default all)");
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
  command.add_option("--normals", args.normals, "auto (make outward), as-given or flip")->capture_default_str();
  command.add_option("--set", args.set,
                     "Run key: velocity (u v w [m/s], p q r [rad/s], body axes) or disturbance, NAME=VALUE "
                     "(repeatable)");
  command.add_flag("--no-sidecar", args.no_sidecar, "Ignore FILE.json / hydrocoef-run.json beside the file");
}

void apply_set(const std::vector<std::string>& set, RunKey& key) {
  for (const auto& text : set) {
    const auto [name, value] = parse_assignment(text, "--set");
    if (const auto i = velocity_index(name)) key.nu_b[*i] = value;
    else key.disturbances[name] = value;
  }
}

SurfaceRunOptions surface_options_for(const std::filesystem::path& file, const SurfaceArgs& args,
                                      std::optional<std::filesystem::path>& sidecar) {
  SurfaceRunOptions options;
  options.key.body = "vehicle";
  if (!args.no_sidecar) sidecar = apply_sidecar(file, options);
  if (!args.body.empty()) options.key.body = args.body;
  options.locations = args.locations;
  options.pressure = args.pressure;
  if (args.shear) {
    options.shear.clear();
    std::stringstream names(*args.shear);
    for (std::string name; std::getline(names, name, ',');) options.shear.push_back(name);
    if (options.shear.size() != 1 && options.shear.size() != 3)
      throw InputError("--shear '" + *args.shear + "': expected one vector array, three arrays x,y,z, or none");
  }
  if (args.pressure_kind) {
    if (*args.pressure_kind == "static") options.pressure_kind = PressureKind::Static;
    else if (*args.pressure_kind == "kinematic") options.pressure_kind = PressureKind::Kinematic;
    else throw InputError("--pressure-kind '" + *args.pressure_kind + "': expected static or kinematic");
  }
  if (args.shear_convention) {
    if (*args.shear_convention == "on-wall") options.shear_convention = ShearConvention::OnWall;
    else if (*args.shear_convention == "on-fluid") options.shear_convention = ShearConvention::OnFluid;
    else throw InputError("--shear-convention '" + *args.shear_convention + "': expected on-wall or on-fluid");
  }
  if (args.rho) options.density = *args.rho;
  if (args.nu) options.kinematic_viscosity = *args.nu;
  if (args.p_ref) options.reference_pressure = *args.p_ref;
  if (args.ref_point) options.reference_point_b = parse_triple(*args.ref_point, "--ref-point");
  options.length_unit = args.length_unit;
  options.pressure_unit = args.pressure_unit;
  if (args.axes) {
    const Vec3 origin = options.frame.origin_cfd;
    options.frame = parse_axes(*args.axes);
    options.frame.origin_cfd = origin;
  }
  if (args.origin) options.frame.origin_cfd = parse_triple(*args.origin, "--origin");
  if (args.flow) {
    const Vec3 flow_b = options.frame.vector_to_body(parse_triple(*args.flow, "--flow"));
    for (std::size_t i = 0; i < 3; ++i) options.key.nu_b[i] = flow_b[i] == 0.0 ? 0.0 : -flow_b[i];
  }
  if (args.normals == "auto") options.normals = NormalPolicy::Auto;
  else if (args.normals == "as-given") options.normals = NormalPolicy::AsGiven;
  else if (args.normals == "flip") options.normals = NormalPolicy::Flip;
  else throw InputError("--normals '" + args.normals + "': expected auto, as-given or flip");
  apply_set(args.set, options.key);
  return options;
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
  out << run.batch.source.path << " (" << run.format << "; pressure '" << run.pressure_array << "' "
      << (run.pressure_kind == PressureKind::Static ? "static" : "kinematic") << ", shear '"
      << (run.shear_array.empty() ? "none" : run.shear_array) << "' "
      << (run.shear_convention == ShearConvention::OnWall ? "on-wall" : "on-fluid") << ")\n";
  out << "  body axes (" << run.batch.runs.front().surface->axes << "), moments about (" << significant(l.reference_point[0])
      << ", " << significant(l.reference_point[1]) << ", " << significant(l.reference_point[2])
      << ") m; forces on the body\n";
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
  for (const auto& w : run.warnings) out << "  note: " << w << '\n';
  return out.str();
}

}  // namespace hydrocoef::cli
