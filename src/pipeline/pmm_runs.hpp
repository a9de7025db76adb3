// Forced-oscillation runs (a virtual planar motion mechanism) as a library
// call: what `hydrocoef pmm` does. Each input is a force history the import
// reads (OpenFOAM case folder or force files, CFX monitor, CSV of time and
// forces), brought into body axes with the import's frame and settings
// (src/pipeline/import_files.hpp, read_body_history); the imposed motion
// comes from the options or from the case (importers/case_motion:
// constant/dynamicMeshDict, or the CCL given with the request), turned into
// body axes (src/pmm/imposed_motion); src/pmm/harmonic_analysis splits each
// component into added mass and damping over whole periods after the
// start-up transient.
//
// Still water or an oscillating stream. A body moved through fluid at rest
// feels F_i = -M_A[i][j] x_j'' - D[i][j] x_j'. A body held in a stream whose
// displacement is x_s(t) feels the stream's pressure gradient as well (the
// Froude-Krylov force rho V x_s''): F_i = (rho V delta_ij + M_A[i][j]) x_s''
// + D[i][j] x_s' for translations (moments of the Froude-Krylov force are
// taken as zero: the centre of buoyancy at the moment reference). So for a
// stream the fitted in-phase and quadrature parts change sign and rho V is
// removed from the diagonal, with rho from the run's settings and V given.
// Rotational streams are refused.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "src/pipeline/import_files.hpp"
#include "src/pmm/harmonic_analysis.hpp"
#include "src/store/database.hpp"
#include "src/store/pmm_record.hpp"

namespace hydrocoef {

struct PmmRequest {
  ImportRequest import;                  ///< inputs, settings (--body, --axes, rho, nu ...), format, jobs, progress
  std::optional<HarmonicMotion> motion;  ///< body axes; none: from each case
  /// A CFX case's CCL (.ccl, .def text export, or solver output .out) to read the motion from.
  std::optional<std::filesystem::path> ccl;
  HarmonicFitOptions fit;
  PmmMedium medium = PmmMedium::StillWater;
  std::optional<double> size;              ///< body size D [m] for the KC and Stokes numbers
  std::optional<double> displaced_volume;  ///< V [m^3], required for an oscillating stream
  /// C of a restoring force F = -C x on the oscillated DOF's own component
  /// (N/m, or N m/rad for a rotation: a floating body's hydrostatics),
  /// removed from the history before the fit. Refused with a stream.
  std::optional<double> restoring;
};

/// The smallest amplitude analysed, relative to the body's scale (its size,
/// at least 1 m) for a translation, in rad for a rotation: below it the
/// displacement is at the round-off of the positions.
inline constexpr double kMinRelativeAmplitude = 1e-9;

struct PmmRun {
  std::filesystem::path path;
  std::string format;
  HarmonicAnalysis analysis;  ///< as fitted, in the still-water sense of the motion given
  PmmRecord record;           ///< what is stored (coefficients after the stream correction)
  std::vector<std::string> notes;
};

/// Reads and analyses every input (nothing is stored). InputError naming the
/// file for an input that is not a time history, a motion that cannot be
/// found or that the options contradict, an amplitude below
/// kMinRelativeAmplitude of the body's scale, fewer than 3 whole periods
/// after the transient, a stream without rho or V, a negative diagonal added
/// mass (the message names the likely causes: a restoring force, a wrong
/// phase or sign), or any result that is not a finite number.
std::vector<PmmRun> analyse_pmm_runs(const PmmRequest& request);

/// Stores the runs' records in one transaction.
std::vector<PmmSaved> store_pmm_runs(RunDatabase& database, const std::vector<PmmRun>& runs);

}  // namespace hydrocoef
