#include "importers/vtk_surface.hpp"

#include <vtkAlgorithm.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCellTypes.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkDataSetAttributes.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkGenericCell.h>
#include <vtkGenericDataObjectReader.h>
#include <vtkGeometryFilter.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkLogger.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkPartitionedDataSet.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <memory>
#include <regex>
#include <set>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

// VTK reports a problem to observers of the object that has it or, when there
// are none, both to vtkLogger (which prints it on stderr) and to the
// vtkOutputWindow. Objects created inside a reader (the XML parser, the readers
// of a .vtm's pieces and their pipeline executives) cannot be observed from
// outside, so instead the output window is swapped for one that keeps the
// messages and vtkLogger's stderr output is switched off while VTK works:
// nothing reaches the terminal, and the errors can become part of an
// InputError.
class CollectingOutputWindow : public vtkOutputWindow {
 public:
  vtkTypeMacro(CollectingOutputWindow, vtkOutputWindow)
  static CollectingOutputWindow* New() {
    auto* window = new CollectingOutputWindow;
    window->InitializeObjectBase();
    return window;
  }

  void DisplayText(const char* text) override { add(warnings, text); }
  void DisplayErrorText(const char* text) override { add(errors, text); }
  void DisplayWarningText(const char* text) override { add(warnings, text); }
  void DisplayGenericWarningText(const char* text) override { add(warnings, text); }
  void DisplayDebugText(const char*) override {}

  std::vector<std::string> errors;
  std::vector<std::string> warnings;

 private:
  CollectingOutputWindow() = default;
  static void add(std::vector<std::string>& into, const char* text) {
    if (text != nullptr) into.emplace_back(text);
  }
};

/// Switches vtkLogger's stderr output off and returns the level it had.
/// vtkLogger can set that level but not report it; what it reports is the
/// highest level of all its outputs (stderr, log files, callbacks), so the
/// level is read off by comparing that before and after. When a log file or
/// callback takes at least as much as stderr did, stderr's old level cannot be
/// told apart and loguru's default (INFO) is assumed, or less if that was all.
vtkLogger::Verbosity silence_vtk_logger_stderr() {
  const vtkLogger::Verbosity before = vtkLogger::GetCurrentVerbosityCutoff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  const vtkLogger::Verbosity others = vtkLogger::GetCurrentVerbosityCutoff();
  if (others < before) return before;
  return std::min(before, vtkLogger::VERBOSITY_INFO);
}

/// Collects VTK's messages for its lifetime and then puts VTK's previous
/// output window and stderr logging back, so that the rest of the program
/// keeps VTK's usual behaviour. Process-wide state: one reader at a time.
class ScopedVtkMessageCapture {
 public:
  ScopedVtkMessageCapture()
      : previous_window_(vtkOutputWindow::GetInstance()), previous_stderr_(silence_vtk_logger_stderr()) {
    vtkOutputWindow::SetInstance(window_);
  }
  ~ScopedVtkMessageCapture() {
    vtkOutputWindow::SetInstance(previous_window_);
    vtkLogger::SetStderrVerbosity(previous_stderr_);
  }
  ScopedVtkMessageCapture(const ScopedVtkMessageCapture&) = delete;
  ScopedVtkMessageCapture& operator=(const ScopedVtkMessageCapture&) = delete;

  const std::vector<std::string>& errors() const { return window_->errors; }
  const std::vector<std::string>& warnings() const { return window_->warnings; }

 private:
  vtkSmartPointer<vtkOutputWindow> previous_window_;
  vtkLogger::Verbosity previous_stderr_;
  vtkNew<CollectingOutputWindow> window_;
};

/// One VTK message on one printable line of bounded length, without the source
/// file and line of VTK itself and without object addresses, which mean
/// nothing to a user.
std::string clean_vtk_message(std::string text) {
  if (text.rfind("ERROR: In ", 0) == 0 || text.rfind("Warning: In ", 0) == 0 ||
      text.rfind("Generic Warning: In ", 0) == 0) {
    const auto end_of_line = text.find('\n');
    text = end_of_line == std::string::npos ? std::string() : text.substr(end_of_line + 1);
  }
  static const std::regex address(R"(\s*\(0x[0-9a-fA-F]+\))");
  static const std::regex whitespace(R"(\s+)");
  text = std::regex_replace(text, address, "");
  // A reader may quote what it found, which in a garbage file is binary.
  for (char& c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if ((byte < 0x20 && std::isspace(byte) == 0) || byte >= 0x7f) c = '?';
  }
  text = std::regex_replace(text, whitespace, " ");
  const auto first = text.find_first_not_of(' ');
  const auto last = text.find_last_not_of(' ');
  text = first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
  constexpr std::size_t kMaxLength = 200;
  if (text.size() > kMaxLength) {
    text.resize(kMaxLength);
    text += "...";
  }
  return text;
}

/// VTK's messages, as one line. The executive's "returned failure for
/// request" follows every reader failure and only repeats that one happened.
std::string summarize_vtk_messages(const std::vector<std::string>& messages) {
  constexpr std::size_t kMaxMessages = 3;
  std::vector<std::string> kept;
  for (const auto& message : messages) {
    std::string line = clean_vtk_message(message);
    if (line.empty() || line.find("returned failure for request") != std::string::npos) continue;
    if (std::find(kept.begin(), kept.end(), line) == kept.end()) kept.push_back(std::move(line));
  }
  std::string summary;
  for (std::size_t i = 0; i < kept.size() && i < kMaxMessages; ++i) summary += (i > 0 ? "; " : "") + kept[i];
  if (kept.size() > kMaxMessages) summary += "; (" + std::to_string(kept.size() - kMaxMessages) + " more)";
  return summary;
}

std::string lower_case(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

template <typename Reader>
vtkSmartPointer<vtkAlgorithm> make_reader(const std::filesystem::path& file) {
  auto reader = vtkSmartPointer<Reader>::New();
  reader->SetFileName(file.string().c_str());
  return reader;
}

/// Reads the file with the VTK reader its extension calls for. The caller
/// holds a ScopedVtkMessageCapture.
vtkSmartPointer<vtkDataObject> read_data_object(const std::filesystem::path& file,
                                                const ScopedVtkMessageCapture& capture) {
  const SourceLocation where{file.string()};
  std::error_code error;
  if (!std::filesystem::exists(file, error)) throw InputError(where, "file not found");
  if (!std::filesystem::is_regular_file(file, error)) throw InputError(where, "not a regular file");
  if (!std::ifstream(file, std::ios::binary)) throw InputError(where, "cannot be opened for reading");
  const auto size = std::filesystem::file_size(file, error);
  if (error) throw InputError(where, "cannot be read: " + error.message());
  if (size == 0) throw InputError(where, "file is empty; expected a VTK file");

  const std::string extension = lower_case(file.extension().string());
  vtkSmartPointer<vtkAlgorithm> reader;
  if (extension == ".vtk")
    reader = make_reader<vtkGenericDataObjectReader>(file);
  else if (extension == ".vtp")
    reader = make_reader<vtkXMLPolyDataReader>(file);
  else if (extension == ".vtu")
    reader = make_reader<vtkXMLUnstructuredGridReader>(file);
  else if (extension == ".vtm")
    reader = make_reader<vtkXMLMultiBlockDataReader>(file);
  else
    throw InputError(where, "unknown extension '" + file.extension().string() +
                                "'; expected .vtk, .vtp, .vtu or .vtm");

  reader->Update();
  vtkSmartPointer<vtkDataObject> output = reader->GetOutputDataObject(0);
  // Readers do not all set an error code, and some recover from a broken file
  // with an empty output and an error message, so every signal counts. The
  // legacy reader reports a truncated array only as a warning and keeps the
  // array half filled, so a warning while reading counts as an error too.
  if (reader->GetErrorCode() != 0 || output == nullptr || !capture.errors().empty() ||
      !capture.warnings().empty()) {
    std::vector<std::string> messages = capture.errors();
    messages.insert(messages.end(), capture.warnings().begin(), capture.warnings().end());
    std::string message = "VTK could not read the file as " + extension.substr(1);
    const std::string details = summarize_vtk_messages(messages);
    if (!details.empty()) message += ": " + details;
    throw InputError(where, message);
  }
  return output;
}

/// A dataset of the file together with the location (block) it belongs to;
/// data is null for an empty block.
struct Leaf {
  std::string location;
  vtkSmartPointer<vtkDataSet> data;
};

std::string block_name(vtkMultiBlockDataSet* blocks, unsigned int index) {
  if (blocks->HasMetaData(index)) {
    const char* name = blocks->GetMetaData(index)->Get(vtkCompositeDataSet::NAME());
    if (name != nullptr && *name != '\0') return name;
  }
  return "block" + std::to_string(index);
}

void collect_blocks(vtkMultiBlockDataSet* blocks, const std::string& prefix, std::vector<Leaf>& leaves) {
  for (unsigned int i = 0; i < blocks->GetNumberOfBlocks(); ++i) {
    const std::string name = prefix.empty() ? block_name(blocks, i) : prefix + "/" + block_name(blocks, i);
    vtkDataObject* block = blocks->GetBlock(i);
    if (auto* nested = vtkMultiBlockDataSet::SafeDownCast(block)) {
      collect_blocks(nested, name, leaves);
    } else if (auto* pieces = vtkPartitionedDataSet::SafeDownCast(block)) {
      // The pieces of a multipiece block are parts of one location.
      for (unsigned int p = 0; p < pieces->GetNumberOfPartitions(); ++p)
        leaves.push_back({name, vtkDataSet::SafeDownCast(pieces->GetPartitionAsDataObject(p))});
      if (pieces->GetNumberOfPartitions() == 0) leaves.push_back({name, nullptr});
    } else {
      leaves.push_back({name, vtkDataSet::SafeDownCast(block)});
    }
  }
}

std::vector<Leaf> collect_leaves(vtkDataObject* object, const std::filesystem::path& file) {
  std::vector<Leaf> leaves;
  if (auto* blocks = vtkMultiBlockDataSet::SafeDownCast(object)) {
    collect_blocks(blocks, "", leaves);
  } else if (auto* data = vtkDataSet::SafeDownCast(object)) {
    leaves.push_back({file.stem().string(), data});
  } else {
    throw InputError(SourceLocation{file.string()},
                     std::string("holds a ") + object->GetClassName() +
                         "; expected polydata, an unstructured grid or a multiblock dataset");
  }
  return leaves;
}

std::vector<std::string> unique_locations(const std::vector<Leaf>& leaves) {
  std::vector<std::string> names;
  for (const auto& leaf : leaves)
    if (std::find(names.begin(), names.end(), leaf.location) == names.end()) names.push_back(leaf.location);
  return names;
}

std::string join_quoted(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "'" : ", '") + name + "'";
  return text.empty() ? "none" : text;
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

/// The faces one dataset contributes, with the cell each face came from (a
/// triangle strip gives several faces of one cell).
struct Part {
  vtkSmartPointer<vtkDataSet> surface;
  std::uint32_t location = 0;
  std::vector<std::uint32_t> offsets{0};
  std::vector<std::uint32_t> indices;
  std::vector<vtkIdType> face_cell;

  std::size_t face_count() const { return face_cell.size(); }
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
      case VTK_POLY_LINE:
        break;
      default:
        throw InputError(SourceLocation{file},
                         "block '" + location_name + "': cell " + std::to_string(cell) + " is a " +
                             vtkCellTypes::GetClassNameFromTypeId(type) +
                             "; expected triangles, quads, pixels, polygons or triangle strips on a surface");
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

void check_tuple_count(vtkDataArray* array, vtkIdType expected, const std::string& file,
                       const std::string& location, const char* per) {
  if (array->GetNumberOfTuples() != expected)
    throw InputError(SourceLocation{file}, "block '" + location + "': array '" + array->GetName() + "' has " +
                                               std::to_string(array->GetNumberOfTuples()) + " tuples; expected " +
                                               std::to_string(expected) + " (one per " + per + ")");
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
        for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
          for (int c = 0; c < components; ++c) field.values.push_back(array->GetComponent(t, c));
      } else {
        check_tuple_count(array, part.surface->GetNumberOfCells(), file, location, "cell");
        for (const vtkIdType cell : part.face_cell)
          for (int c = 0; c < components; ++c) field.values.push_back(array->GetComponent(cell, c));
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

}  // namespace

SurfaceMesh read_vtk_surface(const std::filesystem::path& file, const VtkSurfaceOptions& options) {
  const std::string file_name = file.string();
  ScopedVtkMessageCapture capture;
  const vtkSmartPointer<vtkDataObject> object = read_data_object(file, capture);
  const std::vector<Leaf> leaves = collect_leaves(object, file);
  const std::vector<std::string> available = unique_locations(leaves);

  for (const auto& wanted : options.locations)
    if (std::find(available.begin(), available.end(), wanted) == available.end())
      throw InputError(SourceLocation{file_name},
                       "no location '" + wanted + "'; the file holds " + join_quoted(available));
  const std::set<std::string> wanted(options.locations.begin(), options.locations.end());
  const auto selected = [&wanted](const std::string& name) { return wanted.empty() || wanted.count(name) > 0; };

  SurfaceMesh mesh;
  for (const auto& name : available)
    if (selected(name)) mesh.location_names.push_back(name);

  std::vector<Part> parts;
  for (const auto& leaf : leaves) {
    if (leaf.data == nullptr || !selected(leaf.location)) continue;
    check_point_indices(leaf.data, file_name, leaf.location);
    vtkSmartPointer<vtkDataSet> surface = leaf.data;
    if (vtkPolyData::SafeDownCast(leaf.data) == nullptr && has_volume_cells(leaf.data)) {
      surface = boundary_surface(leaf.data);
      if (!capture.errors().empty())
        throw InputError(SourceLocation{file_name}, "block '" + leaf.location +
                                                        "': VTK could not extract the boundary surface: " +
                                                        summarize_vtk_messages(capture.errors()));
    }
    const auto location = static_cast<std::uint32_t>(
        std::find(mesh.location_names.begin(), mesh.location_names.end(), leaf.location) -
        mesh.location_names.begin());
    Part part = extract_faces(surface, location, file_name, leaf.location);
    if (part.face_count() > 0) parts.push_back(std::move(part));
  }
  if (parts.empty())
    throw InputError(SourceLocation{file_name},
                     "no faces (triangles, quads, polygons or triangle strips) in " +
                         (options.locations.empty() ? std::string("the file") : join_quoted(options.locations)));

  std::size_t point_total = 0;
  std::size_t index_total = 0;
  for (const auto& part : parts) {
    point_total += static_cast<std::size_t>(part.surface->GetNumberOfPoints());
    index_total += part.indices.size();
  }
  check_fits_uint32(point_total, file_name, "points");
  check_fits_uint32(index_total, file_name, "face point indices");

  mesh.points_xyz.reserve(3 * point_total);
  mesh.face_indices.reserve(index_total);
  for (const auto& part : parts) {
    const auto first_point = static_cast<std::uint32_t>(mesh.point_count());
    const auto first_index = static_cast<std::uint32_t>(mesh.face_indices.size());
    double xyz[3];
    for (vtkIdType p = 0; p < part.surface->GetNumberOfPoints(); ++p) {
      part.surface->GetPoint(p, xyz);
      mesh.points_xyz.insert(mesh.points_xyz.end(), xyz, xyz + 3);
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
  return mesh;
}

std::vector<std::string> list_vtk_locations(const std::filesystem::path& file) {
  ScopedVtkMessageCapture capture;
  const vtkSmartPointer<vtkDataObject> object = read_data_object(file, capture);
  return unique_locations(collect_leaves(object, file));
}

}  // namespace hydrocoef
