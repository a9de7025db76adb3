// The damping of several vehicles at once (src/dynamics/damping_lanes.hpp):
// every lane's force is its own model's evaluate(), bit for bit, whether the
// models share their shape (laws and one-axis tables on one axis, evaluated
// lanes at once) or not (lane by lane), with surfaces bound to velocities and
// to a disturbance, beyond a table's axis, and when a lookup fails.
#include "src/dynamics/damping_lanes.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

using motion::kLanes;
using motion::Lanes;

// A one-axis table N(r) (natural spline) with values scaled by `scale`, and a
// two-axis one X(u, current) (linear), clamped or not beyond their axes.
CoefficientSurface yaw_table(double scale, Extrapolation policy) {
  std::vector<GridAxis> axes{{"r", {-0.3, -0.1, 0.0, 0.1, 0.2, 0.3}, policy}};
  std::vector<double> values;
  for (const double r : axes[0].breakpoints) values.push_back(scale * (-0.006 * r - 0.077 * r * std::abs(r)));
  return CoefficientSurface(GridTable(axes, {"N"}, values, Interpolation::NaturalSpline));
}
CoefficientSurface surge_table(double scale) {
  std::vector<GridAxis> axes{{"u", {-0.5, 0.0, 0.5}, Extrapolation::Linear},
                             {"current", {0.0, 1.0}, Extrapolation::Clamp}};
  std::vector<double> values;
  for (const double c : axes[1].breakpoints)
    for (const double u : axes[0].breakpoints) values.push_back(scale * (-11.0 * u * std::abs(u) + 0.1 * c));
  return CoefficientSurface(GridTable(axes, {"X"}, values, Interpolation::Linear));
}

// Lane l: laws on Y and K with lane-dependent coefficients, N from a table.
// `surge` adds X from the two-axis table (looked up lane by lane).
DampingModel lane_model(std::size_t lane, bool surge, Extrapolation policy) {
  const double s = 1.0 + 0.07 * static_cast<double>(lane);
  DampingSpec spec;
  spec[1].kind = DofDamping::Kind::Law;
  spec[1].law = parse_damping_terms("v|v|,v,1");
  spec[1].coefficients = {-11.0 * s, -0.0155 * s, 1e-4 * s};
  spec[3].kind = DofDamping::Kind::Law;
  spec[3].law = parse_damping_terms("p,p^3");
  spec[3].coefficients = {-0.006 * s, -0.3 * s};
  spec[5].kind = DofDamping::Kind::Surface;
  spec[5].surface = "yaw";
  spec[5].output = "N";
  if (surge) {
    spec[0].kind = DofDamping::Kind::Surface;
    spec[0].surface = "surge";
    spec[0].output = "X";
  }
  return DampingModel(spec,
                      [&](const std::string& name) { return name == "yaw" ? yaw_table(s, policy) : surge_table(s); });
}

void expect_lanes_are_each_models_own(const std::array<const DampingModel*, kLanes>& models, const Lanes* nu_r,
                                      std::span<const double> disturbances) {
  const DampingLanes lanes(models);
  Lanes out[6];
  for (Lanes& o : out) o.setConstant(0.25);  // add() adds
  lanes.add(nu_r, disturbances, out);
  for (std::size_t l = 0; l < kLanes; ++l) {
    Vector6 v;
    for (Eigen::Index i = 0; i < 6; ++i) v[i] = nu_r[i][static_cast<Eigen::Index>(l)];
    const Vector6 own = models[l]->evaluate(v, disturbances);
    for (Eigen::Index i = 0; i < 6; ++i)
      EXPECT_EQ(std::bit_cast<std::uint64_t>(out[i][static_cast<Eigen::Index>(l)]),
                std::bit_cast<std::uint64_t>(0.25 + own[i]))
          << "lane " << l << ", DOF " << i;
  }
}

TEST(DampingLanes, EveryLaneIsItsOwnModelsForce) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> velocity(-0.4, 0.4);  // beyond the yaw table's +-0.3 at times
  for (const bool surge : {false, true}) {
    std::vector<DampingModel> drawn;
    for (std::size_t l = 0; l < kLanes; ++l) drawn.push_back(lane_model(l, surge, Extrapolation::Linear));
    std::array<const DampingModel*, kLanes> models;
    for (std::size_t l = 0; l < kLanes; ++l) models[l] = &drawn[l];
    EXPECT_TRUE(DampingLanes(models).shared());
    for (int round = 0; round < 50; ++round) {
      Lanes nu_r[6];
      for (Lanes& v : nu_r)
        for (Eigen::Index l = 0; l < kLanes; ++l) v[l] = velocity(rng);
      const std::vector<double> disturbance = {0.3 * static_cast<double>(round) / 50.0};
      expect_lanes_are_each_models_own(models, nu_r,
                                       surge ? std::span<const double>(disturbance) : std::span<const double>());
    }
  }
}

TEST(DampingLanes, ModelsOfAnotherShapeGoLaneByLane) {
  // One lane's model lacks the surge surface: not shared, still each its own.
  std::vector<DampingModel> drawn;
  for (std::size_t l = 0; l < kLanes; ++l) drawn.push_back(lane_model(l, false, Extrapolation::Clamp));
  // A yaw table on another axis in one lane: shared laws, that lookup lane by lane.
  std::vector<GridAxis> axes{{"r", {-0.3, 0.0, 0.3}, Extrapolation::Clamp}};
  DampingSpec spec;
  spec[1].kind = DofDamping::Kind::Law;
  spec[1].law = parse_damping_terms("v|v|,v,1");
  spec[1].coefficients = {-9.0, -0.02, 0.0};
  spec[3].kind = DofDamping::Kind::Law;
  spec[3].law = parse_damping_terms("p,p^3");
  spec[3].coefficients = {-0.005, -0.2};
  spec[5].kind = DofDamping::Kind::Surface;
  spec[5].surface = "yaw";
  spec[5].output = "N";
  drawn[5] = DampingModel(spec, [&](const std::string&) {
    return CoefficientSurface(GridTable(axes, {"N"}, {0.01, 0.0, -0.01}, Interpolation::NaturalSpline));
  });
  std::array<const DampingModel*, kLanes> models;
  for (std::size_t l = 0; l < kLanes; ++l) models[l] = &drawn[l];
  EXPECT_TRUE(DampingLanes(models).shared());
  Lanes nu_r[6];
  for (std::size_t i = 0; i < 6; ++i)
    for (Eigen::Index l = 0; l < kLanes; ++l)
      nu_r[i][l] = 0.05 * static_cast<double>(l) - 0.17 + 0.01 * static_cast<double>(i);
  expect_lanes_are_each_models_own(models, nu_r, {});
  // Laws of other terms in one lane: nothing shared.
  spec[3].law = parse_damping_terms("p,p|p|");
  drawn[2] = DampingModel(spec, [&](const std::string&) { return yaw_table(1.0, Extrapolation::Clamp); });
  EXPECT_FALSE(DampingLanes(models).shared());
  expect_lanes_are_each_models_own(models, nu_r, {});
  // Another disturbance list is refused.
  drawn[1] = lane_model(1, true, Extrapolation::Clamp);
  EXPECT_THROW(DampingLanes{models}, std::invalid_argument);
}

TEST(DampingLanes, ALookupOutsideItsTableThrowsAsTheModelDoes) {
  std::vector<DampingModel> drawn;
  for (std::size_t l = 0; l < kLanes; ++l) drawn.push_back(lane_model(l, false, Extrapolation::Error));
  std::array<const DampingModel*, kLanes> models;
  for (std::size_t l = 0; l < kLanes; ++l) models[l] = &drawn[l];
  Lanes nu_r[6], out[6];
  for (Lanes& v : nu_r) v.setConstant(0.1);
  nu_r[5][3] = 0.5;  // r beyond 0.3 in lane 3
  EXPECT_THROW(DampingLanes(models).add(nu_r, {}, out), InputError);
}

}  // namespace
}  // namespace hydrocoef
