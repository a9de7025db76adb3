// hydrocoef added-mass BODY: the 6x6 added-mass matrix (and linear damping)
// assembled from the body's stored forced-oscillation runs
// (src/pmm/added_mass_assembly).
#include <memory>

#include "cli/common.hpp"
#include "cli/pmm_output.hpp"
#include "src/pmm/added_mass_assembly.hpp"
#include "src/pmm/imposed_motion.hpp"

namespace hydrocoef::cli {
namespace {

struct AddedMassArgs {
  std::string body;
  std::vector<std::string> same, zero;
  bool json = false;
};

}  // namespace

void add_added_mass_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<AddedMassArgs>();
  auto* command = app.add_subcommand(
      "added-mass",
      "The 6x6 added-mass matrix M_A of a body from its stored forced-oscillation runs (hydrocoef pmm): each "
      "run of DOF j gives column j; runs of one entry are combined by their weighted mean; symmetric by "
      "construction; checked positive definite; missing entries named. Also the linear damping D and, from "
      "several amplitudes at one frequency, the quadratic damping");
  command->add_option("body", args->body, "Body name")->required();
  command->add_option("--same", args->same,
                      "DOF=DOF: take a DOF no run moves from another, e.g. sway=surge for a symmetric body "
                      "(repeatable)");
  command
      ->add_option("--zero", args->zero, "A DOF whose added mass is zero, e.g. roll (repeatable, or comma-separated)")
      ->delimiter(',');
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] {
    Database database(global.database, Database::OpenMode::ReadOnly);
    const AddedMassAssembly assembly = assemble_added_mass(args->body, database.pmm_records(args->body, false),
                                                           parse_added_mass_options(args->same, args->zero));
    print_added_mass(assembly, args->json);
  });
}

}  // namespace hydrocoef::cli
