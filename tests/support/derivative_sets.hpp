// Derivative sets for the export tests (src/export/derivative_*_export):
// one fitted output with its terms and SI coefficients, named "fit-OUTPUT".
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "src/derivatives/terms.hpp"
#include "src/export/derivative_export.hpp"

namespace hydrocoef::test {

/// The set of `output` (X..N) with `terms` ("v, r, v*|v|") and their
/// coefficients, in the on-body sign convention, no covariance.
inline DerivativeSet derivative_set(const std::string& output, const std::string& terms,
                                    std::vector<double> coefficients) {
  DerivativeSet set;
  set.name = "fit-" + output;
  set.output = output;
  set.terms = parse_terms(terms);
  set.coefficients = std::move(coefficients);
  return set;
}

}  // namespace hydrocoef::test
