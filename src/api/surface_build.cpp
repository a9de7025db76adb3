// The surface commands as library calls (include/hydrocoef/surface.hpp):
// surface_build, surface_rebuild, surface_list and surface_show, what
// `hydrocoef surface build | rebuild | list | show` print; the one check of a
// build's options (SurfaceBuildOptions::validate); and Database's
// build_surface and rebuild_surfaces, which are the same calls.
#include "src/api/internal.hpp"
#include "src/api/surface_report.hpp"

#include <optional>

#include "src/core/escape.hpp"
#include "src/surface/gp_surface.hpp"
#include "src/surface/grid_table.hpp"

namespace hydrocoef {
inline namespace api {
namespace {

void check_degree(int degree) {
  if (degree < 0 || degree > 2) throw InputError("--degree " + std::to_string(degree) + ": expected 0, 1 or 2");
}

/// The build specification the options describe (validate() first).
SurfaceBuildSpec build_spec(const SurfaceBuildOptions& options) {
  SurfaceBuildSpec spec;
  SurfaceSpec& surface = spec.surface;
  surface.axes = options.axes;
  surface.outputs = options.outputs;
  surface.method = options.method;
  surface.out_of_range = out_of_range_policies(options.axes, options.extrapolate, "--extrapolate");
  spec.where = options.where;
  spec.exclude_runs = options.exclude_runs;
  spec.mirror_planes = options.mirror;
  spec.mirror_odd = options.mirror_odd;
  if (options.method == "gp") {
    surface.gp.kernel = parse_gp_kernel(options.gp_kernel);
    surface.gp.mean_degree = options.gp_degree;
    surface.gp.starts = options.gp_starts;
    surface.gp.seed = options.gp_seed;
  } else {
    surface.rbf.kernel = parse_rbf_kernel(options.rbf_kernel);
  }
  surface.rbf.polynomial_degree = options.rbf_degree;
  surface.rbf.smoothing = options.rbf_smoothing;
  surface.resample_method = options.resample_method;
  surface.far_threshold = options.far_threshold;
  if (!options.resample.empty()) surface.resample = options.resample;
  return spec;
}

SurfaceInfo surface_info(const SurfaceRecord& record, const CoefficientSurface& surface) {
  return {record.name,           record.body,           record.kind,
          surface.method_name(), surface.axis_names(),  surface.output_names(),
          record.stale,          record.run_ids.size(), record.created_at};
}

SurfaceBuildResult build(Database& db, const SurfaceBuildOptions& options) {
  options.validate();
  const SurfaceBuildSpec spec = build_spec(options);
  auto& impl = Database::Access::impl(db);
  const std::lock_guard lock(impl.mutex);
  return build_and_store_surface(impl.writable_store("a surface build"), options.name, options.body, spec,
                                 options.replace ? RunDatabase::NameTaken::Replace : RunDatabase::NameTaken::Refuse);
}

std::vector<SurfaceBuildResult> rebuild(Database& db, const SurfaceRebuildOptions& options) {
  options.validate();
  auto& impl = Database::Access::impl(db);
  const std::lock_guard lock(impl.mutex);
  auto& store = impl.writable_store("a surface rebuild");
  std::vector<SurfaceBuildResult> out;
  for (const SurfaceRecord& record :
       surfaces_to_rebuild(store, options.name.empty() ? std::nullopt : std::optional(options.name),
                           options.body.empty() ? std::nullopt : std::optional(options.body), options.stale_only))
    out.push_back(rebuild_surface(store, record));
  return out;
}

}  // namespace

void SurfaceBuildOptions::validate() const {
  // In the order the command line has always checked them.
  if (method != "rbf" && method != "gp") parse_interpolation(method);
  (void)out_of_range_policies(axes, extrapolate, "--extrapolate");
  check_degree(rbf_degree);
  if (method == "gp") {
    check_degree(gp_degree);
    (void)parse_gp_kernel(gp_kernel);
    if (gp_starts < 1 || gp_starts > 100)
      throw InputError("--starts " + std::to_string(gp_starts) + ": expected 1 to 100");
  } else {
    (void)parse_rbf_kernel(rbf_kernel);
  }
  if (resample.empty()) return;
  if (method != "rbf") throw InputError("--resample tabulates an RBF surface; it needs --method rbf");
  if (resample.size() != axes.size())
    throw InputError("--resample: " + std::to_string(resample.size()) + " lists of breakpoints for " +
                     std::to_string(axes.size()) + " axes; expected one per axis, in the order of --axes");
  parse_interpolation(resample_method);
}

void SurfaceRebuildOptions::validate() const {}

SurfaceBuildReport surface_build(Database& db, const SurfaceBuildOptions& options) {
  return surface_text::build_report(build(db, options), db.path());
}

SurfaceRebuildReport surface_rebuild(Database& db, const SurfaceRebuildOptions& options) {
  SurfaceRebuildReport out;
  for (const SurfaceBuildResult& result : rebuild(db, options))
    out.rebuilt.push_back(surface_text::build_report(result, db.path()));
  return out;
}

std::string SurfaceRebuildReport::text() const {
  if (rebuilt.empty()) return "no surface to rebuild\n";
  std::string out;
  for (const auto& report : rebuilt) out += report.text();
  return out;
}

std::string SurfaceRebuildReport::json() const {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& report : rebuilt) out.push_back(nlohmann::json::parse(report.json()));
  return escape::json_text(out, 2) + '\n';
}

SurfaceList surface_list(const Database& db, const std::string& body) {
  auto& impl = Database::Access::impl(db);
  const std::lock_guard lock(impl.mutex);
  return surface_text::list_report(impl.open_store().surfaces(body.empty() ? std::nullopt : std::optional(body)),
                                   impl.path);
}

SurfaceReport surface_show(const Database& db, const std::string& name) {
  auto& impl = Database::Access::impl(db);
  const std::lock_guard lock(impl.mutex);
  const StoredSurface stored = load_surface(impl.open_store(), name);
  return surface_text::report(stored.record, stored.surface, nullptr);
}

SurfaceInfo Database::build_surface(const SurfaceBuildOptions& options) {
  const SurfaceBuildResult result = build(*this, options);
  return surface_info(result.stored.record, result.stored.surface);
}

std::vector<SurfaceInfo> Database::rebuild_surfaces(const std::string& name, bool stale_only) {
  std::vector<SurfaceInfo> out;
  for (const SurfaceBuildResult& result : rebuild(*this, {name, "", stale_only}))
    out.push_back(surface_info(result.stored.record, result.stored.surface));
  return out;
}

}  // namespace api
}  // namespace hydrocoef
