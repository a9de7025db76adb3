// OpenFOAM's integrated force output read into a ForceHistory: what the
// `forces` and `forceCoeffs` function objects write under
// postProcessing/<name>/<startTime>/, every layout they have had.
//
// - ESI (openfoam.com) v1906 and later: force.dat and moment.dat, headed
//     # Force
//     # CofR                : (0 0 0)
//     #
//     # Time   (total_x total_y total_z) (pressure_x ...) (viscous_x ...) [(porous_x ...)]
//   with each vector in parentheses up to v2112 and without them from v2206
//   ("redundant parentheses removed"). Columns are found by name, so any order
//   and the porous (also "internal") part are read.
// - Foundation (openfoam.org) releases: forces.dat, headed
//     # Time   forces(pressure viscous porous) moment(pressure viscous porous)
//   (moments(...) and a two-part (pressure viscous) form in newer releases; a
//   CofR column in front for moving bodies), rows nested as
//     t  ((px py pz) (vx vy vz) (ox oy oz)) ((mpx ...) (...) (...))
//   With localForces/localMoments in the header, each time has a second row in
//   the local coordinate system; the first (global axes) is kept.
// - forceCoeffs: coefficient.dat (ESI: Cd Cs Cl CmRoll CmPitch CmYaw and the
//   front/rear parts, in any order) or forceCoeffs.dat (Foundation: Cm Cd Cl
//   ...), with the reference values magUInf, lRef, Aref, CofR and the
//   directions (ESI dragDir/sideDir/liftDir; Foundation dragDir/liftDir/
//   pitchAxis) in the header. Coefficients become forces with
//   F = C * 0.5 rho magUInf^2 Aref and moments with M = C * 0.5 rho magUInf^2
//   Aref lRef; rho is the fluid's density, which the header does not hold (it
//   comes from the case or the caller; a coefficient does not depend on the
//   rhoInf the case used). The components stay in the coefficient axes (x =
//   drag, y = side, z = lift), which HistoryFrame::axes_in_global records;
//   rotated_to_global_axes turns them when all three are present. The
//   front/rear columns are sums of the others and are not read.
//
// Restarts. A function object folder holds a start-time folder per run
// (postProcessing/forces/0, .../500) and, when a run restarts into an existing
// folder, files named force_<time>.dat. All are joined in time order: files
// are ordered by their first time (then start-time folder, then the time in
// their name), and a file replaces whatever earlier files hold from its first
// time on (a run restarted from an earlier write time overwrites the end of
// the previous one). ForceHistory::notes says what was replaced,
// HistorySourceFile::rows_used how much of each file is kept.
//
// Time or iteration. Steady solvers (simpleFoam) count iterations in the time
// column. Unless the caller says (from the case's ddtSchemes), a history whose
// every time value is a whole number is taken as iterations, otherwise as time
// in seconds; a note says which rule decided.
//
// The frame: forces on the patches in the solver's global axes (or in the
// function object's coordinateSystem, which the files do not reveal),
// moments about CofR, in N and N m (OpenFOAM applies rho, or rhoInf for
// incompressible solvers, itself; a case run with rhoInf 1 writes forces per
// unit density: the caller must know).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "src/history/force_history.hpp"

namespace hydrocoef {

inline constexpr std::string_view kOpenFoamForcesImporter = "openfoam-forces";
inline constexpr std::string_view kOpenFoamForcesImporterVersion = "1";

struct OpenFoamForcesOptions {
  /// Time or iteration; empty: decided from the time values (see above).
  std::optional<HistoryAbscissa> abscissa;
  /// Coefficient files: the fluid's density [kg m^-3]. Required for them.
  std::optional<double> rho;
  /// Coefficient files: reference values that fill in for a header that lacks
  /// them; a header value that differs is refused (the file and the caller
  /// disagree). magUInf [m s^-1], lRef [m], Aref [m^2].
  std::optional<double> mag_u_inf;
  std::optional<double> l_ref;
  std::optional<double> a_ref;
  /// Drop a last row cut short (a run stopped while writing) with a note,
  /// and a force row whose moment row was never written, instead of refusing.
  bool drop_incomplete_last_row = false;
  bool compute_sha256 = true;  ///< fill HistorySourceFile::sha256
  unsigned threads = 0;        ///< 0: every core
};

/// Reads a forces or forceCoeffs function object's output. `path` is the
/// function object's folder (postProcessing/<name>, holding start-time
/// folders: all are joined), one start-time folder, or one file (force.dat
/// or moment.dat with its partner beside it, forces.dat, coefficient.dat,
/// forceCoeffs.dat, or their _<time> restarts). A folder with several kinds
/// uses force/moment over forces.dat over coefficient files, with a note.
///
/// Throws InputError naming the file (and line and column where it applies)
/// for: no force files found (listing what the folder holds), a header
/// without the "# Time ..." column line or with columns it does not know
/// (naming them and what is known), a row that is not numbers or has the
/// wrong count (file:line:column, found, expected), unbalanced parentheses,
/// values that are not finite, times that do not increase within a file,
/// force and moment files whose times differ (naming both lines), restarts of
/// another kind, frame or moment centre, coefficient files without rho or a
/// reference value, or whose directions are not orthonormal.
ForceHistory read_openfoam_forces(const std::filesystem::path& path, const OpenFoamForcesOptions& options = {});

/// Parses one file's text. `file` names it in messages and decides what it is
/// when the header does not (force*.dat, moment*.dat). A force.dat gives the
/// force components only, a moment.dat the moments only. No SHA-256.
ForceHistory parse_openfoam_force_file(std::string_view text, const std::string& file,
                                       const OpenFoamForcesOptions& options = {});

/// True when the start of a file looks like output of OpenFOAM's forces or
/// forceCoeffs function objects. For format detection.
bool looks_like_openfoam_forces(std::string_view head);

}  // namespace hydrocoef
