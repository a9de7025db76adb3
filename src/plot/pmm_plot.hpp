// The figure of a forced-oscillation run: the force component in the
// direction of the motion over the kept window, as the CFD wrote it, with
// the harmonic fit drawn over it (src/store/pmm_record.hpp).
#pragma once

#include "src/plot/figure.hpp"
#include "src/store/pmm_record.hpp"

namespace hydrocoef::plot {

/// One panel: F_dof(t) of the stored history and the fit mean + sum_k
/// s_k sin(k(omega t + phase)) + c_k cos(k(omega t + phase)).
Figure pmm_figure(const PmmRecord& record);

}  // namespace hydrocoef::plot
