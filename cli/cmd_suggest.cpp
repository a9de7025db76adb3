// hydrocoef suggest: where to run CFD next so that a GP surface's largest
// standard deviation falls most; printed, and written as a sweep manifest
// that `hydrocoef import --manifest` reads back once the runs are done. The
// command parses its options into hydrocoef::SuggestOptions and prints what
// hydrocoef::suggest_runs (include/hydrocoef/analysis.hpp) returns.
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/analysis.hpp"

namespace hydrocoef::cli {
namespace {

struct SuggestArgs {
  SuggestOptions options;
  bool json = false;
};

}  // namespace

void add_suggest_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<SuggestArgs>();
  auto& o = args->options;
  auto* command = app.add_subcommand(
      "suggest",
      "Propose the next CFD runs of a GP surface: the run keys that most reduce its largest standard deviation inside "
      "the bounds (sequential maximum variance), rounded, in the fundamental domain of its mirrors and not where "
      "a run is or is running, printed and as a sweep manifest for import --manifest");
  command->add_option("name", o.surface, "GP surface name")->required();
  command->add_option("--count", o.count, "Runs to propose (1 to 1000)")->capture_default_str();
  command
      ->add_option("--bounds", o.bounds,
                   "AXIS=FROM:TO in SI units, comma-separated or repeated (default: the surface's range)")
      ->delimiter(',');
  command->add_option("--for", o.output, "The output whose uncertainty to reduce (default: the first)");
  command->add_option("--candidates", o.candidates, "Candidate points searched (Halton sequence)")
      ->capture_default_str();
  command
      ->add_option("--round", o.round,
                   "AXIS=STEP in SI units, comma-separated or repeated: every key a multiple of STEP (default: 1/100 "
                   "of the bounds' width, rounded down to 1, 2 or 5 times a power of ten)")
      ->delimiter(',');
  command->add_option("--running", o.running,
                      "A sweep manifest of runs asked for and not imported yet (repeatable): never proposed again, "
                      "and counted as done when choosing");
  command->add_option("--manifest", o.manifest, "Write the runs as a sweep manifest CSV");
  command->add_flag("--json", args->json, "Machine-readable output");
  command->callback([args, &global] {
    const auto database = Database::open(global.database, OpenMode::ReadOnly);
    const Suggestion suggestion = suggest_runs(database, args->options);
    std::cout << (args->json ? suggestion.json() + "\n" : suggestion.text());
  });
}

}  // namespace hydrocoef::cli
