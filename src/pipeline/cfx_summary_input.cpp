// A CFX solver output (.out) read for its wall force summary: the forces of
// the domain group, or of the boundaries named with --location, at the end of
// the run, as one sample brought into body axes like a history's.
#include <cctype>

#include "importers/cfx_out.hpp"
#include "src/core/error.hpp"
#include "src/core/source_file.hpp"
#include "src/pipeline/import_files_internal.hpp"

namespace hydrocoef::reading {
namespace {

/// Names compared as CFX compares them: runs of blanks as one space, any case.
std::string cfx_name_key(std::string_view name) {
  std::string out;
  bool blank = false;
  for (const char c : name) {
    if (c == ' ' || c == '\t') {
      blank = true;
      continue;
    }
    if (blank && !out.empty()) out += ' ';
    blank = false;
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

/// The loads of the locations a CFX run's forces are taken from: the one
/// domain group's totals by default, else the boundaries or groups named
/// with --location (summed). `what` says which, for notes.
CfxWallLoads cfx_summary_loads(const CfxWallForceSummary& summary, const RunSettings& settings, std::string& what) {
  const SourceLocation at{summary.file, summary.line, 0};
  std::string available;
  for (const auto& group : summary.groups) {
    for (const auto& [name, loads] : group.boundaries) available += (available.empty() ? "" : ", ") + name;
    available += ", " + group.name + " (the domain group's totals)";
  }
  available = printable_text(available, 400);
  const auto names = settings.texts("locations");
  if (!names || names->empty()) {
    if (summary.groups.size() != 1)
      throw InputError(at, std::to_string(summary.groups.size()) +
                               " domain groups in the wall force summary; expected one, or --location NAME of "
                               "the one to import: " +
                               available);
    what = "the totals of domain group '" + printable_text(summary.groups.front().name, 80) + "'";
    return summary.groups.front().totals;
  }
  CfxWallLoads sum;
  bool first = true;
  const auto add = [&](std::optional<Vec3>& total, const std::optional<Vec3>& part) {
    if (first) {
      total = part;
    } else if (total && part) {
      for (std::size_t i = 0; i < 3; ++i) (*total)[i] += (*part)[i];
    } else {
      total.reset();  // a part one location lacks is not known for the sum
    }
  };
  for (const auto& name : *names) {
    const CfxWallLoads* found = nullptr;
    std::size_t matches = 0;
    for (const auto& group : summary.groups) {
      if (cfx_name_key(group.name) == cfx_name_key(name)) found = &group.totals, ++matches;
      for (const auto& [boundary, loads] : group.boundaries)
        if (cfx_name_key(boundary) == cfx_name_key(name)) found = &loads, ++matches;
    }
    if (matches == 0)
      throw InputError(at, "no location '" + printable_text(name, 80) +
                               "' (--location) in the wall force summary; expected one of: " + available);
    if (matches > 1)
      throw InputError(at, "location '" + printable_text(name, 80) +
                               "' (--location) names several boundaries or groups of the wall force summary; "
                               "expected a name found once");
    add(sum.pressure_force, found->pressure_force);
    add(sum.viscous_force, found->viscous_force);
    add(sum.pressure_moment, found->pressure_moment);
    add(sum.viscous_moment, found->viscous_moment);
    if (first) sum.line = found->line;
    first = false;
    what += (what.empty() ? "" : " + ") + printable_text(name, 80);
  }
  return sum;
}

}  // namespace

/// A CFX run from the wall force summary of its solver output: the chosen
/// location's pressure and viscous force and moment, one sample brought into
/// body axes by the transform a history's samples go through (moments to the
/// reference point, mirrored for symmetry planes, rotated).
ImportedInput read_cfx_summary(const PlannedInput& input, RunSettings settings, const ImportRequest& request) {
  ImportedInput out;
  out.input = input;
  out.format = "cfx-out";
  settings_not_applicable(
      settings,
      {"window", "pressure", "shear", "pressure_kind", "shear_convention", "length_unit", "pressure_unit", "normals"},
      "the wall force summary of a CFX solver output", out.notes);
  const SourceFile file = load_source_file(input.path);
  const CfxWallForceSummary summary = parse_cfx_wall_forces(file.bytes, input.path.string());
  std::string what;
  const CfxWallLoads loads = cfx_summary_loads(summary, settings, what);

  ForceHistory history;
  history.abscissa = HistoryAbscissa::Iteration;
  history.abscissa_values = {1.0};
  history.files.push_back(HistorySourceFile{input.path, std::string(kCfxOutImporter), file.sha256,
                                            static_cast<std::uint64_t>(file.bytes.size()), 1, 1});
  const auto put = [&](ForcePart part, std::size_t offset, const std::optional<Vec3>& v) {
    if (!v) return;
    for (std::size_t c = 0; c < 3; ++c) history.series[static_cast<std::size_t>(part)][offset + c] = {(*v)[c]};
  };
  put(ForcePart::Pressure, 0, loads.pressure_force);
  put(ForcePart::Viscous, 0, loads.viscous_force);
  put(ForcePart::Pressure, 3, loads.pressure_moment);
  put(ForcePart::Viscous, 3, loads.viscous_moment);
  for (std::size_t c = 0; c < 6; ++c) {
    const auto& p = history.series[static_cast<std::size_t>(ForcePart::Pressure)][c];
    const auto& v = history.series[static_cast<std::size_t>(ForcePart::Viscous)][c];
    if (!p.empty() || !v.empty())
      history.series[static_cast<std::size_t>(ForcePart::Total)][c] = {(p.empty() ? 0.0 : p[0]) +
                                                                       (v.empty() ? 0.0 : v[0])};
  }
  const auto origin = SampleOrigin{0, static_cast<std::uint32_t>(loads.line)};
  if (loads.pressure_force || loads.viscous_force) history.force_origin = {origin};
  if (loads.pressure_moment || loads.viscous_moment) history.moment_origin = {origin};
  history.frame.description = "the CFX solver's global axes";

  const FrameTransform frame = resolve_frame(settings);
  const Vec3 reference_b = resolve_reference_point(settings, frame);
  const ForceHistory body = history_in_body_axes(std::move(history), settings, frame, reference_b, out.notes);
  ImportedRun run;
  for (std::size_t c = 0; c < 6; ++c) {
    const auto& total = body.series[static_cast<std::size_t>(ForcePart::Total)][c];
    if (total.empty()) continue;
    ForceComponent force;
    force.total = total[0];
    if (const auto& p = body.series[static_cast<std::size_t>(ForcePart::Pressure)][c]; !p.empty())
      force.pressure = p[0];
    if (const auto& v = body.series[static_cast<std::size_t>(ForcePart::Viscous)][c]; !v.empty()) force.viscous = v[0];
    run.tau_b[c] = force;
  }
  run.key = resolve_key(settings, frame, request.default_body);
  check_flow_speed(settings, run.key, input.path, out.notes);
  run.fluid = fluid_of(settings);
  run.reference_point_b = reference_b;
  run.sign = SignConvention::OnBody;
  run.source_line = loads.line;
  out.notes.push_back(input.path.string() + ": forces of " + what + " from the wall force summary at line " +
                      std::to_string(summary.line) +
                      (summary.summaries > 1 ? " (the last of " + std::to_string(summary.summaries) + ")" : "") +
                      ": the solver's values at the end of the run, pressure and viscous parts kept apart; no "
                      "history, so no steady window or standard error");
  out.batch.source.path = input.path.string();
  out.batch.source.sha256 = file.sha256;
  out.batch.source.size_bytes = file.bytes.size();
  out.batch.source.importer = std::string(kCfxOutImporter);
  out.batch.source.importer_version = std::string(kCfxOutImporterVersion);
  out.batch.runs.push_back(std::move(run));
  record_settings(out.batch, settings, "cfx-out", input.path);
  out.settings = std::move(settings);
  return out;
}

}  // namespace hydrocoef::reading
