// integrate_surface (include/hydrocoef/integrate.hpp): `hydrocoef integrate`
// as a library call. The file is planned and read as an import reads it
// (src/pipeline/import_files), with the command line's settings layer of the
// import's options, and nothing is stored: the key is shown as the settings
// give it.
#include "src/api/internal.hpp"

#include <iomanip>
#include <sstream>

#include "hydrocoef/integrate.hpp"
#include "src/api/records_report.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef {
inline namespace api {

struct SurfaceIntegration::Access {
  static void set(SurfaceIntegration& s, std::string text, std::string json) {
    s.text_ = std::move(text);
    s.json_ = std::move(json);
  }
};

namespace {

/// The forces, moments and surface of an integration, with the run key and
/// the settings that did not come from the options, as `integrate` prints them.
std::string integration_text(const SurfaceRun& run, const ImportedInput& input) {
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
  out << "  run key: " << escape::one_line(describe(run.batch.runs.front().key)) << '\n';
  for (const auto& [name, setting] : input.settings.values)
    if (setting.origin.source != SettingSource::CommandLine)
      out << "  setting " << escape::one_line(name) << " from " << escape::one_line(setting.origin.where) << '\n';
  return out.str();
}

}  // namespace

std::string SurfaceIntegration::text() const { return text_; }
std::string SurfaceIntegration::json() const { return json_; }

SurfaceIntegration integrate_surface(const std::string& file, const ImportOptions& options) {
  ImportRequest request;
  request.inputs = {file};
  request.command_line = command_line_layer(options);  // validates the options
  request.format = options.format;
  request.plan.use_sidecars = options.use_sidecars;
  request.require_velocity = false;  // nothing is stored: the key is shown as the settings give it
  const ImportPlan plan = plan_request(request);
  const ImportedInput input = read_input(plan.inputs.front(), request);
  if (!input.surface)
    throw InputError(SourceLocation{file}, "is a " + input.format +
                                               ", not a surface export; expected a CFD-Post "
                                               "export or a VTK-family file (import reads the others)");
  const SurfaceRun& run = *input.surface;
  const auto& l = run.loads_b;
  SurfaceIntegration out;
  out.file = run.batch.source.path;
  out.format = run.format;
  out.force = l.force();
  out.force_pressure = l.force_pressure;
  out.force_viscous = l.force_viscous;
  out.moment = l.moment();
  out.moment_pressure = l.moment_pressure;
  out.moment_viscous = l.moment_viscous;
  out.reference_point = l.reference_point;
  out.area = l.geometry.area;
  out.signed_volume = l.geometry.signed_volume;
  out.faces = l.geometry.faces;
  out.closed = l.geometry.closed;
  out.warnings = run.warnings;
  SurfaceIntegration::Access::set(out, integration_text(run, input), records::surface_run_json_text(run, input));
  return out;
}

}  // namespace api
}  // namespace hydrocoef
