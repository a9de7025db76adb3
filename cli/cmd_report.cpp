// hydrocoef report -o DIR: one self-contained HTML page of the database's
// runs with their convergence and force histories, fits, surfaces with their
// calibration and sigma maps, mesh studies, forced-oscillation fits, and plots.
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/report/report.hpp"
#include "src/store/database.hpp"

namespace hydrocoef::cli {
namespace {

struct ReportArgs {
  std::string dir;
  std::optional<std::string> body;
  std::vector<std::string> trajectories;
  std::optional<std::string> experiment;
  std::string component = "r";
  SelectionArgs selection;
  bool json = false;
};

void run_report(const ReportArgs& args, const GlobalOptions& global) {
  RunDatabase database(global.database, RunDatabase::OpenMode::ReadOnly);
  report::ReportOptions options;
  options.body = args.body;
  options.selection = parse_selection(args.selection.where, args.selection.exclude_runs);
  for (const auto& t : args.trajectories) options.trajectories.emplace_back(t);
  if (args.experiment) options.experiment = *args.experiment;
  options.component = args.component;
  const auto result = report::write_report(database, args.dir, options);
  if (args.json) {
    nlohmann::json out = {{"index", result.index.string()},
                          {"runs", result.runs},
                          {"fits", result.fits},
                          {"surfaces", result.surfaces},
                          {"histories", result.histories},
                          {"sigma_maps", result.sigma_maps},
                          {"mesh_study_rows", result.mesh_study_rows},
                          {"pmm_fits", result.pmm_fits},
                          {"notes", result.notes}};
    out["plots"] = nlohmann::json::array();
    for (const auto& p : result.plots) out["plots"].push_back(p.string());
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  // The database's name, the paths and the notes (which quote names from
  // the database) are printed through escape::one_line.
  std::cout << "report of " << escape::one_line(global.database) << ": " << result.runs << " runs (" << result.histories
            << " force histories drawn), " << result.fits << " fits, " << result.surfaces << " surfaces ("
            << result.sigma_maps << " sigma maps), " << result.mesh_study_rows << " mesh-study rows, "
            << result.pmm_fits << " forced-oscillation fits, " << result.plots.size() << " plots\n  page "
            << escape::one_line(result.index.string())
            << " (self-contained: open it in any browser, no network needed)\n  plots and their values in "
            << escape::one_line((result.index.parent_path() / "plots").string()) << "\n";
  for (const auto& note : result.notes) std::cout << "  note: " << escape::one_line(note) << '\n';
}

}  // namespace

void add_report_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<ReportArgs>();
  auto* command = app.add_subcommand("report",
                                     "Write a self-contained HTML report: runs and their quality, fits, surfaces, mesh "
                                     "studies, forced oscillation and plots");
  command->add_option("-o,--output", args->dir, "Directory to write index.html and plots/ into")->required();
  command->add_option("--body", args->body, "Only this body's runs, fits and surfaces");
  command->add_option("--trajectory", args->trajectories, "Simulated trajectory CSV to plot (repeatable)");
  command->add_option("--experiment", args->experiment, "Measured CSV overlaid on the trajectories");
  command->add_option("--component", args->component, "Velocity component drawn for trajectories")
      ->capture_default_str();
  add_selection_options(*command, args->selection);
  command->add_flag("--json", args->json, "Print JSON: the page, plots and notes");
  command->callback([args, &global] { run_report(*args, global); });
}

}  // namespace hydrocoef::cli
