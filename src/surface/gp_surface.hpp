// Gaussian-process (kriging) coefficient surfaces: a smooth function of 1 to
// 6 axes from scattered CFD runs that also says how sure it is. The surface
// is the posterior of
//
//   f(x) = h(x)^T beta + g(x),   g ~ GP(0, k),   y_i = f(x_i) + e_i,  e_i ~ N(0, s_i^2)
//
// with h the monomials of a polynomial mean of degree 0, 1 or 2 (no cross
// terms; universal kriging: beta is estimated with the surface), k an
// anisotropic kernel of signal standard deviation sigma and one length scale
// per axis,
//
//   squared exponential:  k = sigma^2 exp(-r^2/2)
//   Matérn 5/2:           k = sigma^2 (1 + sqrt5 r + 5 r^2/3) exp(-sqrt5 r),   r^2 = sum_a ((x_a - x'_a)/l_a)^2,
//
// and s_i each run's standard uncertainty (zero for a run that states none;
// a jitter of 1e-10 sigma^2 keeps the matrix positive definite, so noise-free
// data are interpolated). Axes are first scaled by the samples' range, the
// values by their spread, as for the RBF surfaces.
//
// Hyperparameters (sigma, l_a, tau) maximise the restricted marginal
// likelihood (REML: beta integrated out). tau is a model-discrepancy (nugget)
// standard deviation added on top of each run's stated uncertainty: CFD runs
// carry mesh, iterative and model errors their histories do not show, and a
// GP that takes them as exact interpolates them and states a sigma they
// contradict. Priors: log l_a ~ N(log 0.5, 1.5^2) in axes scaled to the runs'
// span (95 % between 1/40 and 10 spans: a length scale the runs cannot
// support, such as 140 spans for a surge force over 0.2 m/s, is not taken),
// log tau ~ N(log 0.05, 3^2) (weak). The optimiser is Ceres' L-BFGS on
// log-parameters with analytic gradients, from several starts; the best is
// kept.
//
// The stated standard deviation (evaluate) is that of the latent function
// (the surface) at x, times sd_factor >= 1; what a new CFD run there would
// give scatters about the mean by run_sd (tau and the run's own uncertainty
// added in quadrature). sd_factor holds two
// corrections for what the point estimate of the hyperparameters ignores:
//   - few runs: with the signal variance estimated from n - m residual
//     degrees of freedom, the predictive distribution is Student-t with
//     n - m degrees of freedom (Santner, Williams & Notz, "The Design and
//     Analysis of Computer Experiments", Springer 2003, section 4.1); the
//     sd is scaled by t_{0.975, n-m} / z_{0.975} so that +-1.96 sd is its
//     95 % interval;
//   - the surface's own leave-one-out evidence: the standardized residuals
//     z_i = (y_i - mu_-i) / sd_-i, computed exactly from the factorisation
//     (universal kriging: e_i = alpha_i / P_ii, sd_-i^2 = 1 / P_ii with
//     P = K^-1 - K^-1 H (H^T K^-1 H)^-1 H^T K^-1; O. Dubrule, Math. Geol. 15
//     (1983) 687-699) should have an RMS of 1; when it is larger the sd is
//     scaled by it, so no sd is smaller than the runs held out show.
// The RMS and the largest |z_i| are kept as the surface's calibration.
//
// Prediction at x (Rasmussen and Williams, "Gaussian Processes for Machine
// Learning", MIT Press 2006, eq. 2.41 and section 2.7):
//
//   mean   m(x) = h^T beta + k*^T alpha,                    alpha = K^-1 (y - H beta)
//   var    v(x) = k(x,x) - w^T w + u^T (H^T K^-1 H)^-1 u,   w = L^-1 k*, u = h - (L^-1 H)^T w
//
// with K = L L^T. The variance is that of the latent function (the run noise
// is not added). A built surface never changes; evaluation is const,
// thread-safe and allocation-free given a Workspace per thread; it costs
// O(n d) for the mean and gradient and O(n^2 / 2) more for the standard
// deviation.
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace hydrocoef {

enum class GpKernel { SquaredExponential, Matern52 };

/// "squared-exponential", "matern52"; and back (InputError listing the names).
std::string_view gp_kernel_name(GpKernel kernel);
GpKernel parse_gp_kernel(std::string_view text);

struct GpOptions {
  GpKernel kernel = GpKernel::Matern52;
  int mean_degree = 1;  ///< 0, 1 or 2
  int starts = 5;       ///< optimiser starts (>= 1)
  unsigned seed = 1;    ///< for the starts after the first three
  /// Fixed hyperparameters (skip the optimisation): sigma in the values'
  /// unit, then one length scale per axis in the axis's unit, then optionally
  /// tau in the values' unit (0 when left out). Empty: estimate.
  std::vector<double> fixed_hyperparameters;
  /// Estimate the model-discrepancy sd tau (false: tau = 0, the runs' stated
  /// uncertainties alone).
  bool estimate_nugget = true;
};

/// Everything a GP surface needs to evaluate, as plain arrays: what the
/// database stores, so that loading is linear in the stored size.
struct GpState {
  GpKernel kernel = GpKernel::Matern52;
  int mean_degree = 1;
  std::size_t dims = 0, samples = 0;
  std::vector<double> axis_centre, axis_scale;   ///< per axis: z = (x - centre) / scale
  double value_centre = 0.0, value_scale = 1.0;  ///< y_scaled = (y - centre) / scale
  double sigma = 1.0;                            ///< in scaled values
  std::vector<double> length_scales;             ///< in scaled axes
  std::vector<double> points;         ///< dims x samples, axis-major, in scaled axes divided by the length scale
  std::vector<double> alpha;          ///< samples
  std::vector<double> beta;           ///< mean coefficients (scaled)
  std::vector<double> cholesky;       ///< L, packed by rows: row i holds L_i0..L_ii
  std::vector<double> basis_solve;    ///< (L^-1 H)^T: terms x samples, row-major
  std::vector<double> mean_cholesky;  ///< Cholesky factor of H^T K^-1 H, terms x terms, packed by rows
  double log_likelihood = 0.0;        ///< the REML objective at the optimum (for reports)
  double nugget = 0.0;                ///< tau, in scaled values (0: none)
  /// What the predictive sd is multiplied by (>= 1): the few-run Student-t
  /// factor times max(1, loo_rms_z).
  double sd_factor = 1.0;
  /// Leave-one-out standardized residuals: their RMS and largest magnitude
  /// (NaN for a surface stored before they were kept).
  double loo_rms_z = std::numeric_limits<double>::quiet_NaN();
  double loo_max_z = std::numeric_limits<double>::quiet_NaN();
};

/// The Student-t quantile t_{0.975, dof} (dof >= 1) over z_{0.975} = 1.96:
/// how much wider a 95 % interval is when the variance is estimated from dof
/// degrees of freedom. 1 in the limit.
double student_t_factor(std::size_t dof);

class GpSurface {
 public:
  /// Builds from `samples` runs: `x` holds dims values per run (run-major),
  /// `y` the value and `noise_sd` its standard uncertainty (>= 0; empty: all
  /// 0). InputError for too few runs for the mean (at least its terms + 1),
  /// non-finite values, two runs at one point, an axis of zero range, or a
  /// kernel matrix that cannot be factorised.
  static GpSurface fit(std::span<const double> x, std::size_t dims, std::span<const double> y,
                       std::span<const double> noise_sd, const GpOptions& options = {});

  /// From a stored state; InputError naming what is inconsistent (sizes,
  /// non-finite numbers, a non-positive diagonal).
  static GpSurface from_state(GpState state);
  const GpState& state() const { return state_; }

  std::size_t dims() const { return state_.dims; }
  std::size_t samples() const { return state_.samples; }
  /// sigma, tau and the length scales in the caller's units.
  double signal_sd() const;
  double nugget_sd() const;
  /// The standard deviation of a new CFD run's value about the mean, from the
  /// latent sd evaluate gave there and the run's own stated uncertainty:
  /// sqrt(sd^2 + (tau sd_factor)^2 + u^2).
  double run_sd(double latent_sd, double run_uncertainty = 0.0) const;
  std::vector<double> length_scales() const;

  /// Scratch space for one thread's evaluations, sized for the surface as it
  /// is (make a new one after add_pseudo_run).
  class Workspace {
   public:
    explicit Workspace(const GpSurface& surface);
    /// The largest sample count this workspace serves.
    std::size_t capacity() const noexcept { return k_.size(); }

   private:
    friend class GpSurface;
    std::vector<double> k_, w_, g_, sum_;
  };

  /// The mean at x (dims values); optionally its standard deviation (the
  /// latent function's, times sd_factor) and the gradient of the mean (dims
  /// values, the value's unit per axis unit).
  double evaluate(const double* x, Workspace& workspace, double* standard_deviation = nullptr,
                  double* gradient = nullptr) const;

  /// The standard deviation of sum_j c_j f(x_j), the latent function at
  /// `count` points (<= 8; point-major, axis units) with coefficients c,
  /// times sd_factor: sqrt(c^T C c) with C their joint posterior covariance
  /// (as posterior gives it), in one triangular solve, O(count n d + n^2/2):
  /// L^-1 is applied to sum_j c_j k*(x_j) once. What the projection of a
  /// symmetric surface states (src/surface/surface_symmetry.hpp).
  double combination_sd(const double* points, const double* coefficients, std::size_t count,
                        Workspace& workspace) const;

  /// The posterior of the latent function at `count` points jointly
  /// (`points`: count x dims, point-major, axis units): mean[j] and
  /// covariance[i * count + j] = cov(f(x_i), f(x_j)) [value unit^2],
  ///   sd_factor^2 (k(x_i, x_j) - w_i^T w_j + (R^-1 u_i)^T (R^-1 u_j))
  /// with w, u as for the standard deviation (the same variance on the
  /// diagonal). What a draw of a whole function is made from. O(count n^2).
  void posterior(std::span<const double> points, std::size_t count, std::vector<double>& mean,
                 std::vector<double>& covariance) const;

  /// Adds a pseudo-run at x whose value is the current mean (it changes no
  /// mean, only where the surface is sure): the basis of sequential design.
  /// O(n^2).
  void add_pseudo_run(const double* x);

 private:
  explicit GpSurface(GpState state);
  GpState state_;
  std::size_t terms_ = 1;
};

/// Number of mean terms of degree `degree` in `dims` axes (1, 1 + d, 1 + 2d).
std::size_t gp_mean_terms(int degree, std::size_t dims);

}  // namespace hydrocoef
