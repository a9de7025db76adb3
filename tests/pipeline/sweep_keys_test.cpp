// Keys from a sweep's own naming and from a manifest: patterns over folder
// and file names with units, ambiguity refused, manifest rows matched by path
// (a case folder's row covers its files), units, and refusals naming the
// line and column.
#include "src/pipeline/sweep_keys.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "src/core/error.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

double number(const SettingsLayer& layer, const std::string& name) {
  return std::get<double>(layer.values.at(name).value);
}

TEST(NamePattern, ReadsTheFolderNamesOfASweep) {
  const NamePattern pattern("u{u}_v{v}");
  const auto layer = pattern.match("u0.20_v0.05/VTK/u0.20_v0.05_1000/boundary/sphere.vtp");
  ASSERT_TRUE(layer);
  EXPECT_EQ(number(*layer, "u"), 0.20);
  EXPECT_EQ(number(*layer, "v"), 0.05);
  EXPECT_EQ(layer->origin.source, SettingSource::NamePattern);
  EXPECT_NE(layer->origin.where.find("'u0.20_v0.05'"), std::string::npos);
  // A case folder itself (its last name is a folder, matched whole).
  EXPECT_EQ(number(*pattern.match("u0.10_v-0.05", false), "v"), -0.05);
  // A file's name without its extension.
  EXPECT_EQ(number(*pattern.match("exports/u0.3_v0.1.vtp"), "u"), 0.3);
  EXPECT_FALSE(pattern.match("baseline/sphere.vtp"));
}

TEST(NamePattern, UnitsAndDisturbancesAndFoldersSpanned) {
  const NamePattern pattern("r{r [deg s^-1]}_c{current_v}");
  const auto layer = pattern.match("yaw/r90_c0.05.csv");
  ASSERT_TRUE(layer);
  EXPECT_NEAR(number(*layer, "r"), std::numbers::pi / 2, 1e-15);
  EXPECT_EQ(number(*layer, "disturbance.current_v"), 0.05);
  const NamePattern two("U{u}/V{v}");
  const auto spanned = two.match("U0.1/V0.2/run.vtp");
  ASSERT_TRUE(spanned);
  EXPECT_EQ(number(*spanned, "v"), 0.2);
  // A literal after a number that begins like a number is found by backtracking.
  const auto exponent = NamePattern("{u}e{v}").match("1.5e2", false);
  ASSERT_TRUE(exponent);
  EXPECT_EQ(number(*exponent, "u"), 1.5);
  EXPECT_EQ(number(*exponent, "v"), 2.0);
}

TEST(NamePattern, CraftedNamesAreMatchedWithoutExponentialBacktracking) {
  // Ten fields separated by a digit, and a name of 60 digits that the
  // numbers can split in 10^15 ways: trying every split took over a minute
  // for ten fields; a (field, position) that failed is now never tried again.
  const NamePattern digits("x{a}1{b}1{c}1{d}1{f}1{g}1{h}1{i}1{j}1{k}y");
  EXPECT_FALSE(digits.match("x" + std::string(60, '1') + "z", false));  // no 'y': every split fails
  // Where a match exists it is the first in the longest-number-first order:
  // the first number takes all the digits the others leave it.
  const auto layer = digits.match("x" + std::string(30, '1') + "y", false);
  ASSERT_TRUE(layer);
  EXPECT_EQ(number(*layer, "disturbance.a"), 111111111111.0);
  for (const char* name : {"b", "c", "d", "f", "g", "h", "i", "j", "k"})
    EXPECT_EQ(number(*layer, std::string("disturbance.") + name), 1.0) << name;
  // Fields separated by 'e' in a name of "1e1e...": each number is "1e1"
  // (10) while enough is left for the rest, then "1".
  const NamePattern exponents("x{a}e{b}e{c}e{d}e{f}e{g}e{h}e{i}e{j}e{k}y");
  std::string ones;
  for (int i = 0; i < 14; ++i) ones += "1e";
  const auto split = exponents.match("x" + ones + "1y", false);
  ASSERT_TRUE(split);
  EXPECT_EQ(number(*split, "disturbance.a"), 10.0);
  EXPECT_EQ(number(*split, "disturbance.f"), 10.0);
  EXPECT_EQ(number(*split, "disturbance.g"), 1.0);
  EXPECT_EQ(number(*split, "disturbance.k"), 1.0);
  EXPECT_FALSE(exponents.match("x" + ones + ones + ones + ones + "1y", false));  // too many for ten numbers
}

TEST(NamePattern, AmbiguousAndMalformedPatternsAreRefused) {
  EXPECT_THROW(NamePattern("u{u}").match("u0.1/u0.2.vtp"), InputError);
  EXPECT_NO_THROW(NamePattern("u{u}").match("u0.1/u0.1.vtp"));
  EXPECT_THROW(NamePattern("u0.1"), InputError);
  EXPECT_THROW(NamePattern("u{u"), InputError);
  EXPECT_THROW(NamePattern("u}"), InputError);
  EXPECT_THROW(NamePattern("{u}{v}"), InputError);
  EXPECT_THROW(NamePattern("{u}_{u}"), InputError);
  EXPECT_THROW(NamePattern("{a;b}"), InputError);
  EXPECT_THROW(NamePattern("{u [N]}"), InputError);  // not a velocity unit
}

class ManifestTest : public ::testing::Test {
 protected:
  void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }
  test::TempDir dir_;
};

TEST_F(ManifestTest, RowsGiveSettingsWithUnitsAndTheirLine) {
  write("sweep.csv",
        "# the sweep of the sphere\n"
        "path,u [m s^-1],r [deg s^-1],current_v [m s^-1],rho,body\n"
        "cases/a,0.1,0,0.05,998.2,sphere\n"
        "cases/b/export.vtp,0.2,90,,,\n");
  const Manifest manifest = Manifest::read(dir_ / "sweep.csv");
  EXPECT_EQ(manifest.rows(), 2u);
  const SettingsLayer* a = manifest.find(dir_ / "cases/a/VTK/x.vtp");  // a case folder's row covers its files
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(number(*a, "u"), 0.1);
  EXPECT_EQ(number(*a, "disturbance.current_v"), 0.05);
  EXPECT_EQ(std::get<std::string>(a->values.at("body").value), "sphere");
  EXPECT_EQ(a->origin.where, (dir_ / "sweep.csv").string() + ":3");
  const SettingsLayer* b = manifest.find(dir_ / "cases" / "b" / "." / "export.vtp");
  ASSERT_NE(b, nullptr);
  EXPECT_NEAR(number(*b, "r"), std::numbers::pi / 2, 1e-15);
  EXPECT_EQ(b->values.count("rho"), 0u);  // empty cells state nothing
  EXPECT_EQ(manifest.find(dir_ / "cases/c.vtp"), nullptr);
}

TEST_F(ManifestTest, FlowColumnsAndRefusals) {
  write("flow.csv", "path;flow_x;flow_y;flow_z\nrun.vtp;0.2;0.05;0\n");
  const Manifest flows = Manifest::read(dir_ / "flow.csv");
  const auto* row = flows.find(dir_ / "run.vtp");
  ASSERT_NE(row, nullptr);
  EXPECT_EQ(std::get<std::vector<double>>(row->values.at("flow").value), (std::vector<double>{0.2, 0.05, 0}));

  const auto refused = [&](const std::string& text) {
    write("bad.csv", text);
    try {
      Manifest::read(dir_ / "bad.csv");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string bad = (dir_ / "bad.csv").string();
  EXPECT_NE(refused("u,v\n0.1,0\n").find("no 'path' column"), std::string::npos);
  EXPECT_EQ(refused("path,u\na,0.1\na,0.2\n").rfind(bad + ":3:1: path 'a' is listed twice", 0), 0u);
  EXPECT_EQ(refused("path,u\na,fast\n").rfind(bad + ":2:3:", 0), 0u);
  EXPECT_NE(refused("path,u [N]\na,1\n").find("expected m s^-1"), std::string::npos);
  EXPECT_NE(refused("path,a;b\nx,1\n").find("parameter name"), std::string::npos);
  EXPECT_NE(refused("path,flow_x\nx,1\n").find("all three"), std::string::npos);
  EXPECT_NE(refused("path,u\nx,1,2\n").find("expected 2"), std::string::npos);
}

}  // namespace
}  // namespace hydrocoef
