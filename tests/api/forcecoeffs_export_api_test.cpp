// export_forcecoeffs (include/hydrocoef/exports.hpp) through the public API
// against `hydrocoef export --format openfoam-forcecoeffs` on the same
// database of the four OpenFOAM sphere runs (full domain, forces averaged over
// windows of 1000-iteration histories, so their traces are binned and each
// file holds one row of the stored forces): the API writes the CLI's files
// byte for byte and reports the CLI's numbers; the files imported again
// through Database::import_files give the stored forces back (each to the
// last bit or the double next to it, as many exact as the export counted);
// validate() refuses with the CLI's messages; a read-only database exports
// and stays byte-identical.
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

namespace fs = std::filesystem;
using hydrocoef::Database;
using hydrocoef::OpenMode;
using hydrocoef::test::cli_error;
using hydrocoef::test::error_of;
using hydrocoef::test::run_cli;
using hydrocoef::test::TempDir;
using nlohmann::json;

class ForceCoeffsExportApiTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(hydrocoef::test::import_sphere_cases(dir_.path()).exit_code, 0);
    path_ = (dir_ / "hydrocoef.db").string();
    cli_out({"body", "set", "sphere", "--length", "0.3", "--area", "frontal=0.070685834705770348"});
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
  TempDir dir_;
  std::string path_;
};

TEST_F(ForceCoeffsExportApiTest, WritesAndReportsWhatTheCliDoes) {
  const json theirs = json::parse(cli_out({"export", "--format", "openfoam-forcecoeffs", "-o", "cli", "--json"}));
  hydrocoef::ForceCoeffsExportOptions options;
  options.output = (dir_ / "api").string();
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  const auto ours = hydrocoef::export_forcecoeffs(db, options);
  const json ours_json = json::parse(ours.json());
  ASSERT_EQ(ours.runs.size(), 4u);
  ASSERT_EQ(theirs["runs"].size(), 4u);
  for (const char* key : {"values", "exact", "one_ulp", "precision", "format", "convention"})
    EXPECT_EQ(ours_json[key], theirs[key]) << key;
  EXPECT_EQ(ours.values, 24u);
  EXPECT_EQ(ours.exact + ours.one_ulp, ours.values);
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& r = ours.runs[i];
    const auto& t = theirs["runs"][i];
    EXPECT_EQ(r.id, t["id"].get<std::int64_t>());
    EXPECT_EQ(r.rows_from, "stored forces");  // 1000 iterations: the trace is binned
    EXPECT_EQ(r.rows, 1u);
    EXPECT_EQ(r.axes, "-x,y,-z");
    EXPECT_EQ(r.rho, 998.2);
    EXPECT_EQ(r.a_ref, 0.070685834705770348);
    EXPECT_EQ(r.l_ref, 0.3);
    for (std::size_t k = 0; k < 6; ++k) {
      const char* names[] = {"Cd", "Cs", "Cl", "CmRoll", "CmPitch", "CmYaw"};
      EXPECT_EQ(r.last_coefficients[k], t["last_coefficients"][names[k]].get<double>()) << names[k];
    }
    // The same file, byte for byte, under the other folder.
    const fs::path relative = fs::path(r.file).lexically_relative(dir_ / "api");
    EXPECT_EQ(hydrocoef::test::read_bytes(r.file), hydrocoef::test::read_bytes(dir_ / "cli" / relative)) << relative;
    // Drag along the case's +x (the stream) is the body's -X: Cd > 0 for these runs.
    EXPECT_GT(r.last_coefficients[0], 0.1);
  }
}

TEST_F(ForceCoeffsExportApiTest, ImportedAgainGivesTheStoredForcesBack) {
  const json original = json::parse(cli_out({"runs", "--json"}));
  hydrocoef::ForceCoeffsExportOptions options;
  options.output = (dir_ / "out").string();
  hydrocoef::ForceCoeffsExportResult result;
  {
    const auto db = Database::open(path_, OpenMode::ReadOnly);
    result = hydrocoef::export_forcecoeffs(db, options);
  }
  ASSERT_EQ(result.runs.size(), original.size());
  const std::string again_path = (dir_ / "again.db").string();
  std::size_t exact = 0, values = 0;
  {
    auto again = Database::open(again_path, OpenMode::Create);
    for (std::size_t i = 0; i < result.runs.size(); ++i) {
      const json& run = original[i];
      ASSERT_EQ(run["id"].get<std::int64_t>(), result.runs[i].id);
      hydrocoef::ImportOptions import;
      import.body = "sphere";
      import.rho = result.runs[i].rho;
      import.axes = result.runs[i].axes;
      import.set = {"u=" + run["u"].dump(), "v=" + run["v"].dump()};
      again.import_files({result.runs[i].file}, import);
    }
  }
  const json back = json::parse(run_cli({"--db", again_path, "runs", "--json"}, dir_.path()).out);
  ASSERT_EQ(back.size(), original.size());
  const char* names[] = {"X", "Y", "Z", "K", "M", "N"};
  for (std::size_t i = 0; i < back.size(); ++i) {
    EXPECT_EQ(back[i]["u"], original[i]["u"]);
    EXPECT_EQ(back[i]["v"], original[i]["v"]);
    for (const char* name : names) {
      const double stored = original[i]["forces"][name]["total"].get<double>();
      const double read = back[i]["forces"][name]["total"].get<double>();
      ++values;
      if (read == stored)
        ++exact;
      else
        EXPECT_EQ(std::nextafter(stored, read), read)
            << "run " << i << " " << name << ": " << read << " for " << stored;
    }
  }
  EXPECT_EQ(values, result.values);
  EXPECT_EQ(exact, result.exact);
}

TEST_F(ForceCoeffsExportApiTest, ValidateRefusesWithTheCliMessages) {
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  const auto both = [&](const hydrocoef::ForceCoeffsExportOptions& options, std::vector<std::string> args) {
    const std::string api = error_of([&] { hydrocoef::export_forcecoeffs(db, options); });
    args.insert(args.begin(), {"export", "--format", "openfoam-forcecoeffs", "-o", "out"});
    EXPECT_EQ(api, cli_error(cli(args)));
    EXPECT_FALSE(fs::exists(dir_ / "out"));
  };
  hydrocoef::ForceCoeffsExportOptions options;
  options.output = "out";
  options.precision = 0;
  both(options, {"--precision", "0"});
  options.precision = 16;
  options.axes = "x,y";
  both(options, {"--axes", "x,y"});
  options.axes = "";
  options.where = {"u>>1"};
  both(options, {"--where", "u>>1"});
  options.where = {};
  options.area = "wetted";
  both(options, {"--area", "wetted"});
  options.area = "";
  options.output = "";
  EXPECT_NE(error_of([&] { options.validate(); }).find("-o FOLDER"), std::string::npos);
}

TEST_F(ForceCoeffsExportApiTest, AReadOnlyDatabaseExportsAndStaysAsItWas) {
  const std::string before = hydrocoef::test::read_bytes(path_);
  {
    const auto db = Database::open(path_, OpenMode::ReadOnly);
    hydrocoef::ForceCoeffsExportOptions options;
    options.output = (dir_ / "ro").string();
    EXPECT_EQ(hydrocoef::export_forcecoeffs(db, options).runs.size(), 4u);
  }
  EXPECT_EQ(hydrocoef::test::read_bytes(path_), before);
}

}  // namespace
