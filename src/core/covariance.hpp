// Checks a matrix received as a covariance (from a vehicle file or a stored
// fit) before anything draws from it.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>

namespace hydrocoef {

/// Why `covariance` (k x k, row by row) cannot be a covariance matrix: a size
/// other than k^2, a number that is not finite, an asymmetry beyond round-off,
/// or a negative eigenvalue beyond round-off. nullopt when it can.
std::optional<std::string> covariance_problem(std::span<const double> covariance, std::size_t k);

}  // namespace hydrocoef
