// Half and quarter models: the part's loads plus their mirror images equal
// the loads integrated over the whole body (a box whose fields have the
// body's symmetry), with moments about a point off the planes; the vanishing
// components; and the parsing of planes.
#include "src/loads/symmetry.hpp"

#include <gtest/gtest.h>

#include "src/core/error.hpp"
#include "tests/support/meshes.hpp"

namespace hydrocoef {
namespace {

using test::P3;

/// A box [x0,x1]×[y0,y1]×[z0,z1] as quads with outward normals, leaving out
/// the faces named in `open` ("y0" = the face at y = y0, ...).
SurfaceMesh box(P3 lo, P3 hi, const std::vector<std::string>& open = {}) {
  SurfaceMesh mesh = test::make_hexahedron(test::box_corners(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], lo));
  // make_hexahedron's faces: z0, z1, y0, x1, y1, x0.
  const std::vector<std::string> names = {"z0", "z1", "y0", "x1", "y1", "x0"};
  SurfaceMesh out;
  out.points_xyz = mesh.points_xyz;
  for (std::size_t f = 0; f < 6; ++f) {
    if (std::find(open.begin(), open.end(), names[f]) != open.end()) continue;
    for (auto k = mesh.face_offsets[f]; k < mesh.face_offsets[f + 1]; ++k)
      out.face_indices.push_back(mesh.face_indices[k]);
    out.face_offsets.push_back(static_cast<std::uint32_t>(out.face_indices.size()));
  }
  // Fields symmetric under y -> -y and z -> -z: a scalar even in y and z, a
  // vector whose y and z components are odd in them (linear, so integrated exactly).
  test::add_point_scalar(out, "p", [](const P3& x) { return 3.0 + 2.0 * x[0]; });
  test::add_point_vector(out, "tau", [](const P3& x) { return P3{1.0 + x[0], 0.5 * x[1], -0.25 * x[2]}; });
  return out;
}

SurfaceLoads integrate(const SurfaceMesh& mesh, const Vec3& reference) {
  SurfaceLoadOptions options;
  options.pressure_field = "p";
  options.shear_fields = {"tau"};
  options.reference_point = reference;
  options.normals = NormalPolicy::AsGiven;
  return integrate_surface_loads(mesh, options);
}

void expect_near(const Vec3& a, const Vec3& b, double tolerance, const char* what) {
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tolerance) << what << "[" << i << "]";
}

TEST(Symmetry, AHalfModelMirroredIsTheWholeBody) {
  const Vec3 reference{0.3, 0.2, -0.1};  // off the plane y = 0
  const SurfaceLoads whole = integrate(box({-1, -1, -0.5}, {2, 1, 0.7}), reference);
  const SurfaceLoads half = integrate(box({-1, 0, -0.5}, {2, 1, 0.7}, {"y0"}), reference);
  const SurfaceLoads mirrored = mirror_loads(half, parse_symmetry("y=0"));
  expect_near(mirrored.force_pressure, whole.force_pressure, 1e-12, "F_p");
  expect_near(mirrored.force_viscous, whole.force_viscous, 1e-12, "F_v");
  expect_near(mirrored.moment_pressure, whole.moment_pressure, 1e-12, "M_p");
  expect_near(mirrored.moment_viscous, whole.moment_viscous, 1e-12, "M_v");
  expect_near(mirrored.geometry.integral_n_dA, whole.geometry.integral_n_dA, 1e-12, "∫n dA");
  expect_near(mirrored.geometry.integral_x_cross_n_dA, whole.geometry.integral_x_cross_n_dA, 1e-12, "∫x×n dA");
  EXPECT_NEAR(mirrored.geometry.area, whole.geometry.area, 1e-12);
  EXPECT_NEAR(mirrored.geometry.signed_volume, whole.geometry.signed_volume, 1e-12);
  // The side force of the whole body vanishes though the half's does not.
  EXPECT_GT(std::abs(half.force()[1]), 0.1);
  EXPECT_EQ(mirrored.force()[1], 0.0);
}

TEST(Symmetry, AQuarterModelGivesFourTimesItsDragAndNoSideForce) {
  const Vec3 centre{0, 0, 0};
  const SurfaceLoads whole = integrate(box({-1, -1, -0.7}, {2, 1, 0.7}), centre);
  const SurfaceLoads quarter = integrate(box({-1, 0, 0}, {2, 1, 0.7}, {"y0", "z0"}), centre);
  const SurfaceLoads mirrored = mirror_loads(quarter, parse_symmetry("y=0,z=0"));
  EXPECT_NEAR(mirrored.force()[0], 4.0 * quarter.force()[0], 1e-9 * std::abs(quarter.force()[0]));
  EXPECT_NEAR(mirrored.force()[0], whole.force()[0], 1e-12);
  EXPECT_EQ(mirrored.force()[1], 0.0);
  EXPECT_EQ(mirrored.force()[2], 0.0);
  expect_near(mirrored.moment(), whole.moment(), 1e-12, "M");
  EXPECT_EQ(mirrored.moment()[0], 0.0);
  EXPECT_EQ(mirrored.moment()[1], 0.0);
  EXPECT_EQ(mirrored.moment()[2], 0.0);
}

TEST(Symmetry, OffsetPlanesAndForceHistories) {
  // The half of a box centred on y = 0.4, cut at y = 0.4.
  const Vec3 reference{0.0, 0.1, 0.0};
  SurfaceMesh whole_mesh = box({-1, -0.6, -0.5}, {2, 1.4, 0.7});
  SurfaceMesh half_mesh = box({-1, 0.4, -0.5}, {2, 1.4, 0.7}, {"y0"});
  // Fields symmetric about y = 0.4.
  for (auto* mesh : {&whole_mesh, &half_mesh}) {
    mesh->fields.clear();
    test::add_point_scalar(*mesh, "p", [](const P3& x) { return 1.0 + x[0] - x[2]; });
    test::add_point_vector(*mesh, "tau", [](const P3& x) { return P3{x[0], x[1] - 0.4, 0.0}; });
  }
  const SurfaceLoads whole = integrate(whole_mesh, reference);
  const SurfaceLoads half = integrate(half_mesh, reference);
  const auto planes = parse_symmetry("y=0.4");
  const SurfaceLoads mirrored = mirror_loads(half, planes);
  expect_near(mirrored.force(), whole.force(), 1e-12, "F");
  expect_near(mirrored.moment(), whole.moment(), 1e-12, "M");
  expect_near(mirrored.geometry.integral_x_cross_n_dA, whole.geometry.integral_x_cross_n_dA, 1e-12, "∫x×n dA");
  Vec3 force = half.force(), moment = half.moment();
  mirror_force_moment(force, moment, reference, planes);
  expect_near(force, whole.force(), 1e-12, "history F");
  expect_near(moment, whole.moment(), 1e-12, "history M");
}

TEST(Symmetry, VanishingComponentsAndParsing) {
  EXPECT_EQ(vanishing_components(parse_symmetry("y=0")), "Fy, Mx, Mz");
  EXPECT_EQ(vanishing_components(parse_symmetry("y=0,z=0")), "Fy, Fz, Mx, My, Mz");
  EXPECT_EQ(symmetry_text(parse_symmetry("z=0,y=+0.5")), "z=0,y=0.5");
  for (const char* bad : {"", "y", "y=", "w=0", "y=0,y=1", "y=abc", "y=inf", "y=0,"})
    EXPECT_THROW(parse_symmetry(bad), InputError) << bad;
}

}  // namespace
}  // namespace hydrocoef
