// hydrocoef body set NAME: a body's reference data (length, named areas,
// draft, displaced volume, moment reference point), what `runs
// --coefficients` divides by; body show [NAME]: the bodies and their
// reference data. The library checks, stores and renders
// (hydrocoef/reference.hpp).
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/reference.hpp"

namespace hydrocoef::cli {
namespace {

struct SetArgs {
  hydrocoef::BodyReferenceOptions options;
  std::vector<std::string> areas;  ///< NAME=A
  std::optional<std::string> moment_point;
  bool json = false;
};

void run_set(const SetArgs& args, const GlobalOptions& global) {
  auto options = args.options;
  for (const auto& text : args.areas) {
    const auto [name, value] = parse_assignment(text, "--area");
    if (!options.areas.emplace(name, value).second) throw InputError("--area names the area '" + name + "' twice");
  }
  if (args.moment_point) options.moment_reference_point = parse_triple(*args.moment_point, "--moment-point");
  options.validate();  // before the database is opened: a bad value leaves it untouched
  auto database = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadWrite);
  const auto stored = hydrocoef::set_body_reference(database, options);
  std::cout << (args.json ? stored.json() : stored.text());
}

struct ShowArgs {
  std::string body;
  bool json = false;
};

void run_show(const ShowArgs& args, const GlobalOptions& global) {
  const auto database = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
  const auto references = hydrocoef::body_references(database, args.body);
  std::cout << (args.json ? references.json() : references.text());
}

}  // namespace

void add_body_command(CLI::App& app, const GlobalOptions& global) {
  auto* command = app.add_subcommand(
      "body", "Set and show a body's reference data (length, areas, draft, volume, moment reference point)");
  command->require_subcommand(1);

  auto set = std::make_shared<SetArgs>();
  auto* set_command = command->add_subcommand(
      "set",
      "Set a body's reference data (SI; body axes x forward, y starboard, z down), for the coefficients of its "
      "runs (runs --coefficients); what is not given stays as it was");
  set_command->add_option("name", set->options.body, "Body name (a body of the database)")->required();
  set_command->add_option("--length", set->options.length, "Reference length L [m] (Re, Fn, moment coefficients)");
  set_command->add_option("--area", set->areas,
                          "A named reference area NAME=A [m^2], e.g. frontal=0.0707 or L*d=0.05 (repeatable; "
                          "replaces one of that name)");
  set_command->add_option("--default-area", set->options.default_area,
                          "The area coefficients use when runs --coefficients names none (a body with one area "
                          "uses it)");
  set_command->add_option("--remove-area", set->options.remove_areas, "Remove the area of this name (repeatable)");
  set_command->add_option("--draft", set->options.draft, "Draft [m]");
  set_command->add_option("--volume", set->options.displaced_volume, "Displaced volume [m^3]");
  set_command->add_option("--moment-point", set->moment_point,
                          "Moment reference point x,y,z [m], body axes: moment coefficients are taken about it "
                          "(default: each run's own reference point)");
  set_command->add_option("--unset", set->options.unset,
                          "Take a value away: length, draft, volume or moment-point (repeatable)");
  set_command->add_flag("--json", set->json, "Print JSON");
  set_command->callback([set, &global] { run_set(*set, global); });

  auto show = std::make_shared<ShowArgs>();
  auto* show_command = command->add_subcommand("show", "Show the reference data of one body, or of every body");
  show_command->add_option("name", show->body, "Body name (default: every body)");
  show_command->add_flag("--json", show->json, "Print JSON");
  show_command->callback([show, &global] { run_show(*show, global); });
}

}  // namespace hydrocoef::cli
