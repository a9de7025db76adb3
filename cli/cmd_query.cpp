// hydrocoef query: a stored surface at one point (NAME u=0.2 v=0.07), or at
// every row of a CSV file or standard input, written as CSV. The work and the
// printing are the library's (hydrocoef::query_surface); this parses.
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/database.hpp"
#include "hydrocoef/surface.hpp"
#include "src/core/escape.hpp"

namespace hydrocoef::cli {
namespace {

struct QueryArgs {
  hydrocoef::SurfaceQueryOptions options;
  std::vector<std::string> point;  ///< AXIS=VALUE
  bool json = false;
};

void run_query(QueryArgs& args, const GlobalOptions& global) {
  auto& options = args.options;
  // The point's text is read once a point (not a batch) is asked for; before
  // that only its presence counts (validate() refuses a point with --input).
  options.point.assign(args.point.size(), {});
  options.validate();
  for (std::size_t i = 0; i < args.point.size(); ++i) options.point[i] = parse_assignment(args.point[i], "point");
  options.warning = [](const std::string& warning) { std::cerr << "hydrocoef: warning: " << warning << '\n'; };
  const auto db = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
  const auto result = hydrocoef::query_surface(db, options);
  if (args.json) {
    std::cout << result.json();
    return;
  }
  std::cout << result.text();
  if (!result.note().empty()) std::cerr << "hydrocoef: " << result.note() << '\n';
}

}  // namespace

void add_query_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<QueryArgs>();
  auto& options = args->options;
  auto* query = app.add_subcommand(
      "query",
      "Evaluate a stored surface: at one point (hydrocoef query NAME u=0.2 v=0.07), or at every row of a CSV whose "
      "header names the axes (--input FILE, - for stdin), written as CSV (--output FILE, default stdout). Values are "
      "forces on the body in N or N m; out-of-range points follow the surface's policy.");
  query->add_option("name", options.name, "Surface name")->required();
  query->add_option("point", args->point, "AXIS=VALUE for each axis (SI units)");
  query->add_option("--input", options.input, "CSV of points (header: axis names), - for standard input");
  query->add_option("--output", options.output, "CSV of results, - for standard output")->capture_default_str();
  query->add_flag("--gradient", options.gradient, "Also the derivative of each output along each axis");
  query->add_flag("--uncertainty", options.uncertainty,
                  "Also each output's standard deviation (GP surfaces: the posterior's, calibrated by the surface's "
                  "leave-one-out residuals and the runs' count, and a new run's about it with the discrepancy sd; "
                  "grid and RBF surfaces: "
                  "the runs' uncertainty interpolated as the surface, with the leave-one-out RMS error in "
                  "quadrature; a sigma_OUT column per output in a batch)");
  query->add_flag("--json", args->json, "Machine-readable output (single point)");
  query->callback([args, &global] { run_query(*args, global); });
}

}  // namespace hydrocoef::cli
