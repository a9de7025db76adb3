// Tests of the CFD-Post Generic export importer: the real export excerpt in
// the shared reference folder, small exports written here by hand in every
// dialect (blocks, CRLF, tab, Node Number, shuffled columns, mm/kPa, null,
// phase prefixes, [Lines]), location selection, every input error with its
// file:line:column, and round trips through tests/support/cfdpost_writer.hpp.
// Expected values come from the text of the files, never from the importer.
#include "importers/cfdpost_export.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "src/core/error.hpp"
#include "tests/support/cfdpost_writer.hpp"
#include "tests/support/sqlite_dump.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
using Strings = std::vector<std::string>;
using Indices = std::vector<std::uint32_t>;

const fs::path kSampleDir = fs::path(HYDROCOEF_DATA_DIR) / "cfx-samples";
const fs::path kSample = kSampleDir / "cfdpost-wall-export-head100.csv";
constexpr const char* kPascal = "kg m^-1 s^-2";  // si_unit_name of a pressure

std::string join_lines(std::initializer_list<std::string_view> lines, std::string_view eol = "\n") {
  std::string out;
  for (const auto line : lines) {
    out += line;
    out += eol;
  }
  return out;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The message of the InputError `action` throws; a test failure when it throws none.
std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

std::string parse_error(std::string_view text, const CfdPostOptions& options = {}) {
  return error_of([&] { (void)parse_cfdpost_export(text, "mem.csv", options); });
}

#define EXPECT_CONTAINS(haystack, needle)                          \
  EXPECT_NE(std::string(haystack).find(needle), std::string::npos) \
      << "'" << (haystack) << "' lacks '" << (needle) << "'"

const FieldArray& field(const SurfaceMesh& mesh, const std::string& name) {
  const FieldArray* found = mesh.find_field(name);
  if (found == nullptr) throw std::runtime_error("no array " + name);
  return *found;
}

Strings field_names(const SurfaceMesh& mesh) {
  Strings names;
  for (const auto& array : mesh.fields) names.push_back(array.name);
  return names;
}

bool close(double a, double b, double relative) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b));
}

/// Same topology, locations and array names/units; values equal to `relative`
/// (0 = bit for bit, NaN equal to NaN).
void expect_same_mesh(const SurfaceMesh& actual, const SurfaceMesh& expected, double relative) {
  EXPECT_EQ(actual.face_offsets, expected.face_offsets);
  EXPECT_EQ(actual.face_indices, expected.face_indices);
  EXPECT_EQ(actual.face_location, expected.face_location);
  EXPECT_EQ(actual.location_names, expected.location_names);
  ASSERT_EQ(actual.points_xyz.size(), expected.points_xyz.size());
  for (std::size_t i = 0; i < actual.points_xyz.size(); ++i)
    ASSERT_TRUE(close(actual.points_xyz[i], expected.points_xyz[i], relative))
        << "coordinate " << i << ": " << actual.points_xyz[i] << " vs " << expected.points_xyz[i];
  ASSERT_EQ(field_names(actual), field_names(expected));
  for (std::size_t a = 0; a < actual.fields.size(); ++a) {
    const FieldArray& x = actual.fields[a];
    const FieldArray& y = expected.fields[a];
    EXPECT_EQ(x.unit, y.unit) << x.name;
    EXPECT_EQ(x.components, y.components) << x.name;
    EXPECT_EQ(x.association, y.association) << x.name;
    ASSERT_EQ(x.values.size(), y.values.size()) << x.name;
    for (std::size_t i = 0; i < x.values.size(); ++i)
      ASSERT_TRUE(close(x.values[i], y.values[i], relative))
          << x.name << "[" << i << "]: " << x.values[i] << " vs " << y.values[i];
  }
}

// Two blocks: a unit square quad (hull, z = 0) and two triangles on the
// square at z = 1 (fin). Pressure = 100 * (global node + 1) Pa, shear
// = pressure / 100 + 0.5 Pa.
const std::string kTwoBlocks = join_lines({
    "",
    "[Name]",
    "hull",
    "",
    "[Data]",
    "X [ m ], Y [ m ], Z [ m ], Pressure [ Pa ], Wall Shear X [ Pa ]",
    "0.00000000e+00, 0.00000000e+00, 0.00000000e+00, 1.00000000e+02, 1.50000000e+00",
    "1.00000000e+00, 0.00000000e+00, 0.00000000e+00, 2.00000000e+02, 2.50000000e+00",
    "1.00000000e+00, 1.00000000e+00, 0.00000000e+00, 3.00000000e+02, 3.50000000e+00",
    "0.00000000e+00, 1.00000000e+00, 0.00000000e+00, 4.00000000e+02, 4.50000000e+00",
    "",
    "[Faces]",
    "0, 1, 2, 3",
    "",
    "[Name]",
    "fin",
    "",
    "[Data]",
    "X [ m ], Y [ m ], Z [ m ], Pressure [ Pa ], Wall Shear X [ Pa ]",
    "0.00000000e+00, 0.00000000e+00, 1.00000000e+00, 5.00000000e+02, 5.50000000e+00",
    "1.00000000e+00, 0.00000000e+00, 1.00000000e+00, 6.00000000e+02, 6.50000000e+00",
    "0.00000000e+00, 1.00000000e+00, 1.00000000e+00, 7.00000000e+02, 7.50000000e+00",
    "1.00000000e+00, 1.00000000e+00, 1.00000000e+00, 8.00000000e+02, 8.50000000e+00",
    "",
    "[Faces]",
    "0, 1, 2",
    "1, 3, 2",
    "",
});

const std::vector<double> kTwoBlocksPoints = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};

void expect_two_blocks(const SurfaceMesh& mesh) {
  EXPECT_EQ(mesh.location_names, (Strings{"hull", "fin"}));
  EXPECT_EQ(mesh.points_xyz, kTwoBlocksPoints);
  EXPECT_EQ(mesh.face_offsets, (Indices{0, 4, 7, 10}));
  // fin's local indices 0..3 become 4..7.
  EXPECT_EQ(mesh.face_indices, (Indices{0, 1, 2, 3, 4, 5, 6, 5, 7, 6}));
  EXPECT_EQ(mesh.face_location, (Indices{0, 1, 1}));
  ASSERT_EQ(field_names(mesh), (Strings{"Pressure", "Wall Shear X"}));
  EXPECT_EQ(field(mesh, "Pressure").values, (std::vector<double>{100, 200, 300, 400, 500, 600, 700, 800}));
  EXPECT_EQ(field(mesh, "Pressure").unit, kPascal);
  EXPECT_EQ(field(mesh, "Pressure").association, FieldAssociation::Point);
  EXPECT_EQ(field(mesh, "Pressure").components, 1);
  EXPECT_EQ(field(mesh, "Wall Shear X").values, (std::vector<double>{1.5, 2.5, 3.5, 4.5, 5.5, 6.5, 7.5, 8.5}));
}

// ---------------------------------------------------------------------------
// The real export excerpt (CRLF, leading blank line, no [Faces]).

std::size_t count_data_rows(const std::string& text) {
  // Independently of the importer: rows are the lines starting with a sign or digit.
  std::size_t rows = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    const char c = text[start];
    if (c == '-' || (c >= '0' && c <= '9')) ++rows;
    const auto newline = text.find('\n', start);
    if (newline == std::string::npos) break;
    start = newline + 1;
  }
  return rows;
}

TEST(CfdPostSample, IsRecognisedAndListsItsLocation) {
  const std::string text = slurp(kSample);
  EXPECT_TRUE(looks_like_cfdpost_export(text));
  EXPECT_TRUE(looks_like_cfdpost_export(text.substr(0, 20)));
  EXPECT_EQ(list_cfdpost_locations(text, kSample.string()), (Strings{"aneurysm"}));
}

TEST(CfdPostSample, WithoutConnectivityIsRefused) {
  const std::string message = error_of([] { (void)read_cfdpost_export(kSample); });
  EXPECT_CONTAINS(message, kSample.string());
  EXPECT_CONTAINS(message, "no [Faces] section");
  EXPECT_CONTAINS(message, "Export Connectivity = On");
}

TEST(CfdPostSample, NodesAndArraysAreReadWhenAFaceIsAppended) {
  const std::string raw = slurp(kSample);
  const std::size_t rows = count_data_rows(raw);
  ASSERT_EQ(rows, 94u);  // 100 lines minus blank, [Name], name, blank, [Data], header
  const SurfaceMesh mesh = parse_cfdpost_export(raw + "\r\n[Faces]\r\n0, 1, 2\r\n", "sample.csv");

  ASSERT_EQ(mesh.point_count(), rows);
  EXPECT_EQ(mesh.location_names, (Strings{"aneurysm"}));
  EXPECT_EQ(mesh.face_indices, (Indices{0, 1, 2}));
  EXPECT_EQ(field_names(mesh), (Strings{"Pressure", "Velocity", "Velocity u", "Velocity v", "Velocity w", "Wall Shear",
                                        "Wall Shear X", "Wall Shear Y", "Wall Shear Z"}));
  EXPECT_EQ(field(mesh, "Pressure").unit, kPascal);
  EXPECT_EQ(field(mesh, "Velocity u").unit, "m s^-1");
  EXPECT_EQ(field(mesh, "Wall Shear Z").unit, kPascal);
  for (const auto& array : mesh.fields) EXPECT_EQ(array.values.size(), rows) << array.name;

  // First row of the file, as written (SI already).
  EXPECT_EQ(mesh.points_xyz[0], -5.05357236e-02);
  EXPECT_EQ(mesh.points_xyz[1], -5.67596816e-02);
  EXPECT_EQ(mesh.points_xyz[2], -1.06314151e-03);
  EXPECT_EQ(field(mesh, "Pressure").values.front(), 2.02633496e+03);
  EXPECT_EQ(field(mesh, "Velocity").values.front(), 0.0);
  EXPECT_EQ(field(mesh, "Wall Shear").values.front(), 7.20992374e+00);
  EXPECT_EQ(field(mesh, "Wall Shear X").values.front(), 4.47006798e+00);
  EXPECT_EQ(field(mesh, "Wall Shear Y").values.front(), -4.78601742e+00);
  EXPECT_EQ(field(mesh, "Wall Shear Z").values.front(), 3.01587963e+00);
  // Last row (line 100).
  const std::size_t last = 3 * (rows - 1);
  EXPECT_EQ(mesh.points_xyz[last + 0], -2.55462583e-02);
  EXPECT_EQ(mesh.points_xyz[last + 1], -7.24225566e-02);
  EXPECT_EQ(mesh.points_xyz[last + 2], 9.24482383e-03);
  EXPECT_EQ(field(mesh, "Pressure").values.back(), 1.92450635e+03);
  EXPECT_EQ(field(mesh, "Wall Shear").values.back(), 4.96454430e+00);
  EXPECT_EQ(field(mesh, "Wall Shear X").values.back(), 4.58620596e+00);
  EXPECT_EQ(field(mesh, "Wall Shear Y").values.back(), 1.65275776e+00);
  EXPECT_EQ(field(mesh, "Wall Shear Z").values.back(), 9.39046085e-01);
  // Velocity is exactly zero at wall nodes in this export.
  for (const double u : field(mesh, "Velocity u").values) EXPECT_EQ(u, 0.0);
}

TEST(CfdPostSample, CutInsideTheLastRowIsAFieldCountError) {
  std::string text = slurp(kSample);
  text.resize(text.size() - 2);  // drop the final CRLF
  const auto last_start = text.rfind('\n') + 1;
  text.resize(last_start + 40);  // about three fields of twelve
  const std::string message = parse_error(text);
  EXPECT_CONTAINS(message, "mem.csv:100:1: ");
  EXPECT_CONTAINS(message, "found 3 fields, expected 12");
  EXPECT_CONTAINS(message, "header on line 6");
}

// ---------------------------------------------------------------------------
// Hand-written exports.

TEST(CfdPostParse, TwoBlocksWithQuadAndTriangles) {
  expect_two_blocks(parse_cfdpost_export(kTwoBlocks, "mem.csv"));
  EXPECT_EQ(list_cfdpost_locations(kTwoBlocks, "mem.csv"), (Strings{"hull", "fin"}));
}

TEST(CfdPostParse, CrlfTabNodeNumberAndShuffledColumnsGiveTheSameMesh) {
  // The same surface as kTwoBlocks, written another way: the two blocks even
  // order their columns differently.
  const std::string text = join_lines(
      {
          "[Name]",
          "hull",
          "",
          "[Data]",
          "Node Number\tWall Shear X [ Pa ]\tZ [ m ]\tPressure [ Pa ]\tX [ m ]\tY [ m ]",
          "1\t1.5\t0\t100\t0\t0",
          "2\t2.5\t0\t200\t1\t0",
          "3\t3.5\t0\t300\t1\t1",
          "4\t4.5\t0\t400\t0\t1",
          "",
          "[Faces]",
          "0\t1\t2\t3",
          "",
          "[Name]",
          "fin",
          "",
          "[Data]",
          "Node Number\tY [ m ]\tX [ m ]\tPressure [ Pa ]\tZ [ m ]\tWall Shear X [ Pa ]",
          "5\t0\t0\t500\t1\t5.5",
          "6\t0\t1\t600\t1\t6.5",
          "7\t1\t0\t700\t1\t7.5",
          "8\t1\t1\t800\t1\t8.5",
          "",
          "[Faces]",
          "0\t1\t2",
          "1\t3\t2",
      },
      "\r\n");
  const SurfaceMesh mesh = parse_cfdpost_export(text, "mem.csv");
  EXPECT_EQ(mesh.location_names, (Strings{"hull", "fin"}));
  EXPECT_EQ(mesh.points_xyz, kTwoBlocksPoints);
  EXPECT_EQ(mesh.face_indices, (Indices{0, 1, 2, 3, 4, 5, 6, 5, 7, 6}));
  // Field order follows the first block's header; Node Number is not an array.
  ASSERT_EQ(field_names(mesh), (Strings{"Wall Shear X", "Pressure"}));
  EXPECT_EQ(field(mesh, "Pressure").values, (std::vector<double>{100, 200, 300, 400, 500, 600, 700, 800}));
  EXPECT_EQ(field(mesh, "Wall Shear X").values, (std::vector<double>{1.5, 2.5, 3.5, 4.5, 5.5, 6.5, 7.5, 8.5}));
}

TEST(CfdPostParse, MillimetreAndKilopascalBecomeMetreAndPascalExactly) {
  const std::string text = join_lines({
      "[Name]",
      "wall",
      "[Data]",
      "X [ mm ], Y [ mm ], Z [ mm ], Pressure [ kPa ], Velocity [ mm s^-1 ], Area [ mm^2 ]",
      "1500, -250, 0.5, 2.5, 3000, 2000000",
      "-2.048e+03, 1.25e+02, 0, -1.0e-03, -7.5e+02, 5.0e+05",
      "9, 0, 1000, 101.325, 0, 1",
      "",
      "[Faces]",
      "0, 1, 2",
  });
  const SurfaceMesh mesh = parse_cfdpost_export(text, "mem.csv");
  // Exact: these decimals are exact binary numbers and one division by a
  // power of ten rounds once, to the double nearest the SI decimal (9 mm
  // times the inexact 1e-3 would give 0.009000000000000001).
  EXPECT_EQ(mesh.points_xyz, (std::vector<double>{1.5, -0.25, 0.0005, -2.048, 0.125, 0.0, 0.009, 0.0, 1.0}));
  EXPECT_EQ(field(mesh, "Pressure").values, (std::vector<double>{2500.0, -1.0, 101325.0}));
  EXPECT_EQ(field(mesh, "Pressure").unit, kPascal);
  EXPECT_EQ(field(mesh, "Velocity").values, (std::vector<double>{3.0, -0.75, 0.0}));
  EXPECT_EQ(field(mesh, "Velocity").unit, "m s^-1");
  EXPECT_EQ(field(mesh, "Area").values, (std::vector<double>{2.0, 0.5, 1e-6}));
  EXPECT_EQ(field(mesh, "Area").unit, "m^2");
}

TEST(CfdPostParse, NullTokenBecomesNaN) {
  const std::string text = join_lines({
      "[Name]",
      "wall",
      "",
      "[Data]",
      "X [ m ], Y [ m ], Z [ m ], Pressure [ Pa ], Yplus",
      "0, 0, 0, null, 1.5",
      "1, 0, 0, 2.0, null",
      "0, 1, 0, 3.0, 2.5",
      "",
      "[Faces]",
      "0, 1, 2",
  });
  const SurfaceMesh mesh = parse_cfdpost_export(text, "mem.csv");
  const auto& pressure = field(mesh, "Pressure").values;
  const auto& yplus = field(mesh, "Yplus").values;
  EXPECT_TRUE(std::isnan(pressure[0]));
  EXPECT_EQ(pressure[1], 2.0);
  EXPECT_EQ(pressure[2], 3.0);
  EXPECT_EQ(yplus[0], 1.5);
  EXPECT_TRUE(std::isnan(yplus[1]));
  EXPECT_EQ(field(mesh, "Yplus").unit, "");
}

TEST(CfdPostParse, PhasePrefixesDotsAndBareNames) {
  const std::string text = join_lines({
      "[Name]",
      "hull wall",
      "[Data]",
      "X [ m ], Y [ m ], Z [ m ], water.Pressure [ Pa ], Velocity u.Gradient X [ s^-1 ], gas.Velocity w [ m s^-1 ], "
      "Normal X, Yplus, Wall Shear X [ Pa ], Wall Shear Y [ Pa ], Wall Shear Z [ Pa ]",
      "0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8",
      "1, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8",
      "0, 1, 0, 1, 2, 3, 4, 5, 6, 7, 8",
      "[Faces]",
      "2, 1, 0",
  });
  const SurfaceMesh mesh = parse_cfdpost_export(text, "mem.csv");
  EXPECT_EQ(mesh.location_names, (Strings{"hull wall"}));
  EXPECT_EQ(field_names(mesh), (Strings{"water.Pressure", "Velocity u.Gradient X", "gas.Velocity w", "Normal X",
                                        "Yplus", "Wall Shear X", "Wall Shear Y", "Wall Shear Z"}));
  EXPECT_EQ(field(mesh, "water.Pressure").unit, kPascal);
  EXPECT_EQ(field(mesh, "Velocity u.Gradient X").unit, "s^-1");
  EXPECT_EQ(field(mesh, "gas.Velocity w").unit, "m s^-1");
  EXPECT_EQ(field(mesh, "Normal X").unit, "");
  EXPECT_EQ(field(mesh, "Wall Shear Y").values, (std::vector<double>{7, 7, 7}));
  EXPECT_EQ(mesh.face_indices, (Indices{2, 1, 0}));
}

TEST(CfdPostParse, LinesBlockAddsNodesButNoFaces) {
  const std::string text = kTwoBlocks + join_lines({
                                            "[Name]",
                                            "streamline 1",
                                            "",
                                            "[Data]",
                                            "X [ m ], Y [ m ], Z [ m ], Pressure [ Pa ], Wall Shear X [ Pa ]",
                                            "5, 5, 5, 9, 0",
                                            "6, 5, 5, 9, 0",
                                            "7, 5, 5, 9, 0",
                                            "",
                                            "[Lines]",
                                            "0, 1",
                                            "1, 2",
                                            "",
                                        });
  const SurfaceMesh mesh = parse_cfdpost_export(text, "mem.csv");
  EXPECT_EQ(mesh.location_names, (Strings{"hull", "fin", "streamline 1"}));
  EXPECT_EQ(mesh.point_count(), 11u);
  EXPECT_EQ(mesh.face_count(), 3u);
  EXPECT_EQ(mesh.face_indices, (Indices{0, 1, 2, 3, 4, 5, 6, 5, 7, 6}));
  EXPECT_EQ(mesh.points_xyz[3 * 10], 7.0);
}

TEST(CfdPostParse, BlankLineVariantsAndMissingFinalNewline) {
  // No leading blank line, several blank lines (some with spaces or CR),
  // tags with blanks around them, trailing blank lines.
  std::string text = kTwoBlocks;
  text.erase(0, 1);
  text.replace(text.find("[Name]\nfin"), 6, "  [Name] \r");
  text += "\n\n   \n\r\n";
  expect_two_blocks(parse_cfdpost_export(text, "mem.csv"));

  std::string bare = kTwoBlocks;
  while (bare.back() == '\n') bare.pop_back();  // ends in "1, 3, 2"
  expect_two_blocks(parse_cfdpost_export(bare, "mem.csv"));
  expect_two_blocks(parse_cfdpost_export("\xEF\xBB\xBF" + kTwoBlocks, "mem.csv"));
}

TEST(CfdPostParse, FacesTagAtTheEndOfTheFileIsAccepted) {
  // Cut right after fin's [Faces]: fin keeps its nodes but adds no faces.
  const std::string text = kTwoBlocks.substr(0, kTwoBlocks.rfind("[Faces]") + 7);
  const SurfaceMesh mesh = parse_cfdpost_export(text, "mem.csv");
  EXPECT_EQ(mesh.point_count(), 8u);
  EXPECT_EQ(mesh.face_offsets, (Indices{0, 4}));
  EXPECT_EQ(mesh.face_location, (Indices{0}));
}

TEST(CfdPostParse, NumberFormsFromCharsDoesNotTakeAlone) {
  const std::string text = join_lines({
      "[Name]",
      "wall",
      "[Data]",
      "X [ m ], Y [ m ], Z [ m ], P [ Pa ]",
      "+1.5, -0, 1e-400, 0.25,  ",  // trailing separator and blanks are harmless
      "  1,0,0 ,  2 ",              // "," without a space, blanks around fields
      "0, 1, 0, 3",
      "[Faces]",
      "0,1,2",
  });
  const SurfaceMesh mesh = parse_cfdpost_export(text, "mem.csv");
  EXPECT_EQ(mesh.points_xyz[0], 1.5);
  EXPECT_TRUE(std::signbit(mesh.points_xyz[1]));
  EXPECT_EQ(mesh.points_xyz[2], 0.0);  // underflow reads as zero
  EXPECT_EQ(field(mesh, "P").values, (std::vector<double>{0.25, 2, 3}));
  EXPECT_EQ(mesh.points_xyz[3], 1.0);
}

TEST(CfdPostParse, RepeatedColumnsWithEqualValuesAreKeptOnce) {
  const std::string text = join_lines({
      "[Name]",
      "wall",
      "[Data]",
      "X [ m ], Y [ m ], Z [ m ], Pressure [ Pa ], X [ m ], Y [ m ], Z [ m ]",
      "0, 0, 0, 1, 0, 0, 0",
      "1, 0, 0, 2, 1, 0, 0",
      "0, 1, null, 3, 0, 1, null",
      "[Faces]",
      "0, 1, 2",
  });
  const SurfaceMesh mesh = parse_cfdpost_export(text, "mem.csv");
  EXPECT_EQ(field_names(mesh), (Strings{"Pressure"}));
  EXPECT_EQ(mesh.points_xyz[3], 1.0);
  EXPECT_TRUE(std::isnan(mesh.points_xyz[8]));
}

// ---------------------------------------------------------------------------
// Locations.

TEST(CfdPostLocations, SelectionKeepsBlocksInFileOrderWithLocalIndices) {
  const SurfaceMesh fin = parse_cfdpost_export(kTwoBlocks, "mem.csv", CfdPostOptions{{"fin"}});
  EXPECT_EQ(fin.location_names, (Strings{"fin"}));
  EXPECT_EQ(fin.points_xyz, (std::vector<double>{0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1}));
  EXPECT_EQ(fin.face_offsets, (Indices{0, 3, 6}));
  EXPECT_EQ(fin.face_indices, (Indices{0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(fin.face_location, (Indices{0, 0}));
  EXPECT_EQ(field(fin, "Pressure").values, (std::vector<double>{500, 600, 700, 800}));

  expect_two_blocks(parse_cfdpost_export(kTwoBlocks, "mem.csv", CfdPostOptions{{"fin", "hull"}}));
}

TEST(CfdPostLocations, UnknownLocationListsTheAvailableOnes) {
  const std::string message = parse_error(kTwoBlocks, CfdPostOptions{{"hull", "rudder"}});
  EXPECT_CONTAINS(message, "mem.csv: ");
  EXPECT_CONTAINS(message, "unknown location 'rudder'");
  EXPECT_CONTAINS(message, "'hull', 'fin'");
}

TEST(CfdPostLocations, BlocksWithTheSameNameShareALocation) {
  std::string text = kTwoBlocks;
  text.replace(text.find("fin"), 3, "hull");
  const SurfaceMesh mesh = parse_cfdpost_export(text, "mem.csv");
  EXPECT_EQ(mesh.location_names, (Strings{"hull"}));
  EXPECT_EQ(mesh.face_location, (Indices{0, 0, 0}));
  EXPECT_EQ(mesh.point_count(), 8u);
  EXPECT_EQ(list_cfdpost_locations(text, "mem.csv"), (Strings{"hull"}));
}

TEST(CfdPostLocations, ArrayMissingFromOneBlockIsNamed) {
  std::string text = kTwoBlocks;
  // fin without "Wall Shear X": drop the header entry and the last field of its rows.
  const auto fin = text.find("[Name]\nfin");
  std::string tail = text.substr(fin);
  tail.replace(tail.find(", Wall Shear X [ Pa ]"), 21, "");
  for (const char* shear : {", 5.50000000e+00", ", 6.50000000e+00", ", 7.50000000e+00", ", 8.50000000e+00"})
    tail.replace(tail.find(shear), 16, "");
  text = text.substr(0, fin) + tail;
  const std::string message = parse_error(text);
  EXPECT_CONTAINS(message, "mem.csv:19:1: ");
  EXPECT_CONTAINS(message, "array 'Wall Shear X'");
  EXPECT_CONTAINS(message, "block 'fin'");
  EXPECT_CONTAINS(message, "lacks it");
  // Selecting the blocks separately works.
  EXPECT_EQ(parse_cfdpost_export(text, "mem.csv", CfdPostOptions{{"fin"}}).fields.size(), 1u);
  EXPECT_EQ(parse_cfdpost_export(text, "mem.csv", CfdPostOptions{{"hull"}}).fields.size(), 2u);

  // The other way round: hull lacks an array fin has.
  std::string extra = kTwoBlocks;
  const auto header = extra.rfind("Wall Shear X [ Pa ]") + 19;
  extra.insert(header, ", Yplus");
  for (const char* row : {"5.50000000e+00", "6.50000000e+00", "7.50000000e+00", "8.50000000e+00"})
    extra.insert(extra.find(row) + 14, ", 1");
  const std::string reverse = parse_error(extra);
  EXPECT_CONTAINS(reverse, "mem.csv:19:");
  EXPECT_CONTAINS(reverse, "array 'Yplus' is in block 'fin' but block 'hull'");
}

// ---------------------------------------------------------------------------
// Errors, each with its place in the file.

const std::string kOneTriangleHeader = "X [ m ], Y [ m ], Z [ m ], Pressure [ Pa ]";

std::string one_triangle(std::string_view header, std::string_view row2, std::string_view faces = "0, 1, 2") {
  return join_lines(
      {"", "[Name]", "wall", "", "[Data]", header, "0, 0, 0, 1", row2, "0, 1, 0, 3", "", "[Faces]", faces});
}

TEST(CfdPostErrors, UnknownUnitNamesColumnAndPlace) {
  const std::string header = "X [ m ], Y [ m ], Z [ m ], Pressure [ psi ]";
  const std::string message = parse_error(one_triangle(header, "1, 0, 0, 2"));
  EXPECT_CONTAINS(message, "mem.csv:6:" + std::to_string(header.find("Pressure") + 1) + ": ");
  EXPECT_CONTAINS(message, "'Pressure [ psi ]'");
  EXPECT_CONTAINS(message, "unknown unit symbol 'psi'");
}

TEST(CfdPostErrors, CoordinateWithoutALengthUnit) {
  const std::string pa = parse_error(one_triangle("X [ m ], Y [ Pa ], Z [ m ], Pressure [ Pa ]", "1, 0, 0, 2"));
  EXPECT_CONTAINS(pa, "mem.csv:6:10: ");
  EXPECT_CONTAINS(pa, "'Y [ Pa ]'");
  EXPECT_CONTAINS(pa, "expected a length");
  const std::string bare = parse_error(one_triangle("X, Y [ m ], Z [ m ], Pressure [ Pa ]", "1, 0, 0, 2"));
  EXPECT_CONTAINS(bare, "mem.csv:6:1: ");
  EXPECT_CONTAINS(bare, "found no unit");
}

TEST(CfdPostErrors, MissingCoordinateColumnIsNamed) {
  const std::string text =
      join_lines({"[Name]", "wall", "[Data]", "X [ m ], Y [ m ], Pressure [ Pa ]", "0, 0, 1", "[Faces]", "0, 0, 0"});
  const std::string message = parse_error(text);
  EXPECT_CONTAINS(message, "mem.csv:4:1: ");
  EXPECT_CONTAINS(message, "no 'Z' column");
}

TEST(CfdPostErrors, WrongFieldCount) {
  const std::string fewer = parse_error(one_triangle(kOneTriangleHeader, "1, 0, 0"));
  EXPECT_CONTAINS(fewer, "mem.csv:8:1: ");
  EXPECT_CONTAINS(fewer, "block 'wall'");
  EXPECT_CONTAINS(fewer, "found 3 fields, expected 4");
  const std::string more = parse_error(one_triangle(kOneTriangleHeader, "1, 0, 0, 2, 5"));
  EXPECT_CONTAINS(more, "mem.csv:8:1: ");
  EXPECT_CONTAINS(more, "found 5 fields, expected 4");
  const std::string cut = parse_error(one_triangle(kOneTriangleHeader, "1, 0, "));
  EXPECT_CONTAINS(cut, "mem.csv:8:1: ");
  EXPECT_CONTAINS(cut, "found 2 fields, expected 4");
}

TEST(CfdPostErrors, TextWhereANumberIsExpected) {
  const std::string word = parse_error(one_triangle(kOneTriangleHeader, "1, 0, 0, high"));
  EXPECT_CONTAINS(word, "mem.csv:8:10: ");
  EXPECT_CONTAINS(word, "column 'Pressure [ Pa ]'");
  EXPECT_CONTAINS(word, "found 'high', expected a number or 'null'");
  const std::string suffix = parse_error(one_triangle(kOneTriangleHeader, "1.0x, 0, 0, 2"));
  EXPECT_CONTAINS(suffix, "mem.csv:8:1: ");
  EXPECT_CONTAINS(suffix, "column 'X [ m ]'");
  EXPECT_CONTAINS(suffix, "found '1.0x'");
  const std::string empty = parse_error(one_triangle(kOneTriangleHeader, "1, , 0, 2"));
  EXPECT_CONTAINS(empty, "mem.csv:8:4: ");
  EXPECT_CONTAINS(empty, "empty field");
  const std::string nul = parse_error(one_triangle(kOneTriangleHeader, "1, 0, 0, NULL"));
  EXPECT_CONTAINS(nul, "found 'NULL'");
}

TEST(CfdPostErrors, NonFiniteAndOverflowingNumbers) {
  for (const char* bad : {"inf", "nan", "-infinity"}) {
    const std::string message = parse_error(one_triangle(kOneTriangleHeader, std::string("1, 0, 0, ") + bad));
    EXPECT_CONTAINS(message, "mem.csv:8:10: ");
    EXPECT_CONTAINS(message, "expected a finite number");
  }
  const std::string huge = parse_error(one_triangle(kOneTriangleHeader, "1, 0, 0, 1e400"));
  EXPECT_CONTAINS(huge, "mem.csv:8:10: ");
  EXPECT_CONTAINS(huge, "found '1e400', expected a finite number within");
  const std::string scaled = parse_error(one_triangle("X [ m ], Y [ m ], Z [ m ], Pressure [ kPa ]", "1, 0, 0, 1e306"));
  EXPECT_CONTAINS(scaled, "mem.csv:8:10: ");
  EXPECT_CONTAINS(scaled, "overflows when converted to SI");
}

TEST(CfdPostErrors, FaceIndexOutOfRangeNamesBlockAndNodeCount) {
  const std::string message = parse_error(one_triangle(kOneTriangleHeader, "1, 0, 0, 2", "0, 1, 3"));
  EXPECT_CONTAINS(message, "mem.csv:12:7: ");
  EXPECT_CONTAINS(message, "block 'wall'");
  EXPECT_CONTAINS(message, "index 3 is out of range");
  EXPECT_CONTAINS(message, "has 3 nodes");

  // Indices are local: fin's 4 (a valid global index) is out of range in fin.
  std::string text = kTwoBlocks;
  text.replace(text.rfind("1, 3, 2"), 7, "1, 4, 2");
  const std::string local = parse_error(text);
  EXPECT_CONTAINS(local, "mem.csv:27:4: ");
  EXPECT_CONTAINS(local, "block 'fin', face 2: index 4 is out of range; the block has 4 nodes");
}

TEST(CfdPostErrors, BadFaceLines) {
  const std::string two = parse_error(one_triangle(kOneTriangleHeader, "1, 0, 0, 2", "0, 1"));
  EXPECT_CONTAINS(two, "mem.csv:12:1: ");
  EXPECT_CONTAINS(two, "found 2 node indices, expected at least 3");
  const std::string negative = parse_error(one_triangle(kOneTriangleHeader, "1, 0, 0, 2", "0, -1, 2"));
  EXPECT_CONTAINS(negative, "mem.csv:12:4: ");
  EXPECT_CONTAINS(negative, "found '-1', expected a 0-based node index");
  const std::string fraction = parse_error(one_triangle(kOneTriangleHeader, "1, 0, 0, 2", "0, 1.0, 2"));
  EXPECT_CONTAINS(fraction, "found '1.0'");
  const std::string dangling = parse_error(one_triangle(kOneTriangleHeader, "1, 0, 0, 2", "0, 1, 2,"));
  EXPECT_CONTAINS(dangling, "mem.csv:12:9: ");
  EXPECT_CONTAINS(dangling, "ends with ','");
}

TEST(CfdPostErrors, DataWithoutHeader) {
  const std::string none = parse_error(join_lines({"[Name]", "wall", "", "[Data]", "", "[Faces]", "0, 1, 2"}));
  EXPECT_CONTAINS(none, "mem.csv:4:1: ");
  EXPECT_CONTAINS(none, "'[Data]' without a header line");
  const std::string at_end = parse_error(join_lines({"[Name]", "wall", "", "[Data]"}));
  EXPECT_CONTAINS(at_end, "mem.csv:4:1: ");
  EXPECT_CONTAINS(at_end, "without a header line");
  // Include Header = Off: the first row sits where the header should be.
  const std::string numbers =
      parse_error(join_lines({"[Name]", "wall", "[Data]", "0, 0, 0, 1", "1, 0, 0, 2", "[Faces]", "0, 1, 2"}));
  EXPECT_CONTAINS(numbers, "mem.csv:4:1: ");
  EXPECT_CONTAINS(numbers, "Include Header = On");
}

TEST(CfdPostErrors, MissingDataSection) {
  const std::string header_first =
      parse_error(join_lines({"[Name]", "wall", "", kOneTriangleHeader, "0, 0, 0, 1", "[Faces]", "0, 1, 2"}));
  EXPECT_CONTAINS(header_first, "mem.csv:4:1: ");
  EXPECT_CONTAINS(header_first, "block 'wall'");
  EXPECT_CONTAINS(header_first, "expected '[Data]'");
  const std::string faces_first = parse_error(join_lines({"[Name]", "wall", "[Faces]", "0, 1, 2"}));
  EXPECT_CONTAINS(faces_first, "mem.csv:3:1: ");
  EXPECT_CONTAINS(faces_first, "found '[Faces]', expected '[Data]'");
  const std::string name_only = parse_error(join_lines({"", "[Name]", "wall", ""}));
  EXPECT_CONTAINS(name_only, "mem.csv:3: ");
  EXPECT_CONTAINS(name_only, "ends after the location name");
  const std::string no_name = parse_error("[Name]\n");
  EXPECT_CONTAINS(no_name, "mem.csv:2:1: ");
  EXPECT_CONTAINS(no_name, "expected a location name");
}

TEST(CfdPostErrors, UnexpectedLineBetweenBlocks) {
  std::string text = kTwoBlocks;
  text.replace(text.find("\n[Name]\nfin"), 1, "\nsomething else\n");
  const std::string message = parse_error(text);
  EXPECT_CONTAINS(message, "mem.csv:15:1: ");
  EXPECT_CONTAINS(message, "after block 'hull': found 'something else', expected '[Name]'");
}

TEST(CfdPostErrors, EmptyAndBlankFiles) {
  const std::string empty = parse_error("");
  EXPECT_CONTAINS(empty, "mem.csv: empty file");
  const std::string blank = parse_error("\n\r\n  \n");
  EXPECT_CONTAINS(blank, "mem.csv: only blank lines");
  EXPECT_FALSE(looks_like_cfdpost_export(""));
}

TEST(CfdPostErrors, BinaryGarbageGivesAPrintableMessage) {
  std::string garbage("PK\x03\x04\x00\xff\xfe\x1b[31m\x7f", 13);
  std::mt19937 random(7);
  for (int i = 0; i < 5000; ++i) garbage += static_cast<char>(random() & 0xff);
  EXPECT_FALSE(looks_like_cfdpost_export(garbage));
  const std::string message = parse_error(garbage);
  EXPECT_CONTAINS(message, "mem.csv:1:1: found 'PK\\x03\\x04\\x00\\xff\\xfe\\x1b[31m\\x7f");
  EXPECT_CONTAINS(message, "expected '[Name]'");
  EXPECT_LT(message.size(), 500u);
  for (const char c : message) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << "byte " << static_cast<int>(c);

  // Garbage inside a number field is escaped too.
  const std::string field = parse_error(one_triangle(kOneTriangleHeader, std::string("1, 0, 0, \x01\x80z", 12)));
  EXPECT_CONTAINS(field, "found '\\x01\\x80z'");
  for (const char c : field) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << "byte " << static_cast<int>(c);
}

TEST(CfdPostErrors, RepeatedColumnsThatDisagree) {
  const std::string values =
      parse_error(join_lines({"[Name]", "wall", "[Data]", "X [ m ], Y [ m ], Z [ m ], X [ m ]", "0, 0, 0, 0",
                              "1, 0, 0, 1.5", "0, 1, 0, 0", "[Faces]", "0, 1, 2"}));
  EXPECT_CONTAINS(values, "mem.csv:6:10: ");
  EXPECT_CONTAINS(values, "column 'X [ m ]' (column 4) differs from the first 'X' column (column 1)");
  const std::string units = parse_error(
      join_lines({"[Name]", "wall", "[Data]", "X [ m ], Y [ m ], Z [ m ], X [ mm ]", "0, 0, 0, 0", "[Faces]"}));
  EXPECT_CONTAINS(units, "mem.csv:4:28: ");
  EXPECT_CONTAINS(units, "'X [ mm ]' repeats 'X [ m ]' (column 1) with another unit");
}

TEST(CfdPostErrors, NoFacesAnywhere) {
  const std::string text = kTwoBlocks.substr(0, kTwoBlocks.find("[Faces]")) + "\n";
  const std::string message = parse_error(text);
  EXPECT_CONTAINS(message, "mem.csv: no [Faces] section in the file: export with Export Connectivity = On");
  // A selection holding only face-less blocks is refused the same way.
  std::string mixed = kTwoBlocks;
  mixed.replace(mixed.find("[Faces]\n0, 1, 2, 3\n"), 19, "");
  const std::string selected = parse_error(mixed, CfdPostOptions{{"hull"}});
  EXPECT_CONTAINS(selected, "no [Faces] section in locations 'hull'");
}

TEST(CfdPostErrors, MissingFileIsNamed) {
  const std::string message = error_of([] { (void)read_cfdpost_export("/nonexistent/wall.csv"); });
  EXPECT_CONTAINS(message, "/nonexistent/wall.csv: no such file");
  const std::string directory = error_of([] { (void)read_cfdpost_export(kSampleDir); });
  EXPECT_CONTAINS(directory, "is a directory");
}

TEST(CfdPostDetect, LooksLikeCfdPostExport) {
  EXPECT_TRUE(looks_like_cfdpost_export("\n[Name]\nwall\n"));
  EXPECT_TRUE(looks_like_cfdpost_export("\xEF\xBB\xBF\r\n  [Name] \r\nwall"));
  EXPECT_TRUE(looks_like_cfdpost_export("[Name]"));
  EXPECT_FALSE(looks_like_cfdpost_export("[Nam"));
  EXPECT_FALSE(looks_like_cfdpost_export("X [ m ], Y [ m ]\n[Name]\n"));
  EXPECT_FALSE(looks_like_cfdpost_export("[Data]\n"));
  EXPECT_FALSE(looks_like_cfdpost_export("# vtk DataFile Version 3.0\n"));
}

// ---------------------------------------------------------------------------
// Round trips through the writer.

// A quad grid (location "hull", nodes 0..ny*nx-1) and a triangle fan
// (location "fin", the following nodes): disjoint, contiguous point ranges so
// the writer's per-block numbering maps back one to one. Values are snapped to
// 9 significant digits when `snap`, so that "%.8e" writes them exactly.
SurfaceMesh make_surface(bool snap, unsigned seed = 11) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const auto snapped = [snap](double v) {
    if (!snap) return v;
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.8e", v);
    return std::strtod(buffer, nullptr);
  };
  const auto value = [&](double scale) { return snapped(scale * uniform(random)); };
  SurfaceMesh mesh;
  mesh.location_names = {"hull", "fin"};
  constexpr std::uint32_t nx = 7, ny = 5;
  for (std::uint32_t j = 0; j < ny; ++j)
    for (std::uint32_t i = 0; i < nx; ++i)
      mesh.points_xyz.insert(mesh.points_xyz.end(), {value(2.0), value(0.5), value(0.3)});
  for (std::uint32_t j = 0; j + 1 < ny; ++j)
    for (std::uint32_t i = 0; i + 1 < nx; ++i) {
      const std::uint32_t a = j * nx + i;
      mesh.face_indices.insert(mesh.face_indices.end(), {a, a + 1, a + nx + 1, a + nx});
      mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.face_indices.size()));
      mesh.face_location.push_back(0);
    }
  const std::uint32_t hub = nx * ny;
  constexpr std::uint32_t rim = 9;
  for (std::uint32_t k = 0; k <= rim; ++k)
    mesh.points_xyz.insert(mesh.points_xyz.end(), {value(0.2), value(0.2), snapped(1.0 + value(0.1))});
  for (std::uint32_t k = 1; k < rim; ++k) {
    mesh.face_indices.insert(mesh.face_indices.end(), {hub, hub + k, hub + k + 1});
    mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.face_indices.size()));
    mesh.face_location.push_back(1);
  }
  const std::size_t points = mesh.point_count();
  const auto add = [&](const std::string& name, const std::string& unit, double scale) {
    FieldArray array;
    array.name = name;
    array.unit = unit;
    for (std::size_t i = 0; i < points; ++i) array.values.push_back(value(scale));
    mesh.fields.push_back(std::move(array));
  };
  add("Pressure", kPascal, 1.0e5);
  add("Wall Shear X", kPascal, 3.0);
  add("Wall Shear Y", kPascal, 3.0);
  add("Wall Shear Z", kPascal, 3.0);
  add("Velocity", "m s^-1", 2.0);
  add("Yplus", "", 50.0);
  add("water.Volume Fraction", "", 1.0);
  mesh.fields[1].values[3] = std::numeric_limits<double>::quiet_NaN();  // a null
  return mesh;
}

TEST(CfdPostRoundTrip, SnappedValuesComeBackExactly) {
  const SurfaceMesh mesh = make_surface(true);
  const std::string text = test::write_cfdpost_export(mesh);
  EXPECT_TRUE(looks_like_cfdpost_export(text));
  EXPECT_NE(text.find("Pressure [ Pa ]"), std::string::npos);
  EXPECT_NE(text.find("null"), std::string::npos);
  expect_same_mesh(parse_cfdpost_export(text, "twin.csv"), mesh, 0.0);
}

TEST(CfdPostRoundTrip, EqualToThePrecisionWritten) {
  const SurfaceMesh mesh = make_surface(false);
  // "%.8e" keeps 9 significant digits: half a unit in the 9th is 5e-9 relative.
  expect_same_mesh(parse_cfdpost_export(test::write_cfdpost_export(mesh), "twin.csv"), mesh, 5.0e-9);
  test::CfdPostWriterOptions exact;
  exact.precision = 17;
  expect_same_mesh(parse_cfdpost_export(test::write_cfdpost_export(mesh, exact), "twin.csv"), mesh, 0.0);
}

TEST(CfdPostRoundTrip, MillimetreKilopascalTwinEqualsTheSiOne) {
  const SurfaceMesh mesh = make_surface(true);
  const SurfaceMesh si = parse_cfdpost_export(test::write_cfdpost_export(mesh), "si.csv");
  for (const unsigned seed : {1u, 2u, 3u}) {
    test::CfdPostWriterOptions options;
    options.units = test::CfdPostUnits::MillimetreKilopascal;
    options.crlf = true;
    options.separator = "\t";
    options.node_numbers = true;
    options.shuffle_columns = true;
    options.seed = seed;
    options.leading_blank_line = false;
    options.trailing_blank_lines = 3;
    const std::string text = test::write_cfdpost_export(mesh, options);
    ASSERT_NE(text.find("Pressure [ kPa ]"), std::string::npos);
    ASSERT_NE(text.find("X [ mm ]"), std::string::npos);
    ASSERT_NE(text.find("Velocity [ mm s^-1 ]"), std::string::npos);
    ASSERT_NE(text.find("Node Number\t"), std::string::npos);
    ASSERT_NE(text.find("\r\n"), std::string::npos);
    SurfaceMesh twin = parse_cfdpost_export(text, "mm.csv");
    // Shuffled columns change the array order; compare by name.
    std::vector<FieldArray> ordered;
    for (const auto& array : si.fields) ordered.push_back(field(twin, array.name));
    twin.fields = ordered;
    expect_same_mesh(twin, si, 1e-12);
  }
}

TEST(CfdPostRoundTrip, ThreeComponentArraysComeBackAsScalars) {
  SurfaceMesh mesh = make_surface(true);
  FieldArray normal;
  normal.name = "Normal";
  normal.components = 3;
  normal.unit = "";
  for (std::size_t i = 0; i < mesh.point_count(); ++i) normal.values.insert(normal.values.end(), {1.0, 0.5, -0.25});
  mesh.fields.push_back(normal);
  const SurfaceMesh read = parse_cfdpost_export(test::write_cfdpost_export(mesh), "twin.csv");
  EXPECT_EQ(field(read, "Normal Y").values, std::vector<double>(mesh.point_count(), 0.5));
  EXPECT_EQ(field(read, "Normal Z").unit, "");
}

TEST(CfdPostRoundTrip, SelectionFromAWrittenFileAndReadFromDisk) {
  const SurfaceMesh mesh = make_surface(true);
  test::TempDir dir;
  const fs::path path = dir / "wall export.csv";
  {
    std::ofstream out(path, std::ios::binary);
    out << test::write_cfdpost_export(mesh, test::CfdPostWriterOptions{.crlf = true});
  }
  expect_same_mesh(read_cfdpost_export(path), mesh, 0.0);
  EXPECT_EQ(list_cfdpost_locations(slurp(path), path.string()), (Strings{"hull", "fin"}));

  const SurfaceMesh fin = read_cfdpost_export(path, CfdPostOptions{{"fin"}});
  EXPECT_EQ(fin.location_names, (Strings{"fin"}));
  EXPECT_EQ(fin.point_count(), 10u);
  EXPECT_EQ(fin.face_count(), 8u);
  EXPECT_EQ(fin.face_indices[0], 0u);  // the hub, first node of its block
  const std::size_t hub = 35;          // 7 x 5 hull nodes come first in the full mesh
  for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(fin.points_xyz[c], mesh.points_xyz[3 * hub + c]);
  EXPECT_EQ(field(fin, "Pressure").values.front(), field(mesh, "Pressure").values[hub]);

  const std::string message = error_of([&] { (void)read_cfdpost_export(path, CfdPostOptions{{"rudder"}}); });
  EXPECT_CONTAINS(message, path.string() + ": unknown location 'rudder'; the file has 'hull', 'fin'");
}

TEST(CfdPostRoundTrip, WriterWithoutFacesGivesTheConnectivityError) {
  test::CfdPostWriterOptions options;
  options.faces = false;
  const std::string message = parse_error(test::write_cfdpost_export(make_surface(true), options));
  EXPECT_CONTAINS(message, "no [Faces] section");
}

}  // namespace
}  // namespace hydrocoef
