// The force-table importer: the real ASR-V tables, line endings, comments,
// CFX-style headers and units converted to SI, delimiters, column order, the
// options (column mapping, units, disturbances, ignored columns, sign, fluid,
// reference point), every refusal with its location and message, and the
// provenance of read_force_table. Expected values are the numbers written in
// the input times the unit's SI factor worked out by hand.
#include "importers/force_table.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "src/core/error.hpp"
#include "src/core/source_file.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kU = 0, kR = 5;
constexpr std::size_t kX = 0, kY = 1, kN = 5;

#define EXPECT_CONTAINS(haystack, needle) \
  EXPECT_NE(std::string(haystack).find(needle), std::string::npos) << "expected '" << (needle) << "' in: " << (haystack)
#define EXPECT_STARTS_WITH(text, prefix) \
  EXPECT_EQ(std::string(text).rfind(prefix, 0), 0u) << "expected it to start with '" << (prefix) << "': " << (text)

fs::path example(const std::string& name) { return fs::path(HYDROCOEF_SOURCE_DIR) / "examples/asr-v" / name; }

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in) << path;
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string to_crlf(const std::string& lf) {
  std::string out;
  for (const char c : lf) {
    if (c == '\n') out += '\r';
    out += c;
  }
  return out;
}

// The InputError message for parsing `text` as "t.csv"; fails if it is accepted.
std::string error_of(std::string_view text, const ForceTableOptions& options = {}) {
  try {
    const auto runs = parse_force_table(text, "t.csv", options);
    ADD_FAILURE() << "accepted with " << runs.size() << " runs:\n" << text;
  } catch (const InputError& error) {
    return error.what();
  }
  return {};
}

void expect_same_runs(const std::vector<ImportedRun>& a, const std::vector<ImportedRun>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].key.body, b[i].key.body) << i;
    EXPECT_EQ(a[i].key.nu_b, b[i].key.nu_b) << i;
    EXPECT_EQ(a[i].key.disturbances, b[i].key.disturbances) << i;
    EXPECT_EQ(a[i].source_line, b[i].source_line) << i;
    EXPECT_EQ(a[i].sign, b[i].sign) << i;
    for (std::size_t c = 0; c < 6; ++c) {
      ASSERT_EQ(a[i].tau_b[c].has_value(), b[i].tau_b[c].has_value()) << i << "," << c;
      if (a[i].tau_b[c]) {
        EXPECT_EQ(a[i].tau_b[c]->total, b[i].tau_b[c]->total) << i << "," << c;
      }
    }
  }
}

// --- the real ASR-V tables -------------------------------------------------

const std::vector<double> kSurgeU = {0.00, 0.02, 0.04, 0.06, 0.08, 0.10, 0.12, 0.14, 0.16, 0.18,
                                     0.20, 0.22, 0.24, 0.26, 0.28, 0.30, 0.32, 0.34, 0.36, 0.38};
const std::vector<double> kSurgeX = {-0.00020, 0.00544, 0.01928, 0.04186, 0.07293, 0.11278, 0.16119,
                                     0.21879,  0.28528, 0.36097, 0.44516, 0.53802, 0.63986, 0.75051,
                                     0.87046,  0.99881, 1.13579, 1.28167, 1.43652, 1.60013};
const std::vector<double> kYawR = {0.0000, 0.0116, 0.0232, 0.0349, 0.0465, 0.0582, 0.0698, 0.0814, 0.0932, 0.1047,
                                   0.1163, 0.1400, 0.1570, 0.1745, 0.1919, 0.2094, 0.2268, 0.2443, 0.2617, 0.2792};
const std::vector<double> kYawN = {-0.00006, -0.00015, -0.00016, -0.00023, -0.00036, -0.00053, -0.00067,
                                   -0.00102, -0.00127, -0.00132, -0.00180, -0.00240, -0.00287, -0.00343,
                                   -0.00402, -0.00467, -0.00532, -0.00607, -0.00682, -0.00766};

TEST(ForceTable, RealSurgeTable) {
  ForceTableOptions options;
  options.body = "asr-v";
  const auto runs = parse_force_table(read_bytes(example("asr-v-surge-damping.csv")), "surge.csv", options);
  ASSERT_EQ(runs.size(), 20u);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const ImportedRun& run = runs[i];
    EXPECT_EQ(run.key.body, "asr-v");
    EXPECT_EQ(run.source_line, i + 3) << i;  // comment on line 1, header on line 2
    std::array<double, 6> nu{};
    nu[kU] = kSurgeU[i];
    EXPECT_EQ(run.key.nu_b, nu) << i;
    EXPECT_TRUE(run.key.disturbances.empty());
    ASSERT_TRUE(run.tau_b[kX].has_value()) << i;
    EXPECT_EQ(run.tau_b[kX]->total, kSurgeX[i]) << i;
    EXPECT_FALSE(run.tau_b[kX]->pressure.has_value());
    EXPECT_FALSE(run.tau_b[kX]->viscous.has_value());
    for (std::size_t c = 1; c < 6; ++c) EXPECT_FALSE(run.tau_b[c].has_value()) << i << "," << c;
  }
}

TEST(ForceTable, RealYawTable) {
  ForceTableOptions options;
  options.body = "asr-v";
  const auto runs = parse_force_table(read_bytes(example("asr-v-yaw-damping.csv")), "yaw.csv", options);
  ASSERT_EQ(runs.size(), 20u);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const ImportedRun& run = runs[i];
    EXPECT_EQ(run.source_line, i + 3) << i;
    std::array<double, 6> nu{};
    nu[kR] = kYawR[i];
    EXPECT_EQ(run.key.nu_b, nu) << i;
    ASSERT_TRUE(run.tau_b[kN].has_value()) << i;
    EXPECT_EQ(run.tau_b[kN]->total, kYawN[i]) << i;
    for (std::size_t c = 0; c < 5; ++c) EXPECT_FALSE(run.tau_b[c].has_value()) << i << "," << c;
  }
}

TEST(ForceTable, CrlfFileEqualsLfFile) {
  const std::string lf = read_bytes(example("asr-v-surge-damping.csv"));
  ASSERT_EQ(lf.find('\r'), std::string::npos);
  const std::string crlf = to_crlf(lf);
  ASSERT_NE(crlf, lf);
  expect_same_runs(parse_force_table(crlf, "t.csv", {}), parse_force_table(lf, "t.csv", {}));
  const std::string yaw = read_bytes(example("asr-v-yaw-damping.csv"));
  expect_same_runs(parse_force_table(to_crlf(yaw), "t.csv", {}), parse_force_table(yaw, "t.csv", {}));
}

TEST(ForceTable, NoFinalNewline) {
  const auto runs = parse_force_table("u [m s^-1],X [N]\n0.1,1.5\n0.2,6", "t.csv", {});
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[1].key.nu_b[kU], 0.2);
  EXPECT_EQ(runs[1].tau_b[kX]->total, 6.0);
}

TEST(ForceTable, CommentsAndBlankLinesAnywhere) {
  const std::string text =
      "\n"                    // 1
      "# leading comment\n"   // 2
      "   \n"                 // 3
      "u [m s^-1],X [N]\n"    // 4: header
      "# between\n"           // 5
      "0.1,1.0\n"             // 6
      "\n"                    // 7
      "   # indented, 9,9\n"  // 8
      "\t\n"                  // 9
      "0.2,4.0\n"             // 10
      "# trailing\n"          // 11
      "\n";                   // 12
  const auto runs = parse_force_table(text, "t.csv", {});
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].source_line, 6u);
  EXPECT_EQ(runs[1].source_line, 10u);
  EXPECT_EQ(runs[0].key.nu_b[kU], 0.1);
  EXPECT_EQ(runs[1].key.nu_b[kU], 0.2);
  EXPECT_EQ(runs[0].tau_b[kX]->total, 1.0);
  EXPECT_EQ(runs[1].tau_b[kX]->total, 4.0);
  // The same text with CRLF endings gives the same runs and lines.
  expect_same_runs(parse_force_table(to_crlf(text), "t.csv", {}), runs);
}

// --- headers and units -----------------------------------------------------

TEST(ForceTable, CfxBracketsWithSpacesAndCommaSpaceSeparator) {
  const auto runs =
      parse_force_table("u [ m s^-1 ], X [ N ], N [ N m ]\n 1.00000000e-01, 2.5e+00, -3.0e-01\n", "t.csv", {});
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].key.nu_b[kU], 0.1);
  EXPECT_EQ(runs[0].tau_b[kX]->total, 2.5);
  EXPECT_EQ(runs[0].tau_b[kN]->total, -0.3);
}

TEST(ForceTable, MillimetresPerSecond) {
  const auto runs = parse_force_table("u [mm s^-1],X [N]\n100,1\n250,2\n", "t.csv", {});
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_DOUBLE_EQ(runs[0].key.nu_b[kU], 0.1);   // 100 mm/s
  EXPECT_DOUBLE_EQ(runs[1].key.nu_b[kU], 0.25);  // 250 mm/s
}

TEST(ForceTable, KilonewtonsAndKilometresPerHour) {
  const auto runs = parse_force_table("u [km h^-1],X [kN],Y [kN]\n3.6,1.5,-0.002\n", "t.csv", {});
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_DOUBLE_EQ(runs[0].key.nu_b[kU], 1.0);  // 3.6 km/h = 1 m/s
  EXPECT_DOUBLE_EQ(runs[0].tau_b[kX]->total, 1500.0);
  EXPECT_DOUBLE_EQ(runs[0].tau_b[kY]->total, -2.0);
}

TEST(ForceTable, DegreesPerSecondAndNewtonMetres) {
  const auto runs = parse_force_table("r [deg s^-1],N [N m]\n10,-0.5\n-90,0.25\n", "t.csv", {});
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_DOUBLE_EQ(runs[0].key.nu_b[kR], 10.0 * std::numbers::pi / 180.0);
  EXPECT_DOUBLE_EQ(runs[1].key.nu_b[kR], -std::numbers::pi / 2.0);
  EXPECT_EQ(runs[0].tau_b[kN]->total, -0.5);
  EXPECT_EQ(runs[1].tau_b[kN]->total, 0.25);
}

TEST(ForceTable, AngularVelocityInInverseSecondsAndTorqueInJoules) {
  const auto runs = parse_force_table("r [s^-1],N [J],K [kN.m]\n0.2,-0.5,0.001\n", "t.csv", {});
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].key.nu_b[kR], 0.2);
  EXPECT_EQ(runs[0].tau_b[kN]->total, -0.5);
  EXPECT_DOUBLE_EQ(runs[0].tau_b[3]->total, 1.0);
}

TEST(ForceTable, TabSeparated) {
  const auto runs = parse_force_table("u [m s^-1]\tX [N]\n0.1\t1.5\n0.2\t6\n", "t.tsv", {});
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[1].key.nu_b[kU], 0.2);
  EXPECT_EQ(runs[1].tau_b[kX]->total, 6.0);
}

TEST(ForceTable, SemicolonSeparated) {
  const auto runs = parse_force_table("u [m s^-1];X [N]\n0.1;1.5\n0.2;6\n", "t.csv", {});
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].key.nu_b[kU], 0.1);
  EXPECT_EQ(runs[0].tau_b[kX]->total, 1.5);
}

TEST(ForceTable, QuotedHeaders) {
  const auto runs = parse_force_table("\"u [m s^-1]\",\"X [N]\"\n0.1,1.5\n", "t.csv", {});
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].tau_b[kX]->total, 1.5);
}

TEST(ForceTable, ColumnOrderIsNotFixed) {
  const auto runs = parse_force_table("N [N m],X [N],r [rad s^-1],u [m s^-1]\n-0.1,2,0.3,0.4\n", "t.csv", {});
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].key.nu_b[kU], 0.4);
  EXPECT_EQ(runs[0].key.nu_b[kR], 0.3);
  EXPECT_EQ(runs[0].tau_b[kX]->total, 2.0);
  EXPECT_EQ(runs[0].tau_b[kN]->total, -0.1);
  EXPECT_FALSE(runs[0].tau_b[kY].has_value());
}

// --- options ---------------------------------------------------------------

TEST(ForceTable, ColumnMapping) {
  ForceTableOptions options;
  options.columns = {{"X", "Drag"}, {"u", "Speed"}};
  const auto runs = parse_force_table("Speed [m s^-1],Drag [kN]\n0.5,0.002\n", "t.csv", options);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].key.nu_b[kU], 0.5);
  ASSERT_TRUE(runs[0].tau_b[kX].has_value());
  EXPECT_DOUBLE_EQ(runs[0].tau_b[kX]->total, 2.0);
}

TEST(ForceTable, UnitsForHeadersWithoutBrackets) {
  ForceTableOptions options;
  options.units = {{"u", "mm s^-1"}, {"X", "N"}};
  const auto runs = parse_force_table("u,X\n500,3\n", "t.csv", options);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_DOUBLE_EQ(runs[0].key.nu_b[kU], 0.5);
  EXPECT_EQ(runs[0].tau_b[kX]->total, 3.0);
}

TEST(ForceTable, UnitsOverrideBrackets) {
  ForceTableOptions options;
  options.units = {{"X", "kN"}};
  const auto runs = parse_force_table("u [m s^-1],X [N]\n0.1,2\n", "t.csv", options);
  EXPECT_DOUBLE_EQ(runs.at(0).tau_b[kX]->total, 2000.0);
}

TEST(ForceTable, MappedColumnWithUnitOption) {
  ForceTableOptions options;
  options.columns = {{"X", "Drag"}};
  options.units = {{"X", "N"}};
  const auto runs = parse_force_table("u [m s^-1],Drag\n0.1,7\n", "t.csv", options);
  EXPECT_EQ(runs.at(0).tau_b[kX]->total, 7.0);
}

TEST(ForceTable, DisturbanceColumnsMakeASweep) {
  ForceTableOptions options;
  options.disturbance_columns = {"current_v"};
  const auto runs = parse_force_table(
      "u [m s^-1],current_v [m s^-1],X [N]\n"
      "0.1,0,1.0\n"
      "0.1,0.05,1.2\n"
      "0.2,0.05,2.0\n",
      "t.csv", options);
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[0].key.disturbances, (std::map<std::string, double>{{"current_v", 0.0}}));
  EXPECT_EQ(runs[1].key.disturbances, (std::map<std::string, double>{{"current_v", 0.05}}));
  EXPECT_EQ(runs[2].key.disturbances, (std::map<std::string, double>{{"current_v", 0.05}}));
  EXPECT_EQ(runs[1].key.nu_b[kU], 0.1);
  EXPECT_EQ(runs[1].tau_b[kX]->total, 1.2);
}

TEST(ForceTable, DisturbanceColumnUnitIsConvertedToSi) {
  ForceTableOptions options;
  options.disturbance_columns = {"current_v"};
  const auto runs = parse_force_table("u [m s^-1],current_v [mm s^-1],X [N]\n0.1,50,1\n", "t.csv", options);
  EXPECT_DOUBLE_EQ(runs.at(0).key.disturbances.at("current_v"), 0.05);
}

TEST(ForceTable, DisturbanceColumnWithoutVelocityColumn) {
  // A current sweep of a body at rest: the disturbance column is the key.
  ForceTableOptions options;
  options.disturbance_columns = {"current_v"};
  const auto runs = parse_force_table("current_v [m s^-1],Y [N]\n0.05,1\n0.10,4\n", "t.csv", options);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[1].key.disturbances.at("current_v"), 0.1);
  EXPECT_EQ(runs[1].key.nu_b, (std::array<double, 6>{}));
}

TEST(ForceTable, SetDisturbancesApplyToEveryRow) {
  ForceTableOptions options;
  options.disturbances = {{"current_v", 0.05}, {"wave_h", 0.1}};
  const auto runs = parse_force_table("u [m s^-1],X [N]\n0.1,1\n0.2,4\n0.3,9\n", "t.csv", options);
  ASSERT_EQ(runs.size(), 3u);
  for (const auto& run : runs) EXPECT_EQ(run.key.disturbances, options.disturbances);
}

TEST(ForceTable, SetDisturbancesCombineWithDisturbanceColumns) {
  ForceTableOptions options;
  options.disturbances = {{"wave_h", 0.1}};
  options.disturbance_columns = {"current_v"};
  const auto runs = parse_force_table("u [m s^-1],current_v [m s^-1],X [N]\n0.1,0.05,1\n", "t.csv", options);
  EXPECT_EQ(runs.at(0).key.disturbances, (std::map<std::string, double>{{"current_v", 0.05}, {"wave_h", 0.1}}));
}

TEST(ForceTable, IgnoredColumnsAreNotParsed) {
  ForceTableOptions options;
  options.ignored_columns = {"Node Number", "Comment", "Pressure"};
  const auto runs = parse_force_table(
      "Node Number,u [m s^-1],Comment,X [N],Pressure [ Pa ]\n"
      "7,0.1,first,1.5,null\n"
      "8,0.2,,6,abc\n",
      "t.csv", options);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].key.nu_b[kU], 0.1);
  EXPECT_EQ(runs[1].tau_b[kX]->total, 6.0);
  EXPECT_TRUE(runs[0].key.disturbances.empty());
}

TEST(ForceTable, SignFluidAndReferencePointAreCopiedIntoEveryRun) {
  ForceTableOptions options;
  options.body = "asr-v";
  options.sign = SignConvention::OpposingMotion;
  options.fluid.density_kg_m3 = 998.2;
  options.fluid.kinematic_viscosity_m2_s = 1.004e-6;
  options.reference_point_b = {0.1, -0.2, 0.05};
  const auto runs = parse_force_table("u [m s^-1],X [N]\n0.1,1\n0.2,4\n", "t.csv", options);
  ASSERT_EQ(runs.size(), 2u);
  for (const auto& run : runs) {
    EXPECT_EQ(run.key.body, "asr-v");
    EXPECT_EQ(run.sign, SignConvention::OpposingMotion);
    ASSERT_TRUE(run.fluid.density_kg_m3.has_value());
    EXPECT_EQ(*run.fluid.density_kg_m3, 998.2);
    ASSERT_TRUE(run.fluid.kinematic_viscosity_m2_s.has_value());
    EXPECT_EQ(*run.fluid.kinematic_viscosity_m2_s, 1.004e-6);
    EXPECT_EQ(run.reference_point_b, (std::array<double, 3>{0.1, -0.2, 0.05}));
  }
}

TEST(ForceTable, DefaultsWhenNoOptionsAreGiven) {
  const auto runs = parse_force_table("u [m s^-1],X [N]\n0.1,1\n", "t.csv", {});
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].key.body, "vehicle");
  EXPECT_EQ(runs[0].sign, SignConvention::OnBody);
  EXPECT_FALSE(runs[0].fluid.density_kg_m3.has_value());
  EXPECT_FALSE(runs[0].fluid.kinematic_viscosity_m2_s.has_value());
  EXPECT_EQ(runs[0].reference_point_b, (std::array<double, 3>{}));
}

TEST(ForceTable, SourceLineIsTheFileLine) {
  const auto runs = parse_force_table("# c\n# c\nu [m s^-1],X [N]\n\n0.1,1\n# c\n0.2,4\n", "t.csv", {});
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].source_line, 5u);
  EXPECT_EQ(runs[1].source_line, 7u);
}

// --- refusals: header ------------------------------------------------------

TEST(ForceTableErrors, UnknownUnit) {
  const std::string message = error_of("u [m s^-1],X [furlong]\n0.1,1\n");
  EXPECT_STARTS_WITH(message, "t.csv:1:12: ");
  EXPECT_CONTAINS(message, "'X [furlong]'");
  EXPECT_CONTAINS(message, "unknown unit symbol 'furlong'");
  EXPECT_CONTAINS(message, "known:");
}

TEST(ForceTableErrors, ForceUnitForAVelocity) {
  const std::string message = error_of("u [N],X [N]\n0.1,1\n");
  EXPECT_STARTS_WITH(message, "t.csv:1:1: ");
  EXPECT_CONTAINS(message, "'u [N]'");
  EXPECT_CONTAINS(message, "is kg m s^-2");
  EXPECT_CONTAINS(message, "expected m s^-1");
}

TEST(ForceTableErrors, MomentUnitForAForce) {
  const std::string message = error_of("u [m s^-1],X [N m]\n0.1,1\n");
  EXPECT_STARTS_WITH(message, "t.csv:1:12: ");
  EXPECT_CONTAINS(message, "'X [N m]'");
  EXPECT_CONTAINS(message, "is kg m^2 s^-2");
  EXPECT_CONTAINS(message, "expected kg m s^-2");
}

TEST(ForceTableErrors, ForceUnitForAMoment) {
  const std::string message = error_of("r [rad s^-1],N [N]\n0.1,1\n");
  EXPECT_STARTS_WITH(message, "t.csv:1:14: ");
  EXPECT_CONTAINS(message, "'N [N]'");
  EXPECT_CONTAINS(message, "expected kg m^2 s^-2");
}

TEST(ForceTableErrors, AngularUnitForALinearVelocity) {
  const std::string message = error_of("u [deg s^-1],X [N]\n0.1,1\n");
  EXPECT_STARTS_WITH(message, "t.csv:1:1: ");
  EXPECT_CONTAINS(message, "'u [deg s^-1]'");
  EXPECT_CONTAINS(message, "is rad s^-1");
  EXPECT_CONTAINS(message, "expected m s^-1");
}

TEST(ForceTableErrors, LinearUnitForAnAngularVelocity) {
  const std::string message = error_of("X [N],r [m s^-1]\n1,0.1\n");
  EXPECT_STARTS_WITH(message, "t.csv:1:7: ");
  EXPECT_CONTAINS(message, "'r [m s^-1]'");
  EXPECT_CONTAINS(message, "expected rad s^-1");
}

TEST(ForceTableErrors, HeaderWithoutUnit) {
  const std::string message = error_of("# c\nu [m s^-1],X\n0.1,1\n");
  EXPECT_STARTS_WITH(message, "t.csv:2:12: ");
  EXPECT_CONTAINS(message, "'X'");
  EXPECT_CONTAINS(message, "no unit");
  EXPECT_CONTAINS(message, "X [N]");
}

TEST(ForceTableErrors, UnknownColumn) {
  const std::string message = error_of("u [m s^-1],Drag [N]\n0.1,1\n");
  EXPECT_STARTS_WITH(message, "t.csv:1:12: ");
  EXPECT_CONTAINS(message, "'Drag [N]'");
  EXPECT_CONTAINS(message, "X Y Z K M N");
  EXPECT_CONTAINS(message, "--column X=Drag");
}

TEST(ForceTableErrors, LowerCaseForceNameIsUnknown) {
  const std::string message = error_of("u [m s^-1],x [N]\n0.1,1\n");
  EXPECT_STARTS_WITH(message, "t.csv:1:12: ");
  EXPECT_CONTAINS(message, "'x [N]'");
}

TEST(ForceTableErrors, DuplicatedComponent) {
  const std::string message = error_of("u [m s^-1],X [N],X [kN]\n0.1,1,0.001\n");
  EXPECT_STARTS_WITH(message, "t.csv:1:18: ");
  EXPECT_CONTAINS(message, "'X [kN]'");
  EXPECT_CONTAINS(message, "column 12");
}

TEST(ForceTableErrors, DuplicatedComponentThroughMapping) {
  ForceTableOptions options;
  options.columns = {{"X", "Drag"}};
  const std::string message = error_of("X [N],u [m s^-1],Drag [N]\n1,0.1,1\n", options);
  EXPECT_STARTS_WITH(message, "t.csv:1:18: ");
  EXPECT_CONTAINS(message, "'Drag [N]'");
  EXPECT_CONTAINS(message, "'X'");
}

TEST(ForceTableErrors, DisturbanceColumnAndSetBothGiveIt) {
  ForceTableOptions options;
  options.disturbance_columns = {"current_v"};
  options.disturbances = {{"current_v", 0.05}};
  const std::string message = error_of("u [m s^-1],current_v [m s^-1],X [N]\n0.1,0.05,1\n", options);
  EXPECT_STARTS_WITH(message, "t.csv:1:12: ");
  EXPECT_CONTAINS(message, "current_v");
}

TEST(ForceTableErrors, BadUnitOfADisturbanceColumnHasItsLocation) {
  // Regression test: this input once slipped through (see the commit that fixed it).
  ForceTableOptions options;
  options.disturbance_columns = {"current_v"};
  const std::string message = error_of("u [m s^-1],current_v [furlong],X [N]\n0.1,1,1\n", options);
  EXPECT_CONTAINS(message, "furlong");
  EXPECT_STARTS_WITH(message, "t.csv:1:12: ");
  EXPECT_CONTAINS(message, "'current_v [furlong]'");
}

TEST(ForceTableErrors, EmptyHeaderField) {
  const std::string message = error_of("u [m s^-1],,X [N]\n0.1,2,1\n");
  EXPECT_STARTS_WITH(message, "t.csv:1:12: ");
  EXPECT_CONTAINS(message, "empty column header");
}

TEST(ForceTableErrors, NoForceColumn) {
  const std::string message = error_of("u [m s^-1],v [m s^-1]\n0.1,0\n");
  EXPECT_STARTS_WITH(message, "t.csv:1: ");
  EXPECT_CONTAINS(message, "no force or moment column");
  EXPECT_CONTAINS(message, "X Y Z K M N");
}

TEST(ForceTableErrors, OnlyIgnoredAndVelocityColumns) {
  ForceTableOptions options;
  options.ignored_columns = {"X"};
  const std::string message = error_of("u [m s^-1],X [N]\n0.1,1\n", options);
  EXPECT_STARTS_WITH(message, "t.csv:1: ");
  EXPECT_CONTAINS(message, "no force or moment column");
}

TEST(ForceTableErrors, NoVelocityColumn) {
  const std::string message = error_of("# c\nX [N],N [N m]\n1,2\n");
  EXPECT_STARTS_WITH(message, "t.csv:2: ");
  EXPECT_CONTAINS(message, "no velocity column");
  EXPECT_CONTAINS(message, "u v w p q r");
}

TEST(ForceTableErrors, EmptyBodyName) {
  ForceTableOptions options;
  options.body = "";
  EXPECT_CONTAINS(error_of("u [m s^-1],X [N]\n0.1,1\n", options), "body");
}

// --- refusals: rows --------------------------------------------------------

TEST(ForceTableErrors, TextInANumberField) {
  const std::string message = error_of("u [m s^-1],X [N]\n0.1,abc\n");
  EXPECT_STARTS_WITH(message, "t.csv:2:5: ");
  EXPECT_CONTAINS(message, "'X [N]'");
  EXPECT_CONTAINS(message, "found 'abc'");
  EXPECT_CONTAINS(message, "expected a number");
}

TEST(ForceTableErrors, TextInAVelocityFieldAfterCommaSpace) {
  const std::string message = error_of("u [ m s^-1 ], X [ N ]\n1.0e-01, 2.0e+00\n null, 3.0\n");
  EXPECT_STARTS_WITH(message, "t.csv:3:2: ");
  EXPECT_CONTAINS(message, "'u [ m s^-1 ]'");
  EXPECT_CONTAINS(message, "found 'null'");
}

TEST(ForceTableErrors, NotANumber) {
  const std::string message = error_of("u [m s^-1],X [N]\n0.1,1\n0.2,NaN\n");
  EXPECT_STARTS_WITH(message, "t.csv:3:5: ");
  EXPECT_CONTAINS(message, "'X [N]'");
  EXPECT_CONTAINS(message, "'NaN'");
  EXPECT_CONTAINS(message, "expected a finite number");
}

TEST(ForceTableErrors, Infinity) {
  const std::string message = error_of("u [m s^-1],X [N]\ninf,1\n");
  EXPECT_STARTS_WITH(message, "t.csv:2:1: ");
  EXPECT_CONTAINS(message, "'u [m s^-1]'");
  EXPECT_CONTAINS(message, "'inf'");
  EXPECT_CONTAINS(message, "expected a finite number");
}

TEST(ForceTableErrors, OverflowAfterScaling) {
  // Regression test: this input once slipped through (see the commit that fixed it).
  const std::string message = error_of("u [m s^-1],X [kN]\n0.1,1e308\n");
  EXPECT_CONTAINS(message, "t.csv:2");
  EXPECT_CONTAINS(message, "X [kN]");
}

TEST(ForceTableErrors, EmptyField) {
  const std::string message = error_of("u [m s^-1],X [N]\n0.1,\n");
  EXPECT_STARTS_WITH(message, "t.csv:2:5: ");
  EXPECT_CONTAINS(message, "'X [N]'");
  EXPECT_CONTAINS(message, "empty field");
  EXPECT_CONTAINS(message, "expected a number");
}

TEST(ForceTableErrors, TooFewFields) {
  const std::string message = error_of("u [m s^-1],X [N],Y [N]\n0.1,1,2\n0.2,4\n");
  EXPECT_STARTS_WITH(message, "t.csv:3: ");
  EXPECT_CONTAINS(message, "found 2 fields, expected 3");
  EXPECT_CONTAINS(message, "line 1");
}

TEST(ForceTableErrors, TooManyFields) {
  const std::string message = error_of("# c\nu [m s^-1],X [N]\n0.1,1,2\n");
  EXPECT_STARTS_WITH(message, "t.csv:3: ");
  EXPECT_CONTAINS(message, "found 3 fields, expected 2");
  EXPECT_CONTAINS(message, "line 2");
}

TEST(ForceTableErrors, DuplicateRunKey) {
  ForceTableOptions options;
  options.body = "asr-v";
  const std::string message = error_of("u [m s^-1],X [N]\n0.1,1\n0.2,4\n0.10,1.1\n", options);
  EXPECT_STARTS_WITH(message, "t.csv:4: ");
  EXPECT_CONTAINS(message, "asr-v u=0.1");
  EXPECT_CONTAINS(message, "line 2");
}

TEST(ForceTableErrors, DuplicateRunKeyAtRestWithNegativeZero) {
  const std::string message = error_of("u [m s^-1],X [N]\n0,1\n-0,1.1\n");
  EXPECT_STARTS_WITH(message, "t.csv:3: ");
  EXPECT_CONTAINS(message, "line 2");
}

TEST(ForceTableErrors, DuplicateRunKeyInADisturbanceSweep) {
  ForceTableOptions options;
  options.disturbance_columns = {"current_v"};
  const std::string message =
      error_of("u [m s^-1],current_v [m s^-1],X [N]\n0.1,0.05,1\n0.1,0.1,1\n0.1,0.05,2\n", options);
  EXPECT_STARTS_WITH(message, "t.csv:4: ");
  EXPECT_CONTAINS(message, "line 2");
}

TEST(ForceTableErrors, DuplicateRunKeyWithNegativeZeroDisturbance) {
  // Regression test: this input once slipped through (see the commit that fixed it).
  ForceTableOptions options;
  options.disturbance_columns = {"current_v"};
  const std::string message = error_of("u [m s^-1],current_v [m s^-1],X [N]\n0.1,0,1\n0.1,-0,2\n", options);
  EXPECT_STARTS_WITH(message, "t.csv:3: ");
  EXPECT_CONTAINS(message, "line 2");
}

TEST(ForceTableErrors, EmptyFile) {
  const std::string message = error_of("");
  EXPECT_STARTS_WITH(message, "t.csv: ");
  EXPECT_CONTAINS(message, "no header line");
}

TEST(ForceTableErrors, OnlyComments) {
  const std::string message = error_of("# one\n\n   # two\r\n\t\n");
  EXPECT_STARTS_WITH(message, "t.csv: ");
  EXPECT_CONTAINS(message, "no header line");
}

TEST(ForceTableErrors, HeaderButNoRows) {
  const std::string message = error_of("# c\nu [m s^-1],X [N]\n# nothing yet\n\n");
  EXPECT_STARTS_WITH(message, "t.csv:2: ");
  EXPECT_CONTAINS(message, "no data rows");
}

TEST(ForceTableErrors, TruncatedLastRow) {
  const std::string short_row = error_of("u [m s^-1],X [N]\n0.1,1\n0.2");
  EXPECT_STARTS_WITH(short_row, "t.csv:3: ");
  EXPECT_CONTAINS(short_row, "found 1 fields, expected 2");
  const std::string cut_after_delimiter = error_of("u [m s^-1],X [N]\n0.1,1\n0.2,");
  EXPECT_STARTS_WITH(cut_after_delimiter, "t.csv:3:5: ");
  EXPECT_CONTAINS(cut_after_delimiter, "'X [N]'");
  EXPECT_CONTAINS(cut_after_delimiter, "empty field");
  const std::string cut_in_number = error_of("u [m s^-1],X [N]\n0.1,1\n0.2,1.5e");
  EXPECT_STARTS_WITH(cut_in_number, "t.csv:3:5: ");
  EXPECT_CONTAINS(cut_in_number, "'1.5e'");
}

TEST(ForceTableErrors, UnterminatedQuoteInARow) {
  const std::string message = error_of("u [m s^-1],X [N]\n0.1,\"1\n");
  EXPECT_STARTS_WITH(message, "t.csv:2:5: ");
  EXPECT_CONTAINS(message, "unterminated");
}

// --- read_force_table ------------------------------------------------------

TEST(ReadForceTable, RealFileProvenance) {
  const fs::path path = example("asr-v-surge-damping.csv");
  const std::string bytes = read_bytes(path);
  ASSERT_FALSE(bytes.empty());
  ForceTableOptions options;
  options.body = "asr-v";
  options.sign = SignConvention::OpposingMotion;
  const ImportBatch batch = read_force_table(path, options);
  EXPECT_EQ(batch.source.importer, "force-table");
  EXPECT_EQ(batch.source.importer_version, std::string(kForceTableImporterVersion));
  EXPECT_EQ(batch.source.path, path.string());
  EXPECT_EQ(batch.source.size_bytes, bytes.size());
  EXPECT_EQ(batch.source.sha256, sha256_hex(bytes));
  EXPECT_EQ(batch.source.sha256.size(), 64u);
  expect_same_runs(batch.runs, parse_force_table(bytes, path.string(), options));
  ASSERT_EQ(batch.runs.size(), 20u);
  EXPECT_EQ(batch.runs.back().tau_b[kX]->total, 1.60013);
  EXPECT_EQ(batch.runs.back().sign, SignConvention::OpposingMotion);
}

TEST(ReadForceTable, ErrorsNameTheFilePath) {
  const fs::path dir = fs::temp_directory_path() / ("hydrocoef-force-table-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path path = dir / "bad.csv";
  {
    std::ofstream out(path, std::ios::binary);
    out << "u [m s^-1],X [N]\n0.1,oops\n";
  }
  try {
    (void)read_force_table(path, {});
    ADD_FAILURE() << "a bad file was accepted";
  } catch (const InputError& error) {
    EXPECT_STARTS_WITH(error.what(), path.string() + ":2:5: ");
  }
  try {
    (void)read_force_table(dir / "missing.csv", {});
    ADD_FAILURE() << "a missing file was accepted";
  } catch (const InputError& error) {
    EXPECT_CONTAINS(error.what(), (dir / "missing.csv").string());
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
}

}  // namespace
}  // namespace hydrocoef
