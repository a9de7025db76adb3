// hydrocoef export: a stored gridded surface as a file another tool loads
// (CSV, JSON, a C99 header, MATLAB/Simulink .mat, JSBSim XML, VTK).
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/export/export.hpp"
#include "src/store/database.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef::cli {
namespace {

struct ExportArgs {
  std::string name;
  std::string format;
  std::string output;
  bool single_precision = false;
  std::string identifier;
  bool json = false;
};

void run_export(const ExportArgs& args, const GlobalOptions& global) {
  const ExportFormat format = parse_export_format(args.format);
  if (args.single_precision && format != ExportFormat::CHeader)
    throw InputError("--float applies to --format c only; expected it with c (got --format " + args.format + ")");
  if (!args.identifier.empty() && format != ExportFormat::CHeader)
    throw InputError("--identifier applies to --format c only; expected it with c (got --format " + args.format + ")");
  RunDatabase database(global.database, RunDatabase::OpenMode::ReadOnly);
  const StoredSurface stored = load_surface(database, args.name);
  const ExportMetadata metadata = metadata_from_record(stored.record, stored.surface);
  const GridTable& table = *stored.surface.grid();
  ExportOptions options;
  options.single_precision = args.single_precision;
  options.c_identifier = args.identifier;
  const auto files = export_table(table, metadata, format, args.output, options);
  // A table whose range leaves out zero on an axis that refuses values
  // outside it fails at rest (u = 0) in the controller: say so, once per axis.
  std::vector<std::string> refusals;
  for (std::size_t a = 0; a < table.axis_count(); ++a) {
    const GridAxis& axis = table.axes()[a];
    const double lower = axis.breakpoints.front(), upper = axis.breakpoints.back();
    if (axis.extrapolation == Extrapolation::Error && (lower > 0.0 || upper < 0.0))
      refusals.push_back("axis " + axis.name + " covers [" + shortest_number(lower) + ", " + shortest_number(upper) +
                         "] and refuses values outside it (policy error): a query at " + axis.name +
                         " = 0 (at rest) fails; build the surface with --extrapolate " + axis.name + "=clamp or " +
                         axis.name + "=linear if the controller will ask there");
  }

  if (args.json) {
    nlohmann::json out = {{"surface", metadata.surface_name},
                          {"body", metadata.body},
                          {"format", std::string(export_format_name(format))},
                          {"method", std::string(interpolation_name(table.method()))},
                          {"content_sha256", metadata.content_sha256},
                          {"runs", metadata.run_ids},
                          {"stale", metadata.stale},
                          {"nodes", table.node_count()}};
    out["files"] = nlohmann::json::array();
    for (const auto& file : files) out["files"].push_back(file.string());
    for (std::size_t a = 0; a < table.axis_count(); ++a) {
      const GridAxis& axis = table.axes()[a];
      out["axes"].push_back({{"name", axis.name},
                             {"unit", metadata.axis_units[a]},
                             {"breakpoints", axis.breakpoints.size()},
                             {"valid_range", {axis.breakpoints.front(), axis.breakpoints.back()}},
                             {"extrapolation", std::string(extrapolation_name(axis.extrapolation))}});
    }
    for (std::size_t k = 0; k < table.output_count(); ++k)
      out["outputs"].push_back({{"name", table.outputs()[k]}, {"unit", metadata.output_units[k]}});
    out["notes"] = refusals;
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  std::cout << "exported surface " << escape::one_line(metadata.surface_name) << " ("
            << interpolation_name(table.method()) << ", " << table.node_count() << " nodes) as "
            << export_format_name(format) << "\n";
  for (std::size_t a = 0; a < table.axis_count(); ++a) {
    const GridAxis& axis = table.axes()[a];
    std::cout << "  axis " << escape::one_line(axis.name) << " [" << escape::one_line(metadata.axis_units[a])
              << "] in [" << shortest_number(axis.breakpoints.front()) << ", "
              << shortest_number(axis.breakpoints.back()) << "], outside: " << extrapolation_name(axis.extrapolation)
              << '\n';
  }
  std::cout << "  outputs";
  for (std::size_t k = 0; k < table.output_count(); ++k)
    std::cout << ' ' << escape::one_line(table.outputs()[k]) << " [" << escape::one_line(metadata.output_units[k])
              << "]";
  std::cout << ", forces on the body\n  content sha256 " << escape::one_line(metadata.content_sha256) << '\n';
  for (const auto& file : files) std::cout << "  wrote " << escape::one_line(file.string()) << '\n';
  for (const auto& note : refusals) std::cout << "  note: " << escape::one_line(note) << '\n';
  if (metadata.stale)
    std::cout << "  note: the body's forces changed since this surface was built; rebuild it with "
                 "hydrocoef surface rebuild "
              << escape::one_line(metadata.surface_name) << '\n';
}

}  // namespace

void add_export_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<ExportArgs>();
  auto* command = app.add_subcommand(
      "export",
      "Write a stored gridded surface for another tool: csv, csv-wide, json, c (C99 header), mat "
      "(MATLAB v5 + Simulink set-up script), jsbsim (XML tables), vtk (ParaView) or daveml (DAVE-ML, "
      "AIAA S-119; with each node's standard deviation when the surface states one)");
  command->add_option("name", args->name, "Surface name")->required();
  command->add_option("--format", args->format, "csv, csv-wide, json, c, mat, jsbsim, vtk or daveml")->required();
  command->add_option("-o,--output", args->output, "File to write (written whole or not at all)")->required();
  command->add_flag("--float", args->single_precision, "C header: float tables and arithmetic (microcontrollers)");
  command->add_option("--identifier", args->identifier,
                      "C header: prefix of its names (default from the surface name)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_export(*args, global); });
}

}  // namespace hydrocoef::cli
