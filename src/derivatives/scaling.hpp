// Resistance from one scale to another: the ITTC-1957 friction line and the
// form-factor (Hughes-Prohaska, ITTC 1978) method, for a surge resistance
// curve X(u) or the coefficients of a surge law such as X(u) = a u + b u|u|.
//
// The method. A resistance R at speed U is made non-dimensional with the
// wetted area S: C_T = R / (1/2 rho S U^2). It is split into
//
//   C_T = (1 + k) C_F + C_W + dC_F + C_AA                          (1)
//
// C_F the frictional coefficient of the ITTC-1957 model-ship correlation line
//
//   C_F = 0.075 / (log10 Re - 2)^2,   Re = U L / nu                 (2)
//
// (1 + k) the form factor, C_W the wave-resistance coefficient, dC_F a
// roughness allowance and C_AA an air-resistance coefficient (the last two
// for a ship at full scale; none unless given). Sources (read as excerpts of
// scanned or summarised copies; the addresses are those the excerpts came
// from):
// - (2): 8th ITTC, Madrid 1957; the friction line of ITTC Recommended
//   Procedures 7.5-02-02-01 "Resistance Test" (rev. 02 2008, rev. 03 2011,
//   section 2.1 "Data Reduction Equations") and 7.5-02-03-01.4 "1978 ITTC
//   Performance Prediction Method" (rev. 00, 1999; scribd.com/document/427530416,
//   pdfcoffee.com/ittc1978-speed-prediction-pdf-free.html). Tabulated in
//   Tupper, "Introduction to Naval Architecture" (4th ed.), Table 8.3, and
//   by Morrall (1970), NPL Ship Report 142 (scribd.com/document/379886867).
// - (1): 7.5-02-03-01.4, section 2.4.1 "Total Resistance of Ship",
//   C_TS = (1 + k) C_FS + dC_F + C_A + C_R + C_AAS, with the residual
//   C_R = C_TM - (1 + k) C_FM of the model at the same Froude number
//   (section 2.3), "assuming the form factor to be independent of scale and
//   speed" (section 2.1.1). C_R is named C_W here; the correlation
//   allowance C_A, an empirical ship-trial correction, is not modelled (a
//   user who wants it adds it to dC_F). Tupper (4th ed., p. 190, "ITTC
//   method") states the same split.
// - The form factor from low-speed runs, Prohaska's plot (Prohaska 1966; the
//   form-factor determination of 7.5-02-02-01 section 3.6.2 "Form Factor"):
//     C_T / C_F = (1 + k) + c Fn^4 / C_F,   Fn = U / sqrt(g L)      (3)
//   a straight line in x = Fn^4 / C_F of intercept 1 + k, fitted by least
//   squares over the runs given (low speeds, where wave resistance grows as
//   Fn^4); nauticalsolver.com/calculators/resistance/scaling/scaling.html
//   states the same fit.
// - dC_F = (105 (k_s / L)^(1/3) - 0.64) 10^-3 with k_s the hull roughness
//   and C_AA = 0.001 A_T / S with A_T the transverse projected area above
//   water: 7.5-02-03-01.4 section 2.4.1. Tupper (4th ed., p. 190) gives
//   k_s = 150e-6 m and C_AA = 0.001 A_T / S; the dC_F formula as
//   shipcalculators.com/docs/formulas/tech-appendage-roughness restates it
//   from 7.5-02-03-01.4.
//
// Which speeds correspond. A surface ship: equal Froude number, U_2 = U_1
// sqrt(L_2 / L_1), and C_W of each run is what (1) leaves of the model's
// C_T, carried to scale 2 unchanged ("C_W equal at equal Froude number").
// A deeply submerged body (an AUV, a sphere robot far from the surface):
// no waves, C_W = 0, the Froude number is irrelevant and the user chooses
// the speed at scale 2 of each run. Or a wave-resistance coefficient given
// by the user, equal at both scales. The library does not pick one of these
// for the user: ScalingOptions::wave must say which (see WaveResistance).
//
// Signs. The project's surge force X is the force on the body (SNAME, x
// forward): a resistance makes X negative for u > 0. The resistance R of
// (1) is the magnitude opposing motion, R = -X for on-body forces (the
// OpposingMotion convention of src/core/sign_convention.hpp, R = X, when the
// forces are given as magnitudes). Speeds are ahead speeds, u > 0; a run whose
// force does not oppose its motion is refused.
//
// Units SI: m, m^2, m/s, m^2/s, kg/m^3, N.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "src/core/damping_terms.hpp"
#include "src/core/sign_convention.hpp"

namespace hydrocoef {

/// The lowest Reynolds number the ITTC-1957 line is evaluated at. The line
/// is a turbulent-flow correlation line (it is infinite at Re = 100, where
/// log10 Re = 2); its published tables start at 1e5 (Tupper Table 8.3;
/// Morrall 1970: 1e5 to 1e10). Below, the flow over most of a body is
/// laminar or transitional and the line does not describe it.
inline constexpr double kIttc1957MinimumReynolds = 1e5;

/// C_F = 0.075 / (log10 Re - 2)^2 (equation (2)). Throws InputError when
/// reynolds is not finite or below kIttc1957MinimumReynolds; `what` names
/// the run or scale in that message ("scale 2, run 3").
double ittc1957_friction(double reynolds, std::string_view what = "");

/// The ITTC 1978 roughness allowance dC_F = (105 (k_s / L)^(1/3) - 0.64)
/// 10^-3: roughness k_s [m] (ITTC standard 150e-6), length L [m] on the
/// waterline. Throws InputError for values that are not finite and positive.
double ittc1978_roughness_allowance(double roughness, double length);

/// The ITTC 1978 air-resistance coefficient C_AA = 0.001 A_T / S: A_T [m^2]
/// the transverse projected area above water, S [m^2] the wetted area.
double ittc1978_air_resistance(double transverse_area, double wetted_area);

/// One scale's body and water (every value SI). The required values default
/// to 0, which the checks refuse, so that none is silently assumed.
struct ScaleConditions {
  double length = 0.0;               ///< L [m]: Re and Fn length (waterline length of a ship, body length of an AUV)
  double wetted_area = 0.0;          ///< S [m^2]: C = R / (1/2 rho S U^2)
  double kinematic_viscosity = 0.0;  ///< nu [m^2/s] (fresh water 15 C: 1.13902e-6, ITTC)
  double density = 0.0;              ///< rho [kg/m^3]
  double roughness_allowance = 0.0;  ///< dC_F: none unless given (a ship at full scale)
  double air_resistance = 0.0;       ///< C_AA: none unless given (a ship at full scale)
};

/// What the user says about wave resistance (there is no default).
enum class WaveStatement {
  Unstated,       ///< refused by every function that needs it
  Submerged,      ///< deeply submerged body: C_W = 0; speeds at scale 2 chosen per run
  Given,          ///< C_W given, equal at both scales; speeds at scale 2 chosen per run
  FroudeMatched,  ///< surface ship: C_W of each model run, carried at equal Froude number
};

struct WaveResistance {
  WaveStatement statement = WaveStatement::Unstated;
  double coefficient = 0.0;  ///< C_W for Given (finite, >= 0); 0 otherwise
};

/// Parses "submerged", "froude" or a number (a given C_W, e.g. "0.0004").
/// Throws InputError saying what to give otherwise.
WaveResistance parse_wave_resistance(std::string_view text);

/// "submerged (C_W = 0)", "C_W = 0.0004 (given)", "C_W at equal Froude number".
std::string describe(const WaveResistance& wave);

/// A resistance run at one scale: ahead speed and surge force.
struct ResistanceRun {
  double speed = 0.0;  ///< u [m/s], > 0
  double force = 0.0;  ///< X [N], in the convention the options name
};

enum class FormFactorMethod {
  Given,     ///< stated by the user
  Prohaska,  ///< Prohaska's plot, equation (3), least squares over the runs
  MeanRatio  ///< submerged or given C_W: mean of (C_T - C_W - dC_F - C_AA) / C_F over the runs
};

struct FormFactor {
  double one_plus_k = 0.0;
  FormFactorMethod method = FormFactorMethod::Given;
  double prohaska_slope = 0.0;  ///< c of equation (3) (Prohaska only)
  std::size_t runs = 0;         ///< runs it was estimated from (0 when given)
  std::string text;             ///< the value and how it was obtained, for reports
};

/// A given form factor (finite and positive, else InputError).
FormFactor given_form_factor(double one_plus_k);

/// Prohaska's plot over the runs (at least two, at two or more Froude
/// numbers): y = C_T / C_F against x = Fn^4 / C_F, a straight line of
/// intercept 1 + k and slope c; C_T less the scale's dC_F and C_AA.
/// Give the low-speed runs (ITTC: where C_W grows as Fn^4). gravity [m/s^2].
FormFactor prohaska_form_factor(std::span<const ResistanceRun> runs, const ScaleConditions& scale,
                                SignConvention convention, double gravity = 9.80665);

/// 1 + k as the mean over the runs of (C_T - C_W - dC_F - C_AA) / C_F, for
/// a submerged body (C_W = 0) or a given C_W. Refuses FroudeMatched or
/// Unstated (Prohaska's plot is the method with waves).
FormFactor mean_ratio_form_factor(std::span<const ResistanceRun> runs, const ScaleConditions& scale,
                                  const WaveResistance& wave, SignConvention convention);

struct ScalingOptions {
  ScaleConditions from;  ///< scale 1 (the runs' scale, usually the model)
  ScaleConditions to;    ///< scale 2 (full scale or another model)
  WaveResistance wave;   ///< required: see WaveStatement
  /// The form factor. When absent: Submerged and Given estimate it with
  /// mean_ratio_form_factor over the runs scaled; FroudeMatched refuses
  /// (give it, e.g. from prohaska_form_factor over the low-speed runs).
  std::optional<FormFactor> form_factor;
  /// Submerged and Given: the speed at scale 2 of each run, one per run.
  /// FroudeMatched: empty (the speeds follow from the Froude number).
  std::vector<double> target_speeds;
  double gravity = 9.80665;                            ///< g [m/s^2] of Fn, equal at both scales
  SignConvention convention = SignConvention::OnBody;  ///< of the forces in and out
};

/// One run at both scales.
struct ScaledPoint {
  double speed_from = 0.0, speed_to = 0.0;            ///< [m/s]
  double froude_from = 0.0, froude_to = 0.0;          ///< U / sqrt(g L)
  double reynolds_from = 0.0, reynolds_to = 0.0;      ///< U L / nu
  double friction_from = 0.0, friction_to = 0.0;      ///< C_F, equation (2)
  double wave = 0.0;                                  ///< C_W, equal at both scales
  double residual = 0.0;                              ///< what (1) leaves of C_T at scale 1 (Submerged, Given), carried
  double total_from = 0.0, total_to = 0.0;            ///< C_T
  double resistance_from = 0.0, resistance_to = 0.0;  ///< R [N], opposing motion (> 0)
  double force_from = 0.0, force_to = 0.0;            ///< X [N] in the options' convention
};

struct ScalingResult {
  FormFactor form_factor;
  WaveResistance wave;
  std::vector<ScaledPoint> points;       ///< in the order of the runs
  std::vector<std::string> assumptions;  ///< in words, one per line
};

/// Scales each run from options.from to options.to:
///   C_T1 = R_1 / (1/2 rho_1 S_1 U_1^2),  R = -X (on-body) for U > 0
///   Froude-matched: U_2 = U_1 sqrt(L_2 / L_1),
///                   C_W = C_T1 - (1 + k) C_F1 - dC_F1 - C_AA1
///   otherwise:      U_2 as given, C_W as stated,
///                   residual = C_T1 - (1 + k) C_F1 - C_W - dC_F1 - C_AA1
///   C_T2 = (1 + k) C_F2 + C_W + residual + dC_F2 + C_AA2
///   R_2 = 1/2 rho_2 S_2 U_2^2 C_T2,      X_2 = -R_2 (on-body)
/// Throws InputError (one line) for a missing wave statement, a value that
/// is not finite and positive, a Reynolds number below
/// kIttc1957MinimumReynolds at either scale, a run whose force does not
/// oppose its motion, target speeds that do not match the statement, or a
/// form factor that cannot be estimated.
ScalingResult scale_resistance(std::span<const ResistanceRun> runs, const ScalingOptions& options);

/// A surge law at scale 2 from one at scale 1.
struct ScaledLaw {
  DampingLawSpec spec;                  ///< the law's terms (those given)
  std::vector<double> coefficients;     ///< at scale 2, in the options' convention
  ScalingResult curve;                  ///< the law's values at the sample speeds, scaled
  double max_relative_deviation = 0.0;  ///< max |law_2(U_2) - X_2| / |X_2| over the points
};

/// Evaluates the law (terms of u, coefficients in the options' convention)
/// at sample_speeds (scale 1, > 0), scales those points with
/// scale_resistance and fits the same terms to the scaled points by least
/// squares. The scaled curve is not exactly of the law's form (C_F changes
/// with Re), so the fit's largest relative deviation is reported. The law
/// is used for ahead speeds; a term odd in u (u|u|) extends it astern by
/// symmetry, which the scaling does not check. Throws InputError when the
/// law is not in u, has more terms than speeds, or the speeds cannot tell
/// its terms apart.
ScaledLaw scale_damping_law(const DampingLawSpec& spec, std::span<const double> coefficients,
                            std::span<const double> sample_speeds, const ScalingOptions& options);

}  // namespace hydrocoef
