// hydrocoef surface build|rebuild|list|show: coefficient surfaces from stored
// runs, kept in the database with their quality figures.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include "cli/common.hpp"
#include "src/pipeline/fit_runs.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/names.hpp"
#include "src/export/export.hpp"
#include "src/surface/breakpoints.hpp"
#include "src/surface/stored_surface.hpp"
#include "src/surface/surface_builder.hpp"

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

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const auto end = text.find(separator, start);
    out.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) return out;
    start = end + 1;
  }
}

double parse_number(const std::string& text, const std::string& option, const std::string& whole) {
  try {
    return parse_assignment("value=" + text, option).second;
  } catch (const InputError&) {
    throw InputError(option + " '" + whole + "': found '" + text + "', expected a finite number");
  }
}

/// "u=0:1.2:13" (from, to, count) or "u=0,0.1,0.4" (the breakpoints).
std::pair<std::string, std::vector<double>> parse_resample(const std::string& text) {
  const auto [axis, spec] = parse_text_assignment(text, "--resample");
  std::vector<double> out;
  if (spec.find(':') != std::string::npos) {
    const auto parts = split(spec, ':');
    if (parts.size() != 3)
      throw InputError("--resample '" + text + "': expected AXIS=FROM:TO:COUNT or AXIS=X1,X2,...");
    const double from = parse_number(parts[0], "--resample", text), to = parse_number(parts[1], "--resample", text);
    const double count = parse_number(parts[2], "--resample", text);
    if (!(to > from) || count < 2 || count != std::floor(count) || count > 100000)
      throw InputError("--resample '" + text + "': expected FROM < TO and a whole COUNT from 2 to 100000");
    out = evenly_spaced(from, to, static_cast<std::size_t>(count));
  } else {
    for (const auto& part : split(spec, ',')) out.push_back(parse_number(part, "--resample", text));
  }
  return {axis, out};
}

SurfaceSpec make_spec(const BuildArgs& args) {
  SurfaceSpec spec;
  spec.axes = args.axes;
  spec.outputs = args.outputs;
  spec.method = args.method;
  if (args.method != "rbf") parse_interpolation(args.method);  // name check before reading runs
  // --extrapolate POLICY (every axis) or AXIS=POLICY (repeatable).
  std::map<std::string, std::string> per_axis;
  std::string all;
  for (const auto& text : args.extrapolate) {
    if (text.find('=') == std::string::npos) {
      all = text;
    } else {
      const auto [axis, policy] = parse_text_assignment(text, "--extrapolate");
      if (std::find(args.axes.begin(), args.axes.end(), axis) == args.axes.end())
        throw InputError("--extrapolate '" + text + "': '" + axis + "' is not one of the surface's axes");
      per_axis[axis] = policy;
    }
  }
  for (const auto& axis : args.axes) {
    const auto it = per_axis.find(axis);
    spec.out_of_range.push_back(it != per_axis.end() ? it->second : all.empty() ? "error" : all);
  }
  if (args.method == "rbf") {
    spec.rbf.kernel = parse_rbf_kernel(args.kernel);
    spec.rbf.polynomial_degree = args.degree;
    spec.rbf.smoothing = args.smoothing;
    if (!args.resample.empty()) {
      std::map<std::string, std::vector<double>> grid;
      for (const auto& text : args.resample) grid.insert(parse_resample(text));
      std::vector<std::vector<double>> breakpoints;
      for (const auto& axis : args.axes) {
        const auto it = grid.find(axis);
        if (it == grid.end())
          throw InputError("--resample gives no breakpoints for axis '" + axis + "'; expected one --resample per axis");
        breakpoints.push_back(it->second);
      }
      if (grid.size() != args.axes.size())
        throw InputError("--resample names an axis the surface does not have; its axes are given by --axes");
      spec.resample = breakpoints;
      spec.resample_method = args.resample_method;
      parse_interpolation(args.resample_method);
    }
    spec.far_threshold = args.far_threshold;
  } else if (!args.resample.empty()) {
    throw InputError("--resample tabulates an RBF surface; it needs --method rbf");
  }
  return spec;
}

nlohmann::json build_json(const BuildArgs& args) {
  return {{"outputs", args.outputs},   {"axes", args.axes},          {"method", args.method},
          {"extrapolate", args.extrapolate}, {"where", args.where},  {"exclude_runs", args.exclude_runs}, {"kernel", args.kernel},
          {"degree", args.degree},     {"smoothing", args.smoothing}, {"resample", args.resample},
          {"resample_method", args.resample_method}, {"far_threshold", args.far_threshold},
          {"mirror", args.mirror}, {"mirror_odd", args.mirror_odd}};
}

BuildArgs args_from_json(const std::string& name, const std::string& body, const nlohmann::json& build) {
  BuildArgs args;
  args.name = name;
  args.body = body;
  try {
    args.outputs = build.at("outputs").get<std::vector<std::string>>();
    args.axes = build.at("axes").get<std::vector<std::string>>();
    args.method = build.at("method").get<std::string>();
    args.extrapolate = build.at("extrapolate").get<std::vector<std::string>>();
    args.where = build.at("where").get<std::vector<std::string>>();
    if (build.contains("exclude_runs")) args.exclude_runs = build.at("exclude_runs").get<std::vector<std::int64_t>>();
    args.kernel = build.at("kernel").get<std::string>();
    args.degree = build.at("degree").get<int>();
    args.smoothing = build.at("smoothing").get<double>();
    args.resample = build.at("resample").get<std::vector<std::string>>();
    args.resample_method = build.at("resample_method").get<std::string>();
    args.far_threshold = build.at("far_threshold").get<double>();
    if (build.contains("mirror")) args.mirror = build.at("mirror").get<std::vector<std::string>>();
    if (build.contains("mirror_odd")) args.mirror_odd = build.at("mirror_odd").get<std::vector<std::string>>();
  } catch (const nlohmann::json::exception& error) {
    throw InputError("surface '" + name + "': its stored build options are incomplete (" + error.what() +
                     "); build it again with hydrocoef surface build");
  }
  return args;
}

std::string json_number_text(const nlohmann::json& value, int digits) {
  return value.is_number() ? significant(value.get<double>(), digits) : "n/a";
}

/// The grid nodes of a resampled surface that are far from every run, as
/// coordinates (empty for other surfaces).
std::vector<std::vector<double>> far_nodes(const SurfaceRecord& record, const CoefficientSurface& surface) {
  if (!surface.grid()) return {};
  return metadata_from_record(record, surface).far_from_data;
}

/// The run with the largest leave-one-out error of an output, and the error;
/// nullopt without per-run errors (surfaces built before they were stored).
std::optional<std::pair<std::int64_t, double>> worst_run(const nlohmann::json& quality, const std::string& output) {
  if (!quality.contains("loo_runs") || !quality.contains("outputs") || !quality["outputs"].contains(output) ||
      !quality["outputs"][output].contains("loo_errors"))
    return std::nullopt;
  const auto& runs = quality["loo_runs"];
  const auto& errors = quality["outputs"][output]["loo_errors"];
  std::optional<std::pair<std::int64_t, double>> worst;
  for (std::size_t i = 0; i < errors.size() && i < runs.size(); ++i)
    if (errors[i].is_number() && runs[i].is_number_integer() &&
        (!worst || std::abs(errors[i].get<double>()) > std::abs(worst->second)))
      worst = std::make_pair(runs[i].get<std::int64_t>(), errors[i].get<double>());
  return worst;
}

void print_quality(const SurfaceRecord& record, const CoefficientSurface& surface) {
  const auto quality = nlohmann::json::parse(record.quality.empty() ? "{}" : record.quality);
  const std::string loo = quality.value("loo_method", "");
  std::cout << "  leave-one-out (" << (loo == "rbf-exact" ? "exact, RBF" : "along grid lines") << ", "
            << quality.value("loo_defined", 0) << " of " << quality.value("runs", 0) << " runs):\n";
  for (std::size_t k = 0; k < surface.output_count(); ++k) {
    const auto& name = surface.output_names()[k];
    const auto entry = quality.contains("outputs") && quality["outputs"].contains(name) ? quality["outputs"][name]
                                                                                       : nlohmann::json::object();
    std::cout << "    " << std::left << std::setw(4) << name << "max " << std::setw(12)
              << json_number_text(entry.value("loo_max", nlohmann::json()), 4) << "RMS " << std::setw(12)
              << json_number_text(entry.value("loo_rms", nlohmann::json()), 4) << surface.output_units()[k];
    if (const auto worst = worst_run(quality, name))
      std::cout << "  (worst: run " << worst->first << ", " << significant(worst->second, 4) << ")";
    std::cout << '\n';
  }
  if (quality.contains("grid_points")) {
    const auto far = quality["far_from_data"].size();
    std::cout << "  resampled grid: " << quality["grid_points"].get<std::size_t>() << " points, " << far
              << " farther than " << significant(quality["far_threshold"].get<double>(), 3)
              << " (scaled) from every run" << (far ? ": extrapolated there, not data" : "") << '\n';
    const auto nodes = far_nodes(record, surface);
    for (std::size_t i = 0; i < nodes.size() && i < 20; ++i) {
      std::cout << "    (";
      for (std::size_t a = 0; a < nodes[i].size(); ++a)
        std::cout << (a ? ", " : "") << surface.axis_names()[a] << " = " << significant(nodes[i][a], 6);
      std::cout << ")\n";
    }
    if (nodes.size() > 20) std::cout << "    ... and " << nodes.size() - 20 << " more (--json lists them all)\n";
  }
}

void print_axes(const CoefficientSurface& surface) {
  for (std::size_t a = 0; a < surface.axis_count(); ++a) {
    std::cout << "    " << std::left << std::setw(12) << surface.axis_names()[a] << "[" << significant(surface.lower(a), 6)
              << ", " << significant(surface.upper(a), 6) << "] "
              << (surface.axis_units()[a].empty() ? "(SI)" : surface.axis_units()[a]);
    if (const GridTable* grid = surface.grid())
      std::cout << ", " << grid->axes()[a].breakpoints.size() << " breakpoints"
                << (grid->evenly_spaced(a) ? " (even)" : "");
    std::cout << ", out of range: " << surface.out_of_range_name(a) << '\n';
  }
}

nlohmann::json surface_json(const SurfaceRecord& record, const CoefficientSurface& surface, bool with_values) {
  nlohmann::json out = {{"name", record.name},       {"body", record.body},     {"kind", record.kind},
                        {"method", record.method},   {"created_at", record.created_at},
                        {"stale", record.stale},     {"runs", record.run_ids}};
  out["axes"] = nlohmann::json::array();
  for (std::size_t a = 0; a < surface.axis_count(); ++a) {
    nlohmann::json axis = {{"name", surface.axis_names()[a]},
                           {"unit", surface.axis_units()[a]},
                           {"lower", surface.lower(a)},
                           {"upper", surface.upper(a)},
                           {"out_of_range", surface.out_of_range_name(a)}};
    if (const GridTable* grid = surface.grid()) {
      axis["breakpoints"] = grid->axes()[a].breakpoints.size();
      if (with_values) axis["breakpoint_values"] = grid->axes()[a].breakpoints;
    }
    out["axes"].push_back(axis);
  }
  out["outputs"] = nlohmann::json::array();
  for (std::size_t k = 0; k < surface.output_count(); ++k)
    out["outputs"].push_back({{"name", surface.output_names()[k]}, {"unit", surface.output_units()[k]}});
  out["quality"] = nlohmann::json::parse(record.quality.empty() ? "{}" : record.quality);
  out["loo_worst"] = nlohmann::json::object();
  for (const auto& name : surface.output_names())
    if (const auto worst = worst_run(out["quality"], name))
      out["loo_worst"][name] = {{"run", worst->first}, {"error", worst->second}};
  out["far_from_data_points"] = nlohmann::json::array();
  for (const auto& node : far_nodes(record, surface)) {
    nlohmann::json point = nlohmann::json::object();
    for (std::size_t a = 0; a < node.size(); ++a) point[surface.axis_names()[a]] = node[a];
    out["far_from_data_points"].push_back(point);
  }
  const auto definition = nlohmann::json::parse(record.definition);
  if (definition.contains("build")) out["build"] = definition["build"];
  return out;
}

void build(const BuildArgs& args, const GlobalOptions& global) {
  check_name(NameKind::Surface, args.name, {}, "the surface name");
  check_name(NameKind::Body, args.body, {}, "--body");
  const SurfaceSpec spec = make_spec(args);
  Database database(global.database, Database::OpenMode::MustExist);
  // Reusing a name replaces what another build made: only when asked.
  if (!args.replace) {
    for (const auto& existing : database.surfaces())
      if (existing.name == args.name)
        throw InputError(SourceLocation{global.database},
                         "a surface named '" + args.name + "' exists (built " + existing.created_at +
                             " from " + std::to_string(existing.run_ids.size()) +
                             " runs); give --replace to replace it, or another name");
  }
  RunFilter filter;
  filter.body = args.body;
  const RunSelection selection = parse_selection(args.where, args.exclude_runs);
  const MirrorSpec mirror = make_mirror_spec(args.mirror, args.mirror_odd);
  const auto measured = selected_runs(database, filter, selection);
  if (measured.empty())
    throw InputError("no runs of body '" + args.body + "'" +
                     (selection.empty() ? "" : " matching '" + selection.text() + "'") + " in " + global.database);
  // Mirror images stand beside the runs in the build; they are never stored as runs.
  std::size_t images_skipped = 0;
  const auto runs = with_mirror_images(measured, mirror, &images_skipped);
  const std::size_t images = runs.size() - measured.size();
  const BuiltSurface built = build_surface(runs, spec);
  SurfaceRecord record = built.record(args.name, args.body);
  auto definition = nlohmann::json::parse(record.definition);
  definition["build"] = build_json(args);
  record.definition = escape::json_text(definition);
  record.id = database.save_surface(record);
  const StoredSurface stored = load_surface(database, args.name);

  if (args.json) {
    nlohmann::json out = surface_json(stored.record, stored.surface, false);
    out["runs_skipped"] = built.runs_skipped;
    out["mirror"] = mirror.text();
    out["mirror_images"] = images;
    out["id"] = record.id;
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  std::cout << "surface " << args.name << " of body " << args.body << ": " << record.kind << ", "
            << stored.surface.method_name() << ", " << built.run_ids.size() << " runs";
  if (built.runs_skipped) std::cout << " (" << built.runs_skipped << " runs without every output skipped)";
  if (!mirror.empty())
    std::cout << "\n  mirror " << mirror.text() << ": " << measured.size() << " runs and " << images
              << " mirror images (never stored as runs)"
              << (images_skipped ? ", " + std::to_string(images_skipped) + " images left out at measured keys"
                                 : std::string());
  std::cout << "\n  axes:\n";
  print_axes(stored.surface);
  std::cout << "  outputs: ";
  for (std::size_t k = 0; k < stored.surface.output_count(); ++k)
    std::cout << (k ? ", " : "") << stored.surface.output_names()[k] << " [" << stored.surface.output_units()[k] << "]";
  std::cout << " (forces on the body)\n";
  print_quality(stored.record, stored.surface);
  std::cout << "  stored as surface " << record.id << " in " << global.database << '\n';
}

struct NameArgs {
  std::string name;
  std::optional<std::string> body;
  bool stale = false;
  bool json = false;
};

void rebuild(const NameArgs& args, const GlobalOptions& global) {
  std::vector<SurfaceRecord> targets;
  {
    Database database(global.database, Database::OpenMode::MustExist);
    if (!args.name.empty()) {
      targets.push_back(database.surface(args.name));
    } else {
      for (auto& record : database.surfaces(args.body))
        if (record.stale || !args.stale) targets.push_back(std::move(record));
    }
  }
  if (targets.empty() && !args.json) std::cout << "no surface to rebuild\n";
  nlohmann::json rebuilt = nlohmann::json::array();
  for (const auto& record : targets) {
    const auto definition = nlohmann::json::parse(record.definition);
    if (!definition.contains("build"))
      throw InputError("surface '" + record.name + "' was not built by hydrocoef surface build; it cannot be rebuilt");
    BuildArgs build_args = args_from_json(record.name, record.body, definition["build"]);
    build_args.json = args.json;
    build_args.replace = true;
    if (args.json) {
      std::ostringstream captured;
      auto* old = std::cout.rdbuf(captured.rdbuf());
      try {
        build(build_args, global);
      } catch (...) {
        std::cout.rdbuf(old);
        throw;
      }
      std::cout.rdbuf(old);
      rebuilt.push_back(nlohmann::json::parse(captured.str()));
    } else {
      build(build_args, global);
    }
  }
  if (args.json) std::cout << escape::json_text(rebuilt, 2) << '\n';
}

/// What a surface was built from, in the selection language: "all runs",
/// "u>=0.1 exclude-run 6", with ", mirror v" when mirror images stood beside
/// the runs.
std::string built_from(const SurfaceRecord& record) {
  const auto definition = nlohmann::json::parse(record.definition, nullptr, false);
  if (definition.is_discarded() || !definition.contains("build")) return "(not built by surface build)";
  try {
    const BuildArgs args = args_from_json(record.name, record.body, definition["build"]);
    const std::string selection = parse_selection(args.where, args.exclude_runs).text();
    const std::string mirror = make_mirror_spec(args.mirror, args.mirror_odd).text();
    return (selection.empty() ? std::string("all runs") : selection) + (mirror.empty() ? "" : ", mirror " + mirror);
  } catch (const InputError&) {
    return "(build options not readable)";
  }
}

void list(const NameArgs& args, const GlobalOptions& global) {
  Database database(global.database, Database::OpenMode::ReadOnly);
  const auto records = database.surfaces(args.body);
  if (args.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& record : records) out.push_back(surface_json(record, surface_from_record(record), false));
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  if (records.empty()) {
    std::cout << "no surfaces in " << global.database << '\n';
    return;
  }
  std::cout << std::left << std::setw(20) << "name" << std::setw(10) << "body" << std::setw(6) << "kind" << std::setw(16)
            << "method" << std::setw(18) << "axes" << std::setw(14) << "outputs" << std::setw(6) << "runs"
            << std::setw(22) << "state" << "built from\n";
  for (const auto& record : records) {
    const CoefficientSurface surface = surface_from_record(record);
    std::string axes, outputs;
    for (const auto& a : surface.axis_names()) axes += (axes.empty() ? "" : ",") + a;
    for (const auto& o : surface.output_names()) outputs += (outputs.empty() ? "" : ",") + o;
    std::cout << std::setw(20) << record.name << std::setw(10) << record.body << std::setw(6) << record.kind
              << std::setw(16) << surface.method_name() << std::setw(18) << axes << std::setw(14) << outputs
              << std::setw(6) << record.run_ids.size() << std::setw(22)
              << (record.stale ? "STALE (runs changed)" : "current") << built_from(record) << '\n';
  }
}

void show(const NameArgs& args, const GlobalOptions& global) {
  Database database(global.database, Database::OpenMode::ReadOnly);
  const StoredSurface stored = load_surface(database, args.name);
  if (args.json) {
    std::cout << escape::json_text(surface_json(stored.record, stored.surface, true), 2) << '\n';
    return;
  }
  const auto& record = stored.record;
  std::cout << "surface " << record.name << " of body " << record.body << "\n  kind: " << record.kind
            << ", method: " << stored.surface.method_name() << "\n  built: " << record.created_at << " from "
            << record.run_ids.size() << " runs\n  state: "
            << (record.stale ? "STALE: forces of this body changed since it was built (hydrocoef surface rebuild " +
                                   record.name + ")"
                             : std::string("current"))
            << "\n  axes:\n";
  print_axes(stored.surface);
  std::cout << "  outputs (forces on the body):\n";
  for (std::size_t k = 0; k < stored.surface.output_count(); ++k)
    std::cout << "    " << stored.surface.output_names()[k] << " [" << stored.surface.output_units()[k] << "]\n";
  print_quality(record, stored.surface);
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
