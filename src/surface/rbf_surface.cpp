#include "src/surface/rbf_surface.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "src/core/dense_decompositions.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/core/text.hpp"

namespace hydrocoef {
namespace {

// 1 + d + d(d+1)/2 monomials of degree <= 2 in d = 6 axes.
constexpr std::size_t kMaxPolynomialTerms =
    1 + RbfSurface::kMaxAxes + RbfSurface::kMaxAxes * (RbfSurface::kMaxAxes + 1) / 2;

// Below this reciprocal condition number (LU estimate) the system is treated
// as singular: its solution would carry no correct digits.
constexpr double kMinReciprocalCondition = 1e-14;
// After one step of iterative refinement, |K z - b| / (|K| |z| + |b|) in the
// max norm; a backward-stable solve gives a few ulps.
constexpr double kMaxRelativeResidual = 1e-10;
// Singular values of the polynomial matrix below this fraction of the largest
// mean the samples do not determine the polynomial.
constexpr double kMinPolynomialSingularRatio = 1e-10;
// A sample whose leverage in the polynomial matrix is this close to 1 is the
// only one fixing some polynomial direction: leaving it out is undefined.
constexpr double kUndefinedLeverage = 1.0 - 1e-9;

std::size_t polynomial_term_count(int degree, std::size_t axes) {
  std::size_t count = 1;
  if (degree >= 1) count += axes;
  if (degree >= 2) count += axes * (axes + 1) / 2;
  return count;
}

// Monomials at z: 1, z_a, z_a z_b (a <= b), in that order. derivatives (when
// not null) receives d p_j / d z_a at [j * axes + a].
void polynomial_terms(int degree, const double* z, std::size_t axes, double* values, double* derivatives) {
  std::size_t j = 0;
  values[j] = 1.0;
  if (derivatives != nullptr) std::fill_n(derivatives, polynomial_term_count(degree, axes) * axes, 0.0);
  ++j;
  if (degree >= 1) {
    for (std::size_t a = 0; a < axes; ++a, ++j) {
      values[j] = z[a];
      if (derivatives != nullptr) derivatives[j * axes + a] = 1.0;
    }
  }
  if (degree >= 2) {
    for (std::size_t a = 0; a < axes; ++a) {
      for (std::size_t b = a; b < axes; ++b, ++j) {
        values[j] = z[a] * z[b];
        if (derivatives != nullptr) {
          derivatives[j * axes + a] += z[b];
          derivatives[j * axes + b] += z[a];
        }
      }
    }
  }
}

double kernel_value(RbfKernel kernel, double r) {
  switch (kernel) {
    case RbfKernel::Cubic: return r * r * r;
    case RbfKernel::ThinPlate: return r > 0.0 ? r * r * std::log(r) : 0.0;
    case RbfKernel::Linear: return -r;
  }
  return 0.0;
}

// phi'(r) / r, so that grad_z phi(|z - z_i|) = factor * (z - z_i). At r = 0
// the gradient of r^3 and r^2 log r is 0; -r has a kink there and 0 is taken.
double kernel_gradient_factor(RbfKernel kernel, double r) {
  switch (kernel) {
    case RbfKernel::Cubic: return 3.0 * r;
    case RbfKernel::ThinPlate: return r > 0.0 ? 2.0 * std::log(r) + 1.0 : 0.0;
    case RbfKernel::Linear: return r > 0.0 ? -1.0 / r : 0.0;
  }
  return 0.0;
}

std::string_view kernel_name(RbfKernel kernel) {
  switch (kernel) {
    case RbfKernel::Cubic: return "cubic r^3";
    case RbfKernel::ThinPlate: return "thin-plate r^2 log r";
    case RbfKernel::Linear: return "linear";
  }
  return "unknown";
}

int minimum_degree(RbfKernel kernel) { return kernel == RbfKernel::Linear ? 0 : 1; }

double squared_distance(const double* a, const double* b, std::size_t axes) {
  double r2 = 0.0;
  for (std::size_t k = 0; k < axes; ++k) {
    const double diff = a[k] - b[k];
    r2 += diff * diff;
  }
  return r2;
}

// Exact duplicates, found by sorting the samples lexicographically and
// comparing neighbours (n log n rather than all pairs).
void check_distinct(std::span<const double> points, std::size_t axes, const std::vector<std::string>& labels) {
  const std::size_t n = points.size() / axes;
  const auto sample = [&](std::size_t i) { return points.subspan(i * axes, axes); };
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return std::ranges::lexicographical_compare(sample(i), sample(j)); });
  for (std::size_t s = 1; s < n; ++s) {
    const std::size_t i = std::min(order[s - 1], order[s]);
    const std::size_t j = std::max(order[s - 1], order[s]);
    if (!std::ranges::equal(sample(i), sample(j))) continue;
    std::vector<std::string> where;
    for (std::size_t a = 0; a < axes; ++a) where.push_back(labels[a] + " = " + shortest_number(points[i * axes + a]));
    throw InputError("RBF samples " + std::to_string(i) + " and " + std::to_string(j) +
                     " (0-based) are at the same point (" + join(where, ", ") +
                     "); expected distinct points (average repeated runs first)");
  }
}

// P_ij = p_j(z_i), and a check that the samples determine the polynomial
// (P has full column rank): otherwise the system is singular.
Eigen::MatrixXd polynomial_matrix(const std::vector<double>& centers, std::size_t axes, int degree,
                                  const std::vector<std::string>& labels) {
  const std::size_t n = centers.size() / axes;
  const std::size_t terms = polynomial_term_count(degree, axes);
  Eigen::MatrixXd polynomial(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(terms));
  std::array<double, kMaxPolynomialTerms> p{};
  for (std::size_t i = 0; i < n; ++i) {
    polynomial_terms(degree, &centers[i * axes], axes, p.data(), nullptr);
    for (std::size_t j = 0; j < terms; ++j)
      polynomial(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = p[j];
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd = jacobi_svd(polynomial);
  const Eigen::VectorXd& sigma = svd.singularValues();
  std::size_t rank = 0;
  for (Eigen::Index j = 0; j < sigma.size(); ++j)
    if (sigma(j) > kMinPolynomialSingularRatio * sigma(0)) ++rank;
  if (rank < terms) {
    const std::string shape = degree == 1
                                  ? "they lie on one line, plane or hyperplane (a linear relation between the axes)"
                                  : "they lie on one quadric (e.g. a circle, a parabola or two lines)";
    throw InputError("the " + std::to_string(n) + " RBF samples do not determine a degree-" + std::to_string(degree) +
                     " polynomial over " + join(labels, ", ") + ": its " + std::to_string(terms) + " terms have rank " +
                     std::to_string(rank) + " on them, so " + shape +
                     "; expected samples spread in every direction, or a lower polynomial degree");
  }
  return polynomial;
}

// [[A + lambda I, P], [P^T, 0]] with A_il = phi(|z_i - z_l|).
Eigen::MatrixXd saddle_point_system(const std::vector<double>& centers, std::size_t axes, RbfKernel kernel,
                                    double smoothing, const Eigen::MatrixXd& polynomial) {
  const Eigen::Index rows = polynomial.rows();
  const Eigen::Index terms = polynomial.cols();
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(rows + terms, rows + terms);
  for (Eigen::Index i = 0; i < rows; ++i) {
    for (Eigen::Index l = 0; l < i; ++l) {
      const double r2 = squared_distance(&centers[static_cast<std::size_t>(i) * axes],
                                         &centers[static_cast<std::size_t>(l) * axes], axes);
      system(i, l) = system(l, i) = kernel_value(kernel, std::sqrt(r2));
    }
    system(i, i) = kernel_value(kernel, 0.0) + smoothing;
  }
  system.topRightCorner(rows, terms) = polynomial;
  system.bottomLeftCorner(terms, rows) = polynomial.transpose();
  return system;
}

struct ClosestPair {
  std::size_t first = 0;
  std::size_t second = 0;
  double distance = std::numeric_limits<double>::infinity();
};

ClosestPair closest_pair(const std::vector<double>& centers, std::size_t axes) {
  const std::size_t n = centers.size() / axes;
  ClosestPair best;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t l = 0; l < i; ++l)
      if (const double r = std::sqrt(squared_distance(&centers[i * axes], &centers[l * axes], axes)); r < best.distance)
        best = {l, i, r};
  return best;
}

// Leave-one-out errors e_ik = w_ik / (K^-1)_ii (Rippa). Leaving sample i out
// is modelled by changing y_i until w_i = 0: the other equations are then
// those of the refit without sample i, which predicts y_i - e_i there,
// smoothing included (lambda multiplies w_i = 0). Undefined (NaN) for a
// sample with leverage 1 in P: without it the others do not determine the
// polynomial.
/// The summary of leave-one-out errors (sample-major, NaN for a sample
/// whose error is undefined): per output the max |error| and the RMS over
/// the samples where it is defined (NaN when there are none), and the count
/// of undefined samples.
RbfCrossValidation summarize_leave_one_out(std::vector<double> errors, std::size_t outputs) {
  RbfCrossValidation cv;
  cv.errors = std::move(errors);
  cv.max_abs.assign(outputs, 0.0);
  cv.rms.assign(outputs, 0.0);
  std::size_t defined = 0;
  for (std::size_t i = 0; i * outputs < cv.errors.size(); ++i) {
    const double* e = &cv.errors[i * outputs];
    if (std::isnan(e[0])) {
      ++cv.undefined_count;
      continue;
    }
    ++defined;
    for (std::size_t k = 0; k < outputs; ++k) {
      cv.max_abs[k] = std::max(cv.max_abs[k], std::abs(e[k]));
      cv.rms[k] += e[k] * e[k];
    }
  }
  for (std::size_t k = 0; k < outputs; ++k) {
    cv.rms[k] =
        defined > 0 ? std::sqrt(cv.rms[k] / static_cast<double>(defined)) : std::numeric_limits<double>::quiet_NaN();
    if (defined == 0) cv.max_abs[k] = std::numeric_limits<double>::quiet_NaN();
  }
  return cv;
}

RbfCrossValidation leave_one_out(const Eigen::PartialPivLU<Eigen::MatrixXd>& lu, const Eigen::MatrixXd& solution,
                                 const Eigen::MatrixXd& polynomial) {
  const Eigen::Index rows = polynomial.rows();
  const Eigen::Index terms = polynomial.cols();
  const auto outputs = static_cast<std::size_t>(solution.cols());
  const Eigen::MatrixXd inverse = lu.inverse();
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(polynomial);
  const Eigen::MatrixXd thin_q = qr.householderQ() * Eigen::MatrixXd::Identity(rows, terms);

  std::vector<double> errors(static_cast<std::size_t>(rows) * outputs, std::numeric_limits<double>::quiet_NaN());
  for (Eigen::Index i = 0; i < rows; ++i) {
    if (thin_q.row(i).squaredNorm() > kUndefinedLeverage) continue;  // undefined: stays NaN
    for (std::size_t k = 0; k < outputs; ++k)
      errors[static_cast<std::size_t>(i) * outputs + k] = solution(i, static_cast<Eigen::Index>(k)) / inverse(i, i);
  }
  return summarize_leave_one_out(std::move(errors), outputs);
}

}  // namespace

RbfSurface::RbfSurface(std::size_t axis_count, std::span<const double> points, std::size_t output_count,
                       std::span<const double> values, const RbfOptions& options)
    : axis_count_(axis_count),
      output_count_(output_count),
      kernel_(options.kernel),
      polynomial_degree_(options.polynomial_degree),
      smoothing_(options.smoothing) {
  prepare(points, values, options);
  solve(values);
}

RbfSurface::RbfSurface(std::size_t axis_count, std::span<const double> points, std::size_t output_count,
                       std::span<const double> values, const RbfOptions& options, const RbfSolution& solution)
    : axis_count_(axis_count),
      output_count_(output_count),
      kernel_(options.kernel),
      polynomial_degree_(options.polynomial_degree),
      smoothing_(options.smoothing) {
  prepare(points, values, options);
  const std::size_t n = sample_count_;
  const auto expect = [](std::string_view what, std::size_t found, std::size_t expected) {
    if (found != expected)
      throw InputError("RBF solution has " + std::to_string(found) + " " + std::string(what) + "; expected " +
                       std::to_string(expected));
  };
  expect("kernel weights", solution.kernel_weights.size(), n * output_count_);
  expect("polynomial weights", solution.polynomial_weights.size(), polynomial_terms_ * output_count_);
  expect("leave-one-out errors", solution.loo_errors.size(), n * output_count_);
  for (const double w : solution.kernel_weights)
    if (!std::isfinite(w)) throw InputError("RBF solution has a kernel weight that is not finite");
  for (const double w : solution.polynomial_weights)
    if (!std::isfinite(w)) throw InputError("RBF solution has a polynomial weight that is not finite");
  // A sample's errors are all NaN (undefined) or all finite.
  for (std::size_t i = 0; i < n; ++i) {
    const double* e = &solution.loo_errors[i * output_count_];
    for (std::size_t k = 0; k < output_count_; ++k)
      if (std::isnan(e[0]) ? !std::isnan(e[k]) : !std::isfinite(e[k]))
        throw InputError("RBF solution has a leave-one-out error that is not finite");
  }
  kernel_weights_ = solution.kernel_weights;
  polynomial_weights_ = solution.polynomial_weights;
  cross_validation_ = summarize_leave_one_out(solution.loo_errors, output_count_);
}

RbfSolution RbfSurface::solution() const { return {kernel_weights_, polynomial_weights_, cross_validation_.errors}; }

void RbfSurface::prepare(std::span<const double> points, std::span<const double> values, const RbfOptions& options) {
  const std::size_t d = axis_count_;
  const std::size_t output_count = output_count_;
  if (d < 1 || d > kMaxAxes)
    throw InputError("RBF surface over " + std::to_string(d) + " axes; expected 1 to " + std::to_string(kMaxAxes));
  if (output_count < 1) throw InputError("RBF surface with 0 outputs; expected at least 1 output per sample");

  if (!options.axis_names.empty() && options.axis_names.size() != d)
    throw InputError("RBF surface got " + std::to_string(options.axis_names.size()) + " axis names for " +
                     std::to_string(d) + " axes; expected one name per axis or none");
  for (std::size_t a = 0; a < d; ++a)
    axis_labels_.push_back(options.axis_names.empty() ? "axis " + std::to_string(a)
                                                      : "axis '" + options.axis_names[a] + "'");

  if (points.size() % d != 0)
    throw InputError("RBF surface got " + std::to_string(points.size()) + " coordinates for " + std::to_string(d) +
                     " axes; expected a whole number of points (samples x axes)");
  const std::size_t n = points.size() / d;
  sample_count_ = n;
  if (n > kMaxSamples)
    throw InputError("RBF surface of " + std::to_string(n) +
                     " samples; this hydrocoef builds RBF surfaces of at most " + std::to_string(kMaxSamples) +
                     " samples (a dense solve: O(N^3) time and O(N^2) memory); expected "
                     "fewer samples (select runs with --where) or a gridded surface");
  if (values.size() != n * output_count)
    throw InputError("RBF surface got " + std::to_string(values.size()) + " values for " + std::to_string(n) +
                     " samples of " + std::to_string(output_count) + " outputs; expected " +
                     std::to_string(n * output_count));

  if (polynomial_degree_ < 0 || polynomial_degree_ > 2)
    throw InputError("RBF polynomial degree " + std::to_string(polynomial_degree_) + "; expected 0, 1 or 2");
  if (polynomial_degree_ < minimum_degree(kernel_))
    throw InputError("RBF polynomial degree " + std::to_string(polynomial_degree_) + " with the " +
                     std::string(kernel_name(kernel_)) +
                     " kernel; expected degree >= " + std::to_string(minimum_degree(kernel_)) +
                     " (the kernel is conditionally positive definite of order 2, so a lower degree does "
                     "not make the system uniquely solvable), or the linear kernel");
  if (!std::isfinite(smoothing_) || smoothing_ < 0.0)
    throw InputError("RBF smoothing " + shortest_number(smoothing_) +
                     "; expected a finite value >= 0 (0 interpolates)");
  if (!options.length_scales.empty() && options.length_scales.size() != d)
    throw InputError("RBF surface got " + std::to_string(options.length_scales.size()) + " length scales for " +
                     std::to_string(d) + " axes; expected one per axis or none");
  if (!options.out_of_range.empty() && options.out_of_range.size() != d)
    throw InputError("RBF surface got " + std::to_string(options.out_of_range.size()) + " out-of-range policies for " +
                     std::to_string(d) + " axes; expected one per axis or none");

  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t a = 0; a < d; ++a)
      if (!std::isfinite(points[i * d + a]))
        throw InputError("RBF sample " + std::to_string(i) + " (0-based) has " + axis_labels_[a] + " = " +
                         shortest_number(points[i * d + a]) + "; expected a finite coordinate");
    for (std::size_t k = 0; k < output_count; ++k)
      if (!std::isfinite(values[i * output_count + k]))
        throw InputError("RBF sample " + std::to_string(i) + " (0-based) has output " + std::to_string(k) + " = " +
                         shortest_number(values[i * output_count + k]) + "; expected a finite value");
  }

  polynomial_terms_ = polynomial_term_count(polynomial_degree_, d);
  if (n < polynomial_terms_)
    throw InputError("RBF surface with a degree-" + std::to_string(polynomial_degree_) + " polynomial over " +
                     std::to_string(d) + " axes has " + std::to_string(polynomial_terms_) +
                     " polynomial terms and needs at least that many samples, found " + std::to_string(n));

  // Ranges and scaling.
  for (std::size_t a = 0; a < d; ++a) {
    double low = points[a];
    double high = points[a];
    for (std::size_t i = 1; i < n; ++i) {
      low = std::min(low, points[i * d + a]);
      high = std::max(high, points[i * d + a]);
    }
    if (!(high > low))
      throw InputError("RBF " + axis_labels_[a] + " has the same value " + shortest_number(low) + " at all " +
                       std::to_string(n) +
                       " samples; expected samples spread along every axis (leave out an axis "
                       "that does not vary)");
    lower_[a] = low;
    upper_[a] = high;
    midpoint_[a] = 0.5 * (low + high);
    if (options.length_scales.empty()) {
      scale_[a] = high - low;
    } else {
      scale_[a] = options.length_scales[a];
      if (!std::isfinite(scale_[a]) || !(scale_[a] > 0.0))
        throw InputError("RBF length scale " + shortest_number(scale_[a]) + " for " + axis_labels_[a] +
                         "; expected a finite value > 0 in the axis's unit");
    }
    policy_[a] = options.out_of_range.empty() ? RbfOutOfRange::Error : options.out_of_range[a];
  }

  check_distinct(points, d, axis_labels_);

  centers_.resize(n * d);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t a = 0; a < d; ++a) centers_[i * d + a] = (points[i * d + a] - midpoint_[a]) / scale_[a];
}

void RbfSurface::solve(std::span<const double> values) {
  const std::size_t d = axis_count_;
  const std::size_t n = sample_count_;
  const std::size_t output_count = output_count_;

  // The system in scaled coordinates; one factorization for all outputs.
  const Eigen::MatrixXd polynomial = polynomial_matrix(centers_, d, polynomial_degree_, axis_labels_);
  const Eigen::MatrixXd system = saddle_point_system(centers_, d, kernel_, smoothing_, polynomial);
  const auto rows = static_cast<Eigen::Index>(n);
  const auto outputs = static_cast<Eigen::Index>(output_count);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(system.rows(), outputs);
  rhs.topRows(rows) = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      values.data(), rows, outputs);

  const auto throw_singular = [&](const std::string& why) {
    const ClosestPair pair = closest_pair(centers_, d);  // near-duplicate samples are the usual cause
    throw InputError("RBF system for " + std::to_string(n) + " samples is numerically singular (" + why +
                     "); the closest samples are " + std::to_string(pair.first) + " and " +
                     std::to_string(pair.second) + " (0-based) at scaled distance " + shortest_number(pair.distance) +
                     "; expected well-separated samples, or smoothing > 0");
  };
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(system);
  if (const double rcond = lu.rcond(); !(rcond >= kMinReciprocalCondition))
    throw_singular("reciprocal condition number " + shortest_number(rcond));
  Eigen::MatrixXd solution = lu.solve(rhs);
  solution += lu.solve(rhs - system * solution);  // one step of iterative refinement
  const double residual = (rhs - system * solution).cwiseAbs().maxCoeff();
  const double residual_scale =
      system.cwiseAbs().rowwise().sum().maxCoeff() * solution.cwiseAbs().maxCoeff() + rhs.cwiseAbs().maxCoeff();
  if (residual_scale > 0.0 && !(residual <= kMaxRelativeResidual * residual_scale))
    throw_singular("relative residual " + shortest_number(residual / residual_scale));

  kernel_weights_.resize(n * output_count);
  polynomial_weights_.resize(polynomial_terms_ * output_count);
  for (Eigen::Index k = 0; k < outputs; ++k) {
    for (Eigen::Index i = 0; i < rows; ++i)
      kernel_weights_[static_cast<std::size_t>(i) * output_count + static_cast<std::size_t>(k)] = solution(i, k);
    for (Eigen::Index j = 0; j < polynomial.cols(); ++j)
      polynomial_weights_[static_cast<std::size_t>(j) * output_count + static_cast<std::size_t>(k)] =
          solution(rows + j, k);
  }
  cross_validation_ = leave_one_out(lu, solution, polynomial);
}

std::size_t RbfSurface::checked(std::size_t axis) const {
  if (axis >= axis_count_)
    throw std::out_of_range("RBF surface axis " + std::to_string(axis) + " of " + std::to_string(axis_count_));
  return axis;
}

void RbfSurface::evaluate(std::span<const double> point, std::span<double> out) const {
  evaluate_at(point, out, nullptr);
}

void RbfSurface::evaluate_with_gradient(std::span<const double> point, std::span<double> out,
                                        std::span<double> gradient) const {
  if (gradient.size() != output_count_ * axis_count_)
    throw std::invalid_argument("RBF gradient buffer has " + std::to_string(gradient.size()) + " values; expected " +
                                std::to_string(output_count_) + " outputs x " + std::to_string(axis_count_) +
                                " axes = " + std::to_string(output_count_ * axis_count_));
  evaluate_at(point, out, gradient.data());
}

void RbfSurface::evaluate_at(std::span<const double> point, std::span<double> out, double* gradient) const {
  const std::size_t d = axis_count_;
  const std::size_t outputs = output_count_;
  if (point.size() != d)
    throw InputError("RBF query point has " + std::to_string(point.size()) + " coordinates; the surface has " +
                     std::to_string(d) + " axes");
  if (out.size() != outputs)
    throw std::invalid_argument("RBF output buffer has " + std::to_string(out.size()) + " values; the surface has " +
                                std::to_string(outputs) + " outputs");

  std::array<double, kMaxAxes> z{};
  std::array<bool, kMaxAxes> clamped{};
  for (std::size_t a = 0; a < d; ++a) {
    double x = point[a];
    if (!std::isfinite(x))
      throw InputError("RBF query has " + axis_labels_[a] + " = " + shortest_number(x) + "; expected a finite value");
    if (x < lower_[a] || x > upper_[a]) {
      switch (policy_[a]) {
        case RbfOutOfRange::Error:
          throw InputError("RBF query " + axis_labels_[a] + " = " + shortest_number(x) +
                           " is outside the samples' range [" + shortest_number(lower_[a]) + ", " +
                           shortest_number(upper_[a]) +
                           "]; expected a value within it (or --extrapolate clamp or extrapolate for that axis)");
        case RbfOutOfRange::Clamp:
          x = std::clamp(x, lower_[a], upper_[a]);
          clamped[a] = true;
          break;
        case RbfOutOfRange::Extrapolate: break;
      }
    }
    z[a] = (x - midpoint_[a]) / scale_[a];
  }

  std::fill(out.begin(), out.end(), 0.0);
  if (gradient != nullptr) std::fill_n(gradient, outputs * d, 0.0);

  std::array<double, kMaxAxes> diff{};
  for (std::size_t i = 0; i < sample_count_; ++i) {
    const double* center = &centers_[i * d];
    double r2 = 0.0;
    for (std::size_t a = 0; a < d; ++a) {
      diff[a] = z[a] - center[a];
      r2 += diff[a] * diff[a];
    }
    const double r = std::sqrt(r2);
    const double phi = kernel_value(kernel_, r);
    const double* w = &kernel_weights_[i * outputs];
    for (std::size_t k = 0; k < outputs; ++k) out[k] += phi * w[k];
    if (gradient != nullptr) {
      const double factor = kernel_gradient_factor(kernel_, r);
      for (std::size_t k = 0; k < outputs; ++k) {
        const double scaled = factor * w[k];
        for (std::size_t a = 0; a < d; ++a) gradient[k * d + a] += scaled * diff[a];
      }
    }
  }

  std::array<double, kMaxPolynomialTerms> p{};
  std::array<double, kMaxPolynomialTerms * kMaxAxes> dp{};
  polynomial_terms(polynomial_degree_, z.data(), d, p.data(), gradient != nullptr ? dp.data() : nullptr);
  for (std::size_t j = 0; j < polynomial_terms_; ++j) {
    const double* c = &polynomial_weights_[j * outputs];
    for (std::size_t k = 0; k < outputs; ++k) {
      out[k] += p[j] * c[k];
      if (gradient != nullptr)
        for (std::size_t a = 0; a < d; ++a) gradient[k * d + a] += dp[j * d + a] * c[k];
    }
  }

  if (gradient != nullptr)
    for (std::size_t k = 0; k < outputs; ++k)
      for (std::size_t a = 0; a < d; ++a) gradient[k * d + a] = clamped[a] ? 0.0 : gradient[k * d + a] / scale_[a];
}

double RbfSurface::nearest_sample_distance(std::span<const double> point) const {
  const std::size_t d = axis_count_;
  if (point.size() != d)
    throw InputError("RBF query point has " + std::to_string(point.size()) + " coordinates; the surface has " +
                     std::to_string(d) + " axes");
  std::array<double, kMaxAxes> z{};
  for (std::size_t a = 0; a < d; ++a) {
    if (!std::isfinite(point[a]))
      throw InputError("RBF query has " + axis_labels_[a] + " = " + shortest_number(point[a]) +
                       "; expected a finite value");
    z[a] = (point[a] - midpoint_[a]) / scale_[a];
  }
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < sample_count_; ++i) {
    double r2 = 0.0;
    for (std::size_t a = 0; a < d; ++a) {
      const double diff = z[a] - centers_[i * d + a];
      r2 += diff * diff;
    }
    best = std::min(best, r2);
  }
  return std::sqrt(best);
}

RbfGrid RbfSurface::resample(const std::vector<std::vector<double>>& breakpoints, double far_threshold) const {
  const std::size_t d = axis_count_;
  if (breakpoints.size() != d)
    throw InputError("RBF resampling got breakpoints for " + std::to_string(breakpoints.size()) +
                     " axes; the surface has " + std::to_string(d));
  if (std::isnan(far_threshold) || far_threshold < 0.0)
    throw InputError("RBF far-from-data threshold " + shortest_number(far_threshold) +
                     "; expected a value >= 0 in scaled units (fractions of the samples' range)");
  std::size_t grid_points = 1;
  for (std::size_t a = 0; a < d; ++a) {
    const auto& axis = breakpoints[a];
    if (axis.empty())
      throw InputError("RBF resampling: no breakpoints on " + axis_labels_[a] + "; expected at least 1");
    for (std::size_t b = 0; b < axis.size(); ++b) {
      if (!std::isfinite(axis[b]))
        throw InputError("RBF resampling: breakpoint " + std::to_string(b) + " on " + axis_labels_[a] + " is " +
                         shortest_number(axis[b]) + "; expected finite values");
      if (b > 0 && !(axis[b] > axis[b - 1]))
        throw InputError("RBF resampling: breakpoints on " + axis_labels_[a] + " go from " +
                         shortest_number(axis[b - 1]) + " to " + shortest_number(axis[b]) + " at index " +
                         std::to_string(b) + "; expected strictly increasing values");
    }
    grid_points *= axis.size();
  }

  RbfGrid grid;
  grid.breakpoints = breakpoints;
  grid.far_threshold = far_threshold;
  grid.values.resize(grid_points * output_count_);
  grid.nearest_sample_distance.resize(grid_points);
  std::array<std::size_t, kMaxAxes> index{};
  std::array<double, kMaxAxes> point{};
  for (std::size_t g = 0; g < grid_points; ++g) {
    for (std::size_t a = 0; a < d; ++a) point[a] = breakpoints[a][index[a]];
    const std::span<const double> here(point.data(), d);
    evaluate_at(here, std::span<double>(grid.values.data() + g * output_count_, output_count_), nullptr);
    const double distance = nearest_sample_distance(here);
    grid.nearest_sample_distance[g] = distance;
    if (distance > far_threshold) grid.far_from_data.push_back(g);
    // Odometer step, axis 0 fastest.
    for (std::size_t a = 0; a < d; ++a) {
      if (++index[a] < breakpoints[a].size()) break;
      index[a] = 0;
    }
  }
  return grid;
}

}  // namespace hydrocoef
