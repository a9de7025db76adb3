// Integration speed and the cost of a whole .vtp import, against VTK.
//
//   BM_IntegrateTriangles      integrate_surface_loads on a closed surface of
//                              1.3 million triangles with point pressure and
//                              point wall shear and every geometry check
//                              (goal: >= 100 M triangles/s; the rate is per
//                              second of the calling thread's CPU time)
//   BM_VtpReadOnly             vtkXMLPolyDataReader alone on that surface as
//                              a .vtp: the floor the goal below is set against
//   BM_VtpImportAndIntegrate   hydrocoef's path: read_vtk_surface (the direct
//                              .vtp reader, importers/vtk_xml_polydata) and
//                              integrate_surface_loads (goal: <= 1.3x read)
//   BM_VtpImportRun            import_surface_run: the same plus the file's
//                              SHA-256 and the unit and axes handling, all
//                              that `hydrocoef import` does before storing
//   BM_VtpImportThroughVtkAndIntegrate
//                              read_vtk_surface through VTK's reader (what
//                              every other VTK format takes) and the integration
//   BM_VtpVtkFilters           the same forces with VTK's own filters:
//                              vtkPointDataToCellData, vtkPolyDataNormals,
//                              vtkArrayCalculator, vtkIntegrateAttributes
//                              (goal: hydrocoef >= 3x faster)
//
// Each .vtp case runs on three layouts of the same surface (see big_vtp).
#include <benchmark/benchmark.h>
#include <vtkArrayCalculator.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIntegrateAttributes.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPointDataToCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <filesystem>

#include "importers/vtk_surface.hpp"
#include "src/loads/surface_loads.hpp"
#include "src/pipeline/surface_run.hpp"
#include "tests/support/meshes.hpp"
#include "tests/support/vtk_polydata.hpp"

namespace {

using namespace hydrocoef;

const SurfaceMesh& big_surface() {
  static const SurfaceMesh mesh = [] {
    SurfaceMesh m = test::make_icosphere(0.15, 8);  // 1,310,720 triangles
    test::add_point_scalar(m, "p", [](const test::P3& x) { return 1000.0 + 4000.0 * x[0] - 900.0 * x[2] * x[1]; });
    test::add_point_vector(m, "tau", [](const test::P3& x) { return test::P3{0.3 + x[1], -0.2 * x[0], 0.1 * x[2]}; });
    return m;
  }();
  return mesh;
}

/// The surface as a .vtp in one of three layouts:
///   0: as VTK's own writer writes by default with raw appended data (float64, zlib);
///   1: as foamToVTK writes a patch (the real exports in shared/data): float32
///      points and arrays, inline base64, no compression;
///   2: float64, raw appended data, no compression (ParaView's "Save Data"
///      with compression off): the cheapest file to read.
const std::filesystem::path& big_vtp(int layout) {
  static std::filesystem::path paths[3];
  std::filesystem::path& path = paths[layout];
  if (!path.empty()) return path;
  path = std::filesystem::temp_directory_path() / ("hydrocoef-bench-sphere-" + std::to_string(layout) + ".vtp");
  auto poly = test::to_vtk_polydata(big_surface());
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(path.c_str());
  if (layout == 0 || layout == 2) {
    writer->SetInputData(poly);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    if (layout == 2) writer->SetCompressorTypeToNone();
  } else {
    vtkNew<vtkPolyData> single;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    points->DeepCopy(poly->GetPoints());
    single->SetPoints(points);
    single->SetPolys(poly->GetPolys());
    for (int a = 0; a < poly->GetPointData()->GetNumberOfArrays(); ++a) {
      vtkDataArray* source = poly->GetPointData()->GetArray(a);
      vtkNew<vtkFloatArray> array;
      array->DeepCopy(source);
      array->SetName(source->GetName());
      single->GetPointData()->AddArray(array);
    }
    writer->SetInputData(single);
    writer->SetDataModeToBinary();
    writer->SetCompressorTypeToNone();
  }
  writer->Write();
  return path;
}

SurfaceLoadOptions options() {
  SurfaceLoadOptions o;
  o.pressure_field = "p";
  o.shear_fields = {"tau"};
  return o;
}

void BM_IntegrateTriangles(benchmark::State& state) {
  const SurfaceMesh& mesh = big_surface();
  const auto o = options();
  for (auto _ : state) benchmark::DoNotOptimize(integrate_surface_loads(mesh, o));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(mesh.face_count()));
  state.counters["triangles"] = static_cast<double>(mesh.face_count());
}
BENCHMARK(BM_IntegrateTriangles)->Unit(benchmark::kMillisecond);

void BM_VtpReadOnly(benchmark::State& state) {
  const auto& file = big_vtp(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    benchmark::DoNotOptimize(reader->GetOutput()->GetNumberOfCells());
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(std::filesystem::file_size(file)));
}
BENCHMARK(BM_VtpReadOnly)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_VtpImportAndIntegrate(benchmark::State& state) {
  const auto& file = big_vtp(static_cast<int>(state.range(0)));
  const auto o = options();
  for (auto _ : state) {
    const SurfaceMesh mesh = read_vtk_surface(file);
    benchmark::DoNotOptimize(integrate_surface_loads(mesh, o));
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(std::filesystem::file_size(file)));
}
BENCHMARK(BM_VtpImportAndIntegrate)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// What `hydrocoef import` does with the file before it writes the run: the
// read and integration above plus the file's SHA-256 (taken on another
// thread meanwhile), the arrays' unit handling and the axes.
void BM_VtpImportRun(benchmark::State& state) {
  const auto& file = big_vtp(static_cast<int>(state.range(0)));
  SurfaceRunOptions run_options;
  run_options.pressure = "p";
  run_options.shear = {"tau"};
  run_options.pressure_kind = PressureKind::Static;
  for (auto _ : state) benchmark::DoNotOptimize(import_surface_run(file, run_options));
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(std::filesystem::file_size(file)));
}
BENCHMARK(BM_VtpImportRun)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same through VTK's reader and the copy into a SurfaceMesh (the path
// every other VTK format takes).
void BM_VtpImportThroughVtkAndIntegrate(benchmark::State& state) {
  const auto& file = big_vtp(static_cast<int>(state.range(0)));
  const auto o = options();
  VtkSurfaceOptions through_vtk;
  through_vtk.direct_vtp = false;
  for (auto _ : state) {
    const SurfaceMesh mesh = read_vtk_surface(file, through_vtk);
    benchmark::DoNotOptimize(integrate_surface_loads(mesh, o));
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(std::filesystem::file_size(file)));
}
BENCHMARK(BM_VtpImportThroughVtkAndIntegrate)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_VtpVtkFilters(benchmark::State& state) {
  const auto& file = big_vtp(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(file.c_str());
    vtkNew<vtkPointDataToCellData> to_cells;
    to_cells->SetInputConnection(reader->GetOutputPort());
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputConnection(to_cells->GetOutputPort());
    normals->ComputeCellNormalsOn();
    normals->ComputePointNormalsOff();
    normals->SplittingOff();
    normals->ConsistencyOff();
    vtkNew<vtkArrayCalculator> pressure_force;
    pressure_force->SetInputConnection(normals->GetOutputPort());
    pressure_force->SetAttributeTypeToCellData();
    pressure_force->AddScalarArrayName("p");
    pressure_force->AddVectorArrayName("Normals");
    pressure_force->SetFunction("-p*Normals");
    pressure_force->SetResultArrayName("dF_p");
    pressure_force->SetResultArrayType(VTK_DOUBLE);
    vtkNew<vtkIntegrateAttributes> integrate;
    integrate->SetInputConnection(pressure_force->GetOutputPort());
    integrate->Update();
    benchmark::DoNotOptimize(integrate->GetOutput()->GetCellData()->GetArray("dF_p")->GetComponent(0, 0));
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(std::filesystem::file_size(file)));
}
BENCHMARK(BM_VtpVtkFilters)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
