#include "src/pmm/harmonic_analysis.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "src/core/dense_decompositions.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/core/run.hpp"

namespace hydrocoef {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// sin and cos of the motion's phase at every sample, and the time each
/// sample stands for (half the steps to its neighbours), computed once.
struct Phases {
  std::vector<double> sin, cos, weight;
};

Phases phases_of(std::span<const double> t, const HarmonicMotion& motion) {
  Phases out;
  out.sin.resize(t.size());
  out.cos.resize(t.size());
  out.weight.resize(t.size());
  for (std::size_t i = 0; i < t.size(); ++i)
    out.weight[i] = 0.5 * ((i + 1 == t.size() ? t[i] : t[i + 1]) - (i == 0 ? t[i] : t[i - 1]));
  // A CFD history steps by a small fraction of a period: each sample's phase
  // is the previous one turned by the step's angle d (sin and cos of d by
  // their Taylor series to d^9, exact to round-off for |d| < 0.05), and
  // computed afresh every 64 samples and after large steps, so round-off
  // cannot accumulate. Four times faster than sin and cos of every sample.
  constexpr std::size_t kResync = 64;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double d = i == 0 ? 0.0 : motion.omega * (t[i] - t[i - 1]);
    if (i % kResync == 0 || !(std::abs(d) < 0.05)) {
      const double theta = motion.omega * t[i] + motion.phase;
      out.sin[i] = std::sin(theta);
      out.cos[i] = std::cos(theta);
      continue;
    }
    const double d2 = d * d;
    const double sin_d = d * (1.0 - d2 / 6.0 * (1.0 - d2 / 20.0 * (1.0 - d2 / 42.0 * (1.0 - d2 / 72.0))));
    const double cos_d = 1.0 - d2 / 2.0 * (1.0 - d2 / 12.0 * (1.0 - d2 / 30.0 * (1.0 - d2 / 56.0 * (1.0 - d2 / 90.0))));
    out.sin[i] = out.sin[i - 1] * cos_d + out.cos[i - 1] * sin_d;
    out.cos[i] = out.cos[i - 1] * cos_d - out.sin[i - 1] * sin_d;
  }
  return out;
}

/// The basis 1, sin θ, cos θ, sin 2θ, cos 2θ, ... from sin θ and cos θ, by
/// the angle-addition recurrence.
inline void basis(double s1, double c1, int harmonics, double* out) {
  out[0] = 1.0;
  double s = s1, c = c1;
  for (int k = 1; k <= harmonics; ++k) {
    out[2 * k - 1] = s;
    out[2 * k] = c;
    const double next_s = s * c1 + c * s1;
    c = c * c1 - s * s1;
    s = next_s;
  }
}

constexpr int kMaxBasis = 21;  // 10 harmonics

/// The share of [lo, hi] that sample i stands for: half the steps to its
/// neighbours, clipped to the window.
inline double sample_weight(std::span<const double> t, std::size_t i, double lo, double hi) {
  const double left = i == 0 ? t[i] : 0.5 * (t[i - 1] + t[i]);
  const double right = i + 1 == t.size() ? t[i] : 0.5 * (t[i] + t[i + 1]);
  return std::max(0.0, std::min(right, hi) - std::max(left, lo));
}

/// Weighted least squares over the window [lo, hi] on `harmonics`
/// harmonics: the coefficients of each present component (mean, s1, c1,
/// s2, c2, ...) and, if asked, the share of the variance they explain.
struct WindowFit {
  std::array<Eigen::VectorXd, 6> coefficients;
  std::array<double, 6> explained{};
  Eigen::MatrixXd normal;  ///< the weighted normal matrix of the basis
};

WindowFit fit_window(std::span<const double> t, const Phases& phases,
                     const std::array<std::span<const double>, 6>& forces, int harmonics, double lo, double hi,
                     bool explained) {
  const int K = 2 * harmonics + 1;
  const std::size_t first = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), lo) - t.begin());
  const std::size_t last = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), hi) - t.begin());
  // Samples just outside the window carry the part of their interval inside it.
  const std::size_t from = first > 0 ? first - 1 : 0, to = std::min(t.size(), last + 1);
  std::array<std::size_t, 6> present{};
  std::size_t n_present = 0;
  for (std::size_t c = 0; c < 6; ++c)
    if (!forces[c].empty()) present[n_present++] = c;
  double normal[kMaxBasis][kMaxBasis] = {};
  double rhs[6][kMaxBasis] = {};
  double squares[6] = {};  // sum of w f^2, for the explained variance
  // Only the samples at the window's ends stand for time outside it.
  const auto weight = [&](std::size_t i) {
    return i <= from + 1 || i + 2 >= to ? sample_weight(t, i, lo, hi) : phases.weight[i];
  };
  if (K == 3) {
    // The first harmonic alone (every period-by-period fit): sums in
    // registers rather than in the arrays.
    double n00 = 0, n10 = 0, n11 = 0, n20 = 0, n21 = 0, n22 = 0;
    for (std::size_t i = from; i < to; ++i) {
      const double w = weight(i), s1 = phases.sin[i], c1 = phases.cos[i];
      n00 += w, n10 += w * s1, n11 += w * s1 * s1, n20 += w * c1, n21 += w * c1 * s1, n22 += w * c1 * c1;
    }
    normal[0][0] = n00, normal[1][0] = n10, normal[1][1] = n11, normal[2][0] = n20, normal[2][1] = n21,
    normal[2][2] = n22;
    for (std::size_t k = 0; k < n_present; ++k) {
      const double* f = forces[present[k]].data();
      double r0 = 0, r1 = 0, r2 = 0, ff = 0;
      for (std::size_t i = from; i < to; ++i) {
        const double wf = weight(i) * f[i];
        r0 += wf, r1 += wf * phases.sin[i], r2 += wf * phases.cos[i], ff += wf * f[i];
      }
      rhs[k][0] = r0, rhs[k][1] = r1, rhs[k][2] = r2, squares[k] = ff;
    }
  } else {
    double b[kMaxBasis];
    for (std::size_t i = from; i < to; ++i) {
      const double w = weight(i);
      if (w <= 0.0) continue;
      basis(phases.sin[i], phases.cos[i], harmonics, b);
      for (int r = 0; r < K; ++r) {
        const double wb = w * b[r];
        for (int q = 0; q <= r; ++q) normal[r][q] += wb * b[q];
        for (std::size_t k = 0; k < n_present; ++k) rhs[k][r] += wb * forces[present[k]][i];
      }
      for (std::size_t k = 0; k < n_present; ++k) squares[k] += w * forces[present[k]][i] * forces[present[k]][i];
    }
  }
  Eigen::MatrixXd A(K, K);
  for (int r = 0; r < K; ++r)
    for (int q = 0; q <= r; ++q) A(r, q) = A(q, r) = normal[r][q];
  WindowFit out;
  out.normal = A;
  if (n_present == 0) return out;
  const Eigen::LDLT<Eigen::MatrixXd> solver(A);
  for (std::size_t k = 0; k < n_present; ++k)
    out.coefficients[present[k]] = solver.solve(Eigen::Map<const Eigen::VectorXd>(rhs[k], K));
  if (!explained) return out;
  // At the least-squares solution A c = rhs, so the weighted residual sum is
  // sum w f^2 - c . rhs and the total sum about the mean sum w f^2 - (sum w f)^2 / sum w.
  for (std::size_t k = 0; k < n_present; ++k) {
    const std::size_t c = present[k];
    const double fitted = out.coefficients[c].dot(Eigen::Map<const Eigen::VectorXd>(rhs[k], K));
    const double residual = std::max(0.0, squares[k] - fitted);
    const double total = std::max(0.0, squares[k] - rhs[k][0] * rhs[k][0] / normal[0][0]);
    out.explained[c] = total > 0.0 ? std::max(0.0, 1.0 - residual / total) : 1.0;
  }
  return out;
}

/// MSER: the number of leading values whose removal minimises the squared
/// standard error of the mean of the rest, searched over the first half.
std::size_t mser_truncation(const std::vector<double>& x) {
  const std::size_t n = x.size();
  std::size_t best = 0;
  double best_value = INFINITY;
  // Suffix sums, so each candidate costs O(1).
  std::vector<double> sum(n + 1, 0.0), squares(n + 1, 0.0);
  for (std::size_t i = n; i-- > 0;) {
    sum[i] = sum[i + 1] + x[i];
    squares[i] = squares[i + 1] + x[i] * x[i];
  }
  for (std::size_t d = 0; d <= n / 2; ++d) {
    const double m = static_cast<double>(n - d);
    const double variance_sum = std::max(0.0, squares[d] - sum[d] * sum[d] / m);
    const double value = variance_sum / (m * m);
    if (value < best_value * (1.0 - 1e-12)) best_value = value, best = d;
  }
  return best;
}

}  // namespace

double HarmonicMotion::period() const { return kTwoPi / omega; }
double HarmonicMotion::displacement(double t) const { return amplitude * std::sin(omega * t + phase); }
double HarmonicMotion::velocity(double t) const { return amplitude * omega * std::cos(omega * t + phase); }
double HarmonicMotion::acceleration(double t) const { return -amplitude * omega * omega * std::sin(omega * t + phase); }

HarmonicAnalysis analyse_forced_oscillation(std::span<const double> t,
                                            const std::array<std::span<const double>, 6>& forces,
                                            const HarmonicMotion& motion, const HarmonicFitOptions& options) {
  if (motion.dof > 5) throw InputError("forced oscillation: degree of freedom must be 0..5 (surge..yaw)");
  if (!(motion.amplitude > 0.0) || !std::isfinite(motion.amplitude) || !(motion.omega > 0.0) ||
      !std::isfinite(motion.omega) || !std::isfinite(motion.phase))
    throw InputError("forced oscillation: expected a finite positive amplitude and frequency");
  if (options.harmonics < 1 || options.harmonics > 10)
    throw InputError("forced oscillation: harmonics must be 1 to 10");
  // M_A and D divide by A w^2 and A w: both must be ordinary numbers (an
  // amplitude of 5e-324 made them 0 and M_A infinite, 1e308 made A w^2
  // infinite and M_A 0).
  for (const double scale : {motion.amplitude * motion.omega, motion.amplitude * motion.omega * motion.omega})
    if (!std::isnormal(scale) || !std::isfinite(scale))
      throw InputError("forced oscillation: amplitude " + shortest_number(motion.amplitude) + " and frequency " +
                       shortest_number(motion.omega) + " rad/s give a velocity amplitude A w = " +
                       shortest_number(motion.amplitude * motion.omega) + " and an acceleration amplitude A w^2 = " +
                       shortest_number(motion.amplitude * motion.omega * motion.omega) +
                       "; expected both finite and well above zero");
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i])) throw InputError("forced oscillation: time " + std::to_string(i + 1) + " is not finite");
    if (i > 0 && !(t[i] > t[i - 1]))
      throw InputError("forced oscillation: times must increase (sample " + std::to_string(i + 1) + ")");
  }
  bool any = false;
  for (std::size_t c = 0; c < 6; ++c) {
    if (forces[c].empty()) continue;
    any = true;
    if (forces[c].size() != t.size())
      throw InputError("forced oscillation: component " + std::to_string(c) + " has " +
                       std::to_string(forces[c].size()) + " samples for " + std::to_string(t.size()) + " times");
    for (std::size_t i = 0; i < t.size(); ++i)
      if (!std::isfinite(forces[c][i]))
        throw InputError("forced oscillation: component " + std::to_string(c) + " sample " + std::to_string(i + 1) +
                         " is not finite");
  }
  if (!any || t.size() < 8) throw InputError("forced oscillation: expected a force history of at least 8 samples");

  // Whole periods: phase θ = ω t + φ crossing multiples of 2π. A period
  // must span a few sampling steps, which also bounds the count of periods
  // by the count of samples before anything is sized by it (omega 1e20 made
  // it 10^19: a conversion out of range, then an empty vector's back()).
  const double period = motion.period();
  const double mean_step = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  if (!(period >= kMinStepsPerPeriod * mean_step)) {
    const auto rounded = [](double x) {  // the steps' sum rounds: 0.01 s, not 0.009999999999999832 s
      char text[32];
      std::snprintf(text, sizeof text, "%.4g", x);
      return std::string(text);
    };
    throw InputError("forced oscillation: the period " + shortest_number(period) + " s is shorter than " +
                     std::to_string(static_cast<int>(kMinStepsPerPeriod)) + " sampling steps (the history steps by " +
                     rounded(mean_step) + " s on average); expected a period of at least " +
                     rounded(kMinStepsPerPeriod * mean_step) + " s");
  }
  // Counted from the window's start (the first sample, or --start), not from
  // where the motion's phase crosses 2π: least squares over whole periods
  // needs no particular phase at the ends, and a motion of phase π (a
  // reversed axis) would otherwise lose a period.
  const double origin = options.start_time ? std::max(t.front(), *options.start_time) : t.front();
  const auto boundary = [&](double k) { return origin + k * period; };
  const double k0 = 0.0;
  const double k_end = std::floor((t.back() - origin) / period + 1e-9);
  const double whole = k_end - k0;
  if (!(whole >= 3.0))
    throw InputError(
        "forced oscillation: the history holds " + std::to_string(static_cast<long>(std::max(0.0, whole))) +
        " whole period(s) of " + shortest_number(period) + " s counted from " +
        (options.start_time
             ? "--start " + shortest_number(*options.start_time) + " s"
             : "its first sample at " + shortest_number(t.front()) + " s (--start counts from a later time)") +
        " to its end at " + shortest_number(t.back()) + " s; expected at least 3 (a longer run" +
        (options.start_time ? ", or an earlier --start)" : ")"));
  const auto total_periods = static_cast<std::size_t>(whole);

  const Phases phases = phases_of(t, motion);
  // The samples must resolve the fitted harmonics: over whole periods the
  // basis 1, sin kθ, cos kθ is orthogonal with weights 1, 1/2, 1/2. A period
  // of one or two sampling steps (every sample at the same phase) or too many
  // harmonics for the samples make it nearly dependent, and the coefficients
  // meaningless however well they fit.
  {
    const WindowFit basis_only = fit_window(t, phases, {}, options.harmonics, boundary(k0), boundary(k_end), false);
    const Eigen::MatrixXd normal = basis_only.normal / basis_only.normal(0, 0);
    const double smallest = symmetric_eigen(normal, Eigen::EigenvaluesOnly).eigenvalues().minCoeff();
    if (!(smallest >= 0.25))
      throw InputError("forced oscillation: the samples do not resolve " + std::to_string(options.harmonics) +
                       (options.harmonics == 1 ? " harmonic" : " harmonics") + " of the period " +
                       shortest_number(period) + " s (the history steps by " +
                       shortest_number((t.back() - t.front()) / static_cast<double>(t.size() - 1)) +
                       " s on average; the sampled sines and cosines are nearly dependent, smallest eigenvalue " +
                       shortest_number(smallest) + " of 0.5); expected many sampling steps per period" +
                       (options.harmonics > 1 ? " or fewer --harmonics" : ""));
  }
  // Period-by-period first harmonics, for the transient and the spread.
  std::vector<std::array<Eigen::VectorXd, 6>> per_period(total_periods);
  for (std::size_t p = 0; p < total_periods; ++p) {
    const double lo = boundary(k0 + static_cast<double>(p)), hi = boundary(k0 + static_cast<double>(p + 1));
    per_period[p] = fit_window(t, phases, forces, 1, lo, hi, false).coefficients;
  }
  std::size_t dropped = 0;
  if (!options.start_time) {
    // The component with the largest first harmonic decides.
    std::size_t dominant = 0;
    double largest = -1.0;
    for (std::size_t c = 0; c < 6; ++c) {
      if (forces[c].empty()) continue;
      const auto& last = per_period.back()[c];
      const double amplitude = std::hypot(last[1], last[2]);
      if (amplitude > largest) largest = amplitude, dominant = c;
    }
    std::vector<double> amplitudes;
    for (const auto& fit : per_period) amplitudes.push_back(std::hypot(fit[dominant][1], fit[dominant][2]));
    dropped = mser_truncation(amplitudes);
  }
  const std::size_t kept = total_periods - dropped;
  if (kept < 3)
    throw InputError("forced oscillation: " + std::to_string(kept) + " whole period(s) of " + shortest_number(period) +
                     " s left after the " + std::to_string(dropped) +
                     " start-up period(s) MSER dropped; expected at least 3 (a longer run, or --start to say where "
                     "the periods begin)");

  HarmonicAnalysis out;
  out.motion = motion;
  out.transient_periods = dropped;
  out.periods = kept;
  out.window_start = boundary(k0 + static_cast<double>(dropped));
  out.window_end = boundary(k0 + static_cast<double>(total_periods));
  out.samples = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), out.window_end) -
                                         std::lower_bound(t.begin(), t.end(), out.window_start));
  const WindowFit fit = fit_window(t, phases, forces, options.harmonics, out.window_start, out.window_end, true);
  const double acceleration_scale = motion.amplitude * motion.omega * motion.omega;
  const double velocity_scale = motion.amplitude * motion.omega;
  for (std::size_t c = 0; c < 6; ++c) {
    if (forces[c].empty()) continue;
    auto& component = out.components[c];
    component.present = true;
    const auto& coefficients = fit.coefficients[c];
    component.mean = coefficients[0];
    for (int k = 1; k <= options.harmonics; ++k) {
      component.in_phase.push_back(coefficients[2 * k - 1]);
      component.quadrature.push_back(coefficients[2 * k]);
    }
    component.explained = fit.explained[c];
    component.added_mass = coefficients[1] / acceleration_scale;
    component.damping = -coefficients[2] / velocity_scale;
    // Spread of the period-by-period first harmonic over the kept periods.
    double mean_s = 0.0, mean_c = 0.0;
    for (std::size_t p = dropped; p < total_periods; ++p) mean_s += per_period[p][c][1], mean_c += per_period[p][c][2];
    mean_s /= static_cast<double>(kept), mean_c /= static_cast<double>(kept);
    double var_s = 0.0, var_c = 0.0;
    for (std::size_t p = dropped; p < total_periods; ++p) {
      var_s += (per_period[p][c][1] - mean_s) * (per_period[p][c][1] - mean_s);
      var_c += (per_period[p][c][2] - mean_c) * (per_period[p][c][2] - mean_c);
    }
    component.in_phase_spread = std::sqrt(var_s / static_cast<double>(kept - 1));
    component.quadrature_spread = std::sqrt(var_c / static_cast<double>(kept - 1));
    const double root_n = std::sqrt(static_cast<double>(kept));
    component.added_mass_se = component.in_phase_spread / root_n / acceleration_scale;
    component.damping_se = component.quadrature_spread / root_n / velocity_scale;
    bool finite = std::isfinite(component.mean) && std::isfinite(component.explained) &&
                  std::isfinite(component.added_mass) && std::isfinite(component.damping) &&
                  std::isfinite(component.added_mass_se) && std::isfinite(component.damping_se);
    for (int k = 0; k < options.harmonics; ++k)
      finite = finite && std::isfinite(component.in_phase[static_cast<std::size_t>(k)]) &&
               std::isfinite(component.quadrature[static_cast<std::size_t>(k)]);
    if (!finite)
      throw InputError("forced oscillation: component " + std::string(kForceNames[c]) + " gives added mass " +
                       shortest_number(component.added_mass) + " +- " + shortest_number(component.added_mass_se) +
                       " and damping " + shortest_number(component.damping) + " +- " +
                       shortest_number(component.damping_se) +
                       "; expected finite numbers (forces too large for their sum in floating point?)");
  }
  return out;
}

QuadraticDamping fit_quadratic_damping(std::span<const double> amplitudes, double omega,
                                       std::span<const double> equivalent_damping,
                                       std::span<const double> standard_errors) {
  const std::size_t n = amplitudes.size();
  if (n < 2 || equivalent_damping.size() != n || (!standard_errors.empty() && standard_errors.size() != n))
    throw InputError("quadratic damping: expected at least two amplitudes, each with its equivalent damping");
  if (!(omega > 0.0) || !std::isfinite(omega)) throw InputError("quadratic damping: expected a positive frequency");
  const double factor = 8.0 / (3.0 * std::numbers::pi) * omega;
  bool weighted = !standard_errors.empty();
  for (std::size_t i = 0; i < n; ++i) {
    if (!(amplitudes[i] > 0.0) || !std::isfinite(amplitudes[i]) || !std::isfinite(equivalent_damping[i]))
      throw InputError("quadratic damping: amplitudes must be positive and values finite");
    if (weighted && !(standard_errors[i] > 0.0)) weighted = false;
  }
  Eigen::MatrixXd X(static_cast<Eigen::Index>(n), 2);
  Eigen::VectorXd y(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double w = weighted ? 1.0 / standard_errors[i] : 1.0;
    X(static_cast<Eigen::Index>(i), 0) = w;
    X(static_cast<Eigen::Index>(i), 1) = w * factor * amplitudes[i];
    y(static_cast<Eigen::Index>(i)) = w * equivalent_damping[i];
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr = col_piv_householder_qr(X);
  if (qr.rank() < 2) throw InputError("quadratic damping: the amplitudes must differ");
  const Eigen::Vector2d beta = qr.solve(y);
  QuadraticDamping out;
  out.linear = beta[0];
  out.quadratic = beta[1];
  if (n > 2 || weighted) {
    const Eigen::Matrix2d covariance_unscaled = (X.transpose() * X).inverse();
    double scale = 1.0;  // weighted: the standard errors are the data's
    if (!weighted) scale = (y - X * beta).squaredNorm() / static_cast<double>(n - 2);
    out.linear_se = std::sqrt(scale * covariance_unscaled(0, 0));
    out.quadratic_se = std::sqrt(scale * covariance_unscaled(1, 1));
  }
  return out;
}

double keulegan_carpenter(double amplitude, double size) { return kTwoPi * amplitude / size; }
double stokes_number(double size, double period, double kinematic_viscosity) {
  return size * size / (kinematic_viscosity * period);
}

}  // namespace hydrocoef
