// What every plot subcommand shares (cli/plot_common.hpp).
#include "cli/plot_common.hpp"

#include <iostream>

namespace hydrocoef::cli {

void add_common(CLI::App* command, CommonPlotArgs& args, bool surface_style, const std::string& default_size) {
  args.image.size = default_size;
  command->add_option(surface_style ? "-o" : "-o,--output", args.image.image,
                      "Image to write: FILE.png or FILE.svg (FILE.dat, FILE.gp beside it)");
  auto* size = command->add_option("--size", args.image.size, "Image size WIDTHxHEIGHT [pixels]");
  if (!default_size.empty()) size->capture_default_str();
  command->add_flag("--json", args.json, "Print JSON: the files written and the series drawn");
}

void print_plot(const PlotFiles& files, const CommonPlotArgs& args) {
  std::cout << (args.json ? files.json() : files.text());
}

}  // namespace hydrocoef::cli
