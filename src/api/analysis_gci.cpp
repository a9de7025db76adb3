// grid_convergence (include/hydrocoef/analysis.hpp): `hydrocoef gci` without
// its printing. The study is src/pipeline/grid_convergence_runs; its numbers
// become the public GciStudy here, its text and JSON are
// src/api/analysis_gci_report.cpp.
#include "src/api/internal.hpp"

#include <cmath>

#include "hydrocoef/analysis.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/pipeline/grid_convergence_runs.hpp"

namespace hydrocoef {
inline namespace api {
namespace {

GridConvergenceRequest request_of(const GciOptions& options) {
  GridConvergenceRequest request;
  request.body = options.body;
  request.mesh_parameter = options.mesh_parameter;
  request.volume = options.volume;
  request.dimension = options.dimension;
  request.allow_unconverged = options.allow_unconverged;
  return request;
}

std::optional<double> present(bool found, double value) { return found ? std::optional<double>(value) : std::nullopt; }

GciStudy study_of(const GridConvergenceStudy& study, const GciOptions& options) {
  GciStudy out;
  out.body = study.body;
  out.mesh_parameter = study.mesh_parameter;
  out.coverage_factor = kGciCoverageFactor;
  out.dimension = options.dimension;
  out.volume_given = options.volume.has_value();
  out.single_level_keys = study.single_level_keys;
  out.runs_without_level = study.runs_without_level;
  for (const KeyConvergence& key : study.keys) {
    GciKey k;
    k.body = key.key.body;
    for (std::size_t i = 0; i < 6; ++i) k.velocity[i] = key.key.nu_b[i];
    for (const auto& [name, value] : key.key.disturbances) k.disturbances[name] = value;
    k.description = describe(key.key);
    k.levels = key.levels;
    k.cell_sizes = key.cell_sizes;
    k.runs = key.run_ids;
    k.cell_size_from = key.size_from;
    k.notes = key.notes;
    for (const ComponentConvergence& c : key.components) {
      const GciResult& r = c.result;
      const bool order = r.convergence == GridConvergence::Monotonic || r.convergence == GridConvergence::Oscillatory;
      const bool found = r.convergence != GridConvergence::NotFound;
      GciComponent component;
      component.component = std::string(kForceNames[c.component]);
      component.phi = c.phi;
      component.r21 = r.r21;
      component.r32 = r.r32;
      component.convergence = std::string(grid_convergence_name(r.convergence));
      component.apparent_order = present(order, r.apparent_order);
      component.extrapolated = present(found, r.extrapolated);
      component.relative_error = present(found, r.relative_error);
      component.extrapolated_relative_error = present(found, r.extrapolated_relative_error);
      component.gci_fine = present(found, r.gci_fine);
      component.gci_medium = present(order, r.gci_medium);
      component.asymptotic_ratio = present(order, r.asymptotic_ratio);
      component.numerical_uncertainty = c.numerical_uncertainty;
      component.values_convergence = c.convergence;
      component.values_error = c.iterative_error;
      component.note = r.note;
      k.components.push_back(std::move(component));
    }
    out.keys.push_back(std::move(k));
  }
  return out;
}

}  // namespace

void GciOptions::validate() const {
  check_name(NameKind::Body, body, {}, "--body");
  check_name(NameKind::Parameter, mesh_parameter, {}, "--mesh-param");
  if (mesh_parameter == kCellCountParameter || mesh_parameter == kCellSizeParameter)
    throw InputError("--mesh-param " + mesh_parameter + ": names a mesh size; expected the level parameter");
  if (dimension < 1 || dimension > 3)
    throw InputError("--dimension " + std::to_string(dimension) + ": expected 1, 2 or 3");
  if (volume && !(*volume > 0.0 && std::isfinite(*volume)))
    throw InputError("--volume " + shortest_number(*volume) + ": expected a finite volume > 0");
}

GciStudy grid_convergence(Database& database, const GciOptions& options) {
  options.validate();
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  RunDatabase& store = options.store ? impl.writable_store("the gci study") : impl.open_store();
  const GridConvergenceStudy study = grid_convergence_of_runs(store, request_of(options));
  GciStudy out = study_of(study, options);
  if (options.store) {
    const StoredStudy stored = store_grid_convergence(store, study);
    out.stored = true;
    out.fits_made_stale = stored.fits_made_stale;
    out.surfaces_made_stale = stored.surfaces_made_stale;
  }
  return out;
}

}  // namespace api
}  // namespace hydrocoef
