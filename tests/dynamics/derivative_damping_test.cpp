// Derivative models of several variables as a vehicle's damping
// (DofDamping::Kind::Derivatives in src/dynamics/damping.hpp): the force
// equals the sum written out by hand, with a disturbance and either sign
// convention; the jacobian equals central differences; lanes equal single
// evaluations bit for bit; Monte Carlo draws have the stated covariance (and
// a model without one is held and says what to give); a vehicle whose sway
// damping is Y(v, r, u) simulates with that force; vehicle files carrying a
// model are read, and bad ones refused naming the key.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "src/dynamics/damping.hpp"
#include "src/dynamics/damping_draws.hpp"
#include "src/dynamics/damping_lanes.hpp"
#include "src/dynamics/equilibrium.hpp"
#include "src/dynamics/simulation.hpp"
#include "src/dynamics/vehicle.hpp"
#include "src/dynamics/vehicle_model.hpp"
#include "tests/dynamics/asr_v_fixture.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;

// Y = Yv v + Yr r + Yv|v| v|v| + Yuv u v + Yur u r + Yvvr v^2 r + Yuud u^2 delta
// (on the body, SI), delta a disturbance.
constexpr const char* kSwayTerms = "v, r, v*|v|, u*v, u*r, v^2*r, u^2*delta";
const std::vector<double> kSway = {-2.0, 0.4, -11.0, -3.0, 0.7, -5.0, 1.5};

double sway_by_hand(const Vector6& nu, double delta, const std::vector<double>& c) {
  const double u = nu[0], v = nu[1], r = nu[5];
  return c[0] * v + c[1] * r + c[2] * v * std::abs(v) + c[3] * u * v + c[4] * u * r + c[5] * v * v * r +
         c[6] * u * u * delta;
}

DampingSpec sway_spec(std::vector<double> coefficients, SignConvention sign = SignConvention::OnBody) {
  DampingSpec spec;
  spec[1].kind = DofDamping::Kind::Derivatives;
  spec[1].terms = parse_terms(kSwayTerms);
  spec[1].coefficients = std::move(coefficients);
  spec[1].sign = sign;
  // N = Nr r + Nv v + Nur u*r: a second model in the same vehicle.
  spec[5].kind = DofDamping::Kind::Derivatives;
  spec[5].terms = parse_terms("r, v, u*r, r*|r|");
  spec[5].coefficients = {-0.8, -0.3, -0.2, -1.1};
  return spec;
}

TEST(DerivativeDamping, ForceIsTheSumOfTheTermsOnTheBody) {
  const DampingModel model(sway_spec(kSway), {});
  ASSERT_EQ(model.disturbance_names(), std::vector<std::string>{"delta"});
  EXPECT_TRUE(model.damped(1));
  EXPECT_TRUE(model.damped(5));
  EXPECT_FALSE(model.damped(0));
  Vector6 nu;
  nu << 1.2, -0.35, 0.1, 0.05, -0.02, 0.21;
  const std::vector<double> delta = {0.15};
  const Vector6 tau = model.evaluate(nu, delta);
  EXPECT_NEAR(tau[1], sway_by_hand(nu, 0.15, kSway), 1e-14);
  EXPECT_NEAR(tau[5], -0.8 * 0.21 - 0.3 * -0.35 - 0.2 * 1.2 * 0.21 - 1.1 * 0.21 * 0.21, 1e-15);
  EXPECT_EQ(tau[0], 0.0);
  EXPECT_EQ(tau[2], 0.0);
  // "opposing": the numbers are damping magnitudes, negated on evaluation.
  std::vector<double> magnitudes;
  for (const double c : kSway) magnitudes.push_back(-c);
  const DampingModel opposing(sway_spec(magnitudes, SignConvention::OpposingMotion), {});
  EXPECT_EQ(opposing.evaluate(nu, delta)[1], tau[1]);
  // add() adds evaluate()'s numbers, bit for bit.
  Vector6 sum = Vector6::Constant(0.5);
  model.add(nu.data(), delta, sum.data());
  for (Eigen::Index i = 0; i < 6; ++i) EXPECT_EQ(sum[i], 0.5 + tau[i]);
}

TEST(DerivativeDamping, JacobianEqualsCentralDifferences) {
  const DampingModel model(sway_spec(kSway), {});
  const std::vector<double> delta = {-0.1};
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> velocity(-0.8, 0.8);
  for (int round = 0; round < 20; ++round) {
    Vector6 nu;
    for (Eigen::Index i = 0; i < 6; ++i) nu[i] = velocity(rng);
    Matrix6 jacobian;
    const Vector6 tau = model.evaluate_with_jacobian(nu, delta, jacobian);
    EXPECT_EQ(tau, model.evaluate(nu, delta));
    for (Eigen::Index j = 0; j < 6; ++j) {
      const double h = 1e-6;
      Vector6 plus = nu, minus = nu;
      plus[j] += h;
      minus[j] -= h;
      const Vector6 difference = (model.evaluate(plus, delta) - model.evaluate(minus, delta)) / (2.0 * h);
      for (Eigen::Index i = 0; i < 6; ++i)
        EXPECT_NEAR(jacobian(i, j), difference[i], 1e-7 * (1.0 + std::abs(difference[i])))
            << "d tau_" << i << " / d nu_" << j << " at round " << round;
    }
  }
  // The cross terms reach the other velocities: dY/du = Yuv v + Yur r + 2 Yuud u delta.
  Vector6 nu;
  nu << 1.0, 0.2, 0.0, 0.0, 0.0, 0.1;
  Matrix6 jacobian;
  model.evaluate_with_jacobian(nu, delta, jacobian);
  EXPECT_NEAR(jacobian(1, 0), -3.0 * 0.2 + 0.7 * 0.1 + 2.0 * 1.5 * 1.0 * -0.1, 1e-15);
  EXPECT_NEAR(jacobian(1, 1), -2.0 - 22.0 * 0.2 - 3.0 * 1.0 - 10.0 * 0.2 * 0.1, 1e-14);
}

TEST(DerivativeDamping, LanesAreEachModelsOwnForceBitForBit) {
  std::vector<DampingModel> drawn;
  for (std::size_t l = 0; l < motion::kLanes; ++l) {
    std::vector<double> c = kSway;
    for (double& x : c) x *= 1.0 + 0.09 * static_cast<double>(l);
    DampingSpec spec = sway_spec(c);
    spec[0].kind = DofDamping::Kind::Law;  // a law beside the models
    spec[0].law = parse_damping_terms("u,u|u|");
    spec[0].coefficients = {-0.5 * (1.0 + 0.01 * static_cast<double>(l)), -10.0};
    drawn.emplace_back(spec, SurfaceResolver{});
  }
  std::array<const DampingModel*, motion::kLanes> models;
  for (std::size_t l = 0; l < models.size(); ++l) models[l] = &drawn[l];
  const DampingLanes lanes(models);
  EXPECT_TRUE(lanes.shared());
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> velocity(-1.0, 1.0);
  for (int round = 0; round < 30; ++round) {
    motion::Lanes nu_r[6], out[6];
    for (auto& v : nu_r)
      for (Eigen::Index l = 0; l < motion::kLanes; ++l) v[l] = velocity(rng);
    for (auto& o : out) o.setConstant(-0.125);
    const std::vector<double> delta = {velocity(rng)};
    lanes.add(nu_r, delta, out);
    for (std::size_t l = 0; l < motion::kLanes; ++l) {
      Vector6 v;
      for (Eigen::Index i = 0; i < 6; ++i) v[i] = nu_r[i][static_cast<Eigen::Index>(l)];
      const Vector6 own = models[l]->evaluate(v, delta);
      for (Eigen::Index i = 0; i < 6; ++i)
        EXPECT_EQ(std::bit_cast<std::uint64_t>(out[i][static_cast<Eigen::Index>(l)]),
                  std::bit_cast<std::uint64_t>(-0.125 + own[i]))
            << "lane " << l << ", DOF " << i;
    }
  }
  // Other terms in one lane: not one shape, lane by lane, still each lane's own.
  DampingSpec other = sway_spec(kSway);
  other[1].terms = parse_terms("v, r, v*|v|, u*v, u*r, v^3, u^2*delta");
  const DampingModel different(other, {});
  models[3] = &different;
  const DampingLanes mixed(models);
  EXPECT_FALSE(mixed.shared());
  motion::Lanes nu_r[6], out[6];
  for (auto& v : nu_r) v.setConstant(0.3);
  for (auto& o : out) o.setZero();
  const std::vector<double> delta = {0.2};
  mixed.add(nu_r, delta, out);
  Vector6 v = Vector6::Constant(0.3);
  EXPECT_EQ(out[1][3], different.evaluate(v, delta)[1]);
  EXPECT_EQ(out[1][2], models[2]->evaluate(v, delta)[1]);
}

TEST(DerivativeDamping, DrawsHaveTheStatedCovariance) {
  DampingSpec spec = sway_spec(kSway);
  // Seven coefficients, correlated: Sigma = B B^T for a fixed B.
  const Eigen::Index m = 7;
  Eigen::MatrixXd b(m, m);
  for (Eigen::Index i = 0; i < m; ++i)
    for (Eigen::Index j = 0; j < m; ++j) b(i, j) = i >= j ? 0.1 * static_cast<double>(1 + i + 2 * j) : 0.0;
  const Eigen::MatrixXd sigma = b * b.transpose();
  spec[1].covariance.assign(sigma.data(), sigma.data() + sigma.size());  // symmetric
  const DampingModel nominal(spec, {});
  const DampingDraws draws(nominal, spec);
  ASSERT_EQ(draws.drawn().size(), 1u);
  EXPECT_NE(draws.drawn()[0].find("Y: derivatives v, r, v*|v|"), std::string::npos) << draws.drawn()[0];
  ASSERT_EQ(draws.held().size(), 1u);  // N states no covariance
  EXPECT_NE(draws.held()[0].find("N: derivatives"), std::string::npos) << draws.held()[0];
  EXPECT_NE(draws.held()[0].find("give \"covariance\""), std::string::npos) << draws.held()[0];

  // The force of a draw is linear in its coefficients: evaluating at points
  // where one term is 1 and the others 0 is not possible for every term, so
  // recover each draw's coefficients by least squares over 7 states.
  Eigen::MatrixXd design(m, m);
  std::vector<Vector6> states;
  std::vector<double> deltas;
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> velocity(-1.0, 1.0);
  const std::vector<Term> terms = parse_terms(kSwayTerms);
  for (Eigen::Index i = 0; i < m; ++i) {
    Vector6 nu;
    for (Eigen::Index j = 0; j < 6; ++j) nu[j] = velocity(rng);
    const double delta = velocity(rng);
    states.push_back(nu);
    deltas.push_back(delta);
    const std::map<std::string, double> point = {{"u", nu[0]}, {"v", nu[1]}, {"r", nu[5]}, {"delta", delta}};
    for (Eigen::Index k = 0; k < m; ++k) design(i, k) = terms[static_cast<std::size_t>(k)].evaluate(point);
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(design);
  const std::size_t n = 20000;
  Eigen::MatrixXd samples(static_cast<Eigen::Index>(n), m);
  for (std::size_t s = 0; s < n; ++s) {
    const DampingModel model = draws.draw(99, s);
    Eigen::VectorXd y(m);
    for (Eigen::Index i = 0; i < m; ++i)
      y[i] = model.evaluate(states[static_cast<std::size_t>(i)],
                            std::span<const double>(&deltas[static_cast<std::size_t>(i)], 1))[1];
    samples.row(static_cast<Eigen::Index>(s)) = lu.solve(y).transpose();
  }
  const Eigen::RowVectorXd mean = samples.colwise().mean();
  const Eigen::MatrixXd centred = samples.rowwise() - mean;
  const Eigen::MatrixXd covariance = centred.transpose() * centred / static_cast<double>(n - 1);
  for (Eigen::Index i = 0; i < m; ++i) {
    const double sd = std::sqrt(sigma(i, i));
    // The mean within 5 standard errors of the coefficient.
    EXPECT_NEAR(mean[i], kSway[static_cast<std::size_t>(i)], 5.0 * sd / std::sqrt(static_cast<double>(n)));
    for (Eigen::Index j = 0; j < m; ++j) {
      // Sample covariance's standard error ~ sqrt((s_ii s_jj + s_ij^2) / n); 5 of them.
      const double se = std::sqrt((sigma(i, i) * sigma(j, j) + sigma(i, j) * sigma(i, j)) / static_cast<double>(n));
      EXPECT_NEAR(covariance(i, j), sigma(i, j), 5.0 * se) << i << "," << j;
    }
  }
  // The same draw twice is the same model.
  EXPECT_EQ(draws.draw(99, 5).evaluate(states[0], std::span<const double>(&deltas[0], 1)),
            draws.draw(99, 5).evaluate(states[0], std::span<const double>(&deltas[0], 1)));
}

TEST(DerivativeDamping, AVehicleWithCrossCoupledSwaySimulates) {
  VehicleDescription d = test::asr_v_vehicle(test::fit_asr_v_yaw_law());
  d.damping[1] = {};
  d.damping[1].kind = DofDamping::Kind::Derivatives;
  d.damping[1].terms = parse_terms("v, v*|v|, u*v, u*r, r");
  const std::vector<double> c = {-0.5, -11.0, -2.0, 0.3, -0.05};
  d.damping[1].coefficients = c;
  const VehicleModel model(d);
  Scenario s;
  s.duration_s = 5.0;
  s.output_rate_Hz = 10.0;
  s.integrator.method = IntegratorSettings::Method::Rk4;
  s.integrator.step_s = 0.01;
  s.initial_nu_b << 0.3, 0.2, 0.0, 0.0, 0.0, 0.1;
  s.segments.resize(1);
  const SimulationResult result = simulate_model(model, s);
  ASSERT_EQ(result.samples.size(), 51u);
  for (const auto& sample : result.samples) {
    const Vector6& nu = sample.forces.nu_r_b;
    const double u = nu[0], v = nu[1], r = nu[5];
    const double by_hand = c[0] * v + c[1] * v * std::abs(v) + c[2] * u * v + c[3] * u * r + c[4] * r;
    EXPECT_NEAR(sample.forces.damping_b[1], by_hand, 1e-14 * (1.0 + std::abs(by_hand))) << "t = " << sample.t_s;
  }
  // The sway is damped: it ends well below where it started.
  EXPECT_LT(std::abs(result.samples.back().nu_b[1]), 0.5 * 0.2);
}

// The equilibrium solver uses the model's exact jacobian: under a constant
// surge and sway force it finds the state a simulation settles at, where the
// cross-coupled sway damping balances the applied force.
TEST(DerivativeDamping, EquilibriumIsWhereTheSimulationSettles) {
  VehicleDescription d = test::asr_v_vehicle(test::fit_asr_v_yaw_law());
  for (const std::size_t dof : {0, 2, 3, 4, 5}) {
    d.damping[dof] = {};
    d.damping[dof].kind = DofDamping::Kind::Law;
    const std::string x(1, "uvwpqr"[dof]);
    d.damping[dof].law = parse_damping_terms(x + "," + x + "|" + x + "|");
    d.damping[dof].coefficients = dof < 3 ? std::vector<double>{-1.0, -11.0365} : std::vector<double>{-0.06, -0.08};
  }
  d.damping[1] = {};
  d.damping[1].kind = DofDamping::Kind::Derivatives;
  d.damping[1].terms = parse_terms("v, v*|v|, u*v, |u|*v");
  d.damping[1].coefficients = {-1.0, -11.0, -0.8, -0.4};
  const VehicleModel model(d);
  EquilibriumInputs inputs;
  inputs.tau_b << 0.5, 0.2, 0.0, 0.0, 0.0, 0.0;
  const EquilibriumResult steady = solve_equilibrium(model, inputs);
  ASSERT_TRUE(steady.converged);
  const double u = steady.nu_b[0], v = steady.nu_b[1];
  EXPECT_GT(u, 0.0);
  EXPECT_GT(v, 0.0);
  EXPECT_NEAR(steady.forces.damping_b[1], -1.0 * v - 11.0 * v * std::abs(v) - 0.8 * u * v - 0.4 * std::abs(u) * v,
              1e-14);
  Scenario scenario;
  scenario.duration_s = 400.0;
  scenario.output_rate_Hz = 0.1;
  scenario.integrator.method = IntegratorSettings::Method::DormandPrince45;
  scenario.integrator.max_step_s = 1.0;
  scenario.segments.resize(1);
  scenario.segments[0].tau_b = inputs.tau_b;
  const SimulationResult run = simulate_model(model, scenario);
  EXPECT_LT((velocity_b(run.final_state) - steady.nu_b).cwiseAbs().maxCoeff(), 1e-7);
}

const std::string kVehicle = R"({
  "mass": 10.0, "inertia": [1, 2, 3], "center_of_gravity": [0, 0, 0.05], "neutrally_buoyant": true,
  "damping": {"Y": {"derivatives": DERIVATIVES, "sign": "on-body"}}
})";

std::string vehicle_with(const std::string& derivatives) {
  std::string text = kVehicle;
  text.replace(text.find("DERIVATIVES"), 11, derivatives);
  return text;
}

TEST(DerivativeDamping, VehicleFilesCarryAModel) {
  const VehicleDescription v =
      parse_vehicle(vehicle_with(R"({"terms": "v, r, v*|v|, u*v, u*r", "coefficients": [-1, 0.5, -10, -2, 0.25],
                       "covariance": [[0.01, 0, 0, 0, 0], [0, 0.02, 0, 0, 0], [0, 0, 0.5, 0.1, 0],
                                      [0, 0, 0.1, 0.04, 0], [0, 0, 0, 0, 0.003]]})"),
                    "v.json");
  const DofDamping& y = v.damping[1];
  ASSERT_EQ(y.kind, DofDamping::Kind::Derivatives);
  EXPECT_EQ(format_terms(y.terms), "v, r, v*|v|, u*v, u*r");
  EXPECT_EQ(y.coefficients, (std::vector<double>{-1, 0.5, -10, -2, 0.25}));
  ASSERT_EQ(y.covariance.size(), 25u);
  EXPECT_EQ(y.covariance[2 * 5 + 3], 0.1);
  EXPECT_EQ(y.sign, SignConvention::OnBody);
  // An array of term strings is the same model.
  const VehicleDescription a =
      parse_vehicle(vehicle_with(R"({"terms": ["v", "u*r"], "coefficients": [-1, 0.25]})"), "v.json");
  EXPECT_EQ(format_terms(a.damping[1].terms), "v, u*r");
  EXPECT_TRUE(a.damping[1].covariance.empty());
  EXPECT_NO_THROW(VehicleModel{a});
}

TEST(DerivativeDamping, BadModelsInVehicleFilesAreRefusedNamingTheKey) {
  const auto refused = [](const std::string& derivatives, const std::vector<std::string>& expected) {
    expect_input_error([&] { parse_vehicle(vehicle_with(derivatives), "v.json"); }, expected);
  };
  refused(R"({"terms": "v, r#", "coefficients": [1, 2]})", {"v.json", "damping.Y.derivatives.terms", "r#"});
  refused(R"({"terms": "v, v", "coefficients": [1, 2]})", {"damping.Y.derivatives.terms", "v"});
  refused(R"({"terms": 3, "coefficients": [1]})", {"damping.Y.derivatives.terms", "found 3"});
  refused(R"({"terms": ["v", 2], "coefficients": [1, 2]})", {"damping.Y.derivatives.terms[1]"});
  refused(R"({"coefficients": [1]})", {"damping.Y.derivatives", "terms"});
  refused(R"({"terms": "v, r"})", {"damping.Y.derivatives", "coefficients"});
  refused(R"({"terms": "v, r", "coefficients": [1]})", {"damping.Y.derivatives.coefficients", "2 numbers"});
  refused(R"({"terms": "v, r", "coefficients": [1, "x"]})", {"damping.Y.derivatives.coefficients[1]"});
  refused(R"({"terms": "v, r", "coefficients": [1, 2], "covariance": [[1, 0], [0, 1], [0, 0]]})",
          {"damping.Y.derivatives.covariance"});
  refused(R"({"terms": "v, r", "coefficients": [1, 2], "covariance": [[1, 0.5], [0, 1]]})",
          {"damping.Y.derivatives.covariance"});
  refused(R"({"terms": "v, r", "coefficients": [1, 2], "covariance": [[1, 2], [2, 1]]})",
          {"damping.Y.derivatives.covariance"});
  refused(R"({"terms": "v, beta", "coefficients": [1, 2]})", {"damping.Y.derivatives.terms", "beta"});
  refused(R"({"terms": "v", "coefficients": [1], "extra": 1})", {"damping.Y.derivatives", "extra"});
  refused(R"("v, r")", {"damping.Y.derivatives"});
  std::string many;
  std::string numbers;
  for (int k = 0; k < 65; ++k) {
    many += (k ? ", " : "") + std::string("v*d") + std::to_string(k);
    numbers += (k ? ", " : "") + std::string("1");
  }
  refused(R"({"terms": ")" + many + R"(", "coefficients": [)" + numbers + "]}", {"damping.Y.derivatives.terms", "65"});
  // A covariance beside the model, and a model beside a law.
  expect_input_error(
      [] {
        parse_vehicle(R"({"mass": 10.0, "inertia": [1, 2, 3], "center_of_gravity": [0, 0, 0.05],
          "neutrally_buoyant": true, "damping": {"Y": {"derivatives": {"terms": "v", "coefficients": [1]},
          "covariance": [[1]], "sign": "on-body"}}})",
                      "v.json");
      },
      {"damping.Y.covariance", "derivatives.covariance"});
  expect_input_error(
      [] {
        parse_vehicle(R"({"mass": 10.0, "inertia": [1, 2, 3], "center_of_gravity": [0, 0, 0.05],
          "neutrally_buoyant": true, "damping": {"Y": {"derivatives": {"terms": "v", "coefficients": [1]},
          "law": {"v": 1}, "sign": "on-body"}}})",
                      "v.json");
      },
      {"damping.Y", "exactly one of"});
}

TEST(DerivativeDamping, BadSpecsAreRefusedNamingTheDof) {
  DampingSpec spec = sway_spec(kSway);
  spec[1].coefficients.pop_back();
  expect_input_error([&] { DampingModel(spec, {}); }, {"damping of Y", "6 coefficients for 7 terms"});
  spec = sway_spec(kSway);
  spec[1].coefficients[2] = std::nan("");
  expect_input_error([&] { DampingModel(spec, {}); }, {"damping of Y", "v*|v|", "not finite"});
  spec = sway_spec(kSway);
  spec[1].terms = {};
  spec[1].coefficients = {};
  expect_input_error([&] { DampingModel(spec, {}); }, {"damping of Y", "0 derivative terms"});
  spec = sway_spec(kSway);
  spec[5].terms = parse_terms("r, alpha, u*r, r*|r|");
  expect_input_error([&] { DampingModel(spec, {}); }, {"damping of N", "alpha"});
  spec = sway_spec(kSway);
  spec[1].covariance = {1.0, 2.0};
  expect_input_error([&] { DampingModel(spec, {}); }, {"damping of Y", "covariance"});
}

}  // namespace
}  // namespace hydrocoef
