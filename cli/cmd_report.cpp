// hydrocoef report -o DIR: one self-contained HTML page of the database's
// runs with their convergence and force histories, fits, surfaces with their
// calibration and sigma maps, mesh studies, forced-oscillation fits, and plots
// (hydrocoef/records.hpp: write_report).
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/records.hpp"

namespace hydrocoef::cli {
namespace {

struct ReportArgs {
  hydrocoef::ReportOptions options;
  SelectionArgs selection;
  bool json = false;
};

void run_report(const ReportArgs& args, const GlobalOptions& global) {
  auto options = args.options;
  options.where = args.selection.where;
  options.exclude_runs = args.selection.exclude_runs;
  const auto database = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
  const auto report = hydrocoef::write_report(database, options);
  std::cout << (args.json ? report.json() : report.text());
}

}  // namespace

void add_report_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<ReportArgs>();
  auto* command = app.add_subcommand("report",
                                     "Write a self-contained HTML report: runs and their quality, fits, surfaces, mesh "
                                     "studies, forced oscillation and plots");
  command->add_option("-o,--output", args->options.output, "Directory to write index.html and plots/ into")->required();
  command->add_option("--body", args->options.body, "Only this body's runs, fits and surfaces");
  command->add_option("--trajectory", args->options.trajectories, "Simulated trajectory CSV to plot (repeatable)");
  command->add_option("--experiment", args->options.experiment, "Measured CSV overlaid on the trajectories");
  command->add_option("--component", args->options.component, "Velocity component drawn for trajectories")
      ->capture_default_str();
  add_selection_options(*command, args->selection);
  command->add_flag("--json", args->json, "Print JSON: the page, plots and notes");
  command->callback([args, &global] { run_report(*args, global); });
}

}  // namespace hydrocoef::cli
