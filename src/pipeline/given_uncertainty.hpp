// An uncertainty the user states for the force components of an import:
// the setting "uncertainty" (hydrocoef import --uncertainty X=0.01,N=2%),
// one entry per component, absolute in the component's unit (N or N m) or
// relative to each value (a percentage). It is stored with each value
// (ForceComponent::uncertainty) and combined with a history's standard error
// in quadrature wherever a run's uncertainty is used.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "src/core/run.hpp"

namespace hydrocoef {

/// One component's stated uncertainty.
struct GivenUncertainty {
  double value = 0.0;     ///< N or N m, or a fraction of |value| when relative
  bool relative = false;  ///< given as a percentage
};

/// Parses "X=0.01,N=2%" (components X..N, each once; values finite and >= 0;
/// a percentage from 0 to 1000). `where` names the setting's origin for
/// messages. InputError otherwise.
std::array<std::optional<GivenUncertainty>, 6> parse_given_uncertainty(const std::string& text,
                                                                       const std::string& where);

/// Sets the stated uncertainty of every run's components in the batch
/// (components a run does not have are left alone).
void apply_given_uncertainty(ImportBatch& batch, const std::array<std::optional<GivenUncertainty>, 6>& given);

}  // namespace hydrocoef
