// Linear manoeuvring derivatives from pure sway and pure yaw forced-oscillation
// runs (a planar motion mechanism, ITTC 7.5-02-06-02), made from the stored
// analyses of src/pmm/harmonic_analysis (src/store/pmm_record.hpp).
//
// Axes and signs: SNAME body axes (x forward, y starboard, z down), forces Y
// [N] and moments N [N m] on the body, hydrodynamic part only. A CFD run's
// forces are the fluid's on the body: they hold no rigid-body inertia, so
// nothing is subtracted. A run whose forces include the body's own inertia
// (a towing-tank dynamometer) must have it taken out by the user first.
//
// Pure sway, y(t) = y_a sin(theta), theta = omega t + phase, heading fixed
// (r = 0): v = y_a omega cos(theta), vdot = -y_a omega^2 sin(theta). In the
// first harmonic, Y = Y_v v + Y_vdot vdot and N = N_v v + N_vdot vdot, so with
// F = F0 + s1 sin(theta) + c1 cos(theta) the part in phase with v (c1) gives
// Y_v = c1 / (y_a omega), the part in phase with vdot (s1) Y_vdot = -s1 /
// (y_a omega^2). The stored analysis holds M_A[i][j] = s1 / (A omega^2) and
// D[i][j] = -c1 / (A omega) (F_i = -M_A[i][j] x'' - D[i][j] x'), so
//
//   Y_v = -D[sway][sway]     Y_vdot = -M_A[sway][sway]
//   N_v = -D[yaw][sway]      N_vdot = -M_A[yaw][sway]
//
// Pure yaw, psi(t) = psi_a sin(theta), the body's sway velocity zero along
// its path (v = 0): r = psi_a omega cos(theta), rdot = -psi_a omega^2
// sin(theta), and the same way
//
//   Y_r = -D[sway][yaw]      Y_rdot = -M_A[sway][yaw]
//   N_r = -D[yaw][yaw]       N_rdot = -M_A[yaw][yaw]
//
// A yaw run is taken as a pure yaw: at forward speed the case must keep the
// body's v zero (move it along the sinusoidal path, or turn the inflow with
// it). A body turned about its origin in a fixed stream of speed U has
// v = -U psi as well, which this analysis does not separate.
//
// At zero speed these are the added mass and damping: Y_vdot = -M_A[1][1],
// N_rdot = -M_A[5][5] (Fossen's M_A, positive). The derivatives depend on the
// frequency: runs are grouped by motion, speed and frequency (each equal to
// 1e-9 relative), and the runs of a group (several amplitudes) are combined
// by their inverse-variance weighted mean (combine_pmm_estimates, as the
// added-mass matrix combines them), so at zero speed the group's Y_vdot is
// -M_A[sway][sway] of `hydrocoef added-mass` at that frequency. The standard
// errors are the harmonic analysis's own (the period-to-period spread of the
// fitted s1 and c1 over the kept periods); none is made up here.
//
// Units: Y_v [N s/m], Y_vdot [N s^2/m = kg], N_v [N s], N_vdot [N s^2 = kg m],
// Y_r [N s], Y_rdot [N s^2 = kg m], N_r [N m s], N_rdot [N m s^2 = kg m^2].
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "src/derivatives/normalisation.hpp"
#include "src/store/pmm_record.hpp"

namespace hydrocoef {

/// The DOFs of the two tests, as stored (src/pmm/imposed_motion: 1 sway, 5 yaw).
inline constexpr std::size_t kPmmSway = 1;
inline constexpr std::size_t kPmmYaw = 5;

/// A run's derivatives, in the order: Y velocity, Y acceleration, N velocity,
/// N acceleration (Y_v, Y_vdot, N_v, N_vdot for sway; Y_r, Y_rdot, N_r, N_rdot
/// for yaw).
inline constexpr std::size_t kPmmDerivativeCount = 4;

/// "Y_v", "Y_vdot", "N_v", "N_vdot" (sway) or "Y_r", ... "N_rdot" (yaw), k in 0..3.
std::string pmm_derivative_name(std::size_t dof, std::size_t k);
/// The SI unit: "N s/m", "kg", "N s", "kg m" (sway); "N s", "kg m", "N m s", "kg m^2" (yaw).
std::string pmm_derivative_unit(std::size_t dof, std::size_t k);
/// What the derivative is the coefficient of, for the normalisation.
DerivativeKind pmm_derivative_kind(std::size_t dof, std::size_t k);
/// The stored entry it is made of: "-D[sway][sway]", "-M_A[sway][sway]", ...
std::string pmm_derivative_source(std::size_t dof, std::size_t k);

struct PmmEstimate {
  double value = 0.0;
  double std_error = 0.0;
};

/// The derivatives of one stored run.
struct PmmRunDerivatives {
  std::int64_t id = 0;  ///< pmm_run id
  std::size_t dof = kPmmSway;
  double amplitude = 0.0;  ///< y_a [m] or psi_a [rad]
  double omega = 0.0;      ///< [rad/s]
  double speed = 0.0;      ///< U [m/s]: the run's u, or the speed given
  std::string source_path;
  std::array<PmmEstimate, kPmmDerivativeCount> derivatives{};
};

/// Runs of one motion at one speed and one frequency, combined.
struct PmmDerivativeGroup {
  std::size_t dof = kPmmSway;
  double speed = 0.0;  ///< U [m/s]
  double omega = 0.0;  ///< [rad/s]
  double amplitude_min = 0.0, amplitude_max = 0.0;
  std::vector<std::int64_t> record_ids;
  std::array<PmmEstimate, kPmmDerivativeCount> derivatives{};
};

struct PmmDerivativeSet {
  std::string body;
  std::vector<PmmRunDerivatives> runs;     ///< in the order of the records
  std::vector<PmmDerivativeGroup> groups;  ///< sway before yaw, then by speed, then by frequency
  std::size_t other_runs = 0;              ///< the body's runs of other DOFs, left out
};

/// One run's derivatives; U is `speed` when given, else the run's mean u.
/// InputError naming the run (its id and file) when it does not move sway or
/// yaw, or when its history lacks Y or N.
PmmRunDerivatives pmm_run_derivatives(const PmmRecord& record, std::optional<double> speed = std::nullopt);

/// The body's sway and yaw runs (those of `ids` when it is not empty: each
/// must be a stored sway or yaw run of the body), their derivatives and
/// their groups. InputError when the body has no stored runs, none of them
/// moves sway or yaw (naming what they move), an id is not a run of the body,
/// a chosen run is not a sway or yaw run, or `speed` is not finite.
PmmDerivativeSet pmm_derivative_set(const std::string& body, const std::vector<PmmRecord>& records,
                                    const std::vector<std::int64_t>& ids = {},
                                    std::optional<double> speed = std::nullopt);

}  // namespace hydrocoef
