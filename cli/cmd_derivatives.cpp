// hydrocoef derivatives fit | list | show | delete | evaluate: derivative
// models of several variables fitted to all the selected runs of a body at
// once, stored, shown in the form asked for (SI, prime, bis, MMG) and
// evaluated with their standard error, and exported
// (cli/cmd_derivatives_export.cpp). The library fits, stores and renders
// (hydrocoef/derivatives.hpp); this command parses, calls and prints.
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/derivatives.hpp"

namespace hydrocoef::cli {
namespace {

struct DerivativesArgs {
  hydrocoef::DerivativeModelOptions fit;
  SelectionArgs selection;
  bool no_store = false, unweighted = false;
  std::string body, name;
  hydrocoef::DerivativeShowOptions show;
  std::vector<std::string> at;
  bool json = false;
};

void print(const auto& result, bool json) { std::cout << (json ? result.json() : result.text()); }

void add_fit(CLI::App& parent, const std::shared_ptr<DerivativesArgs>& args, const GlobalOptions& global) {
  auto* command = parent.add_subcommand(
      "fit",
      "Fit OUTPUT = sum c_k term_k over all the selected runs of a body at once (linear least squares, weighted by "
      "1/s^2 when every run states an uncertainty), with covariance, 95 % intervals, VIFs and condition number; "
      "store it");
  command->add_option("--body", args->fit.body, "Body whose runs are fitted (required)");
  command->add_option("--output", args->fit.output, "Force or moment fitted: X Y Z K M N (required)");
  command->add_option("--terms", args->fit.terms,
                      "Terms over the runs' u v w p q r and disturbances: products of names, x^2..x^4 and |x|, "
                      "comma-separated, e.g. \"v, r, v*|v|, u*v\" (or --template)");
  command->add_option("--template", args->fit.model_template,
                      "A named term list for the output: abkowitz, auv, mmg or mmg-beta (or --terms)");
  command->add_option("--select", args->fit.select,
                      "Choose among the terms by cross-validation: loo (leave-one-out) or kfold:K (backward "
                      "elimination, one-standard-error rule)");
  command->add_option("--seed", args->fit.seed, "Seed of the k-fold shuffle")->capture_default_str();
  add_selection_options(*command, args->selection);
  command->add_option("--name", args->fit.name, "Name to store the model under (default BODY:OUTPUT(TERMS))");
  command->add_flag("--replace", args->fit.replace, "Replace a stored model of the same name (otherwise refused)");
  command->add_option("--vif-threshold", args->fit.vif_threshold, "Warn of variance inflation factors above this")
      ->capture_default_str();
  command->add_option("--u0", args->fit.u0, "Nominal speed U0 [m/s] of terms in du = u - U0 (abkowitz)");
  command->add_flag("--no-store", args->no_store, "Do not store the model");
  command->add_flag("--unweighted", args->unweighted,
                    "Ordinary least squares even when every run states an uncertainty");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] {
    auto options = args->fit;
    options.where = args->selection.where;
    options.exclude_runs = args->selection.exclude_runs;
    options.store = !args->no_store;
    options.weighted = !args->unweighted;
    options.validate();
    auto database = hydrocoef::Database::open(
        global.database, options.store ? hydrocoef::OpenMode::ReadWrite : hydrocoef::OpenMode::ReadOnly);
    print(hydrocoef::fit_derivative_model(database, options), args->json);
  });
}

void add_show(CLI::App& parent, const std::shared_ptr<DerivativesArgs>& args, const GlobalOptions& global) {
  auto* command = parent.add_subcommand(
      "show",
      "Show a stored model: its coefficients with standard errors and intervals in the form asked for, "
      "the normalisation of each named, its statistics, warnings and runs");
  command->add_option("name", args->show.name, "The stored model (hydrocoef derivatives list)")->required();
  command->add_option("--form", args->show.form, "dimensional (SI), prime (SNAME), bis (Norrbin) or mmg")
      ->capture_default_str();
  command->add_option("--length", args->show.length, "Reference length L [m] (prime, bis, mmg)");
  command->add_option("--speed", args->show.speed, "Reference speed U [m/s] (prime, mmg)");
  command->add_option("--density", args->show.density, "Water density rho [kg/m^3] (prime, mmg)");
  command->add_option("--draft", args->show.draft, "Draft d [m] (mmg)");
  command->add_option("--mass", args->show.mass, "Mass m [kg] (bis; else rho times --volume)");
  command->add_option("--volume", args->show.volume, "Displaced volume [m^3] (bis without --mass)");
  command->add_option("--gravity", args->show.gravity, "Acceleration of gravity g [m/s^2] (bis)")
      ->capture_default_str();
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] {
    args->show.validate();
    const auto database = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
    print(hydrocoef::show_derivative_model(database, args->show), args->json);
  });
}

}  // namespace

void add_derivatives_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<DerivativesArgs>();
  auto* derivatives = app.add_subcommand(
      "derivatives",
      "Derivative models of several variables: fit, list, show (SI, prime, bis, MMG), delete, evaluate, "
      "export; pmm: sway and yaw derivatives from forced-oscillation runs");
  derivatives->require_subcommand(1);
  add_fit(*derivatives, args, global);

  auto* list = derivatives->add_subcommand("list", "List stored derivative models");
  list->add_option("--body", args->body, "Only models of this body");
  list->add_flag("--json", args->json, "Print JSON");
  list->callback([args, &global] {
    const auto database = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
    print(hydrocoef::list_derivative_models(database, args->body), args->json);
  });

  add_show(*derivatives, args, global);

  auto* remove = derivatives->add_subcommand("delete", "Delete a stored derivative model");
  remove->add_option("name", args->name, "The stored model")->required();
  remove->add_flag("--json", args->json, "Print JSON");
  remove->callback([args, &global] {
    auto database = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadWrite);
    print(hydrocoef::delete_derivative_model(database, args->name), args->json);
  });

  auto* evaluate = derivatives->add_subcommand(
      "evaluate", "A stored model at one point, with the standard error sqrt(b^T C b) of its value");
  evaluate->add_option("name", args->name, "The stored model")->required();
  evaluate->add_option("--at", args->at, "A variable's value (SI), NAME=VALUE; repeatable, one for each")->required();
  evaluate->add_flag("--json", args->json, "Print JSON");
  evaluate->callback([args, &global] {
    hydrocoef::DerivativeEvaluationOptions options;
    options.name = args->name;
    for (const auto& text : args->at) options.at.insert(parse_assignment(text, "--at"));
    options.validate();
    const auto database = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
    print(hydrocoef::evaluate_derivative_model(database, options), args->json);
  });
  add_derivatives_pmm_command(*derivatives, global);

  add_derivatives_export(*derivatives, global);
}

}  // namespace hydrocoef::cli
