// hydrocoef added-mass BODY: the 6x6 added-mass matrix (and linear damping)
// assembled from the body's stored forced-oscillation runs
// (src/pmm/added_mass_assembly).
#include <memory>
#include <optional>

#include "cli/common.hpp"
#include "cli/pmm_output.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/pmm/added_mass_assembly.hpp"
#include "src/pmm/imposed_motion.hpp"

namespace hydrocoef::cli {
namespace {

struct AddedMassArgs {
  std::string body;
  std::vector<std::string> same, zero;
  std::optional<double> period;
  bool allow_indefinite = false;
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
  command->add_option("body", args->body, "Body name")->required();
  command->add_option("--same", args->same,
                      "DOF=DOF: take a DOF no run moves from another, e.g. sway=surge for a symmetric body "
                      "(repeatable)");
  command
      ->add_option("--zero", args->zero, "A DOF whose added mass is zero, e.g. roll (repeatable, or comma-separated)")
      ->delimiter(',');
  command->add_option("--period", args->period,
                      "Period T [s] of the runs that make the matrices (needed when the body's runs are at several "
                      "frequencies: the added mass and damping depend on it)");
  command->add_flag("--allow-indefinite", args->allow_indefinite,
                    "Print a matrix that is not positive definite instead of refusing it (exit 2)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] {
    RunDatabase database(global.database, RunDatabase::OpenMode::ReadOnly);
    AddedMassOptions options = parse_added_mass_options(args->same, args->zero);
    options.period = args->period;
    const AddedMassAssembly assembly =
        assemble_added_mass(args->body, database.pmm_records(args->body, false), options);
    if (!assembly.positive_definite && !args->allow_indefinite)
      throw InputError("body '" + printable_text(args->body, 80) +
                       "': the assembled M_A is not positive definite (smallest eigenvalue " +
                       significant(assembly.smallest_eigenvalue, 6) +
                       " over the DOFs with a non-zero diagonal); expected positive definite: check the runs' "
                       "signs and phases (pmm --axes) and restoring forces (pmm --restoring), or give "
                       "--allow-indefinite to print it");
    print_added_mass(assembly, args->json);
  });
}

}  // namespace hydrocoef::cli
