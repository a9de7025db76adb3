// Symmetry imposed on surfaces built with --mirror (src/pipeline/surface_mirror,
// src/surface/surface_symmetry): whatever the method, a side force odd in v is
// exactly 0 on the plane v = 0 even where the run there says otherwise (a
// CFD run on the plane carries a small side force from its mesh), the surge
// force even in v has exactly zero slope across it, values at v and -v agree
// to the bit, and all of it survives the database.
#include "src/pipeline/surface_mirror.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "src/pipeline/surface_build.hpp"
#include "src/surface/stored_surface.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/import_batch.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;
using test::TempDir;

double surge(double u, double v) { return -0.3 - 2.0 * u - 10.0 * u * std::abs(u) - 4.0 * v * v; }
// Odd in v, but the run on the plane has the small side force of an asymmetric mesh.
double sway(double u, double v) { return v == 0.0 ? -0.0068 : -3.0 * v - 20.0 * v * std::abs(v) - 0.5 * u * v; }

ImportBatch run_file(int id, double u, double v, double r = 0.0) {
  ImportedRun run;
  run.key.body = "boat";
  run.key.nu_b = {u, v, 0, 0, 0, r};
  run.tau_b[0] = ForceComponent{surge(u, v), std::nullopt, std::nullopt};
  run.tau_b[1] = ForceComponent{sway(u, v) + 0.001 * std::sin(7.0 * u + 3.0 * v), std::nullopt, std::nullopt};
  return test::one_run_batch(id, run);
}

// Half the plane, v >= 0: the mirror gives the other half.
void fill(RunDatabase& database) {
  int id = 1;
  for (const double u : {0.1, 0.2, 0.3, 0.4})
    for (const double v : {0.0, 0.05, 0.1, 0.2}) database.import({run_file(id++, u, v)}, ImportPolicy{});
}

SurfaceBuildSpec mirrored_spec(const std::string& method) {
  SurfaceBuildSpec spec;
  spec.surface.axes = {"u", "v"};
  spec.surface.outputs = {"X", "Y"};
  spec.surface.method = method;
  spec.surface.gp.starts = 2;
  spec.mirror_planes = {"v"};
  return spec;
}

class SurfaceMirror : public ::testing::TestWithParam<const char*> {};

TEST_P(SurfaceMirror, OddOutputsVanishOnThePlaneAndEvenOnesAreFlatAcrossIt) {
  TempDir dir;
  RunDatabase database(dir / "runs.db");
  fill(database);
  const std::string method = GetParam();
  build_and_store_surface(database, "s", "boat", mirrored_spec(method));
  // Loaded from the database: the symmetry is part of what is stored.
  const StoredSurface stored = load_surface(database, "s");
  const CoefficientSurface& surface = stored.surface;
  ASSERT_FALSE(surface.symmetry().empty()) << method;
  EXPECT_EQ(surface.symmetry().describe(surface.axis_names(), surface.output_names()), "v reflected: Y odd");
  double out[2], mirrored[2], gradient[4], mirrored_gradient[4];
  for (const double u : {0.1, 0.15, 0.2, 0.27, 0.4}) {
    const double on_plane[2] = {u, 0.0};
    surface.evaluate_with_gradient(on_plane, out, gradient);
    EXPECT_EQ(out[1], 0.0) << method << " Y at u = " << u;
    EXPECT_EQ(gradient[1], 0.0) << method << " dX/dv at u = " << u;
    EXPECT_LT(out[0], 0.0) << method;
    for (const double v : {0.01, 0.05, 0.13, 0.2}) {
      const double at[2] = {u, v}, image[2] = {u, -v};
      surface.evaluate_with_gradient(at, out, gradient);
      surface.evaluate_with_gradient(image, mirrored, mirrored_gradient);
      EXPECT_EQ(mirrored[0], out[0]) << method;
      EXPECT_EQ(mirrored[1], -out[1]) << method;
      EXPECT_EQ(mirrored_gradient[0], gradient[0]) << method << " dX/du";
      EXPECT_EQ(mirrored_gradient[1], -gradient[1]) << method << " dX/dv";
      EXPECT_EQ(mirrored_gradient[2], -gradient[2]) << method << " dY/du";
      EXPECT_EQ(mirrored_gradient[3], gradient[3]) << method << " dY/dv";
      // Away from the plane the surface still follows the runs.
      EXPECT_NEAR(out[1], sway(u, v), 0.05) << method;  // linear: the chord of v|v| between 0.1 and 0.2
    }
  }
  // The uncertainty: an odd output's projection is known exactly on the
  // plane for a GP (its sd there is 0); a grid or RBF keeps its
  // leave-one-out part; off the plane both state one.
  ASSERT_TRUE(surface.has_standard_deviation());
  double sd[2];
  const double on_plane[2] = {0.25, 0.0}, off[2] = {0.25, 0.15};
  surface.evaluate_with_standard_deviation(on_plane, out, sd);
  EXPECT_EQ(out[1], 0.0);
  if (method == "gp") EXPECT_EQ(sd[1], 0.0);
  EXPECT_GT(sd[0], 0.0);
  surface.evaluate_with_standard_deviation(off, out, sd);
  EXPECT_GT(sd[1], 0.0);
  // A grid's table, as exported, is symmetric itself: Y is 0 at its nodes on the plane.
  if (const GridTable* grid = surface.grid()) {
    const auto& v_axis = grid->axes()[1].breakpoints;
    const std::size_t nu = grid->axes()[0].breakpoints.size();
    for (std::size_t j = 0; j < v_axis.size(); ++j)
      if (v_axis[j] == 0.0)
        for (std::size_t i = 0; i < nu; ++i) EXPECT_EQ(grid->values()[(j * nu + i) * 2 + 1], 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, SurfaceMirror, ::testing::Values("linear", "pchip", "rbf", "gp"));

TEST(SurfaceMirrorRefusal, APlaneThatReversesAQuantityTheSurfaceDoesNotSpanIsRefused) {
  TempDir dir;
  RunDatabase database(dir / "runs.db");
  fill(database);
  // A run turning at r = 0.2 rad/s: its image would turn the other way, off this surface over (u, v).
  database.import({run_file(40, 0.3, 0.3, 0.2)}, ImportPolicy{});
  expect_input_error([&] { build_and_store_surface(database, "s", "boat", mirrored_spec("rbf")); },
                     {"--mirror v reverses r", "is 0.2 in run", "--where"});
  EXPECT_TRUE(database.surfaces().empty());
}

TEST(SurfaceMirrorRefusal, APlaneThatMovesNoAxisZeroesTheOutputsOddInIt) {
  // A surface over u alone with a mirror in v: a symmetric body in pure
  // surge has no side force, whatever the runs on the plane say.
  TempDir dir;
  RunDatabase database(dir / "runs.db");
  int id = 1;
  for (const double u : {0.1, 0.2, 0.3, 0.4}) database.import({run_file(id++, u, 0.0)}, ImportPolicy{});
  SurfaceBuildSpec spec = mirrored_spec("pchip");
  spec.surface.axes = {"u"};
  build_and_store_surface(database, "s", "boat", spec);
  const auto surface = load_surface(database, "s").surface;
  double out[2];
  for (const double u : {0.1, 0.25, 0.4}) {
    surface.evaluate(std::vector<double>{u}, out);
    EXPECT_EQ(out[1], 0.0);
    EXPECT_NEAR(out[0], surge(u, 0.0), 1e-3);
  }
}

}  // namespace
}  // namespace hydrocoef
