// RunDatabase::merge and RunDatabase::copy_from: shards made by cluster jobs into
// one database, and a whole database from one backend to another.
#include <algorithm>
#include <limits>
#include <map>
#include <set>
#include <tuple>

#include "src/core/error.hpp"
#include "src/core/names.hpp"
#include "src/core/numbers.hpp"
#include "src/store/backend.hpp"
#include "src/store/checked_row.hpp"
#include "src/store/database.hpp"
#include "src/store/derivative_store.hpp"
#include "src/store/pmm_record.hpp"
#include "src/store/run_rows.hpp"

namespace hydrocoef {
namespace {

using store::canonical;

bool same_fit(const FitRecord& a, const FitRecord& b) {
  if (std::tie(a.body, a.dof, a.variable, a.terms, a.loss, a.run_filter, a.mirror, a.weighting, a.n) !=
          std::tie(b.body, b.dof, b.variable, b.terms, b.loss, b.run_filter, b.mirror, b.weighting, b.n) ||
      a.sign != b.sign || a.coefficients.size() != b.coefficients.size() || a.covariance != b.covariance)
    return false;
  for (std::size_t i = 0; i < a.coefficients.size(); ++i)
    if (a.coefficients[i].term != b.coefficients[i].term || a.coefficients[i].value != b.coefficients[i].value ||
        a.coefficients[i].std_error != b.coefficients[i].std_error)
      return false;
  return true;
}

bool same_derivative_model(const DerivativeModelRecord& a, const DerivativeModelRecord& b) {
  if (std::tie(a.body, a.output, a.terms, a.run_filter, a.weighting, a.n, a.covariance) !=
          std::tie(b.body, b.output, b.terms, b.run_filter, b.weighting, b.n, b.covariance) ||
      a.coefficients.size() != b.coefficients.size())
    return false;
  for (std::size_t i = 0; i < a.coefficients.size(); ++i)
    if (a.coefficients[i].term != b.coefficients[i].term || a.coefficients[i].value != b.coefficients[i].value ||
        a.coefficients[i].std_error != b.coefficients[i].std_error)
      return false;
  return true;
}

bool same_surface(const SurfaceRecord& a, const SurfaceRecord& b) {
  return std::tie(a.body, a.kind, a.method, a.definition, a.quality, a.data) ==
         std::tie(b.body, b.kind, b.method, b.definition, b.quality, b.data);
}

std::string pmm_identity(const PmmRecord& r) {
  return r.body + "\n" + r.source_sha256 + "\n" + std::to_string(r.dof) + "\n" + shortest_number(r.amplitude) + "\n" +
         shortest_number(r.omega) + "\n" + shortest_number(canonical(r.phase)) + "\n" + pmm_medium_name(r.medium);
}

}  // namespace

std::vector<MergeOutcome> RunDatabase::merge(const std::vector<std::string>& shards,
                                             const std::function<void(std::size_t, std::size_t)>& progress) {
  if (read_only_) throw InputError(SourceLocation{path_.string()}, "database opened read-only; cannot merge into it");
  std::vector<MergeOutcome> out;
  store::Transaction transaction(connection_);
  for (std::size_t i = 0; i < shards.size(); ++i) {
    RunDatabase shard(shards[i], OpenMode::ReadOnly);
    out.push_back(merge_one(shard));
    if (progress) progress(i + 1, shards.size());
  }
  transaction.commit();
  use_wal();
  return out;
}

MergeOutcome RunDatabase::merge_one(RunDatabase& shard) {
  // Every read of the shard sees one state of it, even while a job writes it.
  const store::detail::ReadSnapshot shard_snapshot(shard.connection_.backend_impl());
  MergeOutcome outcome;
  outcome.shard = shard.path().string();
  const SourceLocation where{outcome.shard};
  constexpr std::int64_t kMost = std::numeric_limits<std::int64_t>::max();

  // The files, by the SHA-256 of their bytes.
  store::RunRows rows(connection_);
  std::map<std::int64_t, std::int64_t> source_of;  // shard id -> id here
  for (const SourceRecord& source : shard.sources())
    source_of[source.id] = rows.source_id(source.provenance, source.imported_at);
  const auto mapped_source = [&](std::int64_t id) {
    const auto found = source_of.find(id);
    if (found == source_of.end())
      throw InputError(where, "a force refers to source file " + std::to_string(id) +
                                  ", which the shard does not have; expected every reference to hold");
    return found->second;
  };

  // The imports: a file's bytes read with one set of settings. One already
  // here with the same settings adds nothing; with other settings it is
  // refused, as a second import would be.
  std::map<std::int64_t, std::int64_t> import_of;
  std::set<std::int64_t> imports_here;  // shard imports that were here before
  {
    std::vector<std::int64_t> ids;
    auto list = shard.connection_.prepare("SELECT id FROM import ORDER BY id");
    while (list.step()) ids.push_back(store::CheckedRow(list, outcome.shard, "import", 0).integer(0, 1, kMost));
    auto find = connection_.prepare(
        "SELECT id, settings_key, path, imported_at FROM import WHERE source_id = ? AND reading = ?");
    auto insert = connection_.prepare(
        "INSERT INTO import(source_id, reading, settings_key, settings, path, resolved_path, importer, "
        "importer_version, hydrocoef_version, imported_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?) RETURNING id");
    for (const std::int64_t id : ids) {
      const auto record = shard.import_record(id);
      if (!record)
        throw InputError(where, "table 'import', row " + std::to_string(id) +
                                    ": its file is not in table 'source_file'; expected the file of each import");
      const std::int64_t source = mapped_source(record->source_id);
      find.bind(1, source).bind(2, record->reading);
      if (find.step()) {
        const std::int64_t here = find.get_int(0);
        const std::string key = find.get_text(1), path = find.get_text(2), at = find.get_text(3);
        find.reset();
        if (key != record->settings_key)
          throw InputError(where, "'" + printable_text(record->path, 80) + "' (SHA-256 " +
                                      record->sha256.substr(0, 12) + "...) is imported here already, on " + at +
                                      " from '" + printable_text(path, 80) +
                                      "', with other settings; expected the same settings, or the runs of one of "
                                      "the two imports deleted first (hydrocoef runs delete)");
        import_of[id] = here;
        imports_here.insert(id);
        ++outcome.imports_already;
        continue;
      }
      find.reset();
      insert.bind(1, source)
          .bind(2, record->reading)
          .bind(3, record->settings_key)
          .bind(4, record->settings)
          .bind(5, record->path)
          .bind(6, record->resolved_path)
          .bind(7, record->importer)
          .bind(8, record->importer_version)
          .bind(9, record->hydrocoef_version)
          .bind(10, record->imported_at);
      import_of[id] = store::returned_id(insert);
      ++outcome.imports_added;
    }
  }

  // The runs, by body and key, and their force components.
  std::map<std::int64_t, std::int64_t> run_of;
  std::map<std::int64_t, std::int64_t> surface_source;  // shard run id -> shard source id
  {
    auto list = shard.connection_.prepare("SELECT run_id, source_id FROM run_surface");
    while (list.step()) {
      const store::CheckedRow row(list, outcome.shard, "run_surface", list.get_int(0));
      surface_source[row.integer(0, 1, kMost)] = row.integer(1, 1, kMost);
    }
  }
  auto existing_force = connection_.prepare(
      "SELECT s.path, f.source_line, f.import_id FROM run_force f JOIN source_file s ON s.id = f.source_id "
      "WHERE f.run_id = ? AND f.component = ?");
  auto surface_here = connection_.prepare(
      "SELECT s.path, r.source_id FROM run_surface r JOIN source_file s ON s.id = r.source_id WHERE r.run_id = ?");
  for (const StoredRun& run : shard.runs()) {
    const auto [here, created] = find_or_insert_run(rows, run.key, run.fluid, run.reference_point_b, where);
    if (created) ++outcome.runs_created;
    run_of[run.id] = here;

    bool extended = false;
    for (std::size_t i = 0; i < 6; ++i) {
      const auto& force = run.tau_b[i];
      if (!force) continue;
      const std::string component(kForceNames[i]);
      existing_force.bind(1, here).bind(2, component);
      if (existing_force.step()) {
        const std::string previous = existing_force.get_text(0) + ":" + existing_force.get_text(1);
        const std::int64_t previous_import = existing_force.is_null(2) ? 0 : existing_force.get_int(2);
        existing_force.reset();
        // The same import, here before: the same value.
        if (force->import_id != 0 && imports_here.count(force->import_id) &&
            import_of.at(force->import_id) == previous_import)
          continue;
        throw InputError(where, "run " + describe(run.key) + " has " + component + " from '" +
                                    printable_text(force->source_path, 80) + "' and here from " +
                                    printable_text(previous, 80) +
                                    "; expected each component of a run from one file (delete one of them first)");
      }
      existing_force.reset();
      std::optional<std::int64_t> import_id;
      if (force->import_id != 0) {
        if (!import_of.count(force->import_id))
          throw InputError(where, "run " + describe(run.key) + ": " + component + " names import " +
                                      std::to_string(force->import_id) +
                                      ", which table 'import' does not hold; expected the import of each force");
        import_id = import_of.at(force->import_id);
      }
      rows.write_force(here, i, force->value, force->sign, mapped_source(force->source_id), force->source_line,
                       import_id);
      if (force->statistics) {
        rows.write_statistics(here, i, *force->statistics);
      }
      ++outcome.components;
      extended = true;
    }
    if (extended && !created) ++outcome.runs_extended;
    // The shard's trace comes with the components it merged (as an import's does).
    if (extended) {
      if (const auto trace = shard.run_trace(run.id))
        rows.write_trace(here, *trace);
      else
        rows.drop_trace(here);
    }
    if (run.surface && surface_source.count(run.id)) {
      // A run's surface integrals come from one file, as its forces do.
      const std::int64_t source = mapped_source(surface_source.at(run.id));
      surface_here.bind(1, here);
      if (surface_here.step()) {
        const std::string previous = surface_here.get_text(0);
        const std::int64_t previous_source = surface_here.get_int(1);
        surface_here.reset();
        if (previous_source != source)
          throw InputError(where, "run " + describe(run.key) + " has its surface integrals from another file than " +
                                      "here ('" + printable_text(previous, 80) +
                                      "'); expected a run's surface from one file (delete one of them first)");
      } else {
        surface_here.reset();
        rows.write_surface(here, source, *run.surface);
      }
    }
  }
  const auto mapped_runs = [&](const std::vector<std::int64_t>& ids) {
    std::vector<std::int64_t> out;
    for (const auto id : ids)
      if (const auto found = run_of.find(id); found != run_of.end()) out.push_back(found->second);
    std::sort(out.begin(), out.end());
    return out;
  };

  // Mesh studies, by body and physical key: the same rows, or none here.
  {
    const auto key_of = [](const NumericalUncertaintyRecord& r) {
      return r.key.body + "\n" + shortest_number(r.key.nu_b[0]) + "," + shortest_number(r.key.nu_b[1]) + "," +
             shortest_number(r.key.nu_b[2]) + "," + shortest_number(r.key.nu_b[3]) + "," +
             shortest_number(r.key.nu_b[4]) + "," + shortest_number(r.key.nu_b[5]) + "\n" +
             disturbance_signature(r.key.disturbances);
    };
    std::map<std::string, std::vector<NumericalUncertaintyRecord>> here, theirs;
    for (auto& r : numerical_uncertainties()) here[key_of(r)].push_back(std::move(r));
    for (auto& r : shard.numerical_uncertainties()) theirs[key_of(r)].push_back(std::move(r));
    std::vector<NumericalUncertaintyRecord> added;
    for (auto& [key, records] : theirs) {
      const auto found = here.find(key);
      if (found == here.end()) {
        outcome.mesh_studies_added += records.size();
        for (auto& r : records) added.push_back(std::move(r));
        continue;
      }
      bool same = found->second.size() == records.size();
      for (std::size_t i = 0; same && i < records.size(); ++i)
        same = found->second[i].component == records[i].component && found->second[i].phi == records[i].phi &&
               found->second[i].h == records[i].h && found->second[i].fine_level == records[i].fine_level;
      if (!same)
        throw InputError(where, "the mesh study of run " + describe(records.front().key) +
                                    " differs from the one here; expected the same study (hydrocoef gci)");
      outcome.mesh_studies_already += records.size();
    }
    if (!added.empty()) save_numerical_uncertainties(added);
  }

  // Forced-oscillation analyses, by body, file and motion.
  {
    std::set<std::string> here;
    for (const auto& r : pmm_records(std::nullopt, false)) here.insert(pmm_identity(r));
    std::vector<PmmRecord> added;
    for (auto& r : shard.pmm_records(std::nullopt, true)) {
      if (here.count(pmm_identity(r))) {
        ++outcome.pmm_already;
        continue;
      }
      added.push_back(std::move(r));
    }
    outcome.pmm_added = added.size();
    if (!added.empty()) save_pmm(added);
  }
  // The bodies' reference data: one a body has here must be the same.
  merge_body_references(shard, outcome);
  // Fits and surfaces by name: one of the same name here must be the same.
  auto keep_record = [&](const char* table, std::int64_t id, const std::string& created_at, bool stale) {
    connection_.prepare(std::string("UPDATE ") + table + " SET created_at = ?, stale = ? WHERE id = ?")
        .bind(1, created_at)
        .bind(2, static_cast<std::int64_t>(stale))
        .bind(3, id)
        .run();
  };
  {
    std::map<std::string, FitRecord> here;
    for (auto& fit : fits()) here.emplace(fit.name, std::move(fit));
    for (FitRecord fit : shard.fits()) {
      if (const auto found = here.find(fit.name); found != here.end()) {
        if (!same_fit(found->second, fit))
          throw InputError(where, "fit '" + fit.name +
                                      "' is here already with other terms or coefficients; expected the same fit, "
                                      "or one of them renamed or deleted first");
        ++outcome.fits_already;
        continue;
      }
      fit.run_ids = mapped_runs(fit.run_ids);
      const std::int64_t id = insert_fit(fit);
      keep_record("fit", id, fit.created_at, fit.stale);
      ++outcome.fits_added;
    }
  }
  {
    std::map<std::string, SurfaceRecord> here;
    for (auto& surface : surfaces()) here.emplace(surface.name, std::move(surface));
    for (SurfaceRecord surface : shard.surfaces()) {
      if (const auto found = here.find(surface.name); found != here.end()) {
        if (!same_surface(found->second, surface))
          throw InputError(where, "surface '" + surface.name +
                                      "' is here already with other values; expected the same surface, or one of "
                                      "them renamed first");
        ++outcome.surfaces_already;
        continue;
      }
      surface.run_ids = mapped_runs(surface.run_ids);
      const std::int64_t id = save_surface(surface);
      keep_record("surface", id, surface.created_at, surface.stale);
      ++outcome.surfaces_added;
    }
  }
  // Derivative models by name, as fits (schema/0018_derivative_models.sql).
  {
    std::map<std::string, DerivativeModelRecord> here;
    for (auto& model : derivative_models()) here.emplace(model.name, std::move(model));
    for (DerivativeModelRecord model : shard.derivative_models()) {
      if (const auto found = here.find(model.name); found != here.end()) {
        if (!same_derivative_model(found->second, model))
          throw InputError(where, "derivative model '" + printable_text(model.name, 160) +
                                      "' is here already with other terms or coefficients; expected the same model, "
                                      "or one of them renamed or deleted first");
        ++outcome.derivative_models_already;
        continue;
      }
      model.run_ids = mapped_runs(model.run_ids);
      const std::int64_t id = save_derivative_model(model, NameTaken::Refuse);
      keep_record("derivative_model", id, model.created_at, model.stale);
      ++outcome.derivative_models_added;
    }
  }

  return outcome;
}

}  // namespace hydrocoef
