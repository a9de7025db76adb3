// Evenly spaced breakpoints for resampling a surface onto a grid. A table a
// controller engineer reads must hold the values asked for: FROM:TO:COUNT =
// -0.1:0.05:4 gives -0.1, -0.05, 0, 0.05, not -0.049999999999999996 and
// 1.3877787807814457e-17, so the points are computed in decimal where the
// ends and the step are decimal numbers.
#pragma once

#include <cstddef>
#include <vector>

namespace hydrocoef {

/// `count` (>= 2) points from `from` to `to` (from < to, both finite), both
/// ends included. When from, to and the step are decimals of at most 17
/// significant digits, every point is the double nearest to its exact
/// decimal value (so 0 is 0 and -0.05 reads "-0.05"); otherwise
/// from + (to - from) i / (count - 1), with the last point `to` and points
/// within 1e-12 of the span from zero set to 0. Throws InputError when the
/// arguments break these conditions.
std::vector<double> evenly_spaced(double from, double to, std::size_t count);

}  // namespace hydrocoef
