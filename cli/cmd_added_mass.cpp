// hydrocoef added-mass BODY: the 6x6 added-mass matrix (and linear damping)
// assembled from the body's stored forced-oscillation runs. The command
// parses its options into hydrocoef::AddedMassMatrixOptions and prints what
// hydrocoef::added_mass_matrix (include/hydrocoef/analysis.hpp) returns.
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/analysis.hpp"

namespace hydrocoef::cli {
namespace {

struct AddedMassArgs {
  AddedMassMatrixOptions options;
  std::vector<std::string> same;
  bool json = false;
};

}  // namespace

void add_added_mass_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<AddedMassArgs>();
  auto* command = app.add_subcommand(
      "added-mass",
      "The 6x6 added-mass matrix M_A of a body from its stored forced-oscillation runs (hydrocoef pmm): each "
      "run of DOF j gives column j; runs of one entry are combined by their weighted mean; symmetric by "
      "construction; refused unless positive definite (--allow-indefinite); missing entries named. The runs of one "
      "frequency make the matrices (--period chooses it when there are several); the in-line added mass and damping "
      "of every frequency are listed apart, and from several amplitudes at one frequency, the quadratic damping");
  command->add_option("body", args->options.body, "Body name")->required();
  command->add_option("--same", args->same,
                      "DOF=DOF: take a DOF no run moves from another, e.g. sway=surge for a symmetric body "
                      "(repeatable)");
  command
      ->add_option("--zero", args->options.zero,
                   "A DOF whose added mass is zero, e.g. roll (repeatable, or comma-separated)")
      ->delimiter(',');
  command->add_option("--period", args->options.period,
                      "Period T [s] of the runs that make the matrices (needed when the body's runs are at several "
                      "frequencies: the added mass and damping depend on it)");
  command->add_flag("--allow-indefinite", args->options.allow_indefinite,
                    "Print a matrix that is not positive definite instead of refusing it (exit 2)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] {
    const auto database = Database::open(global.database, OpenMode::ReadOnly);
    for (const auto& text : args->same) {
      const auto [dof, from] = parse_text_assignment(text, "--same");
      args->options.same[dof] = from;
    }
    const AddedMassMatrix matrix = added_mass_matrix(database, args->options);
    std::cout << (args->json ? matrix.json() + "\n" : matrix.text());
  });
}

}  // namespace hydrocoef::cli
