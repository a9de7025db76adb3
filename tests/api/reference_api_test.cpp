// A body's reference data and the runs' coefficients through the public API
// (include/hydrocoef/reference.hpp) against the CLI on the same database of
// the OpenFOAM sphere runs: set_body_reference gives what `body set --json`
// gives, body_references what `body show` prints, run_coefficients the
// numbers, text, JSON and CSV of `runs --coefficients` (its columns equal to
// its JSON); validate() refuses with the CLI's messages; a read-only
// Database refuses a change and leaves the file byte-identical.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hydrocoef/hydrocoef.hpp"
#include "tests/support/api_errors.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/sphere_cases.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

using hydrocoef::Database;
using hydrocoef::OpenMode;
using hydrocoef::test::cli_error;
using hydrocoef::test::error_of;
using hydrocoef::test::run_cli;
using hydrocoef::test::TempDir;
using nlohmann::json;

constexpr double kFrontal = M_PI * 0.15 * 0.15;

class ReferenceApiTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(hydrocoef::test::import_sphere_cases(dir_.path()).exit_code, 0);
    path_ = (dir_ / "hydrocoef.db").string();
  }
  hydrocoef::test::CliResult cli(std::vector<std::string> args) {
    args.insert(args.begin(), {"--db", path_});
    return run_cli(args, dir_.path());
  }
  std::string cli_out(const std::vector<std::string>& args) {
    const auto result = cli(args);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return result.out;
  }
  static hydrocoef::BodyReferenceOptions sphere_options() {
    hydrocoef::BodyReferenceOptions options;
    options.body = "sphere";
    options.length = 0.3;
    options.areas = {{"frontal", kFrontal}, {"L*d", 0.09}};
    options.default_area = "frontal";
    options.displaced_volume = 0.014137166941154069;
    options.moment_reference_point = std::array<double, 3>{0.1, 0.0, 0.0};
    return options;
  }

  TempDir dir_;
  std::string path_;
};

TEST_F(ReferenceApiTest, SetAndShowGiveWhatTheCliGives) {
  json ours;
  {
    auto db = Database::open(path_, OpenMode::ReadWrite);
    const auto stored = hydrocoef::set_body_reference(db, sphere_options());
    EXPECT_EQ(stored.length, 0.3);
    EXPECT_EQ(stored.areas.at("frontal"), kFrontal);
    EXPECT_EQ(stored.default_area, "frontal");
    EXPECT_TRUE(std::isnan(stored.draft));
    EXPECT_EQ(stored.moment_reference_point[0], 0.1);
    ours = json::parse(stored.json());
  }
  // The CLI's show prints what the API stored; its own set (the same values) the same record.
  const json shown = json::parse(cli_out({"body", "show", "sphere", "--json"}));
  EXPECT_EQ(shown["bodies"][0], ours);
  json theirs = json::parse(cli_out({"body", "set", "sphere", "--length", "0.3", "--area",
                                     "frontal=0.070685834705770348", "--area", "L*d=0.09", "--default-area", "frontal",
                                     "--volume", "0.014137166941154069", "--moment-point", "0.1,0,0", "--json"}));
  for (auto* document : {&ours, &theirs}) document->erase("updated_at");
  EXPECT_EQ(ours, theirs);
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  EXPECT_EQ(hydrocoef::body_references(db, "sphere").text(), cli_out({"body", "show", "sphere"}));
  EXPECT_EQ(hydrocoef::body_references(db).json(), cli_out({"body", "show", "--json"}));
}

TEST_F(ReferenceApiTest, CoefficientsGiveTheCliNumbersTextJsonAndCsv) {
  {
    auto db = Database::open(path_, OpenMode::ReadWrite);
    hydrocoef::set_body_reference(db, sphere_options());
  }
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  hydrocoef::CoefficientOptions options;
  options.where = {"u>0.05"};
  options.area = "L*d";
  const auto table = hydrocoef::run_coefficients(db, options);
  const std::vector<std::string> args = {"runs", "--coefficients", "--where", "u>0.05", "--area", "L*d"};
  auto with = [&](const char* flag) {
    auto a = args;
    a.push_back(flag);
    return cli_out(a);
  };
  EXPECT_EQ(table.text(), cli_out(args));
  EXPECT_EQ(table.json(), with("--json"));
  EXPECT_EQ(table.csv(), with("--csv"));
  const json theirs = json::parse(with("--json"));
  ASSERT_EQ(table.size(), 4u);
  ASSERT_EQ(theirs["runs"].size(), 4u);
  const char* names[] = {"C_X", "C_Y", "C_Z", "C_K", "C_M", "C_N"};
  for (std::size_t i = 0; i < table.size(); ++i) {
    const json& run = theirs["runs"][i];
    EXPECT_EQ(table.id[i], run["id"].get<std::int64_t>());
    EXPECT_EQ(table.speed[i], run["speed"].get<double>());
    EXPECT_EQ(table.reynolds[i], run["reynolds"].get<double>());
    EXPECT_EQ(table.froude[i], run["froude"].get<double>());
    EXPECT_EQ(table.density[i], 998.2);
    for (std::size_t c = 0; c < 6; ++c) EXPECT_EQ(table.coefficient[c][i], run["coefficients"][names[c]].get<double>());
  }
  ASSERT_EQ(table.references.size(), 1u);
  EXPECT_EQ(table.references[0].area_name, "L*d");
  EXPECT_EQ(table.references[0].area, 0.09);
  EXPECT_EQ(table.references[0].moment_reference_point, (std::array<double, 3>{0.1, 0.0, 0.0}));
}

TEST_F(ReferenceApiTest, ValidateRefusesWithTheCliMessages) {
  const auto refused = [&](const hydrocoef::BodyReferenceOptions& options, std::vector<std::string> args) {
    args.insert(args.begin(), {"body", "set", "sphere"});
    EXPECT_EQ(error_of([&] { options.validate(); }), cli_error(cli(args)));
  };
  auto options = sphere_options();
  options.length = 0.0;
  refused(options, {"--length", "0"});
  options = sphere_options();
  options.draft = -1.0;
  refused(options, {"--draft", "-1"});
  options = sphere_options();
  options.areas["wetted"] = -0.5;
  refused(options, {"--area", "wetted=-0.5"});
  options = sphere_options();
  options.unset = {"mass"};
  refused(options, {"--unset", "mass"});
  hydrocoef::BodyReferenceOptions nothing;
  nothing.body = "sphere";
  refused(nothing, {});
  hydrocoef::CoefficientOptions bad;
  bad.where = {"u>>1"};
  EXPECT_EQ(error_of([&] { bad.validate(); }), cli_error(cli({"runs", "--coefficients", "--where", "u>>1"})));
}

TEST_F(ReferenceApiTest, AReadOnlyDatabaseRefusesAChangeLeavingTheFileByteIdentical) {
  const std::string before = hydrocoef::test::read_bytes(path_);
  auto db = Database::open(path_, OpenMode::ReadOnly);
  const std::string message = error_of([&] { hydrocoef::set_body_reference(db, sphere_options()); });
  EXPECT_NE(message.find("read-only"), std::string::npos) << message;
  EXPECT_NE(message.find("body set"), std::string::npos) << message;
  // Nothing to divide by yet: the coefficients say what to give.
  EXPECT_NE(error_of([&] { hydrocoef::run_coefficients(db); }).find("has no reference length"), std::string::npos);
  db.close();
  EXPECT_EQ(hydrocoef::test::read_bytes(path_), before);
}

}  // namespace
