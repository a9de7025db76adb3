// A face listed twice: found in any rotation and either orientation, never
// confused with another polygon on the same points, found in a point shared
// by very many faces; and every surface importer refuses the file with both
// faces' places (CFD-Post: both lines; VTK: both cells), where the force would
// otherwise count the face twice.
#include "src/mesh/duplicate_faces.hpp"

#include <gtest/gtest.h>
#include <vtkPolyDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "importers/cfdpost_export.hpp"
#include "importers/vtk_surface.hpp"
#include "src/loads/surface_loads.hpp"
#include "tests/support/cfdpost_writer.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/meshes.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/vtk_polydata.hpp"

namespace hydrocoef {
namespace {

using test::TempDir;

/// The mesh with face `f` appended again, its points rotated by `shift` and reversed when asked.
SurfaceMesh with_copy(SurfaceMesh mesh, std::size_t f, std::size_t shift, bool reversed) {
  std::vector<std::uint32_t> face(mesh.face_indices.begin() + mesh.face_offsets[f],
                                  mesh.face_indices.begin() + mesh.face_offsets[f + 1]);
  std::rotate(face.begin(), face.begin() + static_cast<std::ptrdiff_t>(shift % face.size()), face.end());
  if (reversed) std::reverse(face.begin(), face.end());
  mesh.face_indices.insert(mesh.face_indices.end(), face.begin(), face.end());
  mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.face_indices.size()));
  if (!mesh.face_location.empty()) mesh.face_location.push_back(mesh.face_location[f]);
  return mesh;
}

SurfaceMesh box() { return test::make_hexahedron(test::box_corners(1.0, 2.0, 3.0)); }  // six quads

TEST(DuplicateFaces, ACleanSurfaceHasNone) {
  EXPECT_FALSE(find_duplicate_face(test::make_icosphere(1.0, 3)));
  EXPECT_FALSE(find_duplicate_face(box()));
  EXPECT_FALSE(find_duplicate_face(SurfaceMesh{}));
}

TEST(DuplicateFaces, FoundInEveryRotationAndBothOrientations) {
  const SurfaceMesh sphere = test::make_icosphere(1.0, 2);
  const SurfaceMesh quads = box();
  for (const bool reversed : {false, true})
    for (std::size_t shift = 0; shift < 4; ++shift) {
      const auto triangle = find_duplicate_face(with_copy(sphere, 17, shift, reversed));
      ASSERT_TRUE(triangle) << shift << reversed;
      EXPECT_EQ(triangle->first, 17u);
      EXPECT_EQ(triangle->second, sphere.face_count());
      const auto quad = find_duplicate_face(with_copy(quads, 4, shift, reversed));
      ASSERT_TRUE(quad) << shift << reversed;
      EXPECT_EQ(quad->first, 4u);
      EXPECT_EQ(quad->second, 6u);
    }
}

// The same four points in another cyclic order are another polygon (a
// bow-tie), and a triangle is not the quad it is part of.
TEST(DuplicateFaces, OtherPolygonsOnTheSamePointsAreNotCopies) {
  SurfaceMesh mesh = box();
  const std::uint32_t* q = mesh.face_indices.data() + mesh.face_offsets[2];
  const std::array<std::uint32_t, 4> quad = {q[0], q[1], q[2], q[3]};
  test::add_face(mesh, {quad[0], quad[2], quad[1], quad[3]});
  test::add_face(mesh, {quad[0], quad[1], quad[2]});
  EXPECT_FALSE(find_duplicate_face(mesh));
}

TEST(DuplicateFaces, TheEarliestRepeatIsNamed) {
  SurfaceMesh mesh = with_copy(with_copy(test::make_icosphere(1.0, 2), 30, 1, false), 5, 2, true);
  const std::size_t faces = mesh.face_count();
  const auto found = find_duplicate_face(mesh);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->first, 30u);
  EXPECT_EQ(found->second, faces - 2);
}

// 200,000 distinct triangles on one apex point, then one of them again: the
// bucket of that point is sorted by hash, not compared pair by pair (which
// would take 2e10 comparisons).
TEST(DuplicateFaces, APointSharedByVeryManyFaces) {
  SurfaceMesh mesh;
  test::add_point(mesh, {0, 0, 0});
  const std::uint32_t ring = 200000;
  for (std::uint32_t i = 0; i < ring; ++i) test::add_point(mesh, {std::cos(i * 1e-5), std::sin(i * 1e-5), 1.0});
  for (std::uint32_t i = 0; i < ring; ++i) test::add_face(mesh, {0, 1 + i, 1 + (i + 1) % ring});
  EXPECT_FALSE(find_duplicate_face(mesh));
  test::add_face(mesh, {1 + 77778, 0, 1 + 77777});
  const auto found = find_duplicate_face(mesh);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->first, 77777u);
  EXPECT_EQ(found->second, ring);
}

// --- the importers ---------------------------------------------------------

SurfaceMesh sphere_with_pressure() {
  SurfaceMesh mesh = test::make_icosphere(0.15, 1);  // 80 triangles
  test::add_point_scalar(mesh, "Pressure", [](const test::P3& x) { return 1000.0 + 500.0 * x[2]; });
  return mesh;
}

TEST(DuplicateFaces, CfdPostExportIsRefusedWithBothLines) {
  const SurfaceMesh mesh = with_copy(sphere_with_pressure(), 7, 1, true);
  const std::string text = test::write_cfdpost_export(mesh);
  // The face lines: the line after "[Faces]" holds face 1.
  std::size_t faces_line = 1;
  for (std::size_t at = 0; at < text.find("[Faces]"); ++at) faces_line += text[at] == '\n';
  const std::size_t first_line = faces_line + 1 + 7, second_line = faces_line + 1 + 80;
  test::expect_input_error([&] { parse_cfdpost_export(text, "hull.csv"); },
                           {"hull.csv:" + std::to_string(second_line) + ":1: ", "face 81: the nodes of face 8",
                            "(line " + std::to_string(first_line) + ")", "expected each face once"});
}

TEST(DuplicateFaces, VtkFilesAreRefusedWithBothCells) {
  TempDir dir;
  const SurfaceMesh mesh = with_copy(sphere_with_pressure(), 12, 2, false);
  const auto polydata = test::to_vtk_polydata(mesh);
  vtkNew<vtkXMLPolyDataWriter> xml;  // read by hydrocoef's own .vtp reader
  xml->SetInputData(polydata);
  xml->SetFileName((dir / "hull.vtp").c_str());
  ASSERT_EQ(xml->Write(), 1);
  vtkNew<vtkPolyDataWriter> legacy;  // read through VTK's reader
  legacy->SetInputData(polydata);
  legacy->SetFileName((dir / "hull.vtk").c_str());
  ASSERT_EQ(legacy->Write(), 1);
  for (const char* name : {"hull.vtp", "hull.vtk"})
    test::expect_input_error([&] { read_vtk_surface(dir / name); }, {(dir / name).string(), "cell 80: the points of",
                                                                     "cell 12 again", "expected each face once"});
  VtkSurfaceOptions through_vtk;
  through_vtk.direct_vtp = false;
  test::expect_input_error([&] { read_vtk_surface(dir / "hull.vtp", through_vtk); },
                           {"cell 80: the points of", "cell 12 again"});
}

// End to end: integrate and import refuse with exit code 2 and one line; the
// force of the file without the copy is what it was.
TEST(DuplicateFaces, TheCommandLineRefusesTheFile) {
  TempDir dir;
  const SurfaceMesh once = sphere_with_pressure();
  std::ofstream(dir / "once.csv") << test::write_cfdpost_export(once);
  std::ofstream(dir / "twice.csv") << test::write_cfdpost_export(with_copy(once, 3, 0, false));
  const auto good = test::run_cli({"integrate", "once.csv"}, dir.path());
  ASSERT_EQ(good.exit_code, 0) << good.err;
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"integrate", "twice.csv"}, {"import", "twice.csv", "--body", "hull", "--at-rest"}}) {
    const auto refused = test::run_cli(args, dir.path());
    EXPECT_EQ(refused.exit_code, 2) << refused.err;
    EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
    EXPECT_NE(refused.err.find("twice.csv:"), std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find(": the nodes of face 4 of block"), std::string::npos) << refused.err;
    EXPECT_EQ(refused.err.find("internal error"), std::string::npos) << refused.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "hydrocoef.db"));
}

}  // namespace
}  // namespace hydrocoef
