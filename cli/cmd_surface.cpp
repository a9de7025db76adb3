// hydrocoef surface build|rebuild|list|show: coefficient surfaces from stored
// runs, kept in the database with their quality figures.
#include <iostream>
#include <memory>
#include <optional>

#include "cli/common.hpp"
#include "cli/surface_build_options.hpp"
#include "cli/surface_output.hpp"
#include "src/core/escape.hpp"
#include "src/pipeline/surface_build.hpp"

namespace hydrocoef::cli {
namespace {

void build(const SurfaceBuildArgs& args, const GlobalOptions& global) {
  const SurfaceBuildSpec spec = surface_build_spec(args);
  RunDatabase database(global.database, RunDatabase::OpenMode::MustExist);
  const auto result =
      build_and_store_surface(database, args.name, args.body, spec,
                              args.replace ? RunDatabase::NameTaken::Replace : RunDatabase::NameTaken::Refuse);
  if (args.json) {
    std::cout << escape::json_text(surface_build_json(result), 2) << '\n';
  } else {
    print_surface_build(result, global.database);
  }
}

struct NameArgs {
  std::string name;
  std::optional<std::string> body;
  bool stale = false;
  bool json = false;
};

void rebuild(const NameArgs& args, const GlobalOptions& global) {
  RunDatabase database(global.database, RunDatabase::OpenMode::MustExist);
  const auto targets =
      surfaces_to_rebuild(database, args.name.empty() ? std::nullopt : std::optional(args.name), args.body, args.stale);
  if (targets.empty() && !args.json) std::cout << "no surface to rebuild\n";
  nlohmann::json rebuilt = nlohmann::json::array();
  for (const auto& record : targets) {
    const auto result = rebuild_surface(database, record);
    if (args.json) {
      rebuilt.push_back(surface_build_json(result));
    } else {
      print_surface_build(result, global.database);
    }
  }
  if (args.json) std::cout << escape::json_text(rebuilt, 2) << '\n';
}

void list(const NameArgs& args, const GlobalOptions& global) {
  RunDatabase database(global.database, RunDatabase::OpenMode::ReadOnly);
  print_surface_list(database.surfaces(args.body), global.database, args.json);
}

void show(const NameArgs& args, const GlobalOptions& global) {
  RunDatabase database(global.database, RunDatabase::OpenMode::ReadOnly);
  print_surface(load_surface(database, args.name), args.json);
}

}  // namespace

void add_surface_command(CLI::App& app, const GlobalOptions& global) {
  auto* surface = app.add_subcommand("surface", "Build, rebuild, list and show coefficient surfaces");
  surface->require_subcommand(1);

  auto build_args = std::make_shared<SurfaceBuildArgs>();
  auto* b = surface->add_subcommand(
      "build",
      "Build a surface from a body's runs and store it. Runs that fill a grid over the axes give a gridded table "
      "(nearest, linear, pchip, makima, natural-spline); scattered runs need --method rbf (optionally tabulated "
      "with --resample). Outputs are forces on the body.");
  add_surface_build_options(*b, *build_args);
  b->add_flag("--json", build_args->json, "Machine-readable output");
  b->callback([build_args, &global] { build(*build_args, global); });

  auto rebuild_args = std::make_shared<NameArgs>();
  auto* r = surface->add_subcommand("rebuild",
                                    "Build stored surfaces again from the current runs, with the options "
                                    "they were built with (one by name, or every --stale one)");
  r->add_option("name", rebuild_args->name, "Surface name (omit with --stale or to rebuild all)");
  r->add_option("--body", rebuild_args->body, "Only this body's surfaces");
  r->add_flag("--stale", rebuild_args->stale, "Only surfaces whose runs changed");
  r->add_flag("--json", rebuild_args->json, "Machine-readable output");
  r->callback([rebuild_args, &global] { rebuild(*rebuild_args, global); });

  auto list_args = std::make_shared<NameArgs>();
  auto* l = surface->add_subcommand("list", "List stored surfaces");
  l->add_option("--body", list_args->body, "Only this body's surfaces");
  l->add_flag("--json", list_args->json, "Machine-readable output");
  l->callback([list_args, &global] { list(*list_args, global); });

  auto show_args = std::make_shared<NameArgs>();
  auto* s = surface->add_subcommand("show", "Show one surface: axes, ranges, policies, quality, provenance");
  s->add_option("name", show_args->name, "Surface name")->required();
  s->add_flag("--json", show_args->json, "Machine-readable output (breakpoints included)");
  s->callback([show_args, &global] { show(*show_args, global); });
}

}  // namespace hydrocoef::cli
