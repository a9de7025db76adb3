// hydrocoef suggest: where to run CFD next so that a GP surface's largest
// standard deviation falls most; printed, and written as a sweep manifest
// that `hydrocoef import --manifest` reads back once the runs are done.
#include <iomanip>
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "src/core/escape.hpp"
#include "src/pipeline/next_runs.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef::cli {
namespace {

struct SuggestArgs {
  std::string name;
  NextRunsRequest request;
  std::optional<std::string> manifest;
  std::vector<std::string> running;
  bool json = false;
};

void print_next_runs(const SuggestArgs& args, const NextRuns& next) {
  if (args.json) {
    nlohmann::json out = {{"surface", args.name},
                          {"output", next.output},
                          {"unit", next.unit},
                          {"largest_sd_after", next.largest_sd_after}};
    for (std::size_t a = 0; a < next.axes.size(); ++a) {
      out["bounds"][next.axes[a]] = {next.lower[a], next.upper[a]};
      out["resolution"][next.axes[a]] = next.resolution[a];
    }
    out["mirror"] = next.mirror;
    out["domain"] = next.domain;
    out["candidates"] = next.candidates;
    out["skipped"] = {{"imported", next.imported_skipped}, {"running", next.running_skipped}};
    out["runs"] = nlohmann::json::array();
    for (const auto& run : next.runs) {
      nlohmann::json entry = {{"sd_before", run.standard_deviation}};
      for (std::size_t a = 0; a < next.axes.size(); ++a) entry["key"][next.axes[a]] = run.point[a];
      out["runs"].push_back(entry);
    }
    if (args.manifest) out["manifest"] = *args.manifest;
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  std::cout << "next runs for surface " << escape::one_line(args.name) << ": where the standard deviation of "
            << escape::one_line(next.output) << " is largest, each run counted before the next is chosen\n  bounds:";
  for (std::size_t a = 0; a < next.axes.size(); ++a)
    std::cout << " " << escape::one_line(next.axes[a]) << "=" << significant(next.lower[a], 6) << ":"
              << significant(next.upper[a], 6);
  std::cout << "\n  keys rounded to:";
  for (std::size_t a = 0; a < next.axes.size(); ++a)
    std::cout << " " << escape::one_line(next.axes[a]) << "=" << shortest_number(next.resolution[a])
              << (next.resolution_given[a] ? "" : " (default: 1/100 of the bounds, 1-2-5)");
  std::cout << '\n';
  if (!next.mirror.empty())
    std::cout << "  mirror " << escape::one_line(next.mirror) << ": "
              << (next.domain.empty()
                      ? "changes none of the surface's axes"
                      : "keys with " + escape::one_line(next.domain) + ", each standing for its mirror image too")
              << '\n';
  std::cout << "  " << next.candidates << " new keys searched";
  if (next.imported_skipped + next.running_skipped > 0)
    std::cout << " (left out: " << next.imported_skipped << " where the body has a run, " << next.running_skipped
              << " running)";
  std::cout << "\n  #   ";
  for (const auto& axis : next.axes) std::cout << std::left << std::setw(14) << escape::one_line(axis);
  std::cout << "sd of " << escape::one_line(next.output) << " there before [" << escape::one_line(next.unit) << "]\n";
  for (std::size_t i = 0; i < next.runs.size(); ++i) {
    std::cout << "  " << std::left << std::setw(4) << i + 1;
    for (const double x : next.runs[i].point) std::cout << std::setw(14) << shortest_number(x);
    std::cout << significant(next.runs[i].standard_deviation, 4) << '\n';
  }
  std::cout << "  largest sd in the bounds: " << significant(next.runs.front().standard_deviation, 4) << " now, "
            << significant(next.largest_sd_after, 4) << " " << escape::one_line(next.unit) << " with these runs\n";
  if (args.manifest)
    std::cout << "  manifest " << escape::one_line(*args.manifest)
              << " (fill in each case's path; hydrocoef import --manifest reads it)\n";
}

}  // namespace

void add_suggest_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<SuggestArgs>();
  auto* command = app.add_subcommand(
      "suggest",
      "Propose the next CFD runs of a GP surface: the run keys that most reduce its largest standard deviation inside "
      "the bounds (sequential maximum variance), rounded, in the fundamental domain of its mirrors and not where "
      "a run is or is running, printed and as a sweep manifest for import --manifest");
  command->add_option("name", args->name, "GP surface name")->required();
  command->add_option("--count", args->request.count, "Runs to propose (1 to 1000)")->capture_default_str();
  command
      ->add_option("--bounds", args->request.bounds,
                   "AXIS=FROM:TO in SI units, comma-separated or repeated (default: the surface's range)")
      ->delimiter(',');
  command->add_option("--for", args->request.output, "The output whose uncertainty to reduce (default: the first)");
  command->add_option("--candidates", args->request.candidates, "Candidate points searched (Halton sequence)")
      ->capture_default_str();
  command
      ->add_option("--round", args->request.round,
                   "AXIS=STEP in SI units, comma-separated or repeated: every key a multiple of STEP (default: 1/100 "
                   "of the bounds' width, rounded down to 1, 2 or 5 times a power of ten)")
      ->delimiter(',');
  command->add_option("--running", args->running,
                      "A sweep manifest of runs asked for and not imported yet (repeatable): never proposed again, "
                      "and counted as done when choosing");
  command->add_option("--manifest", args->manifest, "Write the runs as a sweep manifest CSV");
  command->add_flag("--json", args->json, "Machine-readable output");
  command->callback([args, &global] {
    RunDatabase database(global.database, RunDatabase::OpenMode::ReadOnly);
    const StoredSurface stored = load_surface(database, args->name);
    NextRunsRequest request = args->request;
    request.mirror = surface_mirror(stored.record);
    request.imported = imported_keys(database, stored.record.body, stored.surface);
    for (const auto& file : args->running)
      for (auto& key : running_keys(file, stored.record.body, stored.surface))
        request.running.push_back(std::move(key));
    const NextRuns next = suggest_next_runs(stored.surface, request);
    if (args->manifest) write_next_runs_manifest(next, stored.record.body, *args->manifest);
    print_next_runs(*args, next);
  });
}

}  // namespace hydrocoef::cli
