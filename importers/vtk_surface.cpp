// The VTK surface importer's public functions (vtk_surface.hpp): the datasets
// a file holds, as read by read_file (vtk_formats.hpp), made into one
// SurfaceMesh: faces (a volume's boundary, a CGNS patch's own points), points
// and the arrays all selected locations hold.
#include "importers/vtk_surface.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCellTypes.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDataSetAttributes.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkGenericCell.h>
#include <vtkGeometryFilter.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "importers/vtk_formats.hpp"
#include "importers/vtk_messages.hpp"
#include "importers/vtk_reading_internal.hpp"
#include "importers/vtk_xml_polydata.hpp"
#include "src/core/error.hpp"
#include "src/core/huge_pages.hpp"
#include "src/mesh/duplicate_faces.hpp"

namespace hydrocoef {
namespace {

using vtk_detail::FileContents;
using vtk_detail::in_quotes;
using vtk_detail::Leaf;
using vtk_detail::read_file;
using vtk_detail::ScopedVtkMessageCapture;
using vtk_detail::summarize_vtk_messages;

std::string join_quoted(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + in_quotes(name);
  return text.empty() ? "none" : text;
}

std::vector<std::string> unique_locations(const std::vector<Leaf>& leaves) {
  std::vector<std::string> names;
  for (const auto& leaf : leaves)
    if (std::find(names.begin(), names.end(), leaf.location) == names.end()) names.push_back(leaf.location);
  return names;
}

/// Checks every point index of every cell before any filter walks the cells:
/// VTK's readers do not, and a filter would read out of bounds.
void check_point_indices(vtkDataSet* data, const std::string& file, const std::string& location) {
  const vtkIdType point_count = data->GetNumberOfPoints();
  vtkNew<vtkIdList> ids;
  for (vtkIdType cell = 0; cell < data->GetNumberOfCells(); ++cell) {
    data->GetCellPoints(cell, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
      const vtkIdType id = ids->GetId(k);
      if (id < 0 || id >= point_count)
        throw InputError(SourceLocation{file}, "block '" + location + "': cell " + std::to_string(cell) +
                                                   " refers to point " + std::to_string(id) + "; expected 0.." +
                                                   std::to_string(point_count - 1) + " (the block has " +
                                                   std::to_string(point_count) + " points)");
    }
  }
}

bool has_volume_cells(vtkDataSet* data) {
  vtkNew<vtkCellTypes> types;
  data->GetCellTypes(types);
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType i = 0; i < types->GetNumberOfTypes(); ++i) {
    cell->SetCellType(types->GetCellType(i));
    if (cell->GetCellDimension() == 3) return true;
  }
  return false;
}

/// The boundary faces of a dataset with volume cells, ordered outward as VTK
/// orders a cell's faces and carrying the cell data of their volume cell.
vtkSmartPointer<vtkPolyData> boundary_surface(vtkDataSet* data) {
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  auto* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (grid == nullptr) {
    vtkNew<vtkDataSetSurfaceFilter> filter;
    filter->SetInputData(data);
    filter->Update();
    surface->ShallowCopy(filter->GetOutput());
    return surface;
  }
  // Run through the pipeline, VTK 9.1's surface filters leak the summary of
  // the grid they make (LeakSanitizer fails the tests on it); their direct
  // execution methods take one that stays ours. Linear cells go to
  // vtkGeometryFilter, quadratic ones to vtkDataSetSurfaceFilter, which splits
  // their faces into linear triangles: the choice the filters make themselves.
  const std::unique_ptr<vtkGeometryFilterHelper> summary(vtkGeometryFilterHelper::CharacterizeUnstructuredGrid(grid));
  if (summary->IsLinear) {
    vtkNew<vtkGeometryFilter> filter;
    filter->UnstructuredGridExecute(grid, surface, summary.get(), nullptr);
  } else {
    vtkNew<vtkDataSetSurfaceFilter> filter;
    filter->UnstructuredGridExecute(grid, surface, summary.get());
  }
  return surface;
}

/// A CGNS boundary patch as its faces and the points they use (in the zone's
/// order) with their point data: VTK 9.1 gives a patch every point of its
/// zone, volume points included.
vtkSmartPointer<vtkDataSet> patch_surface(vtkDataSet* patch, const std::string& file, const std::string& location) {
  const vtkIdType point_count = patch->GetNumberOfPoints();
  std::vector<vtkIdType> new_index(static_cast<std::size_t>(point_count), -1);
  vtkNew<vtkIdList> ids;
  for (vtkIdType cell = 0; cell < patch->GetNumberOfCells(); ++cell) {
    // VTK makes cells of unknown type of a boundary condition it misreads
    // (one given by a list of vertices, for example).
    const int type = patch->GetCellType(cell);
    if (type != VTK_TRIANGLE && type != VTK_QUAD && type != VTK_POLYGON && type != VTK_LINE && type != VTK_VERTEX)
      throw InputError(SourceLocation{file},
                       "boundary patch '" + location + "': VTK read cell " + std::to_string(cell) + " as cell type " +
                           std::to_string(type) +
                           "; expected triangles or quadrilaterals (VTK 9.1 reads a patch "
                           "given as face elements: PointRange, PointList or ElementRange at FaceCenter)");
    patch->GetCellPoints(cell, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) new_index[static_cast<std::size_t>(ids->GetId(k))] = 0;
  }
  vtkIdType kept = 0;
  std::for_each(new_index.begin(), new_index.end(), [&kept](vtkIdType& index) {
    if (index == 0) index = kept++;
  });

  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  if (auto* point_set = vtkPointSet::SafeDownCast(patch); point_set != nullptr && point_set->GetPoints() != nullptr)
    points->SetDataType(point_set->GetPoints()->GetDataType());
  points->SetNumberOfPoints(kept);
  grid->GetPointData()->CopyAllocate(patch->GetPointData(), kept);
  double xyz[3];
  for (vtkIdType p = 0; p < point_count; ++p) {
    const vtkIdType index = new_index[static_cast<std::size_t>(p)];
    if (index < 0) continue;
    patch->GetPoint(p, xyz);
    points->SetPoint(index, xyz);
    grid->GetPointData()->CopyData(patch->GetPointData(), p, index);
  }
  grid->SetPoints(points);
  grid->Allocate(patch->GetNumberOfCells());
  for (vtkIdType cell = 0; cell < patch->GetNumberOfCells(); ++cell) {
    patch->GetCellPoints(cell, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      ids->SetId(k, new_index[static_cast<std::size_t>(ids->GetId(k))]);
    grid->InsertNextCell(patch->GetCellType(cell), ids);
  }
  grid->GetCellData()->PassData(patch->GetCellData());
  return grid;
}

/// The faces one dataset contributes, with the cell each face came from (a
/// triangle strip gives several faces of one cell).
struct Part {
  vtkSmartPointer<vtkDataSet> surface;
  std::uint32_t location = 0;
  std::vector<std::uint32_t> offsets{0};
  std::vector<std::uint32_t> indices;
  std::vector<vtkIdType> face_cell;  ///< the cell each face came from, unless cells_are_faces
  bool cells_are_faces = false;      ///< face f is cell f (polygon-only polydata)

  std::size_t face_count() const { return offsets.size() - 1; }
};

/// Closes the face whose point indices were just appended; they came from `cell`.
void end_face(Part& part, vtkIdType cell) {
  part.offsets.push_back(static_cast<std::uint32_t>(part.indices.size()));
  part.face_cell.push_back(cell);
}

void add_face(Part& part, vtkIdType cell, std::initializer_list<vtkIdType> ids) {
  for (const vtkIdType id : ids) part.indices.push_back(static_cast<std::uint32_t>(id));
  end_face(part, cell);
}

/// The common case, a polydata of polygons only (what foamToVTK, ParaView and
/// most exporters write): faces read straight from the cell array's offsets
/// and connectivity, point indices checked on the way, instead of one
/// virtual GetCellPoints call per cell.
bool polygons_only(vtkDataSet* data) {
  auto* poly = vtkPolyData::SafeDownCast(data);
  return poly != nullptr && poly->GetNumberOfVerts() == 0 && poly->GetNumberOfLines() == 0 &&
         poly->GetNumberOfStrips() == 0 && poly->GetPolys() != nullptr;
}

template <typename IdArray>
void copy_polygons(IdArray* offsets, IdArray* connectivity, vtkIdType point_count, Part& part, const std::string& file,
                   const std::string& location_name) {
  const auto* off = offsets->GetPointer(0);
  const auto* ids = connectivity->GetPointer(0);
  const vtkIdType cells = offsets->GetNumberOfValues() - 1;
  reserve_with_huge_pages(part.indices, static_cast<std::size_t>(connectivity->GetNumberOfValues()));
  part.indices.resize(static_cast<std::size_t>(connectivity->GetNumberOfValues()));
  part.offsets.resize(static_cast<std::size_t>(cells) + 1);
  part.cells_are_faces = true;
  std::uint32_t* out = part.indices.data();
  for (vtkIdType cell = 0; cell < cells; ++cell) {
    const auto begin = off[cell], end = off[cell + 1];
    if (end - begin < 3)
      throw InputError(SourceLocation{file}, "block '" + location_name + "': cell " + std::to_string(cell) +
                                                 " is a polygon with " + std::to_string(end - begin) +
                                                 " points; expected at least 3");
    for (auto k = begin; k < end; ++k) {
      const auto id = ids[k];
      if (id < 0 || id >= point_count)
        throw InputError(SourceLocation{file}, "block '" + location_name + "': cell " + std::to_string(cell) +
                                                   " refers to point " + std::to_string(id) + "; expected 0.." +
                                                   std::to_string(point_count - 1) + " (the block has " +
                                                   std::to_string(point_count) + " points)");
      *out++ = static_cast<std::uint32_t>(id);
    }
    part.offsets[static_cast<std::size_t>(cell) + 1] = static_cast<std::uint32_t>(end);
  }
}

Part extract_polygons(vtkSmartPointer<vtkDataSet> surface, std::uint32_t location, const std::string& file,
                      const std::string& location_name) {
  Part part;
  part.surface = std::move(surface);
  part.location = location;
  vtkCellArray* polys = vtkPolyData::SafeDownCast(part.surface)->GetPolys();
  const vtkIdType point_count = part.surface->GetNumberOfPoints();
  if (polys->IsStorage64Bit())
    copy_polygons(polys->GetOffsetsArray64(), polys->GetConnectivityArray64(), point_count, part, file, location_name);
  else
    copy_polygons(polys->GetOffsetsArray32(), polys->GetConnectivityArray32(), point_count, part, file, location_name);
  return part;
}

Part extract_faces(vtkSmartPointer<vtkDataSet> surface, std::uint32_t location, const std::string& file,
                   const std::string& location_name) {
  Part part;
  part.surface = std::move(surface);
  part.location = location;
  vtkDataSet* data = part.surface;
  vtkNew<vtkIdList> ids;
  for (vtkIdType cell = 0; cell < data->GetNumberOfCells(); ++cell) {
    const int type = data->GetCellType(cell);
    data->GetCellPoints(cell, ids);
    const vtkIdType n = ids->GetNumberOfIds();
    const auto id = [&ids](vtkIdType k) { return ids->GetId(k); };
    switch (type) {
      case VTK_TRIANGLE:
      case VTK_QUAD:
      case VTK_POLYGON:
        if (n < 3)
          throw InputError(SourceLocation{file}, "block '" + location_name + "': cell " + std::to_string(cell) +
                                                     " is a polygon with " + std::to_string(n) +
                                                     " points; expected at least 3");
        for (vtkIdType k = 0; k < n; ++k) part.indices.push_back(static_cast<std::uint32_t>(id(k)));
        end_face(part, cell);
        break;
      case VTK_PIXEL:
        // A pixel numbers its corners row by row, not around the face.
        add_face(part, cell, {id(0), id(1), id(3), id(2)});
        break;
      case VTK_TRIANGLE_STRIP:
        // Every other triangle of a strip is flipped so that all keep the
        // strip's orientation; repeated points (strip joints) make no face.
        for (vtkIdType k = 0; k + 2 < n; ++k) {
          if (id(k) == id(k + 1) || id(k + 1) == id(k + 2) || id(k) == id(k + 2)) continue;
          if (k % 2 == 0)
            add_face(part, cell, {id(k), id(k + 1), id(k + 2)});
          else
            add_face(part, cell, {id(k + 1), id(k), id(k + 2)});
        }
        break;
      case VTK_EMPTY_CELL:
      case VTK_VERTEX:
      case VTK_POLY_VERTEX:
      case VTK_LINE:
      case VTK_POLY_LINE: break;
      default: {
        const char* class_name = vtkCellTypes::GetClassNameFromTypeId(type);
        throw InputError(
            SourceLocation{file},
            "block '" + location_name + "': cell " + std::to_string(cell) + " is a " +
                (class_name != nullptr ? std::string(class_name) : "cell of type " + std::to_string(type)) +
                "; expected triangles, quads, pixels, polygons or triangle strips on a surface");
      }
    }
  }
  return part;
}

/// The arrays of a dataset's point or cell data that become FieldArrays.
std::vector<vtkDataArray*> usable_arrays(vtkDataSetAttributes* attributes) {
  std::vector<vtkDataArray*> arrays;
  for (int i = 0; i < attributes->GetNumberOfArrays(); ++i) {
    vtkDataArray* array = attributes->GetArray(i);  // null for string and other non-numeric arrays
    if (array == nullptr || array->GetName() == nullptr || *array->GetName() == '\0') continue;
    if (std::string(array->GetName()) == vtkDataSetAttributes::GhostArrayName()) continue;
    const int components = array->GetNumberOfComponents();
    if (components == 1 || components == 3) arrays.push_back(array);
  }
  return arrays;
}

vtkDataSetAttributes* attributes_of(vtkDataSet* data, FieldAssociation association) {
  return association == FieldAssociation::Point ? static_cast<vtkDataSetAttributes*>(data->GetPointData())
                                                : static_cast<vtkDataSetAttributes*>(data->GetCellData());
}

void check_tuple_count(vtkDataArray* array, vtkIdType expected, const std::string& file, const std::string& location,
                       const char* per) {
  if (array->GetNumberOfTuples() != expected)
    throw InputError(SourceLocation{file}, "block '" + location + "': array '" + array->GetName() + "' has " +
                                               std::to_string(array->GetNumberOfTuples()) + " tuples; expected " +
                                               std::to_string(expected) + " (one per " + per + ")");
}

/// Appends all values of a float or double array in one pass; false for
/// other value types (the caller then goes through GetComponent).
template <typename Array>
bool append_typed(vtkDataArray* array, std::vector<double>& out) {
  auto* typed = Array::SafeDownCast(array);
  if (typed == nullptr) return false;
  const auto* values = typed->GetPointer(0);
  const auto count = static_cast<std::size_t>(typed->GetNumberOfValues());
  reserve_with_huge_pages(out, out.size() + count);
  out.insert(out.end(), values, values + count);
  return true;
}

bool append_values(vtkDataArray* array, std::vector<double>& out) {
  return append_typed<vtkDoubleArray>(array, out) || append_typed<vtkFloatArray>(array, out);
}

/// The values of the cells that became faces, in face order.
template <typename Array>
bool append_cells_typed(vtkDataArray* array, const std::vector<vtkIdType>& cells, std::vector<double>& out) {
  auto* typed = Array::SafeDownCast(array);
  if (typed == nullptr) return false;
  const auto* values = typed->GetPointer(0);
  const auto components = static_cast<std::size_t>(typed->GetNumberOfComponents());
  out.reserve(out.size() + cells.size() * components);
  for (const vtkIdType cell : cells)
    for (std::size_t c = 0; c < components; ++c) out.push_back(values[static_cast<std::size_t>(cell) * components + c]);
  return true;
}

bool append_cell_values(vtkDataArray* array, const std::vector<vtkIdType>& cells, std::vector<double>& out) {
  return append_cells_typed<vtkDoubleArray>(array, cells, out) || append_cells_typed<vtkFloatArray>(array, cells, out);
}

/// Appends the arrays that every part holds under the same name with the same
/// number of components; the first part decides the order.
void append_fields(const std::vector<Part>& parts, const std::vector<std::string>& location_names,
                   FieldAssociation association, const std::string& file, SurfaceMesh& mesh) {
  for (vtkDataArray* first : usable_arrays(attributes_of(parts.front().surface, association))) {
    const std::string name = first->GetName();
    const int components = first->GetNumberOfComponents();
    std::vector<vtkDataArray*> per_part;
    for (const auto& part : parts) {
      vtkDataArray* array = attributes_of(part.surface, association)->GetArray(name.c_str());
      if (array == nullptr || array->GetNumberOfComponents() != components) break;
      per_part.push_back(array);
    }
    if (per_part.size() != parts.size()) continue;

    FieldArray field;
    field.name = name;
    field.association = association;
    field.components = components;
    for (std::size_t p = 0; p < parts.size(); ++p) {
      const Part& part = parts[p];
      vtkDataArray* array = per_part[p];
      const std::string& location = location_names[part.location];
      if (association == FieldAssociation::Point) {
        check_tuple_count(array, part.surface->GetNumberOfPoints(), file, location, "point");
        if (!append_values(array, field.values))
          for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
            for (int c = 0; c < components; ++c) field.values.push_back(array->GetComponent(t, c));
      } else {
        check_tuple_count(array, part.surface->GetNumberOfCells(), file, location, "cell");
        if (part.cells_are_faces) {
          if (!append_values(array, field.values))
            for (vtkIdType cell = 0; cell < array->GetNumberOfTuples(); ++cell)
              for (int c = 0; c < components; ++c) field.values.push_back(array->GetComponent(cell, c));
        } else if (!append_cell_values(array, part.face_cell, field.values)) {
          for (const vtkIdType cell : part.face_cell)
            for (int c = 0; c < components; ++c) field.values.push_back(array->GetComponent(cell, c));
        }
      }
    }
    mesh.fields.push_back(std::move(field));
  }
}

void check_fits_uint32(std::size_t count, const std::string& file, const char* what) {
  if (count > std::numeric_limits<std::uint32_t>::max())
    throw InputError(SourceLocation{file}, std::to_string(count) + " " + what + "; at most " +
                                               std::to_string(std::numeric_limits<std::uint32_t>::max()) +
                                               " are supported");
}

/// " (VTK: ...)" with the warnings VTK gave while reading, or "".
std::string vtk_warnings_note(const FileContents& contents) {
  const std::string summary = summarize_vtk_messages(contents.warnings);
  return summary.empty() ? std::string() : " (VTK: " + summary + ")";
}

}  // namespace

SurfaceMesh read_vtk_surface(const std::filesystem::path& file, const VtkSurfaceOptions& options) {
  const std::string file_name = file.string();
  if (options.direct_vtp && lower(file.extension().string()) == ".vtp" &&
      std::all_of(options.locations.begin(), options.locations.end(),
                  [&file](const std::string& location) { return location == file.stem().string(); }))
    if (std::optional<SurfaceMesh> mesh = read_vtp_surface(file)) return std::move(*mesh);
  ScopedVtkMessageCapture capture;
  const FileContents contents = read_file(file, capture);
  const std::vector<Leaf>& leaves = contents.leaves;
  const std::vector<std::string> available = unique_locations(leaves);

  for (const auto& wanted : options.locations)
    if (std::find(available.begin(), available.end(), wanted) == available.end())
      throw InputError(SourceLocation{file_name}, "no location " + in_quotes(wanted) + "; the file holds " +
                                                      join_quoted(available) + vtk_warnings_note(contents));
  const std::set<std::string> wanted(options.locations.begin(), options.locations.end());
  // Unless asked for, CGNS boundary patches are left out: their faces are
  // faces of their zone's boundary too.
  const auto selected = [&wanted](const Leaf& leaf) {
    return wanted.empty() ? !leaf.patch : wanted.count(leaf.location) > 0;
  };

  SurfaceMesh mesh;
  for (const auto& leaf : leaves)
    if (selected(leaf) &&
        std::find(mesh.location_names.begin(), mesh.location_names.end(), leaf.location) == mesh.location_names.end())
      mesh.location_names.push_back(leaf.location);

  std::vector<Part> parts;
  for (const auto& leaf : leaves) {
    if (leaf.data == nullptr || !selected(leaf)) continue;
    const auto location = static_cast<std::uint32_t>(
        std::find(mesh.location_names.begin(), mesh.location_names.end(), leaf.location) - mesh.location_names.begin());
    if (!leaf.patch && polygons_only(leaf.data)) {
      Part part = extract_polygons(leaf.data, location, file_name, leaf.location);
      if (part.face_count() > 0) parts.push_back(std::move(part));
      continue;
    }
    check_point_indices(leaf.data, file_name, leaf.location);
    vtkSmartPointer<vtkDataSet> surface = leaf.data;
    if (leaf.patch) {
      surface = patch_surface(leaf.data, file_name, leaf.location);
    } else if (vtkPolyData::SafeDownCast(leaf.data) == nullptr && has_volume_cells(leaf.data)) {
      surface = boundary_surface(leaf.data);
      if (!capture.errors().empty())
        throw InputError(SourceLocation{file_name}, "block '" + leaf.location +
                                                        "': VTK could not extract the boundary surface: " +
                                                        summarize_vtk_messages(capture.errors()));
    }
    Part part = extract_faces(surface, location, file_name, leaf.location);
    if (part.face_count() > 0) parts.push_back(std::move(part));
  }
  if (parts.empty())
    throw InputError(SourceLocation{file_name},
                     "no faces (triangles, quads, polygons or triangle strips) in " +
                         (options.locations.empty() ? std::string("the file") : join_quoted(options.locations)) +
                         vtk_warnings_note(contents));

  std::size_t point_total = 0;
  std::size_t index_total = 0;
  for (const auto& part : parts) {
    point_total += static_cast<std::size_t>(part.surface->GetNumberOfPoints());
    index_total += part.indices.size();
  }
  check_fits_uint32(point_total, file_name, "points");
  check_fits_uint32(index_total, file_name, "face point indices");

  std::size_t face_total = 0;
  for (const auto& part : parts) face_total += part.face_count();
  reserve_with_huge_pages(mesh.points_xyz, 3 * point_total);
  reserve_with_huge_pages(mesh.face_indices, index_total);
  reserve_with_huge_pages(mesh.face_offsets, face_total + 1);
  reserve_with_huge_pages(mesh.face_location, face_total);
  for (const auto& part : parts) {
    const auto first_point = static_cast<std::uint32_t>(mesh.point_count());
    const auto first_index = static_cast<std::uint32_t>(mesh.face_indices.size());
    vtkPointSet* point_set = vtkPointSet::SafeDownCast(part.surface);
    vtkDataArray* coordinates = point_set && point_set->GetPoints() ? point_set->GetPoints()->GetData() : nullptr;
    if (!coordinates || !append_values(coordinates, mesh.points_xyz)) {
      double xyz[3];
      for (vtkIdType p = 0; p < part.surface->GetNumberOfPoints(); ++p) {
        part.surface->GetPoint(p, xyz);
        mesh.points_xyz.insert(mesh.points_xyz.end(), xyz, xyz + 3);
      }
    }
    for (const auto index : part.indices) mesh.face_indices.push_back(first_point + index);
    for (std::size_t f = 1; f < part.offsets.size(); ++f) mesh.face_offsets.push_back(first_index + part.offsets[f]);
    mesh.face_location.insert(mesh.face_location.end(), part.face_count(), part.location);
  }
  // Face arrays first: where a solver exports both (foamToVTK does by default),
  // the cell values are its own and the point values interpolated, and
  // SurfaceMesh::find_field returns the first array of a name.
  append_fields(parts, mesh.location_names, FieldAssociation::Face, file_name, mesh);
  append_fields(parts, mesh.location_names, FieldAssociation::Point, file_name, mesh);
  if (const auto twice = find_duplicate_face(mesh)) {
    // The block and the cell of a face (a triangle strip's faces share their cell).
    const auto place = [&parts, &mesh](std::size_t face) {
      for (const auto& part : parts) {
        if (face < part.face_count())
          return in_quotes(mesh.location_names[part.location]) + " cell " +
                 std::to_string(part.cells_are_faces ? static_cast<vtkIdType>(face) : part.face_cell[face]);
        face -= part.face_count();
      }
      return std::string("?");
    };
    throw InputError(SourceLocation{file_name}, "block " + place(twice->second) + ": the points of block " +
                                                    place(twice->first) +
                                                    " again, in the same or another order; expected each face once (a "
                                                    "face listed twice counts twice in the forces)");
  }
  return mesh;
}

std::vector<std::string> list_vtk_locations(const std::filesystem::path& file) {
  ScopedVtkMessageCapture capture;
  return unique_locations(read_file(file, capture).leaves);
}

}  // namespace hydrocoef
