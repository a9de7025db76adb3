// The text and JSON of the forced-oscillation results
// (include/hydrocoef/analysis.hpp): what `hydrocoef pmm`, `pmm-runs`,
// `pmm-runs delete` and `added-mass` print, made from the results' public
// fields. Units follow the entry: M_A[i][j] in kg (two translations), kg m
// (one rotation), kg m^2 (two rotations); D[i][j] in N s/m, N s or N m s.
#include "src/api/internal.hpp"

#include <iomanip>
#include <sstream>

#include "hydrocoef/analysis.hpp"
#include "src/api/analysis_format.hpp"
#include "src/core/escape.hpp"

namespace hydrocoef {
inline namespace api {
namespace {

using analysis_format::optional_json;
using analysis_format::significant;

bool translation(const std::string& dof) { return dof == "surge" || dof == "sway" || dof == "heave"; }

std::string unit_of_added_mass(bool translation) { return translation ? "kg" : "kg m^2"; }

const char* const kDofNames[6] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};

nlohmann::json matrix_json(const Matrix6x6& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& row : m) rows.push_back(row);
  return rows;
}

nlohmann::json run_json(const PmmRunResult& r, bool stored) {
  const bool moves = translation(r.dof);
  nlohmann::json out = {{"path", r.path},
                        {"format", r.format},
                        {"body", r.body},
                        {"velocity_b", r.velocity},
                        {"motion",
                         {{"dof", r.dof},
                          {"amplitude", r.amplitude},
                          {"amplitude_unit", moves ? "m" : "rad"},
                          {"omega_rad_s", r.omega},
                          {"period_s", r.period},
                          {"phase_rad", r.phase},
                          {"source", r.motion_source}}},
                        {"medium", r.medium},
                        {"window_s", {r.window_start, r.window_end}},
                        {"periods", r.periods},
                        {"transient_periods", r.transient_periods},
                        {"samples", r.samples},
                        {"harmonics", r.harmonics},
                        {"size_m", optional_json(r.size)},
                        {"keulegan_carpenter", optional_json(r.keulegan_carpenter)},
                        {"stokes_number", optional_json(r.stokes_number)},
                        {"rho_kg_m3", optional_json(r.rho)},
                        {"displaced_volume_m3", optional_json(r.displaced_volume)},
                        {"restoring", optional_json(r.restoring)},
                        {"restoring_unit", moves ? "N/m" : "N m/rad"},
                        {"notes", r.notes},
                        {"components", nlohmann::json::array()}};
  if (stored) out["stored"] = {{"id", r.stored_id}, {"replaced", r.replaced}};
  for (const auto& c : r.components) {
    nlohmann::json entry = {{"component", c.component},
                            {"mean", c.mean},
                            {"added_mass", c.added_mass},
                            {"added_mass_se", c.added_mass_se},
                            {"added_mass_unit", c.added_mass_unit},
                            {"damping", c.damping},
                            {"damping_se", c.damping_se},
                            {"damping_unit", c.damping_unit},
                            {"explained", c.explained},
                            {"harmonics_sin_cos", c.harmonics}};
    if (c.added_mass_coefficient) entry["added_mass_coefficient"] = *c.added_mass_coefficient;
    entry["cycle_spread"] = {{"in_phase", c.in_phase_spread}, {"quadrature", c.quadrature_spread}};
    out["components"].push_back(entry);
  }
  return out;
}

}  // namespace

std::string PmmAnalysis::json() const {
  nlohmann::json out = {{"database", stored ? nlohmann::json(database) : nlohmann::json()},
                        {"runs", nlohmann::json::array()}};
  for (const auto& run : runs) out["runs"].push_back(run_json(run, stored));
  return escape::json_text(out, 2);
}

std::string PmmAnalysis::text() const {
  std::ostringstream out;
  out << "Forced oscillation (virtual PMM): " << runs.size() << (runs.size() == 1 ? " run" : " runs")
      << " analysed; body axes (x forward, y starboard, z down), F = -M_A x'' - D x' on the body\n";
  for (const PmmRunResult& r : runs) {
    const bool moves = translation(r.dof);
    out << "\n" << escape::one_line(r.path) << "  (body " << escape::one_line(r.body) << ")\n";
    out << "  motion: " << r.dof << " " << significant(r.amplitude, 6) << (moves ? " m" : " rad") << " sin("
        << significant(r.omega, 6) << " t + " << significant(r.phase, 4) << "), period " << significant(r.period, 6)
        << " s; from " << escape::one_line(r.motion_source) << "\n";
    out << "  " << r.medium << "; window " << significant(r.window_start, 6) << " to " << significant(r.window_end, 6)
        << " s: " << r.periods << " whole periods after " << r.transient_periods << " start-up "
        << (r.transient_periods == 1 ? "period" : "periods") << ", " << r.samples << " samples, " << r.harmonics
        << (r.harmonics == 1 ? " harmonic" : " harmonics") << "\n";
    std::size_t dof = 0;
    while (dof < 6 && r.dof != kDofNames[dof]) ++dof;
    if (r.restoring)
      out << "  restoring force -C x removed from " << (dof < 6 ? kForceNames[dof] : "?")
          << " before the fit: C = " << significant(*r.restoring, 6) << (moves ? " N/m" : " N m/rad") << "\n";
    if (r.keulegan_carpenter || r.stokes_number) {
      out << " ";
      if (r.keulegan_carpenter) out << " KC = 2 pi A / D = " << significant(*r.keulegan_carpenter, 4) << ";";
      if (r.stokes_number) out << " Stokes number D^2/(nu T) = " << significant(*r.stokes_number, 4) << ";";
      out << " D = " << significant(r.size.value_or(0.0), 6) << " m\n";
    }
    out << "  " << std::left << std::setw(4) << "" << std::right << std::setw(13) << "mean" << std::setw(14)
        << "M_A[.][" + r.dof + "]" << std::setw(11) << "+- se" << std::setw(8) << "" << std::setw(13)
        << "D[.][" + r.dof + "]" << std::setw(11) << "+- se" << std::setw(9) << "" << std::setw(10) << "explained\n";
    for (const auto& c : r.components) {
      out << "  " << std::left << std::setw(4) << c.component << std::right << std::setw(13) << significant(c.mean, 5)
          << std::setw(14) << significant(c.added_mass, 5) << std::setw(11) << significant(c.added_mass_se, 3) << " "
          << std::left << std::setw(7) << c.added_mass_unit << std::right << std::setw(13) << significant(c.damping, 5)
          << std::setw(11) << significant(c.damping_se, 3) << " " << std::left << std::setw(8) << c.damping_unit
          << std::right << std::setw(9) << std::fixed << std::setprecision(2) << 100.0 * c.explained << " %\n"
          << std::defaultfloat << std::setprecision(6);
      if (c.added_mass_coefficient)
        out << "       added-mass coefficient M_A / (rho V) = " << significant(*c.added_mass_coefficient, 5)
            << " (rho V = " << significant(r.rho.value_or(0.0) * r.displaced_volume.value_or(0.0), 5) << " kg)\n";
    }
    for (const auto& note : r.notes) out << "  note: " << escape::one_line(note) << "\n";
    if (stored)
      out << "  stored as pmm run " << r.stored_id << (r.replaced ? " (replacing the earlier analysis)" : "") << "\n";
  }
  if (stored) out << "\nStored in " << escape::one_line(database) << "\n";
  return out.str();
}

std::string PmmRunList::json() const {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : runs)
    out.push_back({{"id", r.id},
                   {"body", r.body},
                   {"dof", r.dof},
                   {"amplitude", r.amplitude},
                   {"amplitude_unit", r.amplitude_unit},
                   {"period_s", r.period},
                   {"omega_rad_s", r.omega},
                   {"medium", r.medium},
                   {"restoring", optional_json(r.restoring)},
                   {"added_mass", optional_json(r.added_mass)},
                   {"damping", optional_json(r.damping)},
                   {"source_path", r.source_path},
                   {"created_at", r.created_at}});
  return escape::json_text(out, 2);
}

std::string PmmRunList::text() const {
  if (runs.empty()) return "No forced-oscillation runs stored (hydrocoef pmm stores them)\n";
  std::ostringstream out;
  out << runs.size() << (runs.size() == 1 ? " forced-oscillation run" : " forced-oscillation runs")
      << " (in-line M_A and D of the moved DOF; body axes, F = -M_A x'' - D x' on the body):\n";
  for (const auto& r : runs) {
    const bool moves = translation(r.dof);
    out << "  " << std::setw(5) << r.id << "  " << escape::one_line(r.body) << "  " << r.dof << " A "
        << significant(r.amplitude, 6) << (moves ? " m" : " rad") << ", T " << significant(r.period, 6) << " s";
    if (r.added_mass)
      out << ": M_A " << significant(*r.added_mass, 5) << " " << r.added_mass_unit << ", D "
          << significant(r.damping.value_or(0.0), 5) << " " << r.damping_unit;
    if (r.restoring) out << ", restoring " << significant(*r.restoring, 6) << (moves ? " N/m" : " N m/rad");
    out << "  " << escape::one_line(r.source_path) << "\n";
  }
  return out.str();
}

std::string PmmDeletion::json() const {
  nlohmann::json out = {{"database", database}, {"deleted", nlohmann::json::array()}};
  for (const auto& d : deleted)
    out["deleted"].push_back({{"id", d.id},
                              {"body", d.body},
                              {"dof", d.dof.empty() ? nlohmann::json() : nlohmann::json(d.dof)},
                              {"source_path", d.source_path}});
  return escape::json_text(out, 2);
}

std::string PmmDeletion::text() const {
  std::ostringstream out;
  out << "deleted " << deleted.size() << (deleted.size() == 1 ? " forced-oscillation run" : " forced-oscillation runs")
      << " from " << escape::one_line(database) << ":\n";
  for (const auto& d : deleted)
    out << "  " << d.id << "  " << escape::one_line(d.body) << "  " << (d.dof.empty() ? "?" : d.dof) << "  "
        << escape::one_line(d.source_path) << "\n";
  return out.str();
}

std::string AddedMassMatrix::json() const {
  nlohmann::json entry_list = nlohmann::json::array();
  for (const auto& e : entries)
    entry_list.push_back(
        {{"row", e.row},
         {"column", e.column},
         {"runs", e.runs},
         {"added_mass", e.added_mass},
         {"added_mass_se", e.added_mass_se},
         {"added_mass_spread", e.added_mass_spread},
         {"damping", e.damping},
         {"damping_se", e.damping_se},
         {"omega_rad_s", {e.omega_min, e.omega_max}},
         {"keulegan_carpenter", e.kc_min ? nlohmann::json{*e.kc_min, e.kc_max.value_or(*e.kc_min)} : nlohmann::json()},
         {"pmm_runs", e.pmm_runs}});
  nlohmann::json quadratic = nlohmann::json::array();
  for (const auto& q : quadratic_damping)
    quadratic.push_back({{"dof", q.dof},
                         {"omega_rad_s", q.omega},
                         {"amplitudes", q.amplitudes},
                         {"linear", q.linear},
                         {"linear_se", q.linear_se},
                         {"quadratic", q.quadratic},
                         {"quadratic_se", q.quadratic_se}});
  nlohmann::json frequencies = nlohmann::json::array();
  for (const auto& f : by_frequency)
    frequencies.push_back({{"dof", f.dof},
                           {"omega_rad_s", f.omega},
                           {"period_s", f.period},
                           {"runs", f.runs},
                           {"amplitudes", {f.amplitude_min, f.amplitude_max}},
                           {"added_mass", f.added_mass},
                           {"added_mass_se", f.added_mass_se},
                           {"damping", f.damping},
                           {"damping_se", f.damping_se},
                           {"used", f.used}});
  const nlohmann::json out = {{"body", body},
                              {"period_s", period},
                              {"omega_rad_s", omega},
                              {"records", records},
                              {"other_frequency_records", other_frequency_records},
                              {"by_frequency", frequencies},
                              {"added_mass_b", matrix_json(added_mass)},
                              {"added_mass_se", matrix_json(added_mass_se)},
                              {"damping_b", matrix_json(damping)},
                              {"damping_se", matrix_json(damping_se)},
                              {"entries", entry_list},
                              {"missing", missing},
                              {"notes", notes},
                              {"positive_definite", positive_definite},
                              {"smallest_eigenvalue", smallest_eigenvalue},
                              {"quadratic_damping", quadratic}};
  return escape::json_text(out, 2);
}

std::string AddedMassMatrix::text() const {
  std::ostringstream out;
  out << "Added mass of body " << escape::one_line(body) << " from " << records
      << (records == 1 ? " forced-oscillation run" : " forced-oscillation runs") << " at period "
      << significant(period, 6) << " s (omega " << significant(omega, 6)
      << " rad/s; body axes; kg, kg m, kg m^2; symmetric)";
  if (other_frequency_records)
    out << "; " << other_frequency_records << (other_frequency_records == 1 ? " run" : " runs")
        << " at other periods left out";
  out << "\n";
  const auto print_matrix = [&out](const Matrix6x6& m, const Matrix6x6& se) {
    out << std::setw(8) << "";
    for (std::size_t j = 0; j < 6; ++j) out << std::setw(24) << kDofNames[j];
    out << "\n";
    for (std::size_t i = 0; i < 6; ++i) {
      out << std::left << std::setw(8) << kDofNames[i] << std::right;
      for (std::size_t j = 0; j < 6; ++j) {
        const double v = m[i][j], s = se[i][j];
        out << ' ' << std::setw(23) << (significant(v, 5) + (s > 0.0 ? " +- " + significant(s, 2) : ""));
      }
      out << "\n";
    }
  };
  print_matrix(added_mass, added_mass_se);
  out << (positive_definite ? "positive definite" : "NOT positive definite (printed: --allow-indefinite)")
      << " over the DOFs with a non-zero diagonal (smallest eigenvalue " << significant(smallest_eigenvalue, 5)
      << ")\n";
  out << "\nLinear damping D (N s/m, N s, N m s; as measured):\n";
  print_matrix(damping, damping_se);
  out << "\nEntries measured:\n";
  for (const auto& e : entries) {
    if (e.row != e.column && e.added_mass == 0.0) continue;
    out << "  " << std::left << std::setw(20) << e.name << std::right << e.runs << (e.runs == 1 ? " run" : " runs")
        << ", omega " << significant(e.omega_min, 4);
    if (e.omega_max != e.omega_min) out << ".." << significant(e.omega_max, 4);
    out << " rad/s";
    if (e.kc_min) {
      out << ", KC " << significant(*e.kc_min, 3);
      if (e.kc_max && *e.kc_max != *e.kc_min) out << ".." << significant(*e.kc_max, 3);
    }
    if (e.runs > 1) out << ", spread " << significant(e.added_mass_spread, 3) << " " << e.unit;
    out << "\n";
  }
  out << "\nIn-line added mass and damping by frequency (runs of one DOF and period combined; * the period "
         "used above):\n";
  for (const auto& f : by_frequency) {
    const bool moves = translation(f.dof);
    out << (f.used ? "* " : "  ") << std::left << std::setw(6) << f.dof << std::right << " T "
        << significant(f.period, 6) << " s (omega " << significant(f.omega, 4) << " rad/s), " << f.runs
        << (f.runs == 1 ? " run" : " runs") << ", A " << significant(f.amplitude_min, 4)
        << (f.amplitude_max != f.amplitude_min ? ".." + significant(f.amplitude_max, 4) : std::string())
        << (moves ? " m" : " rad") << ": M_A = " << significant(f.added_mass, 5) << " +- "
        << significant(f.added_mass_se, 2) << " " << unit_of_added_mass(moves) << ", D = " << significant(f.damping, 5)
        << " +- " << significant(f.damping_se, 2) << " " << (moves ? "N s/m" : "N m s") << "\n";
  }
  if (!quadratic_damping.empty()) {
    out << "\nQuadratic damping from the amplitude dependence, D_eq(A) = b1 + b2 (8/(3 pi)) A omega:\n";
    for (const auto& q : quadratic_damping) {
      const bool moves = translation(q.dof);
      out << "  " << std::left << std::setw(6) << q.dof << std::right << " omega " << significant(q.omega, 4)
          << " rad/s, " << q.amplitudes.size() << " runs: b1 = " << significant(q.linear, 5) << " +- "
          << significant(q.linear_se, 2) << " " << (moves ? "N s/m" : "N m s")
          << ", b2 = " << significant(q.quadratic, 5) << " +- " << significant(q.quadratic_se, 2)
          << (moves ? " N s^2/m^2" : " N m s^2") << "\n";
    }
  }
  for (const auto& m : missing) out << "missing: " << escape::one_line(m) << "\n";
  for (const auto& n : notes) out << "note: " << escape::one_line(n) << "\n";
  return out.str();
}

}  // namespace api
}  // namespace hydrocoef
