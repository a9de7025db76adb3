// The imposed motion of a forced-oscillation run in body axes (x forward,
// y starboard, z down): one degree of freedom moved as
// x_dof(t) = A sin(omega t + phase), A > 0. It comes from the case
// (importers/case_motion: OpenFOAM's dynamicMeshDict, CFX's CCL), turned
// from the case's axes into body axes with the import's frame, or from
// options (--motion surge --amplitude 0.03 --period 2 [--phase 0]).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "importers/case_motion.hpp"
#include "src/loads/frame.hpp"
#include "src/pmm/harmonic_analysis.hpp"

namespace hydrocoef {

/// "surge", "sway", "heave", "roll", "pitch", "yaw" for dof 0..5.
std::string_view dof_name(std::size_t dof);
/// The dof of a name above (or u..r), or nullopt.
std::optional<std::size_t> dof_named(std::string_view name);

/// The motion given as options: the DOF's name, the amplitude (m, or rad for
/// roll, pitch, yaw), the period (s) and the phase (rad). InputError naming
/// the option for a DOF name that is not one, or an amplitude or period that
/// is not a finite number > 0, or a phase that is not finite.
HarmonicMotion motion_from_options(std::string_view dof, double amplitude, double period, double phase);

/// A case's oscillation in body axes. The motion must lie along one body
/// axis (a combined motion, e.g. surge and heave at once, is refused: one
/// degree of freedom per run); a negative direction becomes a phase shift of
/// pi. A rotation must be about the body origin (the moment reference):
/// InputError otherwise, naming the case's origin.
HarmonicMotion body_motion(const CaseOscillation& oscillation, const FrameTransform& frame);

}  // namespace hydrocoef
