// hydrocoef import: read CFD result files (force tables, CFX monitor CSVs,
// CFD-Post exports, VTK-family files; folders of them), in parallel across
// files, and store their runs in one transaction.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <iostream>
#include <memory>
#include <mutex>
#include <thread>

#include "cli/common.hpp"
#include "cli/surface_options.hpp"
#include "importers/cfx_monitor.hpp"
#include "importers/force_table.hpp"
#include "src/core/error.hpp"
#include "src/store/database.hpp"

namespace hydrocoef::cli {
namespace {

struct ImportArgs {
  std::vector<std::string> inputs;
  std::string format = "auto";
  SurfaceArgs surface;
  // force tables
  std::vector<std::string> columns;
  std::vector<std::string> units;
  std::vector<std::string> disturbance_columns;
  std::vector<std::string> ignored;
  std::string sign = "on-body";
  // monitors
  std::vector<std::string> monitors;
  std::size_t average_last = 1;
  unsigned jobs = 0;
  bool replace = false;
  bool json = false;
};

/// What one file produced, ready for the database and for printing.
struct FileResult {
  std::string format;
  ImportBatch batch;
  std::optional<SurfaceRun> surface;
  std::optional<MonitorSummary> monitor;
  std::optional<std::filesystem::path> sidecar;
};

bool importable(const std::filesystem::path& file) {
  static const std::vector<std::string> extensions = {".csv", ".txt", ".tsv", ".dat", ".vtk", ".vtp",
                                                      ".vtu", ".vtm", ".case", ".encas", ".cgns"};
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return std::find(extensions.begin(), extensions.end(), extension) != extensions.end();
}

std::vector<std::filesystem::path> expand_inputs(const std::vector<std::string>& inputs) {
  std::vector<std::filesystem::path> files;
  for (const auto& input : inputs) {
    const std::filesystem::path path(input);
    if (std::filesystem::is_directory(path)) {
      std::vector<std::filesystem::path> found;
      for (const auto& entry : std::filesystem::recursive_directory_iterator(path))
        if (entry.is_regular_file() && importable(entry.path())) found.push_back(entry.path());
      if (found.empty())
        throw InputError(SourceLocation{input}, "folder holds no importable files (.csv .txt .dat .vtk .vtp .vtu "
                                                ".vtm .case .cgns)");
      std::sort(found.begin(), found.end());
      files.insert(files.end(), found.begin(), found.end());
    } else {
      files.push_back(path);
    }
  }
  return files;
}

FileResult import_one(const std::filesystem::path& file, const ImportArgs& args) {
  FileResult result;
  result.format = detect_format(file, args.format);
  if (result.format == "cfdpost" || result.format == "vtk") {
    SurfaceRunOptions options = surface_options_for(file, args.surface, result.sidecar);
    options.format = result.format;
    result.surface = import_surface_run(file, options);
    result.batch = result.surface->batch;
    return result;
  }
  // Tables and monitors take the run key and fluid from the command line.
  RunKey key;
  key.body = args.surface.body.empty() ? "vehicle" : args.surface.body;
  apply_set(args.surface.set, key);
  Fluid fluid{args.surface.rho, args.surface.nu};
  const auto ref = args.surface.ref_point ? parse_triple(*args.surface.ref_point, "--ref-point") : std::array<double, 3>{};
  if (result.format == "table") {
    ForceTableOptions options;
    options.body = key.body;
    options.velocity_b = key.nu_b;
    options.disturbances = key.disturbances;
    for (const auto& text : args.columns) {
      auto [component, header] = parse_text_assignment(text, "--column");
      if (!velocity_index(component) && !force_index(component))
        throw InputError("--column '" + text + "': '" + component + "' is not one of u v w p q r X Y Z K M N");
      options.columns[component] = header;
    }
    for (const auto& text : args.units) options.units.insert(parse_text_assignment(text, "--unit"));
    options.disturbance_columns = args.disturbance_columns;
    options.ignored_columns = args.ignored;
    options.sign = parse_sign_convention(args.sign);
    options.fluid = fluid;
    options.reference_point_b = ref;
    result.batch = read_force_table(file, options);
    return result;
  }
  CfxMonitorOptions options;
  options.key = key;
  options.fluid = fluid;
  options.reference_point_b = ref;
  options.sign = parse_sign_convention(args.sign);
  for (const auto& text : args.monitors) options.monitors.insert(parse_text_assignment(text, "--monitor"));
  for (const auto& text : args.units) options.units.insert(parse_text_assignment(text, "--unit"));
  options.average_last = args.average_last;
  auto imported = read_cfx_monitor(file, options);
  result.batch = std::move(imported.batch);
  result.monitor = imported.summary;
  return result;
}

/// Runs import_one over the files on `jobs` threads; a progress line on a
/// terminal. The first error in file order is rethrown after all stop.
std::vector<FileResult> import_all(const std::vector<std::filesystem::path>& files, const ImportArgs& args) {
  std::vector<FileResult> results(files.size());
  std::vector<std::exception_ptr> errors(files.size());
  std::atomic<std::size_t> next{0}, done{0};
  std::mutex print_mutex;
  const bool progress = isatty(STDERR_FILENO) && files.size() > 1;
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const unsigned jobs = std::clamp<unsigned>(args.jobs ? args.jobs : hardware, 1u, static_cast<unsigned>(files.size()));
  auto worker = [&] {
    for (std::size_t i = next++; i < files.size(); i = next++) {
      try {
        results[i] = import_one(files[i], args);
      } catch (...) {
        errors[i] = std::current_exception();
      }
      const std::size_t finished = ++done;
      if (progress) {
        const std::lock_guard<std::mutex> lock(print_mutex);
        std::cerr << "\r\033[K[" << finished << "/" << files.size() << "] " << files[i].filename().string()
                  << std::flush;
      }
    }
  };
  std::vector<std::thread> threads;
  for (unsigned t = 1; t < jobs; ++t) threads.emplace_back(worker);
  worker();
  for (auto& thread : threads) thread.join();
  if (progress) std::cerr << "\r\033[K" << std::flush;
  for (const auto& error : errors)
    if (error) std::rethrow_exception(error);
  return results;
}

void run_import(const ImportArgs& args, const GlobalOptions& global) {
  // Everything is read and integrated before the database is touched: a bad
  // file leaves it as it was.
  const auto files = expand_inputs(args.inputs);
  const auto results = import_all(files, args);
  std::vector<ImportBatch> batches;
  for (const auto& r : results) batches.push_back(r.batch);
  Database database(global.database);
  const auto outcomes = database.import(batches, args.replace ? ConflictPolicy::Replace : ConflictPolicy::Error);

  if (args.json) {
    nlohmann::json out;
    out["database"] = global.database;
    out["files"] = nlohmann::json::array();
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
      const auto& o = outcomes[i];
      nlohmann::json file = {{"path", o.path},
                             {"format", results[i].format},
                             {"sha256", o.sha256},
                             {"status", o.already_imported ? "already_imported" : "imported"},
                             {"runs_in_file", batches[i].runs.size()},
                             {"runs_created", o.runs_created},
                             {"runs_extended", o.runs_extended},
                             {"components_written", o.components_written}};
      if (o.already_imported) {
        file["previous_path"] = o.previous_path;
        file["previously_imported_at"] = o.previously_imported_at;
      }
      if (results[i].surface) file["surface"] = surface_run_json(*results[i].surface);
      if (results[i].monitor) {
        const auto& m = *results[i].monitor;
        file["monitor"] = {{"iterations", m.iterations}, {"window", m.window}, {"last_iteration", m.last_iteration}};
      }
      out["files"].push_back(file);
    }
    std::cout << out.dump(2) << '\n';
    return;
  }
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const auto& o = outcomes[i];
    if (o.already_imported) {
      std::cout << o.path << ": already imported (same SHA-256 as " << o.previous_path << ", imported "
                << o.previously_imported_at << "); nothing added\n";
      continue;
    }
    std::cout << o.path << ": " << results[i].format << ", " << batches[i].runs.size() << " run(s) of body '"
              << batches[i].runs.front().key.body << "' (" << o.runs_created << " new, " << o.runs_extended
              << " extended, " << o.components_written << " force components)\n";
    if (results[i].surface) {
      const auto& run = batches[i].runs.front();
      std::cout << "  key: " << describe(run.key) << '\n';
      const auto& l = results[i].surface->loads_b;
      const auto F = l.force(), M = l.moment();
      std::cout << "  X Y Z = " << significant(F[0]) << " " << significant(F[1]) << " " << significant(F[2])
                << " N;  K M N = " << significant(M[0]) << " " << significant(M[1]) << " " << significant(M[2])
                << " N m (body axes, on the body)\n";
      for (const auto& w : results[i].surface->warnings) std::cout << "  note: " << w << '\n';
    }
    if (results[i].monitor) {
      const auto& m = *results[i].monitor;
      std::cout << "  monitors: mean of the last " << m.window << " of " << m.iterations << " iterations (to "
                << m.last_iteration << ")\n";
    }
  }
  std::cout << "database: " << global.database << '\n';
}

}  // namespace

void add_import_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<ImportArgs>();
  auto* command = app.add_subcommand("import", "Import CFD result files or folders into the run database");
  command->add_option("inputs", args->inputs, "Files or folders to import (all in one transaction)")->required();
  command->add_option("--format", args->format, "auto (by extension and content), table, monitor, cfdpost or vtk")
      ->capture_default_str();
  command->add_option("--body", args->surface.body, "Body name the runs belong to (default vehicle)");
  add_surface_options(*command, args->surface);
  command->add_option("--column", args->columns,
                      "Table: map a header to a component, COMPONENT=HEADER, e.g. X=Drag (repeatable)");
  command->add_option("--unit", args->units,
                      "Table/monitor: unit of a column without one, NAME=UNIT, e.g. X=kN (repeatable)");
  command->add_option("--disturbance", args->disturbance_columns,
                      "Table: a header whose values are a disturbance parameter (repeatable)");
  command->add_option("--ignore", args->ignored, "Table: a header to skip (repeatable)");
  command->add_option("--sign", args->sign,
                      "Table/monitor sign convention: on-body (force on the body) or opposing (positive opposes "
                      "motion)")
      ->capture_default_str();
  command->add_option("--monitor", args->monitors, "Monitor: COMPONENT=COLUMN, e.g. X=\"USER POINT,Fx\" (repeatable)");
  command->add_option("--average-last", args->average_last, "Monitor: average the last N iterations")
      ->capture_default_str();
  command->add_option("--jobs", args->jobs, "Files read in parallel (default: the number of cores)");
  command->add_flag("--replace", args->replace, "Supersede force components that runs already have");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_import(*args, global); });
}

}  // namespace hydrocoef::cli
