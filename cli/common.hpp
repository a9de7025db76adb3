// Shared pieces of the hydrocoef command line: global options and argument
// parsing helpers. The CLI only parses, calls the public API
// (include/hydrocoef/) and prints what it returns.
#pragma once

#include <CLI/CLI.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hydrocoef/hydrocoef.hpp"

namespace hydrocoef::cli {

struct GlobalOptions {
  std::string database = "hydrocoef.db";
};

/// Registers each subcommand; the callbacks run after parsing.
void add_import_command(CLI::App& app, const GlobalOptions& global);
void add_runs_command(CLI::App& app, const GlobalOptions& global);
void add_body_command(CLI::App& app, const GlobalOptions& global);
void add_fit_command(CLI::App& app, const GlobalOptions& global);
void add_integrate_command(CLI::App& app);
void add_simulate_command(CLI::App& app, const GlobalOptions& global);
void add_equilibrium_command(CLI::App& app, const GlobalOptions& global);
void add_surface_command(CLI::App& app, const GlobalOptions& global);
void add_query_command(CLI::App& app, const GlobalOptions& global);
void add_export_command(CLI::App& app, const GlobalOptions& global);
void add_export_gazebo_command(CLI::App& app, const GlobalOptions& global);
void add_export_fmu_command(CLI::App& app, const GlobalOptions& global);
void add_plot_command(CLI::App& app, const GlobalOptions& global);
void add_report_command(CLI::App& app, const GlobalOptions& global);
void add_suggest_command(CLI::App& app, const GlobalOptions& global);
void add_gci_command(CLI::App& app, const GlobalOptions& global);
void add_pmm_command(CLI::App& app, const GlobalOptions& global);
void add_pmm_runs_command(CLI::App& app, const GlobalOptions& global);
void add_added_mass_command(CLI::App& app, const GlobalOptions& global);
void add_merge_command(CLI::App& app, const GlobalOptions& global);
void add_derivatives_command(CLI::App& app, const GlobalOptions& global);
/// `derivatives pmm`, a subcommand of `derivatives` (cli/cmd_derivatives_pmm.cpp).
void add_derivatives_pmm_command(CLI::App& derivatives, const GlobalOptions& global);
/// `derivatives export` (cli/cmd_derivatives_export.cpp), a subcommand of `derivatives`.
void add_derivatives_export(CLI::App& derivatives, const GlobalOptions& global);
void add_scale_command(CLI::App& app, const GlobalOptions& global);

/// The selection options of runs, fit and surface build: --where (the
/// selection language of src/core/run_selection.hpp, repeatable, combined
/// with AND) and --exclude-run ID (repeatable).
struct SelectionArgs {
  std::vector<std::string> where;
  std::vector<std::int64_t> exclude_runs;
};
void add_selection_options(CLI::App& command, SelectionArgs& args);

/// --mirror u|v|w (repeatable) and --mirror-odd NAME (repeatable) of fit and
/// surface build (src/pipeline/fit_runs.hpp).
void add_mirror_options(CLI::App& command, std::vector<std::string>& planes, std::vector<std::string>& odd);

/// Parses "NAME=VALUE" (VALUE a finite number); InputError naming the option otherwise.
std::pair<std::string, double> parse_assignment(const std::string& text, const std::string& option);
/// Parses "NAME=TEXT".
std::pair<std::string, std::string> parse_text_assignment(const std::string& text, const std::string& option);
/// Parses "x,y,z" into three finite numbers.
std::array<double, 3> parse_triple(const std::string& text, const std::string& option);

}  // namespace hydrocoef::cli
