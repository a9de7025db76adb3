#include "cli/pmm_output.hpp"

#include "cli/common.hpp"
#include "src/core/error.hpp"
#include "src/pmm/imposed_motion.hpp"

namespace hydrocoef::cli {
namespace {

std::size_t dof_of(const std::string& text, const std::string& option) {
  const auto dof = dof_named(text);
  if (!dof)
    throw InputError(option + " '" + printable_text(text, 40) + "': expected surge, sway, heave, roll, pitch or yaw");
  return *dof;
}

}  // namespace

AddedMassOptions parse_added_mass_options(const std::vector<std::string>& same, const std::vector<std::string>& zero) {
  AddedMassOptions options;
  for (const auto& text : same) {
    const auto [dof, from] = parse_text_assignment(text, "--same");
    options.same[dof_of(dof, "--same")] = dof_of(from, "--same");
  }
  for (const auto& text : zero) options.zero.push_back(dof_of(text, "--zero"));
  return options;
}

}  // namespace hydrocoef::cli
