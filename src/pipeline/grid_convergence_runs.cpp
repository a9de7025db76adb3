#include "src/pipeline/grid_convergence_runs.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/names.hpp"
#include "src/core/numbers.hpp"
#include "src/core/sign_convention.hpp"

namespace hydrocoef {
namespace {

/// A run of a study with its level and cell size.
struct Level {
  const StoredRun* run = nullptr;
  double level = 0.0;
  double h = 0.0;
};

std::string run_text(const StoredRun& run) {
  return "run " + std::to_string(run.id) + " (" + escape::one_line(describe(run.key)) + ")";
}

std::string key_text(const RunKey& key) { return "key " + escape::one_line(describe(key)); }

/// Celik et al.'s premise for one component of a study: every value of a
/// history converged (or is a transient's or a given window's mean) and its
/// stated error is small against the change to the adjacent level(s).
/// InputError naming the level, the run and what to do, unless
/// allow_unconverged (then a note).
void check_iterative_convergence(const RunKey& key, std::size_t c, const std::vector<Level>& levels,
                                 const ComponentConvergence& component, const GridConvergenceRequest& request,
                                 std::vector<std::string>& notes) {
  const std::array<double, 2> change = {std::abs(component.phi[1] - component.phi[0]),
                                        std::abs(component.phi[2] - component.phi[1])};
  for (std::size_t i = 0; i < 3; ++i) {
    const std::string& kind = component.convergence[i];
    if (kind == "no history") continue;
    const double adjacent = i == 0 ? change[0] : i == 2 ? change[1] : std::min(change[0], change[1]);
    std::string problem;
    if (kind == "steady-window")
      problem = "did not converge (a steady run's mean over a window)";
    else if (kind == "not recorded")
      problem = "has no recorded convergence kind (imported by an older hydrocoef: import it again)";
    else if (component.iterative_error[i] > kMaxIterativeFraction * adjacent)
      problem = "has an " + std::string(kind == "converged" ? "iterative" : "statistical") + " error of " +
                shortest_number(component.iterative_error[i]) + ", more than " +
                shortest_number(kMaxIterativeFraction) + " of the change " + shortest_number(adjacent) +
                " to the adjacent mesh level";
    if (problem.empty()) continue;
    const std::string where = std::string(kForceNames[c]) + " at " + escape::one_line(request.mesh_parameter) + "=" +
                              shortest_number(levels[i].level) + " (" + run_text(*levels[i].run) + ", " + kind + ")";
    if (!request.allow_unconverged)
      throw InputError(key_text(key) + ": " + where + " " + problem +
                       "; expected converged values whose iterative error is small against the discretisation "
                       "error (Celik et al. 2008): converge the runs further, or give --allow-unconverged");
    notes.push_back(where + " " + problem + " (--allow-unconverged)");
  }
}

/// The run's representative cell size, from cell_size or cells.
std::pair<double, std::string> cell_size_of(const StoredRun& run, const GridConvergenceRequest& request) {
  const auto& d = run.key.disturbances;
  const auto size = d.find(std::string(kCellSizeParameter));
  const auto cells = d.find(std::string(kCellCountParameter));
  const std::string where = run_text(run) + ", at " + escape::one_line(request.mesh_parameter) + "=" +
                            shortest_number(d.at(request.mesh_parameter));
  if (size != d.end() && cells != d.end())
    throw InputError(where + ": has both cell_size and cells; expected one of them");
  if (size != d.end()) {
    if (!(size->second > 0.0))
      throw InputError(where + ": cell_size " + shortest_number(size->second) + "; expected a size > 0 in m");
    return {size->second, std::string(kCellSizeParameter)};
  }
  if (cells != d.end()) {
    if (!(cells->second >= 1.0))
      throw InputError(where + ": cells " + shortest_number(cells->second) + "; expected a cell count >= 1");
    return {representative_cell_size(cells->second, request.volume.value_or(1.0), request.dimension),
            std::string(kCellCountParameter)};
  }
  throw InputError(where + ": no cell size; expected a disturbance parameter cells (cell count) or cell_size (m)");
}

}  // namespace

GridConvergenceStudy grid_convergence_of_runs(RunDatabase& database, const GridConvergenceRequest& request) {
  check_name(NameKind::Body, request.body, {}, "--body");
  check_name(NameKind::Parameter, request.mesh_parameter, {}, "--mesh-param");
  if (request.mesh_parameter == kCellCountParameter || request.mesh_parameter == kCellSizeParameter)
    throw InputError("--mesh-param " + request.mesh_parameter + ": names a mesh size; expected the level parameter");
  if (request.dimension < 1 || request.dimension > 3)
    throw InputError("--dimension " + std::to_string(request.dimension) + ": expected 1, 2 or 3");
  if (request.volume && !(*request.volume > 0.0 && std::isfinite(*request.volume)))
    throw InputError("--volume " + shortest_number(*request.volume) + ": expected a finite volume > 0");

  RunFilter filter;
  filter.body = request.body;
  const auto runs = database.runs(filter);
  if (runs.empty())
    throw InputError("body '" + escape::one_line(request.body) + "' has no runs; expected runs at three mesh levels");

  GridConvergenceStudy study;
  study.body = request.body;
  study.mesh_parameter = request.mesh_parameter;
  // Physical key -> its runs with the level parameter.
  using Identity = std::tuple<std::array<double, 6>, std::string>;
  std::map<Identity, std::vector<const StoredRun*>> groups;
  for (const auto& run : runs) {
    if (!run.key.disturbances.contains(request.mesh_parameter)) {
      ++study.runs_without_level;
      continue;
    }
    std::array<double, 6> nu = run.key.nu_b;
    for (double& x : nu) x = x == 0.0 ? 0.0 : x;
    groups[{nu, disturbance_signature(physical_disturbances(run.key.disturbances, request.mesh_parameter))}].push_back(
        &run);
  }
  if (groups.empty())
    throw InputError("body '" + escape::one_line(request.body) + "': no run has the mesh level parameter '" +
                     escape::one_line(request.mesh_parameter) + "'; expected runs at three mesh levels marked " +
                     escape::one_line(request.mesh_parameter) + "=LEVEL with cells=N or cell_size=H");

  for (const auto& [identity, members] : groups) {
    RunKey key = members.front()->key;
    key.disturbances = physical_disturbances(key.disturbances, request.mesh_parameter);
    std::vector<Level> levels;
    for (const StoredRun* run : members) {
      const double level = run->key.disturbances.at(request.mesh_parameter);
      for (const auto& other : levels)
        if (other.level == level)
          throw InputError(key_text(key) + ": " + run_text(*other.run) + " and " + run_text(*run) + " are both at " +
                           escape::one_line(request.mesh_parameter) + "=" + shortest_number(level) +
                           " with different mesh sizes; expected one run per mesh level");
      levels.push_back({run, level, 0.0});
    }
    if (levels.size() == 1) {
      ++study.single_level_keys;
      continue;
    }
    KeyConvergence out;
    out.key = key;
    for (auto& level : levels) {
      const auto [h, from] = cell_size_of(*level.run, request);
      if (!out.size_from.empty() && out.size_from != from)
        throw InputError(key_text(key) +
                         ": some levels give cells and others cell_size; expected one of them "
                         "for every level of a key");
      out.size_from = from;
      level.h = h;
    }
    if (levels.size() == 2)
      throw InputError(key_text(key) + ": runs at 2 mesh levels (" + escape::one_line(request.mesh_parameter) + "=" +
                       shortest_number(levels[0].level) + ", " + shortest_number(levels[1].level) +
                       "); expected 3 or more for a grid-convergence study");
    std::sort(levels.begin(), levels.end(), [](const Level& a, const Level& b) { return a.h < b.h; });
    for (std::size_t i = 1; i < levels.size(); ++i)
      if (!(levels[i - 1].h < levels[i].h))
        throw InputError(key_text(key) + ": " + escape::one_line(request.mesh_parameter) + "=" +
                         shortest_number(levels[i - 1].level) + " and " + shortest_number(levels[i].level) +
                         " have the same cell size " + shortest_number(levels[i].h) +
                         "; expected a different size at each mesh level");
    for (const auto& level : levels) {
      out.levels.push_back(level.level);
      out.cell_sizes.push_back(level.h);
      out.run_ids.push_back(level.run->id);
    }
    if (levels.size() > 3) {
      std::string left_out;
      for (std::size_t i = 3; i < levels.size(); ++i)
        left_out += (left_out.empty() ? "" : ", ") + escape::one_line(request.mesh_parameter) + "=" +
                    shortest_number(levels[i].level);
      out.notes.push_back(std::to_string(levels.size()) + " mesh levels: the three finest are used (" + left_out +
                          " left out)");
    }
    const std::array<double, 3> h = {levels[0].h, levels[1].h, levels[2].h};
    for (std::size_t i = 0; i < 2; ++i) {
      const double r = h[i + 1] / h[i];
      const std::string pair = escape::one_line(request.mesh_parameter) + "=" + shortest_number(levels[i].level) +
                               " and " + shortest_number(levels[i + 1].level);
      if (!(r >= kMinRefinementRatio))
        throw InputError(key_text(key) + ": the refinement ratio of " + pair + " is " + shortest_number(r) +
                         "; expected at least " + shortest_number(kMinRefinementRatio) +
                         " (Celik et al. ask for more than 1.3): meshes that close cannot tell the order");
      if (r <= 1.3)
        out.notes.push_back("the refinement ratio of " + pair + " is " + shortest_number(r) +
                            ", not above 1.3 as Celik et al. ask");
    }
    for (std::size_t c = 0; c < 6; ++c) {
      std::size_t present = 0;
      for (std::size_t i = 0; i < 3; ++i) present += levels[i].run->tau_b[c] ? 1 : 0;
      if (present == 0) continue;
      if (present < 3) {
        out.notes.push_back(std::string(kForceNames[c]) + " is missing at " + std::to_string(3 - present) +
                            " of the three finest levels: no study of it");
        continue;
      }
      ComponentConvergence component;
      component.component = c;
      for (std::size_t i = 0; i < 3; ++i) {
        const StoredForce& force = *levels[i].run->tau_b[c];
        component.phi[i] = to_on_body(force.value.total, force.sign);
      }
      for (std::size_t i = 0; i < 3; ++i) {
        const StoredForce& force = *levels[i].run->tau_b[c];
        component.convergence[i] = !force.statistics                       ? "no history"
                                   : force.statistics->convergence.empty() ? "not recorded"
                                                                           : force.statistics->convergence;
        component.iterative_error[i] = force.statistics ? force.statistics->values.standard_error : 0.0;
      }
      check_iterative_convergence(key, c, levels, component, request, out.notes);
      component.result = grid_convergence_index(h, component.phi);
      const GciResult& r = component.result;
      const bool has_gci = r.convergence != GridConvergence::NotFound && std::isfinite(r.gci_fine) &&
                           std::isfinite(r.extrapolated) && std::isfinite(r.relative_error) &&
                           std::isfinite(r.extrapolated_relative_error);
      if (r.convergence != GridConvergence::NotFound && !has_gci) {
        component.result.convergence = GridConvergence::NotFound;
        component.result.note = "the finest value (or the extrapolated one) is 0: relative errors are undefined";
      }
      if (component.result.convergence != GridConvergence::NotFound)
        component.numerical_uncertainty = r.gci_fine * std::abs(component.phi[0]) / kGciCoverageFactor;
      out.components.push_back(component);
    }
    study.keys.push_back(std::move(out));
  }
  if (study.keys.empty())
    throw InputError("body '" + escape::one_line(request.body) + "': " + std::to_string(study.single_level_keys) +
                     " key(s) with the parameter '" + escape::one_line(request.mesh_parameter) +
                     "', each at one mesh level; expected a key with runs at 3 or more mesh levels");
  return study;
}

std::vector<NumericalUncertaintyRecord> numerical_uncertainty_records(const GridConvergenceStudy& study) {
  std::vector<NumericalUncertaintyRecord> out;
  const std::string now = utc_timestamp_now();
  for (const auto& key : study.keys) {
    for (const auto& component : key.components) {
      const GciResult& r = component.result;
      NumericalUncertaintyRecord record;
      record.key = key.key;
      record.component = component.component;
      record.mesh_parameter = study.mesh_parameter;
      record.fine_level = key.levels.front();
      record.levels = key.levels.size();
      record.h = {key.cell_sizes[0], key.cell_sizes[1], key.cell_sizes[2]};
      record.phi = component.phi;
      record.convergence = std::string(grid_convergence_name(r.convergence));
      if (r.convergence == GridConvergence::Monotonic || r.convergence == GridConvergence::Oscillatory)
        record.apparent_order = r.apparent_order;
      if (r.convergence != GridConvergence::NotFound) {
        record.extrapolated = r.extrapolated;
        record.relative_error = r.relative_error;
        record.extrapolated_relative_error = r.extrapolated_relative_error;
        record.gci_fine = r.gci_fine;
      }
      record.numerical_uncertainty = component.numerical_uncertainty;
      record.note = r.note;
      record.created_at = now;
      out.push_back(std::move(record));
    }
    // A key whose components all lack a level stores nothing new; its old
    // rows stay. Keys with components replace their rows (save_numerical_uncertainties).
  }
  return out;
}

StoredStudy store_grid_convergence(RunDatabase& database, const GridConvergenceStudy& study) {
  const auto stale = [&] {
    const auto fits = database.fits(study.body);
    const auto surfaces = database.surfaces(study.body);
    return StoredStudy{
        static_cast<std::size_t>(std::count_if(fits.begin(), fits.end(), [](const FitRecord& f) { return f.stale; })),
        static_cast<std::size_t>(
            std::count_if(surfaces.begin(), surfaces.end(), [](const SurfaceRecord& s) { return s.stale; }))};
  };
  const StoredStudy before = stale();
  database.save_numerical_uncertainties(numerical_uncertainty_records(study));
  const StoredStudy after = stale();
  return {after.fits_made_stale - before.fits_made_stale, after.surfaces_made_stale - before.surfaces_made_stale};
}

}  // namespace hydrocoef
