// The CFX monitor importer: both dialects (cfx5mondata -out with quoted
// "CATEGORY,Name" headers, and Export Plot Data with a preamble and units in
// brackets), CRLF, the last value and the mean, spread and drift over the last
// N rows, recognition of monitor names and explicit mapping, unit conversion,
// the options copied into the run, every refusal with its location and
// message, looks_like_cfx_monitor, and the provenance of read_cfx_monitor.
// Expected values are worked out by hand from the numbers in the inputs.
#include "importers/cfx_monitor.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "src/core/error.hpp"
#include "src/core/source_file.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kX = 0, kY = 1, kZ = 2, kK = 3, kM = 4, kN = 5;

#define EXPECT_CONTAINS(haystack, needle) \
  EXPECT_NE(std::string(haystack).find(needle), std::string::npos) << "expected '" << (needle) << "' in: " << (haystack)
#define EXPECT_NOT_CONTAINS(haystack, needle)                      \
  EXPECT_EQ(std::string(haystack).find(needle), std::string::npos) \
      << "did not expect '" << (needle) << "' in: " << (haystack)
#define EXPECT_STARTS_WITH(text, prefix) \
  EXPECT_EQ(std::string(text).rfind(prefix, 0), 0u) << "expected it to start with '" << (prefix) << "': " << (text)

std::string to_crlf(const std::string& lf) {
  std::string out;
  for (const char c : lf) {
    if (c == '\n') out += '\r';
    out += c;
  }
  return out;
}

MonitorImport parse(std::string_view text, const CfxMonitorOptions& options = {}) {
  return parse_cfx_monitor(text, "t.csv", options);
}

const ImportedRun& only_run(const MonitorImport& result) {
  EXPECT_EQ(result.batch.runs.size(), 1u);
  return result.batch.runs.front();
}

// The InputError message for parsing `text` as "t.csv"; fails if it is accepted.
std::string error_of(std::string_view text, const CfxMonitorOptions& options = {}) {
  try {
    (void)parse_cfx_monitor(text, "t.csv", options);
    ADD_FAILURE() << "accepted:\n" << text;
  } catch (const InputError& error) {
    return error.what();
  }
  return {};
}

CfxMonitorOptions averaging(std::size_t n) {
  CfxMonitorOptions options;
  options.average_last = n;
  return options;
}

CfxMonitorOptions mapping(std::map<std::string, std::string> monitors) {
  CfxMonitorOptions options;
  options.monitors = std::move(monitors);
  return options;
}

bool all_printable_ascii(const std::string& text) {
  return std::all_of(text.begin(), text.end(), [](char c) { return c >= 0x20 && c < 0x7F; });
}

// --- cfx5mondata -out ------------------------------------------------------

// A point monitor whose header holds the domain and coordinates in doubled
// quotes, force and torque expression monitors, and a mass flow monitor; the
// unused columns have empty cells. Columns: 1 timestep, 2 temperature, 3 Fx,
// 4 Fy, 5 Torque z, 6 mass flow.
const std::string kPointMonitorHeader =
    "USER POINT,Temperature GT1,D1,\"x= 4.65E-02,y= 4.16E-01,z= 0.00E+00\",Temperature";
const std::string kMondata =
    "\"ACCUMULATED TIMESTEP\",\"USER POINT,Temperature GT1,D1,\"\"x= 4.65E-02,y= 4.16E-01,z= 0.00E+00\"\","
    "Temperature\",\"USER POINT,Fx\",\"USER POINT,Fy\",\"USER POINT,Torque z\",\"USER POINT,Mass Flow Monitor\"\n"
    "1,,1.0,-2.0,0.5,\n"
    "2,300.5,2.0,-4.0,0.25,1.1\n"
    "3,,4.0,-8.0,0.125,\n";

TEST(CfxMonitor, MondataLastValue) {
  const MonitorImport result = parse(kMondata);
  const ImportedRun& run = only_run(result);
  ASSERT_TRUE(run.tau_b[kX].has_value());
  ASSERT_TRUE(run.tau_b[kY].has_value());
  ASSERT_TRUE(run.tau_b[kN].has_value());
  EXPECT_EQ(run.tau_b[kX]->total, 4.0);
  EXPECT_EQ(run.tau_b[kY]->total, -8.0);
  EXPECT_EQ(run.tau_b[kN]->total, 0.125);
  EXPECT_FALSE(run.tau_b[kX]->pressure.has_value());
  EXPECT_FALSE(run.tau_b[kX]->viscous.has_value());
  EXPECT_FALSE(run.tau_b[kZ].has_value());
  EXPECT_FALSE(run.tau_b[kK].has_value());
  EXPECT_FALSE(run.tau_b[kM].has_value());
  EXPECT_EQ(run.source_line, 4u);

  const MonitorSummary& summary = result.summary;
  EXPECT_EQ(summary.iterations, 3u);
  EXPECT_EQ(summary.first_iteration, 1u);
  EXPECT_EQ(summary.window_first_iteration, 3u);
  EXPECT_EQ(summary.last_iteration, 3u);
  EXPECT_EQ(summary.window, 1u);
  EXPECT_EQ(summary.columns[kX], "USER POINT,Fx");
  EXPECT_EQ(summary.columns[kY], "USER POINT,Fy");
  EXPECT_EQ(summary.columns[kN], "USER POINT,Torque z");
  EXPECT_EQ(summary.columns[kZ], "");
  EXPECT_EQ(summary.mean[kX], 4.0);
  EXPECT_EQ(summary.std_dev[kX], 0.0);
  EXPECT_EQ(summary.relative_change[kX], 0.0);
  EXPECT_FALSE(summary.mean[kZ].has_value());
  EXPECT_FALSE(summary.std_dev[kZ].has_value());
  EXPECT_FALSE(summary.relative_change[kZ].has_value());
}

TEST(CfxMonitor, MondataMeanOverTheLastTwoRows) {
  const MonitorImport result = parse(kMondata, averaging(2));
  const ImportedRun& run = only_run(result);
  // X: 2, 4; Y: -4, -8; N: 0.25, 0.125.
  EXPECT_DOUBLE_EQ(run.tau_b[kX]->total, 3.0);
  EXPECT_DOUBLE_EQ(run.tau_b[kY]->total, -6.0);
  EXPECT_DOUBLE_EQ(run.tau_b[kN]->total, 0.1875);
  const MonitorSummary& s = result.summary;
  EXPECT_EQ(s.window, 2u);
  EXPECT_EQ(s.window_first_iteration, 2u);
  EXPECT_EQ(s.last_iteration, 3u);
  EXPECT_DOUBLE_EQ(*s.mean[kX], 3.0);
  EXPECT_DOUBLE_EQ(*s.std_dev[kX], 1.0);
  EXPECT_DOUBLE_EQ(*s.std_dev[kY], 2.0);
  EXPECT_DOUBLE_EQ(*s.std_dev[kN], 0.0625);
  EXPECT_DOUBLE_EQ(*s.relative_change[kX], 2.0 / 3.0);   // (4 - 2) / 3
  EXPECT_DOUBLE_EQ(*s.relative_change[kY], -2.0 / 3.0);  // (-8 + 4) / 6
  EXPECT_DOUBLE_EQ(*s.relative_change[kN], -2.0 / 3.0);  // (0.125 - 0.25) / 0.1875
}

TEST(CfxMonitor, MondataMeanOverAllThreeRows) {
  const MonitorImport result = parse(kMondata, averaging(3));
  const MonitorSummary& s = result.summary;
  // X: 1, 2, 4: mean 7/3; deviations -4/3, -1/3, 5/3; variance (16 + 1 + 25) / 27 = 14/9.
  EXPECT_DOUBLE_EQ(only_run(result).tau_b[kX]->total, 7.0 / 3.0);
  EXPECT_DOUBLE_EQ(*s.std_dev[kX], std::sqrt(14.0) / 3.0);
  EXPECT_DOUBLE_EQ(*s.relative_change[kX], 9.0 / 7.0);  // (4 - 1) / (7/3)
  // N: 0.5, 0.25, 0.125: mean 7/24; deviations 5/24, -1/24, -4/24; variance 42/576/3.
  EXPECT_DOUBLE_EQ(*s.mean[kN], 7.0 / 24.0);
  EXPECT_DOUBLE_EQ(*s.std_dev[kN], std::sqrt(14.0) / 24.0);
  EXPECT_DOUBLE_EQ(*s.relative_change[kN], -9.0 / 7.0);  // (0.125 - 0.5) / (7/24)
  EXPECT_EQ(s.window_first_iteration, 1u);
  EXPECT_EQ(only_run(result).source_line, 4u);
}

TEST(CfxMonitor, RelativeChangeIsEmptyWhenTheMeanIsZero) {
  const MonitorImport result = parse("\"ACCUMULATED TIMESTEP\",\"USER POINT,Fx\"\n1,-1.5\n2,1.5\n", averaging(2));
  EXPECT_EQ(*result.summary.mean[kX], 0.0);
  EXPECT_DOUBLE_EQ(*result.summary.std_dev[kX], 1.5);
  EXPECT_FALSE(result.summary.relative_change[kX].has_value());
}

TEST(CfxMonitor, CrlfEqualsLf) {
  const std::string crlf = to_crlf(kMondata);
  ASSERT_NE(crlf, kMondata);
  const MonitorImport a = parse(crlf, averaging(2));
  const MonitorImport b = parse(kMondata, averaging(2));
  for (std::size_t c = 0; c < 6; ++c) {
    ASSERT_EQ(only_run(a).tau_b[c].has_value(), only_run(b).tau_b[c].has_value()) << c;
    if (only_run(a).tau_b[c]) {
      EXPECT_EQ(only_run(a).tau_b[c]->total, only_run(b).tau_b[c]->total) << c;
    }
    EXPECT_EQ(a.summary.std_dev[c], b.summary.std_dev[c]) << c;
    EXPECT_EQ(a.summary.columns[c], b.summary.columns[c]) << c;
  }
  EXPECT_EQ(only_run(a).tau_b[kX]->total, 3.0);
}

TEST(CfxMonitor, PointMonitorHeaderWithDoubledQuotesCanBeMapped) {
  // The mapping only works if the header was unquoted to the exact text,
  // embedded commas and quotes included. The point monitor has no value on
  // rows 1 and 3, so the window is row 2 alone: make it the last row.
  const std::string text = kMondata.substr(0, kMondata.find("3,,"));
  const MonitorImport result = parse(text, mapping({{"X", kPointMonitorHeader}}));
  EXPECT_EQ(only_run(result).tau_b[kX]->total, 300.5);
  EXPECT_EQ(result.summary.columns[kX], kPointMonitorHeader);
  // Only the mapped component is read when a mapping is given.
  for (std::size_t c = 1; c < 6; ++c) EXPECT_FALSE(only_run(result).tau_b[c].has_value()) << c;
}

TEST(CfxMonitor, TrailingEmptyCellAndNoFinalNewline) {
  const MonitorImport result = parse("\"ACCUMULATED TIMESTEP\",\"USER POINT,Fz\",\"USER POINT,Other\"\n7,2.5,", {});
  EXPECT_EQ(only_run(result).tau_b[kZ]->total, 2.5);
  EXPECT_EQ(result.summary.last_iteration, 7u);
  EXPECT_EQ(result.summary.first_iteration, 7u);
}

TEST(CfxMonitor, EmptyCellsOutsideTheWindowAreAllowed) {
  // A monitor added on a restart has no values on the early rows.
  const MonitorImport result =
      parse("\"ACCUMULATED TIMESTEP\",\"USER POINT,Fx\",\"USER POINT,Fy\"\n1,1,\n2,2,\n3,3,5\n4,4,7\n", averaging(2));
  EXPECT_DOUBLE_EQ(only_run(result).tau_b[kX]->total, 3.5);
  EXPECT_DOUBLE_EQ(only_run(result).tau_b[kY]->total, 6.0);
  EXPECT_EQ(result.summary.iterations, 4u);
}

TEST(CfxMonitor, BlankLinesAndUtf8ByteOrderMark) {
  const MonitorImport result = parse("\xEF\xBB\xBF\"ACCUMULATED TIMESTEP\",\"USER POINT,Fx\"\n1,1\n\n2,9\n\n");
  EXPECT_EQ(only_run(result).tau_b[kX]->total, 9.0);
  EXPECT_EQ(only_run(result).source_line, 4u);
  EXPECT_EQ(result.summary.iterations, 2u);
}

TEST(CfxMonitor, UnitOptionForColumnsWithoutBrackets) {
  CfxMonitorOptions options;
  options.units = {{"X", "kN"}, {"N", "kN m"}};
  const MonitorImport result = parse(
      "\"ACCUMULATED TIMESTEP\",\"USER POINT,Fx\",\"USER POINT,Torque z\",\"USER POINT,Fy\"\n1,1.5,-2,3\n", options);
  EXPECT_EQ(only_run(result).tau_b[kX]->total, 1500.0);
  EXPECT_EQ(only_run(result).tau_b[kN]->total, -2000.0);
  EXPECT_EQ(only_run(result).tau_b[kY]->total, 3.0);  // no unit anywhere: SI
  EXPECT_EQ(result.summary.mean[kX], 1500.0);
}

// --- Solver Manager Export Plot Data --------------------------------------

// Four preamble lines (one with an unterminated quote, which must not be
// parsed), then ", "-separated headers with units in brackets. Columns: 1
// timestep, 2 mass flow [kg s^-1], 3 Fx1 [kN], 4 Fy1 [N], 5 Fz1 [N], 6
// Torque x1 [J], 7 temperature [K] (a unit the library does not know; the
// column is unused so its unit is never read).
const std::string kPlotExport =
    "Solver Manager plot export\n"
    "Run: \"hull_001.res, 2024\n"
    "\n"
    "Monitor data\n"
    "Accumulated Timestep, Monitor Point: MF IMP1 IN [kg s^-1], Fx1 [kN], Fy1 [N], Fz1 [N], Torque x1 [J], "
    "Monitor Point: Probe (Temperature) [K]\n"
    "1, 0.5, 1.5, 2, 3, 10, 300\n"
    "2, 0.6, 2.5, 4, 5, 20, 301\n";

TEST(CfxMonitor, PlotExportLastValueInSi) {
  const MonitorImport result = parse(kPlotExport);
  const ImportedRun& run = only_run(result);
  EXPECT_EQ(run.tau_b[kX]->total, 2500.0);  // 2.5 kN
  EXPECT_EQ(run.tau_b[kY]->total, 4.0);
  EXPECT_EQ(run.tau_b[kZ]->total, 5.0);
  EXPECT_EQ(run.tau_b[kK]->total, 20.0);  // 20 J = 20 N m
  EXPECT_FALSE(run.tau_b[kM].has_value());
  EXPECT_FALSE(run.tau_b[kN].has_value());
  EXPECT_EQ(run.source_line, 7u);
  EXPECT_EQ(result.summary.columns[kX], "Fx1 [kN]");
  EXPECT_EQ(result.summary.columns[kK], "Torque x1 [J]");
  EXPECT_EQ(result.summary.iterations, 2u);
}

TEST(CfxMonitor, PlotExportMeanInSi) {
  const MonitorImport result = parse(to_crlf(kPlotExport), averaging(2));
  EXPECT_DOUBLE_EQ(only_run(result).tau_b[kX]->total, 2000.0);  // (1.5 + 2.5) / 2 kN
  EXPECT_DOUBLE_EQ(*result.summary.std_dev[kX], 500.0);         // SI, like the mean
  EXPECT_DOUBLE_EQ(*result.summary.relative_change[kX], 0.5);   // (2500 - 1500) / 2000
  EXPECT_DOUBLE_EQ(only_run(result).tau_b[kK]->total, 15.0);
  EXPECT_DOUBLE_EQ(*result.summary.std_dev[kK], 5.0);
}

TEST(CfxMonitor, HeaderFoundWithoutPreambleAndInAnyCase) {
  EXPECT_EQ(only_run(parse("ACCUMULATED TIMESTEP, Fx [N]\n1, 4\n")).tau_b[kX]->total, 4.0);
  EXPECT_EQ(only_run(parse("  \"accumulated timestep\",\"Fx\"\n1,5\n")).tau_b[kX]->total, 5.0);
  EXPECT_EQ(only_run(parse("a\nb\nc\nd\ne\nf\nAccumulated Timestep, Fx [N]\n1, 6\n")).tau_b[kX]->total, 6.0);
}

TEST(CfxMonitor, UnitOptionOverridesBrackets) {
  CfxMonitorOptions options;
  options.units = {{"X", "N"}};
  EXPECT_EQ(only_run(parse(kPlotExport, options)).tau_b[kX]->total, 2.5);
}

TEST(CfxMonitor, MomentUnitsConverted) {
  const MonitorImport result = parse("Accumulated Timestep, My [kN m], Mz [N mm]\n1, 2, 3000\n");
  EXPECT_EQ(only_run(result).tau_b[kM]->total, 2000.0);
  EXPECT_DOUBLE_EQ(only_run(result).tau_b[kN]->total, 3.0);
}

// --- recognising monitor names ----------------------------------------------

// The component that a single monitor column called `name` gives, or -1 when
// the importer finds no force or torque column.
int component_of(const std::string& name) {
  const std::string text = "Accumulated Timestep,\"" + name + "\"\n1,7\n";
  try {
    const MonitorImport result = parse(text);
    int found = -1;
    for (std::size_t c = 0; c < 6; ++c)
      if (only_run(result).tau_b[c]) {
        EXPECT_EQ(found, -1) << name;
        EXPECT_EQ(only_run(result).tau_b[c]->total, 7.0) << name;
        found = static_cast<int>(c);
      }
    return found;
  } catch (const InputError& error) {
    EXPECT_CONTAINS(error.what(), "no force or torque monitor");
    return -1;
  }
}

TEST(CfxMonitorNames, RecognisedSpellings) {
  EXPECT_EQ(component_of("Fx"), 0);
  EXPECT_EQ(component_of("fy"), 1);
  EXPECT_EQ(component_of("FZ"), 2);
  EXPECT_EQ(component_of("USER POINT,Fx"), 0);
  EXPECT_EQ(component_of("Hull Fy2"), 1);
  EXPECT_EQ(component_of("Fz12"), 2);
  EXPECT_EQ(component_of("F_x"), 0);
  EXPECT_EQ(component_of("F y"), 1);
  EXPECT_EQ(component_of("Force X"), 0);
  EXPECT_EQ(component_of("Hull Force Y"), 1);
  EXPECT_EQ(component_of("force_z"), 2);
  EXPECT_EQ(component_of("ForceX"), 0);
  EXPECT_EQ(component_of("Mx"), 3);
  EXPECT_EQ(component_of("My1"), 4);
  EXPECT_EQ(component_of("Tz"), 5);
  EXPECT_EQ(component_of("Tx"), 3);
  EXPECT_EQ(component_of("Torque x"), 3);
  EXPECT_EQ(component_of("USER POINT,Torque y"), 4);
  EXPECT_EQ(component_of("torque_z"), 5);
  EXPECT_EQ(component_of("Moment Y"), 4);
  EXPECT_EQ(component_of("Monitor Point: Fx1"), 0);
  EXPECT_EQ(component_of("hull.Mz"), 5);
}

TEST(CfxMonitorNames, NamesThatAreNotForces) {
  EXPECT_EQ(component_of("Flux"), -1);
  EXPECT_EQ(component_of("Max"), -1);
  EXPECT_EQ(component_of("Index"), -1);
  EXPECT_EQ(component_of("HullFx"), -1);
  EXPECT_EQ(component_of("Torque1"), -1);
  EXPECT_EQ(component_of("Fxx"), -1);
  EXPECT_EQ(component_of("Fx Coefficient"), -1);
  EXPECT_EQ(component_of("Fw"), -1);
  EXPECT_EQ(component_of("Temperature"), -1);
  EXPECT_EQ(component_of("x"), -1);
  EXPECT_EQ(component_of("12"), -1);
  EXPECT_EQ(component_of("force_x()@wall"), -1);
}

TEST(CfxMonitorNames, ExplicitMappingByEveryKindOfName) {
  // Whole header, name without the unit, and name after the category.
  EXPECT_EQ(only_run(parse(kPlotExport, mapping({{"X", "Fx1 [kN]"}}))).tau_b[kX]->total, 2500.0);
  EXPECT_EQ(only_run(parse(kPlotExport, mapping({{"X", "Fx1"}}))).tau_b[kX]->total, 2500.0);
  EXPECT_EQ(only_run(parse(kPlotExport, mapping({{"X", "  Fx1  "}}))).tau_b[kX]->total, 2500.0);
  EXPECT_EQ(only_run(parse(kMondata, mapping({{"X", "USER POINT,Fx"}}))).tau_b[kX]->total, 4.0);
  EXPECT_EQ(only_run(parse(kMondata, mapping({{"X", "Fx"}}))).tau_b[kX]->total, 4.0);
  const std::string point = "Accumulated Timestep, Monitor Point: Hull Drag [kN], Monitor Point: Yaw [N m]\n1, 2, 3\n";
  EXPECT_EQ(only_run(parse(point, mapping({{"X", "Hull Drag"}}))).tau_b[kX]->total, 2000.0);
  EXPECT_EQ(only_run(parse(point, mapping({{"N", "Monitor Point: Yaw"}}))).tau_b[kN]->total, 3.0);
}

TEST(CfxMonitorNames, ExplicitMappingOfNamesNotRecognised) {
  const std::string text =
      "\"ACCUMULATED TIMESTEP\",\"USER POINT,Drag\",\"USER POINT,Yaw Moment\",\"USER POINT,Fx\"\n1,-3,0.5,99\n";
  const MonitorImport result = parse(text, mapping({{"X", "Drag"}, {"N", "USER POINT,Yaw Moment"}}));
  const ImportedRun& run = only_run(result);
  EXPECT_EQ(run.tau_b[kX]->total, -3.0);  // not the 99 of "Fx": the mapping wins
  EXPECT_EQ(run.tau_b[kN]->total, 0.5);
  EXPECT_EQ(result.summary.columns[kX], "USER POINT,Drag");
  for (const std::size_t c : {kY, kZ, kK, kM}) EXPECT_FALSE(run.tau_b[c].has_value()) << c;
}

TEST(CfxMonitorNames, MappingResolvesAnAmbiguity) {
  const std::string text = "Accumulated Timestep, Hull Fx [N], Rudder Fx [N]\n1, 10, 2\n";
  EXPECT_CONTAINS(error_of(text), "both look like X");
  EXPECT_EQ(only_run(parse(text, mapping({{"X", "Rudder Fx"}}))).tau_b[kX]->total, 2.0);
}

// --- options copied into the run -------------------------------------------

TEST(CfxMonitor, KeySignFluidAndReferencePointAreCopied) {
  CfxMonitorOptions options;
  options.key.body = "asr-v";
  options.key.nu_b = {0.5, 0.0, 0.0, 0.0, 0.0, 0.1};
  options.key.disturbances = {{"current_v", 0.05}};
  options.sign = SignConvention::OpposingMotion;
  options.fluid.density_kg_m3 = 998.2;
  options.fluid.kinematic_viscosity_m2_s = 1.004e-6;
  options.reference_point_b = {0.1, -0.2, 0.3};
  const MonitorImport result = parse(kMondata, options);
  const ImportedRun& run = only_run(result);
  EXPECT_EQ(run.key.body, "asr-v");
  EXPECT_EQ(run.key.nu_b, (std::array<double, 6>{0.5, 0.0, 0.0, 0.0, 0.0, 0.1}));
  EXPECT_EQ(run.key.disturbances, (std::map<std::string, double>{{"current_v", 0.05}}));
  EXPECT_EQ(run.sign, SignConvention::OpposingMotion);
  EXPECT_EQ(run.fluid.density_kg_m3, 998.2);
  EXPECT_EQ(run.fluid.kinematic_viscosity_m2_s, 1.004e-6);
  EXPECT_EQ(run.reference_point_b, (std::array<double, 3>{0.1, -0.2, 0.3}));
  // The sign convention is recorded, not applied: values stay as written.
  EXPECT_EQ(run.tau_b[kX]->total, 4.0);
}

TEST(CfxMonitor, Defaults) {
  const MonitorImport result = parse(kMondata);
  const ImportedRun& run = only_run(result);
  EXPECT_EQ(run.key.body, "vehicle");
  EXPECT_EQ(run.key.nu_b, (std::array<double, 6>{}));
  EXPECT_TRUE(run.key.disturbances.empty());
  EXPECT_EQ(run.sign, SignConvention::OnBody);
  EXPECT_FALSE(run.fluid.density_kg_m3.has_value());
  EXPECT_EQ(run.reference_point_b, (std::array<double, 3>{}));
  EXPECT_EQ(result.batch.source.importer, "cfx-monitor");
  EXPECT_EQ(result.batch.source.path, "t.csv");
  EXPECT_EQ(result.batch.source.sha256, sha256_hex(kMondata));
  EXPECT_EQ(result.batch.source.size_bytes, kMondata.size());
}

// --- refusals ---------------------------------------------------------------

TEST(CfxMonitorErrors, EmptyFile) {
  const std::string message = error_of("");
  EXPECT_EQ(message.rfind("t.csv: empty file", 0), 0u) << message;
}

TEST(CfxMonitorErrors, NoHeader) {
  const std::string message = error_of("Time, Fx [N]\n1, 2\n");
  EXPECT_STARTS_WITH(message, "t.csv: no header line");
  EXPECT_CONTAINS(message, "'Accumulated Timestep'");
  EXPECT_CONTAINS(message, "found first 'Time, Fx [N]' on line 1");
  EXPECT_CONTAINS(error_of("\n  \r\n\t\n"), "only blank lines");
}

TEST(CfxMonitorErrors, BinaryDataWithANulByte) {
  static constexpr char kPng[] = "\x89PNG\r\n\x1a\n\0\0\0\rIHDR\xff\xfe";
  const std::string garbage(kPng, sizeof kPng - 1);
  const std::string message = error_of(garbage);
  EXPECT_STARTS_WITH(message, "t.csv:3:1: binary data");  // lines end after "\x89PNG\r" and "\x1a"
  EXPECT_TRUE(all_printable_ascii(message)) << message;
  static constexpr char kNulInARow[] = "Accumulated Timestep, Fx\n1, 2\0\n";
  EXPECT_STARTS_WITH(error_of(std::string(kNulInARow, sizeof kNulInARow - 1)), "t.csv:2:5: binary data");
}

TEST(CfxMonitorErrors, BinaryGarbageWithoutNulStaysPrintable) {
  const std::string message = error_of("\x01\x02\xff\xfe\x1b[31m\x7f\xc3\x28 garbage\nmore\n");
  EXPECT_STARTS_WITH(message, "t.csv: no header line");
  EXPECT_CONTAINS(message, "\\x01\\x02\\xff\\xfe\\x1b[31m\\x7f\\xc3( garbage");
  EXPECT_TRUE(all_printable_ascii(message)) << message;
}

TEST(CfxMonitorErrors, ValidUtf8IsKeptInMessages) {
  const std::string message = error_of("Accumulated Timestep, Fx [\xC2\xB5N], Fy [N]\n1, \xC2\xB5, 2\n");
  EXPECT_STARTS_WITH(message, "t.csv:2:4: ");
  EXPECT_CONTAINS(message, "found '\xC2\xB5', expected a number");
}

TEST(CfxMonitorErrors, LongGarbageIsCut) {
  const std::string message = error_of(std::string(5000, '\x01'));
  EXPECT_LT(message.size(), 1200u) << message;
  EXPECT_CONTAINS(message, "\\x01\\x01...");
}

TEST(CfxMonitorErrors, LongPointMonitorNamesAreNotCut) {
  const std::string message = error_of(kMondata, mapping({{"X", "Drag"}}));
  EXPECT_CONTAINS(message, "'" + kPointMonitorHeader + "'");
}

TEST(CfxMonitorErrors, NoForceOrTorqueColumnListsTheColumns) {
  const std::string message = error_of(
      "\"ACCUMULATED TIMESTEP\",\"USER POINT,Mass Flow Monitor\",\"USER POINT,Pressure Ratio\"\n"
      "1,-4.53497200e+01,2.13941860e+00\n");
  EXPECT_STARTS_WITH(message, "t.csv:1: no force or torque monitor");
  EXPECT_CONTAINS(message, "'USER POINT,Mass Flow Monitor', 'USER POINT,Pressure Ratio'");
  EXPECT_CONTAINS(message, "--monitor X=");
  EXPECT_CONTAINS(error_of("Accumulated Timestep\n1\n"), "none besides the timestep");
}

TEST(CfxMonitorErrors, LongColumnListIsCut) {
  std::string header = "Accumulated Timestep";
  std::string row = "1";
  for (int i = 0; i < 40; ++i) {
    header += ", P" + std::to_string(i);
    row += ", 0";
  }
  const std::string message = error_of(header + "\n" + row + "\n");
  EXPECT_CONTAINS(message, "'P29' and 10 more");
  EXPECT_NOT_CONTAINS(message, "'P30'");
}

TEST(CfxMonitorErrors, AmbiguousRecognitionListsBothColumns) {
  const std::string message =
      error_of("\"ACCUMULATED TIMESTEP\",\"USER POINT,Fx\",\"USER POINT,Fy\",\"USER POINT,Force X\"\n1,1,2,3\n");
  EXPECT_STARTS_WITH(message, "t.csv:1:56: ");
  EXPECT_CONTAINS(message, "columns 'USER POINT,Fx' (column 24) and 'USER POINT,Force X' (column 56) both look like X");
  EXPECT_CONTAINS(message, "--monitor X=");
}

TEST(CfxMonitorErrors, MappedMonitorThatDoesNotExist) {
  const std::string message = error_of(kMondata, mapping({{"Y", "Side force"}}));
  EXPECT_STARTS_WITH(message, "t.csv:1: no monitor 'Side force' for Y");
  EXPECT_CONTAINS(message, "'USER POINT,Fx', 'USER POINT,Fy', 'USER POINT,Torque z'");
  // The timestep column is not a monitor.
  EXPECT_CONTAINS(error_of(kMondata, mapping({{"X", "ACCUMULATED TIMESTEP"}})), "no monitor");
}

TEST(CfxMonitorErrors, MappedMonitorMatchingSeveralColumns) {
  const std::string text = "\"ACCUMULATED TIMESTEP\",\"USER POINT,Fx\",\"FORCE,Fx\"\n1,1,2\n";
  const std::string message = error_of(text, mapping({{"X", "Fx"}}));
  EXPECT_STARTS_WITH(message,
                     "t.csv:1: monitor 'Fx' for X matches 'USER POINT,Fx' (column 24), 'FORCE,Fx' (column 40)");
  EXPECT_EQ(only_run(parse(text, mapping({{"X", "FORCE,Fx"}}))).tau_b[kX]->total, 2.0);
}

TEST(CfxMonitorErrors, OneMonitorMappedToTwoComponents) {
  const std::string message = error_of(kMondata, mapping({{"X", "Fx"}, {"Y", "USER POINT,Fx"}}));
  EXPECT_STARTS_WITH(message, "t.csv:1:");
  EXPECT_CONTAINS(message, "mapped to both X and Y");
}

TEST(CfxMonitorErrors, BadOptions) {
  EXPECT_EQ(error_of(kMondata, mapping({{"Q", "Fx"}})).rfind("monitor mapping for 'Q'", 0), 0u);
  EXPECT_CONTAINS(error_of(kMondata, mapping({{"X", " "}})), "names no monitor");
  CfxMonitorOptions units;
  units.units = {{"u", "N"}};
  EXPECT_CONTAINS(error_of(kMondata, units), "unit for 'u'");
  EXPECT_CONTAINS(error_of(kMondata, averaging(0)), "last 0 iterations");
  CfxMonitorOptions no_body;
  no_body.key.body = "";
  EXPECT_CONTAINS(error_of(kMondata, no_body), "empty body name");
}

TEST(CfxMonitorErrors, WrongUnitKind) {
  const std::string torque_as_force = error_of("Accumulated Timestep, Fx [N m]\n1, 2\n");
  EXPECT_STARTS_WITH(torque_as_force, "t.csv:1:23: ");
  EXPECT_CONTAINS(torque_as_force, "column 'Fx [N m]' gives X");
  EXPECT_CONTAINS(torque_as_force, "expected a force");
  const std::string force_as_torque = error_of("Accumulated Timestep, Fx [N], Torque z [kN]\n1, 2, 3\n");
  EXPECT_STARTS_WITH(force_as_torque, "t.csv:1:31: ");
  EXPECT_CONTAINS(force_as_torque, "expected a moment");
  const std::string pressure = error_of("Accumulated Timestep, Fx [Pa]\n1, 2\n");
  EXPECT_CONTAINS(pressure, "expected a force");
  CfxMonitorOptions options;
  options.units = {{"X", "m s^-1"}};
  // "USER POINT,Fx" is the third field; the point monitor header before it is long.
  EXPECT_STARTS_WITH(error_of(kMondata, options), "t.csv:1:108: column 'USER POINT,Fx' gives X");
}

TEST(CfxMonitorErrors, UnknownUnit) {
  const std::string message = error_of("Accumulated Timestep, Fx [furlong]\n1, 2\n");
  EXPECT_STARTS_WITH(message, "t.csv:1:23: column 'Fx [furlong]'");
  EXPECT_CONTAINS(message, "unknown unit symbol 'furlong'");
  EXPECT_CONTAINS(message, "with prefixes G M k h c d m u n");  // the library's message is not cut
}

TEST(CfxMonitorErrors, TextInAUsedValue) {
  const std::string message = error_of("\"ACCUMULATED TIMESTEP\",\"USER POINT,Fx\"\n1,1\n2,oops\n");
  EXPECT_STARTS_WITH(message, "t.csv:3:3: ");
  EXPECT_CONTAINS(message, "column 'USER POINT,Fx'");
  EXPECT_CONTAINS(message, "found 'oops', expected a number");
}

TEST(CfxMonitorErrors, TextOutsideTheWindowOrInUnusedColumnsIsNotRead) {
  EXPECT_EQ(only_run(parse("Accumulated Timestep, Fx, Note\n1, oops, a\n2, 3, b\n")).tau_b[kX]->total, 3.0);
}

TEST(CfxMonitorErrors, NanAndInfinityInAUsedValue) {
  const std::string nan = error_of("Accumulated Timestep, Fx [N]\n1, nan\n");
  EXPECT_STARTS_WITH(nan, "t.csv:2:4: ");
  EXPECT_CONTAINS(nan, "found 'nan', expected a finite number");
  EXPECT_CONTAINS(error_of("Accumulated Timestep, Fx [N]\n1, 1\n2, NaN\n", averaging(2)), "found 'NaN'");
  EXPECT_CONTAINS(error_of("Accumulated Timestep, Fx [N]\n1, -inf\n"), "expected a finite number");
}

TEST(CfxMonitorErrors, OverflowAfterConversion) {
  const std::string message = error_of("Accumulated Timestep, Fx [kN]\n1, 1e306\n");
  EXPECT_STARTS_WITH(message, "t.csv:2:4: ");
  EXPECT_CONTAINS(message, "overflows");
}

TEST(CfxMonitorErrors, ControlCharacterInAValueStaysPrintable) {
  const std::string message = error_of(std::string("Accumulated Timestep, Fx\n1, 2\x08\n"));
  EXPECT_STARTS_WITH(message, "t.csv:2:4: ");
  EXPECT_CONTAINS(message, "found '2\\x08'");
  EXPECT_TRUE(all_printable_ascii(message)) << message;
}

TEST(CfxMonitorErrors, EmptyCellInTheWindow) {
  const std::string text = "\"ACCUMULATED TIMESTEP\",\"USER POINT,Fx\",\"USER POINT,Fy\"\n1,1,2\n2,,3\n3,4,5\n";
  EXPECT_EQ(only_run(parse(text)).tau_b[kX]->total, 4.0);  // the last row alone is fine
  const std::string message = error_of(text, averaging(2));
  EXPECT_STARTS_WITH(message, "t.csv:3:3: ");
  EXPECT_CONTAINS(message, "column 'USER POINT,Fx' (X): empty cell at accumulated timestep 2");
  EXPECT_NOT_CONTAINS(message, "truncated");
}

TEST(CfxMonitorErrors, EmptyCellOnACompleteLastLineIsNotTruncation) {
  const std::string message = error_of("Accumulated Timestep, Fx, Fy\n1, 1, 2\n2, 3,\n");
  EXPECT_STARTS_WITH(message, "t.csv:3:");
  EXPECT_CONTAINS(message, "column 'Fy' (Y): empty cell");
  EXPECT_NOT_CONTAINS(message, "truncated");
}

TEST(CfxMonitorErrors, TruncatedLastLine) {
  const std::string header = "Accumulated Timestep, Fx, Fy\n1, 1, 2\n";
  const std::string missing_fields = error_of(header + "2, 3");
  EXPECT_STARTS_WITH(missing_fields, "t.csv:3: ");
  EXPECT_CONTAINS(missing_fields, "truncated");
  EXPECT_CONTAINS(missing_fields, "found 2 fields, expected 3");
  const std::string empty_cell = error_of(header + "2, 3,");
  EXPECT_STARTS_WITH(empty_cell, "t.csv:3:6: ");
  EXPECT_CONTAINS(empty_cell, "truncated");
  EXPECT_CONTAINS(empty_cell, "column 'Fy' (Y): empty cell");
  const std::string cut_number = error_of(header + "2, 3, 1.5e");
  EXPECT_STARTS_WITH(cut_number, "t.csv:3:7: ");
  EXPECT_CONTAINS(cut_number, "truncated");
  EXPECT_CONTAINS(cut_number, "found '1.5e', expected a number");
  // With its newline the same short row is simply wrong.
  const std::string complete = error_of(header + "2, 3\n");
  EXPECT_STARTS_WITH(complete, "t.csv:3: found 2 fields, expected 3");
  EXPECT_NOT_CONTAINS(complete, "truncated");
  // A short row that is not the last one is wrong too, newline or not.
  EXPECT_NOT_CONTAINS(error_of(header + "2, 3\n3, 4, 5"), "truncated");
}

TEST(CfxMonitorErrors, TooManyFields) {
  const std::string message = error_of("Accumulated Timestep, Fx\n1, 1\n2, 3, 4\n");
  EXPECT_STARTS_WITH(message, "t.csv:3:7: found 3 fields, expected 2 (as in the header on line 1)");
}

TEST(CfxMonitorErrors, WrongFieldCountOutsideTheWindow) {
  EXPECT_STARTS_WITH(error_of("Accumulated Timestep, Fx\n1\n2, 3\n"), "t.csv:2: found 1 fields, expected 2");
}

TEST(CfxMonitorErrors, FewerIterationsThanAveraged) {
  const std::string message = error_of(kMondata, averaging(4));
  EXPECT_STARTS_WITH(message, "t.csv:4: found 3 iterations, expected at least 4");
  EXPECT_STARTS_WITH(error_of("Accumulated Timestep, Fx\n5, 1\n", averaging(2)),
                     "t.csv:2: found 1 iteration, expected at least 2");
}

TEST(CfxMonitorErrors, HeaderButNoRows) {
  const std::string message = error_of("pre\nAccumulated Timestep, Fx [N]\n\n");
  EXPECT_STARTS_WITH(message, "t.csv:2: header but no data rows");
}

TEST(CfxMonitorErrors, BadTimestep) {
  EXPECT_STARTS_WITH(error_of("Accumulated Timestep, Fx\n1.5, 2\n"),
                     "t.csv:2:1: column 'Accumulated Timestep': found '1.5', expected a whole accumulated timestep");
  EXPECT_CONTAINS(error_of("Accumulated Timestep, Fx\n-1, 2\n"), "expected a whole accumulated timestep");
  EXPECT_CONTAINS(error_of("Accumulated Timestep, Fx\nabc, 2\n"), "found 'abc', expected a number");
  EXPECT_CONTAINS(error_of("Accumulated Timestep, Fx\n, 2\n"), "empty field");
  EXPECT_EQ(parse("Accumulated Timestep, Fx\n1.2e1, 2\n").summary.last_iteration, 12u);
}

TEST(CfxMonitorErrors, UnterminatedQuoteInTheHeader) {
  const std::string message = error_of("\"ACCUMULATED TIMESTEP\",\"USER POINT,Fx\n1,2\n");
  EXPECT_STARTS_WITH(message, "t.csv:1:24: ");
  EXPECT_CONTAINS(message, "unterminated");
}

// --- format detection ---------------------------------------------------------

TEST(CfxMonitorDetection, LooksLikeCfxMonitor) {
  EXPECT_TRUE(looks_like_cfx_monitor(kMondata));
  EXPECT_TRUE(looks_like_cfx_monitor(kPlotExport));
  EXPECT_TRUE(looks_like_cfx_monitor(kPlotExport.substr(0, kPlotExport.find("[kg"))));  // cut head
  EXPECT_FALSE(looks_like_cfx_monitor(""));
  EXPECT_FALSE(looks_like_cfx_monitor("u [m s^-1],X [N]\n0.1,1.5\n"));
  EXPECT_FALSE(looks_like_cfx_monitor("\n[Name]\nwall\n\n[Data]\nX [ m ], Y [ m ], Pressure [ Pa ]\n"));
  EXPECT_FALSE(looks_like_cfx_monitor("Time, Accumulated Timestep\n"));
  EXPECT_FALSE(looks_like_cfx_monitor("1\n2\n3\n4\n5\n6\n7\n8\n9\n10\nAccumulated Timestep, Fx\n"));
}

// --- read_cfx_monitor ---------------------------------------------------------

class ReadCfxMonitor : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("hydrocoef-cfx-monitor-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  fs::path write(const std::string& name, const std::string& bytes) {
    const fs::path path = dir_ / name;
    std::ofstream out(path, std::ios::binary);
    out << bytes;
    return path;
  }
  fs::path dir_;
};

TEST_F(ReadCfxMonitor, Provenance) {
  const std::string bytes = "\"ACCUMULATED TIMESTEP\",\"USER POINT,Fx\",\"USER POINT,Torque z\"\n1,2.5,-1\n2,3.5,-3\n";
  const fs::path path = write("mon.csv", bytes);
  CfxMonitorOptions options;
  options.average_last = 2;
  const MonitorImport result = read_cfx_monitor(path, options);
  EXPECT_EQ(result.batch.source.importer, "cfx-monitor");
  EXPECT_EQ(result.batch.source.importer_version, std::string(kCfxMonitorImporterVersion));
  EXPECT_EQ(result.batch.source.path, path.string());
  EXPECT_EQ(result.batch.source.size_bytes, bytes.size());
  // Worked out with sha256sum on the same bytes.
  EXPECT_EQ(result.batch.source.sha256, "70547995bd6075e9f48e5df0831eb185edce8d1b33382eff810d5ec5df148bbd");
  EXPECT_DOUBLE_EQ(only_run(result).tau_b[kX]->total, 3.0);
  EXPECT_DOUBLE_EQ(only_run(result).tau_b[kN]->total, -2.0);
  EXPECT_DOUBLE_EQ(*result.summary.relative_change[kN], -1.0);  // (-3 + 1) / 2
}

TEST_F(ReadCfxMonitor, ErrorsNameTheFilePath) {
  const fs::path path = write("bad.csv", "Accumulated Timestep, Fx\n1, oops\n");
  try {
    (void)read_cfx_monitor(path, {});
    ADD_FAILURE() << "a bad file was accepted";
  } catch (const InputError& error) {
    EXPECT_STARTS_WITH(error.what(), path.string() + ":2:4: ");
  }
  try {
    (void)read_cfx_monitor(dir_ / "missing.csv", {});
    ADD_FAILURE() << "a missing file was accepted";
  } catch (const InputError& error) {
    EXPECT_CONTAINS(error.what(), (dir_ / "missing.csv").string());
  }
}

TEST(CfxMonitorHistory, EveryIterationBecomesASampleInSi) {
  // cfx5mondata writes empty cells for monitors that start later.
  const std::string text =
      "\"ACCUMULATED TIMESTEP\",\"USER POINT,Fx\",\"USER POINT,Torque z\"\n"
      "1,,\n"
      "2,0.5,\n"
      "3,0.6,0.01\n"
      "4,0.7,0.02\n"
      "5,0.8,0.03\n";
  CfxMonitorOptions options;
  options.units = {{"X", "kN"}};
  const ForceHistory history = parse_cfx_monitor_history(text, "m.csv", options);
  ASSERT_EQ(history.size(), 3u);  // rows 1 and 2 lack a monitor used
  EXPECT_EQ(history.abscissa, HistoryAbscissa::Iteration);
  EXPECT_EQ(history.abscissa_values, (std::vector<double>{3, 4, 5}));
  EXPECT_EQ(history.values(ForcePart::Total, HistoryComponent::Fx), (std::vector<double>{600.0, 700.0, 800.0}));
  EXPECT_EQ(history.values(ForcePart::Total, HistoryComponent::Mz), (std::vector<double>{0.01, 0.02, 0.03}));
  EXPECT_FALSE(history.has(ForcePart::Total, HistoryComponent::Fy));
  EXPECT_EQ(history.force_origin.at(0).line, 4u);
  EXPECT_EQ(history.moment_origin.at(2).line, 6u);
  ASSERT_EQ(history.notes.size(), 1u);
  EXPECT_NE(history.notes[0].find("2 leading rows"), std::string::npos) << history.notes[0];
  EXPECT_EQ(history.files.at(0).rows, 5u);
  EXPECT_EQ(history.files.at(0).rows_used, 3u);
  EXPECT_EQ(history.files.at(0).sha256.size(), 64u);
}

TEST(CfxMonitorHistory, GapsAndTimestepsThatGoBackAreRefusedWithTheirLine) {
  const std::string header = "Accumulated Timestep, Fx1 [N], Torque z1 [J]\n";
  try {
    (void)parse_cfx_monitor_history(header + "1, 0.5, 0.1\n2, , 0.1\n3, 0.5, 0.1\n", "gap.csv", {});
    FAIL() << "a gap was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("gap.csv:3:"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("empty cell at accumulated timestep 2"), std::string::npos)
        << error.what();
  }
  try {
    (void)parse_cfx_monitor_history(header + "1, 0.5, 0.1\n3, 0.5, 0.1\n2, 0.5, 0.1\n", "back.csv", {});
    FAIL() << "a timestep going back was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("back.csv:4:"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("accumulated timestep 2 after 3 on line 3"), std::string::npos)
        << error.what();
  }
  CfxMonitorOptions five;
  five.average_last = 5;
  try {
    (void)parse_cfx_monitor_history(header + "1, 0.5, 0.1\n2, 0.4, 0.1\n", "few.csv", five);
    FAIL() << "too few rows for --average-last were accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("few.csv:3:"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("found 2 iterations, expected at least 5"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace hydrocoef
