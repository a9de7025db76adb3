// A stored surface at every row of a CSV of points, written as CSV: the batch
// query of `hydrocoef query --input`, as a library call.
//
// Input: a header naming the surface's axes (each once, any order), then one
// row of finite numbers per point (blank lines skipped, CRLF accepted).
// Output: the header "axes..., outputs..." (with --uncertainty also
// "sigma_OUT", the standard deviation of each output; with --gradient also
// "dOUT/dAXIS" per output and axis, output-major), then one row per point in
// input order, numbers in shortest round-trip form. Rows are answered on
// every core in slices of about 4 MB; the output file is written through an
// atomic file (src/core/atomic_file.hpp), so a batch that fails leaves no
// file. The first bad row in input order is reported, with its line and
// column, and nothing is written then.
#pragma once

#include <cstddef>
#include <string>

#include "src/surface/coefficient_surface.hpp"

namespace hydrocoef {

struct CsvBatchRequest {
  std::string surface_name;         ///< for messages
  std::string input;                ///< a CSV file, or "-" for standard input
  std::string output = "-";         ///< a CSV file, or "-" for standard output
  bool gradient = false;            ///< also the derivatives
  bool standard_deviation = false;  ///< also each output's standard deviation (GP surfaces)
};

/// Answers every row; returns the number of points. InputError naming the
/// input and line (and column) for a bad header or row, or the surface's own
/// message for a point it refuses (out of range); the output's name for a
/// write error.
std::size_t query_csv_batch(const CoefficientSurface& surface, const CsvBatchRequest& request);

}  // namespace hydrocoef
