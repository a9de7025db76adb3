// DAVE-ML export read back: well-formed XML (VTK's expat-based parser, and
// libxml2's xmllint --noout), the DAVE-ML 2.0 structure (one variableDef per
// axis and output, breakpointDef with the breakpoints, griddedTableDef with
// the values and the node standard deviations as normalPDF bounds, in
// DAVE-ML's order: the last breakpoint fastest), and refusals. Not validated
// against the official DTD: no redistributable copy is available (README).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "src/export/daveml_export.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/xml_numbers.hpp"

namespace hydrocoef {
namespace {

using test::numbers_in;

GridTable table_3x2(Interpolation method = Interpolation::Linear) {
  std::vector<GridAxis> axes = {{"u", {0.0, 0.5, 1.5}, Extrapolation::Clamp},
                                {"r", {-0.2, 0.4}, Extrapolation::Linear}};
  std::vector<double> values;
  for (double r : axes[1].breakpoints)
    for (double u : axes[0].breakpoints) {
      values.push_back(-4.0 * u * std::abs(u) + r);  // X
      values.push_back(-0.3 * r + 0.01 * u);         // N
    }
  return GridTable(std::move(axes), {"X", "N"}, std::move(values), method);
}

std::vector<vtkXMLDataElement*> children(vtkXMLDataElement* root, const std::string& name) {
  std::vector<vtkXMLDataElement*> out;
  for (int i = 0; i < root->GetNumberOfNestedElements(); ++i)
    if (name == root->GetNestedElement(i)->GetName()) out.push_back(root->GetNestedElement(i));
  return out;
}

TEST(DavemlExport, HoldsBreakpointsValuesAndStandardDeviationsLastAxisFastest) {
  const GridTable table = table_3x2();
  ExportMetadata metadata = metadata_for_table(table, "asr-v:ur");
  metadata.body = "asr-v";
  metadata.run_ids = {3, 4};
  metadata.created_at = "2026-11-26T10:00:00Z";
  for (std::size_t i = 0; i < table.values().size(); ++i)
    metadata.standard_deviation.push_back(0.001 * static_cast<double>(i + 1));
  test::TempDir dir;
  export_table(table, metadata, ExportFormat::Daveml, dir / "t.dml");
  const auto root = test::read_xml(dir / "t.dml");
  ASSERT_TRUE(root) << test::read_text(dir / "t.dml");
  EXPECT_STREQ(root->GetName(), "DAVEfunc");
  ASSERT_EQ(children(root, "fileHeader").size(), 1u);
  vtkXMLDataElement* header = children(root, "fileHeader")[0];
  EXPECT_EQ(children(header, "provenance").size(), 1u);
  ASSERT_EQ(children(header, "fileCreationDate").size(), 1u);
  EXPECT_STREQ(children(header, "fileCreationDate")[0]->GetAttribute("date"), "2026-11-26");
  const auto variables = children(root, "variableDef");
  ASSERT_EQ(variables.size(), 4u);
  EXPECT_STREQ(variables[0]->GetAttribute("units"), "m/s");
  EXPECT_STREQ(variables[3]->GetAttribute("name"), "N");
  EXPECT_STREQ(variables[3]->GetAttribute("units"), "N m");
  const auto breakpoints = children(root, "breakpointDef");
  ASSERT_EQ(breakpoints.size(), 2u);
  EXPECT_EQ(numbers_in(breakpoints[0]->FindNestedElementWithName("bpVals")), table.axes()[0].breakpoints);
  EXPECT_EQ(numbers_in(breakpoints[1]->FindNestedElementWithName("bpVals")), table.axes()[1].breakpoints);
  const auto tables = children(root, "griddedTableDef");
  ASSERT_EQ(tables.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    // DAVE-ML's order: u (first breakpointRef) slowest, r fastest.
    std::vector<double> values, sd;
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 2; ++j) {
        values.push_back(table.values()[(j * 3 + i) * 2 + k]);
        sd.push_back(metadata.standard_deviation[(j * 3 + i) * 2 + k]);
      }
    EXPECT_EQ(numbers_in(children(tables[k], "dataTable").at(0)), values) << k;
    vtkXMLDataElement* pdf = children(tables[k], "uncertainty").at(0)->FindNestedElementWithName("normalPDF");
    ASSERT_TRUE(pdf);
    EXPECT_STREQ(pdf->GetAttribute("numSigmas"), "1");
    EXPECT_EQ(numbers_in(pdf->FindNestedElementWithName("bounds")->FindNestedElementWithName("dataTable")), sd);
  }
  const auto functions = children(root, "function");
  ASSERT_EQ(functions.size(), 2u);
  const auto inputs = children(functions[1], "independentVarRef");
  ASSERT_EQ(inputs.size(), 2u);
  EXPECT_STREQ(inputs[0]->GetAttribute("extrapolate"), "neither");  // clamp
  EXPECT_STREQ(inputs[1]->GetAttribute("extrapolate"), "both");     // linear
  EXPECT_STREQ(inputs[1]->GetAttribute("min"), "-0.2");
  EXPECT_STREQ(children(functions[1], "dependentVarRef").at(0)->GetAttribute("varID"),
               variables[3]->GetAttribute("varID"));
  EXPECT_STREQ(functions[1]
                   ->FindNestedElementWithName("functionDefn")
                   ->FindNestedElementWithName("griddedTableRef")
                   ->GetAttribute("gtID"),
               tables[1]->GetAttribute("gtID"));
  // Without standard deviations: no uncertainty element.
  metadata.standard_deviation.clear();
  export_table(table, metadata, ExportFormat::Daveml, dir / "plain.dml");
  EXPECT_EQ(test::read_text(dir / "plain.dml").find("<uncertainty"), std::string::npos);
  // libxml2 finds it well-formed too (no DTD validation: see the file comment).
  if (std::filesystem::exists("/usr/bin/xmllint")) {
    const std::string command = "/usr/bin/xmllint --noout --nonet '" + (dir / "t.dml").string() + "' 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0);
  }
}

TEST(DavemlExport, RefusesWhatDavemlCannotInterpolateAndWritesNothing) {
  const GridTable table = table_3x2(Interpolation::Nearest);
  test::TempDir dir;
  test::expect_input_error(
      [&] { export_table(table, metadata_for_table(table, "s"), ExportFormat::Daveml, dir / "t.dml"); },
      {"format daveml", "nearest", "linear"});
  EXPECT_FALSE(std::filesystem::exists(dir / "t.dml"));
}

}  // namespace
}  // namespace hydrocoef
