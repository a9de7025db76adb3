// A coefficient surface evaluated at many points at once, on every core: what
// a batch query (the Python module's Surface call, the C++ API's
// Surface::evaluate_batch) runs.
//
// Points come as strided columns, one per axis, so that a caller's arrays
// (numpy columns, the rows of a table, a constant broadcast with stride 0) are
// read where they are, without a copy; results go to strided columns the
// caller owns. The points are cut into chunks that the threads take in turn;
// no allocation is made per point (each thread has its own small point and
// result buffers). A gridded table's points inside every axis's range take a
// fast path, GridTable's own computation compiled for the table's axis count,
// which gives GridTable::evaluate's numbers bit for bit; other points and
// surfaces go through CoefficientSurface::evaluate.
//
// Units as CoefficientSurface: coordinates in axis units, values in output
// units, gradients in output unit per axis unit.
#pragma once

#include <cstddef>
#include <span>

#include "src/surface/coefficient_surface.hpp"

namespace hydrocoef {

/// Point i's value is data[i * stride]; stride in elements, any sign, 0 repeats one value.
struct StridedInput {
  const double* data = nullptr;
  std::ptrdiff_t stride = 1;
};
/// Point i's result goes to data[i * stride]; stride in elements.
struct StridedOutput {
  double* data = nullptr;
  std::ptrdiff_t stride = 1;
};

/// Evaluates `surface` at `count` points on `threads` threads (0: every core;
/// never more threads than chunks of points).
///   inputs:    surface.axis_count() columns, in axis order.
///   outputs:   surface.output_count() columns, in output order.
///   gradients: empty, or output_count() * axis_count() columns, column
///              k * axis_count() + a receiving d output_k / d axis_a.
///   standard_deviations: empty, or output_count() columns receiving each
///              output's standard deviation (GP surfaces only: InputError for
///              a surface that states none).
/// A point the surface refuses (a NaN or infinite coordinate, a coordinate
/// outside an axis whose policy is "error") stops the batch: the first such
/// point in index order is thrown as InputError "point I: MESSAGE" (I 0-based,
/// MESSAGE the surface's own). Every point before it has then been written;
/// the outputs of that point and of the points after it are unspecified.
/// std::invalid_argument for a wrong number of columns or a column with no
/// data while count > 0.
void evaluate_batch(const CoefficientSurface& surface, std::size_t count, std::span<const StridedInput> inputs,
                    std::span<const StridedOutput> outputs, std::span<const StridedOutput> gradients,
                    unsigned threads = 0, std::span<const StridedOutput> standard_deviations = {});

}  // namespace hydrocoef
