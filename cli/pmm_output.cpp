#include "cli/pmm_output.hpp"

#include <iomanip>
#include <iostream>
#include <numbers>
#include <sstream>

#include "cli/common.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/run.hpp"
#include "src/pmm/imposed_motion.hpp"

namespace hydrocoef::cli {

std::string added_mass_unit(std::size_t i, std::size_t j) {
  const int rotations = int(i >= 3) + int(j >= 3);
  return rotations == 0 ? "kg" : rotations == 1 ? "kg m" : "kg m^2";
}

std::string pmm_damping_unit(std::size_t i, std::size_t j) {
  const int rotations = int(i >= 3) + int(j >= 3);
  return rotations == 0 ? "N s/m" : rotations == 1 ? "N s" : "N m s";
}

namespace {

std::size_t dof_of(const std::string& text, const std::string& option) {
  const auto dof = dof_named(text);
  if (!dof)
    throw InputError(option + " '" + printable_text(text, 40) + "': expected surge, sway, heave, roll, pitch or yaw");
  return *dof;
}

}  // namespace

AddedMassOptions parse_added_mass_options(const std::vector<std::string>& same, const std::vector<std::string>& zero) {
  AddedMassOptions options;
  for (const auto& text : same) {
    const auto [dof, from] = parse_text_assignment(text, "--same");
    options.same[dof_of(dof, "--same")] = dof_of(from, "--same");
  }
  for (const auto& text : zero) options.zero.push_back(dof_of(text, "--zero"));
  return options;
}

namespace {

nlohmann::json optional_json(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json();
}

nlohmann::json matrix_json(const Matrix6& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < 6; ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index j = 0; j < 6; ++j) row.push_back(m(i, j));
    rows.push_back(row);
  }
  return rows;
}

nlohmann::json run_json(const PmmRun& run, const PmmSaved* saved) {
  const PmmRecord& r = run.record;
  nlohmann::json out = {{"path", run.path.string()},
                        {"format", run.format},
                        {"body", r.body},
                        {"velocity_b", r.nu_b},
                        {"motion",
                         {{"dof", std::string(dof_name(r.dof))},
                          {"amplitude", r.amplitude},
                          {"amplitude_unit", r.dof < 3 ? "m" : "rad"},
                          {"omega_rad_s", r.omega},
                          {"period_s", 2.0 * std::numbers::pi / r.omega},
                          {"phase_rad", r.phase},
                          {"source", r.motion_source}}},
                        {"medium", pmm_medium_name(r.medium)},
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
                        {"restoring_unit", r.dof < 3 ? "N/m" : "N m/rad"},
                        {"notes", run.notes},
                        {"components", nlohmann::json::array()}};
  if (saved) out["stored"] = {{"id", saved->id}, {"replaced", saved->replaced}};
  for (const auto& c : r.coefficients) {
    nlohmann::json entry = {{"component", std::string(kForceNames[c.component])},
                            {"mean", c.mean},
                            {"added_mass", c.added_mass},
                            {"added_mass_se", c.added_mass_se},
                            {"added_mass_unit", added_mass_unit(c.component, r.dof)},
                            {"damping", c.damping},
                            {"damping_se", c.damping_se},
                            {"damping_unit", pmm_damping_unit(c.component, r.dof)},
                            {"explained", c.explained},
                            {"harmonics_sin_cos", c.harmonics}};
    if (c.component == r.dof && r.rho && r.displaced_volume && r.dof < 3)
      entry["added_mass_coefficient"] = c.added_mass / (*r.rho * *r.displaced_volume);
    // The cycle-to-cycle spread: standard deviations of s1 and c1 fitted period by period.
    const HarmonicComponent& fit = run.analysis.components[c.component];
    entry["cycle_spread"] = {{"in_phase", fit.in_phase_spread}, {"quadrature", fit.quadrature_spread}};
    out["components"].push_back(entry);
  }
  return out;
}

}  // namespace

void print_pmm_runs(const std::vector<PmmRun>& runs, const std::vector<PmmSaved>& saved, const std::string& database,
                    bool json) {
  if (json) {
    nlohmann::json out = {{"database", saved.empty() ? nlohmann::json() : nlohmann::json(database)},
                          {"runs", nlohmann::json::array()}};
    for (std::size_t k = 0; k < runs.size(); ++k)
      out["runs"].push_back(run_json(runs[k], k < saved.size() ? &saved[k] : nullptr));
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  std::cout << "Forced oscillation (virtual PMM): " << runs.size() << (runs.size() == 1 ? " run" : " runs")
            << " analysed; body axes (x forward, y starboard, z down), F = -M_A x'' - D x' on the body\n";
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const PmmRun& run = runs[k];
    const PmmRecord& r = run.record;
    std::cout << "\n" << escape::one_line(run.path.string()) << "  (body " << escape::one_line(r.body) << ")\n";
    std::cout << "  motion: " << dof_name(r.dof) << " " << significant(r.amplitude, 6) << (r.dof < 3 ? " m" : " rad")
              << " sin(" << significant(r.omega, 6) << " t + " << significant(r.phase, 4) << "), period "
              << significant(2.0 * std::numbers::pi / r.omega, 6) << " s; from " << escape::one_line(r.motion_source)
              << "\n";
    std::cout << "  " << pmm_medium_name(r.medium) << "; window " << significant(r.window_start, 6) << " to "
              << significant(r.window_end, 6) << " s: " << r.periods << " whole periods after " << r.transient_periods
              << " start-up " << (r.transient_periods == 1 ? "period" : "periods") << ", " << r.samples << " samples, "
              << r.harmonics << (r.harmonics == 1 ? " harmonic" : " harmonics") << "\n";
    if (r.restoring)
      std::cout << "  restoring force -C x removed from " << kForceNames[r.dof]
                << " before the fit: C = " << significant(*r.restoring, 6) << (r.dof < 3 ? " N/m" : " N m/rad") << "\n";
    if (r.keulegan_carpenter || r.stokes_number) {
      std::cout << " ";
      if (r.keulegan_carpenter) std::cout << " KC = 2 pi A / D = " << significant(*r.keulegan_carpenter, 4) << ";";
      if (r.stokes_number) std::cout << " Stokes number D^2/(nu T) = " << significant(*r.stokes_number, 4) << ";";
      std::cout << " D = " << significant(*r.size, 6) << " m\n";
    }
    std::cout << "  " << std::left << std::setw(4) << "" << std::right << std::setw(13) << "mean" << std::setw(14)
              << "M_A[.][" + std::string(dof_name(r.dof)) + "]" << std::setw(11) << "+- se" << std::setw(8) << ""
              << std::setw(13) << "D[.][" + std::string(dof_name(r.dof)) + "]" << std::setw(11) << "+- se"
              << std::setw(9) << "" << std::setw(10) << "explained\n";
    for (const auto& c : r.coefficients) {
      std::cout << "  " << std::left << std::setw(4) << kForceNames[c.component] << std::right << std::setw(13)
                << significant(c.mean, 5) << std::setw(14) << significant(c.added_mass, 5) << std::setw(11)
                << significant(c.added_mass_se, 3) << " " << std::left << std::setw(7)
                << added_mass_unit(c.component, r.dof) << std::right << std::setw(13) << significant(c.damping, 5)
                << std::setw(11) << significant(c.damping_se, 3) << " " << std::left << std::setw(8)
                << pmm_damping_unit(c.component, r.dof) << std::right << std::setw(9) << std::fixed
                << std::setprecision(2) << 100.0 * c.explained << " %\n"
                << std::defaultfloat << std::setprecision(6);
      if (c.component == r.dof && r.rho && r.displaced_volume && r.dof < 3)
        std::cout << "       added-mass coefficient M_A / (rho V) = "
                  << significant(c.added_mass / (*r.rho * *r.displaced_volume), 5)
                  << " (rho V = " << significant(*r.rho * *r.displaced_volume, 5) << " kg)\n";
    }
    for (const auto& note : run.notes) std::cout << "  note: " << escape::one_line(note) << "\n";
    if (k < saved.size())
      std::cout << "  stored as pmm run " << saved[k].id
                << (saved[k].replaced ? " (replacing the earlier analysis)" : "") << "\n";
  }
  if (!saved.empty()) std::cout << "\nStored in " << escape::one_line(database) << "\n";
}

void print_pmm_records(const std::vector<PmmRecord>& records, bool json) {
  const auto inline_entry = [](const PmmRecord& r) -> const PmmCoefficient* {
    for (const auto& c : r.coefficients)
      if (c.component == r.dof) return &c;
    return nullptr;
  };
  if (json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& r : records) {
      const PmmCoefficient* own = inline_entry(r);
      out.push_back({{"id", r.id},
                     {"body", r.body},
                     {"dof", std::string(dof_name(r.dof))},
                     {"amplitude", r.amplitude},
                     {"amplitude_unit", r.dof < 3 ? "m" : "rad"},
                     {"period_s", 2.0 * std::numbers::pi / r.omega},
                     {"omega_rad_s", r.omega},
                     {"medium", pmm_medium_name(r.medium)},
                     {"restoring", optional_json(r.restoring)},
                     {"added_mass", own ? nlohmann::json(own->added_mass) : nlohmann::json()},
                     {"damping", own ? nlohmann::json(own->damping) : nlohmann::json()},
                     {"source_path", r.source_path},
                     {"created_at", r.created_at}});
    }
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  if (records.empty()) {
    std::cout << "No forced-oscillation runs stored (hydrocoef pmm stores them)\n";
    return;
  }
  std::cout << records.size() << (records.size() == 1 ? " forced-oscillation run" : " forced-oscillation runs")
            << " (in-line M_A and D of the moved DOF; body axes, F = -M_A x'' - D x' on the body):\n";
  for (const auto& r : records) {
    const PmmCoefficient* own = inline_entry(r);
    std::cout << "  " << std::setw(5) << r.id << "  " << escape::one_line(r.body) << "  " << dof_name(r.dof) << " A "
              << significant(r.amplitude, 6) << (r.dof < 3 ? " m" : " rad") << ", T "
              << significant(2.0 * std::numbers::pi / r.omega, 6) << " s";
    if (own)
      std::cout << ": M_A " << significant(own->added_mass, 5) << " " << added_mass_unit(r.dof, r.dof) << ", D "
                << significant(own->damping, 5) << " " << pmm_damping_unit(r.dof, r.dof);
    if (r.restoring) std::cout << ", restoring " << significant(*r.restoring, 6) << (r.dof < 3 ? " N/m" : " N m/rad");
    std::cout << "  " << escape::one_line(r.source_path) << "\n";
  }
}

void print_pmm_deleted(const std::vector<PmmDeleted>& deleted, const std::string& database, bool json) {
  if (json) {
    nlohmann::json out = {{"database", database}, {"deleted", nlohmann::json::array()}};
    for (const auto& d : deleted)
      out["deleted"].push_back(
          {{"id", d.id},
           {"body", d.body},
           {"dof", d.dof >= 0 && d.dof < 6 ? nlohmann::json(std::string(dof_name(static_cast<std::size_t>(d.dof))))
                                           : nlohmann::json()},
           {"source_path", d.source_path}});
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  std::cout << "deleted " << deleted.size()
            << (deleted.size() == 1 ? " forced-oscillation run" : " forced-oscillation runs") << " from "
            << escape::one_line(database) << ":\n";
  for (const auto& d : deleted)
    std::cout << "  " << d.id << "  " << escape::one_line(d.body) << "  "
              << (d.dof >= 0 && d.dof < 6 ? dof_name(static_cast<std::size_t>(d.dof)) : "?") << "  "
              << escape::one_line(d.source_path) << "\n";
}

void print_added_mass(const AddedMassAssembly& a, bool json) {
  if (json) {
    nlohmann::json entries = nlohmann::json::array();
    for (std::size_t i = 0; i < 6; ++i)
      for (std::size_t j = 0; j < 6; ++j) {
        const PmmEntry& e = a.measured[i][j];
        if (!e.runs) continue;
        entries.push_back({{"row", std::string(dof_name(i))},
                           {"column", std::string(dof_name(j))},
                           {"runs", e.runs},
                           {"added_mass", e.added_mass},
                           {"added_mass_se", e.added_mass_se},
                           {"added_mass_spread", e.added_mass_spread},
                           {"damping", e.damping},
                           {"damping_se", e.damping_se},
                           {"omega_rad_s", {e.omega_min, e.omega_max}},
                           {"keulegan_carpenter", e.kc_min ? nlohmann::json{*e.kc_min, *e.kc_max} : nlohmann::json()},
                           {"pmm_runs", e.record_ids}});
      }
    nlohmann::json quadratic = nlohmann::json::array();
    for (const auto& q : a.quadratic)
      quadratic.push_back({{"dof", std::string(dof_name(q.dof))},
                           {"omega_rad_s", q.omega},
                           {"amplitudes", q.amplitudes},
                           {"linear", q.fit.linear},
                           {"linear_se", q.fit.linear_se},
                           {"quadratic", q.fit.quadratic},
                           {"quadratic_se", q.fit.quadratic_se}});
    nlohmann::json frequencies = nlohmann::json::array();
    for (const auto& f : a.by_frequency)
      frequencies.push_back({{"dof", std::string(dof_name(f.dof))},
                             {"omega_rad_s", f.omega},
                             {"period_s", 2.0 * std::numbers::pi / f.omega},
                             {"runs", f.runs},
                             {"amplitudes", {f.amplitude_min, f.amplitude_max}},
                             {"added_mass", f.added_mass},
                             {"added_mass_se", f.added_mass_se},
                             {"damping", f.damping},
                             {"damping_se", f.damping_se},
                             {"used", f.omega == a.omega}});
    const nlohmann::json out = {{"body", a.body},
                                {"period_s", 2.0 * std::numbers::pi / a.omega},
                                {"omega_rad_s", a.omega},
                                {"records", a.records},
                                {"other_frequency_records", a.other_frequency_records},
                                {"by_frequency", frequencies},
                                {"added_mass_b", matrix_json(a.added_mass)},
                                {"added_mass_se", matrix_json(a.added_mass_se)},
                                {"damping_b", matrix_json(a.damping)},
                                {"damping_se", matrix_json(a.damping_se)},
                                {"entries", entries},
                                {"missing", a.missing},
                                {"notes", a.notes},
                                {"positive_definite", a.positive_definite},
                                {"smallest_eigenvalue", a.smallest_eigenvalue},
                                {"quadratic_damping", quadratic}};
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  std::cout << "Added mass of body " << escape::one_line(a.body) << " from " << a.records
            << (a.records == 1 ? " forced-oscillation run" : " forced-oscillation runs") << " at period "
            << significant(2.0 * std::numbers::pi / a.omega, 6) << " s (omega " << significant(a.omega, 6)
            << " rad/s; body axes; kg, kg m, kg m^2; symmetric)";
  if (a.other_frequency_records)
    std::cout << "; " << a.other_frequency_records << (a.other_frequency_records == 1 ? " run" : " runs")
              << " at other periods left out";
  std::cout << "\n";
  const auto print_matrix = [](const Matrix6& m, const Matrix6& se) {
    std::cout << std::setw(8) << "";
    for (std::size_t j = 0; j < 6; ++j) std::cout << std::setw(24) << dof_name(j);
    std::cout << "\n";
    for (std::size_t i = 0; i < 6; ++i) {
      std::cout << std::left << std::setw(8) << dof_name(i) << std::right;
      for (std::size_t j = 0; j < 6; ++j) {
        const double v = m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
        const double s = se(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
        std::cout << ' ' << std::setw(23) << (significant(v, 5) + (s > 0.0 ? " +- " + significant(s, 2) : ""));
      }
      std::cout << "\n";
    }
  };
  print_matrix(a.added_mass, a.added_mass_se);
  std::cout << (a.positive_definite ? "positive definite" : "NOT positive definite (printed: --allow-indefinite)")
            << " over the DOFs with a non-zero diagonal (smallest eigenvalue " << significant(a.smallest_eigenvalue, 5)
            << ")\n";
  std::cout << "\nLinear damping D (N s/m, N s, N m s; as measured):\n";
  print_matrix(a.damping, a.damping_se);
  std::cout << "\nEntries measured:\n";
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = 0; j < 6; ++j) {
      const PmmEntry& e = a.measured[i][j];
      if (!e.runs || (i != j && e.added_mass == 0.0)) continue;
      std::cout << "  " << std::left << std::setw(20) << added_mass_entry_name(i, j) << std::right << e.runs
                << (e.runs == 1 ? " run" : " runs") << ", omega " << significant(e.omega_min, 4);
      if (e.omega_max != e.omega_min) std::cout << ".." << significant(e.omega_max, 4);
      std::cout << " rad/s";
      if (e.kc_min) {
        std::cout << ", KC " << significant(*e.kc_min, 3);
        if (*e.kc_max != *e.kc_min) std::cout << ".." << significant(*e.kc_max, 3);
      }
      if (e.runs > 1) std::cout << ", spread " << significant(e.added_mass_spread, 3) << " " << added_mass_unit(i, j);
      std::cout << "\n";
    }
  std::cout << "\nIn-line added mass and damping by frequency (runs of one DOF and period combined; * the period "
               "used above):\n";
  for (const auto& f : a.by_frequency)
    std::cout << (f.omega == a.omega ? "* " : "  ") << std::left << std::setw(6) << dof_name(f.dof) << std::right
              << " T " << significant(2.0 * std::numbers::pi / f.omega, 6) << " s (omega " << significant(f.omega, 4)
              << " rad/s), " << f.runs << (f.runs == 1 ? " run" : " runs") << ", A " << significant(f.amplitude_min, 4)
              << (f.amplitude_max != f.amplitude_min ? ".." + significant(f.amplitude_max, 4) : std::string())
              << (f.dof < 3 ? " m" : " rad") << ": M_A = " << significant(f.added_mass, 5) << " +- "
              << significant(f.added_mass_se, 2) << " " << added_mass_unit(f.dof, f.dof)
              << ", D = " << significant(f.damping, 5) << " +- " << significant(f.damping_se, 2) << " "
              << pmm_damping_unit(f.dof, f.dof) << "\n";
  if (!a.quadratic.empty()) {
    std::cout << "\nQuadratic damping from the amplitude dependence, D_eq(A) = b1 + b2 (8/(3 pi)) A omega:\n";
    for (const auto& q : a.quadratic)
      std::cout << "  " << std::left << std::setw(6) << dof_name(q.dof) << std::right << " omega "
                << significant(q.omega, 4) << " rad/s, " << q.amplitudes.size()
                << " runs: b1 = " << significant(q.fit.linear, 5) << " +- " << significant(q.fit.linear_se, 2) << " "
                << pmm_damping_unit(q.dof, q.dof) << ", b2 = " << significant(q.fit.quadratic, 5) << " +- "
                << significant(q.fit.quadratic_se, 2) << (q.dof < 3 ? " N s^2/m^2" : " N m s^2") << "\n";
  }
  for (const auto& m : a.missing) std::cout << "missing: " << escape::one_line(m) << "\n";
  for (const auto& n : a.notes) std::cout << "note: " << escape::one_line(n) << "\n";
}

}  // namespace hydrocoef::cli
