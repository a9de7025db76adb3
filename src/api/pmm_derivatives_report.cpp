// The text and JSON of `hydrocoef derivatives pmm`
// (include/hydrocoef/pmm_derivatives.hpp), made from the result's public
// fields: per motion, speed and frequency a table of derivative, value,
// standard error, unit and, when known, the prime value; the runs after.
#include "src/api/internal.hpp"

#include <iomanip>
#include <sstream>

#include "hydrocoef/pmm_derivatives.hpp"
#include "src/api/analysis_format.hpp"
#include "src/core/escape.hpp"

namespace hydrocoef {
inline namespace api {
namespace {

using analysis_format::optional_json;
using analysis_format::significant;

nlohmann::json derivative_json(const PmmDerivative& d) {
  nlohmann::json out = {{"name", d.name},
                        {"value", d.value},
                        {"std_error", d.std_error},
                        {"unit", d.unit},
                        {"source", d.source},
                        {"prime", optional_json(d.prime)},
                        {"prime_std_error", optional_json(d.prime_std_error)}};
  if (!d.normalisation.empty()) out["normalisation"] = d.normalisation;
  return out;
}

nlohmann::json derivatives_json(const std::vector<PmmDerivative>& derivatives) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& d : derivatives) out.push_back(derivative_json(d));
  return out;
}

}  // namespace

std::string PmmDerivatives::json() const {
  nlohmann::json sets_json = nlohmann::json::array();
  for (const auto& s : sets)
    sets_json.push_back({{"motion", s.motion},
                         {"dof", s.dof},
                         {"speed_m_s", s.speed},
                         {"omega_rad_s", s.omega},
                         {"period_s", s.period},
                         {"omega_prime", optional_json(s.omega_prime)},
                         {"runs", s.runs},
                         {"amplitude_min", s.amplitude_min},
                         {"amplitude_max", s.amplitude_max},
                         {"amplitude_unit", s.amplitude_unit},
                         {"pmm_runs", s.pmm_runs},
                         {"derivatives", derivatives_json(s.derivatives)}});
  nlohmann::json runs_json = nlohmann::json::array();
  for (const auto& r : runs)
    runs_json.push_back({{"id", r.id},
                         {"dof", r.dof},
                         {"speed_m_s", r.speed},
                         {"amplitude", r.amplitude},
                         {"omega_rad_s", r.omega},
                         {"source_path", r.source_path},
                         {"derivatives", derivatives_json(r.derivatives)}});
  const nlohmann::json out = {{"body", body},
                              {"length_m", optional_json(length)},
                              {"length_from", length_from},
                              {"density_kg_m3", optional_json(density)},
                              {"density_from", density_from},
                              {"sets", sets_json},
                              {"runs", runs_json},
                              {"other_runs", other_runs},
                              {"notes", notes}};
  return escape::json_text(out, 2);
}

std::string PmmDerivatives::text() const {
  std::ostringstream out;
  out << "Sway and yaw derivatives of body " << escape::one_line(body)
      << " from forced-oscillation runs (SNAME body axes, forces on the body; Y_v = -D[sway][sway], "
         "Y_vdot = -M_A[sway][sway], ...)\n";
  if (length) out << "L = " << significant(*length, 6) << " m (" << length_from << ")";
  if (density)
    out << (length ? ", " : "") << "rho = " << significant(*density, 6) << " kg/m^3 (" << density_from << ")";
  if (length || density) out << "\n";
  for (const auto& s : sets) {
    out << "\n"
        << s.motion << ", U = " << significant(s.speed, 6) << " m/s, T = " << significant(s.period, 6) << " s (omega "
        << significant(s.omega, 6) << " rad/s";
    if (s.omega_prime) out << ", omega' = omega L / U = " << significant(*s.omega_prime, 5);
    out << "), " << s.runs << (s.runs == 1 ? " run" : " runs") << ", amplitude " << significant(s.amplitude_min, 4);
    if (s.amplitude_max != s.amplitude_min) out << ".." << significant(s.amplitude_max, 4);
    out << " " << s.amplitude_unit << "\n";
    bool any_prime = false;
    for (const auto& d : s.derivatives) any_prime = any_prime || d.prime.has_value();
    out << "  " << std::left << std::setw(10) << "derivative" << std::right << std::setw(14) << "value" << std::setw(12)
        << "std error"
        << "  ";
    if (any_prime)
      out << std::left << std::setw(8) << "unit" << std::right << std::setw(14) << "prime" << std::setw(12)
          << "std error";
    else
      out << "unit";
    out << "\n";
    for (const auto& d : s.derivatives) {
      out << "  " << std::left << std::setw(10) << d.name << std::right << std::setw(14) << significant(d.value, 6)
          << std::setw(12) << significant(d.std_error, 2) << "  ";
      if (d.prime)
        out << std::left << std::setw(8) << d.unit << std::right << std::setw(14) << significant(*d.prime, 6)
            << std::setw(12) << significant(*d.prime_std_error, 2);
      else
        out << d.unit;
      out << "\n";
    }
    for (const auto& d : s.derivatives)
      if (!d.normalisation.empty()) out << "  " << d.normalisation << "\n";
  }
  out << "\nRuns (pmm run id, motion, U, amplitude, omega: derivatives in SI):\n";
  for (const auto& r : runs) {
    out << "  " << r.id << " " << r.dof << ", U " << significant(r.speed, 6) << " m/s, A "
        << significant(r.amplitude, 4) << (r.dof == "sway" ? " m" : " rad") << ", omega " << significant(r.omega, 6)
        << " rad/s:";
    for (const auto& d : r.derivatives) out << " " << d.name << " " << significant(d.value, 5);
    out << "  " << escape::one_line(r.source_path) << "\n";
  }
  for (const auto& note : notes) out << "note: " << note << "\n";
  return out.str();
}

}  // namespace api
}  // namespace hydrocoef
