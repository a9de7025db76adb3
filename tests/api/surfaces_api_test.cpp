// The surface and export commands as public API calls
// (include/hydrocoef/surface.hpp, exports.hpp), driven as a library user
// drives them, on the same database as the hydrocoef CLI: the API's reports
// are the CLI's output byte for byte (text and --json), its numbers are the
// surface's, its files are the CLI's files; each options type refuses what
// the CLI refuses with the CLI's message; a read-only database refuses
// writes and stays byte-identical.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "hydrocoef/hydrocoef.hpp"
#include "tests/support/api_errors.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

using hydrocoef::test::cli_error;
using hydrocoef::test::error_of;

using hydrocoef::Database;
using hydrocoef::OpenMode;
using hydrocoef::test::run_cli;
using hydrocoef::test::TempDir;
using nlohmann::json;

const std::string kAsrV = std::string(HYDROCOEF_SOURCE_DIR) + "/examples/asr-v/";

std::string bytes_of(const std::filesystem::path& path) { return hydrocoef::test::read_text(path); }

/// A file's bytes; the VTK export names every array (VTK would otherwise name
/// the coordinates after their memory address), so two exports are equal byte for byte.
std::string comparable_bytes(const std::filesystem::path& path) {
  const std::string bytes = bytes_of(path);
  EXPECT_EQ(bytes.find("Array 0x"), std::string::npos) << path;
  // A MAT-file's 116-byte descriptive text ends with the second it was
  // written ("Created by: libmatio ... on Sat Nov 28 11:57:44 2026"): two
  // exports a second apart differ there alone. Everything after it is data.
  constexpr std::string_view kMatHeader = "MATLAB 5.0 MAT-file";
  constexpr std::size_t kMatText = 116;
  if (bytes.starts_with(kMatHeader) && bytes.size() > kMatText) return std::string(kMatHeader) + bytes.substr(kMatText);
  return bytes;
}

/// A 2-D force table on a 6 x 5 grid: X = -10 u|u| - 2 v, Y = u - 5 v|v|.
double grid_x(double u, double v) { return -10 * u * std::abs(u) - 2 * v; }
double grid_y(double u, double v) { return u - 5 * v * std::abs(v); }

std::string write_grid_table(const TempDir& dir) {
  const auto path = dir / "grid.csv";
  std::ofstream out(path);
  out << "u [m s^-1],v [m s^-1],X [N],Y [N]\n";
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 5; ++j) {
      const double u = 0.1 * i, v = 0.1 * (j - 2);
      out << u << "," << v << "," << grid_x(u, v) << "," << grid_y(u, v) << "\n";
    }
  return path.string();
}

hydrocoef::SurfaceBuildOptions gp_options(const std::string& name) {
  hydrocoef::SurfaceBuildOptions options;
  options.name = name;
  options.body = "asr-v";
  options.axes = {"u"};
  options.outputs = {"X"};
  options.method = "gp";
  options.gp_starts = 2;
  options.extrapolate = {"clamp"};
  return options;
}

class SurfacesApi : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = (dir_ / "api.db").string();
    auto db = Database::open(path_, OpenMode::Create);
    hydrocoef::ImportOptions surge;
    surge.body = "asr-v";
    surge.settings = {{"sign", "opposing"}, {"rho", "998.2"}, {"nu", "1.004e-6"}};
    db.import_files({kAsrV + "asr-v-surge-damping.csv"}, surge);
    hydrocoef::ImportOptions yaw = surge;
    yaw.settings["sign"] = "on-body";
    db.import_files({kAsrV + "asr-v-yaw-damping.csv"}, yaw);
    hydrocoef::ImportOptions grid;
    grid.body = "grid";
    db.import_files({write_grid_table(dir_)}, grid);
    hydrocoef::FitOptions x;
    x.body = "asr-v";
    x.output = "X";
    x.terms = "u,u|u|";
    db.fit(x);
    hydrocoef::FitOptions n = x;
    n.output = "N";
    n.terms = "r,r|r|";
    db.fit(n);
    db.close();
    for (const auto& args :
         std::vector<std::vector<std::string>>{{"surface", "build", "grid-pchip", "--body", "grid", "--outputs", "X,Y",
                                                "--axes", "u,v", "--method", "pchip"},
                                               {"surface", "build", "grid-linear", "--body", "grid", "--outputs", "X,Y",
                                                "--axes", "u,v", "--method", "linear", "--extrapolate", "clamp"},
                                               {"surface", "build", "gp", "--body", "asr-v", "--outputs", "X", "--axes",
                                                "u", "--method", "gp", "--starts", "2", "--extrapolate", "clamp"}}) {
      const auto result = cli(args);
      ASSERT_EQ(result.exit_code, 0) << result.err;
    }
  }

  hydrocoef::test::CliResult cli(std::vector<std::string> args, const std::filesystem::path& cwd = {}) {
    args.insert(args.begin(), {"--db", path_});
    return run_cli(args, cwd.empty() ? dir_.path() : cwd);
  }

  TempDir dir_;
  std::string path_;
};

TEST_F(SurfacesApi, ShowAndListAreTheCliOutputByteForByte) {
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  for (const std::string name : {"grid-pchip", "gp"}) {
    const auto report = hydrocoef::surface_show(db, name);
    EXPECT_EQ(report.text(), cli({"surface", "show", name}).out) << name;
    EXPECT_EQ(report.json(), cli({"surface", "show", name, "--json"}).out) << name;
  }
  const auto list = hydrocoef::surface_list(db);
  EXPECT_EQ(list.text(), cli({"surface", "list"}).out);
  EXPECT_EQ(list.json(), cli({"surface", "list", "--json"}).out);
  ASSERT_EQ(list.surfaces.size(), 3u);
  EXPECT_EQ(hydrocoef::surface_list(db, "grid").surfaces.size(), 2u);

  // The report's fields are the JSON's numbers.
  const auto shown = json::parse(cli({"surface", "show", "grid-pchip", "--json"}).out);
  const auto report = hydrocoef::surface_show(db, "grid-pchip");
  EXPECT_EQ(report.kind, "grid");
  EXPECT_EQ(report.method, "pchip");
  EXPECT_EQ(report.runs, shown["runs"].get<std::vector<std::int64_t>>());
  ASSERT_EQ(report.axes.size(), 2u);
  for (std::size_t a = 0; a < 2; ++a) {
    EXPECT_EQ(report.axes[a].name, shown["axes"][a]["name"]);
    EXPECT_EQ(report.axes[a].breakpoints, shown["axes"][a]["breakpoint_values"].get<std::vector<double>>());
  }
  ASSERT_EQ(report.outputs.size(), 2u);
  EXPECT_EQ(report.outputs[0].loo_max, shown["quality"]["outputs"]["X"]["loo_max"].get<double>());
  EXPECT_EQ(report.outputs[0].loo_rms, shown["quality"]["outputs"]["X"]["loo_rms"].get<double>());

  // The GP's largest standard deviations: show's, and the Surface's own search.
  const auto gp = json::parse(cli({"surface", "show", "gp", "--json"}).out);
  const auto peaks = db.surface("gp").largest_standard_deviations();
  ASSERT_EQ(peaks.size(), 1u);
  const auto& listed = gp["gp"]["outputs"]["X"]["largest_sd"];
  ASSERT_EQ(peaks[0].size(), listed.size());
  ASSERT_EQ(listed.size(), 3u);
  for (std::size_t i = 0; i < listed.size(); ++i) {
    EXPECT_EQ(peaks[0][i].standard_deviation, listed[i]["sd"].get<double>());
    EXPECT_EQ(peaks[0][i].point[0], listed[i]["point"]["u"].get<double>());
  }
  EXPECT_EQ(hydrocoef::surface_show(db, "gp").outputs[0].largest_sd[0].standard_deviation, listed[0]["sd"]);
}

TEST_F(SurfacesApi, BuildAndRebuildAreTheCliOnes) {
  auto db = Database::open(path_, OpenMode::ReadWrite);
  hydrocoef::SurfaceBuildOptions options;
  options.name = "api-linear";
  options.body = "grid";
  options.axes = {"u", "v"};
  options.outputs = {"X", "Y"};
  options.method = "linear";
  const auto built = hydrocoef::surface_build(db, options);
  const auto by_cli = cli({"surface", "build", "cli-linear", "--body", "grid", "--outputs", "X,Y", "--axes", "u,v",
                           "--method", "linear", "--json"});
  ASSERT_EQ(by_cli.exit_code, 0) << by_cli.err;
  auto api_json = json::parse(built.json()), cli_json = json::parse(by_cli.out);
  EXPECT_EQ(api_json["name"], "api-linear");
  EXPECT_EQ(api_json["id"], built.id);
  for (auto* document : {&api_json, &cli_json})
    for (const char* key : {"name", "created_at", "id"}) document->erase(key);
  EXPECT_EQ(api_json, cli_json);
  EXPECT_EQ(built.runs_measured, 30u);
  EXPECT_EQ(built.surface.axes[0].breakpoints, (std::vector<double>{0, 0.1, 0.2, 0.3, 0.4, 0.5}));
  // The text is the CLI's (the database's path in its last line).
  EXPECT_NE(built.text().find("surface api-linear of body grid: grid, linear, 30 runs\n"), std::string::npos);
  EXPECT_NE(built.text().find("  stored as surface " + std::to_string(built.id) + " in " + path_ + "\n"),
            std::string::npos)
      << built.text();

  // A GP with every GP option, built by both.
  const auto gp = hydrocoef::surface_build(db, gp_options("api-gp"));
  auto gp_api = json::parse(gp.json());
  auto gp_cli = json::parse(cli({"surface", "show", "gp", "--json"}).out);
  EXPECT_EQ(gp_api["gp"], gp_cli["gp"]);
  EXPECT_EQ(gp_api["build_spec"], gp_cli["build_spec"]);
  EXPECT_EQ(gp_api["quality"], gp_cli["quality"]);

  // A rebuild of one surface: the CLI's JSON, but for the time and id.
  const auto rebuilt = hydrocoef::surface_rebuild(db, {"api-linear", "", false});
  ASSERT_EQ(rebuilt.rebuilt.size(), 1u);
  auto again = json::parse(rebuilt.json());
  ASSERT_TRUE(again.is_array());
  ASSERT_EQ(again.size(), 1u);
  for (const char* key : {"name", "created_at", "id"}) again[0].erase(key);
  EXPECT_EQ(again[0], cli_json);
  db.close();
  const auto stale = cli({"surface", "rebuild", "--stale", "--json"});
  EXPECT_EQ(stale.out, "[]\n");
  db = Database::open(path_, OpenMode::ReadWrite);
  const auto none = hydrocoef::surface_rebuild(db, {"", "", true});
  EXPECT_EQ(none.text(), cli({"surface", "rebuild", "--stale"}).out);
  EXPECT_EQ(none.text(), "no surface to rebuild\n");
}

TEST_F(SurfacesApi, QueryIsTheCliQueryWithDeviationsAndGradients) {
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  hydrocoef::SurfaceQueryOptions options;
  options.name = "gp";
  options.point = {{"u", 0.37}};
  options.uncertainty = true;
  options.gradient = true;
  const auto result = hydrocoef::query_surface(db, options);
  const auto args = std::vector<std::string>{"query", "gp", "u=0.37", "--uncertainty", "--gradient"};
  EXPECT_EQ(result.text(), cli(args).out);
  auto json_args = args;
  json_args.push_back("--json");
  const auto printed = cli(json_args);
  EXPECT_EQ(result.json(), printed.out);
  const auto answer = json::parse(printed.out);
  ASSERT_EQ(result.values.size(), 1u);
  EXPECT_EQ(result.values[0], answer["values"]["X"].get<double>());
  EXPECT_EQ(result.standard_deviation[0], answer["standard_deviation"]["X"].get<double>());
  EXPECT_EQ(result.new_run_standard_deviation[0], answer["new_run_standard_deviation"]["X"].get<double>());
  EXPECT_EQ(result.gradient[0], answer["gradient"]["X"]["u"].get<double>());
  EXPECT_GT(result.standard_deviation[0], 0.0);
  // The Surface's own evaluation gives the same numbers.
  const auto direct = db.surface("gp").evaluate_with_standard_deviation({0.37});
  EXPECT_EQ(direct.values[0], result.values[0]);
  EXPECT_EQ(direct.standard_deviation[0], result.standard_deviation[0]);

  // A grid's gradient, and a batch written to a file (the CLI's summary and file).
  options.name = "grid-pchip";
  options.point = {{"v", 0.05}, {"u", 0.25}};
  options.uncertainty = false;
  EXPECT_EQ(hydrocoef::query_surface(db, options).json(),
            cli({"query", "grid-pchip", "v=0.05", "u=0.25", "--gradient", "--json"}).out);
  std::ofstream(dir_ / "points.csv") << "u,v\n0.1,0.0\n0.35,-0.15\n";
  options.point.clear();
  options.input = (dir_ / "points.csv").string();
  options.output = (dir_ / "api-out.csv").string();
  const auto batch = hydrocoef::query_surface(db, options);
  EXPECT_EQ(batch.points, 2u);
  EXPECT_EQ(batch.note(), "2 points of surface 'grid-pchip' written to " + options.output);
  const auto cli_batch = cli({"query", "grid-pchip", "--input", "points.csv", "--output", "cli-out.csv", "--gradient"});
  EXPECT_EQ(cli_batch.err, "hydrocoef: 2 points of surface 'grid-pchip' written to cli-out.csv\n");
  EXPECT_EQ(bytes_of(dir_ / "api-out.csv"), bytes_of(dir_ / "cli-out.csv"));
}

TEST_F(SurfacesApi, GriddedSurfacesGiveTheirTableAndAnySurfaceTabulates) {
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  const auto grid = db.surface("grid-pchip");
  ASSERT_TRUE(grid.gridded());
  const auto table = grid.table();
  const auto shown = json::parse(cli({"surface", "show", "grid-pchip", "--json"}).out);
  ASSERT_EQ(table.breakpoints.size(), 2u);
  for (std::size_t a = 0; a < 2; ++a)
    EXPECT_EQ(table.breakpoints[a], shown["axes"][a]["breakpoint_values"].get<std::vector<double>>());
  ASSERT_EQ(table.node_count(), 30u);
  // Node (i, j) at flat index i + 6 j holds the runs' forces (first axis fastest).
  for (std::size_t j = 0; j < 5; ++j)
    for (std::size_t i = 0; i < 6; ++i) {
      const double u = table.breakpoints[0][i], v = table.breakpoints[1][j];
      EXPECT_NEAR(table.values[0][i + 6 * j], grid_x(u, v), 1e-12);
      EXPECT_NEAR(table.values[1][i + 6 * j], grid_y(u, v), 1e-12);
    }
  // The node standard deviations are what query --uncertainty says there.
  if (grid.has_standard_deviation()) {
    ASSERT_EQ(table.standard_deviation.size(), 2u);
    const auto at = json::parse(cli({"query", "grid-pchip", "u=0.3", "v=0.1", "--uncertainty", "--json"}).out);
    EXPECT_EQ(table.standard_deviation[1][3 + 6 * 3], at["standard_deviation"]["Y"].get<double>());
  }

  // A GP is not gridded; tabulated, it is the CLI's query at every node, with sigma.
  const auto gp = db.surface("gp");
  EXPECT_FALSE(gp.gridded());
  EXPECT_NE(error_of([&] { (void)gp.table(); }).find("is not gridded"), std::string::npos);
  const auto tabulated = gp.tabulate({{0.0, 0.25, 0.5, 1.0}});
  ASSERT_EQ(tabulated.values.size(), 1u);
  ASSERT_EQ(tabulated.standard_deviation.size(), 1u);
  for (std::size_t i = 0; i < 4; ++i) {
    const double x = tabulated.breakpoints[0][i];
    std::ostringstream point;
    point.precision(17);
    point << "u=" << x;
    const auto at = json::parse(cli({"query", "gp", point.str(), "--uncertainty", "--json"}).out);
    EXPECT_EQ(tabulated.values[0][i], at["values"]["X"].get<double>()) << x;
    EXPECT_EQ(tabulated.standard_deviation[0][i], at["standard_deviation"]["X"].get<double>()) << x;
  }
  EXPECT_EQ(error_of([&] {
              (void)gp.tabulate({{0.2, 0.1}});
            }),
            "tabulate: axis 'u': breakpoint 0.1 after 0.2; expected strictly increasing breakpoints");
  EXPECT_NE(error_of([&] { (void)gp.tabulate({{0.1}, {0.2}}); }).find("expected one per axis"), std::string::npos);
}

TEST_F(SurfacesApi, ExportFilesAreTheCliFilesByteForByte) {
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  std::filesystem::create_directories(dir_ / "cli");
  std::filesystem::create_directories(dir_ / "api");
  for (const std::string format : {"csv", "csv-wide", "json", "c", "mat", "jsbsim", "vtk", "daveml"}) {
    const std::string file = "table-" + format + ".out";
    const auto printed = cli({"export", "grid-linear", "--format", format, "-o", file, "--json"}, dir_ / "cli");
    ASSERT_EQ(printed.exit_code, 0) << printed.err;
    hydrocoef::TableExportOptions options;
    options.name = "grid-linear";
    options.format = format;
    options.output = (dir_ / "api" / file).string();
    const auto result = hydrocoef::export_surface(db, options);
    auto cli_json = json::parse(printed.out), api_json = json::parse(result.json());
    ASSERT_EQ(cli_json["files"].size(), result.files.size()) << format;
    for (std::size_t i = 0; i < result.files.size(); ++i) {
      const auto name = std::filesystem::path(result.files[i]).filename();
      EXPECT_EQ(comparable_bytes(dir_ / "api" / name), comparable_bytes(dir_ / "cli" / name)) << format << " " << name;
      EXPECT_FALSE(bytes_of(dir_ / "api" / name).empty()) << name;
    }
    cli_json.erase("files");
    api_json.erase("files");
    EXPECT_EQ(api_json, cli_json) << format;
    EXPECT_EQ(result.nodes, 30u);
  }
  // The text: the CLI's, with the file's name as given.
  hydrocoef::TableExportOptions options{"grid-pchip", "csv", "table.csv", false, ""};
  const auto cli_text = cli({"export", "grid-pchip", "--format", "csv", "-o", "table.csv"}, dir_ / "cli");
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir_ / "api");
  const auto text = hydrocoef::export_surface(db, options).text();
  std::filesystem::current_path(cwd);
  EXPECT_EQ(text, cli_text.out);
  EXPECT_EQ(bytes_of(dir_ / "api" / "table.csv"), bytes_of(dir_ / "cli" / "table.csv"));
  // What a format cannot express is refused as the CLI refuses it, nothing written.
  options = {"grid-pchip", "mat", (dir_ / "api" / "pchip.mat").string(), false, ""};
  EXPECT_EQ(error_of([&] { hydrocoef::export_surface(db, options); }),
            cli_error(cli({"export", "grid-pchip", "--format", "mat", "-o", "pchip.mat"})));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "api" / "pchip.mat"));
  // A GP is not a table: the CLI's refusal, naming --resample.
  options.name = "gp";
  EXPECT_EQ(error_of([&] { hydrocoef::export_surface(db, options); }),
            cli_error(cli({"export", "gp", "--format", "csv", "-o", "gp.csv"})));
}

TEST_F(SurfacesApi, GazeboExportIsTheCliOne) {
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  std::filesystem::create_directories(dir_ / "cli");
  for (const std::string flavor : {"gz", "uuv"}) {
    const auto printed = cli({"export-gazebo", "asr-v", "--flavor", flavor, "-o", "model.sdf", "--allow-missing",
                              "--sphere-radius", "0.15", "--rho", "998.2", "--json"},
                             dir_ / "cli");
    ASSERT_EQ(printed.exit_code, 0) << printed.err;
    hydrocoef::GazeboExportOptions options;
    options.body = "asr-v";
    options.flavor = flavor;
    options.output = (dir_ / ("api-" + flavor + ".sdf")).string();
    options.allow_missing = true;
    options.sphere_radius = 0.15;
    options.rho = 998.2;
    const auto result = hydrocoef::export_gazebo(db, options);
    EXPECT_EQ(bytes_of(options.output), bytes_of(dir_ / "cli" / "model.sdf")) << flavor;
    auto cli_json = json::parse(printed.out), api_json = json::parse(result.json());
    EXPECT_EQ(api_json["file"], options.output);
    cli_json.erase("file");
    api_json.erase("file");
    EXPECT_EQ(api_json, cli_json) << flavor;
    ASSERT_EQ(result.fits.size(), 2u);
    EXPECT_EQ(result.fits[0].dof, "X");
    EXPECT_EQ(result.fits[0].quadratic, cli_json["fits"][0]["quadratic"].get<double>());
    EXPECT_LT(result.fits[0].quadratic, 0.0);  // on-body damping (the table is "opposing")
    EXPECT_EQ(result.linear_b[0], cli_json["linear_b"][0].get<double>());
    EXPECT_EQ(result.added_mass_b[0], 2.0 / 3.0 * 3.141592653589793 * 998.2 * 0.15 * 0.15 * 0.15);
  }
}

TEST_F(SurfacesApi, OptionsAreRefusedWithTheCliMessages) {
  const auto base =
      std::vector<std::string>{"surface", "build", "x", "--body", "grid", "--outputs", "X", "--axes", "u,v"};
  const auto with = [&](std::vector<std::string> more) {
    auto args = base;
    args.insert(args.end(), more.begin(), more.end());
    return cli_error(cli(args));
  };
  hydrocoef::SurfaceBuildOptions options;
  options.name = "x";
  options.body = "grid";
  options.axes = {"u", "v"};
  options.outputs = {"X"};
  auto bad = options;
  bad.rbf_degree = bad.gp_degree = 3;
  EXPECT_EQ(error_of([&] { bad.validate(); }), with({"--degree", "3"}));
  EXPECT_EQ(error_of([&] { bad.validate(); }), "--degree 3: expected 0, 1 or 2");
  bad = options;
  bad.method = "gp";
  bad.gp_starts = 0;
  EXPECT_EQ(error_of([&] { bad.validate(); }), with({"--method", "gp", "--starts", "0"}));
  bad = options;
  bad.resample = {{0, 1}, {0, 1}};
  EXPECT_EQ(error_of([&] { bad.validate(); }), with({"--resample", "u=0:1:5", "--resample", "v=0:1:3"}));
  bad = options;
  bad.method = "cubic";
  EXPECT_EQ(error_of([&] { bad.validate(); }), with({"--method", "cubic"}));
  bad = options;
  bad.method = "gp";
  bad.gp_kernel = "cubic";
  EXPECT_EQ(error_of([&] { bad.validate(); }), with({"--method", "gp", "--kernel", "cubic"}));
  bad = options;
  bad.extrapolate = {"w=clamp"};
  EXPECT_EQ(error_of([&] { bad.validate(); }), with({"--extrapolate", "w=clamp"}));

  hydrocoef::TableExportOptions table{"grid-pchip", "csv", "t.csv", true, ""};
  EXPECT_EQ(error_of([&] { table.validate(); }),
            cli_error(cli({"export", "grid-pchip", "--format", "csv", "-o", "t.csv", "--float"})));
  table = {"grid-pchip", "xls", "t.xls", false, ""};
  EXPECT_EQ(error_of([&] { table.validate(); }),
            cli_error(cli({"export", "grid-pchip", "--format", "xls", "-o", "t.xls"})));

  hydrocoef::SurfaceQueryOptions query;
  query.name = "gp";
  EXPECT_EQ(error_of([&] { query.validate(); }), cli_error(cli({"query", "gp"})));
  query.point = {{"u", 0.1}};
  query.input = "points.csv";
  EXPECT_EQ(error_of([&] { query.validate(); }), cli_error(cli({"query", "gp", "u=0.1", "--input", "points.csv"})));

  hydrocoef::GazeboExportOptions gazebo;
  gazebo.body = "asr-v";
  gazebo.flavor = "gz";
  gazebo.output = "m.sdf";
  EXPECT_EQ(error_of([&] { gazebo.validate(); }),
            cli_error(cli({"export-gazebo", "asr-v", "--flavor", "gz", "-o", "m.sdf"})));
  gazebo.added_mass = "1,2,3";
  EXPECT_EQ(error_of([&] { gazebo.validate(); }),
            cli_error(cli({"export-gazebo", "asr-v", "--flavor", "gz", "-o", "m.sdf", "--added-mass", "1,2,3"})));
  gazebo.flavor = "uuv";
  gazebo.link = "hull";
  EXPECT_EQ(error_of([&] { gazebo.validate(); }), cli_error(cli({"export-gazebo", "asr-v", "--flavor", "uuv", "-o",
                                                                 "m.sdf", "--added-mass", "1,2,3", "--link", "hull"})));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "m.sdf"));

  // Each operation validates its options first.
  auto db = Database::open(path_, OpenMode::ReadWrite);
  bad = options;
  bad.rbf_degree = 5;
  EXPECT_EQ(error_of([&] { hydrocoef::surface_build(db, bad); }), "--degree 5: expected 0, 1 or 2");
  bad.gp_degree = 5;
  bad.rbf_degree = 1;
  bad.method = "gp";
  EXPECT_EQ(error_of([&] { db.build_surface(bad); }), "--degree 5: expected 0, 1 or 2");
}

TEST_F(SurfacesApi, AReadOnlyDatabaseRefusesBuildsAndStaysAsItWas) {
  const std::string before = bytes_of(path_);
  {
    auto db = Database::open(path_, OpenMode::ReadOnly);
    hydrocoef::SurfaceBuildOptions options = gp_options("more");
    EXPECT_NE(error_of([&] { hydrocoef::surface_build(db, options); }).find("read-only"), std::string::npos);
    EXPECT_NE(error_of([&] { hydrocoef::surface_rebuild(db, {}); }).find("read-only"), std::string::npos);
    EXPECT_NE(error_of([&] { db.rebuild_surfaces(); }).find("read-only"), std::string::npos);
    // Reads and exports work.
    EXPECT_EQ(hydrocoef::surface_list(db).surfaces.size(), 3u);
  }
  EXPECT_EQ(bytes_of(path_), before);
}

}  // namespace
