// The direct .vtp reader against VTK's own reader: the same mesh, bit for bit,
// for every encoding VTK's writer can produce and for the OpenFOAM exports in
// the shared data; what it leaves to VTK; and its errors on damaged data,
// crafted here byte by byte.
#include "importers/vtk_xml_polydata.hpp"

#include <gtest/gtest.h>
#include <vtkBase64Utilities.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "importers/vtk_surface.hpp"
#include "src/core/error.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/meshes.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/vtk_polydata.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
using test::expect_input_error;
using test::TempDir;

using test::read_bytes;
using test::write_bytes;

SurfaceMesh read_through_vtk(const fs::path& file) {
  VtkSurfaceOptions options;
  options.direct_vtp = false;
  return read_vtk_surface(file, options);
}

/// Bit-for-bit equality of two meshes, arrays in the same order.
void expect_same_mesh(const SurfaceMesh& direct, const SurfaceMesh& vtk, const std::string& label) {
  EXPECT_EQ(direct.points_xyz, vtk.points_xyz) << label;
  EXPECT_EQ(direct.face_offsets, vtk.face_offsets) << label;
  EXPECT_EQ(direct.face_indices, vtk.face_indices) << label;
  EXPECT_EQ(direct.location_names, vtk.location_names) << label;
  EXPECT_EQ(direct.face_location, vtk.face_location) << label;
  ASSERT_EQ(direct.fields.size(), vtk.fields.size()) << label;
  for (std::size_t i = 0; i < direct.fields.size(); ++i) {
    const FieldArray& a = direct.fields[i];
    const FieldArray& b = vtk.fields[i];
    EXPECT_EQ(a.name, b.name) << label;
    EXPECT_EQ(a.association, b.association) << label << " " << a.name;
    EXPECT_EQ(a.components, b.components) << label << " " << a.name;
    EXPECT_EQ(a.values, b.values) << label << " " << a.name;
    EXPECT_EQ(a.unit, b.unit) << label << " " << a.name;
  }
}

/// A closed surface of quads and triangles with arrays of many types: what
/// each must become is what VTK's reader makes of it.
vtkSmartPointer<vtkPolyData> varied_surface(bool float_points) {
  SurfaceMesh mesh = test::make_uv_sphere(0.5, 7, 9);
  test::add_point_scalar(mesh, "p", [](const test::P3& x) { return 101325.0 + 1e3 * x[0] - 17.25 * x[2]; });
  test::add_point_vector(mesh, "wallShearStress", [](const test::P3& x) { return test::P3{x[1], -x[0], 1e-3}; });
  auto poly = test::to_vtk_polydata(mesh);
  if (float_points) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    points->DeepCopy(poly->GetPoints());
    poly->SetPoints(points);
  }
  const vtkIdType n_points = poly->GetNumberOfPoints(), n_cells = poly->GetNumberOfCells();
  vtkNew<vtkFloatArray> k;
  k->SetName("k");
  vtkNew<vtkIntArray> ids;
  ids->SetName("pointId");
  vtkNew<vtkDoubleArray> two;
  two->SetName("uv");
  two->SetNumberOfComponents(2);  // neither scalar nor vector: not a field
  for (vtkIdType i = 0; i < n_points; ++i) {
    k->InsertNextValue(0.001f * static_cast<float>(i) + 0.5f);
    ids->InsertNextValue(static_cast<int>(i) - 40);
    two->InsertNextTuple2(static_cast<double>(i), -static_cast<double>(i));
  }
  for (vtkDataArray* array :
       {static_cast<vtkDataArray*>(k), static_cast<vtkDataArray*>(ids), static_cast<vtkDataArray*>(two)})
    poly->GetPointData()->AddArray(array);
  vtkNew<vtkFloatArray> cp;
  cp->SetName("p");  // the same name as a point array: both are read, cell values first
  vtkNew<vtkDoubleArray> velocity;
  velocity->SetName("U");
  velocity->SetNumberOfComponents(3);
  vtkNew<vtkUnsignedCharArray> zone;
  zone->SetName("zone");
  vtkNew<vtkTypeInt64Array> big;
  big->SetName("cellId64");
  vtkNew<vtkStringArray> label;
  label->SetName("label");
  for (vtkIdType c = 0; c < n_cells; ++c) {
    cp->InsertNextValue(-0.25f * static_cast<float>(c));
    velocity->InsertNextTuple3(1.0 / static_cast<double>(c + 1), 2.0, -3.5);
    zone->InsertNextValue(static_cast<unsigned char>(c % 7));
    big->InsertNextValue((std::int64_t{1} << 40) + c);
    label->InsertNextValue("cell" + std::to_string(c));
  }
  poly->GetCellData()->AddArray(cp);
  poly->GetCellData()->AddArray(velocity);
  poly->GetCellData()->AddArray(zone);
  poly->GetCellData()->AddArray(big);
  poly->GetCellData()->AddArray(label);
  return poly;
}

struct Encoding {
  int mode;         // 1 binary, 2 appended raw, 3 appended base64
  int compression;  // 0 none, 1 zlib in 64-byte blocks, 2 zlib in VTK's default blocks
  bool header64, big_endian, ids64;
  std::string label() const {
    static const char* modes[] = {"", "binary", "appended-raw", "appended-base64"};
    static const char* compressions[] = {"none", "zlib64", "zlib"};
    return std::string(modes[mode]) + "_" + compressions[compression] + (header64 ? "_h64" : "_h32") +
           (big_endian ? "_be" : "_le") + (ids64 ? "_id64" : "_id32");
  }
};

fs::path write_vtp(vtkPolyData* poly, const Encoding& e, const fs::path& file) {
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(poly);
  writer->SetFileName(file.string().c_str());
  if (e.mode == 1) {
    writer->SetDataModeToBinary();
  } else {
    writer->SetDataModeToAppended();
    writer->SetEncodeAppendedData(e.mode == 3);
  }
  if (e.compression == 0) {
    writer->SetCompressorTypeToNone();
  } else {
    writer->SetCompressorTypeToZLib();
    if (e.compression == 1) writer->SetBlockSize(64);
  }
  if (e.header64)
    writer->SetHeaderTypeToUInt64();
  else
    writer->SetHeaderTypeToUInt32();
  if (e.big_endian)
    writer->SetByteOrderToBigEndian();
  else
    writer->SetByteOrderToLittleEndian();
  if (e.ids64)
    writer->SetIdTypeToInt64();
  else
    writer->SetIdTypeToInt32();
  EXPECT_EQ(writer->Write(), 1) << e.label();
  return file;
}

TEST(VtkXmlPolyData, GivesVtksMeshForEveryEncodingVtkWrites) {
  TempDir dir;
  int files = 0;
  for (const bool float_points : {false, true}) {
    const auto poly = varied_surface(float_points);
    for (int mode = 1; mode <= 3; ++mode)
      for (int compression = 0; compression <= 2; ++compression)
        for (const bool header64 : {false, true})
          for (const bool big_endian : {false, true})
            for (const bool ids64 : {false, true}) {
              const Encoding e{mode, compression, header64, big_endian, ids64};
              const std::string label = e.label() + (float_points ? "_f32" : "_f64");
              const fs::path file = write_vtp(poly, e, dir / (label + ".vtp"));
              const std::optional<SurfaceMesh> direct = read_vtp_surface(file);
              ASSERT_TRUE(direct.has_value()) << label << " was left to VTK";
              const SurfaceMesh vtk = read_through_vtk(file);
              ASSERT_EQ(direct->fields.size(), 8u) << label;  // 4 cell and 4 point arrays (uv and label left out)
              expect_same_mesh(*direct, vtk, label);
              ++files;
            }
  }
  EXPECT_EQ(files, 2 * 3 * 3 * 2 * 2 * 2);
}

TEST(VtkXmlPolyData, GivesVtksMeshForTheOpenFoamExports) {
  const fs::path data = fs::path(HYDROCOEF_DATA_DIR) / "openfoam-sphere";
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(data)) {
    if (entry.path().extension() != ".vtp") continue;
    const std::optional<SurfaceMesh> direct = read_vtp_surface(entry.path());
    ASSERT_TRUE(direct.has_value()) << entry.path();
    EXPECT_GT(direct->face_count(), 100u);
    expect_same_mesh(*direct, read_through_vtk(entry.path()), entry.path().string());
    ++files;
  }
  EXPECT_GE(files, 5);
}

TEST(VtkXmlPolyData, ReadVtkSurfaceTakesTheDirectPathAndStillSelectsByLocation) {
  TempDir dir;
  const fs::path file = write_vtp(varied_surface(false), {2, 2, true, false, true}, dir / "hull.vtp");
  VtkSurfaceOptions named;
  named.locations = {"hull"};
  expect_same_mesh(read_vtk_surface(file, named), read_through_vtk(file), "location hull");
  VtkSurfaceOptions wrong;
  wrong.locations = {"fin"};
  expect_input_error([&] { read_vtk_surface(file, wrong); }, {"hull.vtp", "no location 'fin'", "'hull'"});
}

// --- what is left to VTK's reader -----------------------------------------------

TEST(VtkXmlPolyData, LeavesToVtkWhatItDoesNotRead) {
  TempDir dir;
  const auto poly = varied_surface(false);
  std::vector<fs::path> left;

  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(poly);
  writer->SetDataModeToAscii();
  writer->SetFileName((dir / "ascii.vtp").string().c_str());
  ASSERT_EQ(writer->Write(), 1);
  left.push_back(dir / "ascii.vtp");

  writer->SetDataModeToAppended();
  writer->SetCompressorTypeToLZ4();
  writer->SetFileName((dir / "lz4.vtp").string().c_str());
  ASSERT_EQ(writer->Write(), 1);
  left.push_back(dir / "lz4.vtp");

  writer->SetCompressorTypeToLZMA();
  writer->SetFileName((dir / "lzma.vtp").string().c_str());
  ASSERT_EQ(writer->Write(), 1);
  left.push_back(dir / "lzma.vtp");

  // Lines beside the polygons (VTK's path ignores them).
  auto with_lines = vtkSmartPointer<vtkPolyData>::New();
  with_lines->DeepCopy(poly);
  vtkNew<vtkCellArray> lines;
  const vtkIdType line[2] = {0, 1};
  lines->InsertNextCell(2, line);
  with_lines->SetLines(lines);
  with_lines->GetCellData()->Initialize();
  writer->SetInputData(with_lines);
  writer->SetCompressorTypeToNone();
  writer->SetFileName((dir / "lines.vtp").string().c_str());
  ASSERT_EQ(writer->Write(), 1);
  left.push_back(dir / "lines.vtp");

  // Inline base64 broken over lines, uncompressed and compressed (the line
  // break inside the compression header): left to VTK's reader.
  for (const int compression : {0, 1}) {
    std::string wrapped = read_bytes(write_vtp(poly, {1, compression, true, false, true}, dir / "wrapped_source.vtp"));
    const auto text = wrapped.find("format=\"binary\"");
    const auto data = wrapped.find('>', text) + 1;
    const auto first = wrapped.find_first_not_of(" \n", data);
    wrapped.insert(first + 20, "\n          ");
    const fs::path file = dir / ("wrapped" + std::to_string(compression) + ".vtp");
    write_bytes(file, wrapped);
    left.push_back(file);
  }

  // Two arrays naming the same appended bytes.
  std::string shared = read_bytes(write_vtp(poly, {2, 0, true, false, true}, dir / "shared_source.vtp"));
  const auto k = shared.find("Name=\"k\"");
  const auto k_offset = shared.find("offset=\"", k) + 8;
  const auto p_offset = shared.find("offset=\"", shared.find("Name=\"p\"")) + 8;
  shared.replace(k_offset, shared.find('"', k_offset) - k_offset,
                 shared.substr(p_offset, shared.find('"', p_offset) - p_offset));
  write_bytes(dir / "shared.vtp", shared);
  left.push_back(dir / "shared.vtp");

  for (const auto& file : left) {
    EXPECT_FALSE(read_vtp_surface(file).has_value()) << file;
    if (file.filename() == "wrapped1.vtp") {
      // VTK's reader does not take a line break inside a compression header either.
      expect_input_error([&] { read_vtk_surface(file); }, {"wrapped1.vtp", "compression header"});
      continue;
    }
    expect_same_mesh(read_vtk_surface(file), read_through_vtk(file), file.string());
  }
}

TEST(VtkXmlPolyData, LeavesBrokenXmlToVtksParser) {
  TempDir dir;
  const std::string good = read_bytes(write_vtp(varied_surface(false), {1, 0, true, false, true}, dir / "good.vtp"));
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"cut.vtp", good.substr(0, good.size() / 2)},
      {"garbage.vtp", std::string(256, '\x07')},
      {"doctype.vtp", "<!DOCTYPE x>" + good},
      {"unclosed.vtp", good.substr(0, good.rfind("</VTKFile>"))},
  };
  for (const auto& [name, bytes] : cases) {
    write_bytes(dir / name, bytes);
    EXPECT_FALSE(parse_vtp_surface(bytes, name, "x").has_value()) << name;
  }
  expect_input_error([&] { read_vtk_surface(dir / "cut.vtp"); }, {"cut.vtp", "Error parsing XML"});
}

// --- damaged data -------------------------------------------------------------------

std::string base64(const std::string& bytes) {
  std::string out(4 * (bytes.size() + 2) / 3 + 4, '\0');
  const unsigned long n = vtkBase64Utilities::Encode(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(),
                                                     reinterpret_cast<unsigned char*>(out.data()), 0);
  out.resize(n);
  return out;
}

/// An inline binary DataArray: a UInt64 byte count, then the values.
template <typename T>
std::string data_array(const std::string& type, const std::string& name, int components, const std::vector<T>& values) {
  std::string bytes(8 + sizeof(T) * values.size(), '\0');
  const std::uint64_t count = sizeof(T) * values.size();
  std::memcpy(bytes.data(), &count, 8);
  if (!values.empty()) std::memcpy(bytes.data() + 8, values.data(), sizeof(T) * values.size());
  return "<DataArray type=\"" + type + "\" Name=\"" + name + "\" NumberOfComponents=\"" + std::to_string(components) +
         "\" format=\"binary\">" + base64(bytes) + "</DataArray>\n";
}

/// A little-endian .vtp with UInt64 headers and the given arrays.
std::string crafted_vtp(std::size_t points, std::size_t polys, const std::vector<double>& xyz,
                        const std::vector<std::int64_t>& connectivity, const std::vector<std::int64_t>& offsets,
                        const std::string& point_data = "") {
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n<PolyData>\n<Piece NumberOfPoints=\"" +
         std::to_string(points) + "\" NumberOfPolys=\"" + std::to_string(polys) + "\">\n<PointData>\n" + point_data +
         "</PointData>\n<Points>\n" + data_array<double>("Float64", "Points", 3, xyz) + "</Points>\n<Polys>\n" +
         data_array<std::int64_t>("Int64", "connectivity", 1, connectivity) +
         data_array<std::int64_t>("Int64", "offsets", 1, offsets) + "</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n";
}

const std::vector<double> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};
const std::vector<double> kSquare = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};

TEST(VtkXmlPolyData, ReadsACraftedFileAsVtkDoes) {
  TempDir dir;
  const std::string bytes = crafted_vtp(4, 2, kSquare, {0, 1, 2, 0, 2, 3}, {3, 6},
                                        data_array<float>("Float32", "p", 1, {1.5f, 2.5f, 3.5f, 4.5f}));
  write_bytes(dir / "square.vtp", bytes);
  const std::optional<SurfaceMesh> mesh = read_vtp_surface(dir / "square.vtp");
  ASSERT_TRUE(mesh.has_value());
  EXPECT_EQ(mesh->face_offsets, (std::vector<std::uint32_t>{0, 3, 6}));
  EXPECT_EQ(mesh->face_indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
  ASSERT_EQ(mesh->fields.size(), 1u);
  EXPECT_EQ(mesh->fields[0].values, (std::vector<double>{1.5, 2.5, 3.5, 4.5}));
  EXPECT_EQ(mesh->location_names, std::vector<std::string>{"square"});
  expect_same_mesh(*mesh, read_through_vtk(dir / "square.vtp"), "square");
}

/// Both readers refuse the file; this one with the given message.
void expect_refused(const std::string& bytes, const std::vector<std::string>& expected) {
  TempDir dir;
  const fs::path file = dir / "damaged.vtp";
  write_bytes(file, bytes);
  std::vector<std::string> pieces = {"damaged.vtp"};
  pieces.insert(pieces.end(), expected.begin(), expected.end());
  expect_input_error([&] { read_vtp_surface(file); }, pieces);
  EXPECT_THROW(read_through_vtk(file), InputError) << expected.front();
}

TEST(VtkXmlPolyData, RefusesPointIndicesOutOfRange) {
  expect_refused(crafted_vtp(3, 1, kTriangle, {0, 1, 7}, {3}),
                 {"block 'damaged': cell 0 refers to point 7; expected 0..2 (the block has 3 points)"});
  expect_refused(crafted_vtp(4, 2, kSquare, {0, 1, 2, 0, -2, 3}, {3, 6}), {"cell 1 refers to point -2"});
}

TEST(VtkXmlPolyData, RefusesPolygonsOfFewerThanThreePoints) {
  expect_refused(crafted_vtp(4, 2, kSquare, {0, 1, 2, 0, 2}, {3, 5}),
                 {"block 'damaged': cell 1 is a polygon with 2 points; expected at least 3"});
}

TEST(VtkXmlPolyData, RefusesOffsetsThatGoBackOrPastTheConnectivity) {
  expect_refused(crafted_vtp(4, 3, kSquare, {0, 1, 2, 0, 2, 3}, {3, 6, 4}),
                 {"offsets array goes back at cell 2 (4 after 6)"});
  expect_refused(crafted_vtp(4, 2, kSquare, {0, 1, 2}, {3, 6}),
                 {"connectivity array holds 3 point indices; the offsets call for 6"});
  expect_refused(crafted_vtp(3, 1, kTriangle, {0, 1, 2}, {-3}), {"offsets array holds -3 at cell 0"});
}

TEST(VtkXmlPolyData, RefusesArraysShorterThanThePiece) {
  expect_refused(crafted_vtp(4, 1, kTriangle, {0, 1, 2}, {3}), {"the points array: holds 9 values; expected 12"});
  expect_refused(crafted_vtp(3, 1, kTriangle, {0, 1, 2}, {3}, data_array<double>("Float64", "p", 1, {1.0, 2.0})),
                 {"point data array 'p': holds 2 values; expected 3"});
}

TEST(VtkXmlPolyData, RefusesTextOutsideTheBase64Alphabet) {
  std::string bytes = crafted_vtp(3, 1, kTriangle, {0, 1, 2}, {3});
  const auto points = bytes.find("Name=\"Points\"");
  const auto data = bytes.find('>', points) + 1;
  bytes[data + 20] = '*';
  TempDir dir;
  write_bytes(dir / "star.vtp", bytes);
  expect_input_error([&] { read_vtp_surface(dir / "star.vtp"); },
                     {"star.vtp", "the points array: character 20 of the array's base64 text is '*'",
                      "expected only A-Z a-z 0-9 + / and '=' padding at the end"});
}

/// The offset in `bytes` of the appended data (after the '_').
std::size_t appended_start(const std::string& bytes) { return bytes.find('_', bytes.find("<AppendedData")) + 1; }

TEST(VtkXmlPolyData, RefusesAppendedDataCutShort) {
  TempDir dir;
  const std::string good = read_bytes(write_vtp(varied_surface(false), {2, 0, true, false, true}, dir / "good.vtp"));
  const std::size_t start = appended_start(good);
  for (const double fraction : {0.1, 0.5, 0.95}) {
    const auto cut = start + static_cast<std::size_t>(fraction * static_cast<double>(good.size() - start));
    expect_refused(good.substr(0, cut), {"cut short"});
  }
}

/// Where the compressed data of the connectivity array's first zlib block
/// start in a file written with 8-byte headers, in bytes (raw appended data)
/// or base64 characters (inline or appended base64).
std::size_t first_block_position(const std::string& bytes, int mode) {
  const std::size_t tag = bytes.find("Name=\"connectivity\"", bytes.find("<Polys"));
  std::size_t start;
  if (mode == 1) {
    start = bytes.find('>', tag) + 1;
    while (bytes[start] == ' ' || bytes[start] == '\n') ++start;
  } else {
    const std::size_t offset_at = bytes.find("offset=\"", tag) + 8;
    start = appended_start(bytes) + std::stoul(bytes.substr(offset_at, bytes.find('"', offset_at) - offset_at));
  }
  std::uint64_t blocks = 0;
  if (mode == 2) {
    std::memcpy(&blocks, bytes.data() + start, 8);
    return start + (3 + blocks) * 8;
  }
  unsigned char head[9];
  vtkBase64Utilities::DecodeSafely(reinterpret_cast<const unsigned char*>(bytes.data() + start), 12, head, 9);
  std::memcpy(&blocks, head, 8);
  return start + ((3 + blocks) * 8 + 2) / 3 * 4;
}

TEST(VtkXmlPolyData, RefusesDamagedZlibBlocks) {
  TempDir dir;
  const auto poly = varied_surface(false);
  for (const int mode : {1, 2, 3}) {
    const Encoding e{mode, 1, true, false, true};
    std::string bytes = read_bytes(write_vtp(poly, e, dir / (e.label() + ".vtp")));
    // Past the zlib stream's own header: raw bytes flipped, base64
    // characters swapped for other base64 characters.
    const std::size_t at = first_block_position(bytes, mode) + 8;
    for (std::size_t i = at; i < at + 16; ++i)
      bytes[i] = mode == 2 ? static_cast<char>(bytes[i] ^ 0x5a) : (bytes[i] == 'A' ? 'B' : 'A');
    TempDir damaged_dir;
    write_bytes(damaged_dir / "damaged.vtp", bytes);
    expect_input_error([&] { read_vtp_surface(damaged_dir / "damaged.vtp"); },
                       {"damaged.vtp", "the Polys connectivity array: zlib block 1 of"});
  }
}

TEST(VtkXmlPolyData, RefusesAFileWithoutPolygons) {
  expect_refused(crafted_vtp(3, 0, kTriangle, {}, {}), {"no faces"});
}

// Headers that claim more than any file holds are refused before anything is
// allocated for them; an element with more attributes than VTK writes is left
// to VTK's parser.
TEST(VtkXmlPolyData, RefusesOrLeavesHeadersThatClaimTooMuch) {
  TempDir dir;
  const std::string triangle = crafted_vtp(3, 1, kTriangle, {0, 1, 2}, {3});
  auto with_points = [&](const std::string& count) {
    std::string bytes = triangle;
    const auto at = bytes.find("NumberOfPoints=\"3\"");
    return bytes.replace(at, 18, "NumberOfPoints=\"" + count + "\"");
  };
  expect_input_error([&] { parse_vtp_surface(with_points("5000000000"), "big.vtp", "big"); },
                     {"big.vtp", "NumberOfPoints is 5000000000; at most 4294967295 points are supported"});

  // A zlib header stating 10^12 blocks, in a file of a few hundred bytes.
  std::string compressed = triangle;
  compressed.insert(compressed.find("header_type"), "compressor=\"vtkZLibDataCompressor\" ");
  std::string header(24, '\0');
  const std::uint64_t words[3] = {1000000000000, 32768, 0};
  std::memcpy(header.data(), words, 24);
  const auto points = compressed.find("Name=\"Points\"");
  const auto text = compressed.find('>', points) + 1;
  compressed.replace(text, compressed.find('<', text) - text, base64(header));
  expect_input_error([&] { parse_vtp_surface(compressed, "blocks.vtp", "blocks"); },
                     {"blocks.vtp", "the points array: the compression header gives 1000000000000 blocks"});

  std::string attributes;
  for (int i = 0; i < 65; ++i) attributes += " a" + std::to_string(i) + "=\"0\"";
  std::string many = triangle;
  many.insert(many.find("NumberOfPolys"), attributes.substr(1) + " ");
  EXPECT_FALSE(parse_vtp_surface(many, "many.vtp", "many").has_value());
  write_bytes(dir / "many.vtp", many);
  EXPECT_EQ(read_vtk_surface(dir / "many.vtp").face_count(), 1u) << "VTK's reader reads it";
}

}  // namespace
}  // namespace hydrocoef
