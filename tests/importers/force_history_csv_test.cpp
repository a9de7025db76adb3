// Tables of time and forces (importers/force_history_csv): every delimiter
// and a header as a comment, the names it recognises (Fx, Force X, Torque Z,
// parts, SNAME letters), units converted and checked, mappings, notes for
// what is not read, a real OpenFOAM force history rewritten as a CSV giving
// the same numbers, the digest of read_force_history_csv, every refusal with
// its place.
#include "importers/force_history_csv.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "importers/openfoam_forces.hpp"
#include "src/core/error.hpp"
#include "src/core/source_file.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
using test::expect_input_error;

constexpr auto kTotal = ForcePart::Total;

ForceHistory parse(const std::string& text, const ForceHistoryCsvOptions& options = {}) {
  return parse_force_history_csv(text, "h.csv", options);
}

bool has_note(const ForceHistory& h, const std::string& piece) {
  for (const auto& note : h.notes)
    if (note.find(piece) != std::string::npos) return true;
  return false;
}

TEST(ForceHistoryCsv, CommaTableWithUnits) {
  const ForceHistory h = parse(
      "Time [s], Fx [kN], Fy [N], Mz [N m], Note\n"
      "0.0, 1.5, 2, 3, start\n"
      "0.5, 1.25, -2, 4e-1, \"a, b\"\n");
  ASSERT_EQ(h.size(), 2u);
  EXPECT_EQ(h.abscissa, HistoryAbscissa::Time);
  EXPECT_EQ(h.abscissa_values, (std::vector<double>{0.0, 0.5}));
  EXPECT_EQ(h.values(kTotal, HistoryComponent::Fx), (std::vector<double>{1500.0, 1250.0}));
  EXPECT_EQ(h.values(kTotal, HistoryComponent::Fy), (std::vector<double>{2.0, -2.0}));
  EXPECT_EQ(h.values(kTotal, HistoryComponent::Mz), (std::vector<double>{3.0, 0.4}));
  EXPECT_TRUE(h.values(kTotal, HistoryComponent::Fz).empty());
  EXPECT_EQ(h.frame.naming, ComponentNaming::SourceAxes);
  EXPECT_FALSE(h.frame.moment_centre);
  EXPECT_TRUE(has_note(h, "columns not read: 'Note'"));
  ASSERT_EQ(h.force_origin.size(), 2u);
  EXPECT_EQ(h.force_origin[1].line, 3u);
  EXPECT_EQ(h.moment_origin[0].line, 2u);
  EXPECT_EQ(h.files[0].format, "force-history-csv");
  EXPECT_EQ(sample_location(h, 1, HistoryComponent::Mz), "h.csv:3");
}

TEST(ForceHistoryCsv, TabSemicolonAndBlankSeparatedTablesAndCrlf) {
  for (const std::string& text : {std::string("Iteration\tForce X\tMoment Y\n1\t1\t2\n2\t3\t4\n"),
                                  std::string("Iteration;Force X;Moment Y\r\n1;1;2\r\n2;3;4\r\n"),
                                  std::string("Iteration   Force_X   Moment-Y\n  1  1  2\n  2  3  4"),
                                  std::string("# exported\n# Iteration Fx My\n1 1 2\n# a comment\n\n2 3 4\n")}) {
    SCOPED_TRACE(text);
    const ForceHistory h = parse(text);
    EXPECT_EQ(h.abscissa, HistoryAbscissa::Iteration);
    EXPECT_EQ(h.abscissa_values, (std::vector<double>{1, 2}));
    EXPECT_EQ(h.values(kTotal, HistoryComponent::Fx), (std::vector<double>{1, 3}));
    EXPECT_EQ(h.values(kTotal, HistoryComponent::My), (std::vector<double>{2, 4}));
  }
}

TEST(ForceHistoryCsv, BlankSeparatedUnitsMayHoldBlanks) {
  const ForceHistory h = parse("Time [ s ]   Fx [ kN ]   Torque_z [ J ]\n0 1 2\n1 3 4\n");
  EXPECT_EQ(h.values(kTotal, HistoryComponent::Fx), (std::vector<double>{1000, 3000}));
  EXPECT_EQ(h.values(kTotal, HistoryComponent::Mz), (std::vector<double>{2, 4}));
  // With blanks between cells a name is one word: "Flow Time" is two cells,
  // and the rows have one number fewer than the header has cells.
  expect_input_error([] { parse("Flow Time [ s ] Fx [ kN ]\n0 1\n"); }, {"h.csv:2:", "found 2 fields, expected 3"});
}

TEST(ForceHistoryCsv, PartsAndTotals) {
  const ForceHistory h = parse(
      "t, Fx pressure, Fx_viscous, total_Fy, pressure Fy\n"
      "0, 1, 0.25, 5, 4\n"
      "1, 2, 0.5, 6, 5\n");
  EXPECT_EQ(h.values(ForcePart::Pressure, HistoryComponent::Fx), (std::vector<double>{1, 2}));
  EXPECT_EQ(h.values(ForcePart::Viscous, HistoryComponent::Fx), (std::vector<double>{0.25, 0.5}));
  EXPECT_EQ(h.values(kTotal, HistoryComponent::Fx), (std::vector<double>{1.25, 2.5}));  // from the parts
  EXPECT_EQ(h.values(kTotal, HistoryComponent::Fy), (std::vector<double>{5, 6}));       // as given
  EXPECT_TRUE(has_note(h, "Fx: total = pressure + viscous"));
  EXPECT_FALSE(has_note(h, "Fy: total"));
}

TEST(ForceHistoryCsv, SnameLettersAreBodyAxes) {
  const ForceHistory h = parse("Time,X,Y,N,X pressure\n0,1,2,3,0.5\n1,1,2,3,0.5\n");
  EXPECT_EQ(h.frame.naming, ComponentNaming::BodyAxes);
  EXPECT_EQ(h.values(kTotal, HistoryComponent::Mz), (std::vector<double>{3, 3}));
  EXPECT_EQ(h.values(ForcePart::Pressure, HistoryComponent::Fx), (std::vector<double>{0.5, 0.5}));
  expect_input_error([] { parse("Time,X,Fy\n0,1,2\n"); },
                     {"h.csv:1:8", "names a solver-axis component but 'X' does not", "not both"});
}

TEST(ForceHistoryCsv, MappingsAndAbscissaColumn) {
  ForceHistoryCsvOptions options;
  options.columns = {{"Fx", "Drag"}, {"Mz:viscous", "Yaw visc [mN m]"}};
  options.abscissa_column = "Sim";
  options.abscissa = HistoryAbscissa::Time;
  options.units = {{"time", "ms"}, {"Fx", "kN"}};
  const ForceHistory h = parse("Sim,Drag,Fy,Yaw visc [mN m]\n10,2,9,3\n20,4,9,5\n", options);
  EXPECT_EQ(h.abscissa, HistoryAbscissa::Time);
  EXPECT_EQ(h.abscissa_values, (std::vector<double>{0.01, 0.02}));
  EXPECT_EQ(h.values(kTotal, HistoryComponent::Fx), (std::vector<double>{2000, 4000}));
  EXPECT_NEAR(h.values(ForcePart::Viscous, HistoryComponent::Mz)[1], 5e-3, 1e-18);
  EXPECT_TRUE(h.values(kTotal, HistoryComponent::Fy).empty());  // a mapping reads only what it maps
  EXPECT_TRUE(has_note(h, "columns not read: 'Fy'"));

  options.columns = {{"Fq", "Drag"}};
  expect_input_error([&] { parse("Sim,Drag\n1,2\n", options); }, {"unknown component 'Fq'", "Fx Fy Fz"});
  options.columns = {{"Fx", "Lift"}};
  expect_input_error([&] { parse("Sim,Drag\n1,2\n", options); }, {"h.csv:1", "no column 'Lift'", "'Sim', 'Drag'"});
  options.columns = {{"Fx", "Drag"}, {"Fy", "Drag"}};
  expect_input_error([&] { parse("Sim,Drag\n1,2\n", options); }, {"is mapped twice"});
}

TEST(ForceHistoryCsv, UnitsAreCheckedAgainstTheKind) {
  expect_input_error([] { parse("Time [s],Fx [N m]\n0,1\n"); },
                     {"h.csv:1:10", "column 'Fx [N m]'", "expected a force"});
  expect_input_error([] { parse("Time [m],Fx [N]\n0,1\n"); }, {"h.csv:1:1", "expected a time"});
  expect_input_error([] { parse("Time [s],Mx [N]\n0,1\n"); }, {"expected a moment"});
  expect_input_error([] { parse("Time [s],Fx [furlong]\n0,1\n"); }, {"h.csv:1:10", "'Fx [furlong]'"});
  expect_input_error([] { parse("Iteration [s],Fx\n0,1\n"); }, {"expected an iteration count"});
  const ForceHistory h = parse("Time,Fx\n0,1\n");
  EXPECT_TRUE(has_note(h, "'Fx' has no unit: SI (kg m s^-2) assumed"));
  EXPECT_TRUE(has_note(h, "'Time' has no unit: SI (s) assumed"));
}

TEST(ForceHistoryCsv, RefusesBadTables) {
  expect_input_error([] { parse(""); }, {"h.csv", "no header and no rows"});
  expect_input_error([] { parse("1,2,3\n"); }, {"h.csv:1:1", "holds numbers, not column names"});
  expect_input_error([] { parse("Time,Fx\n"); }, {"h.csv:1", "no rows after the header"});
  expect_input_error([] { parse("Fx,Fy\n1,2\n"); }, {"h.csv:1", "no time or iteration column", "'Fx', 'Fy'"});
  expect_input_error([] { parse("Time,Iteration,Fx\n1,2,3\n"); }, {"h.csv:1:6", "a second time or iteration column"});
  expect_input_error([] { parse("Time,Pressure,Speed\n1,2,3\n"); }, {"h.csv:1", "no force or moment column"});
  expect_input_error([] { parse("Time,Fx,Force X\n1,2,3\n"); }, {"h.csv:1:9", "gives Fx as column 'Fx' does"});
  expect_input_error([] { parse("Time,Fx\n0,1\n1,abc\n"); }, {"h.csv:3:3", "column 2 'Fx'", "found 'abc'"});
  expect_input_error([] { parse("Time,Fx\n0,1\n1,\n"); }, {"h.csv:3:3", "found an empty field"});
  expect_input_error([] { parse("Time,Fx\n0,1\n1\n"); }, {"h.csv:3:", "found 1 fields, expected 2"});
  expect_input_error([] { parse("Time,Fx\n0,1\n1,2,3\n"); }, {"h.csv:3:", "found more than 2 fields"});
  expect_input_error([] { parse("Time,Fx\n0,1\n0,2\n"); }, {"h.csv:3", "time 0 is not after 0 on line 2"});
  expect_input_error([] { parse("Time,Fx\n0,1\n1,inf\n"); }, {"h.csv:3:3", "expected a finite number"});
  expect_input_error([] { parse("Time,Fx [kN]\n0,1e306\n"); }, {"h.csv:2", "overflows when converted to SI"});
}

TEST(ForceHistoryCsv, AnOpenFoamHistoryAsACsvGivesTheSameNumbers) {
  const fs::path folder = fs::path(HYDROCOEF_DATA_DIR) / "openfoam-sphere/cases/u0.20_v0.10/postProcessing/forces";
  const ForceHistory foam = read_openfoam_forces(folder);
  std::string text = "Iteration,Fx pressure [N],Fx viscous [N],Fx [N],Mz [N m]\n";
  char line[200];
  for (std::size_t i = 0; i < foam.size(); ++i) {
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g,%.17g\n", foam.abscissa_values[i],
                  foam.values(ForcePart::Pressure, HistoryComponent::Fx)[i],
                  foam.values(ForcePart::Viscous, HistoryComponent::Fx)[i],
                  foam.values(kTotal, HistoryComponent::Fx)[i], foam.values(kTotal, HistoryComponent::Mz)[i]);
    text += line;
  }
  test::TempDir dir;
  test::write_bytes(dir / "h.csv", text);
  const ForceHistory h = read_force_history_csv(dir / "h.csv");
  EXPECT_EQ(h.abscissa_values, foam.abscissa_values);
  EXPECT_EQ(h.abscissa, HistoryAbscissa::Iteration);
  EXPECT_EQ(h.values(kTotal, HistoryComponent::Fx), foam.values(kTotal, HistoryComponent::Fx));
  EXPECT_EQ(h.values(ForcePart::Pressure, HistoryComponent::Fx),
            foam.values(ForcePart::Pressure, HistoryComponent::Fx));
  EXPECT_EQ(h.values(kTotal, HistoryComponent::Mz), foam.values(kTotal, HistoryComponent::Mz));
  EXPECT_EQ(h.files[0].sha256, sha256_hex(text));
  EXPECT_EQ(h.files[0].size_bytes, text.size());
  EXPECT_EQ(h.files[0].rows, foam.size());
}

TEST(ForceHistoryCsv, ALastRowCutShortCanBeDropped) {
  // Tables may end without a line end; a row cut inside is refused.
  EXPECT_EQ(parse("Time,Fx\n0,1\n1,2").size(), 2u);
  expect_input_error([] { parse("Time,Fx\n0,1\n1,"); }, {"h.csv:3:3"});
  ForceHistoryCsvOptions options;
  options.drop_incomplete_last_row = true;
  const ForceHistory h = parse("Time,Fx\n0,1\n1,", options);
  EXPECT_EQ(h.size(), 1u);
  EXPECT_TRUE(has_note(h, "cut short"));
}

}  // namespace
}  // namespace hydrocoef

namespace hydrocoef {
namespace {

// Values whose statistics are not finite: denormal or huge times or time
// steps, denormal forces (a NaN standard error reached a NOT NULL column:
// "internal error"). The history check refuses them with the file and line.
TEST(ForceHistoryCsv, TimesAndForcesTheStatisticsCannotTakeAreRefusedWithTheLine) {
  EXPECT_EQ(kMinHistoryMagnitude, 1e-100);
  EXPECT_EQ(kMaxHistoryMagnitude, 1e100);
  const auto refused = [](const std::string& text, const std::vector<std::string>& pieces) {
    test::expect_input_error([&] { check_force_history(parse_force_history_csv(text, "h.csv")); }, pieces);
  };
  refused("Time [s],X [N]\n0,1\n5e-324,2\n1e-323,1\n", {"h.csv:3: time 5e-324; expected 0 or a magnitude from"});
  refused("Time [s],X [N]\n0,1\n1e300,2\n2e300,1\n", {"h.csv:3: time 1e+300; expected 0 or a magnitude from", " s "});
  refused("Time [s],X [N],N [N m]\n0,1,1\n0.1,1e-310,1\n0.2,1,1\n", {"h.csv:3: total X 1e-310;", " N ("});
  refused("# Time Fx My\n0 1 1\n0.1 1 3e-200\n", {"h.csv:3: total My 3e-200;", " N m ("});
  // 0 and the magnitudes inside the range are read.
  const ForceHistory kept = parse_force_history_csv("Time [s],X [N]\n0,0\n1e-100,-1e100\n1,1e-100\n", "h.csv");
  EXPECT_NO_THROW(check_force_history(kept));
  // A history built by hand says which sample.
  ForceHistory hand;
  hand.abscissa_values = {0.0, 1.0};
  hand.values(ForcePart::Total, HistoryComponent::Fx) = {1.0, 1e-320};
  test::expect_input_error([&] { check_force_history(hand); }, {"sample 2: total Fx 1e-320"});
}

// Damaged tables: read (a valid history) or refused with a one-line InputError.
TEST(ForceHistoryCsv, DamagedTablesAreReadOrRefusedInOneLine) {
  const std::vector<std::string> seeds{
      "Time [s], Fx [kN], Fy [N], Mz [N m], Note\n0.0, 1.5, 2, 3, start\n0.5, 1.25, -2, 4e-1, \"a, b\"\n",
      "# Iteration Fx My\n1 1 2\n2 3 4\n", "Iteration;Force X;Moment Y\r\n1;1;2\r\n2;3;4\r\n",
      "t\tX\tY pressure\tN\n0\t1\t2\t3\n1\t1\t2\t3\n"};
  const std::string alphabet = "0123456789.eE+-[] \t\n#,;\"\rFxyzMNTtime";
  std::mt19937_64 random(7);
  int read = 0, refused = 0;
  for (int i = 0; i < 3000; ++i) {
    std::string text = seeds[static_cast<std::size_t>(i) % seeds.size()];
    for (int edits = 1 + static_cast<int>(random() % 3); edits > 0 && !text.empty(); --edits) {
      const std::size_t at = random() % text.size();
      switch (random() % 3) {
        case 0: text[at] = alphabet[random() % alphabet.size()]; break;
        case 1: text.erase(at, 1 + random() % 4); break;
        default: text.insert(at, 1, alphabet[random() % alphabet.size()]);
      }
    }
    ForceHistoryCsvOptions options;
    options.drop_incomplete_last_row = i % 2 == 0;
    try {
      check_force_history(parse_force_history_csv(text, "h.csv", options));
      ++read;
    } catch (const InputError& error) {
      const std::string message = error.what();
      ASSERT_EQ(message.find('\n'), std::string::npos) << message;
      ++refused;
    }
  }
  EXPECT_GT(read, 100);
  EXPECT_GT(refused, 100);
}

}  // namespace
}  // namespace hydrocoef
