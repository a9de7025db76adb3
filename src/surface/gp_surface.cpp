#include "src/surface/gp_surface.hpp"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

constexpr double kSqrt5 = 2.23606797749978969641;
constexpr double kJitter = 1e-10;                          ///< relative to sigma^2, on the diagonal
constexpr double kLengthPriorMean = -0.69314718055994531;  ///< log 0.5 (scaled axes: half the runs' span)
constexpr double kLengthPriorSd = 1.5;                     ///< of each log length scale
constexpr double kNuggetPriorMean = -2.99573227355399099;  ///< log 0.05 (scaled values)
constexpr double kNuggetPriorSd = 3.0;
constexpr std::size_t kMaxDims = 6;

/// exp(x) for x <= 0, branch-free so that loops over it vectorize: x = k ln2
/// + f with |f| <= ln2/2, exp(f) by its Taylor series to f^13 (relative
/// error below 1e-17 there), 2^k put into the exponent bits. Below -708 the
/// result is held at exp(-708) ~ 3e-308 instead of underflowing: a kernel
/// value that small counts for nothing either way.
[[gnu::always_inline]] inline double exp_nonpositive(double x) {
  constexpr double kInvLn2 = 1.4426950408889634074, kLn2Hi = 6.93147180369123816490e-01,
                   kLn2Lo = 1.90821492927058770002e-10;
  x = std::max(x, -708.0);
  // Round to the nearest integer by the 1.5 * 2^52 trick (no call, so the
  // loops around it vectorize).
  constexpr double kRound = 6755399441055744.0;
  const double k = (x * kInvLn2 + kRound) - kRound;
  const double f = (x - k * kLn2Hi) - k * kLn2Lo;
  double p = 1.0 / 6227020800.0;  // 1/13!
  p = p * f + 1.0 / 479001600.0;
  p = p * f + 1.0 / 39916800.0;
  p = p * f + 1.0 / 3628800.0;
  p = p * f + 1.0 / 362880.0;
  p = p * f + 1.0 / 40320.0;
  p = p * f + 1.0 / 5040.0;
  p = p * f + 1.0 / 720.0;
  p = p * f + 1.0 / 120.0;
  p = p * f + 1.0 / 24.0;
  p = p * f + 1.0 / 6.0;
  p = p * f + 0.5;
  p = p * f + 1.0;
  p = p * f + 1.0;
  // 2^k without a double-to-integer conversion (which AVX2 lacks): adding
  // 2^52 + 1023 leaves k + 1023 in the low bits of the sum's mantissa.
  const double shifted = k + (4503599627370496.0 + 1023.0);
  std::uint64_t bits;
  __builtin_memcpy(&bits, &shifted, sizeof bits);
  bits <<= 52;
  double scale;
  __builtin_memcpy(&scale, &bits, sizeof scale);
  return p * scale;
}

/// The kernel vector over all runs: k_i = sigma^2 c(r_i^2) and the factors
/// g_i = sigma^2 dc (see correlation), from the squared distances in k.
/// Vectorized (AVX2 where the processor has it).
[[gnu::target_clones("arch=x86-64-v3", "default")]] void kernel_values(GpKernel kernel, double s2, double* k, double* g,
                                                                       std::size_t n) {
  if (kernel == GpKernel::SquaredExponential) {
    for (std::size_t i = 0; i < n; ++i) {
      const double c = exp_nonpositive(-0.5 * k[i]);
      k[i] = s2 * c;
      g[i] = -s2 * c;
    }
    return;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = k[i], r = __builtin_sqrt(r2), e = exp_nonpositive(-kSqrt5 * r);
    k[i] = s2 * (1.0 + kSqrt5 * r + (5.0 / 3.0) * r2) * e;
    g[i] = -s2 * (5.0 / 3.0) * (1.0 + kSqrt5 * r) * e;
  }
}

/// Sum of a[i] * b[i], four lanes at a time (inlined into the vectorized
/// callers, so it takes their instruction set).
[[gnu::always_inline]] inline double dot(const double* a, const double* b, std::size_t n) {
  // Four independent sums, so that the additions do not wait on each other.
  typedef double v4 __attribute__((vector_size(32)));
  v4 s0 = {0, 0, 0, 0}, s1 = s0, s2 = s0, s3 = s0;
  std::size_t i = 0;
  v4 x0, x1, x2, x3, y0, y1, y2, y3;
  for (; i + 16 <= n; i += 16) {
    __builtin_memcpy(&x0, a + i, sizeof x0), __builtin_memcpy(&y0, b + i, sizeof y0);
    __builtin_memcpy(&x1, a + i + 4, sizeof x1), __builtin_memcpy(&y1, b + i + 4, sizeof y1);
    __builtin_memcpy(&x2, a + i + 8, sizeof x2), __builtin_memcpy(&y2, b + i + 8, sizeof y2);
    __builtin_memcpy(&x3, a + i + 12, sizeof x3), __builtin_memcpy(&y3, b + i + 12, sizeof y3);
    s0 += x0 * y0, s1 += x1 * y1, s2 += x2 * y2, s3 += x3 * y3;
  }
  for (; i + 4 <= n; i += 4) {
    __builtin_memcpy(&x0, a + i, sizeof x0), __builtin_memcpy(&y0, b + i, sizeof y0);
    s0 += x0 * y0;
  }
  const v4 sum = (s0 + s1) + (s2 + s3);
  double total = (sum[0] + sum[1]) + (sum[2] + sum[3]);
  for (; i < n; ++i) total += a[i] * b[i];
  return total;
}

/// dot for callers that are not vectorized themselves.
[[gnu::target_clones("arch=x86-64-v3", "default")]] double dot_product(const double* a, const double* b,
                                                                       std::size_t n) {
  return dot(a, b, n);
}

/// Solves L w = k by forward substitution, L packed by rows (row i holds
/// L_i0..L_ii from i (i + 1) / 2 on), four rows at a time: their sums over
/// the already solved w share each load of w and run as four independent
/// chains, so the solve is bound by the loads of L rather than by the
/// latency of one long sum. Returns w^T w.
[[gnu::target_clones("arch=x86-64-v3", "default")]] double forward_substitute(const double* __restrict L,
                                                                              const double* __restrict k,
                                                                              double* __restrict w, std::size_t n) {
  typedef double v4 __attribute__((vector_size(32)));
  double ww = 0.0;
  for (std::size_t block = 0; block < n; block += 4) {
    const std::size_t rows = std::min<std::size_t>(4, n - block);
    const double* row[4];
    for (std::size_t r = 0; r < 4; ++r) {
      const std::size_t i = block + std::min(r, rows - 1);
      row[r] = L + i * (i + 1) / 2;
    }
    v4 a0 = {0, 0, 0, 0}, a1 = a0, a2 = a0, a3 = a0;
    for (std::size_t j = 0; j < block; j += 4) {  // block is a multiple of 4
      v4 x, l0, l1, l2, l3;
      __builtin_memcpy(&x, w + j, sizeof x);
      __builtin_memcpy(&l0, row[0] + j, sizeof l0);
      __builtin_memcpy(&l1, row[1] + j, sizeof l1);
      __builtin_memcpy(&l2, row[2] + j, sizeof l2);
      __builtin_memcpy(&l3, row[3] + j, sizeof l3);
      a0 += l0 * x, a1 += l1 * x, a2 += l2 * x, a3 += l3 * x;
    }
    const double sums[4] = {(a0[0] + a0[1]) + (a0[2] + a0[3]), (a1[0] + a1[1]) + (a1[2] + a1[3]),
                            (a2[0] + a2[1]) + (a2[2] + a2[3]), (a3[0] + a3[1]) + (a3[2] + a3[3])};
    for (std::size_t r = 0; r < rows; ++r) {
      const std::size_t i = block + r;
      double sum = k[i] - sums[r];
      for (std::size_t j = block; j < i; ++j) sum -= row[r][j] * w[j];
      w[i] = sum / row[r][i];
      ww += w[i] * w[i];
    }
  }
  return ww;
}

/// Replaces u by R^-1 u for R lower triangular, packed by rows (row t holds
/// R_t0..R_tt); returns |R^-1 u|^2. For the mean's few terms.
double solve_lower_packed(const double* R, double* u, std::size_t m) {
  double uu = 0.0;
  for (std::size_t t = 0; t < m; ++t) {
    const double* row = R + t * (t + 1) / 2;
    double sum = u[t];
    for (std::size_t j = 0; j < t; ++j) sum -= row[j] * u[j];
    u[t] = sum / row[t];
    uu += u[t] * u[t];
  }
  return uu;
}

/// Kernel correlation c(r^2) (sigma = 1) and, for the gradients, the factor
/// dc such that d c / d x'_a = dc * (x'_a - p_a) (x' = z / l).
inline void correlation(GpKernel kernel, double r2, double& c, double& dc) {
  if (kernel == GpKernel::SquaredExponential) {
    c = std::exp(-0.5 * r2);
    dc = -c;
    return;
  }
  const double r = std::sqrt(r2), e = std::exp(-kSqrt5 * r);
  c = (1.0 + kSqrt5 * r + (5.0 / 3.0) * r2) * e;
  dc = -(5.0 / 3.0) * (1.0 + kSqrt5 * r) * e;
}

/// The monomials of the mean at scaled axes z: 1, z_a (degree 1), z_a^2 (degree 2).
void mean_basis(int degree, std::size_t dims, const double* z, double* h) {
  h[0] = 1.0;
  if (degree >= 1)
    for (std::size_t a = 0; a < dims; ++a) h[1 + a] = z[a];
  if (degree >= 2)
    for (std::size_t a = 0; a < dims; ++a) h[1 + dims + a] = z[a] * z[a];
}

/// The scaled problem the likelihood and the final state are computed on.
struct Scaled {
  GpKernel kernel;
  int degree;
  std::size_t n, d, m;
  Eigen::MatrixXd z;       ///< n x d scaled axes
  Eigen::VectorXd y;       ///< scaled values
  Eigen::VectorXd noise2;  ///< scaled noise variances
  Eigen::MatrixXd H;       ///< n x m mean basis
  bool nugget = true;      ///< tau is a parameter (the last)
};

/// Everything REML needs at one set of hyperparameters.
struct Factorised {
  Eigen::LLT<Eigen::MatrixXd> K;
  Eigen::MatrixXd correlation;    ///< C (sigma = 1)
  Eigen::MatrixXd LinvH;          ///< L^-1 H
  Eigen::LLT<Eigen::MatrixXd> A;  ///< H^T K^-1 H
  Eigen::VectorXd beta, alpha;
  double objective = 0.0;  ///< REML negative log likelihood (without constants and prior)
};

bool factorise(const Scaled& p, double sigma, const std::vector<double>& lengths, double tau, double jitter,
               Factorised& f) {
  const std::size_t n = p.n;
  f.correlation.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j <= i; ++j) {
      double r2 = 0.0;
      for (std::size_t a = 0; a < p.d; ++a) {
        const double delta = (p.z(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(a)) -
                              p.z(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(a))) /
                             lengths[a];
        r2 += delta * delta;
      }
      double c = 0.0, dc = 0.0;
      correlation(p.kernel, r2, c, dc);
      f.correlation(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = c;
      f.correlation(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(i)) = c;
    }
  }
  Eigen::MatrixXd K = sigma * sigma * f.correlation;
  K.diagonal() +=
      p.noise2 + Eigen::VectorXd::Constant(static_cast<Eigen::Index>(n), tau * tau + jitter * sigma * sigma);
  f.K.compute(K);
  if (f.K.info() != Eigen::Success) return false;
  const auto L = f.K.matrixL();
  f.LinvH = L.solve(p.H);
  f.A.compute(f.LinvH.transpose() * f.LinvH);
  if (f.A.info() != Eigen::Success) return false;
  const Eigen::VectorXd Linv_y = L.solve(p.y);
  f.beta = f.A.solve(f.LinvH.transpose() * Linv_y);
  const Eigen::VectorXd Linv_r = Linv_y - f.LinvH * f.beta;
  f.alpha = f.K.matrixU().solve(Linv_r);
  double log_det_K = 0.0, log_det_A = 0.0;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(n); ++i) log_det_K += 2.0 * std::log(f.K.matrixLLT()(i, i));
  for (Eigen::Index i = 0; i < f.A.matrixLLT().rows(); ++i) log_det_A += 2.0 * std::log(f.A.matrixLLT()(i, i));
  f.objective = 0.5 * Linv_r.squaredNorm() + 0.5 * log_det_K + 0.5 * log_det_A;
  return std::isfinite(f.objective);
}

/// REML of log-parameters (log sigma, log l_1..d[, log tau]) with its
/// analytic gradient.
class Reml final : public ceres::FirstOrderFunction {
 public:
  explicit Reml(const Scaled& problem) : p_(problem) {}
  int NumParameters() const override { return static_cast<int>(1 + p_.d + (p_.nugget ? 1 : 0)); }

  bool Evaluate(const double* theta, double* cost, double* gradient) const override {
    const std::size_t parameters = static_cast<std::size_t>(NumParameters());
    for (std::size_t j = 0; j < parameters; ++j)
      if (!(std::abs(theta[j]) < 20.0)) return false;  // far outside anything meaningful
    const double sigma = std::exp(theta[0]);
    std::vector<double> lengths(p_.d);
    for (std::size_t a = 0; a < p_.d; ++a) lengths[a] = std::exp(theta[1 + a]);
    const double tau = p_.nugget ? std::exp(theta[1 + p_.d]) : 0.0;
    Factorised f;
    if (!factorise(p_, sigma, lengths, tau, kJitter, f)) return false;
    double prior = 0.0;
    for (std::size_t a = 0; a < p_.d; ++a) {
      const double e = theta[1 + a] - kLengthPriorMean;
      prior += e * e / (2.0 * kLengthPriorSd * kLengthPriorSd);
    }
    if (p_.nugget) {
      const double e = theta[1 + p_.d] - kNuggetPriorMean;
      prior += e * e / (2.0 * kNuggetPriorSd * kNuggetPriorSd);
    }
    *cost = f.objective + prior;
    if (!gradient) return true;
    // P = K^-1 - K^-1 H A^-1 H^T K^-1; dREML/dtheta = tr(P dK)/2 - alpha^T dK alpha/2.
    const auto n = static_cast<Eigen::Index>(p_.n);
    const Eigen::MatrixXd Kinv = f.K.solve(Eigen::MatrixXd::Identity(n, n));
    const Eigen::MatrixXd KinvH = f.K.solve(p_.H);
    const Eigen::MatrixXd P = Kinv - KinvH * f.A.solve(KinvH.transpose());
    const double s2 = sigma * sigma;
    // log sigma: dK = 2 sigma^2 C (+ the jitter's share, negligible and left out).
    gradient[0] =
        0.5 * (P.cwiseProduct(2.0 * s2 * f.correlation)).sum() - 0.5 * f.alpha.dot(2.0 * s2 * f.correlation * f.alpha);
    for (std::size_t a = 0; a < p_.d; ++a) {
      double trace = 0.0, quadratic = 0.0;
      for (Eigen::Index i = 0; i < n; ++i) {
        for (Eigen::Index j = 0; j < n; ++j) {
          const double delta =
              (p_.z(i, static_cast<Eigen::Index>(a)) - p_.z(j, static_cast<Eigen::Index>(a))) / lengths[a];
          if (delta == 0.0) continue;
          // dC/dlog l_a = c_r * delta^2 with c_r the kernel's factor.
          double dk = 0.0;
          if (p_.kernel == GpKernel::SquaredExponential) {
            dk = f.correlation(i, j) * delta * delta;
          } else {
            double r2 = 0.0;
            for (std::size_t b = 0; b < p_.d; ++b) {
              const double e =
                  (p_.z(i, static_cast<Eigen::Index>(b)) - p_.z(j, static_cast<Eigen::Index>(b))) / lengths[b];
              r2 += e * e;
            }
            const double r = std::sqrt(r2);
            dk = (5.0 / 3.0) * (1.0 + kSqrt5 * r) * std::exp(-kSqrt5 * r) * delta * delta;
          }
          dk *= s2;
          trace += P(i, j) * dk;
          quadratic += f.alpha[i] * dk * f.alpha[j];
        }
      }
      gradient[1 + a] =
          0.5 * trace - 0.5 * quadratic + (theta[1 + a] - kLengthPriorMean) / (kLengthPriorSd * kLengthPriorSd);
    }
    if (p_.nugget) {
      // log tau: dK = 2 tau^2 I.
      const double t2 = tau * tau;
      gradient[1 + p_.d] = 0.5 * P.trace() * 2.0 * t2 - 0.5 * 2.0 * t2 * f.alpha.squaredNorm() +
                           (theta[1 + p_.d] - kNuggetPriorMean) / (kNuggetPriorSd * kNuggetPriorSd);
    }
    return true;
  }

 private:
  const Scaled& p_;
};

void check_state(const GpState& s) {
  const auto bad = [](const std::string& what) { throw InputError("stored GP surface: " + what); };
  if (s.dims == 0 || s.dims > kMaxDims) bad("expected 1 to 6 axes, found " + std::to_string(s.dims));
  if (s.mean_degree < 0 || s.mean_degree > 2) bad("mean degree must be 0, 1 or 2");
  const std::size_t n = s.samples, d = s.dims, m = gp_mean_terms(s.mean_degree, d);
  if (n < m + 1 || n > 100000) bad("sample count " + std::to_string(n) + " out of range");
  const auto sized = [&](const std::vector<double>& v, std::size_t expected, const char* name) {
    if (v.size() != expected)
      bad(std::string(name) + " holds " + std::to_string(v.size()) + " numbers; expected " + std::to_string(expected));
    for (const double x : v)
      if (!std::isfinite(x)) bad(std::string(name) + " holds a number that is not finite");
  };
  sized(s.axis_centre, d, "axis_centre");
  sized(s.axis_scale, d, "axis_scale");
  sized(s.length_scales, d, "length_scales");
  sized(s.points, d * n, "points");
  sized(s.alpha, n, "alpha");
  sized(s.beta, m, "beta");
  sized(s.cholesky, n * (n + 1) / 2, "cholesky");
  sized(s.basis_solve, n * m, "basis_solve");
  sized(s.mean_cholesky, m * (m + 1) / 2, "mean_cholesky");
  for (std::size_t a = 0; a < d; ++a)
    if (!(s.axis_scale[a] > 0.0) || !(s.length_scales[a] > 0.0)) bad("axis and length scales must be positive");
  if (!(s.sigma > 0.0) || !std::isfinite(s.sigma) || !(s.value_scale > 0.0) || !std::isfinite(s.value_scale) ||
      !std::isfinite(s.value_centre))
    bad("signal and value scales must be finite and positive");
  if (!(s.nugget >= 0.0) || !std::isfinite(s.nugget)) bad("the nugget must be a finite number >= 0");
  if (!(s.sd_factor >= 1.0) || !std::isfinite(s.sd_factor) || s.sd_factor > 1e3)
    bad("the standard-deviation factor must be a finite number from 1 to 1000");
  // L packed by rows: row i starts at i (i + 1) / 2, its diagonal i further on.
  for (std::size_t i = 0; i < n; ++i)
    if (!(s.cholesky[i * (i + 1) / 2 + i] > 0.0))
      bad("the Cholesky factor has a non-positive diagonal at " + std::to_string(i));
  for (std::size_t i = 0; i < m; ++i)
    if (!(s.mean_cholesky[i * (i + 1) / 2 + i] > 0.0)) bad("the mean's Cholesky factor has a non-positive diagonal");
}

}  // namespace

std::string_view gp_kernel_name(GpKernel kernel) {
  return kernel == GpKernel::SquaredExponential ? "squared-exponential" : "matern52";
}

GpKernel parse_gp_kernel(std::string_view text) {
  if (text == "squared-exponential" || text == "se") return GpKernel::SquaredExponential;
  if (text == "matern52" || text == "matern") return GpKernel::Matern52;
  throw InputError("GP kernel '" + std::string(text) + "': expected matern52 or squared-exponential");
}

std::size_t gp_mean_terms(int degree, std::size_t dims) {
  return 1 + (degree >= 1 ? dims : 0) + (degree >= 2 ? dims : 0);
}

GpSurface::GpSurface(GpState state)
    : state_(std::move(state)), terms_(gp_mean_terms(state_.mean_degree, state_.dims)) {}

GpSurface GpSurface::from_state(GpState state) {
  check_state(state);
  return GpSurface(std::move(state));
}

GpSurface GpSurface::fit(std::span<const double> x, std::size_t dims, std::span<const double> y,
                         std::span<const double> noise_sd, const GpOptions& options) {
  if (dims == 0 || dims > kMaxDims) throw InputError("GP surface: expected 1 to 6 axes");
  if (options.mean_degree < 0 || options.mean_degree > 2) throw InputError("GP surface: mean degree must be 0, 1 or 2");
  if (options.starts < 1) throw InputError("GP surface: at least one optimiser start");
  const std::size_t n = y.size(), m = gp_mean_terms(options.mean_degree, dims);
  if (x.size() != n * dims || (!noise_sd.empty() && noise_sd.size() != n))
    throw InputError("GP surface: " + std::to_string(x.size()) + " coordinates and " + std::to_string(noise_sd.size()) +
                     " uncertainties for " + std::to_string(n) + " runs of " + std::to_string(dims) + " axes");
  if (n < m + 1)
    throw InputError("GP surface: " + std::to_string(n) + " runs; a mean of degree " +
                     std::to_string(options.mean_degree) + " needs at least " + std::to_string(m + 1));
  if (n > 5000)
    throw InputError("GP surface: " + std::to_string(n) + " runs; at most 5000 are supported (dense O(n^3) solve)");
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(y[i]))
      throw InputError("GP surface: run " + std::to_string(i) + " has a value that is not finite");
    if (!noise_sd.empty() && (!std::isfinite(noise_sd[i]) || noise_sd[i] < 0.0))
      throw InputError("GP surface: run " + std::to_string(i) + " has an uncertainty that is not a finite number >= 0");
    for (std::size_t a = 0; a < dims; ++a)
      if (!std::isfinite(x[i * dims + a]))
        throw InputError("GP surface: run " + std::to_string(i) + " has a coordinate that is not finite");
  }

  GpState state;
  state.kernel = options.kernel;
  state.mean_degree = options.mean_degree;
  state.dims = dims;
  state.samples = n;
  for (std::size_t a = 0; a < dims; ++a) {
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = 0; i < n; ++i) lo = std::min(lo, x[i * dims + a]), hi = std::max(hi, x[i * dims + a]);
    if (!(hi > lo)) throw InputError("GP surface: every run has the same value on axis " + std::to_string(a));
    state.axis_centre.push_back(0.5 * (lo + hi));
    state.axis_scale.push_back(hi - lo);
  }
  double mean = 0.0;
  for (const double v : y) mean += v;
  mean /= static_cast<double>(n);
  double spread = 0.0;
  for (const double v : y) spread += (v - mean) * (v - mean);
  spread = std::sqrt(spread / static_cast<double>(n));
  state.value_centre = mean;
  state.value_scale = spread > 0.0 ? spread : 1.0;

  Scaled p{options.kernel,
           options.mean_degree,
           n,
           dims,
           m,
           Eigen::MatrixXd(n, dims),
           Eigen::VectorXd(n),
           Eigen::VectorXd(n),
           Eigen::MatrixXd(n, m),
           options.estimate_nugget};
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t a = 0; a < dims; ++a)
      p.z(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(a)) =
          (x[i * dims + a] - state.axis_centre[a]) / state.axis_scale[a];
    p.y[static_cast<Eigen::Index>(i)] = (y[i] - state.value_centre) / state.value_scale;
    const double s = noise_sd.empty() ? 0.0 : noise_sd[i] / state.value_scale;
    p.noise2[static_cast<Eigen::Index>(i)] = s * s;
    double h[1 + 2 * kMaxDims];
    mean_basis(options.mean_degree, dims, p.z.row(static_cast<Eigen::Index>(i)).eval().data(), h);
    for (std::size_t t = 0; t < m; ++t) p.H(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(t)) = h[t];
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < i; ++j)
      if ((p.z.row(static_cast<Eigen::Index>(i)) - p.z.row(static_cast<Eigen::Index>(j))).squaredNorm() == 0.0)
        throw InputError("GP surface: runs " + std::to_string(j) + " and " + std::to_string(i) +
                         " are at the same point");

  // Hyperparameters: fixed, or the best of several L-BFGS starts.
  double sigma = 1.0, tau = 0.0;
  std::vector<double> lengths(dims, 0.5);
  if (!options.fixed_hyperparameters.empty()) {
    const auto& fixed = options.fixed_hyperparameters;
    if (fixed.size() != 1 + dims && fixed.size() != 2 + dims)
      throw InputError("GP surface: fixed hyperparameters are sigma, one length scale per axis and optionally tau");
    sigma = fixed[0] / state.value_scale;
    for (std::size_t a = 0; a < dims; ++a) lengths[a] = fixed[1 + a] / state.axis_scale[a];
    if (fixed.size() == 2 + dims) tau = fixed[1 + dims] / state.value_scale;
    if (!(sigma > 0.0) || std::any_of(lengths.begin(), lengths.end(), [](double l) { return !(l > 0.0); }) ||
        !(tau >= 0.0) || !std::isfinite(tau))
      throw InputError("GP surface: fixed hyperparameters must be positive (tau >= 0)");
  } else {
    std::mt19937 random(options.seed);
    std::uniform_real_distribution<double> log_length(std::log(0.05), std::log(3.0));
    double best = INFINITY;
    for (int start = 0; start < options.starts; ++start) {
      std::vector<double> theta(1 + dims + (p.nugget ? 1 : 0), 0.0);
      const double first[3] = {std::log(0.5), std::log(0.2), std::log(1.5)};
      for (std::size_t a = 0; a < dims; ++a) theta[1 + a] = start < 3 ? first[start] : log_length(random);
      if (p.nugget) theta[1 + dims] = start % 2 == 0 ? std::log(0.01) : std::log(0.2);
      ceres::GradientProblem problem(new Reml(p));
      ceres::GradientProblemSolver::Options solver;
      solver.line_search_direction_type = ceres::LBFGS;
      solver.max_num_iterations = 200;
      solver.logging_type = ceres::SILENT;
      ceres::GradientProblemSolver::Summary summary;
      ceres::Solve(solver, problem, theta.data(), &summary);
      if (!std::isfinite(summary.final_cost) || summary.final_cost >= best) continue;
      best = summary.final_cost;
      sigma = std::exp(theta[0]);
      for (std::size_t a = 0; a < dims; ++a) lengths[a] = std::exp(theta[1 + a]);
      tau = p.nugget ? std::exp(theta[1 + dims]) : 0.0;
    }
    if (!std::isfinite(best))
      throw InputError(
          "GP surface: the likelihood could not be evaluated at any start (the kernel matrix is singular)");
  }

  // The final factorisation; more jitter only if the matrix is numerically singular.
  Factorised f;
  double jitter = kJitter;
  while (!factorise(p, sigma, lengths, tau, jitter, f)) {
    jitter *= 100.0;
    if (jitter > 1e-4)
      throw InputError(
          "GP surface: the kernel matrix cannot be factorised; the runs are too close for these length scales");
  }
  // Leave-one-out standardized residuals (Dubrule 1983): alpha = P y, so
  // e_i = alpha_i / P_ii with variance 1 / P_ii.
  {
    const auto nn = static_cast<Eigen::Index>(n);
    const Eigen::MatrixXd Kinv = f.K.solve(Eigen::MatrixXd::Identity(nn, nn));
    const Eigen::MatrixXd KinvH = f.K.solve(p.H);
    const Eigen::VectorXd P_diagonal = Kinv.diagonal() - (KinvH * f.A.solve(KinvH.transpose())).diagonal();
    double sum = 0.0, largest = 0.0;
    for (Eigen::Index i = 0; i < nn; ++i) {
      const double z = P_diagonal[i] > 0.0 ? f.alpha[i] / std::sqrt(P_diagonal[i]) : 0.0;
      sum += z * z;
      largest = std::max(largest, std::abs(z));
    }
    state.loo_rms_z = std::sqrt(sum / static_cast<double>(n));
    state.loo_max_z = largest;
  }
  state.nugget = tau;
  state.sd_factor = student_t_factor(n - m) * std::max(1.0, state.loo_rms_z);
  state.sigma = sigma;
  state.length_scales = lengths;
  state.log_likelihood = -f.objective;
  state.points.resize(dims * n);
  for (std::size_t a = 0; a < dims; ++a)
    for (std::size_t i = 0; i < n; ++i)
      state.points[a * n + i] = p.z(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(a)) / lengths[a];
  state.alpha.assign(f.alpha.data(), f.alpha.data() + n);
  state.beta.assign(f.beta.data(), f.beta.data() + m);
  const Eigen::MatrixXd L = f.K.matrixL();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j <= i; ++j)
      state.cholesky.push_back(L(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)));
  for (std::size_t t = 0; t < m; ++t)
    for (std::size_t i = 0; i < n; ++i)
      state.basis_solve.push_back(f.LinvH(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(t)));
  const Eigen::MatrixXd R = f.A.matrixL();
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j <= i; ++j)
      state.mean_cholesky.push_back(R(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)));
  return GpSurface(std::move(state));
}

double GpSurface::signal_sd() const { return state_.sigma * state_.value_scale; }
double GpSurface::nugget_sd() const { return state_.nugget * state_.value_scale; }
double GpSurface::run_sd(double latent_sd, double run_uncertainty) const {
  const double tau = state_.nugget * state_.value_scale * state_.sd_factor;
  return std::sqrt(latent_sd * latent_sd + tau * tau + run_uncertainty * run_uncertainty);
}

double student_t_factor(std::size_t dof) {
  // t_{0.975, dof} for 1..30 (any table of the Student-t distribution), then
  // the Cornish-Fisher expansion in 1/dof (error below 1e-4 beyond 30).
  static constexpr double kTable[30] = {12.7062, 4.3027, 3.1824, 2.7764, 2.5706, 2.4469, 2.3646, 2.3060,
                                        2.2622,  2.2281, 2.2010, 2.1788, 2.1604, 2.1448, 2.1314, 2.1199,
                                        2.1098,  2.1009, 2.0930, 2.0860, 2.0796, 2.0739, 2.0687, 2.0639,
                                        2.0595,  2.0555, 2.0518, 2.0484, 2.0452, 2.0423};
  constexpr double z = 1.959963984540054;
  if (dof == 0) throw std::invalid_argument("student_t_factor: dof must be at least 1");
  if (dof <= 30) return kTable[dof - 1] / z;
  const double v = static_cast<double>(dof);
  const double z3 = z * z * z, z5 = z3 * z * z;
  return (z + (z3 + z) / (4.0 * v) + (5.0 * z5 + 16.0 * z3 + 3.0 * z) / (96.0 * v * v)) / z;
}

std::vector<double> GpSurface::length_scales() const {
  std::vector<double> out(state_.dims);
  for (std::size_t a = 0; a < state_.dims; ++a) out[a] = state_.length_scales[a] * state_.axis_scale[a];
  return out;
}

GpSurface::Workspace::Workspace(const GpSurface& surface)
    : k_(surface.samples()), w_(surface.samples()), g_(surface.samples()), sum_(surface.samples()) {}

double GpSurface::evaluate(const double* x, Workspace& ws, double* standard_deviation, double* gradient) const {
  const std::size_t n = state_.samples, d = state_.dims, m = terms_;
  if (ws.k_.size() < n) throw std::logic_error("GpSurface: workspace made for a smaller surface");
  double z[kMaxDims], xl[kMaxDims], h[1 + 2 * kMaxDims];
  for (std::size_t a = 0; a < d; ++a) {
    z[a] = (x[a] - state_.axis_centre[a]) / state_.axis_scale[a];
    xl[a] = z[a] / state_.length_scales[a];
  }
  // Squared distances, axis by axis over contiguous rows.
  double* k = ws.k_.data();
  double* g = ws.g_.data();  // dk/dx' factors
  std::fill(k, k + n, 0.0);
  for (std::size_t a = 0; a < d; ++a) {
    const double* row = state_.points.data() + a * n;
    const double xa = xl[a];
    for (std::size_t i = 0; i < n; ++i) {
      const double delta = xa - row[i];
      k[i] += delta * delta;
    }
  }
  const double s2 = state_.sigma * state_.sigma;
  kernel_values(state_.kernel, s2, k, g, n);
  double mean = dot_product(k, state_.alpha.data(), n);
  mean_basis(state_.mean_degree, d, z, h);
  for (std::size_t t = 0; t < m; ++t) mean += h[t] * state_.beta[t];

  if (gradient) {
    for (std::size_t a = 0; a < d; ++a) {
      const double* row = state_.points.data() + a * n;
      double sum = 0.0;
      for (std::size_t i = 0; i < n; ++i) sum += state_.alpha[i] * g[i] * (xl[a] - row[i]);
      double dz = sum / state_.length_scales[a];
      if (state_.mean_degree >= 1) dz += state_.beta[1 + a];
      if (state_.mean_degree >= 2) dz += 2.0 * z[a] * state_.beta[1 + d + a];
      gradient[a] = dz * state_.value_scale / state_.axis_scale[a];
    }
  }
  if (standard_deviation) {
    // w = L^-1 k by forward substitution over the packed rows.
    double* w = ws.w_.data();
    const double ww = forward_substitute(state_.cholesky.data(), k, w, n);
    // u = h - (L^-1 H)^T w, then |R^-1 u|^2 with R the mean's Cholesky factor.
    double u[1 + 2 * kMaxDims];
    for (std::size_t t = 0; t < m; ++t) u[t] = h[t] - dot_product(state_.basis_solve.data() + t * n, w, n);
    const double uu = solve_lower_packed(state_.mean_cholesky.data(), u, m);
    const double variance = std::max(0.0, s2 - ww + uu);
    *standard_deviation = std::sqrt(variance) * state_.value_scale * state_.sd_factor;
  }
  return state_.value_centre + state_.value_scale * mean;
}

double GpSurface::combination_sd(const double* points, const double* coefficients, std::size_t count,
                                 Workspace& ws) const {
  constexpr std::size_t kMaxPoints = 8;
  const std::size_t n = state_.samples, d = state_.dims, m = terms_;
  if (ws.k_.size() < n) throw std::logic_error("GpSurface: workspace made for a smaller surface");
  if (count == 0 || count > kMaxPoints) throw std::logic_error("GpSurface::combination_sd: 1 to 8 points");
  double xl[kMaxPoints][kMaxDims], hsum[1 + 2 * kMaxDims] = {};
  double* k = ws.k_.data();
  double* g = ws.g_.data();
  double* ksum = ws.sum_.data();
  std::fill(ksum, ksum + n, 0.0);
  const double s2 = state_.sigma * state_.sigma;
  for (std::size_t j = 0; j < count; ++j) {
    double z[kMaxDims], h[1 + 2 * kMaxDims];
    for (std::size_t a = 0; a < d; ++a) {
      z[a] = (points[j * d + a] - state_.axis_centre[a]) / state_.axis_scale[a];
      xl[j][a] = z[a] / state_.length_scales[a];
    }
    std::fill(k, k + n, 0.0);
    for (std::size_t a = 0; a < d; ++a) {
      const double* row = state_.points.data() + a * n;
      for (std::size_t i = 0; i < n; ++i) {
        const double delta = xl[j][a] - row[i];
        k[i] += delta * delta;
      }
    }
    kernel_values(state_.kernel, s2, k, g, n);
    const double c = coefficients[j];
    for (std::size_t i = 0; i < n; ++i) ksum[i] += c * k[i];
    mean_basis(state_.mean_degree, d, z, h);
    for (std::size_t t = 0; t < m; ++t) hsum[t] += c * h[t];
  }
  // The prior part: sum_ij c_i c_j k(x_i, x_j).
  double prior = 0.0;
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t j = 0; j < count; ++j) {
      double r2 = 0.0;
      for (std::size_t a = 0; a < d; ++a) r2 += (xl[i][a] - xl[j][a]) * (xl[i][a] - xl[j][a]);
      double c = 0.0, dc = 0.0;
      correlation(state_.kernel, r2, c, dc);
      prior += coefficients[i] * coefficients[j] * s2 * c;
    }
  double* w = ws.w_.data();
  const double ww = forward_substitute(state_.cholesky.data(), ksum, w, n);
  double u[1 + 2 * kMaxDims];
  for (std::size_t t = 0; t < m; ++t) u[t] = hsum[t] - dot_product(state_.basis_solve.data() + t * n, w, n);
  const double uu = solve_lower_packed(state_.mean_cholesky.data(), u, m);
  return std::sqrt(std::max(0.0, prior - ww + uu)) * state_.value_scale * state_.sd_factor;
}

void GpSurface::posterior(std::span<const double> points, std::size_t count, std::vector<double>& mean,
                          std::vector<double>& covariance) const {
  const std::size_t n = state_.samples, d = state_.dims, m = terms_;
  if (points.size() != count * d) throw std::logic_error("GpSurface::posterior: points do not match count x dims");
  Workspace ws(*this);
  // Per point: w = L^-1 k* (n values) and v = R^-1 u (m values), columns of W and V.
  std::vector<double> w(count * n), v(count * m), xl(count * d);
  mean.assign(count, 0.0);
  for (std::size_t j = 0; j < count; ++j) {
    const double* x = points.data() + j * d;
    double sd = 0.0;
    mean[j] = evaluate(x, ws, &sd);  // fills ws.w_ = L^-1 k*
    std::copy(ws.w_.begin(), ws.w_.begin() + static_cast<std::ptrdiff_t>(n),
              w.begin() + static_cast<std::ptrdiff_t>(j * n));
    double z[kMaxDims], h[1 + 2 * kMaxDims];
    for (std::size_t a = 0; a < d; ++a) {
      z[a] = (x[a] - state_.axis_centre[a]) / state_.axis_scale[a];
      xl[j * d + a] = z[a] / state_.length_scales[a];
    }
    mean_basis(state_.mean_degree, d, z, h);
    double* u = v.data() + j * m;
    const double* wj = w.data() + j * n;
    for (std::size_t t = 0; t < m; ++t) u[t] = h[t] - dot_product(state_.basis_solve.data() + t * n, wj, n);
    solve_lower_packed(state_.mean_cholesky.data(), u, m);
  }
  const double s2 = state_.sigma * state_.sigma;
  const double scale2 = state_.value_scale * state_.value_scale * state_.sd_factor * state_.sd_factor;
  covariance.assign(count * count, 0.0);
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t j = 0; j <= i; ++j) {
      double r2 = 0.0;
      for (std::size_t a = 0; a < d; ++a) {
        const double delta = xl[i * d + a] - xl[j * d + a];
        r2 += delta * delta;
      }
      double c = 0.0, dc = 0.0;
      correlation(state_.kernel, r2, c, dc);
      double value = s2 * c - dot_product(w.data() + i * n, w.data() + j * n, n) +
                     dot_product(v.data() + i * m, v.data() + j * m, m);
      value *= scale2;
      covariance[i * count + j] = value;
      covariance[j * count + i] = value;
    }
  }
}

void GpSurface::add_pseudo_run(const double* x) {
  const std::size_t n = state_.samples, d = state_.dims, m = terms_;
  Workspace ws(*this);
  double sd = 0.0;
  evaluate(x, ws, &sd);  // fills k (kernel vector) and w (= L^-1 k)
  const double* k = ws.k_.data();
  const double* w = ws.w_.data();
  // New row of L: [w^T, d] with d^2 = k(x,x) + jitter - w^T w.
  const double s2 = state_.sigma * state_.sigma;
  double ww = 0.0;
  for (std::size_t i = 0; i < n; ++i) ww += w[i] * w[i];
  const double diagonal2 = s2 * (1.0 + kJitter) - ww;
  const double diagonal = std::sqrt(std::max(diagonal2, s2 * kJitter));
  (void)k;
  double z[kMaxDims], h[1 + 2 * kMaxDims];
  for (std::size_t a = 0; a < d; ++a) z[a] = (x[a] - state_.axis_centre[a]) / state_.axis_scale[a];
  mean_basis(state_.mean_degree, d, z, h);
  // New row of L^-1 H: (h - (L^-1 H)^T w) / d.
  std::vector<double> q(m);
  for (std::size_t t = 0; t < m; ++t) q[t] = (h[t] - dot_product(state_.basis_solve.data() + t * n, w, n)) / diagonal;
  state_.cholesky.insert(state_.cholesky.end(), w, w + n);  // the new row
  state_.cholesky.push_back(diagonal);
  std::vector<double> basis_solve(m * (n + 1));  // terms x samples: each row gains one entry
  for (std::size_t t = 0; t < m; ++t) {
    std::copy_n(state_.basis_solve.begin() + static_cast<std::ptrdiff_t>(t * n), n,
                basis_solve.begin() + static_cast<std::ptrdiff_t>(t * (n + 1)));
    basis_solve[t * (n + 1) + n] = q[t];
  }
  state_.basis_solve = std::move(basis_solve);
  // H^T K^-1 H gains q q^T: refactorise the small matrix.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
  for (std::size_t i = 0, at = 0; i < m; ++i)
    for (std::size_t j = 0; j <= i; ++j, ++at)
      A(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = state_.mean_cholesky[at];
  const Eigen::MatrixXd R = A.triangularView<Eigen::Lower>();
  Eigen::MatrixXd AtA = R * R.transpose();
  const Eigen::Map<const Eigen::VectorXd> qv(q.data(), static_cast<Eigen::Index>(m));
  AtA += qv * qv.transpose();
  const Eigen::LLT<Eigen::MatrixXd> llt(AtA);
  const Eigen::MatrixXd Rn = llt.matrixL();
  state_.mean_cholesky.clear();
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j <= i; ++j)
      state_.mean_cholesky.push_back(Rn(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)));
  // The pseudo-run sits at the posterior mean: alpha gains a 0 and beta stays.
  std::vector<double> points(d * (n + 1));
  for (std::size_t a = 0; a < d; ++a) {
    std::copy(state_.points.begin() + static_cast<std::ptrdiff_t>(a * n),
              state_.points.begin() + static_cast<std::ptrdiff_t>((a + 1) * n),
              points.begin() + static_cast<std::ptrdiff_t>(a * (n + 1)));
    points[a * (n + 1) + n] = z[a] / state_.length_scales[a];
  }
  state_.points = std::move(points);
  state_.alpha.push_back(0.0);
  state_.samples = n + 1;
}

}  // namespace hydrocoef
