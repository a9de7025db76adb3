// SurfaceSymmetry's own rules (src/surface/surface_symmetry.hpp): what a
// generator may be, what it does to a point, and how a stored definition
// that states a broken one is refused.
#include "src/surface/surface_symmetry.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "src/surface/coefficient_surface.hpp"
#include "src/surface/stored_surface.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;

TEST(SurfaceSymmetry, DropsIdentitiesAndRefusesMalformedReflections) {
  // Flipping nothing is the identity: dropped.
  EXPECT_TRUE(SurfaceSymmetry(2, 1, {{{1, 1}, {1}}}).empty());
  const SurfaceSymmetry s(2, 2, {{{1, 1}, {1, -1}}, {{1, -1}, {1, -1}}});
  ASSERT_EQ(s.generators().size(), 2u);
  EXPECT_EQ(s.moving_count(), 1u);  // the one that moves an axis comes first
  EXPECT_EQ(s.generators()[0].axis_signs, (std::vector<double>{1, -1}));
  expect_input_error([] { SurfaceSymmetry(2, 1, {{{1, 0.5}, {1}}}); }, {"not +1 or -1"});
  expect_input_error([] { SurfaceSymmetry(2, 1, {{{1, -1, 1}, {1}}}); }, {"3 axis signs", "expected 2"});
  expect_input_error([] { SurfaceSymmetry(1, 1, {{{-1}, {-1}}, {{-1}, {-1}}}); }, {"repeats another"});
  expect_input_error(
      [] {
        SurfaceSymmetry(4, 1, {{{-1, 1, 1, 1}, {1}}, {{1, -1, 1, 1}, {1}}, {{1, 1, -1, 1}, {1}}, {{1, 1, 1, -1}, {1}}});
      },
      {"at most 3"});
}

TEST(SurfaceSymmetry, APointOnThePlaneIsItsOwnImageToTheBit) {
  const SurfaceSymmetry s(2, 1, {{{1, -1}, {-1}}});
  double image[2];
  const double on[2] = {0.3, 0.0}, off[2] = {0.3, 0.25};
  s.reflect(0, on, image);
  EXPECT_FALSE(std::signbit(image[1]));  // +0, not -0
  s.reflect(0, off, image);
  EXPECT_EQ(image[0], 0.3);
  EXPECT_EQ(image[1], -0.25);
}

TEST(SurfaceSymmetry, ATableThatIsNotSymmetricIsProjectedWhenEvaluated) {
  // Breakpoints not symmetric about 0: the table keeps its values, the
  // evaluation is the projection (here of f = 1 + v: the even part is 1).
  GridTable table({{"v", {-0.2, 0.1, 0.3}, Extrapolation::Linear}}, {"X"}, {0.8, 1.1, 1.3}, Interpolation::Linear);
  const CoefficientSurface surface = CoefficientSurface(table).with_symmetry(SurfaceSymmetry(1, 1, {{{-1}, {1}}}));
  EXPECT_EQ(surface.grid()->values(), table.values());
  double out[1], gradient[1];
  surface.evaluate_with_gradient(std::vector<double>{0.1}, out, gradient);
  EXPECT_NEAR(out[0], 1.0, 1e-15);
  EXPECT_NEAR(gradient[0], 0.0, 1e-15);
  // Stored and read back, with the symmetry.
  const CoefficientSurface back = surface_from_record(record_from_surface(surface));
  ASSERT_FALSE(back.symmetry().empty());
  double again[1];
  back.evaluate(std::vector<double>{0.1}, again);
  EXPECT_EQ(again[0], out[0]);
}

TEST(SurfaceSymmetry, AStoredSymmetryThatDoesNotFitTheSurfaceIsRefused) {
  GridTable table({{"v", {-0.2, 0.0, 0.2}, Extrapolation::Error}}, {"Y"}, {0.5, 0.0, -0.5}, Interpolation::Linear);
  const CoefficientSurface surface = CoefficientSurface(table).with_symmetry(SurfaceSymmetry(1, 1, {{{-1}, {-1}}}));
  SurfaceRecord record = record_from_surface(surface);
  record.name = "side";
  const auto at = record.definition.find("\"axis_signs\":[-1.0]");
  ASSERT_NE(at, std::string::npos) << record.definition;
  record.definition.replace(at, 19, "\"axis_signs\":[-1.0,1.0]");
  expect_input_error([&] { (void)surface_from_record(record); }, {"surface 'side'", "2 axis signs", "expected 1"});
  record = record_from_surface(surface);
  record.name = "side";
  const auto sign = record.definition.find("\"output_signs\":[-1.0]");
  ASSERT_NE(sign, std::string::npos) << record.definition;
  record.definition.replace(sign, 21, "\"output_signs\":[-2.0]");
  expect_input_error([&] { (void)surface_from_record(record); }, {"surface 'side'", "not +1 or -1"});
}

TEST(SurfaceSymmetry, AProjectedGpStatesTheStandardDeviationOfItsJointPosterior) {
  // Independent check of the one-solve combination: sqrt(c^T C c) from
  // the joint posterior covariance of the two images (GpSurface::posterior).
  const std::vector<double> x = {0.1, 0.0, 0.2, 0.05, 0.35, -0.1, 0.15, 0.2, 0.4, 0.12, 0.3, -0.2};
  std::vector<double> y;
  for (std::size_t i = 0; i < x.size() / 2; ++i)
    y.push_back(-2.0 * x[2 * i + 1] - 0.5 * x[2 * i] * x[2 * i + 1] + 0.01 * std::cos(9.0 * x[2 * i]));
  GpOptions options;
  options.fixed_hyperparameters = {0.3, 0.2, 0.15, 0.002};
  const std::vector<double> noise(y.size(), 0.001);
  GpSurfaces gp(2, x, 1, y, noise, options, {"u", "v"}, {RbfOutOfRange::Error, RbfOutOfRange::Error});
  const GpSurface single = gp.output(0);
  const CoefficientSurface surface =
      CoefficientSurface(std::move(gp), {"u", "v"}, {"Y"}).with_symmetry(SurfaceSymmetry(2, 1, {{{1, -1}, {-1}}}));
  for (const double v : {0.0, 0.03, 0.1, 0.17}) {
    const double at[2] = {0.22, v};
    double out[1], sd[1];
    surface.evaluate_with_standard_deviation(at, out, sd);
    const std::vector<double> images = {0.22, v, 0.22, -v};
    std::vector<double> mean, covariance;
    single.posterior(images, 2, mean, covariance);
    const double variance = 0.25 * (covariance[0] - covariance[1] - covariance[2] + covariance[3]);
    EXPECT_NEAR(out[0], 0.5 * (mean[0] - mean[1]), 1e-12);
    EXPECT_NEAR(sd[0], std::sqrt(std::max(0.0, variance)), 1e-9 * (1.0 + std::sqrt(covariance[0]))) << v;
    if (v == 0.0) EXPECT_EQ(sd[0], 0.0);
  }
}

}  // namespace
}  // namespace hydrocoef
