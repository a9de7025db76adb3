// What every `hydrocoef plot` subcommand shares: the image options (-o,
// --size, --json) and the printing of the files written.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "hydrocoef/plot.hpp"

namespace hydrocoef::cli {

/// The options of every plot: the image, its size, JSON output.
struct CommonPlotArgs {
  ImageOptions image;
  bool json = false;
};

/// Registers them. surface_style: the image is -o only, since --output names
/// the surface's output there. default_size: what --size shows as its default
/// ("" : the plot's own, described by the caller).
void add_common(CLI::App* command, CommonPlotArgs& args, bool surface_style = false,
                const std::string& default_size = "900x600");

/// Prints what a plot wrote (text or JSON).
void print_plot(const PlotFiles& files, const CommonPlotArgs& args);

struct GlobalOptions;  // cli/common.hpp
/// `plot coefficient` (cli/cmd_plot_coefficient.cpp).
void add_coefficient_plot(CLI::App* plot_cmd, const GlobalOptions& global);

}  // namespace hydrocoef::cli
