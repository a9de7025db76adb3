// CSV (long and wide) and JSON exports read back independently: the CSV
// parsed as text, the JSON with nlohmann::json and rebuilt into a GridTable
// that must evaluate exactly as the original, in range and out of range.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "src/export/csv_export.hpp"
#include "src/export/json_export.hpp"
#include "src/surface/surface_builder.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

GridTable table_2d(Interpolation method) {
  std::vector<GridAxis> axes = {{"u", {-1.0, -0.1, 0.0, 0.3, 1.5}, Extrapolation::Linear},
                                {"r", {-0.5, 0.0, 0.1, 0.7}, Extrapolation::Clamp}};
  std::vector<double> values;
  for (double r : axes[1].breakpoints)
    for (double u : axes[0].breakpoints) {
      values.push_back(-12.5 * u * std::abs(u) + 0.1 * r + 1.0 / 3.0);  // X
      values.push_back(-0.7 * r * std::abs(r) + 0.01 * u);              // N
    }
  return GridTable(std::move(axes), {"X", "N"}, std::move(values), method);
}

ExportMetadata metadata_of(const GridTable& table) {
  ExportMetadata metadata = metadata_for_table(table, "asr-v:ur");
  metadata.body = "asr-v";
  metadata.run_ids = {1, 2, 5};
  metadata.created_at = "2026-11-22T10:04:05Z";
  metadata.quality_json = R"({"loo_max":[0.1,0.2],"loo_rms":[0.05,0.07]})";
  return metadata;
}

std::vector<std::string> data_lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line))
    if (!line.empty() && line[0] != '#') out.push_back(line);
  return out;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream fields(line);
  std::string field;
  while (std::getline(fields, field, ',')) out.push_back(field);
  return out;
}

TEST(CsvExport, LongFormHasOneExactRowPerNodeAxisZeroFastest) {
  const GridTable table = table_2d(Interpolation::Pchip);
  const std::string text = csv_long_text(table, metadata_of(table));
  EXPECT_NE(text.find("# axis 0 u [m/s]: 5 breakpoints, valid range [-1, 1.5], out of range: linear"),
            std::string::npos);
  EXPECT_NE(text.find("runs [1,2,5]"), std::string::npos);
  EXPECT_NE(text.find("on-body"), std::string::npos);
  EXPECT_NE(text.find("method pchip"), std::string::npos);
  const auto lines = data_lines(text);
  ASSERT_EQ(lines.size(), 1 + table.node_count());
  EXPECT_EQ(lines[0], "u [m/s],r [rad/s],X [N],N [N m]");
  for (std::size_t node = 0; node < table.node_count(); ++node) {
    const auto fields = split(lines[node + 1]);
    ASSERT_EQ(fields.size(), 4u);
    EXPECT_EQ(std::stod(fields[0]), table.axes()[0].breakpoints[node % 5]);
    EXPECT_EQ(std::stod(fields[1]), table.axes()[1].breakpoints[node / 5]);
    EXPECT_EQ(std::stod(fields[2]), table.values()[node * 2]);  // exact: shortest round-trip text
    EXPECT_EQ(std::stod(fields[3]), table.values()[node * 2 + 1]);
  }
}

TEST(CsvExport, WideFormIsOneRowPerFirstAxisBreakpointPerOutput) {
  const GridTable table = table_2d(Interpolation::Linear);
  const auto lines = data_lines(csv_wide_text(table, metadata_of(table)));
  ASSERT_EQ(lines.size(), 1 + 2 * 5u);
  EXPECT_EQ(lines[0], "output,u [m/s] \\ r [rad/s],-0.5,0,0.1,0.7");
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t i = 0; i < 5; ++i) {
      const auto fields = split(lines[1 + k * 5 + i]);
      ASSERT_EQ(fields.size(), 6u);
      EXPECT_EQ(fields[0], table.outputs()[k]);
      EXPECT_EQ(std::stod(fields[1]), table.axes()[0].breakpoints[i]);
      for (std::size_t j = 0; j < 4; ++j) EXPECT_EQ(std::stod(fields[2 + j]), table.values()[(j * 5 + i) * 2 + k]);
    }
}

TEST(CsvExport, WideFormRefusesAnythingButTwoAxes) {
  const GridTable table({{"u", {0.0, 1.0}}, {"v", {0.0, 1.0}}, {"w", {0.0, 1.0}}}, {"X"}, std::vector<double>(8, 1.0),
                        Interpolation::Linear);
  test::expect_input_error([&] { csv_wide_text(table, metadata_for_table(table, "s3")); },
                           {"csv-wide", "3 axes (u, v, w)", "expected a 2-D table"});
}

// Rebuilds a GridTable from the JSON export alone.
GridTable table_from_json(const nlohmann::json& document) {
  std::vector<GridAxis> axes;
  for (const auto& axis : document.at("axes"))
    axes.push_back({axis.at("name").get<std::string>(), axis.at("breakpoints").get<std::vector<double>>(),
                    parse_extrapolation(axis.at("extrapolation").get<std::string>())});
  std::vector<std::string> outputs;
  for (const auto& output : document.at("outputs")) outputs.push_back(output.at("name").get<std::string>());
  std::size_t nodes = 1;
  for (const auto& axis : axes) nodes *= axis.breakpoints.size();
  std::vector<double> values(nodes * outputs.size());
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const auto column = document.at("values").at(outputs[k]).get<std::vector<double>>();
    EXPECT_EQ(column.size(), nodes);
    for (std::size_t node = 0; node < nodes && node < column.size(); ++node)
      values[node * outputs.size() + k] = column[node];
  }
  return GridTable(std::move(axes), std::move(outputs), std::move(values),
                   parse_interpolation(document.at("method").get<std::string>()));
}

TEST(JsonExport, ParsesBackIntoATableThatEvaluatesIdentically) {
  for (Interpolation method : {Interpolation::Nearest, Interpolation::Linear, Interpolation::Pchip,
                               Interpolation::Akima, Interpolation::NaturalSpline}) {
    const GridTable table = table_2d(method);
    test::TempDir dir;
    const auto files = export_table(table, metadata_of(table), ExportFormat::Json, dir / "t.json");
    ASSERT_EQ(files.size(), 1u);
    const nlohmann::json document = nlohmann::json::parse(test::read_text(dir / "t.json"));
    EXPECT_EQ(document.at("method"), interpolation_name(method));
    EXPECT_EQ(document.at("axes")[0].at("unit"), "m/s");
    EXPECT_EQ(document.at("axes")[1].at("unit"), "rad/s");
    EXPECT_EQ(document.at("axes")[1].at("extrapolation"), "clamp");
    EXPECT_EQ(document.at("axes")[0].at("valid_range"), nlohmann::json({-1.0, 1.5}));
    EXPECT_EQ(document.at("outputs")[1].at("unit"), "N m");
    EXPECT_EQ(document.at("sign_convention"), "on-body");
    EXPECT_EQ(document.at("provenance").at("runs"), nlohmann::json({1, 2, 5}));
    EXPECT_EQ(document.at("provenance").at("content_sha256"), metadata_of(table).content_sha256);
    EXPECT_EQ(document.at("fit_statistics").at("loo_max")[1], 0.2);
    const GridTable back = table_from_json(document);
    EXPECT_EQ(back.values(), table.values());
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> u(-1.5, 2.0);
    std::uniform_real_distribution<double> r(-0.8, 1.0);
    std::vector<double> a(2), b(2);
    for (int i = 0; i < 2000; ++i) {
      const std::vector<double> point = {u(random), r(random)};
      table.evaluate(point, a);
      back.evaluate(point, b);
      EXPECT_EQ(a, b);
    }
  }
}

TEST(JsonExport, HoldsTheSurfacesStandardDeviationAtEveryNode) {
  // A 4 x 3 grid of runs with stated uncertainties, pchip: sigma per output
  // per node equals evaluate_with_standard_deviation there.
  std::vector<StoredRun> runs;
  std::int64_t id = 1;
  for (double r : {-0.2, 0.0, 0.3})
    for (double u : {0.1, 0.2, 0.5, 0.9}) {
      StoredRun run;
      run.id = id++;
      run.key.body = "asr-v";
      run.key.nu_b[0] = u;
      run.key.nu_b[5] = r;
      run.tau_b[0] = StoredForce{{-3 * u * u + r, {}, {}, 0.02 + 0.05 * u}, SignConvention::OnBody, 1, "f.csv", 0};
      run.tau_b[5] = StoredForce{{-0.5 * r * std::abs(r) + u * r, {}, {}, 0.01}, SignConvention::OnBody, 1, "f.csv", 0};
      runs.push_back(run);
    }
  const BuiltSurface built = build_surface(runs, {{"u", "r"}, {"X", "N"}, "pchip"});
  ASSERT_TRUE(built.surface.has_standard_deviation());
  const SurfaceRecord record = built.record("asr-v:ur", "asr-v");
  const GridTable& table = *built.surface.grid();
  const nlohmann::json document = nlohmann::json::parse(json_text(table, metadata_from_record(record, built.surface)));
  ASSERT_TRUE(document.contains("sigma"));
  EXPECT_TRUE(document.contains("sigma_definition"));
  std::vector<double> values(2), sd(2);
  for (std::size_t node = 0; node < table.node_count(); ++node) {
    const std::vector<double> point = {table.axes()[0].breakpoints[node % 4], table.axes()[1].breakpoints[node / 4]};
    built.surface.evaluate_with_standard_deviation(point, values, sd);
    EXPECT_EQ(document.at("values").at("X")[node].get<double>(), values[0]);
    EXPECT_EQ(document.at("sigma").at("X")[node].get<double>(), sd[0]);
    EXPECT_EQ(document.at("sigma").at("N")[node].get<double>(), sd[1]);
    // At a node the runs' part is that run's own uncertainty.
    const double u = point[0];
    EXPECT_NEAR(sd[0], std::hypot(0.02 + 0.05 * u, built.quality.loo_rms[0]), 1e-15);
  }
  // A table without a stated standard deviation has no sigma.
  const GridTable plain = table_2d(Interpolation::Linear);
  EXPECT_FALSE(nlohmann::json::parse(json_text(plain, metadata_of(plain))).contains("sigma"));
}

}  // namespace
}  // namespace hydrocoef
