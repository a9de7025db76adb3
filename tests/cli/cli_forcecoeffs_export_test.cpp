// `hydrocoef export --format openfoam-forcecoeffs`: runs as OpenFOAM's
// forceCoeffs files, checked three ways on the quarter-domain sphere run of
// data/openfoam-sphere/forcecoeffs/M1-U0.1000, whose coefficient.dat
// OpenFOAM's own forceCoeffs wrote (writePrecision 10; Aref = pi R^2 / 4,
// lRef 0.3, magUInf 0.1, rhoInf 998.2, dragDir x, liftDir z, CofR 0):
// - against OpenFOAM: its forces imported (body axes -x, y, -z of the case's)
//   and exported with the same reference give Cd, Cs, Cl to the digits
//   OpenFOAM printed (one unit of the last, as its force.dat is itself
//   rounded to 11 digits), and the moment coefficients as closely as
//   cli_forcecoeffs_test.cpp finds them;
// - the round trip: with --mean-only, the file imported again (--rho as the
//   header comment says, the case's axes, the run's key) gives the stored
//   forces back, each to the last bit or (where no double coefficient gives
//   it back through F = C 1/2 rho U^2 A) the double next to it, as many of
//   each as the export counted; with the history, every row read as the
//   reader reads it is the solver's own force.dat/moment.dat row (the same
//   rule), and the file imported again over a window gives the case's own
//   means over that window (a one-sample window, the converged run's final
//   iterate, is refused by import's --window);
// - refusals (exit 2, one line naming the run and how to give what is
//   missing, nothing written) and hostile names (never in the files).
// Runs on SQLite and, as postgresql.*, on PostgreSQL (tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/coefficient_dat.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
const fs::path kCase = fs::path(HYDROCOEF_SOURCE_DIR) / "data/openfoam-sphere/forcecoeffs/M1-U0.1000";
const std::string kQuarterFrontal = "0.01767145867644259";

/// Column name -> value of the last data row of a coefficient.dat.
std::map<std::string, double> last_row(const fs::path& file) { return test::last_coefficient_row(file); }

std::size_t data_rows(const fs::path& file) {
  std::ifstream in(file);
  std::size_t rows = 0;
  for (std::string line; std::getline(in, line);) rows += !line.empty() && line[0] != '#';
  return rows;
}

class CliForceCoeffsExport : public ::testing::Test {
 protected:
  json run(const std::vector<std::string>& args) {
    const auto result = test::run_cli(args, dir_.path());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    const bool is_json = !result.out.empty() && (result.out[0] == '{' || result.out[0] == '[');
    return is_json ? json::parse(result.out) : json();
  }
  /// The sphere run imported as a user would, with the quarter sphere's reference.
  void import_sphere(const std::string& db = "hydrocoef.db") {
    run({"--db", db, "import", kCase.string(), "--body", "quarter-sphere", "--axes=-x,y,-z", "--quiet"});
    run({"--db", db, "body", "set", "quarter-sphere", "--length", "0.3", "--area",
         "quarter-frontal=" + kQuarterFrontal});
  }
  test::TempDir dir_;
};

TEST_F(CliForceCoeffsExport, GivesOpenFoamsOwnCoefficientsForTheSameRun) {
  import_sphere();
  const json result = run({"export", "--format", "openfoam-forcecoeffs", "-o", "out", "--precision", "10", "--json"});
  ASSERT_EQ(result["runs"].size(), 1u);
  const auto& r = result["runs"][0];
  EXPECT_EQ(r["axes"], "-x,y,-z");  // as the run was imported
  EXPECT_EQ(r["rows_from"], "history");
  EXPECT_EQ(r["rows"], 199);  // every iteration of force.dat
  EXPECT_EQ(r["magUInf"], 0.1);
  EXPECT_EQ(r["rho"], 998.2);
  const fs::path file = dir_ / "out/run-1/postProcessing/forceCoeffs/0/coefficient.dat";
  ASSERT_EQ(fs::path(r["file"].get<std::string>()), fs::path("out/run-1/postProcessing/forceCoeffs/0/coefficient.dat"));
  ASSERT_TRUE(fs::exists(file));
  EXPECT_EQ(data_rows(file), 199u);

  fs::path theirs_file;
  for (const auto& entry : fs::recursive_directory_iterator(kCase / "postProcessing" / "forceCoeffs"))
    if (entry.path().filename() == "coefficient.dat") theirs_file = entry.path();
  const auto theirs = last_row(theirs_file);
  const auto ours = last_row(file);
  ASSERT_EQ(ours.size(), 13u);
  EXPECT_EQ(ours.at("Time"), theirs.at("Time"));  // iteration 199, the run's final state
  // To OpenFOAM's printed digits (11 significant): within one unit of the last.
  const auto unit = [](double value) { return std::pow(10.0, std::floor(std::log10(std::abs(value))) - 10); };
  for (const char* name : {"Cd", "Cs", "Cl"})
    EXPECT_LE(std::abs(ours.at(name) - theirs.at(name)), unit(theirs.at(name)) * (1 + 1e-6))
        << name << ": " << ours.at(name) << " against OpenFOAM's " << theirs.at(name);
  // Moments are small differences of large terms (cli_forcecoeffs_test.cpp).
  for (const char* name : {"CmRoll", "CmPitch", "CmYaw"})
    EXPECT_LE(std::abs(ours.at(name) - theirs.at(name)), 1e-6 * std::abs(theirs.at(name)) + 1e-9) << name;
  // The front and rear parts as v1912 forms them.
  EXPECT_NEAR(ours.at("Cd(f)"), 0.5 * ours.at("Cd") + ours.at("CmRoll"), 1e-10);
  EXPECT_NEAR(ours.at("Cl(r)"), 0.5 * ours.at("Cl") - ours.at("CmPitch"), 1e-10);
  // The header: OpenFOAM's reference values, and the density in hydrocoef's comment.
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("# magUInf         : 1.0000000000e-01\n"), std::string::npos);
  EXPECT_NE(text.find("# Aref            : 1.7671458676e-02\n"), std::string::npos);
  EXPECT_NE(text.find("import with --rho 998.2"), std::string::npos);
}

/// Stored forces X..N of the database's one run, and its id.
std::pair<std::int64_t, std::array<double, 6>> stored_forces(const json& runs) {
  std::array<double, 6> out{};
  const char* names[] = {"X", "Y", "Z", "K", "M", "N"};
  for (std::size_t c = 0; c < 6; ++c) out[c] = runs[0]["forces"][names[c]]["total"].get<double>();
  return {runs[0]["id"].get<std::int64_t>(), out};
}

/// 0 when equal, 1 when neighbours, 2 otherwise.
int ulps_apart(double a, double b) {
  if (a == b) return 0;
  return std::nextafter(a, b) == b ? 1 : 2;
}

TEST_F(CliForceCoeffsExport, MeanOnlyImportedAgainGivesTheStoredForcesBack) {
  import_sphere();
  const json original = run({"runs", "--json"});
  ASSERT_EQ(original.size(), 1u);
  const auto [id, forces] = stored_forces(original);
  const json result = run({"export", "--format", "openfoam-forcecoeffs", "-o", "mean", "--mean-only", "--json"});
  ASSERT_EQ(result["runs"].size(), 1u);
  EXPECT_EQ(result["runs"][0]["rows_from"], "stored forces");
  // One row at the history's last iteration: the start-time folder is named after it.
  const std::string file = result["runs"][0]["file"];
  EXPECT_EQ(fs::path(file), fs::path("mean/run-1/postProcessing/forceCoeffs/199/coefficient.dat"));
  EXPECT_EQ(result["values"], 6);
  EXPECT_EQ(result["exact"].get<std::size_t>() + result["one_ulp"].get<std::size_t>(), 6u);
  // The file as a user imports it: the density its header states, the case's axes, the run's key.
  run({"--db", "again.db", "import", file, "--body", "quarter-sphere", "--rho", "998.2", "--axes=-x,y,-z", "--set",
       "u=" + original[0]["u"].dump(), "--quiet"});
  const json again = run({"--db", "again.db", "runs", "--json"});
  ASSERT_EQ(again.size(), 1u);
  EXPECT_EQ(again[0]["u"], original[0]["u"]);
  EXPECT_EQ(again[0]["reference_point"], original[0]["reference_point"]);
  EXPECT_EQ(again[0]["density"], 998.2);
  const auto [id2, back] = stored_forces(again);
  std::size_t exact = 0;
  for (std::size_t c = 0; c < 6; ++c) {
    const int apart = ulps_apart(back[c], forces[c]);
    EXPECT_LE(apart, 1) << "component " << c << ": " << back[c] << " for " << forces[c];
    exact += apart == 0;
  }
  EXPECT_EQ(exact, result["exact"].get<std::size_t>());
}

/// The rows of an OpenFOAM file, parentheses dropped: time, then the numbers.
std::vector<std::vector<double>> rows_of(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    for (char& c : line)
      if (c == '(' || c == ')') c = ' ';
    std::istringstream words(line);
    rows.emplace_back();
    for (double v; words >> v;) rows.back().push_back(v);
  }
  return rows;
}

TEST_F(CliForceCoeffsExport, HistoryRowsAreTheSolversOwnForces) {
  import_sphere();
  const json result = run({"export", "--format", "openfoam-forcecoeffs", "-o", "history", "--json"});
  const std::string file = result["runs"][0]["file"];
  const auto ours = rows_of(dir_ / file);
  const auto force = rows_of(kCase / "postProcessing/forces/0/force.dat");
  const auto moment = rows_of(kCase / "postProcessing/forces/0/moment.dat");
  ASSERT_EQ(ours.size(), 199u);
  ASSERT_EQ(force.size(), ours.size());
  ASSERT_EQ(moment.size(), ours.size());
  // What importers/openfoam_forces computes from the header's values: F = C * (q Aref), M = C * (q Aref lRef).
  const double q = 0.5 * 998.2 * 0.1 * 0.1;
  const double area = 0.01767145867644259;
  std::size_t exact = 0, next = 0;
  for (std::size_t i = 0; i < ours.size(); ++i) {
    ASSERT_EQ(ours[i].size(), 13u);
    EXPECT_EQ(ours[i][0], force[i][0]);
    for (std::size_t k = 0; k < 6; ++k) {
      const double solver = k < 3 ? force[i][1 + k] : moment[i][1 + k - 3];  // the totals, the case's axes
      const double read = ours[i][1 + k] * (k < 3 ? q * area : q * area * 0.3);
      const int apart = ulps_apart(read, solver);
      EXPECT_LE(apart, 1) << "row " << i << " component " << k << ": " << read << " for " << solver;
      ++(apart == 0 ? exact : next);
    }
  }
  EXPECT_EQ(exact, result["exact"].get<std::size_t>());
  EXPECT_EQ(next, result["one_ulp"].get<std::size_t>());
  // Imported again over a window, the history gives the case's own means over that window.
  run({"--db", "case.db", "import", kCase.string(), "--body", "quarter-sphere", "--axes=-x,y,-z", "--window", "100:199",
       "--quiet"});
  run({"--db", "again.db", "import", file, "--body", "quarter-sphere", "--rho", "998.2", "--axes=-x,y,-z", "--set",
       "u=0.1", "--window", "100:199", "--quiet"});
  const auto [id1, expected] = stored_forces(run({"--db", "case.db", "runs", "--json"}));
  const auto [id2, back] = stored_forces(run({"--db", "again.db", "runs", "--json"}));
  for (std::size_t c = 0; c < 6; ++c) EXPECT_NEAR(back[c], expected[c], 1e-14 * std::abs(expected[c])) << c;
}

TEST_F(CliForceCoeffsExport, RefusesWhatItWouldHaveToGuessAndWritesNothing) {
  const auto refused = [&](const std::vector<std::string>& args, const std::vector<std::string>& pieces) {
    const auto result = test::run_cli(args, dir_.path());
    EXPECT_EQ(result.exit_code, 2) << result.out << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    for (const auto& piece : pieces) EXPECT_NE(result.err.find(piece), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(dir_ / "out"));
  };
  std::ofstream(dir_ / "table.csv") << "u [m s^-1],X [N],Y [N],Z [N],K [N m],M [N m],N [N m]\n"
                                       "1.0,-10,0.5,0.25,0.01,0.02,0.03\n"
                                       "0.0,0,0,0,0,0,0\n";
  run({"import", "table.csv", "--body", "hull", "--quiet"});
  const std::vector<std::string> cmd = {"export", "--format", "openfoam-forcecoeffs", "-o", "out"};
  auto with = [&](std::vector<std::string> extra) {
    auto args = cmd;
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  refused(cmd, {"body 'hull' has no reference length", "body set", "--length"});
  run({"body", "set", "hull", "--length", "2"});
  refused(cmd, {"no reference area", "--area NAME=A"});
  run({"body", "set", "hull", "--area", "frontal=0.5"});
  refused(cmd, {"run 2 has no density", "--rho"});  // runs in key order: u = 0 first
  refused(with({"--area", "wetted"}), {"--area 'wetted'", "'frontal'"});
  refused(with({"--precision", "17"}), {"--precision 17"});
  refused(with({"--axes", "x,x,z"}), {"--axes"});
  refused({"export", "surf", "--format", "openfoam-forcecoeffs", "-o", "out"}, {"takes no NAME"});
  refused({"export", "surf", "--format", "csv", "-o", "out", "--mean-only"}, {"openfoam-forcecoeffs only"});
  run({"--db", "rho.db", "import", "table.csv", "--body", "hull", "--rho", "1025", "--quiet"});
  run({"--db", "rho.db", "body", "set", "hull", "--length", "2", "--area", "frontal=0.5"});
  refused({"--db", "rho.db", "export", "--format", "openfoam-forcecoeffs", "-o", "out"},
          {"run 2 is at rest", "--exclude-run 2"});
  // Without the run at rest it writes; the table's run has no history: one row, time 0.
  const json result = run(
      {"--db", "rho.db", "export", "--format", "openfoam-forcecoeffs", "-o", "out", "--exclude-run", "2", "--json"});
  ASSERT_EQ(result["runs"].size(), 1u);
  EXPECT_EQ(result["runs"][0]["rows_from"], "stored forces");
  EXPECT_EQ(result["runs"][0]["axes"], "x,y,z");
  const fs::path file = dir_ / "out/run-1/postProcessing/forceCoeffs/0/coefficient.dat";
  EXPECT_EQ(data_rows(file), 1u);
  // Body axes are the case's here: Cd = X / (1/2 rho U^2 A) = -10 / (0.5 * 1025 * 0.5).
  EXPECT_DOUBLE_EQ(last_row(file).at("Cd"), -10.0 / (0.5 * 1025.0 * 0.5));
  EXPECT_DOUBLE_EQ(last_row(file).at("CmYaw"), 0.03 / (0.5 * 1025.0 * 0.5 * 2.0));
  // With the body's moment point, the moments are about it and CofR is it: N_P = N_O + ((O - P) x F)_z.
  run({"--db", "rho.db", "body", "set", "hull", "--moment-point", "0.1,0,0"});
  run({"--db", "rho.db", "export", "--format", "openfoam-forcecoeffs", "-o", "out", "--exclude-run", "2"});
  EXPECT_DOUBLE_EQ(last_row(file).at("CmYaw"), (0.03 - 0.1 * 0.5) / (0.5 * 1025.0 * 0.5 * 2.0));
  EXPECT_DOUBLE_EQ(last_row(file).at("CmPitch"), (0.02 + 0.1 * 0.25) / (0.5 * 1025.0 * 0.5 * 2.0));
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find(": (1.0000000000000001e-01 0.0000000000000000e+00 0.0000000000000000e+00)\n# hydrocoef"),
            std::string::npos)
      << text;
}

TEST_F(CliForceCoeffsExport, NamesStayOutOfTheFiles) {
  // Printable (the name rule refuses control characters), yet header-like.
  const std::string hostile = "hull # magUInf : 99 */ \"' `$(x)` \u00fc";
  std::ofstream(dir_ / "table.csv") << "u [m s^-1],X [N],Y [N],Z [N],K [N m],M [N m],N [N m]\n"
                                       "1.5,-10,0.5,0.25,0.01,0.02,0.03\n";
  run({"import", "table.csv", "--body", hostile, "--rho", "998.2", "--quiet"});
  run({"body", "set", hostile, "--length", "2", "--area", "x: y=0.5"});
  const auto result = test::run_cli({"export", "--format", "openfoam-forcecoeffs", "-o", "out"}, dir_.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("body 'hull # magUInf"), std::string::npos) << result.out;  // printed, quoted
  const fs::path file = dir_ / "out/run-1/postProcessing/forceCoeffs/0/coefficient.dat";
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text.find("hull"), std::string::npos);
  EXPECT_EQ(text.find("magUInf : 99"), std::string::npos);
  EXPECT_EQ(text.find("x: y"), std::string::npos);
  // 17 significant digits: OpenFOAM's column width is the precision (16) plus 8.
  EXPECT_NE(text.find("# magUInf" + std::string(15, ' ') + ": 1.5000000000000000e+00\n"), std::string::npos) << text;
  EXPECT_DOUBLE_EQ(last_row(file).at("Cd"), -10.0 / (0.5 * 998.2 * 1.5 * 1.5 * 0.5));
}

}  // namespace
}  // namespace hydrocoef
