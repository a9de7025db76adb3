// export_fmu (include/hydrocoef/fmu.hpp): `hydrocoef export-fmu`, a stored
// gridded surface as an FMI 2.0 Co-Simulation FMU (docs/fmu.md): the runtime
// file of the surface, with the model texts that choose the FMU binary's
// model kind (fmu_model = surface, fmu_surface = NAME); modelDescription.xml
// with the variables in the binary's value-reference order
// (fmu/src/fmu_surface.c); the embedded binary; all in a stored zip.
#include "src/api/internal.hpp"
#include "src/api/runtime_file.hpp"

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
  if (surface.empty()) throw InputError("--surface is required; expected the stored surface the FMU evaluates");
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

}  // namespace

FmuExportResult export_fmu(const Database& db, const FmuExportOptions& options) {
  options.validate();
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
  out << "exported surface " << escape::one_line(surface) << " of body " << escape::one_line(body)
      << " as an FMI 2.0 Co-Simulation FMU\n  modelIdentifier " << model_identifier << ", guid " << guid << '\n';
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
