// The coordinates of a grid's nodes in GridTable's value order (axis 0
// fastest): what the exports, the surface builder and the Monte Carlo draws
// walk when they visit every node.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "src/surface/grid_table.hpp"

namespace hydrocoef {

/// point[a] = breakpoint of axis a at node `node` (node < product of the
/// axes' breakpoint counts; point holds one value per axis).
inline void grid_node_point(const std::vector<GridAxis>& axes, std::size_t node, std::span<double> point) {
  for (std::size_t a = 0; a < axes.size(); ++a) {
    const std::vector<double>& x = axes[a].breakpoints;
    point[a] = x[node % x.size()];
    node /= x.size();
  }
}

}  // namespace hydrocoef
