// MATLAB v5 .mat export (libmatio) for Simulink's n-D Lookup Table block,
// with a short set-up script beside it.
//
// Variables in the .mat file:
//   bp1 .. bpN      breakpoints of axis 1..N as column vectors [axis unit]
//   table_<OUT>     one N-D array per output, size n_1 x ... x n_N (n_1 x 1
//                   for a 1-D table), first axis varying fastest: exactly the
//                   layout the block's "Table data" expects with
//                   "Breakpoints 1" = bp1, "Breakpoints 2" = bp2, ...
//   info            a char row: JSON with axis and output names and units,
//                   policies, method, sign convention and provenance.
// The script <stem>_simulink.m (a MATLAB function, the stem made a valid
// identifier) loads the .mat beside it and sets a block's dimensions,
// breakpoints, table, InterpMethod, ExtrapMethod and
// DiagnosticForOutOfRangeInput:
//   nearest -> 'Nearest' (ties go to the higher breakpoint, as in hydrocoef);
//   linear  -> 'Linear point-slope';
//   clamp -> ExtrapMethod 'Clip'; error -> 'Clip' with the out-of-range
//   diagnostic 'Error'; linear/method -> 'Linear' (nearest always 'Clip').
// The block has one interpolation and one extrapolation for all its axes, and
// no PCHIP, makima or natural-spline method equal to hydrocoef's, so cubic
// surfaces and axes with differing policies are refused (use the C header).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "src/export/export.hpp"

namespace hydrocoef {

/// Writes PATH (.mat) and the script beside it; returns both paths. Throws
/// InputError (nothing written) when the block cannot reproduce the table or
/// a file cannot be written.
std::vector<std::filesystem::path> write_mat(const GridTable& table, const ExportMetadata& metadata,
                                             const std::filesystem::path& path);

/// The script's path for a .mat path: "dir/<identifier(stem)>_simulink.m".
std::filesystem::path simulink_script_path(const std::filesystem::path& mat_path);

/// A MATLAB identifier from a name: letters, digits and '_', starting with a
/// letter ("x" prefixed otherwise), at most 63 characters.
std::string matlab_identifier(std::string_view name);

}  // namespace hydrocoef
