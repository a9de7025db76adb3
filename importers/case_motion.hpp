// The harmonic motion a CFD case imposes on its body, as the case states it
// (in the case's own axes): what a forced-oscillation run (a virtual planar
// motion mechanism, src/pmm/) needs besides its force history.
//
// OpenFOAM (constant/dynamicMeshDict, the solidBody motion solver; v1912
// source, src/dynamicMesh/motionSolvers/displacement/solidBody and
// solidBodyMotionFunctions):
//   motionSolver solidBody;                      (or dynamicFvMesh solidBodyMotionFvMesh)
//   solidBodyMotionFunction oscillatingLinearMotion;
//   oscillatingLinearMotionCoeffs { amplitude (0.015 0 0); omega 3.14159; }
// gives the displacement amplitude sin(omega t) [m]; oscillatingRotatingMotion
// (origin, amplitude, omega) gives the Euler angles amplitude sin(omega t),
// with the amplitude in DEGREES (the function converts them to radians),
// about `origin`; releases after v1912 add phaseShift (rad, inside the sine)
// and verticalShift (an offset, which changes no velocity), both read. The
// entries may sit in a solidBodyCoeffs (or
// solidBodyMotionFvMeshCoeffs) sub-dictionary, and the coefficients in a
// <function>Coeffs sub-dictionary or beside the function's name, as
// OpenFOAM's optionalSubDict reads them. Other motion functions (linear,
// rotating, SDA, multiMotion, tabulated) are refused with the file and line.
//
// CFX (CCL of the case or of the solver output): a mesh motion of option
// Specified Displacement with Cartesian components, each a constant 0 or
// `A * sin(omega * t + phi)` in CEL, where A, omega and phi are constant
// expressions (named expressions of LIBRARY: CEL: EXPRESSIONS: and `pi`
// are followed). Boundaries that state the same motion (a domain moved
// rigidly) count once; different motions are refused, naming them.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include "importers/cfx_ccl.hpp"

namespace hydrocoef {

/// A harmonic translation or rotation in the case's axes:
/// displacement (m) or rotation angles (rad) = amplitude * sin(omega t + phase).
struct CaseOscillation {
  bool rotation = false;
  std::array<double, 3> amplitude{};  ///< per case axis: m, or rad for a rotation
  double omega = 0.0;                 ///< rad/s
  double phase = 0.0;                 ///< rad
  std::array<double, 3> origin{};     ///< a rotation's centre, case coordinates [m]
  std::string where;                  ///< "case/constant/dynamicMeshDict:21"
  std::string description;            ///< "oscillatingLinearMotion, amplitude (0.015 0 0) m, omega 3.14159 rad/s"
};

/// The solidBody oscillation of constant/dynamicMeshDict, or nullopt when
/// the case has no such file or moves no mesh (staticFvMesh). InputError
/// naming the file and line for a motion that is not a harmonic one, a
/// motion of several bodies, or values that are not numbers.
std::optional<CaseOscillation> read_openfoam_motion(const std::filesystem::path& case_dir);

/// The specified-displacement oscillation of a CFX case, or nullopt when the
/// CCL states no mesh motion. InputError at the CCL line for a displacement
/// that is not of the form A*sin(omega*t + phi), or for boundaries that
/// move differently.
std::optional<CaseOscillation> cfx_motion(const CclDocument& document);

}  // namespace hydrocoef
