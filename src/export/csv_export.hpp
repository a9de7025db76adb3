// CSV exports of a gridded surface, for spreadsheets, pandas and MATLAB's
// readtable. Numbers are written in their shortest round-trip form, so
// reading a file back gives the stored doubles exactly.
//
// Long form (any number of axes): '#' comment lines (surface, provenance,
// method, per-axis range and out-of-range policy, sign convention), then a
// header "u [m/s],v [m/s],X [N],N [N m]" and one row per grid node, axis 0
// varying fastest.
//
// Wide form (2-D tables only): the same comments, then a header
// "output,u [m/s] \ v [m/s],<v breakpoints...>" and, per output, one row per
// breakpoint of axis 0: "X,<u_i>,<X(u_i, v_0)>,<X(u_i, v_1)>,...".
#pragma once

#include <string>

#include "src/export/export.hpp"

namespace hydrocoef {

/// The long-form CSV text of a table.
std::string csv_long_text(const GridTable& table, const ExportMetadata& metadata);

/// The wide-form CSV text of a 2-D table; InputError naming the axes when the
/// table does not have exactly 2 axes.
std::string csv_wide_text(const GridTable& table, const ExportMetadata& metadata);

/// The '#' comment lines both forms start with (also used by other text formats).
std::string csv_comment_block(const GridTable& table, const ExportMetadata& metadata);

}  // namespace hydrocoef
