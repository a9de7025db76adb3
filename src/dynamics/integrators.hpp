// Time integrators for x' = f(t, x) over fixed-size Eigen vectors: the
// classical fixed-step Runge–Kutta 4 and the adaptive Dormand–Prince 5(4)
// pair with error control (Hairer, Norsett and Wanner, "Solving Ordinary
// Differential Equations I", section II.4 and II.5: coefficients, the mixed
// absolute/relative error norm, the step-size controller and the starting
// step). Templates over the vector type so that the dynamics state (13
// numbers) stays on the stack: a step allocates nothing.
//
// f is any callable f(double t, const Vector& x, Vector& x_dot).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

#include "src/core/error.hpp"

namespace hydrocoef {

/// Scratch space of rk4_step, reusable across steps.
template <class Vector>
struct Rk4Workspace {
  Vector k1, k2, k3, k4, stage;
};

/// One classical RK4 step of size h from (t, x); x is replaced by x(t + h).
/// Four evaluations of f; local error O(h^5), global O(h^4).
template <class Vector, class Derivative>
void rk4_step(Derivative& f, double t, double h, Vector& x, Rk4Workspace<Vector>& w) {
  f(t, x, w.k1);
  w.stage = x + (0.5 * h) * w.k1;
  f(t + 0.5 * h, w.stage, w.k2);
  w.stage = x + (0.5 * h) * w.k2;
  f(t + 0.5 * h, w.stage, w.k3);
  w.stage = x + h * w.k3;
  f(t + h, w.stage, w.k4);
  x += (h / 6.0) * (w.k1 + 2.0 * w.k2 + 2.0 * w.k3 + w.k4);
}

struct AdaptiveOptions {
  /// A step is accepted when the estimated local error e_i satisfies
  /// sqrt(mean_i (e_i / (atol + rtol max(|x_i|, |x_new_i|)))^2) <= 1.
  double relative_tolerance = 1e-8;
  double absolute_tolerance = 1e-10;                          ///< in each state component's unit
  double max_step = std::numeric_limits<double>::infinity();  ///< [time unit]
  double min_step = 1e-12;                                    ///< below this the integration gives up (InputError)
  std::size_t max_steps = 100'000'000;
};

struct AdaptiveStats {
  std::size_t accepted = 0;
  std::size_t rejected = 0;
  std::size_t evaluations = 0;  ///< calls of f
};

/// Dormand–Prince 5(4) with FSAL: six evaluations per attempted step (seven
/// for the first of each advance() call); the fifth-order solution is
/// propagated (local extrapolation), the embedded fourth-order one only
/// estimates the error. The proposed step size carries over from one
/// advance() call to the next.
template <class Vector>
class DormandPrince45 {
 public:
  explicit DormandPrince45(const AdaptiveOptions& options = {}) : options_(options) {}

  const AdaptiveOptions& options() const noexcept { return options_; }
  const AdaptiveStats& stats() const noexcept { return stats_; }
  /// The step size the next advance() starts with (0: chosen automatically).
  double proposed_step() const noexcept { return h_; }
  /// Forget the step size (after a discontinuity in f).
  void reset_step() noexcept { h_ = 0.0; }

  /// Integrates from t to t_end (> t), ending exactly at t_end; t and x are
  /// updated. f must be smooth on (t, t_end): put input changes at t_end.
  /// Throws InputError when the step size falls below min_step or max_steps
  /// is exceeded.
  template <class Derivative>
  void advance(Derivative& f, double& t, double t_end, Vector& x) {
    if (!(t_end > t)) return;
    f(t, x, k1_);
    ++stats_.evaluations;
    if (h_ <= 0.0) h_ = initial_step(f, t, t_end, x);
    std::size_t steps = 0;
    while (t < t_end) {
      double h = std::min(h_, options_.max_step);
      bool last = false;
      if (t + h >= t_end || t_end - (t + h) < 1e-12 * std::abs(t_end)) {
        h = t_end - t;
        last = true;
      }
      if (h < options_.min_step && !last)
        throw InputError("adaptive integration: step size " + std::to_string(h) + " at t = " + std::to_string(t) +
                         " is below the minimum " + std::to_string(options_.min_step) +
                         "; the problem is too stiff or not smooth for the tolerance");
      if (++steps > options_.max_steps)
        throw InputError("adaptive integration: more than " + std::to_string(options_.max_steps) + " steps");
      attempt(f, t, h, x);
      const double error = error_norm(x);
      const double factor = error == 0.0 ? kMaxGrowth : std::clamp(0.9 * std::pow(error, -0.2), kMinShrink, kMaxGrowth);
      if (error <= 1.0) {
        ++stats_.accepted;
        t = last ? t_end : t + h;
        x = x_new_;
        k1_ = k7_;  // FSAL
        // A step shortened to hit t_end says little about the step the
        // solution allows: keep the larger proposal.
        h_ = last ? std::max(h_, h * factor) : h * factor;
      } else {
        ++stats_.rejected;
        h_ = h * std::min(1.0, factor);
      }
    }
  }

 private:
  static constexpr double kMaxGrowth = 5.0;
  static constexpr double kMinShrink = 0.2;

  template <class Derivative>
  void attempt(Derivative& f, double t, double h, const Vector& x) {
    // Dormand and Prince (1980), coefficients as in Hairer et al. Table II.5.2.
    constexpr double a21 = 1.0 / 5.0;
    constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
    constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
    constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0, a54 = -212.0 / 729.0;
    constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0, a64 = 49.0 / 176.0,
                     a65 = -5103.0 / 18656.0;
    constexpr double b1 = 35.0 / 384.0, b3 = 500.0 / 1113.0, b4 = 125.0 / 192.0, b5 = -2187.0 / 6784.0,
                     b6 = 11.0 / 84.0;
    // e = b(5th order) - b(4th order).
    constexpr double e1 = 71.0 / 57600.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0, e5 = -17253.0 / 339200.0,
                     e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;
    stage_ = x + h * (a21 * k1_);
    f(t + h / 5.0, stage_, k2_);
    stage_ = x + h * (a31 * k1_ + a32 * k2_);
    f(t + 3.0 * h / 10.0, stage_, k3_);
    stage_ = x + h * (a41 * k1_ + a42 * k2_ + a43 * k3_);
    f(t + 4.0 * h / 5.0, stage_, k4_);
    stage_ = x + h * (a51 * k1_ + a52 * k2_ + a53 * k3_ + a54 * k4_);
    f(t + 8.0 * h / 9.0, stage_, k5_);
    stage_ = x + h * (a61 * k1_ + a62 * k2_ + a63 * k3_ + a64 * k4_ + a65 * k5_);
    f(t + h, stage_, k6_);
    x_new_ = x + h * (b1 * k1_ + b3 * k3_ + b4 * k4_ + b5 * k5_ + b6 * k6_);
    f(t + h, x_new_, k7_);
    stats_.evaluations += 6;
    error_ = h * (e1 * k1_ + e3 * k3_ + e4 * k4_ + e5 * k5_ + e6 * k6_ + e7 * k7_);
  }

  double error_norm(const Vector& x) const {
    double sum = 0.0;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      const double scale =
          options_.absolute_tolerance + options_.relative_tolerance * std::max(std::abs(x[i]), std::abs(x_new_[i]));
      const double e = error_[i] / scale;
      sum += e * e;
    }
    const double norm = std::sqrt(sum / static_cast<double>(x.size()));
    return std::isfinite(norm) ? norm : std::numeric_limits<double>::infinity();
  }

  double scaled_norm(const Vector& v, const Vector& x) const {
    double sum = 0.0;
    for (Eigen::Index i = 0; i < v.size(); ++i) {
      const double e = v[i] / (options_.absolute_tolerance + options_.relative_tolerance * std::abs(x[i]));
      sum += e * e;
    }
    return std::sqrt(sum / static_cast<double>(v.size()));
  }

  // Hairer et al. section II.4, "starting step size"; k1_ holds f(t, x).
  template <class Derivative>
  double initial_step(Derivative& f, double t, double t_end, const Vector& x) {
    const double d0 = scaled_norm(x, x);
    const double d1 = scaled_norm(k1_, x);
    double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
    h0 = std::min({h0, t_end - t, options_.max_step});
    stage_ = x + h0 * k1_;
    f(t + h0, stage_, k2_);
    ++stats_.evaluations;
    const double d2 = scaled_norm(k2_ - k1_, x) / h0;
    const double h1 =
        std::max(d1, d2) <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / std::max(d1, d2), 1.0 / 5.0);
    return std::min(100.0 * h0, h1);
  }

  AdaptiveOptions options_;
  AdaptiveStats stats_;
  double h_ = 0.0;
  Vector k1_, k2_, k3_, k4_, k5_, k6_, k7_, stage_, x_new_, error_;
};

}  // namespace hydrocoef
