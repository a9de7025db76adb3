// Monte Carlo over the damping: draws of a law follow its covariance; a GP
// surface's draws follow its posterior; the sampled equilibrium of a linear
// law with a Gaussian coefficient has the analytic distribution (a Gaussian
// constant term: exactly Gaussian; a Gaussian slope: the distribution of
// tau / d, by quadrature); bands order their percentiles, do not depend on
// the thread count, and failing draws are counted, not hidden.
#include "src/dynamics/ensemble.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "src/core/error.hpp"
#include "src/dynamics/scenario.hpp"
#include "src/dynamics/simulation.hpp"
#include "src/surface/gp_surfaces.hpp"
#include "tests/dynamics/asr_v_fixture.hpp"

namespace hydrocoef {
namespace {

/// A sphere-like vehicle whose yaw damping is the law `terms` with
/// `coefficients` and `covariance` (k x k), everything else undamped but surge.
VehicleDescription yaw_vehicle(const std::string& terms, std::vector<double> coefficients,
                               std::vector<double> covariance) {
  VehicleDescription v = test::asr_v_vehicle(test::YawLaw{0.0, -0.006, -0.077});
  v.damping[5].law = parse_damping_terms(terms);
  v.damping[5].coefficients = std::move(coefficients);
  v.damping[5].covariance = std::move(covariance);
  return v;
}

Scenario yaw_scenario(double tau, double duration, double step) {
  Scenario s;
  s.file = "test scenario";
  s.duration_s = duration;
  s.output_rate_Hz = 2.0;
  s.integrator.method = IntegratorSettings::Method::Rk4;
  s.integrator.step_s = step;
  ScenarioSegment segment;
  segment.tau_b[5] = tau;
  s.segments.push_back(segment);
  return s;
}

TEST(PercentileOfSorted, IsNumPysLinearRule) {
  const std::vector<double> v = {1.0, 2.0, 3.0, 4.0};
  EXPECT_DOUBLE_EQ(percentile_of_sorted(v, 50.0), 2.5);
  EXPECT_DOUBLE_EQ(percentile_of_sorted(v, 25.0), 1.75);  // numpy.percentile([1,2,3,4], 25)
  EXPECT_DOUBLE_EQ(percentile_of_sorted(v, 5.0), 1.15);
  EXPECT_DOUBLE_EQ(percentile_of_sorted(std::vector<double>{7.0}, 95.0), 7.0);
}

TEST(EnsembleOptions, OutOfRangeAreRefused) {
  EnsembleOptions o;
  o.samples = 1;
  EXPECT_THROW(check_ensemble_options(o), InputError);
  o.samples = 10;
  o.percentiles = {50.0, 5.0};
  EXPECT_THROW(check_ensemble_options(o), InputError);
  o.percentiles = {0.0, 50.0};
  EXPECT_THROW(check_ensemble_options(o), InputError);
  o.percentiles = {5.0, 100.0};
  EXPECT_THROW(check_ensemble_options(o), InputError);
  o.percentiles = {5.0, 50.0, 95.0};
  EXPECT_NO_THROW(check_ensemble_options(o));
}

TEST(DampingDraws, LawDrawsHaveTheStatedMeanAndCovariance) {
  // N = c0 + a r + b r|r| with a correlated covariance, stated "opposing":
  // the draws on the body are the negated mean with the same covariance.
  const std::vector<double> mean = {1e-4, 0.006, 0.077};
  const std::vector<double> cov = {4e-10, 1e-9, 0.0, 1e-9, 9e-8, -1.5e-7, 0.0, -1.5e-7, 4e-6};
  VehicleDescription v = yaw_vehicle("1,r,r|r|", mean, cov);
  v.damping[5].sign = SignConvention::OpposingMotion;
  const VehicleModel model(v);
  const DampingDraws draws(model.damping(), v.damping);
  ASSERT_TRUE(draws.any());
  ASSERT_EQ(draws.drawn().size(), 1u);
  EXPECT_EQ(draws.held().size(), 2u);  // surge and sway laws have no covariance
  // Recover each draw's coefficients from its damping at three yaw rates.
  const std::size_t n = 20000;
  Eigen::MatrixXd samples(3, static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const DampingModel d = draws.draw(7, i);
    auto at = [&](double r) {
      Vector6 nu = Vector6::Zero();
      nu[5] = r;
      return d.evaluate(nu, {})[5];
    };
    // c + a r + b r|r| at r = 0, 1, 2.
    const double c = at(0.0), f1 = at(1.0), f2 = at(2.0);
    const double b = 0.5 * (f2 - 2.0 * f1 + c), a = f1 - c - b;
    samples.col(static_cast<Eigen::Index>(i)) << c, a, b;
  }
  const Eigen::Vector3d sample_mean = samples.rowwise().mean();
  const Eigen::MatrixXd centred = samples.colwise() - sample_mean;
  const Eigen::Matrix3d sample_cov = centred * centred.transpose() / static_cast<double>(n - 1);
  for (int k = 0; k < 3; ++k) {
    const double sd = std::sqrt(cov[static_cast<std::size_t>(4 * k)]);
    EXPECT_NEAR(sample_mean[k], -mean[static_cast<std::size_t>(k)], 4.0 * sd / std::sqrt(double(n))) << k;
    for (int j = 0; j < 3; ++j) {
      const double sj = std::sqrt(cov[static_cast<std::size_t>(4 * j)]);
      // Standard error of a sample covariance <= sd_k sd_j sqrt(2 / n).
      EXPECT_NEAR(sample_cov(k, j), cov[static_cast<std::size_t>(3 * k + j)],
                  4.0 * sd * sj * std::sqrt(2.0 / double(n)))
          << k << "," << j;
    }
  }
  // The same seed and index give the same draw; another index another one.
  Vector6 nu = Vector6::Zero();
  nu[5] = 0.3;
  EXPECT_EQ(draws.draw(7, 3).evaluate(nu, {})[5], draws.draw(7, 3).evaluate(nu, {})[5]);
  EXPECT_NE(draws.draw(7, 3).evaluate(nu, {})[5], draws.draw(7, 4).evaluate(nu, {})[5]);
  EXPECT_NE(draws.draw(7, 3).evaluate(nu, {})[5], draws.draw(8, 3).evaluate(nu, {})[5]);
}

TEST(DampingDraws, ACovarianceThatIsNotOneIsRefused) {
  EXPECT_TRUE(covariance_problem(std::vector<double>{1.0, 2.0, 2.0, 1.0}, 2).has_value());  // eigenvalue -1
  EXPECT_TRUE(covariance_problem(std::vector<double>{1.0, 0.5, 0.0, 1.0}, 2).has_value());  // not symmetric
  EXPECT_TRUE(covariance_problem(std::vector<double>{1.0, 0.0, 0.0}, 2).has_value());       // size
  EXPECT_TRUE(covariance_problem(std::vector<double>{NAN, 0.0, 0.0, 1.0}, 2).has_value());
  EXPECT_FALSE(covariance_problem(std::vector<double>{1.0, 1.0, 1.0, 1.0}, 2).has_value());  // semi-definite
  const VehicleDescription v = yaw_vehicle("r", {-0.01}, {-1e-6});
  EXPECT_THROW(VehicleModel{v}, InputError);
}

TEST(DampingDraws, NothingUncertainMeansNothingDrawn) {
  const VehicleDescription v = yaw_vehicle("r", {-0.01}, {});
  const VehicleModel model(v);
  const DampingDraws draws(model.damping(), v.damping);
  EXPECT_FALSE(draws.any());
  EXPECT_EQ(draws.held().size(), 3u);
}

// r = (tau + c0) / d for N = c0 - d r: with c0 ~ N(mu, s^2) the steady yaw
// rate is exactly N((tau + mu) / d, (s / d)^2).
TEST(EquilibriumSamples, GaussianConstantGivesTheAnalyticGaussian) {
  const double tau = 0.0027, mu = 1e-4, s = 2e-4, d = 0.02;
  const VehicleDescription v = yaw_vehicle("1,r", {mu, -d}, {s * s, 0.0, 0.0, 0.0});
  const VehicleModel model(v);
  const DampingDraws draws(model.damping(), v.damping);
  EquilibriumInputs in;
  in.tau_b[5] = tau;
  EnsembleOptions options;
  options.samples = 2000;
  options.seed = 11;
  options.percentiles = {2.5, 50.0, 97.5};
  const EquilibriumSamples out = solve_equilibrium_samples(model, draws, in, options);
  ASSERT_EQ(out.samples, 2000u);
  EXPECT_EQ(out.failures.count, 0u);
  const double mean = (tau + mu) / d, sd = s / d, n = 2000.0;
  EXPECT_NEAR(out.mean[5], mean, 3.0 * sd / std::sqrt(n));
  EXPECT_NEAR(out.standard_deviation[5], sd, 3.0 * sd / std::sqrt(2.0 * (n - 1.0)));
  // The 95 % interval of a Gaussian: mean -+ 1.96 sd (loosely: order statistics scatter).
  EXPECT_NEAR(out.percentile_values[0][5], mean - 1.959964 * sd, 0.15 * sd);
  EXPECT_NEAR(out.percentile_values[2][5], mean + 1.959964 * sd, 0.15 * sd);
}

// r = tau / d for N = -d r with d ~ N(d0, s^2): mean and standard deviation
// of tau / d by quadrature over the Gaussian (s << d0, so d > 0 in practice).
TEST(EquilibriumSamples, GaussianSlopeMatchesQuadratureOfTauOverD) {
  const double tau = 0.0027, d0 = 0.02, s = 0.002;
  const VehicleDescription v = yaw_vehicle("r", {-d0}, {s * s});
  const VehicleModel model(v);
  const DampingDraws draws(model.damping(), v.damping);
  EquilibriumInputs in;
  in.tau_b[5] = tau;
  EnsembleOptions options;
  options.samples = 2000;
  options.seed = 5;
  const EquilibriumSamples out = solve_equilibrium_samples(model, draws, in, options);
  ASSERT_EQ(out.samples, 2000u);
  // E[g(d)] = int g(d) phi((d - d0) / s) / s dd over d0 +- 8 s, Simpson's rule.
  double m1 = 0.0, m2 = 0.0;
  const int steps = 4000;
  const double lo = d0 - 8.0 * s, h = 16.0 * s / steps;
  for (int i = 0; i <= steps; ++i) {
    const double dd = lo + i * h, z = (dd - d0) / s;
    const double w = (i == 0 || i == steps ? 1.0 : (i % 2 ? 4.0 : 2.0)) * h / 3.0;
    const double pdf = std::exp(-0.5 * z * z) / (s * std::sqrt(2.0 * std::numbers::pi));
    m1 += w * pdf * tau / dd;
    m2 += w * pdf * (tau / dd) * (tau / dd);
  }
  const double sd = std::sqrt(m2 - m1 * m1), n = 2000.0;
  EXPECT_GT(m1, tau / d0);  // Jensen: E[1/d] > 1/E[d]
  EXPECT_NEAR(out.mean[5], m1, 3.0 * sd / std::sqrt(n));
  // The sample sd's standard error, with the excess kurtosis of tau/d taken as <= 1.
  EXPECT_NEAR(out.standard_deviation[5], sd, 3.0 * sd * std::sqrt(3.0 / (4.0 * n)));
}

// A 1-D GP surface of the yaw moment from six noise-free runs: its draws
// pass through the runs, and at points between nodes their mean and
// standard deviation are the posterior's.
TEST(DampingDraws, GpSurfaceDrawsFollowThePosterior) {
  std::vector<double> x, y;
  for (int i = 0; i < 6; ++i) {
    x.push_back(0.06 * i);
    y.push_back(-0.006 * x.back() - 0.077 * x.back() * x.back());
  }
  GpOptions gp_options;
  gp_options.fixed_hyperparameters = {0.004, 0.08};  // sigma [N m], length scale [rad/s]
  GpSurfaces gp(1, x, 1, y, {}, gp_options, {"r"}, {RbfOutOfRange::Clamp});
  const CoefficientSurface surface(gp, {"r"}, {"N"});
  // posterior() agrees with the point evaluation's standard deviation.
  std::vector<double> points = {0.01, 0.06, 0.17}, mean, cov;
  gp.output(0).posterior(points, 3, mean, cov);
  GpSurface::Workspace ws(gp.output(0));
  for (std::size_t j = 0; j < 3; ++j) {
    double sd = 0.0;
    EXPECT_DOUBLE_EQ(mean[j], gp.output(0).evaluate(&points[j], ws, &sd));
    EXPECT_NEAR(std::sqrt(std::max(cov[j * 3 + j], 0.0)), sd, 1e-9 * 0.004);
    EXPECT_EQ(cov[j * 3 + 2], cov[2 * 3 + j]);
  }

  VehicleDescription v = yaw_vehicle("r", {-0.01}, {});
  v.damping[5] = DofDamping{};
  v.damping[5].kind = DofDamping::Kind::Surface;
  v.damping[5].surface = "yaw";
  v.damping[5].output = "N";
  const VehicleModel model(v, [&](const std::string&) { return surface; });
  const DampingDraws draws(model.damping(), v.damping);
  ASSERT_EQ(draws.drawn().size(), 1u);
  // Evenly spaced nodes, 1/16 of the length scale apart: 0.3 / (0.08 / 16) + 1.
  EXPECT_NE(draws.drawn()[0].find("on 61 nodes"), std::string::npos) << draws.drawn()[0];
  const std::vector<double> at = {0.06, 0.03, 0.135, 0.27};  // a run, then between runs
  const std::size_t n = 2000;
  std::vector<double> sum(at.size(), 0.0), sum2(at.size(), 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const DampingModel d = draws.draw(2, i);
    for (std::size_t j = 0; j < at.size(); ++j) {
      Vector6 nu = Vector6::Zero();
      nu[5] = at[j];
      const double value = d.evaluate(nu, {})[5];
      sum[j] += value;
      sum2[j] += value * value;
    }
  }
  for (std::size_t j = 0; j < at.size(); ++j) {
    double sd = 0.0;
    const double m = gp.output(0).evaluate(&at[j], ws, &sd);
    const double sample_mean = sum[j] / n;
    const double sample_sd = std::sqrt(std::max(0.0, sum2[j] / n - sample_mean * sample_mean));
    if (j == 0) {  // at a noise-free run every draw passes through it, up to the spline's error
      double between = 0.0;
      gp.output(0).evaluate(&at[1], ws, &between);
      EXPECT_NEAR(sample_mean, y[1], 1e-3 * between);
      EXPECT_LT(sample_sd, 1e-2 * between);
      continue;
    }
    ASSERT_GT(sd, 1e-6) << at[j];
    EXPECT_NEAR(sample_mean, m, 4.0 * sd / std::sqrt(double(n))) << at[j];
    EXPECT_NEAR(sample_sd, sd, 0.1 * sd) << at[j];
  }
}

TEST(SimulateSamples, BandsAreOrderedAndContainTheSteadyInterval) {
  const double tau = 0.0027, mu = 1e-4, s = 2e-4, d = 0.02;
  const VehicleDescription v = yaw_vehicle("1,r", {mu, -d}, {s * s, 0.0, 0.0, 0.0});
  const VehicleModel model(v);
  const DampingDraws draws(model.damping(), v.damping);
  const Scenario scenario = yaw_scenario(tau, 30.0, 0.02);
  EnsembleOptions options;
  options.samples = 100;
  options.seed = 3;
  options.percentiles = {5.0, 50.0, 95.0};
  std::size_t calls = 0, last_done = 0;
  const TrajectoryBands bands = simulate_samples(model, draws, scenario, options, [&](std::size_t done, std::size_t) {
    ++calls;
    last_done = std::max(last_done, done);
  });
  EXPECT_EQ(calls, 100u);
  EXPECT_EQ(last_done, 100u);
  ASSERT_EQ(bands.samples, 100u);
  ASSERT_EQ(bands.t_s.size(), 61u);
  const std::size_t r = bands.quantity_index("r"), psi = bands.quantity_index("psi"), last = 60;
  for (std::size_t k = 0; k < bands.t_s.size(); ++k) {
    EXPECT_LE(bands.value(r, 0, k), bands.value(r, 1, k));
    EXPECT_LE(bands.value(r, 1, k), bands.value(r, 2, k));
  }
  // Steady at 30 s (time constant I / d ~ 3 s): the 5-95 band of r is close
  // to the Gaussian's mean -+ 1.645 sd (order statistics of 100 draws scatter).
  const double mean = (tau + mu) / d, sd = s / d;
  EXPECT_NEAR(bands.value(r, 1, last), mean, 0.4 * sd);
  EXPECT_NEAR(bands.value(r, 0, last), mean - 1.644854 * sd, 0.5 * sd);
  EXPECT_NEAR(bands.value(r, 2, last), mean + 1.644854 * sd, 0.5 * sd);
  // The yaw angle is unwrapped: it keeps growing past pi.
  EXPECT_GT(bands.value(psi, 1, last), std::numbers::pi);
  EXPECT_GT(bands.value(psi, 1, last), bands.value(psi, 1, last - 1));
  // No dependence on the number of threads.
  options.threads = 1;
  const TrajectoryBands serial = simulate_samples(model, draws, scenario, options);
  EXPECT_EQ(serial.values, bands.values);
}

TEST(SimulateSamples, FailingDrawsAreCountedNotHidden) {
  // N = -d r^3 with d ~ N(0.1, 0.2^2): a draw with d < 0 drives r to infinity.
  const VehicleDescription v = yaw_vehicle("r^3", {-0.1}, {0.04});
  const VehicleModel model(v);
  const DampingDraws draws(model.damping(), v.damping);
  EnsembleOptions options;
  options.samples = 40;
  const TrajectoryBands bands = simulate_samples(model, draws, yaw_scenario(0.5, 20.0, 0.01), options);
  EXPECT_GT(bands.failures.count, 0u);
  EXPECT_GT(bands.samples, 0u);
  EXPECT_EQ(bands.samples + bands.failures.count, 40u);
  ASSERT_FALSE(bands.failures.first.empty());
  EXPECT_NE(bands.failures.first.front().find("finite"), std::string::npos) << bands.failures.first.front();
}

TEST(ShareInsideBand, CountsMeasuredValuesBetweenTheOuterPercentiles) {
  TrajectoryBands b;
  b.t_s = {0.0, 1.0, 2.0};
  b.quantities = {"r"};
  b.units = {"rad s^-1"};
  b.percentiles = {5.0, 95.0};
  b.values = {0.0, 1.0, 2.0, /* p95 */ 1.0, 2.0, 3.0};
  const std::vector<double> t = {0.5, 1.5, 2.5, 1.0};
  const std::vector<double> inside_outside = {1.0, 0.5, 2.5, 2.5};  // inside, below, out of span, outside
  EXPECT_DOUBLE_EQ(share_inside_band(b, "r", t, inside_outside), 1.0 / 3.0);
  EXPECT_THROW(share_inside_band(b, "q", t, inside_outside), InputError);
}

}  // namespace
}  // namespace hydrocoef
