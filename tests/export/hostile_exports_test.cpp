// Every export format written with every name of the hostile corpus
// (tests/data/hostile/names.txt) as the surface, body, axis, output and unit
// names, and read back by a real consumer, which proves the output inert:
//   csv, csv-wide  exactly the expected rows and columns (an RFC 4180 reader);
//   json           parses, with the name back;
//   c              compiles under -std=c99 -Wall -Wextra -Werror -pedantic, and
//                  defines exactly the expected macros and symbols;
//   jsbsim         well-formed XML (VTK's expat-based parser);
//   daveml         well-formed XML with the same elements for every name;
//   mat            the Simulink script has no statement that a plain name's
//                  script does not have (a small MATLAB lexer below).
// No file is named after a name: the files are the ones asked for.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "src/core/escape.hpp"
#include "src/export/export.hpp"
#include "src/surface/grid_table.hpp"
#include "tests/support/csv_record.hpp"
#include "tests/support/hostile_names.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/xml_numbers.hpp"

namespace hydrocoef {
namespace {

using test::TempDir;

GridTable table_named(const std::string& name) {
  std::vector<GridAxis> axes = {{name, {-1.0, 0.0, 2.0}, Extrapolation::Clamp},
                                {name == "r" ? "q" : "r", {0.0, 0.5}, Extrapolation::Clamp}};
  std::vector<double> values;
  for (double r : axes[1].breakpoints)
    for (double u : axes[0].breakpoints) {
      values.push_back(-3.0 * u * std::abs(u) + r);
      values.push_back(0.25 * r);
    }
  return GridTable(std::move(axes), {name, name == "N" ? "K" : "N"}, std::move(values), Interpolation::Linear);
}

ExportMetadata metadata_named(const GridTable& table, const std::string& name) {
  ExportMetadata metadata = metadata_for_table(table, name);
  metadata.body = name;
  metadata.axis_units = {name, "rad/s"};
  metadata.output_units = {name, "N m"};
  metadata.run_ids = {1, 2};
  metadata.created_at = "2026-11-25T00:00:00Z";
  return metadata;
}

std::vector<std::string> lines_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::set<std::string> files_in(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.insert(entry.path().filename().string());
  return names;
}

TEST(HostileNames, CsvHasExactlyTheExpectedRowsAndColumns) {
  TempDir dir;
  for (const auto& name : test::hostile_names()) {
    SCOPED_TRACE(testing::PrintToString(name));
    const GridTable table = table_named(name);
    const ExportMetadata metadata = metadata_named(table, name);
    for (const ExportFormat format : {ExportFormat::Csv, ExportFormat::CsvWide}) {
      const auto path = dir / "table.csv";
      export_table(table, metadata, format, path);
      std::vector<std::vector<std::string>> rows;
      for (const auto& line : lines_of(path)) {
        if (!line.empty() && line[0] == '#') continue;
        const auto record = test::csv_record(line);
        ASSERT_TRUE(record) << line;
        rows.push_back(*record);
      }
      // No text cell a spreadsheet would evaluate; every number cell a plain number
      // (the axis starts at -1, and most values are negative).
      for (const auto& row : rows)
        for (const auto& cell : row) EXPECT_FALSE(test::formula_cell(cell) && !test::number_cell(cell)) << cell;
      std::size_t negative = 0;
      if (format == ExportFormat::Csv) {
        ASSERT_EQ(rows.size(), 1 + table.node_count());
        for (const auto& row : rows) EXPECT_EQ(row.size(), 4u);
        EXPECT_EQ(escape::csv_text_value(rows[0][0]), escape::one_line(name + " [" + name + "]"));
        for (std::size_t i = 1; i < rows.size(); ++i)
          for (const auto& cell : rows[i]) {
            EXPECT_TRUE(test::number_cell(cell)) << cell;
            negative += cell.front() == '-';
          }
      } else {
        ASSERT_EQ(rows.size(), 1 + 2 * 3u);
        for (const auto& row : rows) EXPECT_EQ(row.size(), 4u);
        EXPECT_EQ(escape::csv_text_value(rows[1][0]), escape::one_line(name));
        for (std::size_t j = 2; j < rows[0].size(); ++j) EXPECT_TRUE(test::number_cell(rows[0][j])) << rows[0][j];
        for (std::size_t i = 1; i < rows.size(); ++i)
          for (std::size_t j = 1; j < rows[i].size(); ++j) {
            EXPECT_TRUE(test::number_cell(rows[i][j])) << rows[i][j];
            negative += rows[i][j].front() == '-';
          }
      }
      EXPECT_GT(negative, 0u);
    }
  }
  EXPECT_EQ(files_in(dir.path()), std::set<std::string>{"table.csv"});
}

TEST(HostileNames, JsonParsesWithTheNameBack) {
  TempDir dir;
  for (const auto& name : test::hostile_names()) {
    SCOPED_TRACE(testing::PrintToString(name));
    const GridTable table = table_named(name);
    export_table(table, metadata_named(table, name), ExportFormat::Json, dir / "table.json");
    const auto document = nlohmann::json::parse(test::read_text(dir / "table.json"));
    const std::string surface = document.at("surface").get<std::string>();
    EXPECT_TRUE(surface == name || surface.find("\xEF\xBF\xBD") != std::string::npos);
  }
}

TEST(HostileNames, JsbsimXmlIsWellFormed) {
  TempDir dir;
  for (const auto& name : test::hostile_names()) {
    SCOPED_TRACE(testing::PrintToString(name));
    const GridTable table = table_named(name);
    export_table(table, metadata_named(table, name), ExportFormat::Jsbsim, dir / "table.xml");
    const auto root = test::read_xml(dir / "table.xml");
    ASSERT_TRUE(root) << test::read_text(dir / "table.xml");
    EXPECT_STREQ(root->GetName(), "hydrocoef_tables");
    EXPECT_EQ(root->GetNumberOfNestedElements(), 2);
  }
}

// DAVE-ML: names only in attributes and descriptions (the IDs are
// hydrocoef's own), so every name leaves the same elements.
TEST(HostileNames, DavemlXmlIsWellFormed) {
  TempDir dir;
  for (const auto& name : test::hostile_names()) {
    SCOPED_TRACE(testing::PrintToString(name));
    const GridTable table = table_named(name);
    ExportMetadata metadata = metadata_named(table, name);
    metadata.standard_deviation.assign(table.values().size(), 0.5);
    export_table(table, metadata, ExportFormat::Daveml, dir / "table.dml");
    const auto root = test::read_xml(dir / "table.dml");
    ASSERT_TRUE(root) << test::read_text(dir / "table.dml");
    EXPECT_STREQ(root->GetName(), "DAVEfunc");
    // fileHeader, 2 + 2 variableDef, 2 breakpointDef, 2 griddedTableDef, 2 function.
    EXPECT_EQ(root->GetNumberOfNestedElements(), 11);
  }
}

// The report's HTML escape (src/report uses escape::html_text for every
// name): a name inside an element and an attribute leaves one element whose
// text and attribute are the name's printable form.
TEST(HostileNames, HtmlTextStaysInsideItsElement) {
  for (const auto& name : test::hostile_names()) {
    SCOPED_TRACE(testing::PrintToString(name));
    const std::string html = "<p title=\"" + escape::html_text(name) + "\">" + escape::html_text(name) + "</p>";
    const auto element = vtkSmartPointer<vtkXMLDataElement>::Take(vtkXMLUtilities::ReadElementFromString(html.c_str()));
    ASSERT_TRUE(element) << html;
    EXPECT_STREQ(element->GetName(), "p");
    EXPECT_EQ(element->GetNumberOfNestedElements(), 0);
    EXPECT_EQ(element->GetNumberOfAttributes(), 1);
  }
}

// The C headers of every name, included together in one translation unit
// (prefixes t0, t1, ...), compiled pedantically with warnings as errors; the
// macros and symbols it defines are exactly the expected ones.
TEST(HostileNames, CHeadersCompileAndDefineOnlyTheirOwnNames) {
  if (!std::filesystem::exists(HYDROCOEF_C_COMPILER)) GTEST_SKIP() << "no C compiler";
  TempDir dir;
  const auto names = test::hostile_names();
  std::string driver = "#include <stdio.h>\n";
  std::string calls;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const GridTable table = table_named(names[i]);
    ExportOptions options;
    options.c_identifier = "t" + std::to_string(i);
    const std::string header = "t" + std::to_string(i) + ".h";
    export_table(table, metadata_named(table, names[i]), ExportFormat::CHeader, dir / header, options);
    driver += "#include \"" + header + "\"\n";
    const std::string t = "t" + std::to_string(i);
    calls += "  {\n    " + t + "_real x[2] = {0.5, 0.25};\n    " + t + "_real y[2];\n    if (" + t +
             "_eval(x, y) != 0) return 1;\n    printf(\"%.17g\\n\", (double)y[0]);\n  }\n";
  }
  driver += "int main(void)\n{\n" + calls + "  return 0;\n}\n";
  {
    std::ofstream(dir / "driver.c") << driver;
    std::ofstream(dir / "empty.c") << "";
  }
  const std::string cc = std::string(HYDROCOEF_C_COMPILER) + " -std=c99 -Wall -Wextra -Werror -pedantic";
  const std::string in_dir = "cd " + test::shell_quote(dir.path().string()) + " && ";
  ASSERT_EQ(std::system((in_dir + cc + " -O0 -o driver driver.c > cc.log 2>&1").c_str()), 0)
      << test::read_text(dir / "cc.log");

  // Every value printed is the table's value at (0.5, 0.25): linear in u
  // between 0 (0) and 2 (-12), plus r.
  ASSERT_EQ(std::system((in_dir + "./driver > values.txt").c_str()), 0);
  const auto values = lines_of(dir / "values.txt");
  ASSERT_EQ(values.size(), names.size());
  for (const auto& value : values) EXPECT_DOUBLE_EQ(std::stod(value), -3.0 + 0.25);

  // Macros: those of the empty file, plus per header its guard and t<i>_ names.
  ASSERT_EQ(std::system((in_dir + cc + " -E -dM driver.c > driver.macros && " + cc +
                         " -E -dM -include stdio.h -include math.h empty.c > empty.macros")
                            .c_str()),
            0);
  std::set<std::string> baseline;
  for (const auto& line : lines_of(dir / "empty.macros")) baseline.insert(line);
  for (const auto& line : lines_of(dir / "driver.macros")) {
    if (baseline.count(line)) continue;
    std::istringstream words(line);
    std::string define, macro;
    words >> define >> macro;
    macro = macro.substr(0, macro.find('('));
    const bool guard = macro.size() > 11 && macro[0] == 'T' && macro.substr(macro.size() - 11) == "_H_INCLUDED";
    EXPECT_TRUE(guard || (macro[0] == 't' && macro.find('_') != std::string::npos)) << line;
  }
  // Symbols of the program's own object: main and t<i>_ names only.
  ASSERT_EQ(std::system((in_dir + cc + " -O0 -c driver.c -o driver.o && nm driver.o > driver.nm").c_str()), 0);
  for (const auto& line : lines_of(dir / "driver.nm")) {
    const std::string symbol = line.substr(line.rfind(' ') + 1);
    const char type = line.size() > 17 ? line[17] : 'U';
    if (type == 'U') continue;  // printf
    EXPECT_TRUE(symbol == "main" || (symbol[0] == 't' && symbol.find('_') != std::string::npos) || symbol[0] == '.')
        << line;
  }
}

// MATLAB: removes comments and the contents of character literals, leaving
// the statements' skeleton. A quote starts a literal except right after an
// identifier, a closing bracket, a dot or another quote (the transpose).
std::string matlab_skeleton(const std::vector<std::string>& lines, std::string& problem) {
  std::string out;
  for (const auto& line : lines) {
    const std::size_t first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line[first] == '%') {
      const std::string rest = line.substr(first);
      if (rest == "%{" || rest == "%}") problem = "a block comment marker line: " + line;
      continue;
    }
    std::string skeleton;
    for (std::size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      if (c == '%') break;  // a trailing comment
      const char before = skeleton.empty() ? ' ' : skeleton.back();
      const bool transpose = std::isalnum(static_cast<unsigned char>(before)) || before == '_' || before == ')' ||
                             before == ']' || before == '}' || before == '.' || before == '\'';
      if (c == '\'' && !transpose) {
        std::size_t j = i + 1;
        for (;; ++j) {
          if (j >= line.size()) {
            problem = "an unterminated literal: " + line;
            return out;
          }
          if (line[j] == '\'' && j + 1 < line.size() && line[j + 1] == '\'') {
            ++j;
            continue;
          }
          if (line[j] == '\'') break;
        }
        skeleton += "''";
        i = j;
        continue;
      }
      skeleton += c;
    }
    out += skeleton + "\n";
  }
  return out;
}

TEST(HostileNames, SimulinkScriptHasOnlyTheExpectedStatements) {
  TempDir dir;
  const GridTable plain = table_named("u");
  std::filesystem::create_directory(dir / "plain");
  export_table(plain, metadata_named(plain, "u"), ExportFormat::Mat, dir.path() / "plain" / "table.mat");
  std::string problem;
  const std::string expected = matlab_skeleton(lines_of(dir.path() / "plain" / "table_simulink.m"), problem);
  ASSERT_TRUE(problem.empty()) << problem;
  ASSERT_NE(expected.find("set_param(block, ''"), std::string::npos) << expected;
  for (const auto& name : test::hostile_names()) {
    SCOPED_TRACE(testing::PrintToString(name));
    const GridTable table = table_named(name);
    export_table(table, metadata_named(table, name), ExportFormat::Mat, dir / "table.mat");
    const auto lines = lines_of(dir / "table_simulink.m");
    std::string found_problem;
    const std::string skeleton = matlab_skeleton(lines, found_problem);
    EXPECT_TRUE(found_problem.empty()) << found_problem;
    EXPECT_EQ(skeleton, expected);
    for (const auto& line : lines) EXPECT_EQ(line.find('\r'), std::string::npos);
  }
  EXPECT_EQ(files_in(dir.path()), (std::set<std::string>{"plain", "table.mat", "table_simulink.m"}));
}

}  // namespace
}  // namespace hydrocoef
