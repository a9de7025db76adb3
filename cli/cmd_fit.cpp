// hydrocoef fit: fit a damping law to stored runs and store it (per level
// with --by, again with --refit); hydrocoef fits: list stored fits, or
// evaluate one's law with its standard error. The library fits and renders
// (hydrocoef/database.hpp, records.hpp); this command parses, calls and prints.
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/records.hpp"

namespace hydrocoef::cli {
namespace {

struct FitArgs {
  hydrocoef::FitOptions options;
  SelectionArgs selection;
  bool no_store = false;
  bool unweighted = false;
  bool json = false;
};

void run_fit(const FitArgs& args, const GlobalOptions& global) {
  auto options = args.options;
  options.where = args.selection.where;
  options.exclude_runs = args.selection.exclude_runs;
  options.store = !args.no_store;
  options.weighted = !args.unweighted;
  options.validate();
  auto database = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadWrite);
  const auto print = [&](const auto& result) { std::cout << (args.json ? result.json() : result.text()); };
  if (options.refit)
    print(hydrocoef::refit_fits(database, options));
  else if (!options.by.empty())
    print(hydrocoef::fit_by_level(database, options));
  else
    print(database.fit(options));
}

struct FitsArgs {
  std::string body;
  bool json = false;
};

struct EvaluateArgs {
  hydrocoef::FitEvaluationOptions options;
  bool json = false;
};

}  // namespace

void add_fit_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<FitArgs>();
  auto* command = app.add_subcommand(
      "fit", "Fit a damping law F_dof = sum c_k term_k(x) to the runs of a body (Ceres least squares) and store it");
  command->add_option("--body", args->options.body, "Body whose runs are fitted (required unless --refit)");
  command->add_option("--dof", args->options.output, "Force component: X Y Z K M N (required unless --refit)");
  command->add_option("--terms", args->options.terms,
                      "Terms of one velocity component x: 1, x, x|x|, x^2, x^3, |x| "
                      "(e.g. 1,u,u|u|; required unless --refit)");
  command
      ->add_option("--loss", args->options.loss,
                   "squared, or a robust loss huber:S, cauchy:S, soft-l1:S (S in N or N m)")
      ->capture_default_str();
  add_selection_options(*command, args->selection);
  command->add_option("--name", args->options.name,
                      "Name to store the fit under (default body:dof(terms), then @selection; a level of --by "
                      "adds [by=level])");
  command->add_flag("--replace", args->options.replace, "Replace a stored fit of the same name (otherwise refused)");
  command->add_flag("--refit", args->options.refit,
                    "Make stored fits again from the runs their selections pick now: every stale fit, or the one "
                    "given with --name (--body limits them)");
  add_mirror_options(*command, args->options.mirror, args->options.mirror_odd);
  command->add_option("--by", args->options.by,
                      "Fit the law separately at each level of this velocity component or disturbance, then each "
                      "coefficient as a curve of the level");
  command->add_option("--curve", args->options.curve, "With --by: polynomial:D (least squares, degree D) or pchip")
      ->capture_default_str();
  command->add_flag("--strict", args->options.strict,
                    "With --by: refuse the fit when a level has too few runs for the law (default: skip it with a "
                    "note)");
  command->add_flag("--no-store", args->no_store, "Do not store the fit");
  command->add_flag("--unweighted", args->unweighted,
                    "Ordinary least squares even when every run states an uncertainty (a mean over a force history, "
                    "or import --uncertainty; by default such runs are weighted by 1/s^2 and the reduced chi^2 is "
                    "reported)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_fit(*args, global); });

  auto fits_args = std::make_shared<FitsArgs>();
  auto* list = app.add_subcommand("fits", "List stored damping-law fits");
  list->add_option("--body", fits_args->body, "Only fits of this body");
  list->add_flag("--json", fits_args->json, "Print JSON");
  list->callback([fits_args, list, &global] {
    if (!list->get_subcommands().empty()) return;  // "fits" lists only when no subcommand (evaluate) was given
    const auto database = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
    const auto fits = hydrocoef::list_fits(database, fits_args->body);
    std::cout << (fits_args->json ? fits.json() : fits.text());
  });

  auto evaluate = std::make_shared<EvaluateArgs>();
  auto* evaluate_command =
      list->add_subcommand("evaluate",
                           "A stored fit's law at given velocities, with the standard error of each value from the "
                           "coefficients' covariance");
  evaluate_command->add_option("name", evaluate->options.name, "The stored fit (hydrocoef fits lists them)")
      ->required();
  evaluate_command
      ->add_option("--at", evaluate->options.at,
                   "Values of the law's velocity component [m/s or rad/s], e.g. --at 0.1,0.2 (repeatable)")
      ->delimiter(',')
      ->required();
  evaluate_command->add_flag("--json", evaluate->json, "Print JSON");
  evaluate_command->callback([evaluate, &global] {
    const auto database = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
    const auto values = hydrocoef::evaluate_fit(database, evaluate->options);
    std::cout << (evaluate->json ? values.json() : values.text());
  });
}

}  // namespace hydrocoef::cli
