// The captive-test table importer: each row's key (u = U cos beta, v = -+U
// sin beta by the stated drift convention, r = r' U / L, delta in rad) and
// its forces made dimensional in the prime, bis and MMG forms, worked out by
// hand from the numbers written; where each reference value comes from (an
// option over the file's line over the body's stored data); blank-separated
// tables; and every refusal with its file, line and column.
#include "importers/captive_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "src/core/error.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

constexpr std::size_t kU = 0, kV = 1, kW = 2, kR = 5;
constexpr std::size_t kX = 0, kY = 1, kK = 3, kN = 5;
constexpr double kDeg = std::numbers::pi / 180.0;

#define EXPECT_CONTAINS(haystack, needle) \
  EXPECT_NE(std::string(haystack).find(needle), std::string::npos) << "expected '" << (needle) << "' in: " << (haystack)

std::string error_of(std::string_view text, const CaptiveTableOptions& options = {}) {
  try {
    const auto table = parse_captive_table(text, "captive.csv", options);
    ADD_FAILURE() << "accepted with " << table.runs.size() << " runs:\n" << text;
  } catch (const InputError& error) {
    return error.what();
  }
  return {};
}

// L = 4 m, rho = 1000 kg/m^3; the row at U = 2 m/s, beta = 10 deg, r' = 0.3, delta = -5 deg.
const std::string kPrime =
    "# A prime-form table\n"
    "# form = prime\n"
    "# drift_convention = mmg\n"
    "# length = 4\n"
    "# density = 1000\n"
    "test,U [m/s],beta [deg],delta [deg],r',X',Y',N'\n"
    "circular-motion,2,10,-5,0.3,-0.001,0.02,-0.004\n"
    "static-drift,2,4,0,0,-0.0011,0.008,-0.002\n";

TEST(CaptiveTable, PrimeRowsBecomeDimensionalRunsInBodyAxes) {
  const CaptiveTable table = parse_captive_table(kPrime, "captive.csv", {});
  ASSERT_EQ(table.runs.size(), 2u);
  const ImportedRun& run = table.runs[0];
  EXPECT_EQ(run.source_line, 7u);
  EXPECT_EQ(run.key.body, "vehicle");
  EXPECT_NEAR(run.key.nu_b[kU], 2.0 * std::cos(10 * kDeg), 1e-15);
  // mmg: beta = atan2(-v, u), so beta > 0 has v < 0.
  EXPECT_NEAR(run.key.nu_b[kV], -2.0 * std::sin(10 * kDeg), 1e-15);
  EXPECT_EQ(run.key.nu_b[kW], 0.0);
  EXPECT_NEAR(run.key.nu_b[kR], 0.3 * 2.0 / 4.0, 1e-15);
  EXPECT_NEAR(run.key.disturbances.at("delta"), -5 * kDeg, 1e-15);
  const double force_unit = 0.5 * 1000 * 2 * 2 * 4 * 4;  // 1/2 rho U^2 L^2 = 32000 N
  const double moment_unit = force_unit * 4;             // 1/2 rho U^2 L^3
  ASSERT_TRUE(run.tau_b[kX] && run.tau_b[kY] && run.tau_b[kN]);
  EXPECT_FALSE(run.tau_b[kK]);
  EXPECT_NEAR(run.tau_b[kX]->total, -0.001 * force_unit, 1e-12);
  EXPECT_NEAR(run.tau_b[kY]->total, 0.02 * force_unit, 1e-12);
  EXPECT_NEAR(run.tau_b[kN]->total, -0.004 * moment_unit, 1e-12);
  EXPECT_EQ(run.fluid.density_kg_m3, 1000.0);
  EXPECT_EQ(table.runs[1].key.nu_b[kR], 0.0);
  EXPECT_FALSE(std::signbit(table.runs[1].key.nu_b[kR]));
  // The note says what was used and where it came from.
  EXPECT_CONTAINS(table.note, "captive.csv: captive-test table, 2 runs (1 circular-motion, 1 static-drift)");
  EXPECT_CONTAINS(table.note, "X', Y', N' in prime (SNAME 1950) form (line 2)");
  EXPECT_CONTAINS(table.note, "L = 4 m (line 4)");
  EXPECT_CONTAINS(table.note, "rho = 1000 kg/m^3 (line 5)");
  EXPECT_CONTAINS(table.note, "beta = atan2(-v, u) (mmg, line 3)");
  EXPECT_EQ(table.settings_key, "form=prime L=4 U=column rho=1000 drift=mmg");
}

TEST(CaptiveTable, FossenConventionTurnsTheSwaySign) {
  CaptiveTableOptions options;
  options.drift_convention = "fossen";  // the option over the file's line
  const CaptiveTable table = parse_captive_table(kPrime, "captive.csv", options);
  EXPECT_NEAR(table.runs[0].key.nu_b[kV], 2.0 * std::sin(10 * kDeg), 1e-15);
  EXPECT_CONTAINS(table.note, "beta = atan2(v, u) (fossen, --drift-convention)");
}

TEST(CaptiveTable, BisFormUsesMassAndGravityAndMmgTheDraft) {
  const std::string rows = "U [m/s],beta [rad],r',Y'',N''\n1.5,0.1,0,0.002,-0.0005\n";
  CaptiveTableOptions options;
  options.form = "bis";
  options.drift_convention = "mmg";
  options.length = {3.0, "--length"};
  options.volume = {0.5, "--volume"};
  options.density = {1025.0, "--rho"};
  // bis: Y = Y'' m g, N = N'' m g L, m = rho V, standard gravity.
  const double mg = 1025.0 * 0.5 * 9.80665;
  CaptiveTable table = parse_captive_table(rows, "b.csv", options);
  EXPECT_NEAR(table.runs[0].tau_b[kY]->total, 0.002 * mg, 1e-12);
  EXPECT_NEAR(table.runs[0].tau_b[kN]->total, -0.0005 * mg * 3.0, 1e-12);
  EXPECT_CONTAINS(table.note, "V = 0.5 m^3 (--volume)");
  EXPECT_CONTAINS(table.note, "g = 9.80665 m/s^2 (standard gravity)");
  // A mass given is used as it is (no density needed).
  options.density = {};
  options.mass = {600.0, "--mass"};
  options.gravity = {9.81, "--gravity"};
  table = parse_captive_table(rows, "b.csv", options);
  EXPECT_NEAR(table.runs[0].tau_b[kY]->total, 0.002 * 600 * 9.81, 1e-12);
  EXPECT_FALSE(table.runs[0].fluid.density_kg_m3);

  // MMG: Y = Y' 1/2 rho U^2 L d, N = N' 1/2 rho U^2 L^2 d.
  const std::string mmg = "U [m/s],beta [rad],r',Y',N'\n1.5,0.1,0,0.002,-0.0005\n";
  CaptiveTableOptions m;
  m.form = "mmg";
  m.drift_convention = "mmg";
  m.length = {3.0, "--length"};
  m.density = {1025.0, "--rho"};
  m.body_reference.draft = 0.2;
  table = parse_captive_table(mmg, "m.csv", m);
  const double unit = 0.5 * 1025 * 1.5 * 1.5 * 3 * 0.2;
  EXPECT_NEAR(table.runs[0].tau_b[kY]->total, 0.002 * unit, 1e-12);
  EXPECT_NEAR(table.runs[0].tau_b[kN]->total, -0.0005 * unit * 3, 1e-12);
  EXPECT_CONTAINS(table.note, "d = 0.2 m (the body's reference data)");
}

TEST(CaptiveTable, ReferenceValuesComeFromTheOptionThenTheFileThenTheBody) {
  CaptiveTableOptions options;
  options.body_reference.length = 8.0;
  EXPECT_CONTAINS(parse_captive_table(kPrime, "c.csv", options).note, "L = 4 m (line 4)");
  options.length = {5.0, "--length"};
  const CaptiveTable table = parse_captive_table(kPrime, "c.csv", options);
  EXPECT_CONTAINS(table.note, "L = 5 m (--length)");
  EXPECT_NEAR(table.runs[0].key.nu_b[kR], 0.3 * 2.0 / 5.0, 1e-15);
  std::string no_length = kPrime;
  no_length.erase(no_length.find("# length = 4\n"), 13);
  options.length = {};
  const CaptiveTable from_body = parse_captive_table(no_length, "c.csv", options);
  EXPECT_CONTAINS(from_body.note, "L = 8 m (the body's reference data)");
  EXPECT_NEAR(from_body.runs[0].key.nu_b[kR], 0.3 * 2.0 / 8.0, 1e-15);
}

TEST(CaptiveTable, BlankSeparatedTablesWithFroudeNumberAndConstantSpeed) {
  // Blank-separated, "beta [deg]" one header, U from Fn with L and g.
  const std::string text =
      "# form = prime\n# drift_convention = mmg\n# length = 4\n# rho = 1000\n"
      "test  Fn  beta [deg]  Y'  N'\n"
      "static-drift  0.2  6  0.01  -0.002\n";
  const CaptiveTable table = parse_captive_table(text, "w.txt", {});
  const double U = 0.2 * std::sqrt(9.80665 * 4.0);
  EXPECT_NEAR(table.runs[0].key.nu_b[kU], U * std::cos(6 * kDeg), 1e-14);
  EXPECT_NEAR(table.runs[0].tau_b[kY]->total, 0.01 * 0.5 * 1000 * U * U * 16, 1e-10);
  // No speed column: --speed for every row; no beta column needs no convention.
  CaptiveTableOptions options;
  options.form = "prime";
  options.speed = {1.25, "--speed"};
  options.length = {2.0, "--length"};
  options.density = {1025.0, "--rho"};
  const CaptiveTable rudder =
      parse_captive_table("test;delta [deg];Y'\nrudder;10;0.001\nrudder;-10;-0.001\n", "r.csv", options);
  ASSERT_EQ(rudder.runs.size(), 2u);
  EXPECT_EQ(rudder.runs[1].key.nu_b[kU], 1.25);
  EXPECT_EQ(rudder.runs[1].key.nu_b[kV], 0.0);
  EXPECT_CONTAINS(rudder.note, "U = 1.25 m/s (--speed)");
}

TEST(CaptiveTable, ReadsAFileWithItsProvenance) {
  test::TempDir dir;
  const auto path = dir.path() / "captive.csv";
  std::ofstream(path, std::ios::binary) << kPrime;
  const CaptiveTableFile file = read_captive_table(path, {});
  EXPECT_EQ(file.batch.source.importer, "captive-table");
  EXPECT_EQ(file.batch.source.size_bytes, kPrime.size());
  EXPECT_EQ(file.batch.source.sha256.size(), 64u);
  EXPECT_EQ(file.batch.runs.size(), 2u);
  EXPECT_EQ(file.settings_key, "form=prime L=4 U=column rho=1000 drift=mmg");
}

// Each refusal: one line with the file, line and column, what was found and what was expected.
TEST(CaptiveTable, MissingReferenceLengthNamesTheColumn) {
  std::string text = kPrime;
  text.erase(text.find("# length = 4\n"), 13);
  EXPECT_EQ(error_of(text, {}),
            "captive.csv:5:40: column X' (prime) needs the reference length: give --length, a line '# length = L' "
            "before the header or `hydrocoef body set vehicle --length L`");
}

TEST(CaptiveTable, MissingDensitySpeedDraftMassOrFormNameTheColumn) {
  std::string text = kPrime;
  text.erase(text.find("# density = 1000\n"), 17);
  EXPECT_CONTAINS(error_of(text), "captive.csv:5:40: column X' (prime) needs the water density: give --rho");
  EXPECT_CONTAINS(error_of("# form = prime\n# length = 2\n# density = 1000\nr',Y'\n0.1,0.01\n"),
                  "captive.csv:4:4: column Y' (prime) needs the speed U of each run: give a column 'U [m/s]'");
  EXPECT_CONTAINS(error_of("# form = mmg\n# length = 2\n# density = 1000\nU [m/s],Y'\n1,0.01\n"),
                  "captive.csv:4:9: column Y' (mmg) needs the draft d: give --draft");
  EXPECT_CONTAINS(error_of("# form = bis\n# length = 2\nU [m/s],Y''\n1,0.01\n"),
                  "captive.csv:3:9: column Y'' (bis) needs the mass m: give --mass");
  EXPECT_EQ(error_of("U [m/s],Y'\n1,0.01\n"),
            "captive.csv:1:9: column Y': the form of the forces is not stated; expected --form prime|bis|mmg or a "
            "line '# form = prime' before the header");
}

TEST(CaptiveTable, BetaWithoutItsConventionIsRefused) {
  std::string text = kPrime;
  text.erase(text.find("# drift_convention = mmg\n"), 25);
  EXPECT_CONTAINS(error_of(text),
                  "captive.csv:5:14: column beta [deg]: the drift-angle convention is not stated; "
                  "expected --drift-convention mmg");
  EXPECT_CONTAINS(error_of("# drift_convention = port\n" + text),
                  "captive.csv:1: drift convention 'port' (line 1): expected mmg (beta = atan2(-v, u)) or fossen");
}

TEST(CaptiveTable, BadUnitsAreRefusedNamingTheColumn) {
  const std::string settings = "# form = prime\n# drift_convention = mmg\n# length = 2\n# rho = 1000\n";
  EXPECT_EQ(error_of(settings + "U [m/s],beta,Y'\n1,2,0.01\n"),
            "captive.csv:5:9: column 'beta' has no unit; expected e.g. 'beta [deg]'");
  EXPECT_EQ(error_of(settings + "U [m/s],beta [m],Y'\n1,2,0.01\n"),
            "captive.csv:5:9: column 'beta [m]': unit 'm' is m, expected rad (e.g. deg)");
  EXPECT_CONTAINS(error_of(settings + "U [deg],Y'\n1,0.01\n"), "captive.csv:5:1: column 'U [deg]': unit 'deg' is rad");
  EXPECT_CONTAINS(error_of(settings + "U [m/s],Y' [N]\n1,0.01\n"),
                  "captive.csv:5:9: column 'Y' [N]' is non-dimensional; found the unit 'N', expected none");
  EXPECT_CONTAINS(error_of(settings + "U [m/s],Y''\n1,0.01\n"),
                  "captive.csv:5:9: column 'Y''' is in the bis form (two primes) but the table's form is prime");
  EXPECT_CONTAINS(error_of(settings + "U [m/s],Z',Y'\n1,0,0.01\n"),
                  "captive.csv:5:9: column 'Z'' is not a captive-table column");
}

TEST(CaptiveTable, NonFiniteAndOutOfRangeValuesAreRefused) {
  const std::string head =
      "# form = prime\n# drift_convention = mmg\n# length = 2\n# rho = 1000\nU [m/s],beta [deg],Y'\n";
  EXPECT_CONTAINS(error_of(head + "1,nan,0.01\n"), "captive.csv:6:3: column 'beta [deg]': found 'nan', expected");
  EXPECT_CONTAINS(error_of(head + "1,2,inf\n"), "captive.csv:6:5: column 'Y'': found 'inf', expected");
  EXPECT_CONTAINS(error_of(head + "0,2,0.01\n"),
                  "captive.csv:6:1: column 'U [m/s]': found '0', expected a speed above 0");
  EXPECT_CONTAINS(error_of(head + "1,2,1e308\n"),
                  "captive.csv:6:5: column 'Y'': '1e308' overflows when made dimensional");
  EXPECT_CONTAINS(error_of(head + "1,2\n"), "captive.csv:6: found 2 fields, expected 3");
  CaptiveTableOptions set_delta;
  set_delta.disturbances["delta"] = 0.1;
  EXPECT_CONTAINS(error_of("# form = prime\n# length = 2\n# rho = 1000\nU [m/s],delta [deg],Y'\n1,2,0.01\n", set_delta),
                  "captive.csv:4:9: column 'delta [deg]' and --set both give 'delta'");
  EXPECT_CONTAINS(error_of(head + "1,2,0.01\n1,2,0.02\n"), "captive.csv:7: run ");
  EXPECT_CONTAINS(error_of(head + "1,2,0.01\n1,2,0.02\n"), "appears twice (also on line 6)");
  EXPECT_CONTAINS(error_of(head), "captive.csv:5: header but no data rows");
}

TEST(CaptiveTable, UnknownTestTypeAndRowsThatAreNotTheirTestAreRefused) {
  const std::string head =
      "# form = prime\n# drift_convention = mmg\n# length = 2\n# rho = 1000\ntest,U [m/s],beta [deg],r',Y'\n";
  EXPECT_EQ(error_of(head + "pure-sway,1,0,0,0.01\n"),
            "captive.csv:6:1: column test: found 'pure-sway', expected static-drift, rudder, drift-rudder or "
            "circular-motion");
  EXPECT_CONTAINS(error_of(head + "static-drift,1,4,0.2,0.01\n"),
                  "captive.csv:6:1: column test: 'static-drift' with r' = 0.2; expected r' = 0");
  EXPECT_CONTAINS(error_of(head + "rudder,1,4,0,0.01\n"), "'rudder' with beta = 4; expected beta = 0");
  EXPECT_CONTAINS(error_of(head + "circular-motion,1,4,0,0.01\n"), "column test: 'circular-motion' without a yaw rate");
}

TEST(CaptiveTable, SettingLinesAreCheckedAndCommentsLeftAlone) {
  const std::string rows = "U [m/s],Y'\n1,0.01\n";
  EXPECT_CONTAINS(error_of("# form = prime\n# lenght = 2\n" + rows),
                  "captive.csv:2: setting 'lenght' is not known; expected one of form, drift_convention, length");
  EXPECT_CONTAINS(error_of("# length = 2\n# length = 3\n" + rows),
                  "captive.csv:2: setting 'length' again (first on line 1)");
  EXPECT_CONTAINS(error_of("# length = -2\n" + rows),
                  "captive.csv:1: setting 'length': found '-2', expected a number above 0");
  EXPECT_CONTAINS(error_of("# form = ittc\n" + rows), "captive.csv:1: form 'ittc' (line 1): expected prime");
  EXPECT_CONTAINS(error_of("# form = prime\n# length = 2\n# rho = 1000\n" + rows + "# speed = 3\n"),
                  "captive.csv:6: setting 'speed' after the header (line 4)");
  // A free comment, with or without '=' in it, is a comment.
  const auto table =
      parse_captive_table("# Mariner, generated with L = 160.93 m\n# form = prime\n# length = 2\n# rho = 1000\n" +
                              rows + "# a note\n1.5,0.02\n",
                          "c.csv", {});
  EXPECT_EQ(table.runs.size(), 2u);
  EXPECT_CONTAINS(error_of(""), "captive.csv: no header line");
}

}  // namespace
}  // namespace hydrocoef
