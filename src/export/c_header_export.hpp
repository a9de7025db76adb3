// A self-contained C99 header that evaluates a gridded surface on a
// controller or a microcontroller: breakpoint arrays per axis, one flat
// table, and a static inline function implementing exactly GridTable's
// evaluation (the same cell search, nearest-tie rule, tensor-product
// Hermite form and per-axis out-of-range policy, with the same arithmetic
// in the same order), so that in double precision it agrees with
// `hydrocoef query` to rounding (the tests ask for 1e-12).
//
// For the cubic methods the table holds, per node, the value and every
// mixed derivative (GridTable::hermite_data: 2^n numbers per value), so the
// header needs no spline code. It includes only <math.h> (for isfinite) and
// compiles warning-free with `cc -std=c99 -Wall -Wextra -Werror -pedantic`
// and as C++. With single_precision the tables and the arithmetic are float
// (about 1e-6 relative agreement), for targets without a double FPU.
//
// The generated API, for identifier P:
//   #define P_N_AXES, P_N_OUTPUTS, P_OUT_X (index of output X) ...
//   typedef double P_real;            (float with single_precision)
//   static inline int P_eval(const P_real x[P_N_AXES], P_real out[P_N_OUTPUTS]);
//     returns 0 on success; a + 1 when coordinate a is NaN or infinite, or
//     outside its range on an axis whose policy is "error" (out untouched).
#pragma once

#include <string>
#include <string_view>

#include "src/export/export.hpp"

namespace hydrocoef {

struct CHeaderOptions {
  bool single_precision = false;  ///< float tables and arithmetic
  std::string identifier;         ///< prefix of every name; empty = c_identifier_from(surface name)
};

/// The header's text. Throws InputError when the identifier is not a valid C
/// identifier or (single precision) a value does not fit in a float.
std::string c_header_text(const GridTable& table, const ExportMetadata& metadata, const CHeaderOptions& options = {});

/// A C identifier from a surface name: lower case, every other character
/// '_', prefixed "hc_" ("asr-v:surge" -> "hc_asr_v_surge").
std::string c_identifier_from(std::string_view name);

}  // namespace hydrocoef
