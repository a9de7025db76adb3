// The command-line options of the commands that read surface exports and
// force histories (integrate, import): which arrays, their kind and units,
// frames, the run key. Registered once here, into the import's options
// (include/hydrocoef/database.hpp: ImportOptions), which check themselves.
#include "cli/surface_options.hpp"

namespace hydrocoef::cli {

void add_surface_options(CLI::App& command, ImportOptions& args) {
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
  command.add_flag_callback(
      "--no-sidecar", [&args] { args.use_sidecars = false; },
      "Ignore sidecar files (FILE.json beside a file, hydrocoef-run.json in its folder and the folders above)");
}

}  // namespace hydrocoef::cli
