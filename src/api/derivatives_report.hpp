// The units of derivative models' coefficients, shared by the operations
// (src/api/derivatives.cpp) and their renderings (derivatives_report.cpp).
#pragma once

#include <string>

#include "src/derivatives/terms.hpp"

namespace hydrocoef {
inline namespace api {

/// "N" for X, Y, Z; "N m" for K, M, N.
std::string derivative_output_unit(const std::string& output);

/// The output's unit over the term's, SI: "N/(m/s)^2" for Y and v*|v|,
/// "N m/((m/s) (rad/s))" for N and v*r, "N/(m/s)^2" for Y and u*v, "N/rad" for Y and delta; a
/// disturbance with no known unit is written in brackets, "N/[vc]".
std::string derivative_coefficient_unit(const std::string& output, const Term& term);

}  // namespace api
}  // namespace hydrocoef
