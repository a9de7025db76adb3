#include "src/pmm/added_mass_assembly.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numbers>
#include <sstream>

#include "src/core/dense_decompositions.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/pmm/imposed_motion.hpp"

namespace hydrocoef {

std::string added_mass_entry_name(std::size_t i, std::size_t j) {
  return "M_A[" + std::string(dof_name(i)) + "][" + std::string(dof_name(j)) + "]";
}

namespace {

std::string four_digits(double value) {
  std::ostringstream text;
  text << std::setprecision(4) << value;
  return text.str();
}

bool same_frequency(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(a, b); }

/// The frequency of `frequencies` that `omega` equals.
double frequency_of(const std::vector<double>& frequencies, double omega) {
  for (const double f : frequencies)
    if (same_frequency(f, omega)) return f;
  return omega;
}

std::string period_list(const std::string& body, const std::vector<PmmRecord>& records,
                        const std::vector<double>& frequencies) {
  std::string out;
  for (const double f : frequencies) {
    std::size_t runs = 0;
    for (const auto& r : records) runs += r.body == body && same_frequency(r.omega, f) ? 1 : 0;
    out += (out.empty() ? "" : ", ") + shortest_number(2.0 * std::numbers::pi / f) + " s (" + std::to_string(runs) +
           (runs == 1 ? " run)" : " runs)");
  }
  return out;
}

}  // namespace

std::pair<double, double> combine_pmm_estimates(const std::vector<double>& values, const std::vector<double>& se) {
  const std::size_t n = values.size();
  if (n == 1) return {values[0], se[0]};
  const bool weighted = std::all_of(se.begin(), se.end(), [](double s) { return s > 0.0; });
  if (weighted) {
    double sw = 0.0, swx = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double w = 1.0 / (se[k] * se[k]);
      sw += w;
      swx += w * values[k];
    }
    const double mean = swx / sw;
    double chi2 = 0.0;
    for (std::size_t k = 0; k < n; ++k) chi2 += (values[k] - mean) * (values[k] - mean) / (se[k] * se[k]);
    const double birge = std::max(1.0, chi2 / static_cast<double>(n - 1));
    return {mean, std::sqrt(birge / sw)};
  }
  double mean = 0.0;
  for (const double v : values) mean += v / static_cast<double>(n);
  double ss = 0.0;
  for (const double v : values) ss += (v - mean) * (v - mean);
  return {mean, std::sqrt(ss / static_cast<double>(n - 1) / static_cast<double>(n))};
}

std::vector<double> pmm_frequencies(const std::string& body, const std::vector<PmmRecord>& records) {
  std::vector<double> out;
  for (const auto& r : records)
    if (r.body == body && std::none_of(out.begin(), out.end(), [&](double f) { return same_frequency(f, r.omega); }))
      out.push_back(r.omega);
  std::sort(out.begin(), out.end());
  return out;
}

AddedMassOptions added_mass_options(const std::map<std::string, std::string>& same,
                                    const std::vector<std::string>& zero, std::optional<double> period) {
  const auto dof_of = [](const std::string& text, const char* option) {
    const auto dof = dof_named(text);
    if (!dof)
      throw InputError(std::string(option) + " '" + printable_text(text, 40) +
                       "': expected surge, sway, heave, roll, pitch or yaw");
    return *dof;
  };
  AddedMassOptions out;
  for (const auto& [dof, from] : same) out.same[dof_of(dof, "--same")] = dof_of(from, "--same");
  for (const auto& dof : zero) out.zero.push_back(dof_of(dof, "--zero"));
  out.period = period;
  return out;
}

AddedMassAssembly assemble_added_mass(const std::string& body, const std::vector<PmmRecord>& records,
                                      const AddedMassOptions& options) {
  AddedMassAssembly out;
  out.body = body;
  const std::vector<double> frequencies = pmm_frequencies(body, records);
  if (frequencies.empty())
    throw InputError("body '" + printable_text(body, 80) +
                     "' has no stored forced-oscillation runs; expected some (hydrocoef pmm ... --body BODY)");
  if (options.period) {
    const double period = *options.period;
    const auto chosen = std::find_if(frequencies.begin(), frequencies.end(), [&](double f) {
      return std::abs(2.0 * std::numbers::pi / f - period) <= 1e-9 * period;
    });
    if (!(std::isfinite(period) && period > 0.0) || chosen == frequencies.end())
      throw InputError("period " + shortest_number(period) + " s: body '" + printable_text(body, 80) +
                       "' has no run at it; expected one of " + period_list(body, records, frequencies));
    out.omega = *chosen;
  } else if (frequencies.size() > 1) {
    throw InputError("body '" + printable_text(body, 80) + "' has forced-oscillation runs at " +
                     std::to_string(frequencies.size()) + " periods, " + period_list(body, records, frequencies) +
                     ", and the added mass and damping depend on the frequency; expected the period to use "
                     "(added-mass --period T; export-gazebo --added-mass-period T; a vehicle's added_mass.period)");
  } else {
    out.omega = frequencies.front();
  }
  struct Samples {
    std::vector<double> m, m_se, d, d_se;
  };
  std::array<std::array<Samples, 6>, 6> samples;
  // Every frequency's runs, by DOF and frequency: the in-line entries of each
  // and the quadratic damping of each.
  std::map<std::pair<std::size_t, double>, std::vector<const PmmRecord*>> by_frequency;
  for (const auto& record : records) {
    if (record.body != body) continue;
    by_frequency[{record.dof, frequency_of(frequencies, record.omega)}].push_back(&record);
    if (!same_frequency(record.omega, out.omega)) {
      ++out.other_frequency_records;
      continue;
    }
    ++out.records;
    const std::size_t j = record.dof;
    for (const auto& c : record.coefficients) {
      const std::size_t i = c.component;
      auto& s = samples[i][j];
      s.m.push_back(c.added_mass);
      s.m_se.push_back(c.added_mass_se);
      s.d.push_back(c.damping);
      s.d_se.push_back(c.damping_se);
      PmmEntry& e = out.measured[i][j];
      e.omega_min = e.runs == 0 ? record.omega : std::min(e.omega_min, record.omega);
      e.omega_max = e.runs == 0 ? record.omega : std::max(e.omega_max, record.omega);
      if (record.keulegan_carpenter) {
        e.kc_min = std::min(e.kc_min.value_or(*record.keulegan_carpenter), *record.keulegan_carpenter);
        e.kc_max = std::max(e.kc_max.value_or(*record.keulegan_carpenter), *record.keulegan_carpenter);
      }
      e.record_ids.push_back(record.id);
      ++e.runs;
    }
  }
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = 0; j < 6; ++j) {
      const auto& s = samples[i][j];
      if (s.m.empty()) continue;
      PmmEntry& e = out.measured[i][j];
      std::tie(e.added_mass, e.added_mass_se) = combine_pmm_estimates(s.m, s.m_se);
      std::tie(e.damping, e.damping_se) = combine_pmm_estimates(s.d, s.d_se);
      double lo = s.m.front(), hi = s.m.front();
      for (const double v : s.m) lo = std::min(lo, v), hi = std::max(hi, v);
      e.added_mass_spread = hi - lo;
      out.damping(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = e.damping;
      out.damping_se(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = e.damping_se;
    }
  // Columns stated by the caller.
  std::array<bool, 6> measured_column{};
  for (std::size_t j = 0; j < 6; ++j)
    for (std::size_t i = 0; i < 6; ++i) measured_column[j] = measured_column[j] || out.measured[i][j].runs > 0;
  for (const std::size_t dof : options.zero)
    if (measured_column[dof])
      throw InputError("zero " + std::string(dof_name(dof)) +
                       ": the runs measure that column; expected a DOF no run "
                       "moves");
  for (const auto& [dof, from] : options.same) {
    if (measured_column[dof])
      throw InputError("same " + std::string(dof_name(dof)) + "=" + std::string(dof_name(from)) +
                       ": the runs measure " + std::string(dof_name(dof)) + " themselves; expected a DOF no run moves");
    if (!measured_column[from])
      throw InputError("same " + std::string(dof_name(dof)) + "=" + std::string(dof_name(from)) + ": no run moves " +
                       std::string(dof_name(from)) + "; expected a measured DOF");
  }
  // Symmetric M_A from the measured entries.
  const auto at = [](Matrix6& m, std::size_t i, std::size_t j) -> double& {
    return m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
  };
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = i; j < 6; ++j) {
      const PmmEntry& a = out.measured[i][j];
      const PmmEntry& b = out.measured[j][i];
      if (a.runs && b.runs && i != j) {
        const double value = 0.5 * (a.added_mass + b.added_mass);
        const double se = 0.5 * std::hypot(a.added_mass_se, b.added_mass_se);
        at(out.added_mass, i, j) = at(out.added_mass, j, i) = value;
        at(out.added_mass_se, i, j) = at(out.added_mass_se, j, i) = se;
        const double difference = std::abs(a.added_mass - b.added_mass);
        const double scale = std::hypot(a.added_mass_se, b.added_mass_se);
        if (scale > 0.0 && difference > 3.0 * scale)
          out.notes.push_back(added_mass_entry_name(i, j) + " = " + four_digits(a.added_mass) + " and " +
                              added_mass_entry_name(j, i) + " = " + four_digits(b.added_mass) + " differ by " +
                              four_digits(difference / scale) + " standard errors; their mean is used");
        out.known[i][j] = out.known[j][i] = true;
      } else if (a.runs || b.runs) {
        const PmmEntry& e = a.runs ? a : b;
        at(out.added_mass, i, j) = at(out.added_mass, j, i) = e.added_mass;
        at(out.added_mass_se, i, j) = at(out.added_mass_se, j, i) = e.added_mass_se;
        out.known[i][j] = out.known[j][i] = true;
        if (i != j)
          out.notes.push_back(
              a.runs ? added_mass_entry_name(j, i) + " taken from " + added_mass_entry_name(i, j) + " (symmetry)"
                     : added_mass_entry_name(i, j) + " taken from " + added_mass_entry_name(j, i) + " (symmetry)");
      }
    }
  // Columns (and rows) copied from another DOF, and zero columns.
  for (const auto& [dof, from] : options.same) {
    at(out.added_mass, dof, dof) = at(out.added_mass, from, from);
    at(out.added_mass_se, dof, dof) = at(out.added_mass_se, from, from);
    for (std::size_t k = 0; k < 6; ++k) out.known[k][dof] = out.known[dof][k] = true;
    out.notes.push_back(added_mass_entry_name(dof, dof) + " taken from " + added_mass_entry_name(from, from) +
                        " (stated: same " + std::string(dof_name(dof)) + "=" + std::string(dof_name(from)) + ")");
  }
  for (const std::size_t dof : options.zero)
    for (std::size_t k = 0; k < 6; ++k) out.known[k][dof] = out.known[dof][k] = true;
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = i; j < 6; ++j)
      if (!out.known[i][j])
        out.missing.push_back(added_mass_entry_name(i, j) + (i == j ? " (no " + std::string(dof_name(j)) + " run)"
                                                                    : " (no " + std::string(dof_name(j)) + " or " +
                                                                          std::string(dof_name(i)) + " run gives it)"));
  // Positive definite over the DOFs with a non-zero diagonal, and, once no
  // entry is missing, no negative eigenvalue beyond round-off in the whole
  // matrix (a DOF stated zero whose row holds measured couplings of weight
  // makes it indefinite; a missing diagonal beside measured couplings says
  // nothing yet).
  std::vector<Eigen::Index> dofs;
  for (Eigen::Index k = 0; k < 6; ++k)
    if (out.added_mass(k, k) != 0.0) dofs.push_back(k);
  if (!dofs.empty()) {
    Eigen::MatrixXd sub(static_cast<Eigen::Index>(dofs.size()), static_cast<Eigen::Index>(dofs.size()));
    for (std::size_t a = 0; a < dofs.size(); ++a)
      for (std::size_t b = 0; b < dofs.size(); ++b)
        sub(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) = out.added_mass(dofs[a], dofs[b]);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen = symmetric_eigen(sub, Eigen::EigenvaluesOnly);
    out.smallest_eigenvalue = eigen.eigenvalues().minCoeff();
    const Eigen::SelfAdjointEigenSolver<Matrix6> whole(out.added_mass, Eigen::EigenvaluesOnly);
    const double scale = out.added_mass.cwiseAbs().maxCoeff();
    out.positive_definite =
        out.smallest_eigenvalue > 0.0 && (!out.missing.empty() || whole.eigenvalues().minCoeff() >= -1e-9 * scale);
    if (out.smallest_eigenvalue > 0.0 && !out.positive_definite)
      out.notes.push_back("the whole matrix has eigenvalue " + four_digits(whole.eigenvalues().minCoeff()) +
                          ": a DOF with no added mass of its own has couplings to the others");
  }
  // The in-line entries at each frequency, and the quadratic damping from
  // the amplitude dependence at one frequency.
  for (const auto& [dof_omega, group] : by_frequency) {
    FrequencyRow frequency;
    frequency.dof = dof_omega.first;
    frequency.omega = dof_omega.second;
    std::vector<double> m, m_se, d, d_se;
    for (const PmmRecord* record : group)
      for (const auto& c : record->coefficients)
        if (c.component == record->dof) {
          frequency.amplitude_min =
              frequency.runs == 0 ? record->amplitude : std::min(frequency.amplitude_min, record->amplitude);
          frequency.amplitude_max = std::max(frequency.amplitude_max, record->amplitude);
          ++frequency.runs;
          m.push_back(c.added_mass), m_se.push_back(c.added_mass_se);
          d.push_back(c.damping), d_se.push_back(c.damping_se);
        }
    if (frequency.runs > 0) {
      std::tie(frequency.added_mass, frequency.added_mass_se) = combine_pmm_estimates(m, m_se);
      std::tie(frequency.damping, frequency.damping_se) = combine_pmm_estimates(d, d_se);
      out.by_frequency.push_back(frequency);
    }
  }
  for (const auto& [dof_omega, group] : by_frequency) {
    std::vector<double> amplitudes, damping, se;
    for (const PmmRecord* record : group)
      for (const auto& c : record->coefficients)
        if (c.component == record->dof) {
          amplitudes.push_back(record->amplitude);
          damping.push_back(c.damping);
          se.push_back(c.damping_se);
        }
    std::vector<double> distinct = amplitudes;
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    if (distinct.size() < 2) continue;
    QuadraticDampingRow row;
    row.dof = dof_omega.first;
    row.omega = dof_omega.second;
    row.amplitudes = amplitudes;
    row.fit = fit_quadratic_damping(amplitudes, row.omega, damping, se);
    out.quadratic.push_back(std::move(row));
  }
  return out;
}

}  // namespace hydrocoef
