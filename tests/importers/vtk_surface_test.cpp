// Tests of the VTK surface importer against the OpenFOAM sphere exports in
// the shared data folder, against VTK's own geometry filters, and against
// small files written here with VTK's writers.
#include "importers/vtk_surface.hpp"

#include <gtest/gtest.h>
#include <vtkAlgorithmOutput.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCompositeDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkMassProperties.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "src/core/error.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

const fs::path kSphereDir = fs::path(HYDROCOEF_DATA_DIR) / "openfoam-sphere";
const fs::path kFullVtp = kSphereDir / "full" / "u0.10_v0.00" / "u0.10_v0.00_sphere_t1000.vtp";
const fs::path kFullVtk = kSphereDir / "full" / "u0.10_v0.00" / "u0.10_v0.00_sphere_t1000.vtk";
const fs::path kQuarterVtp = kSphereDir / "quarter" / "U0.1000" / "U0.1000_sphere_t145.vtp";
constexpr double kSphereRadius = 0.15;  // [m]
constexpr std::size_t kFullSphereFaces = 4024;

using test::TempDir;

using test::read_bytes;
using test::write_bytes;

using Vec3 = std::array<double, 3>;

Vec3 point(const SurfaceMesh& mesh, std::uint32_t index) {
  return {mesh.points_xyz[3 * index], mesh.points_xyz[3 * index + 1], mesh.points_xyz[3 * index + 2]};
}

/// Newell's area vector of face f (half the sum of the edge cross products,
/// taken about the first corner to keep the round-off small).
Vec3 area_vector(const SurfaceMesh& mesh, std::size_t f) {
  const std::uint32_t begin = mesh.face_offsets[f];
  const std::uint32_t end = mesh.face_offsets[f + 1];
  const Vec3 origin = point(mesh, mesh.face_indices[begin]);
  Vec3 sum{};
  for (std::uint32_t k = begin + 1; k + 1 < end; ++k) {
    const Vec3 a = point(mesh, mesh.face_indices[k]);
    const Vec3 b = point(mesh, mesh.face_indices[k + 1]);
    const Vec3 u{a[0] - origin[0], a[1] - origin[1], a[2] - origin[2]};
    const Vec3 v{b[0] - origin[0], b[1] - origin[1], b[2] - origin[2]};
    sum[0] += 0.5 * (u[1] * v[2] - u[2] * v[1]);
    sum[1] += 0.5 * (u[2] * v[0] - u[0] * v[2]);
    sum[2] += 0.5 * (u[0] * v[1] - u[1] * v[0]);
  }
  return sum;
}

double surface_area(const SurfaceMesh& mesh) {
  double total = 0.0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const Vec3 s = area_vector(mesh, f);
    total += std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  }
  return total;
}

std::vector<std::uint64_t> bits(const std::vector<double>& values) {
  std::vector<std::uint64_t> out(values.size());
  if (!values.empty()) std::memcpy(out.data(), values.data(), values.size() * sizeof(double));
  return out;
}

/// What foamToVTK's ASCII legacy writer makes of a float32 value: 6
/// significant digits, read back by VTK as float.
double as_six_digit_ascii(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", static_cast<double>(static_cast<float>(value)));
  return static_cast<double>(std::strtof(text, nullptr));
}

void expect_same_structure(const SurfaceMesh& a, const SurfaceMesh& b) {
  ASSERT_EQ(a.point_count(), b.point_count());
  EXPECT_EQ(a.face_offsets, b.face_offsets);
  EXPECT_EQ(a.face_indices, b.face_indices);
  EXPECT_EQ(a.location_names, b.location_names);
  EXPECT_EQ(a.face_location, b.face_location);
  ASSERT_EQ(a.fields.size(), b.fields.size());
  for (std::size_t i = 0; i < a.fields.size(); ++i) {
    EXPECT_EQ(a.fields[i].name, b.fields[i].name);
    EXPECT_EQ(a.fields[i].association, b.fields[i].association);
    EXPECT_EQ(a.fields[i].components, b.fields[i].components);
    EXPECT_EQ(a.fields[i].values.size(), b.fields[i].values.size());
    EXPECT_EQ(a.fields[i].unit, b.fields[i].unit);
  }
}

// --- the OpenFOAM sphere ----------------------------------------------------

// foamToVTK wrote the legacy twin in ASCII with 6 significant digits, so it
// cannot match the .vtp's float32 bit for bit; what it must match bit for bit
// is each .vtp value printed the way foamToVTK prints it.
TEST(VtkSurface, LegacyAsciiTwinOfTheVtpHoldsTheSameMeshToItsPrintedDigits) {
  const SurfaceMesh vtp = read_vtk_surface(kFullVtp);
  const SurfaceMesh vtk = read_vtk_surface(kFullVtk);
  expect_same_structure(vtp, vtk);
  ASSERT_EQ(vtp.points_xyz.size(), vtk.points_xyz.size());

  std::size_t mismatches = 0;
  std::size_t differing = 0;  // values where the ASCII rounding did change something
  for (std::size_t i = 0; i < vtp.points_xyz.size(); ++i) {
    mismatches += as_six_digit_ascii(vtp.points_xyz[i]) != vtk.points_xyz[i];
    differing += vtp.points_xyz[i] != vtk.points_xyz[i];
  }
  for (std::size_t a = 0; a < vtp.fields.size(); ++a) {
    const auto& from_vtp = vtp.fields[a].values;
    const auto& from_vtk = vtk.fields[a].values;
    ASSERT_EQ(from_vtp.size(), from_vtk.size()) << vtp.fields[a].name;
    for (std::size_t i = 0; i < from_vtp.size(); ++i) {
      const bool mismatch = as_six_digit_ascii(from_vtp[i]) != from_vtk[i];
      mismatches += mismatch;
      differing += from_vtp[i] != from_vtk[i];
      if (mismatch && mismatches < 5)
        ADD_FAILURE() << vtp.fields[a].name << "[" << i << "]: vtp " << from_vtp[i] << ", vtk " << from_vtk[i];
    }
  }
  EXPECT_EQ(mismatches, 0u);
  EXPECT_GT(differing, 0u) << "the legacy file was expected to be the 6-digit ASCII export";
}

// A binary legacy file holds float32 exactly, so there the two formats must
// agree bit for bit.
TEST(VtkSurface, VtpAndBinaryLegacyVtkGiveBitIdenticalMeshes) {
  TempDir dir;
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(kFullVtp.string().c_str());
  vtkNew<vtkPolyDataWriter> writer;
  writer->SetInputConnection(reader->GetOutputPort());
  writer->SetFileTypeToBinary();
  const fs::path binary = dir / (kFullVtp.stem().string() + ".vtk");
  writer->SetFileName(binary.string().c_str());
  ASSERT_EQ(writer->Write(), 1);

  const SurfaceMesh vtp = read_vtk_surface(kFullVtp);
  const SurfaceMesh vtk = read_vtk_surface(binary);
  expect_same_structure(vtp, vtk);
  EXPECT_EQ(bits(vtp.points_xyz), bits(vtk.points_xyz));
  for (std::size_t a = 0; a < std::min(vtp.fields.size(), vtk.fields.size()); ++a)
    EXPECT_EQ(bits(vtp.fields[a].values), bits(vtk.fields[a].values)) << vtp.fields[a].name;
}

TEST(VtkSurface, FullSphereHasItsFacesPointsAndArrays) {
  const SurfaceMesh mesh = read_vtk_surface(kFullVtp);
  ASSERT_EQ(mesh.face_count(), kFullSphereFaces);
  EXPECT_EQ(mesh.point_count(), 5042u);
  EXPECT_EQ(mesh.location_names, std::vector<std::string>{"u0.10_v0.00_sphere_t1000"});
  EXPECT_EQ(mesh.face_location, std::vector<std::uint32_t>(kFullSphereFaces, 0));
  EXPECT_EQ(mesh.face_offsets.back(), mesh.face_indices.size());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto corners = mesh.face_offsets[f + 1] - mesh.face_offsets[f];
    EXPECT_GE(corners, 4u) << "face " << f;  // quads, pentagons and hexagons
    EXPECT_LE(corners, 6u) << "face " << f;
  }
  EXPECT_TRUE(std::all_of(mesh.face_indices.begin(), mesh.face_indices.end(),
                          [&mesh](std::uint32_t index) { return index < mesh.point_count(); }));
  // snappyHexMesh snapped the points to the sphere only to about 1e-3 (the
  // worst is 1.14e-3 inside), but none lies outside it beyond float32 rounding.
  double smallest = kSphereRadius;
  for (std::uint32_t p = 0; p < mesh.point_count(); ++p) {
    const Vec3 x = point(mesh, p);
    const double radius = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    ASSERT_LE(radius, kSphereRadius * (1.0 + 1e-6)) << "point " << p;
    ASSERT_GE(radius, kSphereRadius * (1.0 - 2e-3)) << "point " << p;
    smallest = std::min(smallest, radius);
  }
  EXPECT_NEAR(smallest, 0.1498293, 1e-7);

  for (const auto& [name, components] :
       {std::pair<std::string, int>{"p", 1}, {"pMean", 1}, {"wallShearStress", 3}, {"wallShearStressMean", 3}}) {
    const FieldArray* field = mesh.find_field(name);
    ASSERT_NE(field, nullptr) << name;
    EXPECT_EQ(field->association, FieldAssociation::Face) << name;
    EXPECT_EQ(field->components, components) << name;
    EXPECT_EQ(field->size(), kFullSphereFaces) << name;
    EXPECT_EQ(field->unit, "") << name;
  }
  // Values as the ASCII twin prints them (6 digits) and as a text editor shows them there.
  EXPECT_NEAR(mesh.find_field("p")->values[0], -0.00165955, 5e-9);
  EXPECT_NEAR(mesh.find_field("p")->values[3], -0.00126476, 5e-9);
  EXPECT_EQ(mesh.find_field("TimeValue"), nullptr);  // field data, not point or cell data
}

/// The faces of a SurfaceMesh as VTK polydata, to hand them back to VTK's filters.
vtkSmartPointer<vtkPolyData> to_polydata(const SurfaceMesh& mesh) {
  auto polydata = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (std::uint32_t p = 0; p < mesh.point_count(); ++p) points->InsertNextPoint(point(mesh, p).data());
  polydata->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    polys->InsertNextCell(static_cast<int>(mesh.face_offsets[f + 1] - mesh.face_offsets[f]));
    for (auto k = mesh.face_offsets[f]; k < mesh.face_offsets[f + 1]; ++k) polys->InsertCellPoint(mesh.face_indices[k]);
  }
  polydata->SetPolys(polys);
  return polydata;
}

/// vtkMassProperties' area of VTK's triangulation (vtkTriangleFilter) of a surface.
double vtk_triangulated_area(vtkAlgorithmOutput* surface) {
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(surface);
  vtkNew<vtkMassProperties> mass;
  mass->SetInputConnection(triangles->GetOutputPort());
  mass->Update();
  return mass->GetSurfaceArea();
}

double vtk_triangulated_area(vtkPolyData* surface) {
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(surface);
  vtkNew<vtkMassProperties> mass;
  mass->SetInputConnection(triangles->GetOutputPort());
  mass->Update();
  return mass->GetSurfaceArea();
}

TEST(VtkSurface, FaceAreasAgreeWithVtkMassPropertiesAndTheSphere) {
  TempDir dir;
  const double sphere = 4.0 * std::numbers::pi * kSphereRadius * kSphereRadius;
  for (const auto& [file, fraction] : {std::pair{kFullVtp, 1.0}, std::pair{kQuarterVtp, 0.25}}) {
    SCOPED_TRACE(file.filename().string());
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(file.string().c_str());
    const double vtk_area = vtk_triangulated_area(reader->GetOutputPort());

    // The faces we read, triangulated by VTK, are VTK's own faces.
    const SurfaceMesh mesh = read_vtk_surface(file);
    EXPECT_NEAR(vtk_triangulated_area(to_polydata(mesh)), vtk_area, 1e-12 * vtk_area);

    // snappyHexMesh's polygons are slightly warped: Newell's area is their
    // projected area, a little less than the area of any triangulation.
    const double newell_area = surface_area(mesh);
    EXPECT_LE(newell_area, vtk_area);
    EXPECT_NEAR(newell_area, vtk_area, 1e-4 * vtk_area);

    // On VTK's triangles the two areas are the same thing.
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputConnection(reader->GetOutputPort());
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputConnection(triangles->GetOutputPort());
    const fs::path triangulated = dir / ("triangulated_" + file.filename().string());
    writer->SetFileName(triangulated.string().c_str());
    ASSERT_EQ(writer->Write(), 1);
    const double triangle_area = surface_area(read_vtk_surface(triangulated));
    EXPECT_NEAR(triangle_area, vtk_area, 1e-9 * vtk_area);

    // Flat facets inside the sphere: a little less than the sphere's area.
    EXPECT_LT(newell_area, fraction * sphere);
    EXPECT_NEAR(newell_area, fraction * sphere, 0.03 * fraction * sphere);
  }
}

// --- files written here ---------------------------------------------------

struct CellSpec {
  int type;
  std::vector<vtkIdType> ids;
};

vtkSmartPointer<vtkUnstructuredGrid> make_grid(const std::vector<Vec3>& points, const std::vector<CellSpec>& cells) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> xyz;
  xyz->SetDataTypeToDouble();
  for (const auto& p : points) xyz->InsertNextPoint(p.data());
  grid->SetPoints(xyz);
  grid->Allocate(static_cast<vtkIdType>(cells.size()));
  for (const auto& cell : cells)
    grid->InsertNextCell(cell.type, static_cast<vtkIdType>(cell.ids.size()), cell.ids.data());
  return grid;
}

template <typename Array = vtkDoubleArray>
void add_array(vtkDataSetAttributes* attributes, const char* name, int components, const std::vector<double>& values) {
  vtkNew<Array> array;
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()) / components);
  for (std::size_t i = 0; i < values.size(); ++i)
    array->SetValue(static_cast<vtkIdType>(i), static_cast<typename Array::ValueType>(values[i]));
  attributes->AddArray(array);
}

const std::vector<double> kHullVelocity = {0.1, 0, 0, 0.2, 0, 0, 0.3, 0, 0, 0.4, 0, 0, 0.5, 0, 0, 0.6, 0, -1};

/// Two quads side by side at z = 0 and a line (ignored): cell data p, a
/// float32 array only this block has and a 9-component array; point data U.
vtkSmartPointer<vtkUnstructuredGrid> make_hull() {
  auto grid = make_grid({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}},
                        {{VTK_LINE, {0, 1}}, {VTK_QUAD, {0, 1, 4, 3}}, {VTK_QUAD, {1, 2, 5, 4}}});
  add_array(grid->GetCellData(), "p", 1, {99.0, 1.5, 2.5});
  add_array<vtkFloatArray>(grid->GetCellData(), "hull_only", 1, {0.0, 0.1, 0.2});
  add_array(grid->GetCellData(), "tensor", 9, std::vector<double>(27, 1.0));
  add_array(grid->GetPointData(), "U", 3, kHullVelocity);
  return grid;
}

/// A triangle strip of 4 points (2 triangles) at z = 1 and a pixel at z = 2:
/// cell data p, point data U.
vtkSmartPointer<vtkUnstructuredGrid> make_fin() {
  auto grid = make_grid({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}, {0, 0, 2}, {1, 0, 2}, {0, 1, 2}, {1, 1, 2}},
                        {{VTK_TRIANGLE_STRIP, {0, 1, 2, 3}}, {VTK_PIXEL, {4, 5, 6, 7}}});
  add_array(grid->GetCellData(), "p", 1, {7.0, 8.0});
  add_array(grid->GetPointData(), "U", 3, std::vector<double>(24, 2.0));
  return grid;
}

void write_vtu(vtkUnstructuredGrid* grid, const fs::path& file) {
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName(file.string().c_str());
  ASSERT_EQ(writer->Write(), 1);
}

void set_block(vtkMultiBlockDataSet* blocks, unsigned int index, vtkDataObject* block, const char* name) {
  blocks->SetBlock(index, block);
  blocks->GetMetaData(index)->Set(vtkCompositeDataSet::NAME(), name);
}

void write_vtm(vtkMultiBlockDataSet* blocks, const fs::path& file) {
  vtkNew<vtkXMLMultiBlockDataWriter> writer;
  writer->SetInputData(blocks);
  writer->SetFileName(file.string().c_str());
  ASSERT_EQ(writer->Write(), 1);
}

TEST(VtkSurface, ReadsAnUnstructuredSurfaceGrid) {
  TempDir dir;
  const fs::path file = dir / "hull.vtu";
  write_vtu(make_hull(), file);

  const SurfaceMesh mesh = read_vtk_surface(file);
  EXPECT_EQ(mesh.location_names, std::vector<std::string>{"hull"});
  EXPECT_EQ(mesh.points_xyz, (std::vector<double>{0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0}));
  EXPECT_EQ(mesh.face_offsets, (std::vector<std::uint32_t>{0, 4, 8}));
  EXPECT_EQ(mesh.face_indices, (std::vector<std::uint32_t>{0, 1, 4, 3, 1, 2, 5, 4}));
  EXPECT_EQ(mesh.face_location, (std::vector<std::uint32_t>{0, 0}));

  const FieldArray* p = mesh.find_field("p");
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->association, FieldAssociation::Face);
  EXPECT_EQ(p->values, (std::vector<double>{1.5, 2.5}));  // the line's 99 is not a face's
  const FieldArray* hull_only = mesh.find_field("hull_only");
  ASSERT_NE(hull_only, nullptr);
  EXPECT_EQ(hull_only->values, (std::vector<double>{static_cast<double>(0.1f), static_cast<double>(0.2f)}));
  const FieldArray* u = mesh.find_field("U");
  ASSERT_NE(u, nullptr);
  EXPECT_EQ(u->association, FieldAssociation::Point);
  EXPECT_EQ(u->components, 3);
  EXPECT_EQ(u->values, kHullVelocity);
  EXPECT_EQ(mesh.find_field("tensor"), nullptr);  // 9 components
  ASSERT_EQ(mesh.fields.size(), 3u);
  EXPECT_EQ(mesh.fields.back().name, "U");  // face arrays first
}

// A 2 x 2 x 2 block of unit hexahedra: 24 boundary quads on 26 points (the
// centre point is inside), each with the pressure of its hexahedron.
TEST(VtkSurface, ReducesAVolumeGridToItsBoundary) {
  TempDir dir;
  const fs::path file = dir / "block.vtu";
  std::vector<Vec3> points;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) points.push_back({double(i), double(j), double(k)});
  const auto id = [](int i, int j, int k) { return vtkIdType{i + 3 * j + 9 * k}; };
  std::vector<CellSpec> cells;
  std::vector<double> pressure;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        cells.push_back({VTK_HEXAHEDRON,
                         {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                          id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)}});
        pressure.push_back(100.0 + i + 2 * j + 4 * k);
      }
  auto block = make_grid(points, cells);
  add_array(block->GetCellData(), "p", 1, pressure);
  write_vtu(block, file);

  const SurfaceMesh mesh = read_vtk_surface(file);
  ASSERT_EQ(mesh.face_count(), 24u);
  EXPECT_EQ(mesh.point_count(), 26u);
  EXPECT_NEAR(surface_area(mesh), 24.0, 1e-12);
  const FieldArray* p = mesh.find_field("p");
  ASSERT_NE(p, nullptr);
  ASSERT_EQ(p->size(), 24u);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    ASSERT_EQ(mesh.face_offsets[f + 1] - mesh.face_offsets[f], 4u);
    Vec3 centre{};
    for (auto k = mesh.face_offsets[f]; k < mesh.face_offsets[f + 1]; ++k)
      for (int c = 0; c < 3; ++c) centre[c] += 0.25 * point(mesh, mesh.face_indices[k])[c];
    // Boundary faces point out of the block...
    const Vec3 s = area_vector(mesh, f);
    EXPECT_GT(s[0] * (centre[0] - 1) + s[1] * (centre[1] - 1) + s[2] * (centre[2] - 1), 0.0) << "face " << f;
    // ... and carry the pressure of the hexahedron just inside them.
    const auto cell = [&](int c) { return centre[c] - 0.1 * s[c] < 1.0 ? 0 : 1; };
    EXPECT_EQ(p->values[f], 100.0 + cell(0) + 2 * cell(1) + 4 * cell(2)) << "face " << f;
  }
}

TEST(VtkSurface, ReadsAndSelectsTheBlocksOfAMultiblockFile) {
  TempDir dir;
  const fs::path file = dir / "vehicle.vtm";
  vtkNew<vtkMultiBlockDataSet> blocks;
  set_block(blocks, 0, make_hull(), "hull");
  set_block(blocks, 1, make_fin(), "fin");
  write_vtm(blocks, file);

  EXPECT_EQ(list_vtk_locations(file), (std::vector<std::string>{"hull", "fin"}));

  const SurfaceMesh all = read_vtk_surface(file);
  EXPECT_EQ(all.location_names, (std::vector<std::string>{"hull", "fin"}));
  EXPECT_EQ(all.point_count(), 14u);
  EXPECT_EQ(all.face_offsets, (std::vector<std::uint32_t>{0, 4, 8, 11, 14, 18}));
  // The fin's points follow the hull's 6; the strip's second triangle is
  // flipped to keep the strip's orientation; the pixel goes round its corners.
  EXPECT_EQ(all.face_indices, (std::vector<std::uint32_t>{0, 1, 4, 3, 1, 2, 5, 4, 6, 7, 8, 8, 7, 9, 10, 11, 13, 12}));
  EXPECT_EQ(all.face_location, (std::vector<std::uint32_t>{0, 0, 1, 1, 1}));
  ASSERT_NE(all.find_field("p"), nullptr);
  EXPECT_EQ(all.find_field("p")->values, (std::vector<double>{1.5, 2.5, 7.0, 7.0, 8.0}));
  ASSERT_NE(all.find_field("U"), nullptr);
  EXPECT_EQ(all.find_field("U")->size(), 14u);
  EXPECT_EQ(all.find_field("hull_only"), nullptr);  // the fin does not have it
  for (std::size_t f = 0; f < all.face_count(); ++f) {
    const Vec3 s = area_vector(all, f);
    EXPECT_GT(s[2], 0.0) << "face " << f;  // every face of both blocks faces +z
  }

  const SurfaceMesh fin = read_vtk_surface(file, {.locations = {"fin"}});
  EXPECT_EQ(fin.location_names, std::vector<std::string>{"fin"});
  EXPECT_EQ(fin.face_count(), 3u);
  EXPECT_EQ(fin.point_count(), 8u);
  EXPECT_EQ(fin.face_indices, (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3, 4, 5, 7, 6}));
  EXPECT_EQ(fin.face_location, (std::vector<std::uint32_t>{0, 0, 0}));
  EXPECT_EQ(fin.find_field("p")->values, (std::vector<double>{7.0, 7.0, 8.0}));

  try {
    read_vtk_surface(file, {.locations = {"fin", "rudder"}});
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("vehicle.vtm"), std::string::npos) << message;
    EXPECT_NE(message.find("'rudder'"), std::string::npos) << message;
    EXPECT_NE(message.find("'hull', 'fin'"), std::string::npos) << message;
  }
}

TEST(VtkSurface, NamesNestedAndUnnamedBlocksByTheirPath) {
  TempDir dir;
  const fs::path file = dir / "nested.vtm";
  vtkNew<vtkMultiBlockDataSet> boundary;
  set_block(boundary, 0, make_hull(), "hull");
  boundary->SetBlock(1, make_fin());
  vtkNew<vtkMultiBlockDataSet> top;
  set_block(top, 0, boundary, "boundary");
  write_vtm(top, file);

  EXPECT_EQ(list_vtk_locations(file), (std::vector<std::string>{"boundary/hull", "boundary/block1"}));
  const SurfaceMesh mesh = read_vtk_surface(file, {.locations = {"boundary/block1"}});
  EXPECT_EQ(mesh.face_count(), 3u);
}

// --- errors ------------------------------------------------------------------

/// The message of the InputError that reading `file` throws, "" if none.
std::string read_error(const fs::path& file) {
  try {
    read_vtk_surface(file);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

void expect_input_error_naming_file(const fs::path& file) {
  ::testing::internal::CaptureStderr();
  const std::string message = read_error(file);
  const std::string stderr_text = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(message.find(file.filename().string()), std::string::npos)
      << file << ": " << (message.empty() ? "no InputError" : message);
  EXPECT_EQ(stderr_text, "") << "VTK wrote to the terminal reading " << file;
}

TEST(VtkSurface, MissingUnknownAndEmptyFilesAreInputErrors) {
  TempDir dir;
  expect_input_error_naming_file(dir / "missing.vtp");

  write_bytes(dir / "sphere.stl", "solid sphere\nendsolid sphere\n");
  expect_input_error_naming_file(dir / "sphere.stl");
  EXPECT_NE(read_error(dir / "sphere.stl").find(".stl"), std::string::npos);

  for (const char* name : {"empty.vtp", "empty.vtk", "empty.vtu", "empty.vtm"}) {
    write_bytes(dir / name, "");
    expect_input_error_naming_file(dir / name);
  }
}

TEST(VtkSurface, TruncatedAndGarbageFilesAreInputErrorsCarryingVtksMessage) {
  TempDir dir;
  const std::string vtp = read_bytes(kFullVtp);
  write_bytes(dir / "truncated.vtp", vtp.substr(0, vtp.size() / 2));
  expect_input_error_naming_file(dir / "truncated.vtp");
  EXPECT_NE(read_error(dir / "truncated.vtp").find("Error parsing XML"), std::string::npos)
      << read_error(dir / "truncated.vtp");

  // The legacy reader only warns about a truncated array and keeps it half
  // filled; that must still be an error, wherever the file was cut.
  const std::string vtk = read_bytes(kFullVtk);
  for (const std::size_t size : {vtk.size() / 2, std::size_t{30000}, std::size_t{150000}, vtk.size() - 100}) {
    const std::string name = "truncated_" + std::to_string(size) + ".vtk";
    write_bytes(dir / name, vtk.substr(0, size));
    expect_input_error_naming_file(dir / name);
    EXPECT_NE(read_error(dir / name).find("Error reading ascii data"), std::string::npos) << read_error(dir / name);
  }

  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(kFullVtp.string().c_str());
  vtkNew<vtkPolyDataWriter> writer;
  writer->SetInputConnection(reader->GetOutputPort());
  writer->SetFileTypeToBinary();
  writer->SetFileName((dir / "binary.vtk").string().c_str());
  ASSERT_EQ(writer->Write(), 1);
  const std::string binary = read_bytes(dir / "binary.vtk");
  write_bytes(dir / "truncated_binary.vtk", binary.substr(0, binary.size() / 2));
  expect_input_error_naming_file(dir / "truncated_binary.vtk");

  std::mt19937 random(20240521);
  std::string garbage(4096, '\0');
  std::generate(garbage.begin(), garbage.end(), [&random] { return static_cast<char>(random() & 0xff); });
  for (const char* name : {"random.vtk", "random.vtp", "random.vtu", "random.vtm"}) {
    write_bytes(dir / name, garbage);
    expect_input_error_naming_file(dir / name);
    for (const char c : read_error(dir / name))  // VTK quotes the garbage; the message stays printable
      EXPECT_TRUE(c >= 0x20 && c < 0x7f) << name << ": byte " << static_cast<int>(static_cast<unsigned char>(c));
  }
}

// Silencing VTK is for the importer's own reads only: afterwards VTK reports
// to the terminal again as it did before.
TEST(VtkSurface, LeavesVtksMessagesAsTheyWereAfterReading) {
  TempDir dir;
  write_bytes(dir / "random.vtp", std::string(64, '\x01'));
  EXPECT_NE(read_error(dir / "random.vtp"), "");

  ::testing::internal::CaptureStderr();
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName((dir / "random.vtp").string().c_str());
  reader->Update();
  const std::string stderr_text = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(stderr_text.find("Error parsing XML"), std::string::npos) << stderr_text;
}

TEST(VtkSurface, AMultiblockFileWithABrokenPieceIsAnInputError) {
  TempDir dir;
  vtkNew<vtkMultiBlockDataSet> blocks;
  set_block(blocks, 0, make_hull(), "hull");
  set_block(blocks, 1, make_fin(), "fin");
  write_vtm(blocks, dir / "vehicle.vtm");
  ASSERT_NO_THROW(read_vtk_surface(dir / "vehicle.vtm"));

  // The writer puts the pieces in a folder named after the file.
  std::vector<fs::path> pieces;
  for (const auto& entry : fs::recursive_directory_iterator(dir / "vehicle"))
    if (entry.is_regular_file()) pieces.push_back(entry.path());
  ASSERT_EQ(pieces.size(), 2u);
  std::sort(pieces.begin(), pieces.end());
  const std::string piece = read_bytes(pieces[1]);
  write_bytes(pieces[1], piece.substr(0, piece.size() / 2));
  expect_input_error_naming_file(dir / "vehicle.vtm");

  fs::remove(pieces[1]);
  expect_input_error_naming_file(dir / "vehicle.vtm");
}

TEST(VtkSurface, PointIndexOutOfRangeIsAnInputError) {
  TempDir dir;
  const fs::path file = dir / "bad_index.vtp";
  write_bytes(file, R"(<?xml version="1.0"?>
<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">
  <PolyData>
    <Piece NumberOfPoints="3" NumberOfPolys="1">
      <Points>
        <DataArray type="Float64" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0</DataArray>
      </Points>
      <Polys>
        <DataArray type="Int64" Name="connectivity" format="ascii">0 1 7</DataArray>
        <DataArray type="Int64" Name="offsets" format="ascii">3</DataArray>
      </Polys>
    </Piece>
  </PolyData>
</VTKFile>
)");
  expect_input_error_naming_file(file);
  EXPECT_NE(read_error(file).find("point 7"), std::string::npos) << read_error(file);
}

TEST(VtkSurface, AFileWithoutFacesIsAnInputError) {
  TempDir dir;
  const fs::path file = dir / "lines.vtp";
  vtkNew<vtkPolyData> lines;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  lines->SetPoints(points);
  vtkNew<vtkCellArray> cells;
  const vtkIdType ids[2] = {0, 1};
  cells->InsertNextCell(2, ids);
  lines->SetLines(cells);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(lines);
  writer->SetFileName(file.string().c_str());
  ASSERT_EQ(writer->Write(), 1);

  expect_input_error_naming_file(file);
  EXPECT_NE(read_error(file).find("no faces"), std::string::npos) << read_error(file);
}

}  // namespace
}  // namespace hydrocoef
