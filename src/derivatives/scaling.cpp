#include "src/derivatives/scaling.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "src/core/dense_decompositions.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/core/text.hpp"

namespace hydrocoef {
namespace {

bool finite_positive(double value) { return std::isfinite(value) && value > 0.0; }

// A number in a message or an assumption: six significant digits ("0.0004",
// "43897.4", "100000"), "nan" and "inf" as they are.
std::string shown(double value) { return std::isfinite(value) ? significant(value, 6) : shortest_number(value); }

// "run 3 (u = 1.5 m/s)": runs are numbered from 1 in messages.
std::string run_name(std::size_t index, double speed) {
  return "run " + std::to_string(index + 1) + " (u = " + shown(speed) + " m/s)";
}

void check_scale(const ScaleConditions& scale, std::string_view name) {
  const auto require = [&](double value, std::string_view field, std::string_view expected) {
    if (!finite_positive(value))
      throw InputError("scaling, " + std::string(name) + ": the " + std::string(field) + " = " + shown(value) +
                       " is not finite and positive: give " + std::string(expected));
  };
  require(scale.length, "length L", "the body's length in m (waterline length of a ship)");
  require(scale.wetted_area, "wetted area S", "the wetted surface area in m^2");
  require(scale.kinematic_viscosity, "kinematic viscosity nu", "the water's viscosity in m^2/s (about 1.1e-6)");
  require(scale.density, "density rho", "the water's density in kg/m^3");
  if (!std::isfinite(scale.roughness_allowance))
    throw InputError("scaling, " + std::string(name) + ": the roughness allowance dC_F = " +
                     shown(scale.roughness_allowance) + " is not finite: give a number, or 0 for none");
  if (!std::isfinite(scale.air_resistance))
    throw InputError("scaling, " + std::string(name) + ": the air-resistance coefficient C_AA = " +
                     shown(scale.air_resistance) + " is not finite: give a number, or 0 for none");
}

void check_gravity(double gravity) {
  if (!finite_positive(gravity))
    throw InputError("scaling: the acceleration of gravity g = " + shown(gravity) +
                     " is not finite and positive: give it in m/s^2 (standard 9.80665)");
}

void check_wave(const WaveResistance& wave) {
  if (wave.statement == WaveStatement::Unstated)
    throw InputError(
        "scaling: wave resistance not stated: say 'submerged' (deeply submerged body, C_W = 0), give a "
        "wave-resistance coefficient C_W, or say 'froude' (surface ship: C_W from the runs at equal Froude number)");
  if (wave.statement == WaveStatement::Given && !(std::isfinite(wave.coefficient) && wave.coefficient >= 0.0))
    throw InputError("scaling: the wave-resistance coefficient C_W = " + shown(wave.coefficient) +
                     " is not finite and non-negative: give C_W >= 0");
}

// The stated C_W (0 for a submerged body).
double stated_wave(const WaveResistance& wave) {
  return wave.statement == WaveStatement::Given ? wave.coefficient : 0.0;
}

// A run's resistance (opposing motion, > 0) and its total coefficient C_T.
struct RunCoefficients {
  double resistance = 0.0;
  double total = 0.0;
  double reynolds = 0.0;
  double friction = 0.0;
  double froude = 0.0;
};

RunCoefficients run_coefficients(const ResistanceRun& run, std::size_t index, const ScaleConditions& scale,
                                 SignConvention convention, double gravity, std::string_view scale_name) {
  const std::string name = std::string(scale_name) + ", " + run_name(index, run.speed);
  if (!finite_positive(run.speed))
    throw InputError("scaling, " + name + ": the speed is not finite and positive: give ahead speeds u > 0 in m/s");
  if (!std::isfinite(run.force))
    throw InputError("scaling, " + name + ": the force X = " + shown(run.force) +
                     " is not finite: give the surge force in N");
  RunCoefficients c;
  c.resistance = to_convention(run.force, convention, SignConvention::OpposingMotion);
  if (!(c.resistance > 0.0))
    throw InputError("scaling, " + name + ": the force X = " + shown(run.force) + " N (" +
                     std::string(to_string(convention)) + ") does not oppose the motion: " +
                     (convention == SignConvention::OnBody ? "an on-body surge force is negative for u > 0"
                                                           : "a resistance magnitude is positive") +
                     "; check the sign convention");
  c.total = c.resistance / (0.5 * scale.density * scale.wetted_area * run.speed * run.speed);
  c.reynolds = run.speed * scale.length / scale.kinematic_viscosity;
  c.friction = ittc1957_friction(c.reynolds, name);
  c.froude = run.speed / std::sqrt(gravity * scale.length);
  return c;
}

std::string allowance_text(const ScaleConditions& scale, std::string_view name) {
  std::string text = std::string(name) + ": ";
  text += scale.roughness_allowance == 0.0 ? "no roughness allowance"
                                           : "roughness allowance dC_F = " + shown(scale.roughness_allowance);
  text += scale.air_resistance == 0.0 ? ", no air resistance"
                                      : ", air-resistance coefficient C_AA = " + shown(scale.air_resistance);
  return text;
}

}  // namespace

double ittc1957_friction(double reynolds, std::string_view what) {
  if (!(std::isfinite(reynolds) && reynolds >= kIttc1957MinimumReynolds)) {
    const std::string prefix = what.empty() ? "" : std::string(what) + ": ";
    throw InputError("scaling, " + prefix + "the Reynolds number U L / nu = " + shown(reynolds) + " is below " +
                     shown(kIttc1957MinimumReynolds) +
                     ", the lowest the ITTC-1957 line is used at (it describes turbulent flow): give a higher "
                     "speed, a longer body or check the viscosity");
  }
  const double log_term = std::log10(reynolds) - 2.0;
  return 0.075 / (log_term * log_term);
}

double ittc1978_roughness_allowance(double roughness, double length) {
  if (!finite_positive(roughness) || !finite_positive(length))
    throw InputError("roughness allowance: the roughness k_s = " + shown(roughness) + " m and length L = " +
                     shown(length) + " m must be finite and positive (ITTC standard k_s = 150e-6 m)");
  return (105.0 * std::cbrt(roughness / length) - 0.64) * 1e-3;
}

double ittc1978_air_resistance(double transverse_area, double wetted_area) {
  if (!finite_positive(transverse_area) || !finite_positive(wetted_area))
    throw InputError("air resistance: the transverse area A_T = " + shown(transverse_area) +
                     " m^2 and wetted area S = " + shown(wetted_area) + " m^2 must be finite and positive");
  return 0.001 * transverse_area / wetted_area;
}

WaveResistance parse_wave_resistance(std::string_view text) {
  const std::string word = lower(trim(text));
  if (word == "submerged") return {WaveStatement::Submerged, 0.0};
  if (word == "froude") return {WaveStatement::FroudeMatched, 0.0};
  if (const auto value = parse_finite_number(trim(text)); value && *value >= 0.0) return {WaveStatement::Given, *value};
  throw InputError("wave resistance '" + printable_text(text, 40) +
                   "': expected 'submerged' (C_W = 0), 'froude' (C_W from the runs at equal Froude number) or a "
                   "wave-resistance coefficient C_W >= 0");
}

std::string describe(const WaveResistance& wave) {
  switch (wave.statement) {
    case WaveStatement::Unstated: return "wave resistance not stated";
    case WaveStatement::Submerged: return "submerged (C_W = 0)";
    case WaveStatement::Given: return "C_W = " + shown(wave.coefficient) + " (given)";
    case WaveStatement::FroudeMatched: return "C_W at equal Froude number";
  }
  return "?";
}

FormFactor given_form_factor(double one_plus_k) {
  if (!finite_positive(one_plus_k))
    throw InputError("scaling: the form factor 1+k = " + shown(one_plus_k) +
                     " is not finite and positive: give 1+k (about 1.05 to 1.5 for a hull)");
  FormFactor factor;
  factor.one_plus_k = one_plus_k;
  factor.method = FormFactorMethod::Given;
  factor.text = "1+k = " + shown(one_plus_k) + " (given)";
  return factor;
}

FormFactor prohaska_form_factor(std::span<const ResistanceRun> runs, const ScaleConditions& scale,
                                SignConvention convention, double gravity) {
  check_scale(scale, "scale 1");
  check_gravity(gravity);
  if (runs.size() < 2)
    throw InputError("Prohaska's plot: " + std::to_string(runs.size()) +
                     " run(s) given: give two or more low-speed runs at different Froude numbers");
  std::vector<double> x(runs.size()), y(runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const RunCoefficients c = run_coefficients(runs[i], i, scale, convention, gravity, "scale 1");
    const double fn2 = c.froude * c.froude;
    x[i] = fn2 * fn2 / c.friction;
    y[i] = (c.total - scale.roughness_allowance - scale.air_resistance) / c.friction;
  }
  const double n = static_cast<double>(runs.size());
  double x_mean = 0.0, y_mean = 0.0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    x_mean += x[i];
    y_mean += y[i];
  }
  x_mean /= n;
  y_mean /= n;
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    sxx += (x[i] - x_mean) * (x[i] - x_mean);
    sxy += (x[i] - x_mean) * (y[i] - y_mean);
  }
  // Runs at one Froude number leave the slope undetermined.
  if (!(sxx > n * 1e-24 * x_mean * x_mean))
    throw InputError("Prohaska's plot: the " + std::to_string(runs.size()) +
                     " runs are at one Froude number: give runs at two or more speeds");
  const double slope = sxy / sxx;
  FormFactor factor;
  factor.one_plus_k = y_mean - slope * x_mean;
  factor.prohaska_slope = slope;
  factor.method = FormFactorMethod::Prohaska;
  factor.runs = runs.size();
  if (!finite_positive(factor.one_plus_k))
    throw InputError("Prohaska's plot: the intercept 1+k = " + significant(factor.one_plus_k) +
                     " is not positive: the runs do not follow C_T/C_F = (1+k) + c Fn^4/C_F (give low-speed runs)");
  factor.text = "1+k = " + significant(factor.one_plus_k, 8) +
                " (Prohaska's plot, C_T/C_F = (1+k) + c Fn^4/C_F, c = " + significant(slope, 8) +
                ", least squares over " + std::to_string(runs.size()) + " runs)";
  return factor;
}

FormFactor mean_ratio_form_factor(std::span<const ResistanceRun> runs, const ScaleConditions& scale,
                                  const WaveResistance& wave, SignConvention convention) {
  check_scale(scale, "scale 1");
  check_wave(wave);
  if (wave.statement == WaveStatement::FroudeMatched)
    throw InputError(
        "form factor: the mean of C_T/C_F needs a known C_W (submerged or given); with C_W at equal Froude number "
        "give 1+k or use Prohaska's plot over low-speed runs");
  if (runs.empty()) throw InputError("form factor: no runs given: give one or more runs, or the form factor 1+k");
  const double wave_coefficient = stated_wave(wave);
  double sum = 0.0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    // gravity does not enter C_T/C_F; 1 keeps run_coefficients' Froude number finite.
    const RunCoefficients c = run_coefficients(runs[i], i, scale, convention, 1.0, "scale 1");
    sum += (c.total - wave_coefficient - scale.roughness_allowance - scale.air_resistance) / c.friction;
  }
  FormFactor factor;
  factor.one_plus_k = sum / static_cast<double>(runs.size());
  factor.method = FormFactorMethod::MeanRatio;
  factor.runs = runs.size();
  if (!finite_positive(factor.one_plus_k))
    throw InputError("form factor: the mean of (C_T - C_W)/C_F over the runs is " + significant(factor.one_plus_k) +
                     ", not positive: C_W = " + shown(wave_coefficient) + " is larger than the runs' resistance");
  factor.text = "1+k = " + significant(factor.one_plus_k, 8) + " (mean of (C_T - C_W" +
                std::string(scale.roughness_allowance != 0.0 || scale.air_resistance != 0.0 ? " - dC_F - C_AA" : "") +
                ")/C_F over " + std::to_string(runs.size()) + " runs, " + describe(wave) + ")";
  return factor;
}

ScalingResult scale_resistance(std::span<const ResistanceRun> runs, const ScalingOptions& options) {
  check_wave(options.wave);
  check_scale(options.from, "scale 1");
  check_scale(options.to, "scale 2");
  check_gravity(options.gravity);
  if (runs.empty()) throw InputError("scaling: no runs given: give the runs (speed, force) at scale 1");
  const bool froude = options.wave.statement == WaveStatement::FroudeMatched;
  if (froude && !options.target_speeds.empty())
    throw InputError("scaling: " + std::to_string(options.target_speeds.size()) +
                     " target speeds given, but with C_W at equal Froude number the speeds at scale 2 follow from "
                     "U_2 = U_1 sqrt(L_2/L_1): give none");
  if (!froude && options.target_speeds.size() != runs.size())
    throw InputError("scaling: " + std::to_string(options.target_speeds.size()) + " target speeds for " +
                     std::to_string(runs.size()) + " runs: with " + describe(options.wave) +
                     " give the speed at scale 2 of each run (the Froude number does not pair them)");

  ScalingResult result;
  result.wave = options.wave;
  if (options.form_factor) {
    result.form_factor = *options.form_factor;
    if (!finite_positive(result.form_factor.one_plus_k))
      throw InputError("scaling: the form factor 1+k = " + shown(result.form_factor.one_plus_k) +
                       " is not finite and positive: give 1+k");
  } else if (froude) {
    throw InputError(
        "scaling: form factor not given: with C_W at equal Froude number give 1+k, or estimate it with Prohaska's "
        "plot over the model's low-speed runs");
  } else {
    result.form_factor = mean_ratio_form_factor(runs, options.from, options.wave, options.convention);
  }
  const double one_plus_k = result.form_factor.one_plus_k;
  const double length_ratio = options.to.length / options.from.length;
  const ScaleConditions& from = options.from;
  const ScaleConditions& to = options.to;

  result.points.reserve(runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const RunCoefficients c = run_coefficients(runs[i], i, from, options.convention, options.gravity, "scale 1");
    ScaledPoint p;
    p.speed_from = runs[i].speed;
    p.froude_from = c.froude;
    p.reynolds_from = c.reynolds;
    p.friction_from = c.friction;
    p.total_from = c.total;
    p.resistance_from = c.resistance;
    p.force_from = runs[i].force;
    const double viscous_and_allowances_from = one_plus_k * c.friction + from.roughness_allowance + from.air_resistance;
    if (froude) {
      p.speed_to = runs[i].speed * std::sqrt(length_ratio);
      p.wave = c.total - viscous_and_allowances_from;
      p.residual = 0.0;
    } else {
      p.speed_to = options.target_speeds[i];
      if (!finite_positive(p.speed_to))
        throw InputError("scaling, scale 2, " + run_name(i, runs[i].speed) + ": the target speed " + shown(p.speed_to) +
                         " is not finite and positive: give ahead speeds in m/s");
      p.wave = stated_wave(options.wave);
      p.residual = c.total - viscous_and_allowances_from - p.wave;
    }
    p.froude_to = p.speed_to / std::sqrt(options.gravity * to.length);
    p.reynolds_to = p.speed_to * to.length / to.kinematic_viscosity;
    p.friction_to = ittc1957_friction(p.reynolds_to, "scale 2, " + run_name(i, runs[i].speed));
    p.total_to = one_plus_k * p.friction_to + p.wave + p.residual + to.roughness_allowance + to.air_resistance;
    p.resistance_to = 0.5 * to.density * to.wetted_area * p.speed_to * p.speed_to * p.total_to;
    p.force_to = to_convention(p.resistance_to, SignConvention::OpposingMotion, options.convention);
    result.points.push_back(p);
  }

  auto& a = result.assumptions;
  a.push_back(
      "friction from the ITTC-1957 model-ship correlation line C_F = 0.075/(log10 Re - 2)^2, Re = U L/nu, "
      "used for Re >= " +
      shown(kIttc1957MinimumReynolds));
  a.push_back("form factor " + result.form_factor.text + ", independent of scale and Reynolds number");
  switch (options.wave.statement) {
    case WaveStatement::FroudeMatched:
      a.push_back("surface ship: C_W equal at equal Froude number Fn = U/sqrt(g L), g = " + shown(options.gravity) +
                  " m/s^2; U_2 = U_1 sqrt(L_2/L_1); C_W of each run = C_T1 - "
                  "(1+k) C_F1 - dC_F1 - C_AA1");
      break;
    case WaveStatement::Submerged:
      a.push_back(
          "deeply submerged body: no wave resistance (C_W = 0); Froude number irrelevant, speeds at scale 2 "
          "as given");
      break;
    case WaveStatement::Given:
      a.push_back("wave-resistance coefficient C_W = " + shown(options.wave.coefficient) +
                  " as given, equal at both scales; speeds at scale 2 as given");
      break;
    case WaveStatement::Unstated: break;
  }
  if (!froude)
    a.push_back(
        "what (1+k) C_F + C_W leaves of each run's C_T at scale 1 (its residual) is carried unchanged to "
        "scale 2, as ITTC 1978 carries C_R");
  // A negative C_W is kept (low-speed runs scatter about zero) but said.
  std::string negative_wave;
  for (std::size_t i = 0; froude && i < result.points.size(); ++i)
    if (result.points[i].wave < 0.0) negative_wave += (negative_wave.empty() ? "" : ", ") + std::to_string(i + 1);
  if (!negative_wave.empty())
    a.push_back("C_W < 0 at run(s) " + negative_wave +
                ": (1+k) C_F exceeds their C_T (a form factor too large for them, or scatter at low speed)");
  a.push_back(allowance_text(from, "scale 1"));
  a.push_back(allowance_text(to, "scale 2"));
  a.push_back("resistance R = " + std::string(options.convention == SignConvention::OnBody ? "-X" : "X") + " (forces " +
              std::string(to_string(options.convention)) +
              "; an on-body X opposes motion when negative), C = R/(1/2 rho S U^2) with S the wetted area, "
              "ahead speeds u > 0");
  a.push_back("scale 2 geometrically similar to scale 1 (L and S as given: L_2/L_1 = " + significant(length_ratio) +
              ", S_2/S_1 = " + significant(to.wetted_area / from.wetted_area) + ")");
  return result;
}

ScaledLaw scale_damping_law(const DampingLawSpec& spec, std::span<const double> coefficients,
                            std::span<const double> sample_speeds, const ScalingOptions& options) {
  check_damping_law_spec(spec);
  if (spec.variable != "u")
    throw InputError("scaling a law: the law is in " + spec.variable +
                     ", expected a surge law in u (the resistance curve X(u))");
  if (coefficients.size() != spec.terms.size())
    throw InputError("scaling a law: " + std::to_string(coefficients.size()) + " coefficients for the " +
                     std::to_string(spec.terms.size()) + " terms " + format_damping_terms(spec));
  for (std::size_t k = 0; k < coefficients.size(); ++k)
    if (!std::isfinite(coefficients[k]))
      throw InputError("scaling a law: the coefficient of " + term_name(spec.terms[k], spec.variable) +
                       " is not finite");
  if (sample_speeds.size() < spec.terms.size())
    throw InputError("scaling a law: " + std::to_string(sample_speeds.size()) + " sample speeds for the " +
                     std::to_string(spec.terms.size()) + " terms " + format_damping_terms(spec) +
                     ": give at least as many speeds as terms");
  std::vector<ResistanceRun> runs;
  runs.reserve(sample_speeds.size());
  for (const double speed : sample_speeds) {
    if (!finite_positive(speed))
      throw InputError("scaling a law: the sample speed " + shown(speed) +
                       " is not finite and positive: give ahead speeds in m/s");
    runs.push_back({speed, damping_law_value(spec.terms, coefficients, speed)});
  }
  ScaledLaw law;
  law.spec = spec;
  law.curve = scale_resistance(runs, options);

  const auto rows = static_cast<Eigen::Index>(runs.size());
  const auto cols = static_cast<Eigen::Index>(spec.terms.size());
  Eigen::MatrixXd design(rows, cols);
  Eigen::VectorXd target(rows);
  for (Eigen::Index i = 0; i < rows; ++i) {
    const ScaledPoint& p = law.curve.points[static_cast<std::size_t>(i)];
    for (Eigen::Index k = 0; k < cols; ++k)
      design(i, k) = basis_value(spec.terms[static_cast<std::size_t>(k)], p.speed_to);
    target(i) = p.force_to;
  }
  // Columns scaled to unit norm, so that the rank test does not depend on units.
  Eigen::VectorXd norms = design.colwise().norm().transpose();
  for (Eigen::Index k = 0; k < cols; ++k)
    if (norms(k) > 0.0) design.col(k) /= norms(k);
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr = col_piv_householder_qr(design);
  qr.setThreshold(1e-10);
  if (qr.rank() < cols)
    throw InputError("scaling a law: the " + std::to_string(runs.size()) + " sample speeds cannot tell the terms " +
                     format_damping_terms(spec) + " apart: give more distinct speeds");
  const Eigen::VectorXd solution = qr.solve(target);
  law.coefficients.resize(spec.terms.size());
  for (Eigen::Index k = 0; k < cols; ++k)
    law.coefficients[static_cast<std::size_t>(k)] = norms(k) > 0.0 ? solution(k) / norms(k) : 0.0;
  for (const ScaledPoint& p : law.curve.points) {
    const double fitted = damping_law_value(law.spec.terms, law.coefficients, p.speed_to);
    law.max_relative_deviation =
        std::max(law.max_relative_deviation, std::abs(fitted - p.force_to) / std::abs(p.force_to));
  }
  return law;
}

}  // namespace hydrocoef
