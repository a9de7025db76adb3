// The .mat export read back with libmatio: variables, classes, sizes, values
// (first axis fastest), the info JSON; the Simulink script's settings; and
// refusals that write nothing.
#include <gtest/gtest.h>
#include <matio.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "src/export/mat_export.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

GridTable table_3d(Interpolation method, Extrapolation policy) {
  std::vector<GridAxis> axes = {
      {"u", {-1.0, 0.0, 0.5, 2.0}, policy}, {"v", {-0.4, 0.0, 0.4}, policy}, {"r", {-0.2, 0.2}, policy}};
  std::vector<double> values;
  for (std::size_t l = 0; l < 2; ++l)
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t i = 0; i < 4; ++i) {
        values.push_back(100.0 * static_cast<double>(l) + 10.0 * static_cast<double>(j) + static_cast<double>(i));
        values.push_back(-0.5 * static_cast<double>(i * j) + 0.25);
      }
  return GridTable(std::move(axes), {"Y", "N"}, std::move(values), method);
}

struct MatReader {
  explicit MatReader(const std::filesystem::path& path) : mat(Mat_Open(path.c_str(), MAT_ACC_RDONLY)) {}
  ~MatReader() {
    if (mat) Mat_Close(mat);
  }
  mat_t* mat;
};

TEST(MatExport, ReadsBackWithMatioInSimulinkLayout) {
  const GridTable table = table_3d(Interpolation::Linear, Extrapolation::Clamp);
  ExportMetadata metadata = metadata_for_table(table, "rov:uvr");
  metadata.run_ids = {7, 8};
  test::TempDir dir;
  const auto files = export_table(table, metadata, ExportFormat::Mat, dir / "rov-uvr.mat");
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[1], dir / "rov_uvr_simulink.m");

  MatReader reader(dir / "rov-uvr.mat");
  ASSERT_NE(reader.mat, nullptr);
  EXPECT_EQ(Mat_GetVersion(reader.mat), MAT_FT_MAT5);
  for (std::size_t a = 0; a < 3; ++a) {
    matvar_t* bp = Mat_VarRead(reader.mat, ("bp" + std::to_string(a + 1)).c_str());
    ASSERT_NE(bp, nullptr);
    EXPECT_EQ(bp->class_type, MAT_C_DOUBLE);
    ASSERT_EQ(bp->rank, 2);
    EXPECT_EQ(bp->dims[0], table.axes()[a].breakpoints.size());
    EXPECT_EQ(bp->dims[1], 1u);
    const auto* x = static_cast<const double*>(bp->data);
    for (std::size_t i = 0; i < bp->dims[0]; ++i) EXPECT_EQ(x[i], table.axes()[a].breakpoints[i]);
    Mat_VarFree(bp);
  }
  const char* names[] = {"table_Y", "table_N"};
  for (std::size_t k = 0; k < 2; ++k) {
    matvar_t* t = Mat_VarRead(reader.mat, names[k]);
    ASSERT_NE(t, nullptr) << names[k];
    ASSERT_EQ(t->rank, 3);
    EXPECT_EQ(t->dims[0], 4u);
    EXPECT_EQ(t->dims[1], 3u);
    EXPECT_EQ(t->dims[2], 2u);
    const auto* v = static_cast<const double*>(t->data);
    // MATLAB's T(i, j, l) is element i + 4 j + 12 l (column-major).
    for (std::size_t l = 0; l < 2; ++l)
      for (std::size_t j = 0; j < 3; ++j)
        for (std::size_t i = 0; i < 4; ++i) {
          const double expected =
              k == 0 ? 100.0 * static_cast<double>(l) + 10.0 * static_cast<double>(j) + static_cast<double>(i)
                     : -0.5 * static_cast<double>(i * j) + 0.25;
          EXPECT_EQ(v[i + 4 * j + 12 * l], expected);
        }
    Mat_VarFree(t);
  }
  matvar_t* info = Mat_VarRead(reader.mat, "info");
  ASSERT_NE(info, nullptr);
  EXPECT_EQ(info->class_type, MAT_C_CHAR);
  const std::string text(static_cast<const char*>(info->data), info->dims[1]);
  Mat_VarFree(info);
  const auto json = nlohmann::json::parse(text);
  EXPECT_EQ(json.at("axes")[2].at("name"), "r");
  EXPECT_EQ(json.at("axes")[2].at("unit"), "rad/s");
  EXPECT_EQ(json.at("outputs")[1].at("unit"), "N m");
  EXPECT_EQ(json.at("provenance").at("runs"), nlohmann::json({7, 8}));
  EXPECT_EQ(json.at("provenance").at("content_sha256"), metadata.content_sha256);

  const std::string script = test::read_text(files[1]);
  EXPECT_EQ(script.rfind("function rov_uvr_simulink(block, output)", 0), 0u);
  for (const std::string piece :
       {"'NumberOfTableDimensions', '3'", "BreakpointsForDimension3', mat2str(data.bp3, 17)", "'Linear point-slope'",
        "'ExtrapMethod', 'Clip'", "'DiagnosticForOutOfRangeInput', 'None'", "load(fullfile(", "rov-uvr.mat"})
    EXPECT_NE(script.find(piece), std::string::npos) << piece;
}

TEST(MatExport, OneDimensionalTablesAreColumnsAndPoliciesMapToTheBlock) {
  const GridTable table({{"u", {0.0, 1.0, 2.0}, Extrapolation::Error}}, {"X"}, {0.0, -1.0, -4.0},
                        Interpolation::Nearest);
  test::TempDir dir;
  const auto files = export_table(table, metadata_for_table(table, "x"), ExportFormat::Mat, dir / "x.mat");
  MatReader reader(dir / "x.mat");
  matvar_t* t = Mat_VarRead(reader.mat, "table_X");
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->rank, 2);
  EXPECT_EQ(t->dims[0], 3u);
  EXPECT_EQ(t->dims[1], 1u);
  Mat_VarFree(t);
  const std::string script = test::read_text(files[1]);
  EXPECT_NE(script.find("'InterpMethod', 'Nearest'"), std::string::npos);
  EXPECT_NE(script.find("'DiagnosticForOutOfRangeInput', 'Error'"), std::string::npos);

  const GridTable linear = table_3d(Interpolation::Linear, Extrapolation::Method);
  const auto more = export_table(linear, metadata_for_table(linear, "y"), ExportFormat::Mat, dir / "y.mat");
  EXPECT_NE(test::read_text(more[1]).find("'ExtrapMethod', 'Linear'"), std::string::npos);
}

TEST(MatExport, RefusesWhatTheBlockCannotReproduceAndWritesNothing) {
  test::TempDir dir;
  const GridTable cubic({{"u", {0.0, 1.0, 2.0}, Extrapolation::Clamp}}, {"X"}, {0.0, -1.0, -4.0}, Interpolation::Pchip);
  test::expect_input_error(
      [&] { export_table(cubic, metadata_for_table(cubic, "c"), ExportFormat::Mat, dir / "c.mat"); },
      {"format mat", "pchip", "expected a nearest or linear surface"});
  std::vector<GridAxis> axes = {{"u", {0.0, 1.0}, Extrapolation::Clamp}, {"v", {0.0, 1.0}, Extrapolation::Linear}};
  const GridTable mixed(axes, {"X"}, {1.0, 2.0, 3.0, 4.0}, Interpolation::Linear);
  test::expect_input_error(
      [&] { export_table(mixed, metadata_for_table(mixed, "m"), ExportFormat::Mat, dir / "m.mat"); },
      {"axis 'v'", "one extrapolation for all axes"});
  test::expect_input_error(
      [&] { export_table(cubic, metadata_for_table(cubic, "m"), ExportFormat::Csv, dir / "missing" / "m.csv"); },
      {"/missing' does not exist"});
  const GridTable fine = table_3d(Interpolation::Linear, Extrapolation::Clamp);
  test::expect_input_error(
      [&] { export_table(fine, metadata_for_table(fine, "m"), ExportFormat::Mat, dir / "missing" / "m.mat"); },
      {"/missing' does not exist"});
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace hydrocoef
