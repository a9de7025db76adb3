#include "src/pipeline/surface_build.hpp"

#include <nlohmann/json.hpp>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/names.hpp"
#include "src/core/numbers.hpp"
#include "src/core/run_selection.hpp"
#include "src/pipeline/fit_runs.hpp"
#include "src/pipeline/surface_mirror.hpp"
#include "src/surface/grid_table.hpp"

namespace hydrocoef {
namespace {

std::string surface_context(const SurfaceRecord& record) {
  return "surface '" + record.name + "'" + (record.database.empty() ? "" : " in " + record.database);
}

}  // namespace

SurfaceBuildResult build_and_store_surface(RunDatabase& database, const std::string& name, const std::string& body,
                                           const SurfaceBuildSpec& spec, RunDatabase::NameTaken taken) {
  check_name(NameKind::Surface, name, {}, "the surface name");
  check_name(NameKind::Body, body, {}, "the body");
  if (spec.surface.method != "rbf" && spec.surface.method != "gp")
    (void)parse_interpolation(spec.surface.method);  // before reading runs
  // What is stored must read back (a NaN threshold was stored as null and
  // then blocked every rebuild).
  if (!(spec.surface.far_threshold > 0.0) || !std::isfinite(spec.surface.far_threshold))
    throw InputError("--far-threshold " + shortest_number(spec.surface.far_threshold) +
                     ": expected a finite fraction of the runs' range > 0");
  if (!(spec.surface.rbf.smoothing >= 0.0) || !std::isfinite(spec.surface.rbf.smoothing))
    throw InputError("--smoothing " + shortest_number(spec.surface.rbf.smoothing) + ": expected a finite number >= 0");
  const RunSelection selection = parse_selection(spec.where, spec.exclude_runs);
  const MirrorSpec mirror = make_mirror_spec(spec.mirror_planes, spec.mirror_odd);
  // Reusing a name replaces what another build made: only when asked.
  if (taken == RunDatabase::NameTaken::Refuse)
    for (const auto& existing : database.surfaces())
      if (existing.name == name)
        throw InputError(SourceLocation{database.path().string()},
                         "a surface named '" + name + "' exists (built " + existing.created_at + " from " +
                             std::to_string(existing.run_ids.size()) +
                             " runs); give --replace to replace it, or another name");
  RunFilter filter;
  filter.body = body;
  const auto measured = selected_runs(database, filter, selection);
  if (measured.empty())
    throw InputError("no runs of body '" + body + "'" +
                     (selection.empty() ? "" : " matching '" + selection.text() + "'") + " in " +
                     database.path().string());
  std::size_t images_skipped = 0;
  const auto runs = with_mirror_images(measured, mirror, &images_skipped);
  SurfaceSpec surface_spec = spec.surface;
  surface_spec.symmetry = mirror_symmetry(mirror, spec.surface.axes, spec.surface.outputs, measured);
  const BuiltSurface built = build_surface(runs, surface_spec);
  SurfaceRecord record = built.record(name, body);
  auto definition = nlohmann::json::parse(record.definition);
  definition["build_spec"] = build_spec_json(spec);
  record.definition = escape::json_text(definition);
  database.save_surface(record);
  return SurfaceBuildResult{
      load_surface(database, name), measured.size(), runs.size() - measured.size(), images_skipped,
      built.runs_skipped,           mirror.text()};
}

SurfaceBuildSpec stored_build_spec(const SurfaceRecord& record) {
  const auto definition = nlohmann::json::parse(record.definition, nullptr, false);
  if (definition.is_discarded() || !definition.is_object())
    throw InputError(surface_context(record) + ": its definition is not JSON; expected what hydrocoef stores");
  if (!definition.contains("build_spec"))
    throw InputError("surface '" + record.name + "' was not built by hydrocoef surface build; it cannot be rebuilt");
  return parse_build_spec(definition["build_spec"], surface_context(record));
}

SurfaceBuildResult rebuild_surface(RunDatabase& database, const SurfaceRecord& record) {
  return build_and_store_surface(database, record.name, record.body, stored_build_spec(record),
                                 RunDatabase::NameTaken::Replace);
}

std::vector<SurfaceRecord> surfaces_to_rebuild(RunDatabase& database, const std::optional<std::string>& name,
                                               const std::optional<std::string>& body, bool stale_only) {
  std::vector<SurfaceRecord> targets;
  if (name) {
    targets.push_back(database.surface(*name));
    return targets;
  }
  for (auto& record : database.surfaces(body))
    if (record.stale || !stale_only) targets.push_back(std::move(record));
  return targets;
}

std::string built_from(const SurfaceRecord& record) {
  const auto definition = nlohmann::json::parse(record.definition, nullptr, false);
  if (definition.is_discarded() || !definition.contains("build_spec")) return "(not built by surface build)";
  try {
    const SurfaceBuildSpec spec = parse_build_spec(definition["build_spec"], surface_context(record));
    const std::string selection = parse_selection(spec.where, spec.exclude_runs).text();
    const std::string mirror = make_mirror_spec(spec.mirror_planes, spec.mirror_odd).text();
    return (selection.empty() ? std::string("all runs") : selection) + (mirror.empty() ? "" : ", mirror " + mirror);
  } catch (const InputError&) {
    return "(build specification not readable)";
  }
}

}  // namespace hydrocoef
