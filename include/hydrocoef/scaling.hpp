// Resistance from one scale to another, as `hydrocoef scale` computes it: a
// surge resistance curve (points U, X at scale 1) or a stored surge law
// (a fit X(u) = a u + b u|u| ... made by `hydrocoef fit`) carried to scale 2
// with the ITTC-1957 friction line and a form factor (1 + k):
//
//   C_T = R / (1/2 rho S U^2) = (1 + k) C_F + C_W + dC_F + C_AA,
//   C_F = 0.075 / (log10 Re - 2)^2,  Re = U L / nu
//
// (8th ITTC, Madrid 1957; ITTC Recommended Procedures 7.5-02-02-01
// "Resistance Test" and 7.5-02-03-01.4 "1978 ITTC Performance Prediction
// Method"; the form factor given, or from Prohaska's plot, Prohaska 1966;
// dC_F = (105 (k_s/L)^(1/3) - 0.64) 10^-3 and C_AA = 0.001 A_T / S of
// 7.5-02-03-01.4). The form factor is taken independent of scale and
// speed; C_W is 0 for a deeply submerged body, given and equal at both
// scales, or (a surface ship) what the model's C_T leaves, carried at equal
// Froude number U_2 = U_1 sqrt(L_2 / L_1). Each result lists its
// assumptions in words.
//
// Units SI: m, m^2, m/s, m^2/s, kg/m^3, N. Signs: X is the surge force on
// the body (SNAME, x forward; a resistance makes it negative ahead), or the
// resistance magnitude with sign "opposing"; R = -X on the body. Speeds are
// ahead speeds, U > 0.
//
// Errors: InputError, one line, with the message the command-line tool
// prints; scaling never writes to the database.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "hydrocoef/database.hpp"
#include "hydrocoef/export.hpp"

namespace hydrocoef {
inline namespace api {

/// What `hydrocoef scale` scales, and between which scales.
struct ResistanceScalingOptions {
  /// Scale 1 (the points' or the fit's scale, usually the model) and scale 2
  /// (full scale or another model): length L [m] (Re and Fn; waterline
  /// length of a ship), wetted area S [m^2], kinematic viscosity nu
  /// [m^2/s], density rho [kg/m^3]. Required (NaN: not given): --from-length,
  /// --from-area, --from-viscosity, --from-density, --to-length, ...
  double from_length = std::numeric_limits<double>::quiet_NaN();
  double from_area = std::numeric_limits<double>::quiet_NaN();
  double from_viscosity = std::numeric_limits<double>::quiet_NaN();
  double from_density = std::numeric_limits<double>::quiet_NaN();
  double to_length = std::numeric_limits<double>::quiet_NaN();
  double to_area = std::numeric_limits<double>::quiet_NaN();
  double to_viscosity = std::numeric_limits<double>::quiet_NaN();
  double to_density = std::numeric_limits<double>::quiet_NaN();
  /// Optional allowances of either scale (NaN: none): the hull roughness
  /// k_s [m] of the ITTC 1978 roughness allowance dC_F (--from-roughness,
  /// --to-roughness; ITTC's standard 150e-6 m), and the transverse area
  /// above water A_T [m^2] of the air resistance C_AA (--from-air-area,
  /// --to-air-area).
  double from_roughness = std::numeric_limits<double>::quiet_NaN();
  double to_roughness = std::numeric_limits<double>::quiet_NaN();
  double from_air_area = std::numeric_limits<double>::quiet_NaN();
  double to_air_area = std::numeric_limits<double>::quiet_NaN();
  /// Required (--wave): "submerged" (C_W = 0), "froude" (a surface ship: C_W
  /// at equal Froude number) or a number, a C_W given and equal at both scales.
  std::string wave;
  /// --form-factor: 1 + k given (a number), "prohaska" (Prohaska's plot over
  /// the points at scale 1: give the low-speed runs), or "" (submerged or
  /// given C_W: the mean of (C_T - C_W - dC_F - C_AA) / C_F over the points;
  /// refused with froude).
  std::string form_factor;
  /// The curve at scale 1 (--point U,X, repeatable): speeds [m/s] > 0 and
  /// surge forces [N] in `sign`. Or, instead, `fit`.
  std::vector<double> speeds, forces;
  /// A stored surge law in u (--fit NAME), evaluated at sample_speeds
  /// (--speeds, scale 1, at least as many as its terms), scaled and fitted
  /// again with the same terms; its own sign convention is used.
  std::string fit;
  std::vector<double> sample_speeds;
  /// Submerged or given C_W: the speed at scale 2 of each point (or sample
  /// speed), one each (--target-speeds); froude: none (U_2 follows from Fn).
  std::vector<double> target_speeds;
  double gravity = 9.80665;      ///< g [m/s^2] of Fn, equal at both scales (--gravity)
  std::string sign = "on-body";  ///< of the points' forces in and out: on-body or opposing (--sign)

  /// InputError for a scale value not given or not finite and positive, an
  /// allowance not finite and positive, a wave statement or form factor that
  /// does not parse, neither or both of points and fit, a point count other
  /// than the forces', sample speeds without a fit (or a fit without them),
  /// or a sign other than on-body and opposing.
  HYDROCOEF_EXPORT void validate() const;
};

/// One point at both scales.
struct ResistanceScalingPoint {
  double speed_from = 0.0, speed_to = 0.0;            ///< U [m/s]
  double force_from = 0.0, force_to = 0.0;            ///< X [N] in the result's sign
  double resistance_from = 0.0, resistance_to = 0.0;  ///< R [N], opposing motion (> 0)
  double froude_from = 0.0, froude_to = 0.0;          ///< U / sqrt(g L)
  double reynolds_from = 0.0, reynolds_to = 0.0;      ///< U L / nu
  double friction_from = 0.0, friction_to = 0.0;      ///< C_F (ITTC 1957)
  double wave = 0.0;                                  ///< C_W, equal at both scales
  double residual = 0.0;                              ///< what the split leaves of C_T at scale 1, carried
  double total_from = 0.0, total_to = 0.0;            ///< C_T
};

/// What `hydrocoef scale` prints.
struct ResistanceScalingResult {
  std::string method;  ///< the method and its sources, one sentence
  std::string sign;    ///< "on-body" or "opposing": of every force in and out
  std::string wave;    ///< "submerged (C_W = 0)", "C_W at equal Froude number", "C_W = 0.0004 (given)"
  double one_plus_k = 0.0;
  std::string form_factor_method;                                    ///< "given", "prohaska" or "mean ratio"
  double prohaska_slope = std::numeric_limits<double>::quiet_NaN();  ///< c of C_T/C_F = (1+k) + c Fn^4/C_F
  std::string form_factor;                                           ///< the value and how it was obtained
  std::vector<ResistanceScalingPoint> points;                        ///< in the order given
  std::vector<std::string> assumptions;                              ///< in words, one each
  /// With a fit: its name, terms ("u,u|u|"), coefficients at both scales in
  /// its sign [N over the term's unit], their units, and the largest
  /// |law_2(U_2) - X_2| / |X_2| over the points (the scaled curve is not
  /// exactly of the law's form).
  std::string fit;
  std::string terms;
  std::vector<double> coefficients_from, coefficients_to;
  std::vector<std::string> units;
  double max_relative_deviation = std::numeric_limits<double>::quiet_NaN();

  HYDROCOEF_EXPORT std::string text() const;  ///< what `scale` prints
  HYDROCOEF_EXPORT std::string json() const;  ///< what `scale --json` prints
};

/// Scales the points (options.validate() first); InputError for a fit (it
/// needs the database: the other overload), and as scale_resistance
/// refuses: a Reynolds number below 1e5 at either scale, a point whose force
/// does not oppose its motion, target speeds that do not match the wave
/// statement, a form factor that cannot be estimated.
HYDROCOEF_EXPORT ResistanceScalingResult scale_surge_resistance(const ResistanceScalingOptions& options);
/// As above, and a stored fit: InputError listing the stored fits of X in u
/// when there is none of that name, or when the fit is not a law in u.
HYDROCOEF_EXPORT ResistanceScalingResult scale_surge_resistance(const Database& db,
                                                                const ResistanceScalingOptions& options);

}  // namespace api
}  // namespace hydrocoef
