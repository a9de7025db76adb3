// hydrocoef fit: fit a damping law to stored runs and store it;
// hydrocoef fits: list stored fits. The library fits
// (src/pipeline/fit_stored_runs.hpp); this command parses, calls and prints.
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "cli/fit_output.hpp"
#include "src/core/error.hpp"
#include "src/pipeline/fit_stored_runs.hpp"
#include "src/store/database.hpp"

namespace hydrocoef::cli {
namespace {

struct FitArgs {
  std::string body;
  std::string dof;
  std::string terms;
  std::string loss = "squared";
  SelectionArgs selection;
  std::optional<std::string> name;
  std::optional<std::string> by;
  std::string curve = "polynomial:2";
  std::vector<std::string> mirror;
  std::vector<std::string> mirror_odd;
  bool no_store = false;
  bool strict = false;
  bool replace = false;
  bool refit = false;
  bool unweighted = false;
  bool json = false;
};

void run_fit(const FitArgs& args, const GlobalOptions& global) {
  if (args.refit) {
    if (!args.dof.empty() || !args.terms.empty() || args.by || !args.selection.where.empty() ||
        !args.selection.exclude_runs.empty() || !args.mirror.empty())
      throw InputError(
          "--refit makes stored fits again as they were made; expected only --name, --body and --json with it");
    RunDatabase database(global.database, RunDatabase::OpenMode::MustExist);
    const auto result = refit_stored_fits(database, args.name,
                                          args.body.empty() ? std::nullopt : std::optional<std::string>(args.body));
    print_refit(result, global.database, args.json);
    return;
  }
  FitRequest request{args.body,
                     args.dof,
                     args.terms,
                     args.loss,
                     args.selection.where,
                     args.selection.exclude_runs,
                     args.mirror,
                     args.mirror_odd,
                     args.name,
                     !args.no_store,
                     args.replace ? RunDatabase::NameTaken::Replace : RunDatabase::NameTaken::Refuse,
                     !args.unweighted};
  RunDatabase database(global.database, RunDatabase::OpenMode::MustExist);
  if (args.by) {
    const LevelFitRequest level_request{request, *args.by, args.curve, args.strict};
    print_level_fit(fit_stored_runs_by_level(database, level_request), level_request, global.database, args.json);
    return;
  }
  print_fit(fit_stored_runs(database, request), args.dof, args.body, global.database, args.json);
}

struct FitsArgs {
  std::optional<std::string> body;
  bool json = false;
};

void run_fits(const FitsArgs& args, const GlobalOptions& global) {
  RunDatabase database(global.database, RunDatabase::OpenMode::ReadOnly);
  print_fits(database.fits(args.body), global.database, args.json);
}

}  // namespace

void add_fit_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<FitArgs>();
  auto* command = app.add_subcommand(
      "fit", "Fit a damping law F_dof = sum c_k term_k(x) to the runs of a body (Ceres least squares) and store it");
  command->add_option("--body", args->body, "Body whose runs are fitted (required unless --refit)");
  command->add_option("--dof", args->dof, "Force component: X Y Z K M N (required unless --refit)");
  command->add_option("--terms", args->terms,
                      "Terms of one velocity component x: 1, x, x|x|, x^2, x^3, |x| "
                      "(e.g. 1,u,u|u|; required unless --refit)");
  command->add_option("--loss", args->loss, "squared, or a robust loss huber:S, cauchy:S, soft-l1:S (S in N or N m)")
      ->capture_default_str();
  add_selection_options(*command, args->selection);
  command->add_option("--name", args->name,
                      "Name to store the fit under (default body:dof(terms), then @selection; a level of --by "
                      "adds [by=level])");
  command->add_flag("--replace", args->replace, "Replace a stored fit of the same name (otherwise refused)");
  command->add_flag("--refit", args->refit,
                    "Make stored fits again from the runs their selections pick now: every stale fit, or the one "
                    "given with --name (--body limits them)");
  add_mirror_options(*command, args->mirror, args->mirror_odd);
  command->add_option("--by", args->by,
                      "Fit the law separately at each level of this velocity component or disturbance, then each "
                      "coefficient as a curve of the level");
  command->add_option("--curve", args->curve, "With --by: polynomial:D (least squares, degree D) or pchip")
      ->capture_default_str();
  command->add_flag("--strict", args->strict,
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
  list->callback([fits_args, &global] { run_fits(*fits_args, global); });
}

}  // namespace hydrocoef::cli
