// The analyses of include/hydrocoef/analysis.hpp driven through the public
// C++ API and through the hydrocoef CLI on the same databases: the mesh
// study of data/openfoam-sphere/converged (gci), the forced-oscillation runs
// of examples/openfoam-sphere/pmm (pmm, pmm-runs, pmm-runs delete,
// added-mass) and a GP surface's next runs (suggest) give the same numbers
// and the same documents both ways; validate() refuses each bad option with
// the CLI's message; a read-only Database refuses every write and leaves the
// file byte-identical.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <sstream>
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

namespace fs = std::filesystem;
using hydrocoef::Database;
using hydrocoef::OpenMode;
using hydrocoef::test::run_cli;
using hydrocoef::test::TempDir;
using nlohmann::json;

const fs::path kSource = HYDROCOEF_SOURCE_DIR;
const fs::path kConverged = kSource / "data/openfoam-sphere/converged";
const fs::path kPmm = kSource / "examples/openfoam-sphere/pmm";
constexpr double kSphereVolume = 4.0 / 3.0 * 3.14159265358979323846 * 0.15 * 0.15 * 0.15;

std::string number_text(double value) {
  std::ostringstream text;
  text << std::setprecision(17) << value;
  return text.str();
}

class AnalysisApiTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // The API opens the SQLite file the CLI is given; on the PostgreSQL
    // backend the CLI would read a schema instead.
    if (hydrocoef::test::on_postgresql()) GTEST_SKIP() << "the API and the CLI share an SQLite file here";
    path_ = (dir_ / "analysis.db").string();
  }

  hydrocoef::test::CliResult cli(std::vector<std::string> args, const std::string& path = "") {
    args.insert(args.begin(), {"--db", path.empty() ? path_ : path});
    return run_cli(args, dir_.path());
  }

  std::string cli_out(const std::vector<std::string>& args, const std::string& path = "") {
    const auto result = cli(args, path);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return result.out;
  }

  /// The six runs of the converged mesh study, each with its mesh level and cell count.
  void import_mesh_study() {
    std::ifstream in(kConverged / "reference.json");
    const json cases = json::parse(in)["cases"];
    auto db = Database::open(path_, OpenMode::Create);
    for (const auto& [name, entry] : cases.items()) {
      hydrocoef::ImportOptions options;
      options.body = "sphere";
      options.settings["disturbances"] = json{{"mesh", entry["mesh"]}, {"cells", entry["cells"]}}.dump();
      const auto summary = db.import_files({(kConverged / entry["case"].get<std::string>()).string()}, options);
      ASSERT_EQ(summary.runs_created, 1u) << name;
    }
  }

  /// The sphere's two forced-oscillation runs, as the CLI test analyses them.
  hydrocoef::PmmOptions sphere_options() const {
    hydrocoef::PmmOptions options;
    options.body = "sphere";
    options.axes = "-x,y,-z";
    options.rho = 998.2;
    options.nu = 1.004e-6;
    options.volume = kSphereVolume;
    options.size = 0.3;
    return options;
  }
  std::vector<std::string> sphere_inputs() const {
    return {(kPmm / "surge-A0.015-T2").string(), (kPmm / "surge-A0.045-T2").string()};
  }
  std::vector<std::string> sphere_cli_args() const {
    return {"pmm",
            sphere_inputs()[0],
            sphere_inputs()[1],
            "--body",
            "sphere",
            "--axes=-x,y,-z",
            "--rho",
            "998.2",
            "--nu",
            "1.004e-6",
            "--volume",
            number_text(kSphereVolume),
            "--size",
            "0.3"};
  }

  TempDir dir_;
  std::string path_;
};

TEST_F(AnalysisApiTest, GridConvergenceGivesTheCliStudy) {
  import_mesh_study();
  const std::string copy = (dir_ / "copy.db").string();
  fs::copy_file(path_, copy);

  // Studied, not stored: the same document and table as gci --no-store.
  hydrocoef::GciOptions options;
  options.body = "sphere";
  options.allow_unconverged = true;
  options.store = false;
  {
    auto db = Database::open(path_, OpenMode::ReadOnly);
    const auto study = hydrocoef::grid_convergence(db, options);
    const std::string cli_json = cli_out({"gci", "--body", "sphere", "--allow-unconverged", "--no-store", "--json"});
    EXPECT_EQ(study.json() + "\n", cli_json);
    EXPECT_EQ(study.text(), cli_out({"gci", "--body", "sphere", "--allow-unconverged", "--no-store"}));
    const json document = json::parse(cli_json);
    ASSERT_EQ(study.keys.size(), 2u);
    ASSERT_EQ(document["keys"].size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
      const auto& key = study.keys[k];
      EXPECT_EQ(key.velocity[0], document["keys"][k]["key"]["u"].get<double>());
      EXPECT_EQ(key.runs, document["keys"][k]["runs"].get<std::vector<std::int64_t>>());
      ASSERT_FALSE(key.components.empty());
      const auto& x = key.components[0];
      const auto& x_json = document["keys"][k]["components"]["X"];
      EXPECT_EQ(x.component, "X");
      ASSERT_TRUE(x.apparent_order && x.gci_fine && x.numerical_uncertainty);
      EXPECT_EQ(*x.apparent_order, x_json["apparent_order"].get<double>());
      EXPECT_EQ(*x.extrapolated, x_json["extrapolated"].get<double>());
      EXPECT_EQ(*x.gci_fine, x_json["gci_fine"].get<double>());
      EXPECT_EQ(*x.numerical_uncertainty, x_json["numerical_uncertainty"].get<double>());
      EXPECT_GT(*x.apparent_order, 0.0);
    }
    EXPECT_FALSE(study.stored);
  }

  // Storing needs a writable database: refused read-only, the file unchanged.
  const std::string before = hydrocoef::test::read_bytes(path_);
  options.store = true;
  {
    auto db = Database::open(path_, OpenMode::ReadOnly);
    EXPECT_NE(error_of([&] { hydrocoef::grid_convergence(db, options); }).find("read-only"), std::string::npos);
  }
  EXPECT_EQ(hydrocoef::test::read_bytes(path_), before);

  // Stored through the API and through the CLI: the same document and the same runs after.
  {
    auto db = Database::open(path_, OpenMode::ReadWrite);
    const auto study = hydrocoef::grid_convergence(db, options);
    EXPECT_TRUE(study.stored);
    const std::string cli_json = cli_out({"gci", "--body", "sphere", "--allow-unconverged", "--json"}, copy);
    EXPECT_EQ(study.json() + "\n", cli_json);
    EXPECT_TRUE(json::parse(cli_json)["stored"].get<bool>());
  }
  EXPECT_EQ(cli_out({"runs", "--json"}), cli_out({"runs", "--json"}, copy));
}

TEST_F(AnalysisApiTest, ForcedOscillationGivesTheCliNumbers) {
  // Analysed, nothing stored: the same document and text as pmm --no-store.
  auto args = sphere_cli_args();
  args.push_back("--no-store");
  auto analysis = hydrocoef::analyse_pmm(sphere_inputs(), sphere_options());
  auto json_args = args;
  json_args.push_back("--json");
  const std::string cli_json = cli_out(json_args);
  EXPECT_EQ(analysis.json() + "\n", cli_json);
  EXPECT_EQ(analysis.text(), cli_out(args));
  EXPECT_FALSE(fs::exists(path_)) << "pmm --no-store made a database";
  const json document = json::parse(cli_json);
  ASSERT_EQ(analysis.runs.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& run = analysis.runs[k];
    const auto& run_json = document["runs"][k];
    EXPECT_EQ(run.dof, "surge");
    EXPECT_EQ(run.period, run_json["motion"]["period_s"].get<double>());
    ASSERT_EQ(run.components.at(0).component, "X");
    const auto& x = run.components[0];
    EXPECT_EQ(x.added_mass, run_json["components"][0]["added_mass"].get<double>());
    EXPECT_EQ(x.damping, run_json["components"][0]["damping"].get<double>());
    ASSERT_TRUE(x.added_mass_coefficient.has_value());
    EXPECT_EQ(*x.added_mass_coefficient, run_json["components"][0]["added_mass_coefficient"].get<double>());
    EXPECT_NEAR(*x.added_mass_coefficient, 0.5, 0.05);  // half the displaced mass, within 10 %
    EXPECT_EQ(run.stored_id, 0);
  }

  // Stored by the API in one database and by the CLI in another: the same
  // listing (but the time each was made) and the same assembled matrix.
  {
    auto db = Database::open(path_, OpenMode::Create);
    hydrocoef::store_pmm(db, analysis);
  }
  EXPECT_TRUE(analysis.stored);
  EXPECT_EQ(analysis.database, path_);
  EXPECT_GT(analysis.runs[0].stored_id, 0);
  const std::string other = (dir_ / "other.db").string();
  auto store_args = sphere_cli_args();
  store_args.push_back("--json");
  const json stored = json::parse(cli_out(store_args, other));
  for (std::size_t k = 0; k < 2; ++k)
    EXPECT_EQ(analysis.runs[k].stored_id, stored["runs"][k]["stored"]["id"].get<std::int64_t>());

  const auto db = Database::open(path_, OpenMode::ReadOnly);
  const auto list = hydrocoef::pmm_runs(db);
  EXPECT_EQ(list.json() + "\n", cli_out({"pmm-runs", "--json"}));
  EXPECT_EQ(list.text(), cli_out({"pmm-runs"}));
  json ours = json::parse(list.json()), theirs = json::parse(cli_out({"pmm-runs", "--json"}, other));
  ASSERT_EQ(ours.size(), 2u);
  for (auto* listing : {&ours, &theirs})
    for (auto& entry : *listing) entry.erase("created_at");
  EXPECT_EQ(ours, theirs);
  EXPECT_EQ(*list.runs[0].added_mass, analysis.runs[0].components[0].added_mass);

  hydrocoef::AddedMassMatrixOptions matrix_options;
  matrix_options.body = "sphere";
  matrix_options.same = {{"sway", "surge"}, {"heave", "surge"}};
  matrix_options.zero = {"roll", "pitch", "yaw"};
  const auto matrix = hydrocoef::added_mass_matrix(db, matrix_options);
  const std::vector<std::string> matrix_args = {"added-mass", "sphere",      "--same", "sway=surge",
                                                "--same",     "heave=surge", "--zero", "roll,pitch,yaw"};
  auto matrix_json_args = matrix_args;
  matrix_json_args.push_back("--json");
  const std::string matrix_json = cli_out(matrix_json_args);
  EXPECT_EQ(matrix.json() + "\n", matrix_json);
  EXPECT_EQ(matrix.text(), cli_out(matrix_args));
  const json assembled = json::parse(matrix_json);
  EXPECT_TRUE(matrix.positive_definite);
  EXPECT_EQ(matrix.records, 2u);
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = 0; j < 6; ++j) {
      EXPECT_EQ(matrix.added_mass[i][j], assembled["added_mass_b"][i][j].get<double>()) << i << " " << j;
      EXPECT_EQ(matrix.damping[i][j], assembled["damping_b"][i][j].get<double>()) << i << " " << j;
    }
  EXPECT_EQ(matrix.added_mass[1][1], matrix.added_mass[0][0]);  // sway as surge
  EXPECT_NEAR(matrix.added_mass[0][0] / (998.2 * kSphereVolume), 0.5, 0.05);
  ASSERT_EQ(matrix.quadratic_damping.size(), 1u);  // two amplitudes at one frequency
  EXPECT_EQ(matrix.quadratic_damping[0].quadratic, assembled["quadratic_damping"][0]["quadratic"].get<double>());
}

TEST_F(AnalysisApiTest, DeletingPmmRunsIsTheCliDeletionAndReadOnlyRefusesWrites) {
  auto analysis = hydrocoef::analyse_pmm(sphere_inputs(), sphere_options());
  {
    auto db = Database::open(path_, OpenMode::Create);
    hydrocoef::store_pmm(db, analysis);
  }
  const std::int64_t first = analysis.runs[0].stored_id;
  const std::string before = hydrocoef::test::read_bytes(path_);
  {
    auto db = Database::open(path_, OpenMode::ReadOnly);
    EXPECT_NE(error_of([&] { hydrocoef::store_pmm(db, analysis); }).find("read-only"), std::string::npos);
    EXPECT_NE(error_of([&] { hydrocoef::delete_pmm_runs(db, {first}); }).find("read-only"), std::string::npos);
  }
  EXPECT_EQ(hydrocoef::test::read_bytes(path_), before);

  // An id that is not stored deletes nothing, with the CLI's message.
  const std::string refused = cli_error(cli({"pmm-runs", "delete", std::to_string(first), "999"}));
  EXPECT_NE(refused.find("no forced-oscillation run 999"), std::string::npos) << refused;
  {
    auto db = Database::open(path_, OpenMode::ReadWrite);
    EXPECT_EQ(error_of([&] { hydrocoef::delete_pmm_runs(db, {first, 999}); }), refused);
  }
  EXPECT_EQ(hydrocoef::pmm_runs(Database::open(path_, OpenMode::ReadOnly)).runs.size(), 2u);
  const std::string copy = (dir_ / "copy.db").string();
  fs::copy_file(path_, copy);

  hydrocoef::PmmDeletion deletion;
  {
    auto db = Database::open(path_, OpenMode::ReadWrite);
    deletion = hydrocoef::delete_pmm_runs(db, {first});
  }
  json ours = json::parse(deletion.json());
  json theirs = json::parse(cli_out({"pmm-runs", "delete", std::to_string(first), "--json"}, copy));
  EXPECT_EQ(ours["database"], path_);
  EXPECT_EQ(theirs["database"], copy);
  ours.erase("database");
  theirs.erase("database");
  EXPECT_EQ(ours, theirs);
  ASSERT_EQ(deletion.deleted.size(), 1u);
  EXPECT_EQ(deletion.deleted[0].id, first);
  EXPECT_EQ(deletion.deleted[0].dof, "surge");
  const auto left = hydrocoef::pmm_runs(Database::open(path_, OpenMode::ReadOnly));
  ASSERT_EQ(left.runs.size(), 1u);
  EXPECT_EQ(left.runs[0].id, analysis.runs[1].stored_id);
}

TEST_F(AnalysisApiTest, SuggestGivesTheCliRunsAndManifest) {
  {
    auto db = Database::open(path_, OpenMode::Create);
    hydrocoef::ImportOptions options;
    options.body = "asr-v";
    options.settings = {{"sign", "opposing"}, {"rho", "998.2"}};
    db.import_files({(kSource / "examples/asr-v/asr-v-surge-damping.csv").string()}, options);
    hydrocoef::SurfaceBuildOptions build;
    build.name = "surge-gp";
    build.body = "asr-v";
    build.axes = {"u"};
    build.outputs = {"X"};
    build.method = "gp";
    build.gp_starts = 2;
    db.build_surface(build);
  }
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  hydrocoef::SuggestOptions options;
  options.surface = "surge-gp";
  options.count = 3;
  options.bounds = {"u=0.05:0.35"};
  options.manifest = (dir_ / "api.csv").string();
  const auto suggestion = hydrocoef::suggest_runs(db, options);
  const std::vector<std::string> args = {"suggest", "surge-gp", "--count", "3", "--bounds", "u=0.05:0.35"};
  auto json_args = args;
  for (const char* a : {"--json", "--manifest", "cli.csv"}) json_args.push_back(a);
  const json document = json::parse(cli_out(json_args));
  json ours = json::parse(suggestion.json());
  EXPECT_EQ(ours["manifest"], options.manifest);
  ours.erase("manifest");
  json theirs = document;
  theirs.erase("manifest");
  EXPECT_EQ(ours, theirs);
  EXPECT_EQ(hydrocoef::test::read_bytes(options.manifest), hydrocoef::test::read_bytes(dir_ / "cli.csv"));
  ASSERT_EQ(suggestion.runs.size(), 3u);
  EXPECT_EQ(suggestion.axes, std::vector<std::string>{"u"});
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(suggestion.runs[i].key.at(0), document["runs"][i]["key"]["u"].get<double>());
    EXPECT_EQ(suggestion.runs[i].sd_before, document["runs"][i]["sd_before"].get<double>());
    EXPECT_GE(suggestion.runs[i].key[0], 0.05);
    EXPECT_LE(suggestion.runs[i].key[0], 0.35);
  }
  EXPECT_LT(suggestion.largest_sd_after, suggestion.runs[0].sd_before);
  options.manifest.clear();
  EXPECT_EQ(hydrocoef::suggest_runs(db, options).text(), cli_out(args));
}

TEST_F(AnalysisApiTest, ValidateRefusesEachBadOptionWithTheCliMessage) {
  import_mesh_study();
  const auto refused_alike = [&](const std::function<void()>& validate, const std::vector<std::string>& args) {
    std::string joined;
    for (const auto& a : args) joined += a + " ";
    const std::string message = error_of(validate);
    EXPECT_FALSE(message.empty()) << joined;
    EXPECT_EQ(message, cli_error(cli(args))) << joined;
  };
  hydrocoef::GciOptions gci;
  gci.body = "sphere";
  gci.dimension = 4;
  refused_alike([&] { gci.validate(); }, {"gci", "--body", "sphere", "--dimension", "4"});
  gci.dimension = 3;
  gci.volume = -1.0;
  refused_alike([&] { gci.validate(); }, {"gci", "--body", "sphere", "--volume", "-1"});
  gci.volume.reset();
  gci.mesh_parameter = "cells";
  refused_alike([&] { gci.validate(); }, {"gci", "--body", "sphere", "--mesh-param", "cells"});

  const std::string input = sphere_inputs()[0];
  hydrocoef::PmmOptions pmm;
  pmm.motion = "surge";
  pmm.amplitude = 0.05;
  refused_alike([&] { pmm.validate(); }, {"pmm", input, "--motion", "surge", "--amplitude", "0.05"});
  pmm.period = 2.0;
  pmm.motion = "twist";
  refused_alike([&] { pmm.validate(); }, {"pmm", input, "--motion", "twist", "--amplitude", "0.05", "--period", "2"});
  pmm.motion = "surge";
  pmm.amplitude = -1.0;
  refused_alike([&] { pmm.validate(); }, {"pmm", input, "--motion", "surge", "--amplitude", "-1", "--period", "2"});
  pmm = {};
  pmm.harmonics = 11;
  refused_alike([&] { pmm.validate(); }, {"pmm", input, "--harmonics", "11"});
  pmm = {};
  pmm.size = 0.0;
  refused_alike([&] { pmm.validate(); }, {"pmm", input, "--size", "0"});
  pmm = {};
  pmm.axes = "x,x,z";
  refused_alike([&] { pmm.validate(); }, {"pmm", input, "--axes", "x,x,z"});
  pmm = {};
  pmm.rho = std::nan("");
  refused_alike([&] { pmm.validate(); }, {"pmm", input, "--rho", "nan"});

  hydrocoef::AddedMassMatrixOptions added;
  added.body = "sphere";
  added.zero = {"twist"};
  refused_alike([&] { added.validate(); }, {"added-mass", "sphere", "--zero", "twist"});
  added.zero.clear();
  added.same = {{"sway", "drift"}};
  refused_alike([&] { added.validate(); }, {"added-mass", "sphere", "--same", "sway=drift"});

  hydrocoef::SuggestOptions suggest;
  suggest.surface = "none";
  suggest.count = 0;
  refused_alike([&] { suggest.validate(); }, {"suggest", "none", "--count", "0"});
  suggest.count = 1001;
  refused_alike([&] { suggest.validate(); }, {"suggest", "none", "--count", "1001"});
}

}  // namespace
