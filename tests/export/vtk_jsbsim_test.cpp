// VTK and JSBSim exports read back by independent parsers: VTK's own
// rectilinear-grid readers (XML and legacy) and VTK's XML parser for the
// JSBSim tables, whose numbers are rebuilt into a linear, clamped table that
// must evaluate as the original in and out of range.
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkRectilinearGrid.h>
#include <vtkRectilinearGridReader.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLRectilinearGridReader.h>
#include <vtkXMLUtilities.h>

#include <random>
#include <sstream>

#include "src/export/jsbsim_export.hpp"
#include "src/export/vtk_export.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

GridTable table_of(std::size_t axes_count, Interpolation method, Extrapolation policy) {
  const std::vector<std::vector<double>> breakpoints = {
      {-1.0, 0.0, 0.5, 2.0}, {-0.4, 0.0, 0.4}, {-0.2, 0.1, 0.2}, {0.0, 1.0}};
  std::vector<GridAxis> axes;
  const char* names[] = {"u", "v", "r", "current_v"};
  std::size_t nodes = 1;
  for (std::size_t a = 0; a < axes_count; ++a) {
    axes.push_back({names[a], breakpoints[a], policy});
    nodes *= breakpoints[a].size();
  }
  std::vector<double> values;
  for (std::size_t node = 0; node < nodes; ++node) {
    values.push_back(1.5 * static_cast<double>(node) - 7.25);
    values.push_back(std::sin(static_cast<double>(node)));
  }
  return GridTable(std::move(axes), {"X", "N"}, std::move(values), method);
}

void expect_grid_matches(vtkRectilinearGrid* grid, const GridTable& table) {
  ASSERT_NE(grid, nullptr);
  int dims[3];
  grid->GetDimensions(dims);
  vtkDataArray* coordinates[3] = {grid->GetXCoordinates(), grid->GetYCoordinates(), grid->GetZCoordinates()};
  for (std::size_t a = 0; a < 3; ++a) {
    const std::size_t expected = a < table.axis_count() ? table.axes()[a].breakpoints.size() : 1;
    EXPECT_EQ(static_cast<std::size_t>(dims[a]), expected);
    for (std::size_t i = 0; i < expected; ++i)
      EXPECT_EQ(coordinates[a]->GetComponent(static_cast<vtkIdType>(i), 0),
                a < table.axis_count() ? table.axes()[a].breakpoints[i] : 0.0);
  }
  for (std::size_t k = 0; k < table.output_count(); ++k) {
    vtkDataArray* array = grid->GetPointData()->GetArray(table.outputs()[k].c_str());
    ASSERT_NE(array, nullptr) << table.outputs()[k];
    ASSERT_EQ(static_cast<std::size_t>(array->GetNumberOfTuples()), table.node_count());
    for (std::size_t node = 0; node < table.node_count(); ++node)
      EXPECT_EQ(array->GetComponent(static_cast<vtkIdType>(node), 0), table.values()[node * 2 + k]);
  }
  auto* units = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("output_units"));
  ASSERT_NE(units, nullptr);
  EXPECT_EQ(units->GetValue(1), "N m");
  auto* names = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("axis_names"));
  ASSERT_NE(names, nullptr);
  EXPECT_EQ(names->GetValue(0), "u");
  EXPECT_NE(grid->GetFieldData()->GetAbstractArray("hydrocoef_info"), nullptr);
}

TEST(VtkExport, XmlAndLegacyFilesReadBackThroughVtkWithTheSameValues) {
  for (std::size_t n : {1u, 2u, 3u}) {
    const GridTable table = table_of(n, Interpolation::Pchip, Extrapolation::Clamp);
    test::TempDir dir;
    export_table(table, metadata_for_table(table, "s"), ExportFormat::Vtk, dir / "s.vtr");
    vtkNew<vtkXMLRectilinearGridReader> xml;
    xml->SetFileName((dir / "s.vtr").c_str());
    xml->Update();
    expect_grid_matches(xml->GetOutput(), table);

    export_table(table, metadata_for_table(table, "s"), ExportFormat::Vtk, dir / "s.vtk");
    vtkNew<vtkRectilinearGridReader> legacy;
    legacy->SetFileName((dir / "s.vtk").c_str());
    legacy->Update();
    expect_grid_matches(legacy->GetOutput(), table);
  }
}

TEST(VtkExport, RefusesFourAxesAndWritesNothing) {
  const GridTable table = table_of(4, Interpolation::Linear, Extrapolation::Clamp);
  test::TempDir dir;
  test::expect_input_error(
      [&] { export_table(table, metadata_for_table(table, "s4"), ExportFormat::Vtk, dir / "s4.vtr"); },
      {"format vtk", "4 axes (u, v, r, current_v)", "at most 3"});
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

std::vector<double> numbers(const std::string& text) {
  std::vector<double> out;
  std::istringstream in(text);
  double value;
  while (in >> value) out.push_back(value);
  return out;
}

// Parses one <function>'s <table> back into (breakpoints per axis, values).
GridTable table_from_jsbsim(vtkXMLDataElement* function, const std::vector<std::string>& axis_names) {
  vtkXMLDataElement* xml_table = function->FindNestedElementWithName("table");
  EXPECT_NE(xml_table, nullptr);
  std::vector<std::string> lookups;
  std::vector<vtkXMLDataElement*> blocks;
  for (int i = 0; i < xml_table->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* element = xml_table->GetNestedElement(i);
    if (std::string(element->GetName()) == "independentVar") {
      lookups.push_back(element->GetAttribute("lookup"));
      EXPECT_EQ(std::string(element->GetCharacterData()), "hydrocoef/" + axis_names[lookups.size() - 1]);
    } else if (std::string(element->GetName()) == "tableData") {
      blocks.push_back(element);
    }
  }
  const std::size_t n = lookups.size();
  std::vector<std::vector<double>> x(n);
  std::vector<std::vector<std::vector<double>>> rows_per_block;
  for (vtkXMLDataElement* block : blocks) {
    if (n == 3) x[2].push_back(std::stod(block->GetAttribute("breakPoint")));
    std::istringstream lines(block->GetCharacterData());
    std::string line;
    std::vector<std::vector<double>> rows;
    while (std::getline(lines, line)) {
      auto row = numbers(line);
      if (!row.empty()) rows.push_back(row);
    }
    rows_per_block.push_back(rows);
  }
  const auto& first = rows_per_block.front();
  const std::size_t header = n >= 2 ? 1 : 0;
  if (n >= 2) x[1] = first.front();
  for (std::size_t i = header; i < first.size(); ++i) x[0].push_back(first[i].front());
  const std::size_t n1 = n >= 2 ? x[1].size() : 1;
  std::vector<double> values(x[0].size() * n1 * rows_per_block.size());
  for (std::size_t l = 0; l < rows_per_block.size(); ++l)
    for (std::size_t i = 0; i < x[0].size(); ++i)
      for (std::size_t j = 0; j < n1; ++j)
        values[(l * n1 + j) * x[0].size() + i] = rows_per_block[l][header + i][1 + j];
  std::vector<GridAxis> axes;
  for (std::size_t a = 0; a < n; ++a) axes.push_back({axis_names[a], x[a], Extrapolation::Clamp});
  return GridTable(std::move(axes), {"out"}, std::move(values), Interpolation::Linear);
}

TEST(JsbsimExport, XmlParsesAndTheTablesEvaluateAsTheOriginal) {
  for (std::size_t n : {1u, 2u, 3u}) {
    const GridTable table = table_of(n, Interpolation::Linear, n == 2 ? Extrapolation::Error : Extrapolation::Clamp);
    test::TempDir dir;
    ExportMetadata metadata = metadata_for_table(table, "rov:tab");
    export_table(table, metadata, ExportFormat::Jsbsim, dir / "t.xml");
    vtkSmartPointer<vtkXMLDataElement> root;
    root.TakeReference(vtkXMLUtilities::ReadElementFromFile((dir / "t.xml").c_str()));
    ASSERT_NE(root, nullptr);
    EXPECT_EQ(std::string(root->GetName()), "hydrocoef_tables");
    EXPECT_EQ(std::string(root->GetAttribute("sha256")), metadata.content_sha256);
    ASSERT_EQ(root->GetNumberOfNestedElements(), 2);
    std::vector<std::string> names;
    for (std::size_t a = 0; a < n; ++a) names.push_back(table.axes()[a].name);
    for (std::size_t k = 0; k < 2; ++k) {
      vtkXMLDataElement* function = root->GetNestedElement(static_cast<int>(k));
      EXPECT_EQ(std::string(function->GetAttribute("name")), "hydrocoef/rov:tab/" + table.outputs()[k]);
      const std::string description = function->FindNestedElementWithName("description")->GetCharacterData();
      EXPECT_NE(description.find(k == 0 ? "X [N]" : "N [N m]"), std::string::npos);
      EXPECT_NE(description.find("u [m/s] valid in [-1, 2]"), std::string::npos);
      const GridTable back = table_from_jsbsim(function, names);
      std::mt19937_64 random(3);
      std::vector<double> point(n), expected(2), got(1);
      for (int i = 0; i < 500; ++i) {
        for (std::size_t a = 0; a < n; ++a) {
          const auto& x = table.axes()[a].breakpoints;
          point[a] = std::uniform_real_distribution<double>(x.front(), x.back())(random);
        }
        table.evaluate(point, expected);
        back.evaluate(point, got);
        EXPECT_NEAR(got[0], expected[k], 1e-12 * std::max(1.0, std::abs(expected[k])));
      }
    }
  }
}

TEST(JsbsimExport, RefusesWhatJsbsimCannotExpress) {
  const GridTable cubic = table_of(2, Interpolation::Pchip, Extrapolation::Clamp);
  test::expect_input_error([&] { jsbsim_text(cubic, metadata_for_table(cubic, "c")); },
                           {"format jsbsim", "pchip", "expected a linear surface"});
  const GridTable extrapolating = table_of(2, Interpolation::Linear, Extrapolation::Linear);
  test::expect_input_error([&] { jsbsim_text(extrapolating, metadata_for_table(extrapolating, "e")); },
                           {"axis 'u'", "expected clamp or error"});
  const GridTable four = table_of(4, Interpolation::Linear, Extrapolation::Clamp);
  test::expect_input_error([&] { jsbsim_text(four, metadata_for_table(four, "f")); }, {"4 axes", "at most 3"});
}

}  // namespace
}  // namespace hydrocoef
