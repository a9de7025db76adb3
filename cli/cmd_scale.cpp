// hydrocoef scale: a surge resistance curve or a stored surge law from one
// scale to another with the ITTC-1957 friction line and a form factor
// (1 + k), the method and its assumptions printed. The library scales and
// reports (hydrocoef::scale_surge_resistance, include/hydrocoef/scaling.hpp);
// this command parses, calls and prints.
#include <charconv>
#include <cmath>
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/error.hpp"
#include "hydrocoef/scaling.hpp"

namespace hydrocoef::cli {
namespace {

struct ScaleArgs {
  hydrocoef::ResistanceScalingOptions options;
  std::vector<std::string> points;
  bool json = false;
};

/// "U,X" into two finite numbers.
std::pair<double, double> parse_point(const std::string& text) {
  const auto comma = text.find(',');
  double values[2] = {0.0, 0.0};
  const std::string parts[2] = {text.substr(0, comma), comma == std::string::npos ? "" : text.substr(comma + 1)};
  for (int k = 0; k < 2; ++k) {
    const auto& part = parts[k];
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), values[k]);
    if (comma == std::string::npos || part.empty() || ec != std::errc() || end != part.data() + part.size() ||
        !std::isfinite(values[k]))
      throw hydrocoef::InputError("--point '" + text + "': expected U,X: a speed [m/s] and a surge force [N]");
  }
  return {values[0], values[1]};
}

}  // namespace

void add_scale_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<ScaleArgs>();
  auto& o = args->options;
  auto* command = app.add_subcommand(
      "scale",
      "Surge resistance from one scale to another (model to ship, or between models): the ITTC-1957 friction line "
      "C_F = 0.075/(log10 Re - 2)^2 with a form factor, C_T = (1+k) C_F + C_W + dC_F + C_AA (ITTC 1978 method), for "
      "points U,X or a stored surge law X(u); prints the method, its assumptions and U, R at both scales");
  command->add_option("--point", args->points, "A point U,X at scale 1: speed [m/s] and surge force [N] (repeatable)");
  command->add_option("--fit", o.fit, "A stored surge law, a fit of X in u (instead of --point)");
  command->add_option("--speeds", o.sample_speeds, "With --fit: the speeds at scale 1 [m/s] the law is scaled at")
      ->delimiter(',');
  command->add_option("--from-length", o.from_length, "Scale 1: length L [m] (waterline length of a ship)");
  command->add_option("--from-area", o.from_area, "Scale 1: wetted area S [m^2]");
  command->add_option("--from-viscosity", o.from_viscosity, "Scale 1: kinematic viscosity nu [m^2/s]");
  command->add_option("--from-density", o.from_density, "Scale 1: density rho [kg/m^3]");
  command->add_option("--to-length", o.to_length, "Scale 2: length L [m]");
  command->add_option("--to-area", o.to_area, "Scale 2: wetted area S [m^2]");
  command->add_option("--to-viscosity", o.to_viscosity, "Scale 2: kinematic viscosity nu [m^2/s]");
  command->add_option("--to-density", o.to_density, "Scale 2: density rho [kg/m^3]");
  command->add_option("--from-roughness", o.from_roughness,
                      "Scale 1: hull roughness k_s [m] of the ITTC 1978 allowance dC_F (default none)");
  command->add_option("--to-roughness", o.to_roughness,
                      "Scale 2: hull roughness k_s [m] of the ITTC 1978 allowance dC_F (ITTC: 150e-6; default none)");
  command->add_option("--from-air-area", o.from_air_area,
                      "Scale 1: transverse area above water A_T [m^2], C_AA = 0.001 A_T/S (default none)");
  command->add_option("--to-air-area", o.to_air_area,
                      "Scale 2: transverse area above water A_T [m^2], C_AA = 0.001 A_T/S (default none)");
  command->add_option("--wave", o.wave,
                      "submerged (C_W = 0), froude (surface ship: C_W at equal Froude number, U2 = U1 "
                      "sqrt(L2/L1)) or a C_W given at both scales (required)");
  command->add_option("--form-factor", o.form_factor,
                      "1+k given, or prohaska (Prohaska's plot over the scale-1 points: give low speeds); default: "
                      "submerged or given C_W, the mean of (C_T - C_W)/C_F over the points");
  command
      ->add_option("--target-speeds", o.target_speeds,
                   "submerged or given C_W: the speed at scale 2 [m/s] of each point (or --speeds)")
      ->delimiter(',');
  command->add_option("--gravity", o.gravity, "g [m/s^2] of the Froude number")->capture_default_str();
  command->add_option("--sign", o.sign, "The points' forces: on-body (X, negative ahead) or opposing (R)")
      ->capture_default_str();
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] {
    auto options = args->options;
    for (const auto& text : args->points) {
      const auto [speed, force] = parse_point(text);
      options.speeds.push_back(speed);
      options.forces.push_back(force);
    }
    options.validate();
    const auto result = options.fit.empty()
                            ? hydrocoef::scale_surge_resistance(options)
                            : hydrocoef::scale_surge_resistance(
                                  hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly), options);
    std::cout << (args->json ? result.json() : result.text());
  });
}

}  // namespace hydrocoef::cli
