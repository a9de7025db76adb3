#include "src/pipeline/surface_run.hpp"

#include <cmath>
#include <cstdio>

#include <algorithm>
#include <fstream>
#include <future>
#include <mutex>

#include "importers/cfdpost_export.hpp"
#include "importers/cfx_monitor.hpp"
#include "importers/vtk_surface.hpp"
#include "src/core/error.hpp"
#include "src/core/names.hpp"
#include "src/core/source_file.hpp"
#include "src/core/text.hpp"
#include "src/core/units.hpp"

namespace hydrocoef {
namespace {

// VTK's readers swap the process-wide output window while reading, so VTK
// files are read one at a time even when files are imported in parallel.
std::mutex& vtk_read_mutex() {
  static std::mutex mutex;
  return mutex;
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// The first array whose name is one of `names`, or ends in "." + name (a
/// CFX phase prefix such as "water.Pressure").
const FieldArray* find_named(const SurfaceMesh& mesh, std::initializer_list<const char*> names, int components) {
  for (const char* name : names)
    for (const auto& field : mesh.fields)
      if (field.components == components && (field.name == name || ends_with(field.name, std::string(".") + name)))
        return &field;
  return nullptr;
}

std::string array_list(const SurfaceMesh& mesh) {
  std::string out;
  for (const auto& field : mesh.fields) out += (out.empty() ? "'" : ", '") + printable_text(field.name, 60) + "'";
  return out.empty() ? "none" : out;
}

FieldArray& field_named(SurfaceMesh& mesh, const std::string& name) {
  for (auto& field : mesh.fields)
    if (field.name == name) return field;
  throw InputError("array '" + name + "' is not in the file; arrays there: " + array_list(mesh));
}

void scale_field(SurfaceMesh& mesh, const std::string& name, double factor) {
  for (auto& v : field_named(mesh, name).values) v *= factor;
}

/// Reads the mesh and the file's SHA-256 and size: text formats are read
/// once, hashed and parsed from the same bytes; VTK-family files are read by
/// their reader while another thread hashes them block by block.
SurfaceMesh read_mesh(const std::filesystem::path& file, const std::string& format,
                      const std::vector<std::string>& locations, FileDigest& digest) {
  if (format == "cfdpost") {
    const SourceFile source = load_source_file(file);
    digest = {source.sha256, source.bytes.size()};
    CfdPostOptions options;
    options.locations = locations;
    return parse_cfdpost_export(source.bytes, file.string(), options);
  }
  std::future<FileDigest> hashing = std::async(std::launch::async, [&file] { return digest_file(file); });
  VtkSurfaceOptions options;
  options.locations = locations;
  SurfaceMesh mesh;
  try {
    const std::lock_guard<std::mutex> lock(vtk_read_mutex());
    mesh = read_vtk_surface(file, options);
  } catch (...) {
    hashing.get();  // a file that cannot be opened is reported as digest_file reports it
    throw;
  }
  digest = hashing.get();
  return mesh;
}

}  // namespace

std::string detect_format(const std::filesystem::path& file, const std::string& requested) {
  static const std::vector<std::string> known = {"auto", "cfdpost", "vtk", "monitor", "table"};
  if (std::find(known.begin(), known.end(), requested) == known.end())
    throw InputError("--format '" + requested + "': expected one of auto, cfdpost, vtk, monitor, table");
  if (requested != "auto") return requested;
  const std::string extension = lower(file.extension().string());
  if (extension == ".vtk" || extension == ".vtp" || extension == ".vtu" || extension == ".vtm" ||
      extension == ".case" || extension == ".encas" || extension == ".cgns")
    return "vtk";
  if (extension == ".csv" || extension == ".txt" || extension == ".tsv" || extension == ".dat") {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(SourceLocation{file.string()}, "cannot open the file");
    std::string head(4096, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    if (looks_like_cfdpost_export(head)) return "cfdpost";
    if (looks_like_cfx_monitor(head)) return "monitor";
    return "table";
  }
  throw InputError(SourceLocation{file.string()},
                   "cannot tell the format from the extension '" + extension +
                       "'; expected .csv .txt .dat (tables, CFD-Post exports), .vtk .vtp .vtu .vtm .case .cgns, "
                       "or give --format");
}

SurfaceRun import_surface_run(const std::filesystem::path& file, const SurfaceRunOptions& options) {
  const std::string path = file.string();
  SurfaceRun result;
  result.format = detect_format(file, options.format);
  if (result.format != "cfdpost" && result.format != "vtk")
    throw InputError(SourceLocation{path}, "format '" + result.format + "' is not a surface export");
  FileDigest digest;
  try {
    SurfaceMesh mesh = read_mesh(file, result.format, options.locations, digest);

    // Which arrays: the user's, else what the file's naming says.
    const FieldArray* pressure = nullptr;
    if (options.pressure) {
      pressure = mesh.find_field(*options.pressure);
      if (!pressure)
        throw InputError("pressure array '" + *options.pressure +
                         "' is not in the file; arrays there: " + array_list(mesh));
    } else {
      pressure = find_named(mesh, {"Pressure", "p", "pressure", "Static Pressure", "static_pressure"}, 1);
      if (!pressure)
        throw InputError("no pressure array found (looked for Pressure, p, pressure); arrays there: " +
                         array_list(mesh) + "; name one with --pressure");
    }
    // Array names come from the file: the name rule applies where they are used.
    result.pressure_array = check_name(NameKind::Field, pressure->name, {}, "the pressure array");
    const bool openfoam_naming = pressure->name == "p" || pressure->name == "pMean";

    std::vector<std::string> shear = options.shear;
    if (shear.empty()) {
      if (const FieldArray* vector =
              find_named(mesh, {"wallShearStress", "Wall Shear", "Wall_Shear", "wall_shear_stress"}, 3)) {
        shear = {vector->name};
      } else if (const FieldArray* x = find_named(mesh, {"Wall Shear X"}, 1)) {
        const std::string prefix = x->name.substr(0, x->name.size() - 1);
        shear = {x->name, prefix + "Y", prefix + "Z"};
      } else {
        result.warnings.push_back(
            "no wall shear array (looked for Wall Shear X/Y/Z, wallShearStress): only the "
            "pressure force was integrated; name one with --shear");
      }
    } else if (shear.size() == 1 && shear[0] == "none") {
      shear.clear();
    }
    for (const auto& name : shear) (void)field_named(mesh, name);
    result.shear_array.clear();
    for (const auto& name : shear)
      result.shear_array +=
          (result.shear_array.empty() ? "" : ",") + std::string(check_name(NameKind::Field, name, {}, "a shear array"));

    result.pressure_kind =
        options.pressure_kind.value_or(openfoam_naming ? PressureKind::Kinematic : PressureKind::Static);
    const bool openfoam_shear = !shear.empty() && shear.size() == 1 && shear[0].rfind("wallShearStress", 0) == 0;
    result.shear_convention =
        options.shear_convention.value_or(openfoam_shear ? ShearConvention::OnFluid : ShearConvention::OnWall);

    // Units: CFD-Post arrays arrive in SI with their unit; VTK arrays do not say.
    const Dimension expected = result.pressure_kind == PressureKind::Static ? kPressure : Dimension{{0, 2, -2, 0}};
    double pressure_scale = 1.0;
    if (options.pressure_unit) {
      const Unit unit = parse_unit(*options.pressure_unit);
      if (!dimension_matches(unit.dimension, expected))
        throw InputError("--pressure-unit '" + unit.text + "' is " + si_unit_name(unit.dimension) + ", expected " +
                         si_unit_name(expected) + " for " +
                         (result.pressure_kind == PressureKind::Static ? "static" : "kinematic") + " pressure");
      if (!pressure->unit.empty())
        throw InputError("array '" + pressure->name + "' already has a unit (" + pressure->unit +
                         ") from the file; --pressure-unit is for files that do not say");
      pressure_scale = unit.scale;
    } else if (!pressure->unit.empty()) {
      const Unit unit = parse_unit(pressure->unit);
      if (!dimension_matches(unit.dimension, expected))
        throw InputError("array '" + pressure->name + "' is in " + pressure->unit + ", expected " +
                         si_unit_name(expected) + " for " +
                         (result.pressure_kind == PressureKind::Static ? "static" : "kinematic") +
                         " pressure (see --pressure-kind)");
    }
    if (options.length_unit) {
      const Unit unit = parse_unit(*options.length_unit);
      if (!dimension_matches(unit.dimension, kLength))
        throw InputError("--length-unit '" + unit.text + "' is " + si_unit_name(unit.dimension) +
                         ", expected a length");
      if (result.format == "cfdpost")
        throw InputError("--length-unit: a CFD-Post export states its own length unit in its header");
      for (auto& x : mesh.points_xyz) x *= unit.scale;
    }
    double to_pascal = pressure_scale;
    if (result.pressure_kind == PressureKind::Kinematic) {
      if (!options.density)
        throw InputError("array '" + result.pressure_array +
                         "' is kinematic pressure (m^2 s^-2, as OpenFOAM writes it): give --rho (kg m^-3) or "
                         "--pressure-kind static");
      to_pascal *= *options.density;
    }
    const std::string pressure_name = result.pressure_array;
    if (to_pascal != 1.0) {
      scale_field(mesh, pressure_name, to_pascal);
      for (const auto& name : shear) scale_field(mesh, name, to_pascal);
    }

    SurfaceLoadOptions load_options;
    load_options.pressure_field = pressure_name;
    load_options.shear_fields = shear;
    load_options.shear_convention = result.shear_convention;
    load_options.reference_pressure = options.reference_pressure;
    load_options.reference_point = options.frame.point_to_cfd(options.reference_point_b);
    load_options.normals = options.normals;
    SurfaceLoads loads_cfd = integrate_surface_loads(mesh, load_options);
    if (!options.symmetry.empty()) {
      loads_cfd = mirror_loads(loads_cfd, options.symmetry);
      result.warnings.push_back("the whole body's loads from a model cut by the symmetry planes " +
                                symmetry_text(options.symmetry) +
                                " (CFD axes): " + vanishing_components(options.symmetry) + " vanish");
    }
    result.loads_b = loads_to_body(loads_cfd, options.frame);
    for (const auto& w : result.loads_b.geometry.warnings) result.warnings.push_back(w);
    // An open surface's pressure force depends on the reference pressure:
    // each pascal of it adds -∫n dA (a closed surface's ∫n dA is zero).
    const auto& n_dA = result.loads_b.geometry.integral_n_dA;
    const double open = std::sqrt(n_dA[0] * n_dA[0] + n_dA[1] * n_dA[1] + n_dA[2] * n_dA[2]);
    if (open > 1e-9 * std::max(result.loads_b.geometry.area, 1e-300)) {
      char text[256];
      std::snprintf(text, sizeof text,
                    "open surface: |∫n dA| = %.4g m^2, so each 1 Pa of reference pressure adds %.4g N "
                    "to the force; the forces depend on --p-ref (%g Pa used)",
                    open, open, options.reference_pressure);
      result.warnings.push_back(text);
    }
  } catch (const InputError& error) {
    if (!error.where().file.empty()) throw;
    throw InputError(SourceLocation{path}, error.what());
  }

  const SurfaceLoads& loads = result.loads_b;
  ImportedRun run;
  run.key = options.key;
  run.fluid.density_kg_m3 = options.density;
  run.fluid.kinematic_viscosity_m2_s = options.kinematic_viscosity;
  run.reference_point_b = options.reference_point_b;
  run.sign = SignConvention::OnBody;
  const bool has_shear = !result.shear_array.empty();
  for (std::size_t i = 0; i < 3; ++i) {
    run.tau_b[i] = ForceComponent{loads.force_pressure[i] + loads.force_viscous[i], loads.force_pressure[i],
                                  has_shear ? std::optional<double>(loads.force_viscous[i]) : std::nullopt};
    run.tau_b[3 + i] = ForceComponent{loads.moment_pressure[i] + loads.moment_viscous[i], loads.moment_pressure[i],
                                      has_shear ? std::optional<double>(loads.moment_viscous[i]) : std::nullopt};
  }
  SurfaceIntegrals integrals;
  const auto& g = loads.geometry;
  integrals.faces = g.faces;
  integrals.area = g.area;
  integrals.signed_volume = g.signed_volume;
  integrals.closed = g.closed;
  integrals.boundary_edges = g.boundary_edges;
  integrals.degenerate_faces = g.degenerate_faces;
  integrals.normals_flipped = g.normals_flipped;
  integrals.integral_n_dA_b = g.integral_n_dA;
  integrals.integral_x_cross_n_dA_b = g.integral_x_cross_n_dA;
  integrals.reference_pressure = options.reference_pressure;
  integrals.pressure_array = result.pressure_array;
  integrals.shear_array = result.shear_array;
  integrals.pressure_kind = result.pressure_kind == PressureKind::Static ? "static" : "kinematic";
  integrals.shear_convention = result.shear_convention == ShearConvention::OnWall ? "on-wall" : "on-fluid";
  integrals.axes = options.frame.axes_text();
  run.surface = integrals;

  result.batch.source.path = path;
  result.batch.source.sha256 = digest.sha256;
  result.batch.source.size_bytes = digest.size_bytes;
  result.batch.source.importer = result.format == "cfdpost" ? "cfdpost-surface" : "vtk-surface";
  result.batch.source.importer_version = std::string(kSurfaceImporterVersion);
  result.batch.runs.push_back(std::move(run));
  return result;
}

}  // namespace hydrocoef
