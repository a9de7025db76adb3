// hydrocoef surface build|rebuild|list|show: coefficient surfaces from stored
// runs, kept in the database with their quality figures.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include "cli/common.hpp"
#include "cli/surface_output.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/pipeline/surface_build.hpp"
#include "src/surface/grid_table.hpp"

namespace hydrocoef::cli {
namespace {

struct BuildArgs {
  std::string name;
  std::string body;
  std::vector<std::string> outputs;
  std::vector<std::string> axes;
  std::string method = "linear";
  std::vector<std::string> extrapolate;
  std::vector<std::string> where;
  std::vector<std::int64_t> exclude_runs;
  std::vector<std::string> mirror;
  std::vector<std::string> mirror_odd;
  bool replace = false;  ///< a surface of this name may be replaced (rebuild always replaces)
  std::string kernel = "cubic";
  int degree = 1;
  double smoothing = 0.0;
  std::vector<std::string> resample;
  std::string resample_method = "linear";
  double far_threshold = 0.25;
  bool json = false;
};

/// The build specification the options describe (names and grammar checked
/// before any run is read).
SurfaceBuildSpec make_spec(const BuildArgs& args) {
  SurfaceBuildSpec spec;
  SurfaceSpec& surface = spec.surface;
  surface.axes = args.axes;
  surface.outputs = args.outputs;
  surface.method = args.method;
  if (args.method != "rbf") parse_interpolation(args.method);
  surface.out_of_range = out_of_range_policies(args.axes, args.extrapolate, "--extrapolate");
  spec.where = args.where;
  spec.exclude_runs = args.exclude_runs;
  spec.mirror_planes = args.mirror;
  spec.mirror_odd = args.mirror_odd;
  surface.rbf.kernel = parse_rbf_kernel(args.kernel);
  surface.rbf.polynomial_degree = args.degree;
  surface.rbf.smoothing = args.smoothing;
  surface.resample_method = args.resample_method;
  surface.far_threshold = args.far_threshold;
  if (args.resample.empty()) return spec;
  if (args.method != "rbf") throw InputError("--resample tabulates an RBF surface; it needs --method rbf");
  std::map<std::string, std::vector<double>> grid;
  for (const auto& text : args.resample) grid.insert(parse_resample_entry(text, "--resample"));
  std::vector<std::vector<double>> breakpoints;
  for (const auto& axis : args.axes) {
    const auto it = grid.find(axis);
    if (it == grid.end())
      throw InputError("--resample gives no breakpoints for axis '" + axis + "'; expected one --resample per axis");
    breakpoints.push_back(it->second);
  }
  if (grid.size() != args.axes.size())
    throw InputError("--resample names an axis the surface does not have; its axes are given by --axes");
  surface.resample = breakpoints;
  parse_interpolation(args.resample_method);
  return spec;
}

nlohmann::json result_json(const SurfaceBuildResult& result) {
  nlohmann::json out = surface_json(result.stored.record, result.stored.surface, false);
  out["runs_skipped"] = result.runs_skipped;
  out["mirror"] = result.mirror;
  out["mirror_images"] = result.mirror_images;
  out["id"] = result.stored.record.id;
  return out;
}

void print_result(const SurfaceBuildResult& result, const std::string& database) {
  const auto& [record, surface] = result.stored;
  std::cout << "surface " << record.name << " of body " << record.body << ": " << record.kind << ", "
            << surface.method_name() << ", " << record.run_ids.size() << " runs";
  if (result.runs_skipped) std::cout << " (" << result.runs_skipped << " runs without every output skipped)";
  if (!result.mirror.empty())
    std::cout << "\n  mirror " << result.mirror << ": " << result.runs_measured << " runs and " << result.mirror_images
              << " mirror images (never stored as runs)"
              << (result.images_skipped
                      ? ", " + std::to_string(result.images_skipped) + " images left out at measured keys"
                      : std::string());
  std::cout << "\n  axes:\n";
  print_axes(surface);
  std::cout << "  outputs: ";
  for (std::size_t k = 0; k < surface.output_count(); ++k)
    std::cout << (k ? ", " : "") << surface.output_names()[k] << " [" << surface.output_units()[k] << "]";
  std::cout << " (forces on the body)\n";
  print_quality(record, surface);
  std::cout << "  stored as surface " << record.id << " in " << database << '\n';
}

void build(const BuildArgs& args, const GlobalOptions& global) {
  const SurfaceBuildSpec spec = make_spec(args);
  Database database(global.database, Database::OpenMode::MustExist);
  const auto result = build_and_store_surface(database, args.name, args.body, spec,
                                              args.replace ? Database::NameTaken::Replace : Database::NameTaken::Refuse);
  if (args.json) {
    std::cout << escape::json_text(result_json(result), 2) << '\n';
  } else {
    print_result(result, global.database);
  }
}

struct NameArgs {
  std::string name;
  std::optional<std::string> body;
  bool stale = false;
  bool json = false;
};

void rebuild(const NameArgs& args, const GlobalOptions& global) {
  Database database(global.database, Database::OpenMode::MustExist);
  const auto targets = surfaces_to_rebuild(database, args.name.empty() ? std::nullopt : std::optional(args.name),
                                           args.body, args.stale);
  if (targets.empty() && !args.json) std::cout << "no surface to rebuild\n";
  nlohmann::json rebuilt = nlohmann::json::array();
  for (const auto& record : targets) {
    const auto result = rebuild_surface(database, record);
    if (args.json) {
      rebuilt.push_back(result_json(result));
    } else {
      print_result(result, global.database);
    }
  }
  if (args.json) std::cout << escape::json_text(rebuilt, 2) << '\n';
}

void list(const NameArgs& args, const GlobalOptions& global) {
  Database database(global.database, Database::OpenMode::ReadOnly);
  print_surface_list(database.surfaces(args.body), global.database, args.json);
}

void show(const NameArgs& args, const GlobalOptions& global) {
  Database database(global.database, Database::OpenMode::ReadOnly);
  print_surface(load_surface(database, args.name), args.json);
}

}  // namespace

void add_surface_command(CLI::App& app, const GlobalOptions& global) {
  auto* surface = app.add_subcommand("surface", "Build, rebuild, list and show coefficient surfaces");
  surface->require_subcommand(1);

  auto build_args = std::make_shared<BuildArgs>();
  auto* b = surface->add_subcommand(
      "build",
      "Build a surface from a body's runs and store it. Runs that fill a grid over the axes give a gridded table "
      "(nearest, linear, pchip, makima, natural-spline); scattered runs need --method rbf (optionally tabulated "
      "with --resample). Outputs are forces on the body.");
  b->add_option("name", build_args->name, "Surface name")->required();
  b->add_option("--body", build_args->body, "Body whose runs are used")->required();
  b->add_option("--outputs", build_args->outputs, "Force components, e.g. X or X,Y,N")->required()->delimiter(',');
  b->add_option("--axes", build_args->axes, "Axes: velocity components (u..r) or disturbance names, e.g. u,current_v")
      ->required()
      ->delimiter(',');
  b->add_option("--method", build_args->method, "nearest, linear, pchip, makima, natural-spline, or rbf")
      ->capture_default_str();
  b->add_option("--extrapolate", build_args->extrapolate,
                "Out-of-range policy for every axis, or AXIS=POLICY (repeatable): error (default), clamp, linear, "
                "method; for rbf: error, clamp, extrapolate");
  b->add_option("--where", build_args->where,
                 "Select runs: NAME=VALUE, NAME!=VALUE, NAME<VALUE (<=, >, >=) or NAME=FROM:TO on a velocity component "
                 "(SI) or disturbance; repeatable, all must hold");
  b->add_flag("--replace", build_args->replace, "Replace a stored surface of the same name");
  b->add_option("--exclude-run", build_args->exclude_runs, "Leave out the run with this id (repeatable; leave-one-out by hand)");
  add_mirror_options(*b, build_args->mirror, build_args->mirror_odd);
  b->add_option("--kernel", build_args->kernel, "RBF kernel: cubic, thin-plate, linear")->capture_default_str();
  b->add_option("--degree", build_args->degree, "RBF polynomial degree (0, 1, 2)")->capture_default_str();
  b->add_option("--smoothing", build_args->smoothing, "RBF smoothing (0 interpolates)")->capture_default_str();
  b->add_option("--resample", build_args->resample,
                "Tabulate the RBF on a grid: AXIS=FROM:TO:COUNT or AXIS=X1,X2,... (one per axis)");
  b->add_option("--resample-method", build_args->resample_method, "Interpolation of the resampled grid")
      ->capture_default_str();
  b->add_option("--far-threshold", build_args->far_threshold,
                "Report grid points farther than this from every run (fraction of the runs' range)")
      ->capture_default_str();
  b->add_flag("--json", build_args->json, "Machine-readable output");
  b->callback([build_args, &global] { build(*build_args, global); });

  auto rebuild_args = std::make_shared<NameArgs>();
  auto* r = surface->add_subcommand("rebuild", "Build stored surfaces again from the current runs, with the options "
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
