// Added mass and damping from a forced-oscillation run (a virtual planar
// motion mechanism): the body is moved harmonically in one degree of freedom
// j, x_j(t) = A sin(w t + phi), and each force or moment component i is split
// into its mean, the part in phase with the acceleration and the part in
// phase with the velocity, and optionally higher harmonics:
//
//   F_i(t) = F0 + sum_k [ s_k sin(k(w t + phi)) + c_k cos(k(w t + phi)) ]
//
// With x'' = -A w^2 sin and x' = A w cos, the linear model on the body
// F_i = -M_A[i][j] x_j'' - D[i][j] x_j' (Fossen's sign: M_A and D positive
// for a body in still water) gives
//
//   M_A[i][j] = s_1 / (A w^2)        D[i][j] = -c_1 / (A w)
//
// Units: A in m (surge, sway, heave) or rad (roll, pitch, yaw); w in rad/s;
// F in N or N m; M_A in kg, kg m or kg m^2; D in N s/m, N s or N m s.
//
// The fit is least squares over whole periods after the start-up transient,
// counted from the first sample (or the given start time) whatever the
// motion's phase there, each sample weighted by the time it stands for (so uneven steps do not
// bias it). The transient is found by MSER truncation (White 1997, "An
// effective truncation heuristic for bias reduction in simulation output",
// Simulation 69(6)) applied to the first-harmonic amplitude of each period:
// the periods dropped are those whose removal minimises the squared
// standard error of the mean of the rest, searched over the first half. The
// uncertainty of M_A and D comes from the spread of the same coefficients
// fitted period by period: their standard error of the mean over the kept
// periods.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace hydrocoef {

/// The imposed motion of one degree of freedom (0..5 = surge..yaw).
struct HarmonicMotion {
  std::size_t dof = 0;
  double amplitude = 0.0;  ///< A [m or rad], > 0
  double omega = 0.0;      ///< w [rad/s], > 0
  double phase = 0.0;      ///< phi [rad]

  double period() const;
  double displacement(double t) const;
  double velocity(double t) const;
  double acceleration(double t) const;
};

struct HarmonicFitOptions {
  int harmonics = 1;                 ///< 1..10 fitted harmonics
  std::optional<double> start_time;  ///< keep whole periods from here (s); none: detect the transient
};

/// One force or moment component's fit.
struct HarmonicComponent {
  bool present = false;
  double mean = 0.0;               ///< F0
  std::vector<double> in_phase;    ///< s_k, k = 1..harmonics (with sin)
  std::vector<double> quadrature;  ///< c_k (with cos)
  double explained = 0.0;          ///< fraction of the variance about the mean the fit explains (R^2)
  double added_mass = 0.0;         ///< M_A[i][j]
  double damping = 0.0;            ///< D[i][j]
  double added_mass_se = 0.0;      ///< standard errors from the period-to-period spread
  double damping_se = 0.0;
  double in_phase_spread = 0.0;    ///< standard deviation of s_1 over the periods
  double quadrature_spread = 0.0;  ///< of c_1
};

struct HarmonicAnalysis {
  HarmonicMotion motion;
  double window_start = 0.0, window_end = 0.0;  ///< s, whole periods
  std::size_t periods = 0;                      ///< kept
  std::size_t transient_periods = 0;            ///< dropped at the start
  std::size_t samples = 0;
  std::array<HarmonicComponent, 6> components;  ///< X..N, `present` where given
};

/// The fewest sampling steps (the history's mean step) a period may span.
inline constexpr double kMinStepsPerPeriod = 4.0;

/// Analyses a force history sampled at times `t` (increasing, s). `forces[i]`
/// is component i's samples (same length as t) or empty when absent.
/// InputError when the times are not increasing or not finite, the motion's
/// amplitude or frequency is not positive or A w or A w^2 is not an ordinary
/// finite number, a component has the wrong length or a non-finite value,
/// the period spans fewer than kMinStepsPerPeriod mean sampling steps, fewer
/// than 3 whole periods remain after the transient (the message says how
/// many there are and names --start), the samples do not resolve the fitted
/// harmonics (the sampled basis is nearly dependent), or a fitted
/// coefficient is not finite.
HarmonicAnalysis analyse_forced_oscillation(std::span<const double> t,
                                            const std::array<std::span<const double>, 6>& forces,
                                            const HarmonicMotion& motion, const HarmonicFitOptions& options = {});

/// Linear and quadratic damping from the equivalent linear damping at
/// several amplitudes of one frequency. A quadratic term b2 x'|x'| has the
/// same first-harmonic work as a linear one of b2 (8 / (3 pi)) A w (the
/// Fourier coefficient of cos|cos| is 8/(3 pi)), so
///
///   D_eq(A) = b1 + b2 (8 / (3 pi)) A w
///
/// is fitted by weighted least squares (weights from the standard errors,
/// equal when they are zero).
struct QuadraticDamping {
  double linear = 0.0, quadratic = 0.0;        ///< b1 [N s/m], b2 [N s^2/m^2] (or the rotational units)
  double linear_se = 0.0, quadratic_se = 0.0;  ///< standard errors (0 with exactly two amplitudes)
};
QuadraticDamping fit_quadratic_damping(std::span<const double> amplitudes, double omega,
                                       std::span<const double> equivalent_damping,
                                       std::span<const double> standard_errors = {});

/// Keulegan-Carpenter number of a harmonic motion of amplitude A of a body
/// of size D: KC = U_max T / D = 2 pi A / D.
double keulegan_carpenter(double amplitude, double size);
/// Stokes number (frequency parameter) beta = D^2 / (nu T).
double stokes_number(double size, double period, double kinematic_viscosity);

}  // namespace hydrocoef
