// hydrocoef plot coefficient: a non-dimensional coefficient of the runs
// (C_X..C_N, as runs --coefficients gives them) against Re, Fn or U, one set
// of points per body. The work is include/hydrocoef/plot.hpp; this file
// parses and prints.
#include <memory>

#include "cli/common.hpp"
#include "cli/plot_common.hpp"
#include "hydrocoef/plot.hpp"

namespace hydrocoef::cli {

void add_coefficient_plot(CLI::App* plot_cmd, const GlobalOptions& global) {
  struct CoefficientArgs : CommonPlotArgs {
    CoefficientPlotOptions options;
    SelectionArgs selection;
  };
  auto args = std::make_shared<CoefficientArgs>();
  auto* command = plot_cmd->add_subcommand(
      "coefficient",
      "A non-dimensional coefficient of the runs against Re, Fn or U, with each body's reference data "
      "(hydrocoef body set): C_X..C_N = F/(1/2 rho U^2 A), M/(1/2 rho U^2 A L), body axes, forces on the body");
  CoefficientPlotOptions& o = args->options;
  command->add_option("--coefficient", o.coefficient, "C_X, C_Y, C_Z, C_K, C_M or C_N")->capture_default_str();
  command->add_option("--against", o.against, "Re, Fn or U")->capture_default_str();
  command->add_option("--area", o.runs.area, "The reference area of this name (default: the body's default area)");
  command->add_option("--body", o.runs.body, "Only runs of this body");
  add_selection_options(*command, args->selection);
  add_common(command, *args);
  command->callback([args, &global] {
    auto options = args->options;
    options.runs.where = args->selection.where;
    options.runs.exclude_runs = args->selection.exclude_runs;
    const auto database = Database::open(global.database, OpenMode::ReadOnly);
    print_plot(plot_coefficient(database, options, args->image), *args);
  });
}

}  // namespace hydrocoef::cli
