// Test support: reads the data file written beside a plot (src/plot/figure):
// blocks of whitespace-separated numbers, each under a "# block K: TITLE" line.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/support/run_cli.hpp"

namespace hydrocoef::test {

/// (title, rows of numbers) per block, in file order.
using PlotBlocks = std::vector<std::pair<std::string, std::vector<std::vector<double>>>>;

inline PlotBlocks read_plot_blocks(const std::filesystem::path& path) {
  PlotBlocks blocks;
  std::istringstream in(read_text(path));
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("# block ", 0) == 0) {
      blocks.emplace_back(line.substr(line.find(": ") + 2), std::vector<std::vector<double>>{});
      continue;
    }
    if (line.empty() || line[0] == '#' || blocks.empty()) continue;
    std::istringstream row(line);
    std::vector<double> values;
    std::string cell;
    while (row >> cell) values.push_back(std::strtod(cell.c_str(), nullptr));
    blocks.back().second.push_back(values);
  }
  return blocks;
}

}  // namespace hydrocoef::test
