// Test and benchmark support: a SurfaceMesh handed to VTK as a vtkPolyData
// (double-precision points, every face a polygon cell, every point array as a
// double array), so VTK's own filters and writers can be run on the same
// surface as hydrocoef's code.
#pragma once

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <vector>

#include "src/mesh/surface_mesh.hpp"

namespace hydrocoef::test {

inline vtkSmartPointer<vtkPolyData> to_vtk_polydata(const SurfaceMesh& mesh) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();  // VTK's default float32 points would limit comparisons to ~1e-8
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.point_count()));
  for (std::size_t i = 0; i < mesh.point_count(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), &mesh.points_xyz[3 * i]);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  std::vector<vtkIdType> ids;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    ids.assign(mesh.face_indices.begin() + mesh.face_offsets[f], mesh.face_indices.begin() + mesh.face_offsets[f + 1]);
    cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(cells);
  for (const auto& field : mesh.fields) {
    if (field.association != FieldAssociation::Point) continue;
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(field.name.c_str());
    array->SetNumberOfComponents(field.components);
    array->SetNumberOfTuples(static_cast<vtkIdType>(field.size()));
    std::copy(field.values.begin(), field.values.end(), array->GetPointer(0));
    poly->GetPointData()->AddArray(array);
  }
  return poly;
}

}  // namespace hydrocoef::test
