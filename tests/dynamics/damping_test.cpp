// Damping of each DOF: laws (with the "opposing" sign flipped to forces on the
// body), surface outputs bound to relative velocity components, remapped
// axes and disturbance parameters, several DOFs from one surface, and the
// errors a wrong binding gives.
#include "src/dynamics/damping.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "src/core/error.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;

// Outputs X and N, linear in the axes so that linear interpolation is exact:
// X = 2 a0 - 3 a1 + 0.5, N = -a0 + 4 a1.
CoefficientSurface linear_surface(const std::string& axis0, const std::string& axis1) {
  std::vector<GridAxis> axes{{axis0, {-1.0, 0.0, 0.5, 1.0}, Extrapolation::Linear},
                             {axis1, {-2.0, -1.0, 0.0, 1.0, 2.0}, Extrapolation::Linear}};
  std::vector<double> values;
  for (const double a1 : axes[1].breakpoints)
    for (const double a0 : axes[0].breakpoints) {
      values.push_back(2 * a0 - 3 * a1 + 0.5);
      values.push_back(-a0 + 4 * a1);
    }
  return CoefficientSurface(GridTable(axes, {"X", "N"}, values, Interpolation::Linear));
}

SurfaceResolver resolver_of(const std::map<std::string, CoefficientSurface>& surfaces) {
  return [surfaces](const std::string& name) {
    const auto it = surfaces.find(name);
    if (it == surfaces.end()) throw InputError("no surface '" + name + "'");
    return it->second;
  };
}

TEST(DampingModel, LawsGiveForcesOnTheBody) {
  DampingSpec spec;
  spec[5].kind = DofDamping::Kind::Law;
  spec[5].law = parse_damping_terms("1,r,r|r|");
  spec[5].coefficients = {1e-5, -0.006, -0.077};
  spec[0].kind = DofDamping::Kind::Law;
  spec[0].law = parse_damping_terms("u,u|u|");
  spec[0].coefficients = {0.0155, 11.0365};
  spec[0].sign = SignConvention::OpposingMotion;
  const DampingModel model(spec, {});
  Vector6 nu = Vector6::Zero();
  nu[0] = -0.2;
  nu[5] = 0.15;
  const Vector6 tau = model.evaluate(nu, {});
  EXPECT_NEAR(tau[5], 1e-5 - 0.006 * 0.15 - 0.077 * 0.15 * 0.15, 1e-17);
  EXPECT_NEAR(tau[0], -(0.0155 * -0.2 + 11.0365 * -0.2 * 0.2), 1e-15);  // opposes motion: positive for u < 0
  EXPECT_GT(tau[0], 0.0);
  EXPECT_EQ(tau[1], 0.0);
  EXPECT_TRUE(model.damped(0) && model.damped(5) && !model.damped(3));
  EXPECT_TRUE(model.disturbance_names().empty());
}

// The model evaluates a law term by term as damping_law_value does, for
// every term kind, both signs of the velocity and zero: the same numbers.
TEST(DampingModel, EveryTermKindIsTheLawsOwnValue) {
  const DampingLawSpec all = parse_damping_terms("1,r,r|r|,r^2,r^3,|r|");
  ASSERT_EQ(all.terms.size(), 6u);
  // One term at a time (the others' coefficients 0), then all of them.
  std::vector<std::vector<double>> coefficient_sets;
  for (std::size_t t = 0; t < 6; ++t) {
    std::vector<double> c(6, 0.0);
    c[t] = -0.37;
    coefficient_sets.push_back(c);
  }
  coefficient_sets.push_back({1e-5, -0.006, -0.077, 0.01, -0.002, 0.003});
  for (std::size_t set = 0; set < coefficient_sets.size(); ++set) {
    DampingSpec spec;
    spec[5].kind = DofDamping::Kind::Law;
    spec[5].law = all;
    spec[5].coefficients = coefficient_sets[set];
    const DampingModel model(spec, {});
    for (const double r : {-1.3, -0.2, 0.0, 0.45, 2.0}) {
      Vector6 nu = Vector6::Zero();
      nu[5] = r;
      const double expected = damping_law_value(all.terms, spec[5].coefficients, r);
      EXPECT_EQ(model.evaluate(nu, {})[5], expected) << "set " << set << " at r = " << r;
      if (set < 6) EXPECT_EQ(expected, -0.37 * basis_value(all.terms[set], r)) << "term " << set;
    }
  }
}

TEST(DampingModel, SurfaceAxesBindToVelocityOrDisturbance) {
  const std::map<std::string, CoefficientSurface> surfaces{{"s-ur", linear_surface("u", "r")},
                                                           {"s-dist", linear_surface("v", "current_v")}};
  DampingSpec spec;
  spec[0] = {DofDamping::Kind::Surface, {}, {}, "s-ur", "X", {}, SignConvention::OnBody, {}, {}, true};
  spec[5] = {DofDamping::Kind::Surface, {}, {}, "s-ur", "N", {}, SignConvention::OpposingMotion, {}, {}, true};
  // Y reads surface axis "u" from the relative w instead (remapped), "r" by name.
  spec[1] = {DofDamping::Kind::Surface, {}, {}, "s-ur", "X", {{"u", "w"}}, SignConvention::OnBody, {}, {}, true};
  // K from a surface over v and the disturbance current_v.
  spec[3] = {DofDamping::Kind::Surface, {}, {}, "s-dist", "N", {}, SignConvention::OnBody, {}, {}, true};
  const DampingModel model(spec, resolver_of(surfaces));
  ASSERT_EQ(model.disturbance_names(), std::vector<std::string>{"current_v"});
  Vector6 nu;
  nu << 0.3, -0.4, 0.7, 0.0, 0.0, 1.5;
  const std::vector<double> disturbance{0.25};
  const Vector6 tau = model.evaluate(nu, disturbance);
  EXPECT_NEAR(tau[0], 2 * 0.3 - 3 * 1.5 + 0.5, 1e-13);
  EXPECT_NEAR(tau[5], -(-0.3 + 4 * 1.5), 1e-13);
  EXPECT_NEAR(tau[1], 2 * 0.7 - 3 * 1.5 + 0.5, 1e-13);
  EXPECT_NEAR(tau[3], -(-0.4) + 4 * 0.25, 1e-13);
  EXPECT_EQ(tau[2], 0.0);
  EXPECT_EQ(tau[4], 0.0);
}

TEST(DampingModel, BadDescriptionsNameTheDof) {
  const std::map<std::string, CoefficientSurface> surfaces{{"s", linear_surface("u", "r")}};
  DampingSpec spec;
  spec[5] = {DofDamping::Kind::Surface, {}, {}, "s", "Q", {}, SignConvention::OnBody, {}, {}, true};
  expect_input_error([&] { DampingModel(spec, resolver_of(surfaces)); }, {"damping of N", "'s'", "Q"});
  spec[5].output = "N";
  spec[5].axis_sources = {{"p", "r"}};
  expect_input_error([&] { DampingModel(spec, resolver_of(surfaces)); }, {"damping of N", "no axis 'p'", "u, r"});
  spec[5].axis_sources = {};
  spec[5].surface = "missing";
  expect_input_error([&] { DampingModel(spec, resolver_of(surfaces)); }, {"damping of N", "missing"});
  expect_input_error([&] { DampingModel(spec, {}); }, {"damping of N", "no surface source"});
  DampingSpec law;
  law[2].kind = DofDamping::Kind::Law;
  law[2].law = parse_damping_terms("w,w|w|");
  law[2].coefficients = {1.0};
  expect_input_error([&] { DampingModel(law, {}); }, {"damping of Z", "1 coefficients for 2 terms"});
}

}  // namespace
}  // namespace hydrocoef
