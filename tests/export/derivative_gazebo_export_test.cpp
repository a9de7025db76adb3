// gz-sim Hydrodynamics parameters from derivative sets
// (src/export/derivative_gazebo_export.hpp): every term gz-sim can hold is
// written under its SDF name with the FRD or FLU sign, checked two ways: by
// a table written out by hand, and by applying gz-sim's force law
// F_i = sum L_ij s_j + A_ijk s_j |s_k| + Q_ijk s_j s_k to the written
// parameters at random states and comparing with the sets' own forces. A
// cubic term, a constant or a control is refused naming it, or dropped and
// listed when asked; hostile names stay data.
#include "src/export/derivative_gazebo_export.hpp"

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <random>
#include <string>

#include "tests/support/derivative_sets.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::derivative_set;
using test::expect_input_error;

std::vector<DerivativeSet> sets() {
  return {derivative_set("X", "u, u*|u|, v*r, u^2", {-1.5, -20.0, 3.0, -0.5}),
          derivative_set("Y", "v, r, v*|v|, u*v, u*r, |u|*v, u*p, u", {-2.0, 0.4, -11.0, -3.0, 0.7, -0.9, 0.05, 0.02}),
          derivative_set("K", "p, p*|p|, v", {-0.1, -0.2, 0.03}),
          derivative_set("N", "r, v, r*|r|, u*r, v*|r|", {-0.8, -0.3, -1.1, -0.2, 0.6})};
}

std::map<std::string, double> by_name(const DerivativeGazeboExport& e) {
  std::map<std::string, double> out;
  for (const auto& element : e.elements) out[element.name] = element.values.at(0);
  return out;
}

TEST(DerivativeGazebo, EveryTermUnderItsSdfNameWithTheLinksSign) {
  DerivativeGazeboOptions frd;
  frd.link_axes = GazeboLinkAxes::Frd;
  const auto in_frd = by_name(derivative_gazebo(sets(), frd));
  const auto in_flu = by_name(derivative_gazebo(sets(), {}));  // FLU by default
  // name, FRD value (on body, as given), FLU sign t_i t_j (t_i t_j t_k for s_j s_k), t = (1,-1,-1,1,-1,-1).
  const std::vector<std::tuple<std::string, double, double>> expected = {
      {"xU", -1.5, 1},   {"xUabsU", -20.0, 1}, {"xVR", 3.0, 1},     {"xUU", -0.5, 1},    {"yV", -2.0, 1},
      {"yR", 0.4, 1},    {"yVabsV", -11.0, 1}, {"yUV", -3.0, 1},    {"yUR", 0.7, 1},     {"yVabsU", -0.9, 1},
      {"yUP", 0.05, -1}, {"yU", 0.02, -1},     {"kP", -0.1, 1},     {"kPabsP", -0.2, 1}, {"kV", 0.03, -1},
      {"nR", -0.8, 1},   {"nV", -0.3, 1},      {"nRabsR", -1.1, 1}, {"nUR", -0.2, 1},    {"nVabsR", 0.6, 1}};
  for (const auto& [name, value, flu] : expected) {
    ASSERT_TRUE(in_frd.count(name)) << name;
    EXPECT_EQ(in_frd.at(name), value) << name;
    EXPECT_EQ(in_flu.at(name), flu * value) << name;
  }
  // Every diagonal term is written, 0 where no set has it; added mass 0 without Ma.
  EXPECT_EQ(in_frd.at("zW"), 0.0);
  EXPECT_EQ(in_frd.at("mQabsQ"), 0.0);
  EXPECT_EQ(in_frd.at("nDotR"), 0.0);
  // Nothing else: the 20 terms, the 12 diagonal terms (8 of them among the terms: xU,
  // xUabsU, yV, yVabsV, kP, kPabsP, nR, nRabsR) and the 6 added-mass diagonals.
  EXPECT_EQ(in_frd.size(), 20u + 12u - 8u + 6u);
}

// gz-sim's damping force at s (its parameters, its axes).
std::array<double, 6> gz_force(const std::map<std::string, double>& p, const std::array<double, 6>& s) {
  static const std::string f = "xyzkmn", v = "UVWPQR";
  std::array<double, 6> out{};
  for (const auto& [name, value] : p) {
    if (name.find("Dot") != std::string::npos) continue;
    const std::size_t i = f.find(name[0]), j = v.find(name[1]);
    if (name.size() == 2)
      out[i] += value * s[j];
    else if (name.size() == 3)
      out[i] += value * s[j] * s[v.find(name[2])];
    else
      out[i] += value * s[j] * std::abs(s[v.find(name[5])]);
  }
  return out;
}

TEST(DerivativeGazebo, GzSimsForceLawGivesTheSetsForces) {
  const auto all = sets();
  const auto frd = by_name(derivative_gazebo(all, {.link_axes = GazeboLinkAxes::Frd}));
  const auto flu = by_name(derivative_gazebo(all, {}));
  const std::array<double, 6> t{1, -1, -1, 1, -1, -1};
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> velocity(-1.0, 1.0);
  for (int round = 0; round < 20; ++round) {
    std::array<double, 6> s{}, s_flu{};
    std::map<std::string, double> point;
    for (std::size_t j = 0; j < 6; ++j) {
      s[j] = velocity(rng);
      s_flu[j] = t[j] * s[j];
      point[std::string(1, "uvwpqr"[j])] = s[j];
    }
    const auto f_frd = gz_force(frd, s);
    const auto f_flu = gz_force(flu, s_flu);
    for (const auto& set : all) {
      const std::size_t i = std::string("XYZKMN").find(set.output);
      double own = 0.0;
      for (std::size_t k = 0; k < set.terms.size(); ++k) own += set.coefficients[k] * set.terms[k].evaluate(point);
      EXPECT_NEAR(f_frd[i], own, 1e-12) << set.output;
      EXPECT_NEAR(t[i] * f_flu[i], own, 1e-12) << set.output;
    }
  }
}

TEST(DerivativeGazebo, OpposingSetsAreNegatedAndAddedMassWritten) {
  DerivativeSet y = derivative_set("Y", "v, v*|v|", {2.0, 11.0});
  y.sign = SignConvention::OpposingMotion;
  DerivativeGazeboOptions options;
  Matrix6 ma = Matrix6::Identity() * 3.0;
  ma(1, 5) = ma(5, 1) = 0.5;   // a sway-yaw coupling: FLU keeps its sign (t_y t_r = 1)
  ma(0, 4) = ma(4, 0) = 0.25;  // surge-pitch: FLU flips it
  options.added_mass = ma;
  const auto p = by_name(derivative_gazebo({y}, options));
  EXPECT_EQ(p.at("yV"), -2.0);
  EXPECT_EQ(p.at("yVabsV"), -11.0);
  EXPECT_EQ(p.at("yDotV"), -3.0);
  EXPECT_EQ(p.at("yDotR"), -0.5);
  EXPECT_EQ(p.at("xDotQ"), 0.25);
}

TEST(DerivativeGazebo, TermsGzSimCannotHoldAreRefusedOrDroppedWhenAsked) {
  std::vector<DerivativeSet> s = sets();
  s[1] = derivative_set("Y", "v, v^2*r, r", {-2.0, 5.0, 0.4});
  expect_input_error([&] { derivative_gazebo(s, {}); }, {"fit-Y", "'v^2*r'", "drop"});
  DerivativeGazeboOptions drop;
  drop.drop_unrepresentable = true;
  const auto dropped = derivative_gazebo(s, drop);
  ASSERT_EQ(dropped.dropped.size(), 1u);
  EXPECT_NE(dropped.dropped[0].find("Y: v^2*r"), std::string::npos);
  EXPECT_NE(dropped.text.find("dropped Y: v^2*r"), std::string::npos);
  EXPECT_EQ(by_name(dropped).at("yR"), 0.4);
  for (const std::string& bad : {"1", "|v|", "delta", "u*v*r", "|u|*|v|", "v^3"}) {
    std::vector<DerivativeSet> one = {derivative_set("N", "r, " + bad, {-1.0, 1.0})};
    expect_input_error([&] { derivative_gazebo(one, {}); }, {"fit-N", "'" + parse_terms(bad)[0].text() + "'"});
  }
  expect_input_error([&] { derivative_gazebo({derivative_set("CY", "v", {1.0})}, {}); },
                     {"'CY'", "X, Y, Z, K, M or N"});
  expect_input_error(
      [&] {
        derivative_gazebo({derivative_set("Y", "v", {1.0}), derivative_set("Y", "r", {1.0})}, {});
      },
      {"second set of output Y"});
  // A plain s_j s_k parameter comes with gz-sim's own warning restated.
  const auto x = derivative_gazebo({derivative_set("X", "u^2", {-1.0})}, {});
  EXPECT_NE(x.text.find("may cause"), std::string::npos);
}

TEST(DerivativeGazebo, HostileNamesStayData) {
  DerivativeSet y = derivative_set("Y", "v", {-1.0});
  y.name = "a --> <plugin name=\"evil\"/> <!--";
  DerivativeGazeboOptions options;
  options.link_name = "base</link_name><evil/><link_name>";
  const auto e = derivative_gazebo({y}, options);
  // Outside the comments (each closed by the first "-->" after it) nothing of the names is markup.
  std::string markup;
  for (std::size_t at = 0; at < e.text.size();) {
    const std::size_t open = e.text.find("<!--", at);
    markup += e.text.substr(at, open == std::string::npos ? std::string::npos : open - at);
    if (open == std::string::npos) break;
    const std::size_t close = e.text.find("-->", open + 4);
    ASSERT_NE(close, std::string::npos);
    at = close + 3;
  }
  const std::size_t escaped = markup.find("&lt;evil/&gt;");
  ASSERT_NE(escaped, std::string::npos) << markup;
  EXPECT_EQ(markup.find("evil"), escaped + 4) << markup;  // the link name's, escaped, alone
  EXPECT_EQ(markup.rfind("evil"), escaped + 4) << markup;
  EXPECT_EQ(markup.find("<plugin "), markup.rfind("<plugin "));  // one plugin element
  options.link_name.clear();
  expect_input_error([&] { derivative_gazebo({y}, options); }, {"empty link name"});
}

}  // namespace
}  // namespace hydrocoef
