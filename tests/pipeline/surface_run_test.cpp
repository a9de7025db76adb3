// Tests of src/pipeline/surface_run: one surface written in every format
// hydrocoef reads gives the same forces; a non-SI CFD-Post export gives the
// same forces as its SI twin; frames, sidecars and defaults.
#include "src/pipeline/surface_run.hpp"

#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkEnSightWriter.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>

#include <fstream>

#include "src/core/error.hpp"
#include "tests/support/cfdpost_writer.hpp"
#include "tests/support/meshes.hpp"
#include "tests/support/sqlite_dump.hpp"
#include "tests/support/vtk_polydata.hpp"

namespace hydrocoef {
namespace {

using test::P3;

/// A closed surface with CFX-style arrays: static pressure [Pa] and the
/// fluid's shear on the wall [Pa], both per point.
SurfaceMesh cfx_like_surface() {
  SurfaceMesh mesh = test::make_icosphere(0.15, 3, {0.02, -0.01, 0.03});
  test::add_point_scalar(mesh, "Pressure", [](const P3& x) { return 2000.0 + 1.5e4 * x[0] - 3.0e3 * x[1] * x[2]; });
  test::add_point_vector(mesh, "Wall Shear", [](const P3& x) { return P3{0.8 + 2.0 * x[1], -0.3 * x[0], 0.1 + x[2]}; });
  return mesh;
}

template <typename Dataset>
void fill_vtk(const SurfaceMesh& mesh, Dataset* data) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (std::size_t i = 0; i < mesh.point_count(); ++i) points->InsertNextPoint(&mesh.points_xyz[3 * i]);
  data->SetPoints(points);
  for (const auto& field : mesh.fields) {
    vtkNew<vtkDoubleArray> array;
    array->SetName(field.name.c_str());
    array->SetNumberOfComponents(field.components);
    for (std::size_t i = 0; i < field.size(); ++i)
      array->InsertNextTuple(&field.values[i * static_cast<std::size_t>(field.components)]);
    data->GetPointData()->AddArray(array);
  }
}

/// EnSight Gold through VTK's writer (binary, float32). The writer needs a
/// BlockId cell array for the part number, and VTK 9.1's case file is left
/// unflushed by the writer, so the case file is written here.
std::filesystem::path write_ensight(SurfaceMesh mesh, const std::filesystem::path& dir) {
  // EnSight variable descriptions are single words: cfx5export writes Wall_Shear.
  for (auto& field : mesh.fields) std::replace(field.name.begin(), field.name.end(), ' ', '_');
  vtkNew<vtkUnstructuredGrid> grid;
  fill_vtk(mesh, grid.Get());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const vtkIdType ids[3] = {mesh.face_indices[3 * f], mesh.face_indices[3 * f + 1], mesh.face_indices[3 * f + 2]};
    grid->InsertNextCell(VTK_TRIANGLE, 3, ids);
  }
  vtkNew<vtkIntArray> block;
  block->SetName("BlockId");
  for (std::size_t f = 0; f < mesh.face_count(); ++f) block->InsertNextValue(1);
  grid->GetCellData()->AddArray(block);
  vtkNew<vtkEnSightWriter> writer;
  writer->SetInputData(grid);
  writer->SetPath(dir.string().c_str());
  writer->SetBaseName("hull");
  writer->Write();
  const auto case_file = dir / "hull.case";
  std::ofstream(case_file) << "FORMAT\ntype: ensight gold\n\nGEOMETRY\nmodel: hull.0.00000.geo\n\nVARIABLE\n"
                              "scalar per node: Pressure hull.0.00000_n.Pressure\n"
                              "vector per node: Wall_Shear hull.0.00000_n.Wall_Shear\n";
  return case_file;
}

double length(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

void expect_same_loads(const SurfaceLoads& a, const SurfaceLoads& b, double relative, const std::string& what) {
  const double force_scale = length(a.force_pressure) + length(a.force_viscous);
  const double moment_scale = length(a.moment_pressure) + length(a.moment_viscous);
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_NEAR(a.force_pressure[c], b.force_pressure[c], relative * force_scale) << what << " Fp " << c;
    EXPECT_NEAR(a.force_viscous[c], b.force_viscous[c], relative * force_scale) << what << " Fv " << c;
    EXPECT_NEAR(a.moment_pressure[c], b.moment_pressure[c], relative * moment_scale) << what << " Mp " << c;
    EXPECT_NEAR(a.moment_viscous[c], b.moment_viscous[c], relative * moment_scale) << what << " Mv " << c;
  }
}

TEST(SurfaceRun, TheSameSurfaceInEveryFormatGivesTheSameForces) {
  test::TempDir dir;
  const SurfaceMesh mesh = cfx_like_surface();
  SurfaceRunOptions options;
  options.key.body = "hull";
  options.reference_point_b = {0.01, 0.0, -0.02};

  test::CfdPostWriterOptions si;
  si.precision = 17;
  std::ofstream(dir / "hull-si.csv", std::ios::binary) << test::write_cfdpost_export(mesh, si);
  test::CfdPostWriterOptions mm = si;
  mm.units = test::CfdPostUnits::MillimetreKilopascal;
  mm.crlf = true;
  mm.shuffle_columns = true;
  std::ofstream(dir / "hull-mm-kpa.csv", std::ios::binary) << test::write_cfdpost_export(mesh, mm);

  const auto poly = test::to_vtk_polydata(mesh);
  vtkNew<vtkXMLPolyDataWriter> xml;
  xml->SetInputData(poly);
  xml->SetFileName((dir / "hull.vtp").c_str());
  xml->Write();
  vtkNew<vtkPolyDataWriter> legacy;
  legacy->SetInputData(poly);
  legacy->SetFileTypeToBinary();
  legacy->SetFileName((dir / "hull.vtk").c_str());
  legacy->Write();
  std::filesystem::create_directories(dir / "ensight");
  const auto ensight = write_ensight(mesh, dir / "ensight");

  const SurfaceRun reference = import_surface_run(dir / "hull.vtp", options);
  EXPECT_EQ(reference.pressure_array, "Pressure");
  EXPECT_EQ(reference.shear_array, "Wall Shear");
  EXPECT_EQ(reference.shear_convention, ShearConvention::OnWall);
  EXPECT_EQ(reference.pressure_kind, PressureKind::Static);
  EXPECT_GT(length(reference.loads_b.force_viscous), 0.0);

  const SurfaceRun from_si = import_surface_run(dir / "hull-si.csv", options);
  EXPECT_EQ(from_si.format, "cfdpost");
  EXPECT_EQ(from_si.shear_array, "Wall Shear X,Wall Shear Y,Wall Shear Z");
  expect_same_loads(reference.loads_b, from_si.loads_b, 1e-12, "CFD-Post SI");
  const SurfaceRun from_mm = import_surface_run(dir / "hull-mm-kpa.csv", options);
  expect_same_loads(from_si.loads_b, from_mm.loads_b, 1e-12, "CFD-Post mm/kPa twin");
  expect_same_loads(reference.loads_b, import_surface_run(dir / "hull.vtk", options).loads_b, 1e-12, "legacy VTK");
  // EnSight Gold stores float32.
  expect_same_loads(reference.loads_b, import_surface_run(ensight, options).loads_b, 1e-5, "EnSight Gold");

  // Provenance hashes each file's own bytes.
  EXPECT_NE(from_si.batch.source.sha256, from_mm.batch.source.sha256);
  EXPECT_EQ(from_si.batch.source.importer, "cfdpost-surface");
}

TEST(SurfaceRun, FramesRotateForcesMomentsAndIntegrals) {
  test::TempDir dir;
  const SurfaceMesh mesh = cfx_like_surface();
  const auto poly = test::to_vtk_polydata(mesh);
  vtkNew<vtkXMLPolyDataWriter> xml;
  xml->SetInputData(poly);
  xml->SetFileName((dir / "hull.vtp").c_str());
  xml->Write();
  SurfaceRunOptions cfd;
  cfd.reference_point_b = {0.05, 0.02, -0.01};
  const SurfaceRun in_cfd = import_surface_run(dir / "hull.vtp", cfd);
  SurfaceRunOptions body = cfd;
  body.frame = parse_axes("-x,y,-z");
  body.frame.origin_cfd = {0.1, 0.0, 0.2};
  // The same physical point, now given in body axes.
  const Vec3 ref_cfd = cfd.reference_point_b;
  body.reference_point_b = body.frame.point_to_body(ref_cfd);
  const SurfaceRun in_body = import_surface_run(dir / "hull.vtp", body);
  const auto& a = in_cfd.loads_b;
  const auto& b = in_body.loads_b;
  const double F = length(a.force()), M = length(a.moment());
  EXPECT_NEAR(b.force()[0], -a.force()[0], 1e-12 * F);
  EXPECT_NEAR(b.force()[1], a.force()[1], 1e-12 * F);
  EXPECT_NEAR(b.force()[2], -a.force()[2], 1e-12 * F);
  EXPECT_NEAR(b.moment()[0], -a.moment()[0], 1e-12 * M);
  EXPECT_NEAR(b.moment()[1], a.moment()[1], 1e-12 * M);
  EXPECT_NEAR(b.moment()[2], -a.moment()[2], 1e-12 * M);
  EXPECT_NEAR(b.geometry.signed_volume, a.geometry.signed_volume, 1e-15);
  // ∫ x × n dA about the body origin, from the stored integrals alone, gives
  // the moment of a uniform pressure about that origin.
  const auto& run = in_body.batch.runs.front();
  ASSERT_TRUE(run.surface.has_value());
  EXPECT_EQ(run.surface->axes, "-x,y,-z");
  EXPECT_EQ(run.tau_b[0]->total, b.force()[0]);
  EXPECT_EQ(run.tau_b[5]->pressure, b.moment_pressure[2]);
}

TEST(SurfaceRun, FormatDetection) {
  test::TempDir dir;
  std::ofstream(dir / "a.csv") << "\n[Name]\nhull\n\n[Data]\nX [ m ], Y [ m ], Z [ m ]\n";
  std::ofstream(dir / "b.csv") << "u [m s^-1],X [N]\n0.1,1\n";
  std::ofstream(dir / "c.csv") << "\"ACCUMULATED TIMESTEP\",\"USER POINT,Fx\"\n1,2\n";
  EXPECT_EQ(detect_format(dir / "a.csv"), "cfdpost");
  EXPECT_EQ(detect_format(dir / "b.csv"), "table");
  EXPECT_EQ(detect_format(dir / "c.csv"), "monitor");
  EXPECT_EQ(detect_format(dir / "x.vtp"), "vtk");
  EXPECT_EQ(detect_format(dir / "x.cgns"), "vtk");
  EXPECT_EQ(detect_format(dir / "b.csv", "table"), "table");
  EXPECT_THROW(detect_format(dir / "x.stl"), InputError);
  EXPECT_THROW(detect_format(dir / "b.csv", "fluent"), InputError);
}

}  // namespace
}  // namespace hydrocoef
