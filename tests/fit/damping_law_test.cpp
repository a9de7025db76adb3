// Damping-law fitting: the ASR-V paper's published coefficients, a direct
// least-squares cross-check with Eigen, exact recovery, robust losses, and the
// loss parser's and fitter's handling of bad input. (The term lists:
// tests/core/damping_terms_test.cpp.)
#include "src/fit/damping_law.hpp"

#include <gtest/gtest.h>

#include "tests/support/expect_input_error.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <fstream>
#include <functional>
#include <ostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

struct Table {
  std::vector<double> x;
  std::vector<double> y;
};

// Two numeric columns; '#' lines are comments and the first other line is the header.
Table read_two_column_csv(const std::string& relative_path) {
  const std::string path = std::string(HYDROCOEF_SOURCE_DIR) + "/" + relative_path;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  Table table;
  bool header_seen = false;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line.front() == '#') continue;
    if (!header_seen) {
      header_seen = true;
      continue;
    }
    std::istringstream fields(line);
    std::string first;
    std::string second;
    std::getline(fields, first, ',');
    std::getline(fields, second, ',');
    table.x.push_back(std::stod(first));
    table.y.push_back(std::stod(second));
  }
  return table;
}

Table surge_table() { return read_two_column_csv("examples/asr-v/asr-v-surge-damping.csv"); }
Table yaw_table() { return read_two_column_csv("examples/asr-v/asr-v-yaw-damping.csv"); }

// Runs `action` and checks it throws InputError whose message contains every `expected` piece.
using test::expect_input_error;

TEST(DampingLawFitAsrV, SurgeWithOffsetMatchesPaper) {
  const Table table = surge_table();
  ASSERT_EQ(table.x.size(), 20u);
  const DampingLawFit fit = fit_damping_law(parse_damping_terms("1,u,u|u|"), table.x, table.y);
  ASSERT_EQ(fit.coefficients.size(), 3u);
  EXPECT_NEAR(fit.coefficients[1], 0.01551, 5e-6);
  EXPECT_NEAR(fit.coefficients[2], 11.0364, 5e-5);
  EXPECT_EQ(fit.n, 20u);
  EXPECT_EQ(fit.loss, "squared");
  EXPECT_GT(fit.r2, 0.9999);
}

TEST(DampingLawFitAsrV, YawWithOffsetMatchesPaper) {
  const Table table = yaw_table();
  ASSERT_EQ(table.x.size(), 20u);
  const DampingLawFit fit = fit_damping_law(parse_damping_terms("1,r,r|r|"), table.x, table.y);
  EXPECT_NEAR(fit.coefficients[1], -0.006075, 5e-7);
  EXPECT_NEAR(fit.coefficients[2], -0.07714, 5e-6);
}

TEST(DampingLawFitAsrV, SurgeWithoutOffsetMatchesPaper) {
  const Table table = surge_table();
  const DampingLawFit fit = fit_damping_law(parse_damping_terms("u,u|u|"), table.x, table.y);
  ASSERT_EQ(fit.coefficients.size(), 2u);
  EXPECT_NEAR(fit.coefficients[0], 0.02184, 5e-6);
  EXPECT_NEAR(fit.coefficients[1], 11.0229, 5e-5);
}

struct CrossCheckCase {
  std::string table;
  std::string terms;
};

void PrintTo(const CrossCheckCase& test_case, std::ostream* out) { *out << test_case.table << " " << test_case.terms; }

class DampingLawCrossCheck : public ::testing::TestWithParam<CrossCheckCase> {};

// The Ceres fit against a direct QR solve of the same design matrix, and its
// standard errors against the textbook s^2 (A^T A)^-1.
TEST_P(DampingLawCrossCheck, AgreesWithEigenQr) {
  const Table table = GetParam().table == "surge" ? surge_table() : yaw_table();
  const DampingLawSpec spec = parse_damping_terms(GetParam().terms);
  const DampingLawFit fit = fit_damping_law(spec, table.x, table.y);

  const auto n = static_cast<Eigen::Index>(table.x.size());
  const auto k = static_cast<Eigen::Index>(spec.terms.size());
  Eigen::MatrixXd design(n, k);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < k; ++j)
      design(i, j) = basis_value(spec.terms[static_cast<std::size_t>(j)], table.x[static_cast<std::size_t>(i)]);
  const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(table.y.data(), n);
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(design);
  const Eigen::VectorXd expected = qr.solve(y);

  const Eigen::VectorXd residuals = design * expected - y;
  const double ssr = residuals.squaredNorm();
  const double s2 = ssr / static_cast<double>(n - k);
  // (A^T A)^-1 = P R^-1 R^-T P^T from the same factorization.
  const Eigen::MatrixXd r = qr.matrixR().topLeftCorner(k, k).triangularView<Eigen::Upper>();
  const Eigen::MatrixXd r_inverse = r.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(k, k));
  const Eigen::MatrixXd permuted = r_inverse * r_inverse.transpose();
  const Eigen::MatrixXd normal_inverse = qr.colsPermutation() * permuted * qr.colsPermutation().transpose();

  for (Eigen::Index j = 0; j < k; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    EXPECT_NEAR(fit.coefficients[jj], expected(j), 1e-9 * std::abs(expected(j))) << "term " << j;
    const double expected_error = std::sqrt(s2 * normal_inverse(j, j));
    EXPECT_NEAR(fit.std_errors[jj], expected_error, 1e-6 * expected_error) << "term " << j;
    EXPECT_GT(fit.std_errors[jj], 0.0);
  }

  const double mean = y.mean();
  const double sst = (y.array() - mean).square().sum();
  EXPECT_NEAR(fit.r2, 1.0 - ssr / sst, 1e-9);
  const double rmse = std::sqrt(ssr / static_cast<double>(n));
  EXPECT_NEAR(fit.rmse, rmse, 1e-7 * rmse);

  for (double x : {-0.3, 0.0, 0.17, 0.5}) {
    double value = 0.0;
    for (Eigen::Index j = 0; j < k; ++j) value += expected(j) * basis_value(spec.terms[static_cast<std::size_t>(j)], x);
    EXPECT_NEAR(fit.evaluate(x), value, 1e-9 * (1.0 + std::abs(value)));
  }
}

INSTANTIATE_TEST_SUITE_P(AsrV, DampingLawCrossCheck,
                         ::testing::Values(CrossCheckCase{"surge", "1,u,u|u|"}, CrossCheckCase{"surge", "u,u|u|"},
                                           CrossCheckCase{"surge", "u,u|u|,u^3"}, CrossCheckCase{"yaw", "1,r,r|r|"},
                                           CrossCheckCase{"yaw", "r|r|,r"}, CrossCheckCase{"yaw", "1,r^2,r^3"}));

double synthetic_law(double u) { return 0.3 - 2.0 * u + 5.0 * u * std::abs(u) + 0.7 * u * u * u; }

TEST(DampingLawFit, RecoversAnExactLaw) {
  std::vector<double> x;
  std::vector<double> y;
  for (int i = 0; i < 30; ++i) {
    x.push_back(-1.5 + 3.0 * i / 29.0);
    y.push_back(synthetic_law(x.back()));
  }
  const DampingLawFit fit = fit_damping_law(parse_damping_terms("1,u,u|u|,u^3"), x, y);
  const std::vector<double> truth = {0.3, -2.0, 5.0, 0.7};
  for (std::size_t j = 0; j < truth.size(); ++j) {
    EXPECT_NEAR(fit.coefficients[j], truth[j], 1e-10) << "term " << j;
    EXPECT_LT(fit.std_errors[j], 1e-10) << "term " << j;
  }
  EXPECT_LT(fit.rmse, 1e-12);
  EXPECT_NEAR(fit.r2, 1.0, 1e-12);
}

TEST(DampingLawFit, StandardErrorsAreNanWithoutSpareRuns) {
  const std::vector<double> x = {-1.0, 0.5, 2.0};
  const std::vector<double> y = {2.0, 1.25, -7.0};  // 1 + 2u - 3u|u|
  const DampingLawFit fit = fit_damping_law(parse_damping_terms("1,u,u|u|"), x, y);
  EXPECT_NEAR(fit.coefficients[0], 1.0, 1e-10);
  EXPECT_NEAR(fit.coefficients[1], 2.0, 1e-10);
  EXPECT_NEAR(fit.coefficients[2], -3.0, 1e-10);
  for (double error : fit.std_errors) EXPECT_TRUE(std::isnan(error));
}

// Data from y = 0.1 + 2u + 8u|u| with small noise and three gross outliers.
struct OutlierData {
  std::vector<double> x;
  std::vector<double> y;
  std::vector<double> truth = {0.1, 2.0, 8.0};
};

OutlierData outlier_data() {
  OutlierData data;
  for (int i = 0; i < 40; ++i) {
    const double u = -1.0 + 2.0 * i / 39.0;
    data.x.push_back(u);
    data.y.push_back(0.1 + 2.0 * u + 8.0 * u * std::abs(u) + 0.002 * std::sin(7.0 * i));
  }
  data.y[5] += 3.0;
  data.y[20] -= 2.5;
  data.y[33] += 4.0;
  return data;
}

double worst_coefficient_error(const DampingLawFit& fit, const std::vector<double>& truth) {
  double worst = 0.0;
  for (std::size_t j = 0; j < truth.size(); ++j) worst = std::max(worst, std::abs(fit.coefficients[j] - truth[j]));
  return worst;
}

TEST(DampingLawFit, RobustLossesIgnoreOutliersThatSquaredLossFollows) {
  const OutlierData data = outlier_data();
  const DampingLawSpec spec = parse_damping_terms("1,u,u|u|");

  const DampingLawFit squared = fit_damping_law(spec, data.x, data.y);
  EXPECT_GT(worst_coefficient_error(squared, data.truth), 0.05);

  for (const char* loss : {"huber:0.01", "cauchy:0.01", "soft-l1:0.01"}) {
    const DampingLawFit robust = fit_damping_law(spec, data.x, data.y, parse_loss(loss));
    EXPECT_EQ(robust.loss, loss);
    EXPECT_LT(worst_coefficient_error(robust, data.truth), 0.01) << loss;
    for (std::size_t j = 0; j < 3; ++j) {
      EXPECT_TRUE(std::isfinite(robust.std_errors[j])) << loss;
      EXPECT_GT(robust.std_errors[j], 0.0) << loss;
    }
  }
}

TEST(DampingLawLoss, ParsesEveryForm) {
  EXPECT_EQ(parse_loss("squared").loss, LossKind::Squared);
  const LossOptions huber = parse_loss("huber:0.01");
  EXPECT_EQ(huber.loss, LossKind::Huber);
  EXPECT_EQ(huber.loss_scale, 0.01);
  const LossOptions cauchy = parse_loss(" cauchy : 2.5 ");
  EXPECT_EQ(cauchy.loss, LossKind::Cauchy);
  EXPECT_EQ(cauchy.loss_scale, 2.5);
  const LossOptions soft = parse_loss("soft-l1:1e-3");
  EXPECT_EQ(soft.loss, LossKind::SoftLOne);
  EXPECT_EQ(soft.loss_scale, 1e-3);
  EXPECT_EQ(format_loss(soft), "soft-l1:0.001");
  EXPECT_EQ(format_loss(huber), "huber:0.01");
  EXPECT_EQ(format_loss(LossOptions{}), "squared");
}

TEST(DampingLawLoss, RejectsBadText) {
  for (const char* text : {"l2", "huber", "huber:", "huber:0", "huber:-1", "huber:abc", "huber:0.01x", "cauchy:nan",
                           "cauchy:inf", "squared:1", "Huber:0.1", ""})
    expect_input_error([text] { parse_loss(text); }, {std::string("'").append(text).append("'"), "expected"});
}

TEST(DampingLawFit, RejectsTooFewRuns) {
  const std::vector<double> x = {0.1, 0.2};
  const std::vector<double> y = {1.0, 2.0};
  expect_input_error([&] { fit_damping_law(parse_damping_terms("1,u,u|u|"), x, y); },
                     {"needs at least 3 runs, found 2"});
}

TEST(DampingLawFit, RejectsMismatchedSizes) {
  const std::vector<double> x = {0.1, 0.2, 0.3};
  const std::vector<double> y = {1.0, 2.0};
  expect_input_error([&] { fit_damping_law(parse_damping_terms("u"), x, y); }, {"3", "2"});
}

TEST(DampingLawFit, RejectsNonFiniteValues) {
  std::vector<double> x = {0.1, 0.2, 0.3, 0.4};
  std::vector<double> y = {1.0, 2.0, 3.0, 4.0};
  x[2] = std::nan("");
  expect_input_error([&] { fit_damping_law(parse_damping_terms("1,u"), x, y); }, {"run 3", "nan", "finite"});
  x[2] = 0.3;
  y[1] = INFINITY;
  expect_input_error([&] { fit_damping_law(parse_damping_terms("1,u"), x, y); }, {"run 2", "inf", "finite"});
}

TEST(DampingLawFit, RejectsDataThatCannotSeparateTheTerms) {
  const std::vector<double> same_u = {0.2, 0.2, 0.2, 0.2};
  const std::vector<double> forces = {1.0, 1.1, 0.9, 1.0};
  expect_input_error([&] { fit_damping_law(parse_damping_terms("1,u"), same_u, forces); },
                     {"1, u", "linearly dependent", "all 4 values of u are 0.2"});

  // Without negative speeds u and |u| are the same column; the constant is still determined.
  const std::vector<double> positive_u = {0.1, 0.2, 0.3, 0.4};
  expect_input_error([&] { fit_damping_law(parse_damping_terms("1,u,|u|"), positive_u, forces); },
                     {"terms u, |u| are linearly dependent"});

  const std::vector<double> at_rest = {0.0, 0.0, 0.0, 0.0};
  expect_input_error([&] { fit_damping_law(parse_damping_terms("1,u|u|"), at_rest, forces); }, {"'u|u|' is zero"});
}

TEST(DampingLawFit, RejectsBadSpecsAndOptions) {
  const std::vector<double> x = {0.1, 0.2, 0.3};
  const std::vector<double> y = {1.0, 2.0, 3.0};
  expect_input_error([&] { fit_damping_law(DampingLawSpec{"x", {DampingTerm::Linear}}, x, y); }, {"'x'"});
  expect_input_error(
      [&] {
        fit_damping_law(DampingLawSpec{"u", {DampingTerm::Linear, DampingTerm::Linear}}, x, y);
      },
      {"'u'", "twice"});
  expect_input_error([&] { fit_damping_law(DampingLawSpec{"u", {}}, x, y); }, {"no terms"});
  expect_input_error(
      [&] {
        fit_damping_law(parse_damping_terms("u"), x, y, LossOptions{LossKind::Huber, 0.0});
      },
      {"scale", "> 0"});
}

}  // namespace
}  // namespace hydrocoef

namespace hydrocoef {
namespace {

// Velocities and forces at the ends of the double range: the fit is made in
// units of the largest |x| and |y|, so a representable law is found and one
// that is not is refused saying why (never Ceres' warnings or "zero at every
// run").
TEST(DampingLawFit, ExtremeVelocitiesAndForcesFitOrAreRefusedSayingWhy) {
  const std::vector<double> x = {-1e308, -5e307, 5e307, 1e308};
  const std::vector<double> y = {1.0, 0.5, -0.5, -1.0};
  const DampingLawFit linear = fit_damping_law(parse_damping_terms("u"), x, y);
  EXPECT_NEAR(linear.coefficients[0] / -1e-308, 1.0, 1e-12);
  EXPECT_NEAR(linear.r2, 1.0, 1e-12);
  const DampingLawFit two = fit_damping_law(parse_damping_terms("u,u|u|"), x, y);
  EXPECT_NEAR(two.coefficients[0] / -1e-308, 1.0, 1e-9);
  test::expect_input_error([&] { fit_damping_law(parse_damping_terms("u^3"), x, y); },
                           {"coefficient of u^3", "outside the range of a double", "largest |u| = 1e+308"});

  // Velocities of a few denormals: the law's coefficient would be ~1e323.
  const std::vector<double> tiny = {4.9406564584124654e-324, 9.8813129168249309e-324, 1.4821969375237396e-323};
  const std::vector<double> forces = {1.0, 2.0, 3.0};
  test::expect_input_error([&] { fit_damping_law(parse_damping_terms("u"), tiny, forces); },
                           {"coefficient of u", "outside the range of a double"});

  // Forces of 1e308: fitted in units of the largest, no overflow of their squares.
  const std::vector<double> speeds = {0.1, 0.2, 0.3, 0.4};
  std::vector<double> huge;
  for (double u : speeds) huge.push_back(-2e307 * u - 5e307 * u * u);
  const DampingLawFit big = fit_damping_law(parse_damping_terms("u,u|u|"), speeds, huge);
  EXPECT_NEAR(big.coefficients[0] / -2e307, 1.0, 1e-9);
  EXPECT_NEAR(big.coefficients[1] / -5e307, 1.0, 1e-9);
  EXPECT_TRUE(std::isfinite(big.rmse));
  // A robust loss's scale stays in the force's unit.
  const DampingLawFit huber = fit_damping_law(parse_damping_terms("u,u|u|"), speeds, huge, parse_loss("huber:1e300"));
  EXPECT_NEAR(huber.coefficients[1] / -5e307, 1.0, 1e-6);
}

// Weighted least squares: the coefficients, covariance and reduced chi^2
// of the closed form c = (A^T W A)^-1 A^T W y, Cov = max(1, chi^2) (A^T W A)^-1,
// chi^2 = r^T W r / (n - k), W = diag(1/s_i^2), solved here with Eigen.
TEST(DampingLawWeightedFit, IsTheClosedFormWeightedLeastSquares) {
  const DampingLawSpec spec = parse_damping_terms("1,u,u|u|");
  std::vector<double> x, y, sigma;
  for (int i = 0; i < 15; ++i) {
    const double u = -0.3 + 0.05 * i;
    x.push_back(u);
    y.push_back(0.02 - 1.5 * u - 9.0 * u * std::abs(u) + 0.01 * std::sin(7.0 * i));
    sigma.push_back(0.002 + 0.004 * (i % 4));
  }
  const DampingLawFit fit = fit_damping_law(spec, x, y, {}, sigma);
  const Eigen::Index n = 15, k = 3;
  Eigen::MatrixXd a(n, k), w = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double u = x[static_cast<std::size_t>(i)];
    a(i, 0) = 1.0, a(i, 1) = u, a(i, 2) = u * std::abs(u);
    b(i) = y[static_cast<std::size_t>(i)];
    w(i, i) = 1.0 / (sigma[static_cast<std::size_t>(i)] * sigma[static_cast<std::size_t>(i)]);
  }
  const Eigen::MatrixXd covariance = (a.transpose() * w * a).inverse();
  const Eigen::VectorXd c = covariance * a.transpose() * w * b;
  const Eigen::VectorXd r = a * c - b;
  const double chi2 = r.dot(w * r) / static_cast<double>(n - k);
  // The runs scatter more than they say here: the covariance is scaled by
  // the Birge ratio squared.
  ASSERT_GT(chi2, 1.0);
  EXPECT_NEAR(fit.covariance_scale, chi2, 1e-8 * chi2);
  const Eigen::MatrixXd scaled = chi2 * covariance;
  ASSERT_TRUE(fit.weighted);
  for (Eigen::Index j = 0; j < k; ++j) {
    EXPECT_NEAR(fit.coefficients[static_cast<std::size_t>(j)], c(j), 1e-9 * (1.0 + std::abs(c(j))));
    EXPECT_NEAR(fit.std_errors[static_cast<std::size_t>(j)], std::sqrt(scaled(j, j)), 1e-7 * std::sqrt(scaled(j, j)));
    for (Eigen::Index l = 0; l < k; ++l)
      EXPECT_NEAR(fit.covariance[static_cast<std::size_t>(j * k + l)], scaled(j, l),
                  1e-7 * std::sqrt(scaled(j, j) * scaled(l, l)));
  }
  EXPECT_NEAR(fit.chi2_reduced, chi2, 1e-8 * chi2);
  // RMSE and R^2 stay those of the unweighted residuals.
  EXPECT_NEAR(fit.rmse, std::sqrt(r.squaredNorm() / n), 1e-10);

  // With one uncertainty for every run the coefficients are the unweighted
  // ones, and chi^2 is SSR / s^2 / (n - k).
  const std::vector<double> same(15, 0.01);
  const DampingLawFit uniform = fit_damping_law(spec, x, y, {}, same);
  const DampingLawFit plain = fit_damping_law(spec, x, y);
  EXPECT_FALSE(plain.weighted);
  EXPECT_TRUE(std::isnan(plain.chi2_reduced));
  for (std::size_t j = 0; j < 3; ++j)
    EXPECT_NEAR(uniform.coefficients[j], plain.coefficients[j], 1e-9 * (1.0 + std::abs(plain.coefficients[j])));
  EXPECT_NEAR(uniform.chi2_reduced, 15.0 * plain.rmse * plain.rmse / 1e-4 / 12.0, 1e-8 * uniform.chi2_reduced);
  // The unweighted covariance is s^2 (A^T A)^-1 with s^2 = SSR / (n - k).
  const Eigen::MatrixXd plain_cov = (a.transpose() * a).inverse() * (15.0 * plain.rmse * plain.rmse / 12.0);
  for (Eigen::Index j = 0; j < k; ++j)
    EXPECT_NEAR(plain.covariance[static_cast<std::size_t>(j * k + j)], plain_cov(j, j), 1e-7 * plain_cov(j, j));
}

// Runs that scatter exactly as their stated uncertainties say give a reduced
// chi^2 near 1; understated uncertainties give a larger one.
TEST(DampingLawWeightedFit, ReducedChiSquareMeasuresTheScatterAgainstTheUncertainties) {
  const DampingLawSpec spec = parse_damping_terms("u,u|u|");
  std::mt19937 random(2);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> x, y, sigma, half;
  for (int i = 0; i < 400; ++i) {
    const double u = 0.001 * i, s = 0.001 * (1 + i % 5);
    x.push_back(u);
    y.push_back(-2.0 * u - 10.0 * u * u + s * normal(random));
    sigma.push_back(s);
    half.push_back(s / 2);
  }
  const double spread = std::sqrt(2.0 / 398.0);  // standard deviation of chi^2/(n-k)
  EXPECT_NEAR(fit_damping_law(spec, x, y, {}, sigma).chi2_reduced, 1.0, 3 * spread);
  EXPECT_NEAR(fit_damping_law(spec, x, y, {}, half).chi2_reduced, 4.0, 12 * spread);
}

TEST(DampingLawWeightedFit, UncertaintiesMustBePositiveAndOnePerRun) {
  const DampingLawSpec spec = parse_damping_terms("u");
  const std::vector<double> x{0.1, 0.2, 0.3}, y{-1.0, -2.0, -3.1};
  expect_input_error(
      [&] {
        (void)fit_damping_law(spec, x, y, {}, std::vector<double>{0.1, 0.1});
      },
      {"2 uncertainties for 3 runs"});
  expect_input_error(
      [&] {
        (void)fit_damping_law(spec, x, y, {}, std::vector<double>{0.1, 0.0, 0.1});
      },
      {"run 2 of 3 has uncertainty 0"});
  expect_input_error(
      [&] {
        (void)fit_damping_law(spec, x, y, {}, std::vector<double>{0.1, 0.1, std::nan("")});
      },
      {"run 3 of 3 has uncertainty"});
}

}  // namespace
}  // namespace hydrocoef
