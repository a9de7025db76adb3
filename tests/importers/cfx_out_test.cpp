// The wall force and moment summary of a CFX solver output file
// (importers/cfx_out): tests/data/cfx/hull_u1.5_001.out (see its PROVENANCE.md)
// read per boundary and per domain group, its numbers checked against the
// file's own table (each group's totals the sum of its boundaries, pressure
// plus viscous the run's force); units converted; the last summary of a
// transient run; and the refusals, each at its line.
#include "importers/cfx_out.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "src/core/error.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

const std::filesystem::path kOut = HYDROCOEF_SOURCE_DIR "/tests/data/cfx/hull_u1.5_001.out";

std::string text_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::size_t line_of(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  return at == std::string::npos ? 0 : static_cast<std::size_t>(std::count(text.begin(), text.begin() + at, '\n')) + 1;
}

using V = std::array<double, 3>;

TEST(CfxOut, PerBoundaryAndDomainGroupTotalsAsTheFileStatesThem) {
  const std::string text = text_of(kOut);
  ASSERT_TRUE(has_cfx_wall_forces(text));
  const CfxWallForceSummary s = read_cfx_wall_forces(kOut);
  EXPECT_EQ(s.summaries, 1u);
  EXPECT_EQ(s.line, line_of(text, "Wall Force and Moment Summary"));
  ASSERT_EQ(s.groups.size(), 1u);
  const CfxDomainGroup& g = s.groups[0];
  EXPECT_EQ(g.name, "Default Domain");
  ASSERT_EQ(g.boundaries.size(), 2u);
  EXPECT_EQ(g.boundaries[0].first, "hull");
  EXPECT_EQ(g.boundaries[1].first, "rudder");
  const CfxWallLoads& hull = g.boundaries[0].second;
  const CfxWallLoads& rudder = g.boundaries[1].second;
  EXPECT_EQ(hull.line, line_of(text, " hull  "));
  // The rows as printed.
  EXPECT_EQ(*hull.pressure_force, (V{12.5, 0.25, -0.5}));
  EXPECT_EQ(*hull.viscous_force, (V{3.5, 0.01, 0.02}));
  EXPECT_EQ(*rudder.pressure_moment, (V{0.0, 0.01, -0.625}));
  EXPECT_EQ(*rudder.viscous_moment, (V{0.0, 0.0005, -0.00125}));
  // Every table: the group's totals are the sum of its boundaries.
  const auto check_sum = [](const std::optional<V>& total, const std::optional<V>& a, const std::optional<V>& b) {
    ASSERT_TRUE(total && a && b);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR((*total)[i], (*a)[i] + (*b)[i], 1e-12) << i;
  };
  check_sum(g.totals.pressure_force, hull.pressure_force, rudder.pressure_force);
  check_sum(g.totals.viscous_force, hull.viscous_force, rudder.viscous_force);
  check_sum(g.totals.pressure_moment, hull.pressure_moment, rudder.pressure_moment);
  check_sum(g.totals.viscous_moment, hull.viscous_moment, rudder.viscous_moment);
  // Pressure plus viscous: the drag of the stream along +x, 17 N.
  EXPECT_DOUBLE_EQ((*g.totals.pressure_force)[0] + (*g.totals.viscous_force)[0], 17.0);
}

TEST(CfxOut, UnitsAreConvertedAndTheLastSummaryIsRead) {
  std::string text = text_of(kOut);
  // A transient run writes a summary per time step: the last is the run's end.
  const auto start = text.find(" +-----", text.find("Termination and Interrupt"));
  const auto end = text.find(" +-----", text.find("Viscous Moment (N m)"));
  ASSERT_NE(start, std::string::npos);
  std::string earlier = text.substr(start, end - start);
  earlier.replace(earlier.find("Pressure Force (N)"), 18, "Pressure Force (kN)");
  text.insert(start, earlier);
  const CfxWallForceSummary s = parse_cfx_wall_forces(text, "t.out");
  EXPECT_EQ(s.summaries, 2u);
  EXPECT_EQ((*s.groups[0].boundaries[0].second.pressure_force)[0], 12.5);  // the second summary's, in N
  const CfxWallForceSummary first = parse_cfx_wall_forces(earlier, "e.out");
  EXPECT_EQ((*first.groups[0].boundaries[0].second.pressure_force)[0], 12500.0);  // kN in SI
}

TEST(CfxOut, RefusalsNameTheLine) {
  const std::string text = text_of(kOut);
  const auto changed = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  const std::string row = " rudder                    7.5000E-01    1.2500E+00    0.0000E+00";
  const std::string short_row = changed(row, " rudder                    7.5000E-01    1.2500E+00");
  test::expect_input_error([&] { parse_cfx_wall_forces(short_row, "r.out"); },
                           {"r.out:" + std::to_string(line_of(text, row)) + ":2:", "in the Pressure Force table",
                            "expected a boundary name and three numbers"});
  const std::string word = changed(row, " rudder                    7.5000E-01    1.2500E+00    zero");
  test::expect_input_error([&] { parse_cfx_wall_forces(word, "r.out"); },
                           {"r.out:" + std::to_string(line_of(text, row)) + ":", "'zero'"});
  test::expect_input_error(
      [&] { parse_cfx_wall_forces(changed("Viscous Force (N)", "Viscous Force (Pa)"), "u.out"); },
      {"u.out:" + std::to_string(line_of(text, "Viscous Force (N)")) + ":", "'Pa'", "a force unit"});
  test::expect_input_error(
      [&] { parse_cfx_wall_forces(changed("Pressure Moment (N m)", "Pressure Moment (N)"), "m.out"); },
      {"m.out:" + std::to_string(line_of(text, "Pressure Moment (N m)")) + ":", "a moment unit"});
  const std::string twice = changed(row, row + "\n" + row);
  test::expect_input_error([&] { parse_cfx_wall_forces(twice, "d.out"); },
                           {"d.out:" + std::to_string(line_of(text, row) + 1) + ":", "'rudder' twice"});
  test::expect_input_error(
      [&] { parse_cfx_wall_forces(text.substr(0, text.find(" +-----", text.find("Termination"))), "n.out"); },
      {"n.out", "no wall force and moment summary", "cfx5mondata"});
  EXPECT_FALSE(has_cfx_wall_forces(text_of(HYDROCOEF_SOURCE_DIR "/tests/data/cfx/tow_u1.5_001.out")));
  EXPECT_FALSE(file_has_cfx_wall_forces("/nonexistent/file.out"));
}

}  // namespace
}  // namespace hydrocoef
