// What every `hydrocoef plot` subcommand shares: the image options, drawing
// the figure, and the report of the files written; and the parsing of the
// steady and curves plots' own options.
#pragma once

#include <CLI/CLI.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "src/plot/plots.hpp"

namespace hydrocoef::cli {

/// The options of every plot: the image, its size, JSON output.
struct CommonPlotArgs {
  std::optional<std::string> output;
  std::string size = "900x600";
  bool json = false;
};

/// Registers them. surface_style: the image is -o only, since --output names
/// the surface's output there.
void add_common(CLI::App* command, CommonPlotArgs& args, bool surface_style = false);

/// "asr-v:X(1,u,u|u|)" -> "fit-asr-v_X_1_u_u_u_.png": a default image name.
std::string default_image(const std::string& kind, const std::string& name);

/// Draws the figure to the image (-o or the default name) and prints the
/// files written (text or JSON).
void render_and_print(const plot::Figure& figure, const std::string& default_name, const CommonPlotArgs& args);

/// plot steady's forces: the --tau values, then --count values evenly from
/// --tau-from to --tau-to. InputError when none are given or the range is bad.
std::vector<double> steady_forces(const std::vector<double>& taus, std::optional<double> from, std::optional<double> to,
                                  std::size_t count);

/// plot curves' base fit name from --body, --dof and --terms (as fit --by
/// names its per-level fits). InputError when one is missing.
std::string curves_base_name(const std::optional<std::string>& body, const std::optional<std::string>& dof,
                             const std::optional<std::string>& terms);

}  // namespace hydrocoef::cli
