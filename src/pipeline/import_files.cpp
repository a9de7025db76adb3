// A whole import (src/pipeline/import_files.hpp): the inputs planned, read
// (src/pipeline/read_input.cpp), checked for two files giving one run's
// component, and stored in one transaction, with the notes summed up by kind.
#include "src/pipeline/import_files.hpp"

#include <algorithm>
#include <chrono>

#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/core/text.hpp"

namespace hydrocoef {

ImportPlan plan_request(const ImportRequest& request) { return plan_import(request.inputs, request.plan); }

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool is_key_setting(const std::string& name) {
  return velocity_index(name) || name == "flow" || name.rfind("disturbance.", 0) == 0;
}

/// True when the input states its runs' keys (a table's rows, or a velocity
/// or disturbance from any source), false when its key is only the default.
bool states_key(const ImportedInput& input) {
  if (input.format == "table" || input.format == "captive-table") return true;
  return std::any_of(input.settings.values.begin(), input.settings.values.end(),
                     [](const auto& entry) { return is_key_setting(entry.first); });
}

/// A file and where its run's key came from, for collision messages.
std::string key_origin(const ImportedInput& input, const ImportedRun& run) {
  const std::string file = printable_text(input.input.path.string(), 200);
  if (input.format == "table" || input.format == "captive-table")
    return file + " (its row at line " + std::to_string(run.source_line) + ")";
  std::string parts;
  for (const auto& [name, setting] : input.settings.values) {
    if (!is_key_setting(name)) continue;
    parts +=
        (parts.empty() ? "" : ", ") + name + " from the " + std::string(setting_source_name(setting.origin.source));
    if (!setting.origin.where.empty()) parts += " " + printable_text(setting.origin.where, 120);
  }
  return file + " (" + (parts.empty() ? std::string("no velocity stated by any source") : parts) + ")";
}

/// Two inputs of one import that give the same component of the same run:
/// refused before anything is stored, naming both files and where each key
/// came from. Superseding is for a later import (--replace); within one
/// import it would keep whichever file was stored last.
void check_key_collisions(const std::vector<ImportedInput>& inputs) {
  std::map<std::string, std::pair<std::size_t, std::size_t>> seen;  // key and component -> input, run
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const auto& runs = inputs[i].batch.runs;
    for (std::size_t r = 0; r < runs.size(); ++r) {
      const RunKey& key = runs[r].key;
      std::string text = key.body + "\n" + disturbance_signature(key.disturbances);
      for (const double v : key.nu_b) text += "\n" + shortest_number(v);
      for (std::size_t c = 0; c < 6; ++c) {
        if (!runs[r].tau_b[c]) continue;
        const auto [it, inserted] = seen.try_emplace(text + "\n" + std::string(kForceNames[c]), i, r);
        if (inserted || it->second.first == i) continue;
        const ImportedInput& earlier = inputs[it->second.first];
        const ImportedRun& earlier_run = earlier.batch.runs[it->second.second];
        const bool neither = !states_key(earlier) && !states_key(inputs[i]);
        throw InputError(
            SourceLocation{inputs[i].input.path.string()},
            "run " + printable_text(describe(key), 200) + " gets " + std::string(kForceNames[c]) +
                " from two files of this import: " + key_origin(earlier, earlier_run) + " and " +
                key_origin(inputs[i], runs[r]) + "; " +
                (neither ? "neither states its run's velocity; expected each file's key with --key-from-name PATTERN "
                           "(file names and folder contents alike), --manifest or a sidecar FILE.json"
                         : "expected one file per run and component (a file meant to supersede another is "
                           "imported on its own, in a later import with --replace)"));
      }
    }
  }
}

/// One line per kind of convergence and per kind of flag over the inputs'
/// force histories (not one note per run and component): what a user should
/// act on, and where to look.
std::vector<std::string> history_summary(const std::vector<ImportedInput>& inputs) {
  std::map<std::string, std::size_t> kinds;
  std::map<std::string, std::map<std::string, std::size_t>> flagged;  // flag -> component -> runs
  std::map<std::string, std::size_t> negligible;                      // component -> runs
  std::size_t histories = 0;
  for (const auto& input : inputs) {
    if (!input.history) continue;
    ++histories;
    const HistoryAnalysis& a = *input.history;
    ++kinds[std::string(convergence_name(a.convergence))];
    for (std::size_t c = 0; c < kHistoryComponents; ++c) {
      const ComponentAnalysis& component = a.components[c];
      if (!component.present) continue;
      const std::string name = std::string(kForceNames[c]);
      if (component.negligible) ++negligible[name];
      for (const auto& flag : flag_names(component.flags)) ++flagged[flag][name];
    }
  }
  std::vector<std::string> out;
  if (histories == 0) return out;
  std::string line = "force histories: ";
  bool first = true;
  for (const auto& [kind, count] : kinds) {
    line += (first ? "" : ", ") + std::to_string(count) + " " + kind;
    first = false;
  }
  if (kinds.count("converged")) line += " (converged: the final iterate, with its iterative error as standard error)";
  out.push_back(line + "; 'runs show ID' says why, with the files");
  if (!negligible.empty()) {
    std::string names;
    for (const auto& [name, count] : negligible)
      names += (names.empty() ? "" : ", ") + name + " of " + std::to_string(count);
    out.push_back("zero to round-off, never flagged: " + names + " run(s)");
  }
  for (const auto& [flag, components] : flagged) {
    std::string where;
    for (const auto& [name, count] : components)
      where += (where.empty() ? "" : ", ") + name + " of " + std::to_string(count);
    out.push_back(flag + ": " + where +
                  " run(s); 'runs show ID' gives the windows and the import's --json the "
                  "details");
  }
  return out;
}

}  // namespace

ImportResult read_import(const ImportRequest& request) {
  ImportResult result;
  auto start = std::chrono::steady_clock::now();
  result.plan = plan_request(request);
  result.plan_s = seconds_since(start);
  start = std::chrono::steady_clock::now();
  result.inputs = read_inputs(result.plan, request);
  check_key_collisions(result.inputs);
  result.read_s = seconds_since(start);
  return result;
}

void store_import(RunDatabase& database, ImportResult& result, const ImportPolicy& options) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<ImportBatch> batches;
  for (const auto& input : result.inputs) batches.push_back(input.batch);
  result.outcomes = database.import(batches, options);
  result.store_s = seconds_since(start);
  result.notes.clear();
  const auto add_note = [&](const std::string& note) {
    for (auto& [text, count] : result.notes)
      if (text == note) return void(++count);
    result.notes.emplace_back(note, 1);
  };
  for (const auto& note : result.plan.notes) add_note(note);
  for (const auto& input : result.inputs)
    for (const auto& note : input.notes) add_note(note);
  for (const auto& note : history_summary(result.inputs)) add_note(note);
  result.runs = result.runs_created = result.runs_extended = result.already_imported = result.replaced = 0;
  for (std::size_t i = 0; i < result.outcomes.size(); ++i) {
    const auto& outcome = result.outcomes[i];
    result.runs_created += outcome.runs_created;
    result.runs_extended += outcome.runs_extended;
    result.already_imported += outcome.already_imported ? 1 : 0;
    result.replaced += outcome.replaced ? 1 : 0;
    result.runs += result.inputs[i].batch.runs.size();
  }
}

ImportResult import_into(RunDatabase& database, const ImportRequest& request, const ImportPolicy& options) {
  ImportResult result = read_import(request);
  store_import(database, result, options);
  return result;
}

}  // namespace hydrocoef
