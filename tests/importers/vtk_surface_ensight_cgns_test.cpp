// Tests of the EnSight Gold (.case) and CGNS (.cgns) paths of the VTK surface
// importer, on files written here: EnSight by VTK's own vtkEnSightWriter (C
// binary), by hand (ASCII) and by the small binary writer below (C and Fortran
// binary in both byte orders); CGNS by libcgns, as cfx5export -cgns writes it
// (unstructured zones, element sections, FlowSolution at Vertex and
// CellCenter, boundary conditions).
#include "importers/vtk_surface.hpp"

#include <cgnslib.h>
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkEnSightWriter.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "src/core/error.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

using test::TempDir;

using test::read_bytes;
using test::write_bytes;

/// The message of the InputError that reading `file` throws, "" if none.
std::string read_error(const fs::path& file, const VtkSurfaceOptions& options = {}) {
  try {
    read_vtk_surface(file, options);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

/// Reading `file` throws an InputError whose message holds `needle` (the
/// name of the file at fault), and VTK prints nothing.
void expect_input_error(const fs::path& file, const std::string& needle, const VtkSurfaceOptions& options = {}) {
  ::testing::internal::CaptureStderr();
  const std::string message = read_error(file, options);
  const std::string stderr_text = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(message.find(needle), std::string::npos)
      << "reading " << file << ": " << (message.empty() ? "no InputError" : message) << "; expected '" << needle
      << "' in it";
  EXPECT_EQ(stderr_text, "") << "VTK wrote to the terminal reading " << file;
}

double as_float(double value) { return static_cast<double>(static_cast<float>(value)); }

std::vector<double> as_float(std::vector<double> values) {
  for (auto& value : values) value = as_float(value);
  return values;
}

std::vector<std::string> field_names(const SurfaceMesh& mesh) {
  std::vector<std::string> names;
  for (const auto& field : mesh.fields) names.push_back(field.name);
  return names;
}

const FieldArray& field(const SurfaceMesh& mesh, const std::string& name) {
  const FieldArray* found = mesh.find_field(name);
  if (found == nullptr) throw std::runtime_error("no field '" + name + "'");
  return *found;
}

// --- the test surface: a closed box of triangles and quads -------------------

using Vec3 = std::array<double, 3>;

/// A closed box, faces outward, half of them quads and the other faces split
/// into triangles, interleaved; values that float32 cannot hold exactly.
struct Box {
  std::vector<Vec3> points;
  std::vector<std::vector<std::uint32_t>> faces;
  std::vector<double> p;    // per point
  std::vector<double> U;    // per point, 3 components
  std::vector<double> tau;  // per face
  std::vector<double> wss;  // per face, 3 components
};

Box make_box() {
  Box box;
  const double x[2] = {0.1, 1.1};
  const double y[2] = {-0.2, 0.7};
  const double z[2] = {-0.3, 0.4};
  for (int k = 0; k < 2; ++k)
    for (const auto& [i, j] : {std::pair{0, 0}, std::pair{1, 0}, std::pair{1, 1}, std::pair{0, 1}})
      box.points.push_back({x[i], y[j], z[k]});
  box.faces = {{0, 3, 2}, {4, 5, 6, 7}, {0, 2, 1}, {0, 1, 5, 4}, {2, 3, 7}, {1, 2, 6, 5}, {2, 7, 6}, {3, 0, 4, 7}};
  for (std::size_t i = 0; i < box.points.size(); ++i) {
    const double d = static_cast<double>(i);
    box.p.push_back(101325.0 + 0.1 * d + 1.0 / 3.0);
    box.U.insert(box.U.end(), {0.1 * d, -0.2 * d + 1.0 / 7.0, 3.3});
  }
  for (std::size_t f = 0; f < box.faces.size(); ++f) {
    const double d = static_cast<double>(f);
    box.tau.push_back(1.1 + d / 3.0);
    box.wss.insert(box.wss.end(), {0.01 * d, -0.02 * d, 1.0 / (d + 3.0)});
  }
  return box;
}

/// Where EnSight puts the box's faces: grouped by element type (tria3, then
/// quad4), each group in the order of the box.
std::vector<std::size_t> ensight_face_order(const Box& box) {
  std::vector<std::size_t> order;
  for (const std::size_t corners : {3u, 4u})
    for (std::size_t f = 0; f < box.faces.size(); ++f)
      if (box.faces[f].size() == corners) order.push_back(f);
  return order;
}

/// The box as EnSight stores it: float32 values, faces in EnSight's order,
/// one location; `cell_vector`: with wss.
SurfaceMesh expected_ensight_box(const Box& box, const std::string& location, bool cell_vector = true) {
  SurfaceMesh mesh;
  for (const auto& p : box.points)
    for (const double c : p) mesh.points_xyz.push_back(as_float(c));
  const auto order = ensight_face_order(box);
  FieldArray tau{"tau", FieldAssociation::Face, 1, {}, ""};
  FieldArray wss{"wss", FieldAssociation::Face, 3, {}, ""};
  for (const std::size_t f : order) {
    mesh.face_indices.insert(mesh.face_indices.end(), box.faces[f].begin(), box.faces[f].end());
    mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.face_indices.size()));
    mesh.face_location.push_back(0);
    tau.values.push_back(as_float(box.tau[f]));
    for (int c = 0; c < 3; ++c) wss.values.push_back(as_float(box.wss[3 * f + c]));
  }
  mesh.location_names = {location};
  mesh.fields = {tau,
                 wss,
                 {"p", FieldAssociation::Point, 1, as_float(box.p), ""},
                 {"U", FieldAssociation::Point, 3, as_float(box.U), ""}};
  if (!cell_vector) mesh.fields.erase(mesh.fields.begin() + 1);
  return mesh;
}

void expect_same_mesh(const SurfaceMesh& actual, const SurfaceMesh& expected) {
  EXPECT_EQ(actual.points_xyz, expected.points_xyz);
  EXPECT_EQ(actual.face_offsets, expected.face_offsets);
  EXPECT_EQ(actual.face_indices, expected.face_indices);
  EXPECT_EQ(actual.location_names, expected.location_names);
  EXPECT_EQ(actual.face_location, expected.face_location);
  ASSERT_EQ(field_names(actual), field_names(expected));
  for (std::size_t i = 0; i < expected.fields.size(); ++i) {
    EXPECT_EQ(actual.fields[i].association, expected.fields[i].association) << expected.fields[i].name;
    EXPECT_EQ(actual.fields[i].components, expected.fields[i].components) << expected.fields[i].name;
    EXPECT_EQ(actual.fields[i].values, expected.fields[i].values) << expected.fields[i].name;
    EXPECT_EQ(actual.fields[i].unit, "") << expected.fields[i].name;
  }
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

/// The box as an unstructured grid; `cell_vector`: with wss.
vtkSmartPointer<vtkUnstructuredGrid> box_grid(const Box& box, bool cell_vector = true) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : box.points) points->InsertNextPoint(p.data());
  grid->SetPoints(points);
  for (const auto& face : box.faces) {
    std::vector<vtkIdType> ids(face.begin(), face.end());
    grid->InsertNextCell(face.size() == 3 ? VTK_TRIANGLE : VTK_QUAD, static_cast<vtkIdType>(ids.size()), ids.data());
  }
  add_array(grid->GetPointData(), "p", 1, box.p);
  add_array(grid->GetPointData(), "U", 3, box.U);
  add_array(grid->GetCellData(), "tau", 1, box.tau);
  if (cell_vector) add_array(grid->GetCellData(), "wss", 3, box.wss);
  return grid;
}

/// Writes the box with vtkEnSightWriter into <dir> and returns the case file.
/// The writer takes the part number from a "BlockId" cell array (without one
/// it prints "No BlockID was found" for every cell on stdout). VTK 9.1's
/// writer has two faults worked around here: it writes a vector per element
/// as x, y, z of each element in turn instead of all x, then all y, then all
/// z (the format, and VTK's reader, want the latter), so the box goes without
/// wss; and its WriteCaseFile never closes the file it writes (the text stays
/// in a buffer until the process ends), so the case file is written here,
/// naming the variables by their own names as cfx5export does (the writer
/// would append "_n" and "_c").
fs::path write_box_with_vtk(const Box& box, const fs::path& dir) {
  auto grid = box_grid(box, false);
  add_array<vtkIntArray>(grid->GetCellData(), "BlockId", 1, std::vector<double>(box.faces.size(), 1.0));
  vtkNew<vtkEnSightWriter> writer;
  writer->SetInputData(grid);
  writer->SetPath(dir.string().c_str());
  writer->SetBaseName("box");
  writer->Write();
  const fs::path case_file = dir / "box.case";
  write_bytes(case_file,
              "FORMAT\ntype: ensight gold\n\nGEOMETRY\nmodel: box.0.00000.geo\n\nVARIABLE\n"
              "scalar per node: p box.0.00000_n.p\nvector per node: U box.0.00000_n.U\n"
              "scalar per element: tau box.0.00000_c.tau\n");
  return case_file;
}

// --- EnSight written by VTK ---------------------------------------------------

TEST(VtkSurfaceEnSight, VtkEnSightWriterOutputReadsBackAsWritten) {
  TempDir dir;
  const Box box = make_box();
  const fs::path case_file = write_box_with_vtk(box, dir.path());
  // What vtkEnSightWriter writes: EnSight Gold, C binary, one part ("VTK
  // Part", number 1) with float32 coordinates and values.
  EXPECT_EQ(read_bytes(dir / "box.0.00000.geo").substr(0, 8), "C Binary");

  EXPECT_EQ(list_vtk_locations(case_file), std::vector<std::string>{"VTK Part"});
  const SurfaceMesh mesh = read_vtk_surface(case_file);
  expect_same_mesh(mesh, expected_ensight_box(box, "VTK Part", false));
  EXPECT_EQ(mesh.find_field("BlockId"), nullptr);   // written, but not named by the case file
  EXPECT_NE(mesh.points_xyz[0], box.points[0][0]);  // float32 is not double
}

/// Face f of `mesh` rotated to start at its smallest point index (orientation
/// kept), for comparing faces whatever their first corner and order.
std::vector<std::uint32_t> canonical_face(const SurfaceMesh& mesh, std::size_t f) {
  std::vector<std::uint32_t> face(mesh.face_indices.begin() + mesh.face_offsets[f],
                                  mesh.face_indices.begin() + mesh.face_offsets[f + 1]);
  std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
  return face;
}

/// Every face with the values of the face arrays on it, sorted by face.
std::vector<std::pair<std::vector<std::uint32_t>, std::vector<double>>> faces_with_values(const SurfaceMesh& mesh) {
  std::vector<std::pair<std::vector<std::uint32_t>, std::vector<double>>> faces;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    std::vector<double> values;
    for (const auto& array : mesh.fields)
      if (array.association == FieldAssociation::Face)
        for (int c = 0; c < array.components; ++c)
          values.push_back(array.values[f * static_cast<std::size_t>(array.components) + static_cast<std::size_t>(c)]);
    faces.emplace_back(canonical_face(mesh, f), values);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

// The same surface with the same arrays, once as .vtp and once as EnSight
// Gold: the same mesh, to float32 (EnSight's precision), up to the order of
// the faces, which EnSight groups by element type.
TEST(VtkSurfaceEnSight, VtpAndEnSightGoldGiveTheSameMesh) {
  TempDir dir;
  const Box box = make_box();
  const fs::path case_file = write_box_with_vtk(box, dir.path());
  const fs::path vtu = dir / "box.vtu";
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(box_grid(box, false));
  writer->SetFileName(vtu.string().c_str());
  ASSERT_EQ(writer->Write(), 1);

  const SurfaceMesh from_vtu = read_vtk_surface(vtu);
  const SurfaceMesh from_ensight = read_vtk_surface(case_file);
  EXPECT_EQ(as_float(from_vtu.points_xyz), from_ensight.points_xyz);
  ASSERT_EQ(field_names(from_vtu), field_names(from_ensight));
  for (std::size_t i = 0; i < from_vtu.fields.size(); ++i) {
    EXPECT_EQ(from_vtu.fields[i].association, from_ensight.fields[i].association);
    EXPECT_EQ(from_vtu.fields[i].components, from_ensight.fields[i].components);
    if (from_vtu.fields[i].association == FieldAssociation::Point) {
      EXPECT_EQ(as_float(from_vtu.fields[i].values), from_ensight.fields[i].values) << from_vtu.fields[i].name;
    }
  }
  auto vtu_faces = faces_with_values(from_vtu);
  for (auto& face : vtu_faces) face.second = as_float(face.second);
  EXPECT_EQ(vtu_faces, faces_with_values(from_ensight));
  EXPECT_NE(from_vtu.face_indices, from_ensight.face_indices);  // the order does differ
}

// --- EnSight Gold binary written here ------------------------------------------

/// EnSight Gold binary items: 80-character strings, 32-bit integers and
/// floats, one after the other ("C Binary") or each in a Fortran record
/// between two 32-bit byte counts ("Fortran Binary"), in either byte order.
class EnSightBinary {
 public:
  EnSightBinary(bool fortran, bool big_endian) : fortran_(fortran), big_endian_(big_endian) {}

  EnSightBinary& text(const std::string& line) {
    std::string padded = line;
    padded.resize(80, '\0');
    return record(padded);
  }
  EnSightBinary& ints(const std::vector<std::int32_t>& values) {
    std::string payload;
    for (const auto value : values) payload += word(static_cast<std::uint32_t>(value));
    return record(payload);
  }
  EnSightBinary& floats(const std::vector<double>& values) {
    std::string payload;
    for (const double value : values) {
      const auto single = static_cast<float>(value);
      std::uint32_t bits = 0;
      std::memcpy(&bits, &single, 4);
      payload += word(bits);
    }
    return record(payload);
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string word(std::uint32_t value) const {
    std::string out(4, '\0');
    for (int i = 0; i < 4; ++i)
      out[static_cast<std::size_t>(big_endian_ ? 3 - i : i)] = static_cast<char>((value >> (8 * i)) & 0xff);
    return out;
  }
  EnSightBinary& record(const std::string& payload) {
    if (fortran_) bytes_ += word(static_cast<std::uint32_t>(payload.size()));
    bytes_ += payload;
    if (fortran_) bytes_ += word(static_cast<std::uint32_t>(payload.size()));
    return *this;
  }

  bool fortran_;
  bool big_endian_;
  std::string bytes_;
};

std::vector<double> component(const std::vector<Vec3>& points, int c) {
  std::vector<double> values;
  for (const auto& p : points) values.push_back(p[static_cast<std::size_t>(c)]);
  return values;
}

/// Every `stride`-th value of `values` from `first`, over the faces in `faces`.
std::vector<double> pick(const std::vector<double>& values, const std::vector<std::size_t>& faces, int stride,
                         int first) {
  std::vector<double> out;
  for (const std::size_t f : faces)
    out.push_back(values[f * static_cast<std::size_t>(stride) + static_cast<std::size_t>(first)]);
  return out;
}

/// Writes the box as <dir>/box.case with a binary geometry (node and element
/// ids given, extents) and four variables.
fs::path write_box_binary(const Box& box, const fs::path& dir, bool fortran, bool big_endian) {
  const std::string format = fortran ? "Fortran Binary" : "C Binary";
  std::vector<std::size_t> triangles;
  std::vector<std::size_t> quads;
  for (std::size_t f = 0; f < box.faces.size(); ++f) (box.faces[f].size() == 3 ? triangles : quads).push_back(f);
  const auto connectivity = [&box](const std::vector<std::size_t>& faces) {
    std::vector<std::int32_t> ids;
    for (const std::size_t f : faces)
      for (const auto index : box.faces[f]) ids.push_back(static_cast<std::int32_t>(index + 1));
    return ids;
  };
  const auto element_ids = [](const std::vector<std::size_t>& faces) {
    std::vector<std::int32_t> ids;
    for (const std::size_t f : faces) ids.push_back(static_cast<std::int32_t>(1000 + f));
    return ids;
  };
  EnSightBinary geo(fortran, big_endian);
  geo.text(format).text("box for the tests").text("written by hand").text("node id given").text("element id given");
  geo.text("extents").floats({0.1, 1.1, -0.2, 0.7, -0.3, 0.4});
  geo.text("part").ints({1}).text("box").text("coordinates").ints({8});
  geo.ints({101, 102, 103, 104, 105, 106, 107, 108});
  for (int c = 0; c < 3; ++c) geo.floats(component(box.points, c));
  geo.text("tria3")
      .ints({static_cast<std::int32_t>(triangles.size())})
      .ints(element_ids(triangles))
      .ints(connectivity(triangles));
  geo.text("quad4").ints({static_cast<std::int32_t>(quads.size())}).ints(element_ids(quads)).ints(connectivity(quads));
  write_bytes(dir / "box.geo", geo.bytes());

  EnSightBinary p(fortran, big_endian);
  p.text("p").text("part").ints({1}).text("coordinates").floats(box.p);
  write_bytes(dir / "box.p", p.bytes());
  EnSightBinary u(fortran, big_endian);
  u.text("U").text("part").ints({1}).text("coordinates");
  for (int c = 0; c < 3; ++c) {
    std::vector<double> values;
    for (std::size_t i = 0; i < box.points.size(); ++i) values.push_back(box.U[3 * i + static_cast<std::size_t>(c)]);
    u.floats(values);
  }
  write_bytes(dir / "box.U", u.bytes());
  EnSightBinary tau(fortran, big_endian);
  tau.text("tau").text("part").ints({1});
  tau.text("tria3").floats(pick(box.tau, triangles, 1, 0)).text("quad4").floats(pick(box.tau, quads, 1, 0));
  write_bytes(dir / "box.tau", tau.bytes());
  EnSightBinary wss(fortran, big_endian);
  wss.text("wss").text("part").ints({1});
  for (const auto* faces : {&triangles, &quads}) {
    wss.text(faces == &triangles ? "tria3" : "quad4");
    for (int c = 0; c < 3; ++c) wss.floats(pick(box.wss, *faces, 3, c));
  }
  write_bytes(dir / "box.wss", wss.bytes());

  write_bytes(dir / "box.case",
              "FORMAT\ntype: ensight gold\n\nGEOMETRY\nmodel: box.geo\n\nVARIABLE\n"
              "scalar per node: p box.p\nvector per node: U box.U\n"
              "scalar per element: tau box.tau\nvector per element: wss box.wss\n");
  return dir / "box.case";
}

TEST(VtkSurfaceEnSight, ReadsCAndFortranBinaryInBothByteOrders) {
  const Box box = make_box();
  for (const bool fortran : {false, true}) {
    for (const bool big_endian : {false, true}) {
      SCOPED_TRACE(std::string(fortran ? "Fortran" : "C") + (big_endian ? " big-endian" : " little-endian"));
      TempDir dir;
      const fs::path case_file = write_box_binary(box, dir.path(), fortran, big_endian);
      expect_same_mesh(read_vtk_surface(case_file), expected_ensight_box(box, "box"));
    }
  }
}

// VTK 9.1's EnSight readers read a truncated file past its end: they crash
// (a segmentation fault) or silently make a shorter part. Every cut of every
// file must be an InputError naming the file instead.
TEST(VtkSurfaceEnSight, EveryTruncationOfABinaryFileIsAnInputErrorNamingIt) {
  const Box box = make_box();
  for (const bool fortran : {false, true}) {
    SCOPED_TRACE(fortran ? "Fortran" : "C");
    TempDir dir;
    const fs::path case_file = write_box_binary(box, dir.path(), fortran, false);
    ::testing::internal::CaptureStderr();
    for (const std::string name : {"box.geo", "box.p", "box.U", "box.tau", "box.wss"}) {
      const std::string whole = read_bytes(dir / name);
      // Every cut of the geometry; of the variables, every even one (items
      // are 4 bytes long; odd cuts take the same paths).
      const std::size_t step = name == "box.geo" ? 1 : 2;
      for (std::size_t size = 0; size < whole.size(); size += step) {
        write_bytes(dir / name, whole.substr(0, size));
        const std::string message = read_error(case_file);
        EXPECT_NE(message.find(name), std::string::npos) << name << " cut to " << size << " bytes: " << message;
      }
      write_bytes(dir / name, whole);
    }
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
    EXPECT_NO_THROW(read_vtk_surface(case_file));
  }
}

TEST(VtkSurfaceEnSight, TruncatedVtkWriterGeometryIsAnInputError) {
  TempDir dir;
  const fs::path case_file = write_box_with_vtk(make_box(), dir.path());
  const fs::path geo = dir / "box.0.00000.geo";
  const std::string whole = read_bytes(geo);
  for (const std::size_t size : {std::size_t{0}, std::size_t{80}, std::size_t{300}, std::size_t{400}, whole.size() / 2,
                                 std::size_t{800}, whole.size() - 1}) {
    write_bytes(geo, whole.substr(0, size));
    expect_input_error(case_file, geo.filename().string());
  }
}

// --- EnSight Gold ASCII written by hand ----------------------------------------

std::string reals(const std::vector<double>& values) {
  std::string text;
  char line[32];
  for (const double value : values) {
    std::snprintf(line, sizeof line, "%12.5e\n", value);
    text += line;
  }
  return text;
}

std::string ints(const std::vector<int>& values) {
  std::string text;
  char item[16];
  for (const int value : values) {
    std::snprintf(item, sizeof item, "%10d", value);
    text += item;
  }
  return text + "\n";
}

// Two parts: "hull", two quads at z = -0.25, and "fin", a triangle and a
// pentagon (nsided) at z = 1.5; node ids given. Values all hold exactly in
// float32 and in 6 digits.
const std::string kBodyGeo =
    "hydrocoef test body\n"
    "written by hand\n"
    "node id given\n"
    "element id off\n"
    "part\n" +
    ints({1}) + "hull\ncoordinates\n" + ints({6}) + ints({101}) + ints({102}) + ints({103}) + ints({104}) +
    ints({105}) + ints({106}) + reals({0, 1, 2, 0, 1, 2}) + reals({0, 0, 0, 1, 1, 1}) +
    reals({-0.25, -0.25, -0.25, -0.25, -0.25, -0.25}) + "quad4\n" + ints({2}) + ints({1, 2, 5, 4}) +
    ints({2, 3, 6, 5}) + "part\n" + ints({2}) + "fin\ncoordinates\n" + ints({6}) + ints({201}) + ints({202}) +
    ints({203}) + ints({204}) + ints({205}) + ints({206}) + reals({0, 1, 0, 2, 2, 1}) + reals({0, 0, 1, 0, 1, 1}) +
    reals({1.5, 1.5, 1.5, 1.5, 1.5, 1.5}) + "tria3\n" + ints({1}) + ints({1, 2, 3}) + "nsided\n" + ints({1}) +
    ints({5}) + ints({2, 4, 5, 6, 3});

const std::vector<double> kHullPressure = {1.5, 2.5, 3.5, 4.5, 5.5, 6.5};
const std::vector<double> kFinPressure = {10.25, 11.25, 12.25, 13.25, 14.25, 15.25};

std::string pressure_file(double offset) {
  std::vector<double> hull = kHullPressure;
  std::vector<double> fin = kFinPressure;
  for (auto& value : hull) value += offset;
  for (auto& value : fin) value += offset;
  return "pressure\npart\n" + ints({1}) + "coordinates\n" + reals(hull) + "part\n" + ints({2}) + "coordinates\n" +
         reals(fin);
}

const std::string kBodyVelocity = "velocity\npart\n" + ints({1}) + "coordinates\n" + reals({1, 1, 1, 1, 1, 1}) +
                                  reals({0, 0, 0, 0, 0, 0}) + reals({-0.5, -0.5, -0.5, -0.5, -0.5, -0.5}) + "part\n" +
                                  ints({2}) + "coordinates\n" + reals({2, 2, 2, 2, 2, 2}) +
                                  reals({0.125, 0.125, 0.125, 0.125, 0.125, 0.125}) + reals({0, 0, 0, 0, 0, 0});
const std::string kBodyCp = "cp\npart\n" + ints({1}) + "quad4\n" + reals({-0.75, 0.25}) + "part\n" + ints({2}) +
                            "tria3\n" + reals({0.5}) + "nsided\n" + reals({0.625});

std::string wss_file(double offset) {
  return "wss\npart\n" + ints({1}) + "quad4\n" + reals({0.5 + offset, 1.5 + offset}) + reals({2, 3}) + reals({4, 5}) +
         "part\n" + ints({2}) + "tria3\n" + reals({6 + offset}) + reals({7}) + reals({8}) + "nsided\n" +
         reals({9 + offset}) + reals({10}) + reals({11});
}

fs::path write_body_ascii(const fs::path& dir) {
  write_bytes(dir / "body.geo", kBodyGeo);
  write_bytes(dir / "body.pressure", pressure_file(0));
  write_bytes(dir / "body.velocity", kBodyVelocity);
  write_bytes(dir / "body.cp", kBodyCp);
  write_bytes(dir / "body.wss", wss_file(0));
  write_bytes(dir / "body.case",
              "# EnSight Gold case written by hand\n"
              "FORMAT\ntype:  ensight gold\n\n"
              "GEOMETRY\nmodel: body.geo\n\n"
              "VARIABLE\n"
              "scalar per node: pressure body.pressure\n"
              "vector per node: velocity body.velocity\n"
              "scalar per element: cp body.cp\n"
              "vector per element: wss body.wss\n"
              "tensor symm per node: stress body.stress\n");  // not read (and not there)
  return dir / "body.case";
}

TEST(VtkSurfaceEnSight, ReadsAndSelectsThePartsOfAnAsciiCase) {
  TempDir dir;
  const fs::path case_file = write_body_ascii(dir.path());
  EXPECT_EQ(list_vtk_locations(case_file), (std::vector<std::string>{"hull", "fin"}));

  const SurfaceMesh all = read_vtk_surface(case_file);
  EXPECT_EQ(all.location_names, (std::vector<std::string>{"hull", "fin"}));
  EXPECT_EQ(all.points_xyz,
            (std::vector<double>{0, 0, -0.25, 1, 0, -0.25, 2, 0, -0.25, 0, 1, -0.25, 1, 1, -0.25, 2, 1, -0.25,
                                 0, 0, 1.5,   1, 0, 1.5,   0, 1, 1.5,   2, 0, 1.5,   2, 1, 1.5,   1, 1, 1.5}));
  EXPECT_EQ(all.face_offsets, (std::vector<std::uint32_t>{0, 4, 8, 11, 16}));
  EXPECT_EQ(all.face_indices, (std::vector<std::uint32_t>{0, 1, 4, 3, 1, 2, 5, 4, 6, 7, 8, 7, 9, 10, 11, 8}));
  EXPECT_EQ(all.face_location, (std::vector<std::uint32_t>{0, 0, 1, 1}));
  EXPECT_EQ(field_names(all), (std::vector<std::string>{"cp", "wss", "pressure", "velocity"}));
  EXPECT_EQ(field(all, "cp").association, FieldAssociation::Face);
  EXPECT_EQ(field(all, "cp").values, (std::vector<double>{-0.75, 0.25, 0.5, 0.625}));
  EXPECT_EQ(field(all, "wss").components, 3);
  EXPECT_EQ(field(all, "wss").values, (std::vector<double>{0.5, 2, 4, 1.5, 3, 5, 6, 7, 8, 9, 10, 11}));
  std::vector<double> pressure = kHullPressure;
  pressure.insert(pressure.end(), kFinPressure.begin(), kFinPressure.end());
  EXPECT_EQ(field(all, "pressure").association, FieldAssociation::Point);
  EXPECT_EQ(field(all, "pressure").values, pressure);
  EXPECT_EQ(field(all, "velocity").values.size(), 36u);
  EXPECT_EQ(field(all, "velocity").values[2], -0.5);
  EXPECT_EQ(field(all, "velocity").values[19], 0.125);

  const SurfaceMesh fin = read_vtk_surface(case_file, {.locations = {"fin"}});
  EXPECT_EQ(fin.location_names, std::vector<std::string>{"fin"});
  EXPECT_EQ(fin.point_count(), 6u);
  EXPECT_EQ(fin.face_indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 4, 5, 2}));
  EXPECT_EQ(field(fin, "pressure").values, kFinPressure);

  // Locations come in file order, whatever the order asked for.
  const SurfaceMesh both = read_vtk_surface(case_file, {.locations = {"fin", "hull"}});
  EXPECT_EQ(both.location_names, (std::vector<std::string>{"hull", "fin"}));
  EXPECT_EQ(both.face_indices, all.face_indices);

  expect_input_error(case_file, "'rudder'", {.locations = {"fin", "rudder"}});
  const std::string message = read_error(case_file, {.locations = {"rudder"}});
  EXPECT_NE(message.find("body.case"), std::string::npos) << message;
  EXPECT_NE(message.find("'hull', 'fin'"), std::string::npos) << message;
}

// Two time sets of different lengths and ends: every variable is read at the
// last step of its own set, whatever the other set does.
TEST(VtkSurfaceEnSight, ReadsTheLastTimeStepOfEveryTimeSet) {
  TempDir dir;
  write_body_ascii(dir.path());
  for (int step = 0; step < 3; ++step)
    write_bytes(dir / ("body" + std::to_string(5 * (step + 1)) + ".pressure"), pressure_file(100.0 * step));
  for (int step = 1; step <= 2; ++step)
    write_bytes(dir / ("body0" + std::to_string(step) + ".wss"), wss_file(1000.0 * step));
  write_bytes(dir / "transient.case",
              "FORMAT\ntype: ensight gold\nGEOMETRY\nmodel: body.geo\nVARIABLE\n"
              "scalar per node: 1 pressure body*.pressure\n"
              "vector per element: 2 wss body**.wss\n"
              "TIME\n"
              "time set: 1 pressure steps\nnumber of steps: 3\nfilename numbers: 5 10\n15\n"
              "time values: 0.0 0.5\n 1.0\n"
              "time set: 2\nnumber of steps: 2\nfilename start number: 1\nfilename increment: 1\n"
              "time values: 0.25 2.0\n");
  const SurfaceMesh mesh = read_vtk_surface(dir / "transient.case");
  std::vector<double> pressure = kHullPressure;
  pressure.insert(pressure.end(), kFinPressure.begin(), kFinPressure.end());
  for (auto& value : pressure) value += 200.0;
  EXPECT_EQ(field(mesh, "pressure").values, pressure);
  EXPECT_EQ(field(mesh, "wss").values, (std::vector<double>{2000.5, 2, 4, 2001.5, 3, 5, 2006, 7, 8, 2009, 10, 11}));

  fs::remove(dir / "body02.wss");
  expect_input_error(dir / "transient.case", "body02.wss");
}

// Cut anywhere, a file must give an InputError naming it, except right before
// a variable file's second part: EnSight cannot tell that from a variable
// given on the first part only. VTK then gives the variable to the first part
// only, and, not on every part, it is left out.
TEST(VtkSurfaceEnSight, EveryTruncationOfAnAsciiFileIsAnInputErrorNamingIt) {
  TempDir dir;
  const fs::path case_file = write_body_ascii(dir.path());
  const SurfaceMesh whole_mesh = read_vtk_surface(case_file);
  const std::map<std::string, std::string> variables{
      {"body.pressure", "pressure"}, {"body.velocity", "velocity"}, {"body.cp", "cp"}, {"body.wss", "wss"}};
  ::testing::internal::CaptureStderr();
  for (const std::string name : {"body.geo", "body.pressure", "body.velocity", "body.cp", "body.wss"}) {
    const std::string whole = read_bytes(dir / name);
    const std::size_t second_part =
        name == "body.geo" ? std::string::npos : whole.find("part\n", whole.find("part\n") + 1);
    for (std::size_t size = 0; size < whole.size(); ++size) {
      write_bytes(dir / name, whole.substr(0, size));
      if (size == second_part) {
        const SurfaceMesh mesh = read_vtk_surface(case_file);
        EXPECT_EQ(mesh.find_field(variables.at(name)), nullptr) << name;
        EXPECT_EQ(read_vtk_surface(case_file, {.locations = {"hull"}}).find_field(variables.at(name))->values,
                  field(read_vtk_surface(dir / "body.case", {.locations = {"hull"}}), variables.at(name)).values);
        continue;
      }
      const std::string message = read_error(case_file);
      EXPECT_NE(message.find(name), std::string::npos) << name << " cut to " << size << " bytes: " << message;
    }
    write_bytes(dir / name, whole);
  }
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(read_vtk_surface(case_file).fields.size(), whole_mesh.fields.size());
}

TEST(VtkSurfaceEnSight, MissingAndInconsistentFilesAreInputErrorsNamingTheFile) {
  TempDir dir;
  const fs::path case_file = write_body_ascii(dir.path());
  ASSERT_NO_THROW(read_vtk_surface(case_file));

  fs::rename(dir / "body.wss", dir / "moved.wss");
  expect_input_error(case_file, "body.wss");
  EXPECT_NE(read_error(case_file).find("'wss'"), std::string::npos) << read_error(case_file);
  fs::rename(dir / "moved.wss", dir / "body.wss");

  fs::rename(dir / "body.geo", dir / "moved.geo");
  expect_input_error(case_file, "body.geo");
  fs::rename(dir / "moved.geo", dir / "body.geo");

  // A variable for a part the geometry does not have (VTK would use a null part).
  write_bytes(dir / "body.cp", kBodyCp + "part\n" + ints({3}) + "tria3\n" + reals({1}));
  expect_input_error(case_file, "body.cp");
  EXPECT_NE(read_error(case_file).find("part 3"), std::string::npos) << read_error(case_file);
  // Values for only some of a part's elements (VTK would leave the others undefined).
  write_bytes(dir / "body.cp", "cp\npart\n" + ints({1}) + "quad4\n" + reals({-0.75, 0.25}) + "part\n" + ints({2}) +
                                   "tria3\n" + reals({0.5}));
  expect_input_error(case_file, "body.cp");
  // Undefined values.
  write_bytes(dir / "body.cp", "cp\npart\n" + ints({1}) + "quad4 undef\n" + reals({-1e34, -0.75, 0.25}));
  expect_input_error(case_file, "body.cp");
  write_bytes(dir / "body.cp", kBodyCp);

  // A connectivity entry beyond the part's nodes.
  std::string geo = kBodyGeo;
  geo.replace(geo.rfind(ints({2, 4, 5, 6, 3})), 51, ints({2, 4, 5, 7, 3}));
  write_bytes(dir / "body.geo", geo);
  expect_input_error(case_file, "body.geo");
  EXPECT_NE(read_error(case_file).find("found 7"), std::string::npos) << read_error(case_file);
  write_bytes(dir / "body.geo", kBodyGeo);
  ASSERT_NO_THROW(read_vtk_surface(case_file));

  write_bytes(dir / "six.case", "FORMAT\ntype: ensight\nGEOMETRY\nmodel: body.geo\n");
  expect_input_error(dir / "six.case", "six.case");
  EXPECT_NE(read_error(dir / "six.case").find("EnSight Gold"), std::string::npos) << read_error(dir / "six.case");
  write_bytes(dir / "no_model.case", "FORMAT\ntype: ensight gold\nVARIABLE\nscalar per node: p body.pressure\n");
  expect_input_error(dir / "no_model.case", "no_model.case");
  write_bytes(dir / "garbage.case", std::string(300, 'x'));
  expect_input_error(dir / "garbage.case", "garbage.case");

  write_bytes(dir / "block.geo",
              "structured\nbody\nnode id off\nelement id off\npart\n" + ints({1}) + "box\nblock\n" + ints({2, 2, 2}));
  write_bytes(dir / "block.case", "FORMAT\ntype: ensight gold\nGEOMETRY\nmodel: block.geo\n");
  expect_input_error(dir / "block.case", "block.geo");
}

// VTK 9.1's EnSight reader puts the case file's folder in front of every file
// name, an absolute one too, and then cannot open it: VTK's own error, which
// must come back as the InputError and not on the terminal.
TEST(VtkSurfaceEnSight, VtksOwnErrorsBecomeTheInputError) {
  TempDir dir;
  write_body_ascii(dir.path());
  fs::create_directories(dir / "elsewhere");
  write_bytes(dir / "elsewhere" / "absolute.case",
              "FORMAT\ntype: ensight gold\nGEOMETRY\nmodel: " + (dir / "body.geo").string() + "\n");
  expect_input_error(dir / "elsewhere" / "absolute.case", "absolute.case");
  EXPECT_NE(read_error(dir / "elsewhere" / "absolute.case").find("Unable to open file"), std::string::npos)
      << read_error(dir / "elsewhere" / "absolute.case");
}

// --- CGNS ------------------------------------------------------------------------

void cg(int status, const char* call) {
  if (status != CG_OK) throw std::runtime_error(std::string(call) + ": " + cg_get_error());
}

/// A CGNS file being written with libcgns.
class CgnsWriter {
 public:
  explicit CgnsWriter(const fs::path& file) { cg(cg_open(file.string().c_str(), CG_MODE_WRITE, &file_), "cg_open"); }
  ~CgnsWriter() { cg_close(file_); }
  CgnsWriter(const CgnsWriter&) = delete;
  CgnsWriter& operator=(const CgnsWriter&) = delete;

  int base(const char* name, int cell_dimension) {
    int index = 0;
    cg(cg_base_write(file_, name, cell_dimension, 3, &index), "cg_base_write");
    return index;
  }
  /// An unstructured zone with its coordinates.
  int zone(int base, const char* name, const std::vector<Vec3>& points, cgsize_t cells) {
    cgsize_t size[3] = {static_cast<cgsize_t>(points.size()), cells, 0};
    int index = 0;
    cg(cg_zone_write(file_, base, name, size, CGNS_ENUMV(Unstructured), &index), "cg_zone_write");
    const char* names[3] = {"CoordinateX", "CoordinateY", "CoordinateZ"};
    for (int c = 0; c < 3; ++c) {
      const std::vector<double> values = component(points, c);
      int coordinate = 0;
      cg(cg_coord_write(file_, base, index, CGNS_ENUMV(RealDouble), names[c], values.data(), &coordinate),
         "cg_coord_write");
    }
    return index;
  }
  /// Elements first..first+n-1 of one type; node indices 1-based.
  void section(int base, int zone, const char* name, CGNS_ENUMT(ElementType_t) type, cgsize_t first,
               const std::vector<cgsize_t>& nodes, cgsize_t per_element) {
    const auto count = static_cast<cgsize_t>(nodes.size()) / per_element;
    int index = 0;
    cg(cg_section_write(file_, base, zone, name, type, first, first + count - 1, 0, nodes.data(), &index),
       "cg_section_write");
  }
  int solution(int base, int zone, const char* name, CGNS_ENUMT(GridLocation_t) location) {
    int index = 0;
    cg(cg_sol_write(file_, base, zone, name, location, &index), "cg_sol_write");
    return index;
  }
  void field(int base, int zone, int solution, const char* name, const std::vector<double>& values) {
    int index = 0;
    cg(cg_field_write(file_, base, zone, solution, CGNS_ENUMV(RealDouble), name, values.data(), &index),
       "cg_field_write");
  }
  int boco(int base, int zone, const char* name, CGNS_ENUMT(BCType_t) type, CGNS_ENUMT(PointSetType_t) set,
           const std::vector<cgsize_t>& points, bool face_center) {
    int index = 0;
    cg(cg_boco_write(file_, base, zone, name, type, set, static_cast<cgsize_t>(points.size()), points.data(), &index),
       "cg_boco_write");
    if (face_center) cg(cg_boco_gridlocation_write(file_, base, zone, index, CGNS_ENUMV(FaceCenter)), "gridlocation");
    return index;
  }
  /// Puts boundary condition `boco` of the zone in family `family` (and
  /// writes the family).
  void family(int base, int zone, int boco, const char* family) {
    cg(cg_goto(file_, base, "Zone_t", zone, "ZoneBC_t", 1, "BC_t", boco, "end"), "cg_goto");
    cg(cg_famname_write(family), "cg_famname_write");
    int index = 0;
    cg(cg_family_write(file_, base, family, &index), "cg_family_write");
  }
  int file() const { return file_; }

 private:
  int file_ = 0;
};

const std::vector<Vec3> kHullPoints = {{0, 0, 0.1}, {1, 0, 0.1}, {2, 0, 0.1},  {0, 1, 0.1},
                                       {1, 1, 0.1}, {2, 1, 0.1}, {3, 0.5, 0.1}};
const std::vector<Vec3> kFinPoints = {{0, 0, 2.3}, {1, 0, 2.3}, {0, 1, 2.3}};

std::vector<double> flatten(const std::vector<Vec3>& points) {
  std::vector<double> values;
  for (const auto& p : points) values.insert(values.end(), p.begin(), p.end());
  return values;
}

/// Two surface zones in a 3-D base (cell dimension 2) as a CFX export of body
/// surfaces: "hull", two quads and a triangle, and "fin", one triangle, each
/// with Pressure and VelocityX/Y/Z at the vertices and WallShear at the cells.
void write_surface_zones(const fs::path& file) {
  CgnsWriter out(file);
  const int base = out.base("Base", 2);
  const int hull = out.zone(base, "hull", kHullPoints, 3);
  out.section(base, hull, "Quads", CGNS_ENUMV(QUAD_4), 1, {1, 2, 5, 4, 2, 3, 6, 5}, 4);
  out.section(base, hull, "Tris", CGNS_ENUMV(TRI_3), 3, {3, 7, 6}, 3);
  int solution = out.solution(base, hull, "NodeData", CGNS_ENUMV(Vertex));
  out.field(base, hull, solution, "Pressure", {1.1, 2.1, 3.1, 4.1, 5.1, 6.1, 7.1});
  out.field(base, hull, solution, "VelocityX", {1, 1, 1, 1, 1, 1, 1});
  out.field(base, hull, solution, "VelocityY", {0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6});
  out.field(base, hull, solution, "VelocityZ", {-1, -1, -1, -1, -1, -1, -1});
  solution = out.solution(base, hull, "CellData", CGNS_ENUMV(CellCenter));
  out.field(base, hull, solution, "WallShear", {10.5, 11.5, 12.5});

  const int fin = out.zone(base, "fin", kFinPoints, 1);
  out.section(base, fin, "Tris", CGNS_ENUMV(TRI_3), 1, {1, 2, 3}, 3);
  solution = out.solution(base, fin, "NodeData", CGNS_ENUMV(Vertex));
  out.field(base, fin, solution, "Pressure", {8.1, 9.1, 10.1});
  out.field(base, fin, solution, "VelocityX", {2, 2, 2});
  out.field(base, fin, solution, "VelocityY", {0, 0, 0});
  out.field(base, fin, solution, "VelocityZ", {0.7, 0.7, 0.7});
  solution = out.solution(base, fin, "CellData", CGNS_ENUMV(CellCenter));
  out.field(base, fin, solution, "WallShear", {13.5});
}

TEST(VtkSurfaceCgns, ReadsAndSelectsSurfaceZones) {
  TempDir dir;
  const fs::path file = dir / "body.cgns";
  write_surface_zones(file);
  EXPECT_EQ(list_vtk_locations(file), (std::vector<std::string>{"hull", "fin"}));

  const SurfaceMesh all = read_vtk_surface(file);
  EXPECT_EQ(all.location_names, (std::vector<std::string>{"hull", "fin"}));
  std::vector<double> points = flatten(kHullPoints);
  const std::vector<double> fin_points = flatten(kFinPoints);
  points.insert(points.end(), fin_points.begin(), fin_points.end());
  EXPECT_EQ(all.points_xyz, points);  // doubles, exactly
  EXPECT_EQ(all.face_offsets, (std::vector<std::uint32_t>{0, 4, 8, 11, 14}));
  EXPECT_EQ(all.face_indices, (std::vector<std::uint32_t>{0, 1, 4, 3, 1, 2, 5, 4, 2, 6, 5, 7, 8, 9}));
  EXPECT_EQ(all.face_location, (std::vector<std::uint32_t>{0, 0, 0, 1}));
  EXPECT_EQ(field_names(all), (std::vector<std::string>{"WallShear", "Pressure", "Velocity"}));
  EXPECT_EQ(field(all, "WallShear").association, FieldAssociation::Face);
  EXPECT_EQ(field(all, "WallShear").values, (std::vector<double>{10.5, 11.5, 12.5, 13.5}));
  EXPECT_EQ(field(all, "Pressure").association, FieldAssociation::Point);
  EXPECT_EQ(field(all, "Pressure").values, (std::vector<double>{1.1, 2.1, 3.1, 4.1, 5.1, 6.1, 7.1, 8.1, 9.1, 10.1}));
  const FieldArray& velocity = field(all, "Velocity");  // VTK joins VelocityX/Y/Z
  EXPECT_EQ(velocity.components, 3);
  ASSERT_EQ(velocity.values.size(), 30u);
  EXPECT_EQ((std::vector<double>(velocity.values.begin() + 3, velocity.values.begin() + 6)),
            (std::vector<double>{1, 0.1, -1}));
  EXPECT_EQ((std::vector<double>(velocity.values.end() - 3, velocity.values.end())), (std::vector<double>{2, 0, 0.7}));

  const SurfaceMesh fin = read_vtk_surface(file, {.locations = {"fin"}});
  EXPECT_EQ(fin.location_names, std::vector<std::string>{"fin"});
  EXPECT_EQ(fin.points_xyz, fin_points);
  EXPECT_EQ(fin.face_indices, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(field(fin, "WallShear").values, std::vector<double>{13.5});

  expect_input_error(file, "'rudder'", {.locations = {"rudder"}});
  EXPECT_NE(read_error(file, {.locations = {"rudder"}}).find("'hull', 'fin'"), std::string::npos);
}

/// A 2 x 1 x 1 block of hexahedra (zone "fluid", a volume zone of a 3-D base)
/// with boundary conditions on its faces, as element sections and BC_t nodes:
/// "wall" (FamilySpecified, family "Hull", the two faces at z = 0 as a
/// PointRange or, if `wall_as_list`, a PointList), "lid" (BCWall without a
/// family, ElementRange of the two faces at z = 1) and "outlet" (BCOutflow,
/// the face at x = 2), which VTK 9.1 skips.
void write_volume_zone(const fs::path& file, bool wall_as_list = false) {
  CgnsWriter out(file);
  const int base = out.base("Base", 3);
  std::vector<Vec3> points;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) points.push_back({double(i), double(j), double(k)});
  const int zone = out.zone(base, "fluid", points, 2);
  const auto id = [](int i, int j, int k) { return cgsize_t{i + 3 * j + 6 * k + 1}; };
  out.section(base, zone, "Hexes", CGNS_ENUMV(HEXA_8), 1,
              {id(0, 0, 0), id(1, 0, 0), id(1, 1, 0), id(0, 1, 0), id(0, 0, 1), id(1, 0, 1), id(1, 1, 1), id(0, 1, 1),
               id(1, 0, 0), id(2, 0, 0), id(2, 1, 0), id(1, 1, 0), id(1, 0, 1), id(2, 0, 1), id(2, 1, 1), id(1, 1, 1)},
              8);
  out.section(base, zone, "wall", CGNS_ENUMV(QUAD_4), 3,
              {id(0, 0, 0), id(0, 1, 0), id(1, 1, 0), id(1, 0, 0), id(1, 0, 0), id(1, 1, 0), id(2, 1, 0), id(2, 0, 0)},
              4);
  out.section(base, zone, "lid", CGNS_ENUMV(QUAD_4), 5,
              {id(0, 0, 1), id(1, 0, 1), id(1, 1, 1), id(0, 1, 1), id(1, 0, 1), id(2, 0, 1), id(2, 1, 1), id(1, 1, 1)},
              4);
  out.section(base, zone, "outlet", CGNS_ENUMV(QUAD_4), 7, {id(2, 0, 0), id(2, 1, 0), id(2, 1, 1), id(2, 0, 1)}, 4);
  const int wall = out.boco(base, zone, "wall", CGNS_ENUMV(FamilySpecified),
                            wall_as_list ? CGNS_ENUMV(PointList) : CGNS_ENUMV(PointRange), {3, 4}, true);
  out.family(base, zone, wall, "Hull");
  out.boco(base, zone, "lid", CGNS_ENUMV(BCWall), CGNS_ENUMV(ElementRange), {5, 6}, false);
  out.boco(base, zone, "outlet", CGNS_ENUMV(BCOutflow), CGNS_ENUMV(PointRange), {7, 7}, true);
  int solution = out.solution(base, zone, "NodeData", CGNS_ENUMV(Vertex));
  std::vector<double> pressure;
  for (int i = 0; i < 12; ++i) pressure.push_back(100.0 + i);
  out.field(base, zone, solution, "Pressure", pressure);
  solution = out.solution(base, zone, "CellData", CGNS_ENUMV(CellCenter));
  out.field(base, zone, solution, "Density", {1.5, 2.5});
}

TEST(VtkSurfaceCgns, ReadsAVolumeZoneAsItsBoundaryAndItsPatchesOnRequest) {
  TempDir dir;
  const fs::path file = dir / "fluid.cgns";
  write_volume_zone(file);
  EXPECT_EQ(list_vtk_locations(file), (std::vector<std::string>{"fluid", "fluid/wall", "fluid/lid"}));

  // Unasked, the patches are left out: their faces are on the zone's boundary.
  const SurfaceMesh zone = read_vtk_surface(file);
  EXPECT_EQ(zone.location_names, std::vector<std::string>{"fluid"});
  EXPECT_EQ(zone.face_count(), 10u);
  EXPECT_EQ(zone.point_count(), 12u);
  EXPECT_EQ(field_names(zone), (std::vector<std::string>{"Density", "Pressure"}));
  const auto& density = field(zone, "Density").values;
  EXPECT_EQ(std::count(density.begin(), density.end(), 1.5), 5);  // each hexahedron has 5 boundary faces
  EXPECT_EQ(std::count(density.begin(), density.end(), 2.5), 5);

  // The wall patch: its two faces, on the 6 points they use (in the zone's
  // order), with their pressures; no face arrays.
  const SurfaceMesh wall = read_vtk_surface(file, {.locations = {"fluid/wall"}});
  EXPECT_EQ(wall.location_names, std::vector<std::string>{"fluid/wall"});
  EXPECT_EQ(wall.points_xyz, (std::vector<double>{0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0}));
  EXPECT_EQ(wall.face_indices, (std::vector<std::uint32_t>{0, 3, 4, 1, 1, 4, 5, 2}));
  EXPECT_EQ(field_names(wall), std::vector<std::string>{"Pressure"});
  EXPECT_EQ(field(wall, "Pressure").values, (std::vector<double>{100, 101, 102, 103, 104, 105}));

  const SurfaceMesh lids = read_vtk_surface(file, {.locations = {"fluid/wall", "fluid/lid"}});
  EXPECT_EQ(lids.face_location, (std::vector<std::uint32_t>{0, 0, 1, 1}));
  EXPECT_EQ(lids.point_count(), 12u);
  EXPECT_EQ(field(lids, "Pressure").values.size(), 12u);

  // The outlet's BC type is one VTK 9.1 skips; the error says so.
  expect_input_error(file, "'fluid', 'fluid/wall', 'fluid/lid'", {.locations = {"fluid/outlet"}});
  EXPECT_NE(read_error(file, {.locations = {"fluid/outlet"}}).find("BCOutflow"), std::string::npos)
      << read_error(file, {.locations = {"fluid/outlet"}});
}

// VTK 9.1 reads a boundary condition given as a list of faces (PointList) on
// another path than a range, one that leaks a vtkIdList for every face: under
// LeakSanitizer this test runs with the suppression in tests/lsan.supp.
TEST(VtkSurfaceCgns, ReadsAPatchGivenAsAListOfFaces) {
  TempDir dir;
  const fs::path file = dir / "fluid.cgns";
  write_volume_zone(file, true);
  const SurfaceMesh wall = read_vtk_surface(file, {.locations = {"fluid/wall"}});
  EXPECT_EQ(wall.points_xyz, (std::vector<double>{0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0}));
  EXPECT_EQ(wall.face_indices, (std::vector<std::uint32_t>{0, 3, 4, 1, 1, 4, 5, 2}));
  EXPECT_EQ(field(wall, "Pressure").values, (std::vector<double>{100, 101, 102, 103, 104, 105}));
}

TEST(VtkSurfaceCgns, ReadsTheLastTimeStep) {
  TempDir dir;
  const fs::path file = dir / "transient.cgns";
  {
    CgnsWriter out(file);
    const int base = out.base("Base", 2);
    const int zone = out.zone(base, "hull", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, 1);
    out.section(base, zone, "Quads", CGNS_ENUMV(QUAD_4), 1, {1, 2, 3, 4}, 4);
    std::string pointers;
    for (int step = 1; step <= 3; ++step) {
      const std::string name = "FlowSolution" + std::to_string(step);
      const int solution = out.solution(base, zone, name.c_str(), CGNS_ENUMV(Vertex));
      out.field(base, zone, solution, "Pressure", {10.0 * step, 10.0 * step + 1, 10.0 * step + 2, 10.0 * step + 3});
      pointers += name + std::string(32 - name.size(), ' ');
    }
    cg(cg_biter_write(out.file(), base, "BaseIterativeData", 3), "cg_biter_write");
    cg(cg_goto(out.file(), base, "BaseIterativeData_t", 1, "end"), "cg_goto");
    const double times[3] = {0.5, 1.0, 1.5};
    cgsize_t steps = 3;
    cg(cg_array_write("TimeValues", CGNS_ENUMV(RealDouble), 1, &steps, times), "cg_array_write");
    cg(cg_ziter_write(out.file(), base, zone, "ZoneIterativeData"), "cg_ziter_write");
    cg(cg_goto(out.file(), base, "Zone_t", zone, "ZoneIterativeData_t", 1, "end"), "cg_goto");
    cgsize_t dimensions[2] = {32, 3};
    cg(cg_array_write("FlowSolutionPointers", CGNS_ENUMV(Character), 2, dimensions, pointers.data()), "cg_array_write");
    cg(cg_simulation_type_write(out.file(), base, CGNS_ENUMV(TimeAccurate)), "cg_simulation_type_write");
  }
  EXPECT_EQ(field(read_vtk_surface(file), "Pressure").values, (std::vector<double>{30, 31, 32, 33}));
}

TEST(VtkSurfaceCgns, NamesZonesByBaseWhenThereAreSeveralBases) {
  TempDir dir;
  const fs::path file = dir / "bases.cgns";
  {
    CgnsWriter out(file);
    const int first = out.base("Hull", 2);
    const int hull = out.zone(first, "surface", kFinPoints, 1);
    out.section(first, hull, "Tris", CGNS_ENUMV(TRI_3), 1, {1, 2, 3}, 3);
    const int second = out.base("Fin", 2);
    const int fin = out.zone(second, "surface", kHullPoints, 3);
    out.section(second, fin, "Quads", CGNS_ENUMV(QUAD_4), 1, {1, 2, 5, 4, 2, 3, 6, 5}, 4);
    out.section(second, fin, "Tris", CGNS_ENUMV(TRI_3), 3, {3, 7, 6}, 3);
  }
  EXPECT_EQ(list_vtk_locations(file), (std::vector<std::string>{"Hull/surface", "Fin/surface"}));
  EXPECT_EQ(read_vtk_surface(file, {.locations = {"Fin/surface"}}).face_count(), 3u);
}

// VTK 9.1's CGNS reader ends the process (exit) on a file it cannot open: a
// broken file must be an InputError, and the tests still running shows that.
TEST(VtkSurfaceCgns, TruncatedAndGarbageFilesAreInputErrors) {
  TempDir dir;
  const fs::path good = dir / "body.cgns";
  write_surface_zones(good);
  const std::string whole = read_bytes(good);
  for (const std::size_t size : {std::size_t{8}, std::size_t{100}, std::size_t{1000}, whole.size() / 4,
                                 whole.size() / 2, whole.size() - 1000, whole.size() - 100, whole.size() - 1}) {
    const fs::path cut = dir / ("cut_" + std::to_string(size) + ".cgns");
    write_bytes(cut, whole.substr(0, size));
    expect_input_error(cut, cut.filename().string());
  }
  std::mt19937 random(20240611);
  std::string garbage(4096, '\0');
  std::generate(garbage.begin(), garbage.end(), [&random] { return static_cast<char>(random() & 0xff); });
  write_bytes(dir / "random.cgns", garbage);
  expect_input_error(dir / "random.cgns", "random.cgns");
  write_bytes(dir / "empty.cgns", "");
  expect_input_error(dir / "empty.cgns", "empty.cgns");
  EXPECT_NO_THROW(read_vtk_surface(good));
}

}  // namespace
}  // namespace hydrocoef
