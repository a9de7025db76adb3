// export_fmu (include/hydrocoef/fmu.hpp): `hydrocoef export-fmu`, a stored
// gridded surface as an FMI 2.0 Co-Simulation FMU (docs/fmu.md): the runtime
// file of the surface, with the model texts that choose the FMU binary's
// model kind (fmu_model = surface, fmu_surface = NAME); modelDescription.xml
// with the variables in the binary's value-reference order
// (fmu/src/fmu_surface.c); the embedded binary; all in a stored zip. With
// a vehicle: the runtime file of the vehicle and its damping surfaces
// (fmu_model = vehicle) and the variables of fmu/src/fmu_vehicle.c.
#include "src/api/internal.hpp"
#include "src/api/runtime_file.hpp"
#include "src/api/vehicle_inputs.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>

#include "hydrocoef/fmu.hpp"
#include "src/core/atomic_file.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/export/export.hpp"
#include "src/export/fmu_binary.hpp"
#include "src/export/fmu_model_description.hpp"
#include "src/export/zip_writer.hpp"
#include "src/surface/grid_table.hpp"

namespace hydrocoef {
inline namespace api {

void FmuExportOptions::validate() const {
  if (body.empty()) throw InputError("BODY is empty; expected the body whose surface the FMU evaluates");
  if (surface.empty() && vehicle.empty())
    throw InputError(
        "--surface or --vehicle is required; expected the stored surface the FMU evaluates or the "
        "vehicle file it steps");
  if (!surface.empty() && !vehicle.empty())
    throw InputError("--surface and --vehicle were both given; expected one: a surface FMU or a vehicle FMU");
  if (output.empty()) throw InputError("-o/--output is required; expected the .fmu file to write");
  if (output.size() < 5 || output.compare(output.size() - 4, 4, ".fmu") != 0)
    throw InputError("-o/--output '" + output + "' does not end in .fmu; expected an FMU file name (NAME.fmu)");
}

namespace {

std::uint64_t content_hash_of(const std::string& runtime_file) {
  std::uint64_t hash = 0;
  for (int i = 7; i >= 0; --i) hash = (hash << 8) | static_cast<unsigned char>(runtime_file.at(24 + i));
  return hash;
}

// Writes the zip of `model` and `runtime` and fills the rest of `out`.
void write_fmu(const FmuModelSpec& model, const std::string& runtime, const FmuExportOptions& options,
               FmuExportResult& out) {
  const std::string description = fmu_model_description(model);
  const std::string_view binary(reinterpret_cast<const char*>(fmu_binary_bytes()), fmu_binary_size());
  const std::string zip = zip_stored({{"modelDescription.xml", description},
                                      {"binaries/linux64/" + out.model_identifier + ".so", binary, true},
                                      {"resources/model.hcr", runtime}});
  write_file_atomically(options.output, zip);
  for (const auto& v : model.variables)
    out.variables.push_back({v.value_reference, v.name, v.causality, v.unit, v.start, v.description});
  out.runtime_file_bytes = runtime.size();
  out.binary_bytes = binary.size();
  out.fmu_bytes = zip.size();
}

FmuVariableSpec real(std::uint32_t vr, std::string name, std::string causality, std::string unit,
                     std::string description) {
  FmuVariableSpec v;
  v.value_reference = vr;
  v.name = std::move(name);
  v.causality = std::move(causality);
  v.variability = v.causality == "parameter" ? "fixed" : "continuous";
  v.unit = std::move(unit);
  v.description = std::move(description);
  return v;
}

// The vehicle FMU (fmu/src/fmu_vehicle.c states the value references).
FmuExportResult export_vehicle_fmu(const Database& db, const FmuExportOptions& options) {
  const VehicleModel vehicle = load_vehicle_model(options.vehicle, db.path());
  std::vector<std::string> names;
  for (const DofDamping& d : vehicle.description().damping)
    if (d.kind == DofDamping::Kind::Surface && std::find(names.begin(), names.end(), d.surface) == names.end())
      names.push_back(d.surface);
  const std::string name = vehicle.description().name.empty() ? options.body : vehicle.description().name;
  const std::string& file = vehicle.description().file;
  const RuntimeVehicle runtime_vehicle{&vehicle, {{"name", name}, {"file", file.empty() ? "JSON text" : file}}};
  std::vector<StoredSurface> stored;
  const std::string runtime =
      runtime_file_of(db, names, {{"fmu_model", "vehicle"}}, stored, &runtime_vehicle, options.body);

  FmuExportResult out;
  out.body = options.body;
  out.vehicle = name;
  out.kind = "vehicle";
  out.model_identifier = fmu_model_identifier(name);
  out.guid = fmu_guid(content_hash_of(runtime));
  out.file = options.output;

  FmuModelSpec model;
  model.model_name = name;
  model.model_identifier = out.model_identifier;
  model.guid = out.guid;
  model.description =
      "hydrocoef vehicle '" + name + "' of body '" + options.body +
      "': 6-DOF equation of motion (Fossen 2011, eq. 6.1 with current; hydrocoef simulate's) stepped with RK4 at the "
      "parameter step; body axes x forward, y starboard, z down (FRD) about CO, world NED, forces and moments on the "
      "body (SNAME signs: damping opposes motion), SI units";
  model.generation_tool = std::string("hydrocoef ") + kVersion;
  model.generation_time = utc_timestamp_now();
  std::uint32_t vr = 0;
  const char* const dofs[6] = {"X", "Y", "Z", "K", "M", "N"};
  const char* const dof_what[6] = {"surge force", "sway force",   "heave force",
                                   "roll moment", "pitch moment", "yaw moment"};
  for (int i = 0; i < 6; ++i)
    model.variables.push_back(
        real(vr++, dofs[i], "input", i < 3 ? "N" : "N m",
             std::string("control ") + dof_what[i] + " tau_b on the body about CO, body axes FRD (held over a step)"));
  std::vector<std::uint32_t> current;
  for (const char* axis : {"north", "east", "down"}) {
    current.push_back(vr);
    model.variables.push_back(real(vr++, std::string("current_") + axis, "input", "m/s",
                                   std::string("water velocity over ground, ") + axis + " component (NED)"));
  }
  std::vector<std::uint32_t> damping_inputs = current;
  for (const std::string& d : vehicle.disturbance_names()) {
    damping_inputs.push_back(vr);
    model.variables.push_back(
        real(vr++, d, "input", "", "disturbance parameter '" + d + "' the damping reads (SI; held over a step)"));
  }
  for (auto& v : model.variables) v.start = 0.0;
  for (const char* axis : {"x_n", "y_n", "z_n"})
    model.variables.push_back(real(vr++, axis, "output", "m", std::string(axis) + ": position of CO in NED"));
  const char* const q_names[4] = {"q_eta", "q_eps1", "q_eps2", "q_eps3"};
  for (const char* q : q_names)
    model.variables.push_back(
        real(vr++, q, "output", "1", std::string(q) + ": attitude quaternion q_nb (body FRD to NED), scalar first"));
  const char* const euler[3] = {"phi", "theta", "psi"};
  for (const char* e : euler)
    model.variables.push_back(
        real(vr++, e, "output", "rad", std::string(e) + ": zyx Euler angle of q_nb (roll, pitch, yaw), wrapped"));
  const char* const nu[6] = {"u", "v", "w", "p", "q", "r"};
  for (int i = 0; i < 6; ++i)
    model.variables.push_back(real(vr++, nu[i], "output", i < 3 ? "m/s" : "rad/s",
                                   std::string(nu[i]) + ": body velocity over ground, body axes FRD"));
  for (int i = 0; i < 6; ++i) {
    auto v = real(vr++, std::string(dofs[i]) + "_damping", "output", i < 3 ? "N" : "N m",
                  std::string("damping ") + dof_what[i] + " -D(nu_r) nu_r on the body, body axes FRD");
    v.dependencies = damping_inputs;
    model.variables.push_back(v);
  }
  auto step = real(vr++, "step", "parameter", "s",
                   "internal RK4 step: fmi2DoStep(t, H) takes max(1, ceil(H/step - 1e-9)) equal steps of H/n");
  step.start = 0.001;
  model.variables.push_back(step);
  for (const char* axis : {"x_n0", "y_n0", "z_n0"})
    model.variables.push_back(real(vr++, axis, "parameter", "m", "initial position of CO in NED"));
  for (const char* e : {"phi0", "theta0", "psi0"})
    model.variables.push_back(real(vr++, e, "parameter", "rad", "initial zyx Euler angle"));
  for (int i = 0; i < 6; ++i)
    model.variables.push_back(real(vr++, std::string(nu[i]) + "0", "parameter", i < 3 ? "m/s" : "rad/s",
                                   "initial body velocity over ground"));
  std::vector<std::uint32_t> initial_state;  // the parameters x_n0 .. r0
  for (auto& v : model.variables)
    if (v.causality == "parameter" && !v.start) {
      v.start = 0.0;
      initial_state.push_back(v.value_reference);
    }
  // In initialisation the outputs are those of the initial state: they depend on its parameters too.
  for (auto& v : model.variables)
    if (v.causality == "output") {
      std::vector<std::uint32_t> at_start = v.dependencies;
      at_start.insert(at_start.end(), initial_state.begin(), initial_state.end());
      v.initial_dependencies = at_start;
    }
  write_fmu(model, runtime, options, out);
  return out;
}

}  // namespace

FmuExportResult export_fmu(const Database& db, const FmuExportOptions& options) {
  options.validate();
  if (!options.vehicle.empty()) return export_vehicle_fmu(db, options);
  std::vector<StoredSurface> stored;
  const std::string runtime =
      runtime_file_of(db, {options.surface}, {{"fmu_model", "surface"}, {"fmu_surface", options.surface}}, stored);
  const StoredSurface& s = stored.front();
  if (s.record.body != options.body)
    throw InputError("surface '" + s.record.name + "' belongs to body '" + s.record.body +
                     "'; expected a surface of body '" + options.body + "'");
  const ExportMetadata metadata = metadata_from_record(s.record, s.surface);
  const GridTable& table = *s.surface.grid();

  FmuExportResult out;
  out.body = options.body;
  out.surface = s.record.name;
  out.kind = "surface";
  out.model_identifier = fmu_model_identifier(s.record.name);
  out.guid = fmu_guid(content_hash_of(runtime));
  out.file = options.output;

  FmuModelSpec model;
  model.model_name = s.record.name;
  model.model_identifier = out.model_identifier;
  model.guid = out.guid;
  model.description = "hydrocoef coefficient surface '" + s.record.name + "' of body '" + s.record.body + "' (" +
                      std::string(interpolation_name(table.method())) +
                      "): forces and moments of the fluid on the body (SNAME on-body signs), body axes x forward, "
                      "y starboard, z down (FRD), SI units";
  model.generation_tool = std::string("hydrocoef ") + kVersion;
  model.generation_time = utc_timestamp_now();
  const std::size_t n = table.axis_count(), m = table.outputs().size();
  std::vector<std::uint32_t> inputs;
  for (std::size_t a = 0; a < n; ++a) {
    const GridAxis& axis = table.axes()[a];
    const double lower = axis.breakpoints.front(), upper = axis.breakpoints.back();
    FmuVariableSpec v;
    v.name = axis.name;
    v.value_reference = static_cast<std::uint32_t>(a);
    v.causality = "input";
    v.variability = "continuous";
    v.unit = metadata.axis_units[a];
    v.start = std::min(std::max(0.0, lower), upper);
    v.description = "axis " + axis.name + ": breakpoints from " + shortest_number(lower) + " to " +
                    shortest_number(upper) + ", outside them " + std::string(extrapolation_name(axis.extrapolation));
    inputs.push_back(v.value_reference);
    model.variables.push_back(v);
    if (axis.extrapolation == Extrapolation::Error)
      out.notes.push_back("input " + axis.name + " refuses values outside [" + shortest_number(lower) + ", " +
                          shortest_number(upper) + "] (policy error): a step there fails with fmi2Error");
  }
  const bool sigma = s.surface.has_standard_deviation();
  for (std::size_t copy = 0; copy < (sigma ? 2u : 1u); ++copy) {
    for (std::size_t k = 0; k < m; ++k) {
      FmuVariableSpec v;
      const std::string& name = table.outputs()[k];
      v.name = copy == 0 ? name : "sigma(" + name + ")";
      v.value_reference = static_cast<std::uint32_t>(n + copy * m + k);
      v.causality = "output";
      v.variability = "continuous";
      v.unit = metadata.output_units[k];
      v.description = copy == 0 ? "output " + name + " of the surface, on the body"
                                : "standard deviation of " + name + ", as hydrocoef query --uncertainty states it";
      v.dependencies = inputs;
      model.variables.push_back(v);
    }
  }
  write_fmu(model, runtime, options, out);
  if (s.record.stale)
    out.notes.push_back(
        "the body's forces changed since this surface was built; rebuild it with hydrocoef surface "
        "rebuild " +
        s.record.name);
  return out;
}

std::string FmuExportResult::json() const {
  nlohmann::json out = {{"body", body},
                        {"surface", surface},
                        {"vehicle", vehicle},
                        {"kind", kind},
                        {"fmi_version", "2.0"},
                        {"interface", "CoSimulation"},
                        {"model_identifier", model_identifier},
                        {"guid", guid},
                        {"file", file},
                        {"runtime_file_bytes", runtime_file_bytes},
                        {"binary_bytes", binary_bytes},
                        {"fmu_bytes", fmu_bytes}};
  out["variables"] = nlohmann::json::array();
  for (const auto& v : variables) {
    nlohmann::json variable = {{"value_reference", v.value_reference},
                               {"name", v.name},
                               {"causality", v.causality},
                               {"unit", v.unit},
                               {"description", v.description}};
    if (v.start) variable["start"] = *v.start;
    out["variables"].push_back(variable);
  }
  out["notes"] = notes;
  return escape::json_text(out, 2) + '\n';
}

std::string FmuExportResult::text() const {
  std::ostringstream out;
  out << "exported "
      << (kind == "vehicle" ? "vehicle " + escape::one_line(vehicle) : "surface " + escape::one_line(surface))
      << " of body " << escape::one_line(body) << " as an FMI 2.0 Co-Simulation FMU\n  modelIdentifier "
      << model_identifier << ", guid " << guid << '\n';
  for (const auto& v : variables) {
    out << "  " << v.causality << (v.causality == "input" ? "  " : " ") << v.value_reference << ' '
        << escape::one_line(v.name) << " [" << escape::one_line(v.unit) << "]";
    if (v.start) out << ", start " << shortest_number(*v.start);
    out << '\n';
  }
  out << "  wrote " << escape::one_line(file) << " (" << fmu_bytes << " bytes: binary " << binary_bytes
      << ", runtime file " << runtime_file_bytes << ")\n";
  for (const auto& note : notes) out << "  note: " << escape::one_line(note) << '\n';
  return out.str();
}

}  // namespace api
}  // namespace hydrocoef
