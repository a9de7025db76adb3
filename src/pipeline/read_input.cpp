// read_input: one input read by the importer of its format (a surface
// export, a force table, a force history, a CFX wall force summary) into
// runs in body axes with its settings; read_inputs: every input of a plan on
// a pool of threads.
#include <atomic>
#include <mutex>

#include "importers/case_motion.hpp"
#include "importers/force_table.hpp"
#include "src/core/error.hpp"
#include "src/core/parallel.hpp"
#include "src/loads/symmetry.hpp"
#include "src/pipeline/given_uncertainty.hpp"
#include "src/pipeline/import_files_internal.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
using reading::check_flow_speed;
using reading::fluid_of;
using reading::read_cfx_summary;
using reading::read_history;
using reading::record_settings;
using reading::settings_not_applicable;
using reading::sign_of;

SurfaceRunOptions surface_options(const RunSettings& settings, const std::string& format, const FrameTransform& frame,
                                  const RunKey& key, const Vec3& reference_point_b) {
  SurfaceRunOptions options;
  options.format = format;
  options.key = key;
  options.frame = frame;
  options.reference_point_b = reference_point_b;
  if (const auto locations = settings.texts("locations")) options.locations = *locations;
  options.pressure = settings.text("pressure");
  if (const auto shear = settings.texts("shear")) {
    options.shear = *shear;
    if (options.shear.size() != 1 && options.shear.size() != 3)
      throw InputError(settings.find("shear")->origin.where +
                       ": setting 'shear': expected one vector array, three arrays x,y,z, or none");
  }
  const auto choice = [&](const char* name, std::initializer_list<const char*> allowed) -> std::optional<std::string> {
    const auto text = settings.text(name);
    if (!text) return std::nullopt;
    for (const char* a : allowed)
      if (*text == a) return text;
    std::string list;
    for (const char* a : allowed) list += (list.empty() ? "" : " or ") + std::string(a);
    throw InputError(settings.find(name)->origin.where + ": setting '" + name + "' is '" + printable_text(*text, 40) +
                     "'; expected " + list);
  };
  if (const auto kind = choice("pressure_kind", {"static", "kinematic"}))
    options.pressure_kind = *kind == "static" ? PressureKind::Static : PressureKind::Kinematic;
  if (const auto convention = choice("shear_convention", {"on-wall", "on-fluid"}))
    options.shear_convention = *convention == "on-wall" ? ShearConvention::OnWall : ShearConvention::OnFluid;
  if (const auto normals = choice("normals", {"auto", "as-given", "flip"}))
    options.normals = *normals == "auto"   ? NormalPolicy::Auto
                      : *normals == "flip" ? NormalPolicy::Flip
                                           : NormalPolicy::AsGiven;
  options.density = settings.number("rho");
  options.kinematic_viscosity = settings.number("nu");
  options.reference_pressure = settings.number("p_ref").value_or(0.0);
  options.length_unit = settings.text("length_unit");
  options.pressure_unit = settings.text("pressure_unit");
  if (const auto symmetry = settings.text("symmetry")) options.symmetry = parse_symmetry(*symmetry);
  return options;
}

/// A forced-oscillation case (an imposed harmonic motion in
/// constant/dynamicMeshDict) is not a run at one velocity: `hydrocoef pmm`
/// reads it. A motion that is not an oscillation gives a note.
void refuse_forced_oscillation(const fs::path& case_dir, std::vector<std::string>& notes) {
  std::optional<CaseOscillation> motion;
  try {
    motion = read_openfoam_motion(case_dir);
  } catch (const InputError& e) {
    notes.push_back(case_dir.string() +
                    ": constant/dynamicMeshDict moves the mesh in a way that is not a forced oscillation (" + e.what() +
                    "); imported as a run at the velocity of its settings: check its key");
    return;
  }
  if (!motion) return;
  throw InputError(motion->where + ": a forced-oscillation case (" + motion->description +
                   "), not a run at one velocity; expected `hydrocoef pmm " + case_dir.string() +
                   "`, which reads forced-oscillation runs, or a case without an imposed motion");
}

/// A captive-test table: its rows' keys and forces from its columns and the
/// table's normalisation (importers/captive_table.hpp); the body, fixed
/// disturbances, density, viscosity and sign from the input's settings.
void read_captive_input(const PlannedInput& input, const ImportRequest& request, const RunSettings& settings,
                        const RunKey& key, const Vec3& reference_b, ImportedInput& out) {
  settings_not_applicable(settings,
                          {"flow", "axes", "origin", "cofr", "symmetry", "window", "pressure", "shear", "pressure_kind",
                           "shear_convention", "length_unit", "pressure_unit", "normals", "locations"},
                          "a captive-test table (its rows are in body axes)", out.notes);
  for (std::size_t c = 0; c < key.nu_b.size(); ++c)
    if (const Setting* given = settings.find(kVelocityNames[c]))
      throw InputError(SourceLocation{input.path.string()},
                       "setting '" + std::string(kVelocityNames[c]) + "' (" + given->origin.where +
                           "): a captive-test table's rows give u, v and r (from U, beta and r'); expected no "
                           "velocity setting");
  CaptiveTableOptions options = request.captive;
  options.body = key.body;
  options.disturbances = key.disturbances;
  if (const auto body = request.body_references.find(key.body); body != request.body_references.end())
    options.body_reference = body->second;
  const Fluid fluid = fluid_of(settings);
  if (fluid.density_kg_m3)
    options.density = CaptiveValue{fluid.density_kg_m3, settings.find("rho")->origin.where.empty()
                                                            ? std::string("the settings")
                                                            : settings.find("rho")->origin.where};
  options.kinematic_viscosity = fluid.kinematic_viscosity_m2_s;
  options.sign = sign_of(settings);
  options.reference_point_b = reference_b;
  options.ignored_columns = request.columns.ignored_columns;
  CaptiveTableFile table = read_captive_table(input.path, options);
  out.batch = std::move(table.batch);
  out.notes.push_back(std::move(table.note));
  out.captive_settings = std::move(table.settings_key);
}

/// The runs of one input as its format gives them, with its settings.
ImportedInput read_input_values(const PlannedInput& input, const ImportRequest& request) {
  RunSettings settings = reading::input_settings(input, request);
  const std::string format = input_format(input, request.format);
  if (format == "openfoam-case") {
    std::vector<std::string> motion_notes;
    refuse_forced_oscillation(input.path, motion_notes);
    ImportedInput out = read_history(input, format, std::move(settings), request);
    out.notes.insert(out.notes.end(), motion_notes.begin(), motion_notes.end());
    return out;
  }
  if (format == "openfoam-forces" || format == "force-history" || format == "monitor")
    return read_history(input, format, std::move(settings), request);
  if (format == "cfx-out") return read_cfx_summary(input, std::move(settings), request);

  ImportedInput out;
  out.input = input;
  out.format = format;
  const FrameTransform frame = resolve_frame(settings);
  const RunKey key = resolve_key(settings, frame, request.default_body);
  check_flow_speed(settings, key, input.path, out.notes);
  const Vec3 reference_b = resolve_reference_point(settings, frame);
  if (format == "cfdpost" || format == "vtk") {
    settings_not_applicable(settings, {"window", "sign"}, "a surface export", out.notes);
    SurfaceRunOptions options = surface_options(settings, format, frame, key, reference_b);
    out.surface = import_surface_run(input.path, options);
    // After the file is read, so that a broken file is said before a missing key.
    if (request.require_velocity) require_velocity(settings, input.path.string());
    out.batch = out.surface->batch;
    for (const auto& w : out.surface->warnings) out.notes.push_back(w);
  } else if (format == "table") {
    settings_not_applicable(
        settings,
        {"flow", "axes", "origin", "cofr", "symmetry", "window", "pressure", "shear", "pressure_kind",
         "shear_convention", "length_unit", "pressure_unit", "normals", "locations"},
        "a force table (its rows are in body axes)", out.notes);
    ForceTableOptions options;
    options.body = key.body;
    options.velocity_b = key.nu_b;
    options.disturbances = key.disturbances;
    options.columns = request.columns.columns;
    options.units = request.columns.units;
    options.disturbance_columns = request.columns.disturbance_columns;
    options.ignored_columns = request.columns.ignored_columns;
    options.sign = sign_of(settings);
    options.fluid = fluid_of(settings);
    options.reference_point_b = reference_b;
    out.batch = read_force_table(input.path, options);
  } else if (format == "captive-table") {
    read_captive_input(input, request, settings, key, reference_b, out);
  } else {
    throw InputError(SourceLocation{input.path.string()}, "no importer for format '" + format + "'");
  }
  record_settings(out.batch, settings, format, input.path);
  if (!out.captive_settings.empty()) out.batch.source.settings_key += " " + out.captive_settings;
  out.settings = std::move(settings);
  return out;
}

}  // namespace

ImportedInput read_input(const PlannedInput& input, const ImportRequest& request) {
  ImportedInput out = read_input_values(input, request);
  if (const auto text = out.settings.text("uncertainty"))
    apply_given_uncertainty(out.batch, parse_given_uncertainty(*text, out.settings.find("uncertainty")->origin.where));
  return out;
}

std::vector<ImportedInput> read_inputs(const ImportPlan& plan, const ImportRequest& request) {
  // Files in plan order on request.jobs threads (0: every core); the first
  // file that cannot be read, in plan order, is the error (src/core/parallel.hpp).
  const std::size_t count = plan.inputs.size();
  std::vector<std::optional<ImportedInput>> results(count);
  std::atomic<std::size_t> done{0};
  std::mutex progress_mutex;
  parallel_for(count, request.jobs, [&](std::size_t i) {
    results[i] = read_input(plan.inputs[i], request);
    const std::size_t finished = ++done;
    if (request.progress) {
      const std::lock_guard<std::mutex> lock(progress_mutex);
      request.progress(finished, count, plan.inputs[i].path);
    }
  });
  std::vector<ImportedInput> out;
  out.reserve(count);
  for (auto& r : results) out.push_back(std::move(*r));
  return out;
}

}  // namespace hydrocoef
