// The records' operations of the public API (include/hydrocoef/records.hpp,
// database.hpp) against the CLI on the same database: an import, the runs
// (table, CSV, JSON, one run), fits (a law, weighted and not, per level,
// refit, list, a stored law evaluated), delete, merge, copy and report give
// the CLI's printed text and JSON; validate() refuses with the CLI's
// messages; a read-only Database refuses every write and leaves the file
// byte-identical.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hydrocoef/hydrocoef.hpp"
#include "tests/support/api_errors.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

using hydrocoef::test::cli_error;
using hydrocoef::test::error_of;

using hydrocoef::Database;
using hydrocoef::OpenMode;
using hydrocoef::test::run_cli;
using hydrocoef::test::TempDir;
namespace fs = std::filesystem;

const std::string kAsrV = std::string(HYDROCOEF_SOURCE_DIR) + "/examples/asr-v/";

/// The ASR-V surge table (a stated uncertainty of 2 % on X) and the yaw table, and a 2-D grid table:
/// X = -10 u|u| - 2 v at u = 0 ... 0.5, v = -0.2 ... 0.2.
hydrocoef::ImportOptions surge_options() {
  hydrocoef::ImportOptions options;
  options.body = "asr-v";
  options.sign = "opposing";
  options.rho = 998.2;
  options.nu = 1.004e-6;
  options.uncertainty = {"X=2%"};
  return options;
}

const std::vector<std::string> kSurgeCli = {"--body", "asr-v", "--sign",   "opposing",      "--rho",
                                            "998.2",  "--nu",  "1.004e-6", "--uncertainty", "X=2%"};

class RecordsApiTest : public ::testing::Test {
 protected:
  void SetUp() override {
    grid_ = (dir_ / "grid.csv").string();
    std::ofstream out(grid_);
    out << "u [m s^-1],v [m s^-1],X [N]\n";
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 5; ++j) {
        const double u = 0.1 * i, v = 0.1 * (j - 2);
        out << u << "," << v << "," << -10 * u * std::abs(u) - 2 * v + 0.01 * ((i + j) % 3 - 1) << "\n";
      }
    out.close();
    path_ = (dir_ / "api.db").string();
    auto db = Database::open(path_, OpenMode::Create);
    hydrocoef::import_prepared(db, hydrocoef::prepare_import({kAsrV + "asr-v-surge-damping.csv"}, surge_options()));
    hydrocoef::ImportOptions yaw;
    yaw.body = "asr-v";
    yaw.sign = "on-body";
    db.import_files({kAsrV + "asr-v-yaw-damping.csv"}, yaw);
    hydrocoef::ImportOptions grid;
    grid.body = "grid";
    db.import_files({grid_}, grid);
  }

  /// The CLI on database `db` (default: the test's).
  hydrocoef::test::CliResult cli(std::vector<std::string> args, const std::string& db = "") {
    args.insert(args.begin(), {"--db", db.empty() ? path_ : db});
    return run_cli(args, dir_.path());
  }
  /// Its standard output, the command having succeeded.
  std::string cli_out(std::vector<std::string> args, const std::string& db = "") {
    const auto result = cli(std::move(args), db);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return result.out;
  }
  /// A copy of the test's database.
  std::string copy(const std::string& name) {
    const auto to = dir_ / name;
    fs::copy_file(path_, to);
    return to.string();
  }

  TempDir dir_;
  std::string path_, grid_;
};

TEST_F(RecordsApiTest, AnImportReportsWhatTheCliReports) {
  const std::string api = (dir_ / "import-api.db").string(), cli_db = (dir_ / "import-cli.db").string();
  auto db = Database::open(api, OpenMode::Create);
  const auto summary = db.import_files({kAsrV + "asr-v-surge-damping.csv"}, surge_options());
  auto args = std::vector<std::string>{"import", kAsrV + "asr-v-surge-damping.csv"};
  args.insert(args.end(), kSurgeCli.begin(), kSurgeCli.end());
  auto json_args = args;
  json_args.push_back("--json");
  auto ours = nlohmann::json::parse(summary.json());
  auto theirs = nlohmann::json::parse(cli_out(json_args, cli_db));
  EXPECT_EQ(ours["database"], api);
  EXPECT_EQ(ours["summary"]["runs_created"], 20);
  // The stage times differ from run to run; the settings record where each came from (--rho), identically.
  for (auto* json : {&ours, &theirs}) {
    json->erase("timing_s");
    json->erase("database");
  }
  EXPECT_EQ(ours, theirs);
  EXPECT_EQ(summary.runs_created, 20u);
  EXPECT_EQ(summary.database, api);

  // Again: already imported, and the text (the database named) says so as the CLI does.
  auto again = db.import_files({kAsrV + "asr-v-surge-damping.csv"}, surge_options());
  std::string text = cli_out(args, cli_db);
  EXPECT_EQ(again.already_imported, 1u);
  const std::string ours_text = again.text();
  ASSERT_NE(ours_text.find(api), std::string::npos);
  EXPECT_NE(text.find(cli_db), std::string::npos);
  EXPECT_EQ(ours_text.substr(ours_text.rfind("imported 1 input")),
            "imported 1 input into " + api + ": 0 new runs, 0 extended, 1 already imported, 0 notes\n");
  EXPECT_EQ(again.text(/*quiet=*/true),
            "imported 1 input into " + api + ": 0 new runs, 0 extended, 1 already imported, 0 notes\n");
  EXPECT_EQ(text.substr(text.rfind("imported 1 input")),
            "imported 1 input into " + cli_db + ": 0 new runs, 0 extended, 1 already imported, 0 notes\n");
}

TEST_F(RecordsApiTest, ImportOptionsRefuseAsTheCliRefuses) {
  for (const auto& [option, value] : std::vector<std::pair<std::string, std::string>>{{"--ref-point", "1,2"},
                                                                                      {"--origin", "1,2,x"},
                                                                                      {"--set", "u"},
                                                                                      {"--set", "u=abc"},
                                                                                      {"--axes", "x,x,z"},
                                                                                      {"--uncertainty", "X=-1"},
                                                                                      {"--symmetry", "q=0"},
                                                                                      {"--shear", "a,b"}}) {
    hydrocoef::ImportOptions options;
    if (option == "--ref-point") options.ref_point = value;
    if (option == "--origin") options.origin = value;
    if (option == "--set") options.set = {value};
    if (option == "--axes") options.axes = value;
    if (option == "--uncertainty") options.uncertainty = {value};
    if (option == "--symmetry") options.symmetry = value;
    if (option == "--shear") options.shear = value;
    const std::string message = error_of([&] { options.validate(); });
    EXPECT_FALSE(message.empty()) << option;
    EXPECT_EQ(message, cli_error(cli({"import", kAsrV + "asr-v-surge-damping.csv", option, value},
                                     (dir_ / "never.db").string())))
        << option << " " << value;
    // Refused before anything is read or made.
    EXPECT_EQ(error_of([&] { (void)hydrocoef::prepare_import({kAsrV + "asr-v-surge-damping.csv"}, options); }),
              message);
  }
  EXPECT_FALSE(fs::exists(dir_ / "never.db"));
  // A setting given as an option and in the settings map: refused.
  hydrocoef::ImportOptions twice;
  twice.rho = 998.2;
  twice.settings = {{"rho", "1000"}};
  EXPECT_NE(error_of([&] { twice.validate(); }).find("'rho' is given twice"), std::string::npos);
}

TEST_F(RecordsApiTest, RunsPrintWhatTheCliPrints) {
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  const auto all = db.runs();
  EXPECT_EQ(all.text(), cli_out({"runs"}));
  EXPECT_EQ(all.json(), cli_out({"runs", "--json"}));
  EXPECT_EQ(all.csv(), cli_out({"runs", "--csv"}));
  const auto some = db.runs({"u>=0.3"}, "asr-v");
  EXPECT_EQ(some.size(), 5u);
  EXPECT_EQ(some.text(), cli_out({"runs", "--body", "asr-v", "--where", "u>=0.3"}));
  EXPECT_EQ(some.json(), cli_out({"runs", "--body", "asr-v", "--where", "u>=0.3", "--json"}));
  const auto none = db.runs({}, "nobody");
  EXPECT_EQ(none.text(), "no runs of body 'nobody' in " + path_ + "\n");
  EXPECT_EQ(none.text(), cli_out({"runs", "--body", "nobody"}));

  // One run: its provenance, as `runs show`.
  const auto run = hydrocoef::show_run(db, some.id[0]);
  EXPECT_EQ(run.json(), cli_out({"runs", "show", std::to_string(some.id[0]), "--json"}));
  EXPECT_EQ(run.text(), cli_out({"runs", "show", std::to_string(some.id[0])}));
  EXPECT_EQ(run.body, "asr-v");
  EXPECT_EQ(run.velocity[0], 0.30);
  EXPECT_EQ(run.force[0], 0.99881);  // as tabulated: a damping magnitude
  EXPECT_EQ(run.sign_convention[0], "opposing");
  EXPECT_EQ(run.density, 998.2);
  ASSERT_EQ(run.imports.size(), 1u);
  EXPECT_EQ(run.imports[0].importer, "force-table");
  EXPECT_TRUE(std::isnan(run.force[5]));
  EXPECT_EQ(error_of([&] { (void)hydrocoef::show_run(db, 9999); }), cli_error(cli({"runs", "show", "9999"})));
}

TEST_F(RecordsApiTest, FitsGiveTheCliJsonWeightedOrNot) {
  auto db = Database::open(path_, OpenMode::ReadWrite);
  hydrocoef::FitOptions options;
  options.body = "asr-v";
  options.output = "X";
  options.terms = "1,u,u|u|";
  options.store = false;
  const std::vector<std::string> args = {"fit", "--body", "asr-v", "--dof", "X", "--terms", "1,u,u|u|", "--no-store"};
  const auto weighted = db.fit(options);
  EXPECT_EQ(weighted.weighting, "uncertainty");  // every surge run states 2 %
  auto json_args = args;
  json_args.push_back("--json");
  EXPECT_EQ(weighted.json(), cli_out(json_args));
  EXPECT_EQ(weighted.text(), cli_out(args));
  const auto json = nlohmann::json::parse(weighted.json());
  EXPECT_EQ(json["weighting"], "uncertainty");
  EXPECT_EQ(weighted.chi2_reduced, json["chi2_reduced"].get<double>());
  EXPECT_EQ(weighted.covariance_scale, json["covariance_scale"].get<double>());
  ASSERT_EQ(weighted.covariance.size(), 9u);
  for (std::size_t i = 0; i < 9; ++i) EXPECT_EQ(weighted.covariance[i], json["covariance"][i].get<double>());
  // The covariance's diagonal is the standard errors squared.
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_NEAR(std::sqrt(weighted.covariance[k * 4]), weighted.coefficients[k].std_error,
                1e-12 * weighted.coefficients[k].std_error);

  options.weighted = false;
  const auto plain = db.fit(options);
  json_args.push_back("--unweighted");
  EXPECT_EQ(plain.json(), cli_out(json_args));
  EXPECT_EQ(plain.weighting, "none");
  EXPECT_TRUE(std::isnan(plain.chi2_reduced));
  EXPECT_NE(plain.coefficients[2].value, weighted.coefficients[2].value);
  // README: X(u) = 0.000618201 + 0.0155077 u + 11.0364 u|u| (ordinary least squares).
  EXPECT_NEAR(plain.coefficients[2].value, 11.0364, 1e-4);
}

TEST_F(RecordsApiTest, PerLevelFitsGiveTheCliJson) {
  auto db = Database::open(path_, OpenMode::ReadWrite);
  hydrocoef::FitOptions options;
  options.body = "grid";
  options.output = "X";
  options.terms = "1,u|u|";
  options.by = "v";
  options.curve = "polynomial:1";
  options.store = false;
  const auto levels = hydrocoef::fit_by_level(db, options);
  const std::vector<std::string> args = {"fit",  "--body", "grid",    "--dof",        "X",         "--terms", "1,u|u|",
                                         "--by", "v",      "--curve", "polynomial:1", "--no-store"};
  EXPECT_EQ(levels.text(), cli_out(args));
  auto json_args = args;
  json_args.push_back("--json");
  EXPECT_EQ(levels.json(), cli_out(json_args));
  ASSERT_EQ(levels.levels.size(), 5u);
  ASSERT_EQ(levels.curves.size(), 2u);
  // The constant is -2 v at each level (within the table's +-0.01 N wiggle): a line of slope -2.
  EXPECT_NEAR(levels.curves[0].polynomial[1], -2.0, 0.05);
  EXPECT_NEAR(levels.levels[0].coefficients[1].value, -10.0, 0.1);
  // Options that do not go together: the CLI's message, before the database is opened.
  options.refit = true;
  EXPECT_EQ(error_of([&] { options.validate(); }),
            cli_error(cli({"fit", "--refit", "--by", "v"}, (dir_ / "never.db").string())));
  EXPECT_FALSE(fs::exists(dir_ / "never.db"));
  options = {};
  options.body = "grid";
  EXPECT_NE(error_of([&] { (void)hydrocoef::fit_by_level(db, options); }).find("--by"), std::string::npos);
}

TEST_F(RecordsApiTest, DeleteRefitListAndEvaluateAsTheCli) {
  // One copy for the API, one for the CLI: the same fit stored in each, the same run deleted.
  const std::string api = copy("a.db"), cli_db = copy("c.db");
  auto db = Database::open(api, OpenMode::ReadWrite);
  hydrocoef::FitOptions options;
  options.body = "asr-v";
  options.output = "X";
  options.terms = "1,u,u|u|";
  options.weighted = false;
  const auto stored = db.fit(options);
  cli_out({"fit", "--body", "asr-v", "--dof", "X", "--terms", "1,u,u|u|", "--unweighted"}, cli_db);
  // Listed as `fits` lists them (created_at differs between the two databases: compared apart).
  auto listed = hydrocoef::list_fits(db);
  auto ours = nlohmann::json::parse(listed.json()), theirs = nlohmann::json::parse(cli_out({"fits", "--json"}, cli_db));
  ASSERT_EQ(ours.size(), 1u);
  EXPECT_EQ(ours[0]["created_at"], listed.fits[0].created_at);
  ours[0].erase("created_at");
  theirs[0].erase("created_at");
  EXPECT_EQ(ours, theirs);
  EXPECT_EQ(listed.fits[0].covariance, stored.covariance);
  EXPECT_EQ(nlohmann::json::parse(cli_out({"fits", "--json"}, api))[0], nlohmann::json::parse(listed.fits[0].json()));
  EXPECT_EQ(listed.text(), cli_out({"fits"}, api));

  // The stored law evaluated: sum c_k b_k(x), its standard error sqrt(b^T C b).
  const auto values = hydrocoef::evaluate_fit(db, {stored.name, {0.0, 0.2, -0.1, 0.5}});
  EXPECT_EQ(values.json(),
            cli_out({"fits", "evaluate", stored.name, "--at", "0,0.2", "--at", "-0.1,0.5", "--json"}, api));
  EXPECT_EQ(values.text(), cli_out({"fits", "evaluate", stored.name, "--at", "0,0.2,-0.1,0.5"}, api));
  const auto& c = stored.coefficients;
  const auto& cov = stored.covariance;
  for (std::size_t i = 0; i < values.at.size(); ++i) {
    const double x = values.at[i];
    const double b[3] = {1.0, x, x * std::abs(x)};
    double value = 0.0, variance = 0.0;
    for (std::size_t k = 0; k < 3; ++k) value += c[k].value * b[k];
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t l = 0; l < 3; ++l) variance += b[k] * cov[k * 3 + l] * b[l];
    EXPECT_NEAR(values.value[i], value, 1e-12) << x;
    EXPECT_NEAR(values.std_error[i], std::sqrt(variance), 1e-15) << x;
  }
  EXPECT_NEAR(values.std_error[0], c[0].std_error, 1e-12 * c[0].std_error);  // at u = 0 only the constant is left
  EXPECT_EQ(values.unit, "N");
  EXPECT_EQ(values.fitted_min, 0.0);
  EXPECT_EQ(values.fitted_max, 0.38);
  EXPECT_EQ(error_of([&] {
              (void)hydrocoef::evaluate_fit(db, {"nope", {0.1}});
            }),
            cli_error(cli({"fits", "evaluate", "nope", "--at", "0.1"}, api)));
  EXPECT_EQ(error_of([&] {
              (void)hydrocoef::evaluate_fit(db, {stored.name, {}});
            }),
            "fits evaluate: expected at least one value of the law's velocity (--at)");

  // Delete the run at u = 0.38 from both.
  const auto runs = db.runs({"u=0.38"}, "asr-v");
  ASSERT_EQ(runs.size(), 1u);
  hydrocoef::DeleteRunsOptions deletion;
  deletion.ids = {runs.id[0]};
  const auto deleted = hydrocoef::delete_runs(db, deletion);
  EXPECT_EQ(deleted.json(), cli_out({"runs", "delete", std::to_string(runs.id[0]), "--json"}, cli_db));
  EXPECT_EQ(deleted.runs, 1u);
  EXPECT_EQ(deleted.fits_made_stale, 1u);
  EXPECT_EQ(deleted.text().rfind("deleted 1 run (1 force components) from " + api + ";", 0), 0u);
  EXPECT_TRUE(hydrocoef::list_fits(db).fits[0].stale);
  EXPECT_EQ(error_of([&] { (void)hydrocoef::delete_runs(db, {}); }), cli_error(cli({"runs", "delete"}, cli_db)));
  deletion = {};
  deletion.where = {"u>=abc"};
  EXPECT_EQ(error_of([&] { deletion.validate(); }), cli_error(cli({"runs", "delete", "--where", "u>=abc"}, cli_db)));

  // Refit: the stale fit made again from 19 runs, as `fit --refit`.
  const auto refits = hydrocoef::refit_fits(db, {});
  EXPECT_EQ(refits.json(), cli_out({"fit", "--refit", "--json"}, cli_db));
  ASSERT_EQ(refits.made.size(), 1u);
  EXPECT_EQ(refits.made[0].runs.size(), 19u);
  EXPECT_EQ(refits.previous[0].runs.size(), 20u);
  EXPECT_EQ(hydrocoef::refit_fits(db, {}).text(), "no stale fits in " + api + "; nothing to fit again\n");
  hydrocoef::FitOptions bad;
  bad.refit = true;
  bad.output = "X";
  EXPECT_EQ(error_of([&] { (void)hydrocoef::refit_fits(db, bad); }),
            cli_error(cli({"fit", "--refit", "--dof", "X"}, cli_db)));
}

TEST_F(RecordsApiTest, MergeCopyAndReportAsTheCli) {
  const std::string shard = copy("shard.db");
  {
    auto into = Database::open((dir_ / "merged-api.db").string(), OpenMode::Create);
    const auto merged = hydrocoef::merge_databases(into, {{shard}, {}});
    auto ours = nlohmann::json::parse(merged.json());
    auto theirs = nlohmann::json::parse(cli_out({"merge", shard, "--json"}, (dir_ / "merged-cli.db").string()));
    EXPECT_EQ(ours["into"], (dir_ / "merged-api.db").string());
    EXPECT_EQ(ours["shards"], theirs["shards"]);
    ASSERT_EQ(merged.shards.size(), 1u);
    EXPECT_EQ(merged.shards[0].runs_created, 20u + 19u + 30u);
    EXPECT_NE(merged.text().find("merged 1 shard(s) into " + (dir_ / "merged-api.db").string()), std::string::npos);
    // Merging twice adds nothing.
    EXPECT_EQ(hydrocoef::merge_databases(into, {{shard}, {}}).shards[0].runs_created, 0u);
    EXPECT_EQ(error_of([&] { (void)hydrocoef::merge_databases(into, {}); }),
              "merge: expected at least one shard database");

    EXPECT_EQ(hydrocoef::migration(into).from, 0);  // made by this open
    const auto migrated = hydrocoef::migration(Database::open(into.path(), OpenMode::ReadWrite));
    EXPECT_EQ(migrated.from, migrated.to);
    EXPECT_GT(migrated.to, 10);
    EXPECT_EQ(nlohmann::json::parse(migrated.json())["to"],
              nlohmann::json::parse(cli_out({"migrate", "--json"}, (dir_ / "merged-api.db").string()))["to"]);
  }
  {
    const auto from = Database::open(shard, OpenMode::ReadOnly);
    auto to = Database::open((dir_ / "copy-api.db").string(), OpenMode::Create);
    const auto copied = hydrocoef::copy_database(from, to);
    auto ours = nlohmann::json::parse(copied.json());
    auto theirs = nlohmann::json::parse(
        cli_out({"copy", "--from", shard, "--to", (dir_ / "copy-cli.db").string(), "--json"}, shard));
    EXPECT_EQ(ours["rows"], theirs["rows"]);
    EXPECT_EQ(to.runs().json(), from.runs().json());
    EXPECT_FALSE(error_of([&] { (void)hydrocoef::copy_database(from, to); }).empty());  // not empty any more
  }
  {
    const auto db = Database::open(path_, OpenMode::ReadOnly);
    hydrocoef::ReportOptions options;
    options.output = (dir_ / "report-api").string();
    options.body = "asr-v";
    const auto report = hydrocoef::write_report(db, options);
    auto theirs =
        nlohmann::json::parse(cli_out({"report", "-o", (dir_ / "report-cli").string(), "--body", "asr-v", "--json"}));
    auto ours = nlohmann::json::parse(report.json());
    EXPECT_EQ(ours["index"], (dir_ / "report-api" / "index.html").string());
    for (const char* key : {"runs", "fits", "surfaces", "histories", "sigma_maps", "mesh_study_rows", "pmm_fits"})
      EXPECT_EQ(ours[key], theirs[key]) << key;
    EXPECT_EQ(ours["plots"].size(), theirs["plots"].size());
    EXPECT_EQ(report.runs, 39u);
    EXPECT_TRUE(fs::exists(report.index));
    hydrocoef::ReportOptions no_output;
    EXPECT_EQ(error_of([&] { no_output.validate(); }),
              "report: expected the directory to write the report into (-o DIR)");
    options.body = "nobody";
    options.output = (dir_ / "report-none").string();
    EXPECT_EQ(error_of([&] { (void)hydrocoef::write_report(db, options); }),
              cli_error(cli({"report", "-o", (dir_ / "report-none").string(), "--body", "nobody"})));
  }
}

TEST_F(RecordsApiTest, AReadOnlyDatabaseRefusesEveryWriteAndStaysByteIdentical) {
  const std::string shard = copy("shard.db");
  const std::string before = hydrocoef::test::read_bytes(path_);
  {
    auto db = Database::open(path_, OpenMode::ReadOnly);
    auto other = Database::open((dir_ / "other.db").string(), OpenMode::Create);
    hydrocoef::FitOptions fit;
    fit.body = "asr-v";
    fit.output = "X";
    fit.terms = "1,u,u|u|";
    hydrocoef::FitOptions by_level = fit;
    by_level.body = "grid";
    by_level.by = "v";
    hydrocoef::DeleteRunsOptions deletion;
    deletion.ids = {1};
    const std::vector<std::function<void()>> writes = {
        [&] { hydrocoef::import_prepared(db, hydrocoef::prepare_import({grid_}, {})); },
        [&] { db.import_files({grid_}, {}); },
        [&] { db.fit(fit); },
        [&] { hydrocoef::fit_by_level(db, by_level); },
        [&] { hydrocoef::refit_fits(db, {}); },
        [&] { hydrocoef::delete_runs(db, deletion); },
        [&] {
          hydrocoef::merge_databases(db, {{shard}, {}});
        },
        [&] { hydrocoef::copy_database(other, db); },
    };
    for (std::size_t i = 0; i < writes.size(); ++i)
      EXPECT_NE(error_of(writes[i]).find("database is open read-only"), std::string::npos) << "write " << i;
    // Reading is fine, and a fit that stores nothing too.
    fit.store = false;
    EXPECT_EQ(db.fit(fit).id, 0);
  }
  EXPECT_EQ(hydrocoef::test::read_bytes(path_), before);
  // A prepared import is stored once.
  auto db = Database::open((dir_ / "once.db").string(), OpenMode::Create);
  auto prepared = hydrocoef::prepare_import({grid_}, {});
  hydrocoef::import_prepared(db, std::move(prepared));
  EXPECT_EQ(error_of([&] { hydrocoef::import_prepared(db, std::move(prepared)); }),
            "import: these inputs were stored already; prepare the import again");
}

}  // namespace
