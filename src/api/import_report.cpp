// What `hydrocoef import` prints (ImportSummary::text, json): one line per
// input and a summary, or the JSON of every input, the totals, the stage
// times and the notes.
#include "src/api/internal.hpp"
#include "src/api/records_format.hpp"
#include "src/api/records_report.hpp"
#include "src/core/escape.hpp"

#include <sstream>

namespace hydrocoef {
namespace records {
namespace {

/// One line for a stored input: where, what, which run, its forces.
std::string input_line(const ImportedInput& input, const ImportOutcome& outcome) {
  const auto& runs = input.batch.runs;
  std::string line = input.input.path.string() + ": " + input.format + ", ";
  if (outcome.already_imported)
    return line + "already imported (same bytes and settings as " + outcome.previous_path + ", imported " +
           outcome.previously_imported_at + "); nothing added";
  if (runs.size() == 1) {
    line += describe(runs.front().key);
  } else {
    line += std::to_string(runs.size()) + " runs of body '" + runs.front().key.body + "'";
  }
  line += " (" + std::to_string(outcome.runs_created) + " new, " + std::to_string(outcome.runs_extended) + " extended" +
          (outcome.replaced ? "; replaces its import of " + outcome.previously_imported_at : std::string()) + ")";
  if (runs.size() == 1) {
    const auto& run = runs.front();
    std::string forces;
    for (std::size_t i = 0; i < 6; ++i) {
      if (!run.tau_b[i]) continue;
      forces += std::string(forces.empty() ? "" : " ") + std::string(kForceNames[i]) + "=" +
                significant(run.tau_b[i]->total, 4);
      if (run.statistics && run.statistics->components[i])
        forces += "±" + significant(run.statistics->components[i]->standard_error, 2);
    }
    if (!forces.empty()) line += ": " + forces;
    if (run.statistics) {
      line += " [" + run.statistics->convergence;
      for (std::size_t i = 0; i < 6; ++i)
        for (const auto& flag : run.statistics->windows[i].flags)
          line += ", " + std::string(kForceNames[i]) + " " + flag;
      line += "]";
    }
  }
  return line;
}

nlohmann::json statistics_json(const RunStatistics& s) {
  nlohmann::json out = {{"abscissa", s.abscissa},
                        {"convergence", s.convergence},
                        {"convergence_reason", s.convergence_reason},
                        {"flags", s.flags},
                        {"components", nlohmann::json::object()}};
  for (std::size_t i = 0; i < 6; ++i)
    if (const auto& c = s.components[i]) {
      const ComponentWindow& w = s.windows[i];
      out["components"][std::string(kForceNames[i])] = {{"standard_error", c->standard_error},
                                                        {"spread", c->spread},
                                                        {"drift", c->drift},
                                                        {"effective_samples", c->effective_samples},
                                                        {"window", w.method},
                                                        {"window_first", w.first},
                                                        {"window_last", w.last},
                                                        {"samples", w.samples},
                                                        {"flags", w.flags}};
    }
  return out;
}

/// An integrated surface export, as `hydrocoef integrate --json` gives it.
nlohmann::json surface_run_json(const SurfaceRun& run) {
  const auto& l = run.loads_b;
  const auto& g = l.geometry;
  const auto& key = run.batch.runs.front().key;
  return {{"file", run.batch.source.path},
          {"format", run.format},
          {"key", key_json(key)},
          {"frame", "body axes (x forward, y starboard, z down); forces on the body"},
          {"axes", run.batch.runs.front().surface->axes},
          {"reference_point", l.reference_point},
          {"force_pressure", l.force_pressure},
          {"force_viscous", l.force_viscous},
          {"force", l.force()},
          {"moment_pressure", l.moment_pressure},
          {"moment_viscous", l.moment_viscous},
          {"moment", l.moment()},
          {"area", g.area},
          {"faces", g.faces},
          {"triangles", g.triangles},
          {"quads", g.quads},
          {"polygons", g.polygons},
          {"closed", g.closed},
          {"boundary_edges", g.boundary_edges},
          {"degenerate_faces", g.degenerate_faces},
          {"signed_volume", g.signed_volume},
          {"normals_flipped", g.normals_flipped},
          {"integral_n_dA", g.integral_n_dA},
          {"integral_x_cross_n_dA", g.integral_x_cross_n_dA},
          {"pressure_array", run.pressure_array},
          {"shear_array", run.shear_array},
          {"pressure_kind", run.pressure_kind == PressureKind::Static ? "static" : "kinematic"},
          {"shear_convention", run.shear_convention == ShearConvention::OnWall ? "on-wall" : "on-fluid"},
          {"warnings", run.warnings}};
}

std::string import_json(const ImportResult& result, const std::string& database) {
  const auto& [plan, inputs, outcomes, notes, runs, created, extended, already, replaced, plan_s, read_s, store_s] =
      result;
  nlohmann::json out;
  out["database"] = database;
  out["files"] = nlohmann::json::array();
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const auto& o = outcomes[i];
    const auto& input = inputs[i];
    nlohmann::json file = {
        {"path", o.path},
        {"format", input.format},
        {"sha256", o.sha256},
        {"status", o.already_imported ? "already_imported"
                   : o.replaced       ? "replaced"
                                      : "imported"},
        {"import_id", o.import_id},
        {"reading", o.reading},
        {"runs_in_file", input.batch.runs.size()},
        {"runs_created", o.runs_created},
        {"runs_extended", o.runs_extended},
        {"components_written", o.components_written},
        {"settings", nlohmann::json::parse(input.batch.source.settings.empty() ? "{}" : input.batch.source.settings)},
        {"notes", input.notes}};
    if (o.already_imported) {
      file["previous_path"] = o.previous_path;
      file["previously_imported_at"] = o.previously_imported_at;
    }
    if (input.batch.runs.size() == 1) {
      file["key"] = key_json(input.batch.runs.front().key);
      if (input.batch.runs.front().statistics)
        file["statistics"] = statistics_json(*input.batch.runs.front().statistics);
    }
    if (input.surface) file["surface"] = surface_run_json(*input.surface);
    if (input.history) file["history_notes"] = input.history->notes;
    out["files"].push_back(file);
  }
  out["summary"] = {
      {"files", outcomes.size()},    {"runs", runs},         {"runs_created", created},  {"runs_extended", extended},
      {"already_imported", already}, {"replaced", replaced}, {"excluded", plan.excluded}};
  // plan: the folder walk, sidecars and case files' settings; read: parsing,
  // integration and window analysis of every input (on every core); store:
  // the one transaction.
  out["timing_s"] = {{"plan", plan_s}, {"read", read_s}, {"store", store_s}};
  out["notes"] = nlohmann::json::array();
  for (const auto& [text, count] : notes) out["notes"].push_back({{"note", text}, {"count", count}});
  return escape::json_text(out, 2) + '\n';
}

std::string summary_line(const ImportResult& result, const std::string& database) {
  const std::size_t files = result.outcomes.size(), created = result.runs_created;
  std::ostringstream line;
  line << "imported " << files << (files == 1 ? " input" : " inputs") << " into " << escape::one_line(database) << ": "
       << created << " new " << (created == 1 ? "run" : "runs") << ", " << result.runs_extended << " extended, "
       << result.already_imported << " already imported"
       << (result.replaced ? ", " + std::to_string(result.replaced) + " replaced" : std::string())
       << (result.plan.excluded ? ", " + std::to_string(result.plan.excluded) + " left out by the filters"
                                : std::string())
       << ", " << result.notes.size() << (result.notes.size() == 1 ? " note" : " notes") << '\n';
  return line.str();
}

}  // namespace

ImportSummary import_summary(const ImportResult& result, const std::string& database) {
  const auto& inputs = result.inputs;
  const auto& outcomes = result.outcomes;
  ImportSummary summary;
  for (const auto& [text, count] : result.notes) summary.notes.push_back(text);
  summary.excluded = result.plan.excluded;
  for (std::size_t i = 0; i < outcomes.size() && i < inputs.size(); ++i) {
    const ImportOutcome& o = outcomes[i];
    summary.files.push_back({o.path, inputs[i].format, inputs[i].batch.runs.size(), o.runs_created, o.runs_extended,
                             o.already_imported, o.replaced, inputs[i].notes});
  }
  summary.runs_created = result.runs_created;
  summary.runs_extended = result.runs_extended;
  summary.already_imported = result.already_imported;
  summary.replaced = result.replaced;
  summary.database = database;

  // Paths, previous paths, bodies and notes come from outside: one printable line each.
  std::string text;
  for (std::size_t i = 0; i < outcomes.size(); ++i) text += escape::one_line(input_line(inputs[i], outcomes[i])) + '\n';
  for (const auto& [note, count] : result.notes)
    text += "note" + (count > 1 ? " (" + std::to_string(count) + " inputs)" : std::string()) + ": " +
            escape::one_line(note) + '\n';
  const std::string line = summary_line(result, database);
  ImportSummary::Access::set(summary, text + line, line, import_json(result, database));
  return summary;
}

std::string surface_run_json_text(const SurfaceRun& run, const ImportedInput& input) {
  nlohmann::json out = surface_run_json(run);
  out["settings"] = nlohmann::json::parse(input.batch.source.settings.empty() ? "{}" : input.batch.source.settings);
  return escape::json_text(out, 2) + '\n';
}

}  // namespace records

inline namespace api {
std::string ImportSummary::text(bool quiet) const { return quiet ? summary_line_ : text_; }
std::string ImportSummary::json() const { return json_; }
}  // namespace api

}  // namespace hydrocoef
