#include "src/fit/damping_law.hpp"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "src/core/dense_decompositions.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/core/text.hpp"

namespace hydrocoef {
namespace {

// A law has each DampingTerm at most once.
constexpr std::size_t kMaxTerms = 6;
// What a loss text may hold around and inside its parts.
constexpr std::string_view kLossBlanks = " \t\r\n";
constexpr std::string_view kAcceptedLosses =
    "expected 'squared', 'huber:SCALE', 'cauchy:SCALE' or 'soft-l1:SCALE' with SCALE > 0 in the force's unit";

// Ceres' covariance calls J rank-deficient when sigma_min/sigma_max falls below
// this; the up-front check uses the same limit so both agree on what is degenerate.
constexpr double kMinReciprocalConditionNumber = 1e-14;
const double kMinSingularValueRatio = std::sqrt(kMinReciprocalConditionNumber);

std::string term_list(const DampingLawSpec& spec, const std::vector<std::size_t>& which) {
  std::string out;
  for (std::size_t j : which) {
    if (!out.empty()) out += ", ";
    out += term_name(spec.terms[j], spec.variable);
  }
  return out;
}

std::vector<std::size_t> all_indices(std::size_t count) {
  std::vector<std::size_t> out(count);
  for (std::size_t j = 0; j < count; ++j) out[j] = j;
  return out;
}

// One run's contribution r = sum_j c_j b_j(x) - y. The basis row is scaled by
// the design matrix's column norms so that the solver and the covariance see
// unit-norm columns whatever the units and sizes of the terms.
class ObservationResidual final : public ceres::CostFunction {
 public:
  ObservationResidual(const double* scaled_basis_row, std::size_t term_count, double observed)
      : term_count_(term_count), observed_(observed) {
    std::copy_n(scaled_basis_row, term_count, scaled_basis_.begin());
    set_num_residuals(1);
    mutable_parameter_block_sizes()->push_back(static_cast<int>(term_count));
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    double predicted = 0.0;
    for (std::size_t j = 0; j < term_count_; ++j) predicted += parameters[0][j] * scaled_basis_[j];
    residuals[0] = predicted - observed_;
    if (jacobians != nullptr && jacobians[0] != nullptr) std::copy_n(scaled_basis_.begin(), term_count_, jacobians[0]);
    return true;
  }

 private:
  std::array<double, kMaxTerms> scaled_basis_{};
  std::size_t term_count_;
  double observed_;
};

std::unique_ptr<ceres::LossFunction> make_loss(const LossOptions& options) {
  switch (options.loss) {
    case LossKind::Squared: return nullptr;
    case LossKind::Huber: return std::make_unique<ceres::HuberLoss>(options.loss_scale);
    case LossKind::Cauchy: return std::make_unique<ceres::CauchyLoss>(options.loss_scale);
    case LossKind::SoftLOne: return std::make_unique<ceres::SoftLOneLoss>(options.loss_scale);
  }
  throw std::invalid_argument("make_loss: unknown LossKind");
}

struct ScaledSolution {
  Eigen::VectorXd coefficients;
  Eigen::MatrixXd covariance;  // (J^T W J)^-1 in scaled coordinates; empty unless asked for
  bool covariance_ok = false;
};

ScaledSolution solve(const Eigen::MatrixXd& scaled_design, std::span<const double> y, ceres::LossFunction* loss,
                     const Eigen::VectorXd& start, bool want_covariance) {
  const auto term_count = static_cast<std::size_t>(scaled_design.cols());
  // Row-major copy so that each residual can read its basis row contiguously.
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rows = scaled_design;

  ScaledSolution solution{start, {}, false};
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;  // one loss shared by all runs
  ceres::Problem problem(problem_options);
  double* parameters = solution.coefficients.data();
  problem.AddParameterBlock(parameters, static_cast<int>(term_count));
  for (Eigen::Index i = 0; i < rows.rows(); ++i)
    problem.AddResidualBlock(new ObservationResidual(rows.row(i).data(), term_count, y[static_cast<std::size_t>(i)]),
                             loss, parameters);

  // The problem is linear (or IRLS-like for robust losses), so tight
  // tolerances cost a few iterations and make the answer match a direct solve.
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.function_tolerance = 1e-15;
  options.gradient_tolerance = 1e-15;
  options.parameter_tolerance = 1e-14;
  options.max_num_iterations = 500;
  // Levenberg-Marquardt damping would only slow a linear problem down: start
  // from (almost) Gauss-Newton and let the trust region shrink if a robust loss needs it.
  options.initial_trust_region_radius = 1e12;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (!summary.IsSolutionUsable())
    throw std::runtime_error("damping law fit: Ceres found no usable solution: " + summary.message);

  if (want_covariance) {
    ceres::Covariance::Options covariance_options;
    covariance_options.algorithm_type = ceres::DENSE_SVD;
    covariance_options.min_reciprocal_condition_number = kMinReciprocalConditionNumber;
    covariance_options.num_threads = 1;
    ceres::Covariance covariance(covariance_options);
    const std::vector<std::pair<const double*, const double*>> blocks = {{parameters, parameters}};
    if (covariance.Compute(blocks, &problem)) {
      Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> block(term_count, term_count);
      covariance.GetCovarianceBlock(parameters, parameters, block.data());
      solution.covariance = block;
      solution.covariance_ok = true;
    }
  }
  return solution;
}

[[noreturn]] void throw_dependent_terms(const DampingLawSpec& spec, const std::vector<std::size_t>& which,
                                        std::span<const double> x) {
  std::string detail;
  if (std::all_of(x.begin(), x.end(), [&](double value) { return value == x.front(); }))
    detail = " (all " + std::to_string(x.size()) + " values of " + spec.variable + " are " +
             shortest_number(x.front()) + ")";
  if (which.size() == 1)
    throw InputError("damping term '" + term_list(spec, which) + "' is zero at every one of the " +
                     std::to_string(x.size()) + " runs" + detail +
                     ", so its coefficient cannot be fitted; expected runs where it is not zero");
  throw InputError("damping terms " + term_list(spec, which) + " are linearly dependent on these " +
                   std::to_string(x.size()) + " runs" + detail +
                   ", so their coefficients cannot be told apart; expected runs over a range of " + spec.variable +
                   " that separates them, or fewer terms");
}

// Terms that take part in a (near) null vector of the scaled design matrix;
// empty when the columns are independent.
std::vector<std::size_t> dependent_terms(const Eigen::MatrixXd& scaled_design) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd = jacobi_svd(scaled_design, Eigen::ComputeFullV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  const Eigen::Index k = scaled_design.cols();
  std::vector<std::size_t> which;
  if (sigma.size() < k) return all_indices(static_cast<std::size_t>(k));
  for (Eigen::Index j = 0; j < k; ++j) {
    bool involved = false;
    for (Eigen::Index s = 0; s < k; ++s)
      if (!(sigma(s) > kMinSingularValueRatio * sigma(0)) && std::abs(svd.matrixV()(j, s)) > 1e-3) involved = true;
    if (involved) which.push_back(static_cast<std::size_t>(j));
  }
  return which;
}

}  // namespace

LossOptions parse_loss(std::string_view text) {
  const std::string spelled = without_blanks(text, kLossBlanks);
  if (spelled == "squared") return {};

  const auto colon = spelled.find(':');
  const std::string name = spelled.substr(0, colon);
  LossOptions options;
  if (name == "huber") {
    options.loss = LossKind::Huber;
  } else if (name == "cauchy") {
    options.loss = LossKind::Cauchy;
  } else if (name == "soft-l1") {
    options.loss = LossKind::SoftLOne;
  } else {
    throw InputError("unknown loss '" + std::string(text) + "': " + std::string(kAcceptedLosses));
  }
  if (colon == std::string::npos)
    throw InputError("loss '" + std::string(text) + "' has no scale: " + std::string(kAcceptedLosses));

  const char* first = spelled.data() + colon + 1;
  const char* last = spelled.data() + spelled.size();
  auto [end, ec] = std::from_chars(first, last, options.loss_scale);
  if (ec != std::errc() || end != last || first == last || !std::isfinite(options.loss_scale) ||
      !(options.loss_scale > 0.0))
    throw InputError("bad scale in loss '" + std::string(text) + "': " + std::string(kAcceptedLosses));
  return options;
}

std::string format_loss(const LossOptions& options) {
  switch (options.loss) {
    case LossKind::Squared: return "squared";
    case LossKind::Huber: return "huber:" + shortest_number(options.loss_scale);
    case LossKind::Cauchy: return "cauchy:" + shortest_number(options.loss_scale);
    case LossKind::SoftLOne: return "soft-l1:" + shortest_number(options.loss_scale);
  }
  throw std::invalid_argument("format_loss: unknown LossKind");
}

double DampingLawFit::evaluate(double x) const { return damping_law_value(spec.terms, coefficients, x); }

DampingLawFit fit_damping_law(const DampingLawSpec& spec, std::span<const double> x, std::span<const double> y,
                              const LossOptions& options, std::span<const double> sigma) {
  check_damping_law_spec(spec);
  if (options.loss != LossKind::Squared && !(std::isfinite(options.loss_scale) && options.loss_scale > 0.0))
    throw InputError("loss scale " + shortest_number(options.loss_scale) +
                     " for a robust loss: expected a finite scale > 0 "
                     "in the force's unit");
  if (x.size() != y.size())
    throw InputError("damping law fit got " + std::to_string(x.size()) + " velocity values but " +
                     std::to_string(y.size()) + " force values; expected one of each per run");
  const std::size_t n = x.size();
  const std::size_t k = spec.terms.size();
  if (n < k)
    throw InputError("damping law '" + format_damping_terms(spec) + "' has " + std::to_string(k) +
                     " terms and needs at least " + std::to_string(k) + " runs, found " + std::to_string(n));
  if (!sigma.empty() && sigma.size() != n)
    throw InputError("damping law fit got " + std::to_string(sigma.size()) + " uncertainties for " + std::to_string(n) +
                     " runs; expected one per run or none");
  for (std::size_t i = 0; i < sigma.size(); ++i)
    if (!std::isfinite(sigma[i]) || !(sigma[i] > 0.0))
      throw InputError("run " + std::to_string(i + 1) + " of " + std::to_string(n) + " has uncertainty " +
                       shortest_number(sigma[i]) + "; a weighted fit needs each run's uncertainty finite and > 0");
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(x[i]) || !std::isfinite(y[i]))
      throw InputError("run " + std::to_string(i + 1) + " of " + std::to_string(n) + " has " + spec.variable + " = " +
                       shortest_number(x[i]) + ", force = " + shortest_number(y[i]) + "; expected finite values");

  // The fit is made in units of the largest |x| and the largest |y|, so that
  // no power of a velocity and no square of a force over- or underflows
  // (velocities of 1e308 or 5e-324 m/s, forces of 1e308 N); the coefficients
  // are turned back at the end, and refused if they do not fit a double.
  double x_scale = 0.0, y_scale = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    x_scale = std::max(x_scale, std::abs(x[i]));
    y_scale = std::max(y_scale, std::abs(y[i]));
  }
  if (x_scale == 0.0) x_scale = 1.0;
  if (y_scale == 0.0) y_scale = 1.0;
  // A weighted fit is the unweighted one of the rows divided by sigma_i
  // (in units of y_scale): residuals r_i / sigma_i.
  const bool weighted = !sigma.empty();
  std::vector<double> row_weight(n, 1.0);
  if (weighted)
    for (std::size_t i = 0; i < n; ++i) row_weight[i] = y_scale / sigma[i];
  std::vector<double> y_scaled(n);
  for (std::size_t i = 0; i < n; ++i) y_scaled[i] = y[i] / y_scale * row_weight[i];

  const auto rows = static_cast<Eigen::Index>(n);
  const auto cols = static_cast<Eigen::Index>(k);
  Eigen::MatrixXd design(rows, cols);
  for (Eigen::Index i = 0; i < rows; ++i)
    for (Eigen::Index j = 0; j < cols; ++j)
      design(i, j) = basis_value(spec.terms[static_cast<std::size_t>(j)], x[static_cast<std::size_t>(i)] / x_scale) *
                     row_weight[static_cast<std::size_t>(i)];
  // An all-zero column keeps scale 1; the rank check below reports it.
  const Eigen::VectorXd column_norm = design.colwise().norm().transpose();
  const Eigen::VectorXd column_scale = (column_norm.array() > 0.0).select(column_norm, 1.0);
  const Eigen::MatrixXd scaled_design = design * column_scale.cwiseInverse().asDiagonal();
  if (const auto which = dependent_terms(scaled_design); !which.empty()) throw_dependent_terms(spec, which, x);

  // A robust loss's scale is in the force's unit: in units of y_scale here.
  LossOptions scaled_options = options;
  scaled_options.loss_scale = options.loss_scale / y_scale;
  const auto loss = make_loss(scaled_options);
  ScaledSolution solution = solve(scaled_design, y_scaled, nullptr, Eigen::VectorXd::Zero(cols), loss == nullptr);
  if (loss != nullptr) solution = solve(scaled_design, y_scaled, loss.get(), solution.coefficients, true);
  if (!solution.covariance_ok) throw_dependent_terms(spec, all_indices(k), x);

  const Eigen::Map<const Eigen::VectorXd> observed(y_scaled.data(), rows);
  const Eigen::VectorXd residuals = scaled_design * solution.coefficients - observed;  // weighted: r_i / sigma_i
  // R^2 and RMSE of the unweighted residuals (in units of y_scale).
  const Eigen::Map<const Eigen::VectorXd> weights(row_weight.data(), rows);
  const Eigen::VectorXd plain_residuals = residuals.cwiseQuotient(weights);
  const Eigen::VectorXd plain_observed = observed.cwiseQuotient(weights);
  const double ssr = plain_residuals.squaredNorm();
  const double sst = (plain_observed.array() - plain_observed.mean()).matrix().squaredNorm();

  // The covariance Ceres reports already carries the robust weights W, so the
  // residual variance is the weighted one that goes with it.
  double weighted_ssr = residuals.squaredNorm();
  if (loss != nullptr) {
    weighted_ssr = 0.0;
    for (Eigen::Index i = 0; i < rows; ++i) {
      std::array<double, 3> rho{};
      const double r_squared = residuals(i) * residuals(i);
      loss->Evaluate(r_squared, rho.data());
      weighted_ssr += rho[1] * r_squared;
    }
  }
  const double residual_variance =
      n > k ? weighted_ssr / static_cast<double>(n - k) : std::numeric_limits<double>::quiet_NaN();
  // Weighted: the covariance of the stated uncertainties, scaled by the
  // Birge ratio squared, chi^2 / (n - k), when the runs scatter more than
  // they say (the Particle Data Group's scale factor S; never scaled down).
  const double chi2_reduced =
      n > k ? residuals.squaredNorm() / static_cast<double>(n - k) : std::numeric_limits<double>::quiet_NaN();
  const double birge_squared = weighted && std::isfinite(chi2_reduced) ? std::max(1.0, chi2_reduced) : 1.0;
  const double covariance_factor = weighted ? birge_squared : residual_variance;

  DampingLawFit fit;
  fit.spec = spec;
  fit.n = n;
  fit.loss = format_loss(options);
  fit.weighted = weighted;
  if (weighted && n > k) fit.chi2_reduced = chi2_reduced;
  fit.covariance_scale = birge_squared;
  fit.rmse = std::sqrt(ssr / static_cast<double>(n)) * y_scale;
  fit.r2 = sst > 0.0 ? 1.0 - ssr / sst : std::numeric_limits<double>::quiet_NaN();
  for (Eigen::Index j = 0; j < cols; ++j) {
    const DampingTerm term = spec.terms[static_cast<std::size_t>(j)];
    // c_j in the law's units: (c_scaled / column) * y_scale / x_scale^power,
    // divided one factor at a time so that no intermediate overflows early.
    const auto to_law_units = [&](double value) {
      value = value / column_scale(j) * y_scale;
      for (int p = 0; p < term_power(term); ++p) value /= x_scale;
      return value;
    };
    const double scaled = solution.coefficients(j);
    const double coefficient = to_law_units(scaled);
    if (!std::isfinite(coefficient) ||
        (coefficient == 0.0 && scaled / column_scale(j) != 0.0 && std::abs(scaled / column_scale(j)) > 1e-12))
      throw InputError("the coefficient of " + term_name(term, spec.variable) + " is " +
                       shortest_number(scaled / column_scale(j)) + " x " + shortest_number(y_scale) + " / " +
                       shortest_number(x_scale) + "^" + std::to_string(term_power(term)) +
                       ", outside the range of a double; expected velocities (largest |" + spec.variable +
                       "| = " + shortest_number(x_scale) + ") and forces (largest " + shortest_number(y_scale) +
                       ") whose powers in this law stay within double precision");
    fit.coefficients.push_back(coefficient);
    fit.std_errors.push_back(to_law_units(std::sqrt(covariance_factor * solution.covariance(j, j))));
  }
  // Cov(c_i, c_j) in law units: each index carries its own conversion.
  std::vector<double> to_law(k);
  for (std::size_t j = 0; j < k; ++j) {
    double factor = y_scale / column_scale(static_cast<Eigen::Index>(j));
    for (int p = 0; p < term_power(spec.terms[j]); ++p) factor /= x_scale;
    to_law[j] = factor;
  }
  fit.covariance.resize(k * k);
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < k; ++j)
      fit.covariance[i * k + j] = covariance_factor *
                                  solution.covariance(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) *
                                  to_law[i] * to_law[j];
  if (!std::isfinite(fit.rmse))
    throw InputError("the residuals of the fit overflow (largest force " + shortest_number(y_scale) +
                     "); expected forces whose squares stay within double precision");
  return fit;
}

}  // namespace hydrocoef
