// Sway and yaw manoeuvring derivatives from pure sway and pure yaw
// forced-oscillation runs (a planar motion mechanism), as `hydrocoef
// derivatives pmm BODY` prints them: the runs are those `hydrocoef pmm`
// stored (include/hydrocoef/analysis.hpp).
//
// Axes and signs: SNAME body axes (x forward, y starboard, z down); Y [N] and
// N [N m] the fluid's force and moment on the body, the hydrodynamic part
// only. CFD forces hold no rigid-body inertia, so nothing is subtracted; a run
// whose forces include the body's own inertia must have it removed first.
//
// Pure sway, y = y_a sin(omega t + phase), heading fixed: v = y' and
// Y = Y_v v + Y_vdot vdot, N = N_v v + N_vdot vdot in the first harmonic: the
// part of the force in phase with v gives Y_v and N_v, the part in phase with
// vdot gives Y_vdot and N_vdot. Pure yaw, psi = psi_a sin(omega t + phase)
// with v = 0 along the path: Y_r, Y_rdot, N_r, N_rdot the same way from r and
// rdot. A yaw run is taken as a pure yaw (a body turned about its origin in a
// fixed stream also has v = -U psi, which is not separated). With the stored
// added mass and damping (F_i = -M_A[i][j] x_j'' - D[i][j] x_j'):
// Y_v = -D[sway][sway], Y_vdot = -M_A[sway][sway], N_v = -D[yaw][sway],
// N_vdot = -M_A[yaw][sway], Y_r = -D[sway][yaw], ..., N_rdot = -M_A[yaw][yaw].
// At zero speed Y_vdot = -M_A[1][1] and N_rdot = -M_A[5][5] of
// `hydrocoef added-mass` (Fossen's M_A, positive).
//
// The derivatives depend on the frequency: they are given per motion, speed
// U (each run's u key, or the speed given) and frequency, the runs of one
// (several amplitudes) combined by their inverse-variance weighted mean, with
// the non-dimensional frequency omega' = omega L / U when U > 0 and L is
// known. Standard errors are the harmonic analysis's (the period-to-period
// spread of the fitted harmonics). The prime form (SNAME 1950: Y' = Y /
// (1/2 rho U^2 L^2), N' = N / (1/2 rho U^2 L^3), v' = v / U, r' = r L / U,
// so Y_v' = Y_v / (1/2 rho U L^2), Y_vdot' = Y_vdot / (1/2 rho L^3), N_rdot' =
// N_rdot / (1/2 rho L^5)) is given when L, rho (and U > 0 for a velocity
// derivative) are known, its normalisation named.
//
// Units: Y_v [N s/m], Y_vdot [kg], N_v [N s], N_vdot [kg m], Y_r [N s],
// Y_rdot [kg m], N_r [N m s], N_rdot [kg m^2].
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hydrocoef/database.hpp"
#include "hydrocoef/error.hpp"
#include "hydrocoef/export.hpp"

namespace hydrocoef {
inline namespace api {

/// The options of `hydrocoef derivatives pmm BODY`.
struct HYDROCOEF_EXPORT PmmDerivativeOptions {
  std::string body;                ///< required
  std::vector<std::int64_t> runs;  ///< pmm run ids (--run; empty: all the body's sway and yaw runs)
  std::optional<double> speed;     ///< U [m/s] for every run (--speed; none: each run's u key)
  std::optional<double> length;    ///< L [m] (--length; none: the body's reference length)
  std::optional<double> density;   ///< rho [kg/m^3] (--density; none: the runs' density)
  /// Refuse unless omega' and the prime form of every derivative can be given
  /// (--prime): L, rho and U > 0 known.
  bool prime = false;

  /// InputError for an empty or bad body name, or a speed, length or density
  /// that is not finite (speed) or not finite and > 0 (length, density).
  void validate() const;
};

/// One derivative of a group (or of a run, without the prime form).
struct PmmDerivative {
  std::string name;    ///< "Y_v", "Y_vdot", "N_v", "N_vdot", "Y_r", "Y_rdot", "N_r", "N_rdot"
  double value = 0.0;  ///< SI
  double std_error = 0.0;
  std::string unit;             ///< "N s/m", "kg", "N s", "kg m", "N m s", "kg m^2"
  std::string source;           ///< the stored entry it is: "-M_A[sway][sway]"
  std::optional<double> prime;  ///< the prime value, when L, rho (and U > 0) are known
  std::optional<double> prime_std_error;
  std::string normalisation;  ///< "prime (SNAME 1950): Y_v' = Y_v / (1/2 rho U L^2), L = ..." ("" without)
};

/// The runs of one motion at one speed and frequency, combined.
struct PmmFrequencyDerivatives {
  std::string motion;                 ///< "pure sway" or "pure yaw"
  std::string dof;                    ///< "sway" or "yaw"
  double speed = 0.0;                 ///< U [m/s]
  double omega = 0.0;                 ///< [rad/s]
  double period = 0.0;                ///< [s]
  std::optional<double> omega_prime;  ///< omega L / U (U > 0 and L known)
  std::size_t runs = 0;
  double amplitude_min = 0.0, amplitude_max = 0.0;  ///< y_a [m] or psi_a [rad]
  std::string amplitude_unit;                       ///< "m" or "rad"
  std::vector<std::int64_t> pmm_runs;
  std::vector<PmmDerivative> derivatives;  ///< Y velocity, Y acceleration, N velocity, N acceleration
};

/// One run's derivatives (SI, no prime form).
struct PmmDerivativeRun {
  std::int64_t id = 0;  ///< pmm run id
  std::string dof;
  double speed = 0.0, amplitude = 0.0, omega = 0.0;
  std::string source_path;
  std::vector<PmmDerivative> derivatives;
};

/// What `hydrocoef derivatives pmm` prints.
struct HYDROCOEF_EXPORT PmmDerivatives {
  std::string body;
  std::optional<double> length;               ///< L [m] used for omega' and the prime form
  std::optional<double> density;              ///< rho [kg/m^3] used for the prime form
  std::string length_from, density_from;      ///< "--length", "body reference", "--density", "the runs" ("" none)
  std::vector<PmmFrequencyDerivatives> sets;  ///< sway before yaw, then by speed, then by frequency
  std::vector<PmmDerivativeRun> runs;
  std::size_t other_runs = 0;  ///< the body's runs of other DOFs, left out
  std::vector<std::string> notes;

  std::string text() const;  ///< the tables `hydrocoef derivatives pmm` prints
  std::string json() const;  ///< what --json prints (without the final newline)
};

/// The body's sway and yaw derivatives from its stored pure sway and pure
/// yaw runs. InputError for a bad option; a body with no stored runs, or
/// none that moves sway or yaw; a chosen run that is not the body's or not a
/// sway or yaw run; a run without Y or N; chosen runs whose densities
/// differ (without a density given); or, with prime, a missing L, rho or
/// U > 0 (naming what to give). Reads only.
HYDROCOEF_EXPORT PmmDerivatives pmm_derivatives(const Database& database, const PmmDerivativeOptions& options);

}  // namespace api
}  // namespace hydrocoef
