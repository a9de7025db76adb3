// How the CLI reports an import: one line per input and a summary, or JSON.
#include "cli/import_output.hpp"

#include <iostream>

#include "cli/common.hpp"
#include "cli/surface_options.hpp"
#include "src/core/escape.hpp"

namespace hydrocoef::cli {
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

}  // namespace

void print_import(const ImportResult& result, const std::string& database, bool json, bool quiet) {
  const auto& [plan, inputs, outcomes, notes, runs, created, extended, already, replaced, plan_s, read_s, store_s] =
      result;
  if (json) {
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
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  if (!quiet) {
    // Paths, previous paths, bodies and notes come from outside: one printable line each.
    for (std::size_t i = 0; i < outcomes.size(); ++i)
      std::cout << escape::one_line(input_line(inputs[i], outcomes[i])) << '\n';
    for (const auto& [text, count] : notes)
      std::cout << "note" << (count > 1 ? " (" + std::to_string(count) + " inputs)" : std::string()) << ": "
                << escape::one_line(text) << '\n';
  }
  std::cout << "imported " << outcomes.size() << (outcomes.size() == 1 ? " input" : " inputs") << " into "
            << escape::one_line(database) << ": " << created << " new " << (created == 1 ? "run" : "runs") << ", "
            << extended << " extended, " << already << " already imported"
            << (replaced ? ", " + std::to_string(replaced) + " replaced" : std::string())
            << (plan.excluded ? ", " + std::to_string(plan.excluded) + " left out by the filters" : std::string())
            << ", " << notes.size() << (notes.size() == 1 ? " note" : " notes") << '\n';
}

}  // namespace hydrocoef::cli
