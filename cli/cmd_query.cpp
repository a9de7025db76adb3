// hydrocoef query: a stored surface at one point (NAME u=0.2 v=0.07), or at
// every row of a CSV file or standard input, written as CSV.
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include "cli/common.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/text.hpp"
#include "src/surface/batch_query.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef::cli {
namespace {

struct QueryArgs {
  std::string name;
  std::vector<std::string> point;
  std::string input;
  std::string output = "-";
  bool gradient = false;
  bool uncertainty = false;
  bool json = false;
};

void warn_if_stale(const SurfaceRecord& record) {
  if (record.stale)
    std::cerr << "hydrocoef: warning: surface '" << escape::one_line(record.name)
              << "' is stale: forces of its body changed since it was built (hydrocoef surface rebuild "
              << escape::one_line(record.name) << ")\n";
}

void query_point(const QueryArgs& args, const StoredSurface& stored) {
  const CoefficientSurface& surface = stored.surface;
  const std::size_t n_axes = surface.axis_count(), n_out = surface.output_count();
  std::vector<double> point(n_axes, std::nan(""));
  for (const auto& text : args.point) {
    const auto [axis, value] = parse_assignment(text, "point");
    const std::size_t a = surface.axis_index(axis);
    if (!std::isnan(point[a])) throw InputError("axis '" + axis + "' is given twice");
    point[a] = value;
  }
  for (std::size_t a = 0; a < n_axes; ++a)
    if (std::isnan(point[a]))
      throw InputError("no value for axis '" + surface.axis_names()[a] + "'; surface '" + args.name +
                       "' needs one value for each of its axes: " + join(surface.axis_names(), ", ") + " (e.g. " +
                       surface.axis_names()[a] + "=0.1)");
  std::vector<double> out(n_out), gradient(n_out * n_axes), sd(n_out);
  if (args.uncertainty)
    surface.evaluate_with_standard_deviation(point, out, sd,
                                             args.gradient ? std::span<double>(gradient) : std::span<double>());
  else if (args.gradient)
    surface.evaluate_with_gradient(point, out, gradient);
  else
    surface.evaluate(point, out);

  if (args.json) {
    nlohmann::json json = {{"surface", args.name}, {"stale", stored.record.stale}};
    for (std::size_t a = 0; a < n_axes; ++a) json["point"][surface.axis_names()[a]] = point[a];
    for (std::size_t k = 0; k < n_out; ++k) {
      json["values"][surface.output_names()[k]] = out[k];
      json["units"][surface.output_names()[k]] = surface.output_units()[k];
      if (args.uncertainty) json["standard_deviation"][surface.output_names()[k]] = sd[k];
      if (args.uncertainty && surface.gp())
        json["new_run_standard_deviation"][surface.output_names()[k]] = surface.gp()->output(k).run_sd(sd[k]);
      if (args.gradient)
        for (std::size_t a = 0; a < n_axes; ++a)
          json["gradient"][surface.output_names()[k]][surface.axis_names()[a]] = gradient[k * n_axes + a];
    }
    std::cout << escape::json_text(json, 2) << '\n';
    return;
  }
  std::cout << escape::one_line(args.name) << " at";
  for (std::size_t a = 0; a < n_axes; ++a)
    std::cout << " " << escape::one_line(surface.axis_names()[a]) << "=" << significant(point[a], 8);
  std::cout << " (forces on the body)\n";
  for (std::size_t k = 0; k < n_out; ++k) {
    std::cout << "  " << std::left << std::setw(4) << escape::one_line(surface.output_names()[k]) << std::setw(16)
              << significant(out[k], 9) << escape::one_line(surface.output_units()[k]);
    if (args.uncertainty)
      std::cout << "  +/- " << significant(sd[k], 3) << " " << escape::one_line(surface.output_units()[k]) << " (1 sd"
                << (surface.gp() ? "; a new run there: +/- " + significant(surface.gp()->output(k).run_sd(sd[k]), 3)
                                 : std::string())
                << ")";
    std::cout << '\n';
    if (args.gradient)
      for (std::size_t a = 0; a < n_axes; ++a) {
        const std::string& unit = surface.axis_units()[a];
        std::cout << "      d" << escape::one_line(surface.output_names()[k]) << "/d" << std::setw(10)
                  << escape::one_line(surface.axis_names()[a]) << std::setw(16)
                  << significant(gradient[k * n_axes + a], 9) << escape::one_line(surface.output_units()[k])
                  << (unit.empty() ? "" : " per " + escape::one_line(unit)) << '\n';
      }
  }
}

void query_batch(const QueryArgs& args, const StoredSurface& stored) {
  const std::size_t points = query_csv_batch(
      stored.surface, CsvBatchRequest{args.name, args.input, args.output, args.gradient, args.uncertainty});
  if (args.output != "-" && !args.json)
    std::cerr << "hydrocoef: " << points << " points of surface '" << escape::one_line(args.name) << "' written to "
              << escape::one_line(args.output) << '\n';
  if (args.json && args.output != "-")
    std::cout << escape::json_text(nlohmann::json{{"surface", args.name}, {"points", points}, {"output", args.output}},
                                   2)
              << '\n';
}

void run_query(const QueryArgs& args, const GlobalOptions& global) {
  if (!args.input.empty() && !args.point.empty())
    throw InputError("give either a point (AXIS=VALUE ...) or --input, not both");
  if (args.input.empty() && args.point.empty())
    throw InputError("no point; expected AXIS=VALUE for each axis of the surface, or --input FILE (- for stdin)");
  RunDatabase database(global.database, RunDatabase::OpenMode::ReadOnly);
  const StoredSurface stored = load_surface(database, args.name);
  warn_if_stale(stored.record);
  if (args.input.empty())
    query_point(args, stored);
  else
    query_batch(args, stored);
}

}  // namespace

void add_query_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<QueryArgs>();
  auto* query = app.add_subcommand(
      "query",
      "Evaluate a stored surface: at one point (hydrocoef query NAME u=0.2 v=0.07), or at every row of a CSV whose "
      "header names the axes (--input FILE, - for stdin), written as CSV (--output FILE, default stdout). Values are "
      "forces on the body in N or N m; out-of-range points follow the surface's policy.");
  query->add_option("name", args->name, "Surface name")->required();
  query->add_option("point", args->point, "AXIS=VALUE for each axis (SI units)");
  query->add_option("--input", args->input, "CSV of points (header: axis names), - for standard input");
  query->add_option("--output", args->output, "CSV of results, - for standard output")->capture_default_str();
  query->add_flag("--gradient", args->gradient, "Also the derivative of each output along each axis");
  query->add_flag("--uncertainty", args->uncertainty,
                  "Also each output's standard deviation (GP surfaces: the posterior's, calibrated by the surface's "
                  "leave-one-out residuals and the runs' count, and a new run's about it with the discrepancy sd; "
                  "grid and RBF surfaces: "
                  "the runs' uncertainty interpolated as the surface, with the leave-one-out RMS error in "
                  "quadrature; a sigma_OUT column per output in a batch)");
  query->add_flag("--json", args->json, "Machine-readable output (single point)");
  query->callback([args, &global] { run_query(*args, global); });
}

}  // namespace hydrocoef::cli
