// Resistance from one scale to another (include/hydrocoef/scaling.hpp):
// `hydrocoef scale` without its printing. The options become the library's
// ScalingOptions (src/derivatives/scaling.hpp), the points or the stored
// surge law are scaled by scale_resistance or scale_damping_law, and the
// result is restated in public types. What the command prints is
// scaling_report.cpp.
#include "src/api/internal.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

#include "hydrocoef/scaling.hpp"
#include "src/core/damping_terms.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/sign_convention.hpp"
#include "src/derivatives/scaling.hpp"

namespace hydrocoef {
inline namespace api {
namespace {

/// 1 + k from --form-factor's text; nullopt for "" and "prohaska".
std::optional<double> given_one_plus_k(const std::string& text) {
  if (text.empty() || text == "prohaska") return std::nullopt;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value) || !(value > 0.0))
    throw InputError("--form-factor '" + escape::one_line(text) +
                     "': expected 1+k (a number above 0, e.g. 1.15) or prohaska (Prohaska's plot over the points)");
  return value;
}

void check_positive(double value, const char* option) {
  if (!(std::isfinite(value) && value > 0.0))
    throw InputError(std::string(option) + " must be a finite number above 0, not " + shortest_number(value));
}

ScaleConditions conditions(double length, double area, double viscosity, double density, double roughness,
                           double air_area) {
  ScaleConditions c;
  c.length = length;
  c.wetted_area = area;
  c.kinematic_viscosity = viscosity;
  c.density = density;
  if (!std::isnan(roughness)) c.roughness_allowance = ittc1978_roughness_allowance(roughness, length);
  if (!std::isnan(air_area)) c.air_resistance = ittc1978_air_resistance(air_area, area);
  return c;
}

ScalingOptions library_options(const ResistanceScalingOptions& o, SignConvention convention) {
  ScalingOptions out;
  out.from =
      conditions(o.from_length, o.from_area, o.from_viscosity, o.from_density, o.from_roughness, o.from_air_area);
  out.to = conditions(o.to_length, o.to_area, o.to_viscosity, o.to_density, o.to_roughness, o.to_air_area);
  out.wave = parse_wave_resistance(o.wave);
  out.target_speeds = o.target_speeds;
  out.gravity = o.gravity;
  out.convention = convention;
  return out;
}

/// The form factor as the options state it, Prohaska's plot over `runs`.
std::optional<FormFactor> form_factor(const ResistanceScalingOptions& o, const ScalingOptions& scaling,
                                      const std::vector<ResistanceRun>& runs) {
  if (const auto given = given_one_plus_k(o.form_factor)) return given_form_factor(*given);
  if (o.form_factor == "prohaska") return prohaska_form_factor(runs, scaling.from, scaling.convention, scaling.gravity);
  return std::nullopt;
}

const char* method_name(FormFactorMethod method) {
  switch (method) {
    case FormFactorMethod::Given: return "given";
    case FormFactorMethod::Prohaska: return "prohaska";
    default: return "mean ratio";
  }
}

ResistanceScalingResult public_result(const ScalingResult& scaled, SignConvention convention) {
  ResistanceScalingResult r;
  r.method =
      "ITTC-1957 friction line C_F = 0.075/(log10 Re - 2)^2 (8th ITTC, Madrid 1957; ITTC 7.5-02-02-01 and "
      "7.5-02-03-01.4) with a form factor: C_T = (1+k) C_F + C_W + dC_F + C_AA, 1+k independent of scale and speed "
      "(ITTC 1978 method; Prohaska 1966 for 1+k from low-speed runs)";
  r.sign = std::string(to_string(convention));
  r.wave = describe(scaled.wave);
  r.one_plus_k = scaled.form_factor.one_plus_k;
  r.form_factor_method = method_name(scaled.form_factor.method);
  if (scaled.form_factor.method == FormFactorMethod::Prohaska) r.prohaska_slope = scaled.form_factor.prohaska_slope;
  r.form_factor = scaled.form_factor.text;
  r.assumptions = scaled.assumptions;
  for (const ScaledPoint& p : scaled.points)
    r.points.push_back({p.speed_from, p.speed_to, p.force_from, p.force_to, p.resistance_from, p.resistance_to,
                        p.froude_from, p.froude_to, p.reynolds_from, p.reynolds_to, p.friction_from, p.friction_to,
                        p.wave, p.residual, p.total_from, p.total_to});
  return r;
}

ResistanceScalingResult scale(const ResistanceScalingOptions& options, const FitRecord* fit) {
  if (!fit) {
    const SignConvention convention = *sign_convention_named(options.sign);
    const ScalingOptions scaling = library_options(options, convention);
    std::vector<ResistanceRun> runs;
    for (std::size_t k = 0; k < options.speeds.size(); ++k) runs.push_back({options.speeds[k], options.forces[k]});
    ScalingOptions with_factor = scaling;
    with_factor.form_factor = form_factor(options, scaling, runs);
    return public_result(scale_resistance(runs, with_factor), convention);
  }
  const DampingLawSpec spec = parse_damping_terms(fit->terms);
  std::vector<double> coefficients;
  for (const auto& c : fit->coefficients) coefficients.push_back(c.value);
  ScalingOptions scaling = library_options(options, fit->sign);
  std::vector<ResistanceRun> runs;  // the law at the sample speeds, for Prohaska's plot
  if (coefficients.size() == spec.terms.size())
    for (const double u : options.sample_speeds) runs.push_back({u, damping_law_value(spec.terms, coefficients, u)});
  scaling.form_factor = form_factor(options, scaling, runs);
  const ScaledLaw law = scale_damping_law(spec, coefficients, options.sample_speeds, scaling);
  ResistanceScalingResult r = public_result(law.curve, fit->sign);
  r.fit = fit->name;
  r.terms = fit->terms;
  r.coefficients_from = coefficients;
  r.coefficients_to = law.coefficients;
  r.units = coefficient_units(fit->terms, "X", "u");
  r.max_relative_deviation = law.max_relative_deviation;
  return r;
}

}  // namespace

void ResistanceScalingOptions::validate() const {
  const std::array<std::pair<double, const char*>, 8> required{{{from_length, "--from-length"},
                                                                {from_area, "--from-area"},
                                                                {from_viscosity, "--from-viscosity"},
                                                                {from_density, "--from-density"},
                                                                {to_length, "--to-length"},
                                                                {to_area, "--to-area"},
                                                                {to_viscosity, "--to-viscosity"},
                                                                {to_density, "--to-density"}}};
  for (const auto& [value, option] : required) {
    if (std::isnan(value))
      throw InputError(std::string("scale: expected ") + option +
                       " (each scale's length [m], wetted area [m^2], kinematic viscosity [m^2/s] and density "
                       "[kg/m^3]; none is assumed)");
    check_positive(value, option);
  }
  const std::array<std::pair<double, const char*>, 4> allowances{{{from_roughness, "--from-roughness"},
                                                                  {to_roughness, "--to-roughness"},
                                                                  {from_air_area, "--from-air-area"},
                                                                  {to_air_area, "--to-air-area"}}};
  for (const auto& [value, option] : allowances)
    if (!std::isnan(value)) check_positive(value, option);
  check_positive(gravity, "--gravity");
  if (wave.empty())
    throw InputError(
        "scale: expected --wave submerged (a deeply submerged body, C_W = 0), froude (a surface ship, C_W at equal "
        "Froude number) or a wave-resistance coefficient C_W; there is no default");
  (void)parse_wave_resistance(wave);
  (void)given_one_plus_k(form_factor);
  if (speeds.empty() == fit.empty())
    throw InputError(std::string("scale: expected either --point U,X (repeatable) or --fit NAME (") +
                     (fit.empty() ? "neither" : "both") + " given)");
  if (speeds.size() != forces.size())
    throw InputError("scale: " + std::to_string(speeds.size()) + " speeds and " + std::to_string(forces.size()) +
                     " forces; expected one force a speed");
  if (!sample_speeds.empty() && fit.empty())
    throw InputError("--speeds applies to --fit only; expected --fit NAME with it (points are given with --point)");
  if (!fit.empty() && sample_speeds.empty())
    throw InputError("--fit '" + escape::one_line(fit) +
                     "' needs --speeds U1,U2,...: the speeds at scale 1 at which the law is evaluated and scaled");
  if (!sign_convention_named(sign))
    throw InputError("--sign '" + escape::one_line(sign) + "': expected on-body or opposing");
}

ResistanceScalingResult scale_surge_resistance(const ResistanceScalingOptions& options) {
  options.validate();
  if (!options.fit.empty())
    throw InputError("--fit '" + escape::one_line(options.fit) +
                     "': a stored fit is read from a database; expected scale_surge_resistance(database, options)");
  return scale(options, nullptr);
}

ResistanceScalingResult scale_surge_resistance(const Database& db, const ResistanceScalingOptions& options) {
  options.validate();
  if (options.fit.empty()) return scale(options, nullptr);
  auto& impl = Database::Access::impl(db);
  const std::lock_guard lock(impl.mutex);
  const std::vector<FitRecord> fits = impl.open_store().fits();
  const auto found = std::find_if(fits.begin(), fits.end(), [&](const FitRecord& f) { return f.name == options.fit; });
  if (found == fits.end() || found->dof != "X" || found->variable != "u") {
    std::string surge;
    for (const auto& f : fits)
      if (f.dof == "X" && f.variable == "u") surge += (surge.empty() ? "'" : ", '") + escape::one_line(f.name) + "'";
    throw InputError(SourceLocation{impl.path},
                     "--fit '" + escape::one_line(options.fit) + "': " +
                         (found == fits.end() ? std::string("no fit of that name")
                                              : "a fit of " + found->dof + " in " + found->variable) +
                         "; expected a stored surge law, a fit of X in u (" +
                         (surge.empty() ? std::string("none stored") : surge) + ")");
  }
  return scale(options, &*found);
}

}  // namespace api
}  // namespace hydrocoef
