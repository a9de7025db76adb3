// hydrocoef derivatives export from the command line. Runs generated from
// known surge, sway and yaw models over (u, v, r, delta) are imported and
// fitted; then
// - the prime CSV read back equals `derivatives show --form prime --json`
//   (coefficients, standard errors and covariance, to the last bit), and the
//   dimensional JSON's terms, coefficients and covariance are the stored
//   model's;
// - the gz-sim file and the MATLAB function the CLI writes equal, byte for
//   byte, what the library's exporters (derivative_gazebo, derivative_matlab)
//   write for the same sets made from `derivatives show --json`;
// - each refusal (format, form, several models for csv, a term gz-sim cannot
//   hold, models of two bodies or of one output twice, no mass matrix, a
//   path that is not NAME.m, a missing reference value, an unknown model) is
//   one line, exit 2, no file written, the database unchanged;
// - a hostile body and model name is data in every format: a JSON string,
//   inside CSV comments and XML and MATLAB comments only.
#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>

#include "src/core/matrix6.hpp"
#include "src/core/text.hpp"
#include "src/export/derivative_export.hpp"
#include "src/export/derivative_gazebo_export.hpp"
#include "src/export/derivative_matlab_export.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::read_bytes;
using test::run_cli;
using test::TempDir;

// Printable, so a valid name; every character a format could take for its own.
const std::string kHostile = "h'\"%{ <!-- x --> ]]> */ \\ $(rm) ,;&amp; q";

void write_runs(const std::filesystem::path& path) {
  std::ofstream out(path);
  out << std::setprecision(17) << "u [m s^-1],v [m s^-1],r [rad s^-1],delta [rad],X [N],Y [N],N [N m]\n";
  int i = 0;
  for (const double u : {0.5, 1.0, 1.5, 2.0})
    for (const double v : {-0.3, -0.1, 0.0, 0.1, 0.3})
      for (const double r : {-0.1, -0.04, 0.0, 0.05, 0.1})
        for (const double delta : {-0.2, 0.0, 0.2}) {
          const double e = 0.01 * std::sin(1.3 * ++i);  // deterministic scatter: a covariance of full rank
          out << u << "," << v << "," << r << "," << delta << "," << -5 * u - 20 * u * std::abs(u) + 3 * v * r + e
              << "," << -120 * v + 35 * r - 480 * v * std::abs(v) - 60 * u * v - 25 * u * u * delta + 2 * e << ","
              << -40 * v - 90 * r - 300 * r * std::abs(r) - 10 * u * r + 0.5 * e << "\n";
        }
}

class CliDerivativesExport : public ::testing::Test {
 protected:
  void SetUp() override {
    write_runs(dir_ / "captive.csv");
    for (const std::string body : {"ship", "other"}) {
      std::vector<std::string> args{"import",        "captive.csv", "--body", body,
                                    "--disturbance", "delta",       "--sign", "on-body"};
      if (body == "other") args.insert(args.end(), {"--also", "other"});  // the same file read again
      const auto imported = run_cli(args, dir_.path());
      ASSERT_EQ(imported.exit_code, 0) << imported.err;
    }
    fit("ship", "X", "u, u*|u|, v*r", "surge");
    fit("ship", "Y", "v, r, v*|v|, u*v", "sway");
    fit("ship", "N", "v, r, r*|r|, u*r", "yaw");
    fit("ship", "Y", "v, r, v*|v|, u*v, u^2*delta", "sway-rudder");
    fit("other", "N", "v, r", "other-yaw");
  }
  void fit(const std::string& body, const std::string& output, const std::string& terms, const std::string& name) {
    const auto fitted = run_cli(
        {"derivatives", "fit", "--body", body, "--output", output, "--terms", terms, "--name", name}, dir_.path());
    ASSERT_EQ(fitted.exit_code, 0) << fitted.err;
  }
  test::CliResult cli(std::vector<std::string> args) { return run_cli(args, dir_.path()); }
  nlohmann::json show(const std::string& name, std::vector<std::string> extra = {}) {
    std::vector<std::string> args{"derivatives", "show", name, "--json"};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto shown = cli(args);
    EXPECT_EQ(shown.exit_code, 0) << shown.err;
    return nlohmann::json::parse(shown.out);
  }
  /// The set the export makes of a stored model, built here from `show --json`.
  DerivativeSet set_of(const std::string& name) {
    const auto model = show(name);
    DerivativeSet set;
    set.name = model.at("name");
    set.output = model.at("output");
    set.terms = parse_terms(model.at("terms").get<std::string>());
    for (const auto& c : model.at("coefficients")) set.coefficients.push_back(c.at("value"));
    for (const auto& x : model.at("covariance")) set.covariance.push_back(x);
    return set;
  }
  TempDir dir_;
};

double number(std::string_view text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  EXPECT_TRUE(ec == std::errc() && end == text.data() + text.size()) << text;
  return value;
}

TEST_F(CliDerivativesExport, APrimeCsvReadBackIsWhatShowPrints) {
  const std::vector<std::string> reference{"--length", "3", "--speed", "1.5", "--density", "1025"};
  std::vector<std::string> args{"derivatives", "export", "sway", "--format", "csv",
                                "--form",      "prime",  "-o",   "sway.csv"};
  args.insert(args.end(), reference.begin(), reference.end());
  const auto written = cli(args);
  ASSERT_EQ(written.exit_code, 0) << written.err;
  EXPECT_NE(written.out.find("wrote sway.csv (csv, prime"), std::string::npos) << written.out;
  const auto shown = show("sway", {"--form", "prime", "--length", "3", "--speed", "1.5", "--density", "1025"});

  const std::string csv = read_bytes(dir_ / "sway.csv");
  std::vector<std::vector<std::string_view>> rows;
  for (const std::string_view line : split(csv, '\n'))
    if (!line.empty() && line.front() != '#') rows.push_back(split(line, ','));
  const std::size_t m = shown.at("coefficients").size();
  ASSERT_EQ(m, 4u);
  ASSERT_EQ(rows.size(), m + 1);
  EXPECT_EQ(rows[0][2], "coefficient");
  EXPECT_EQ(rows[0][3], "std_error");
  EXPECT_EQ(rows[0][4], "scale");
  ASSERT_EQ(rows[0].size(), 5 + m);
  for (std::size_t k = 0; k < m; ++k) {
    const auto& row = rows[k + 1];
    const auto& c = shown.at("coefficients")[k];
    EXPECT_EQ(row[0], "Y");
    EXPECT_EQ(row[1], c.at("term").get<std::string>());
    EXPECT_EQ(number(row[2]), c.at("value").get<double>()) << k;
    EXPECT_EQ(number(row[3]), c.at("std_error").get<double>()) << k;
    for (std::size_t j = 0; j < m; ++j)
      EXPECT_EQ(number(row[5 + j]), shown.at("covariance")[k * m + j].get<double>()) << k << "," << j;
  }
  // The value is truly non-dimensional: Y_v' = Y_v / (1/2 rho U L^2).
  EXPECT_NEAR(number(rows[1][2]), show("sway").at("coefficients")[0].at("value").get<double>() / (0.5 * 1025 * 1.5 * 9),
              1e-15);

  // The dimensional JSON: the stored model's numbers, the object a vehicle's "derivatives" takes.
  ASSERT_EQ(cli({"derivatives", "export", "sway", "--format", "json", "-o", "sway.json"}).exit_code, 0);
  const auto doc = nlohmann::json::parse(read_bytes(dir_ / "sway.json"));
  const auto stored = show("sway");
  EXPECT_EQ(doc.at("form"), "dimensional");
  EXPECT_EQ(doc.at("terms"), stored.at("terms"));
  for (std::size_t k = 0; k < m; ++k)
    EXPECT_EQ(doc.at("coefficients")[k].get<double>(), stored.at("coefficients")[k].at("value").get<double>());
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j < m; ++j)
      EXPECT_EQ(doc.at("covariance")[i][j].get<double>(), stored.at("covariance")[i * m + j].get<double>());
}

TEST_F(CliDerivativesExport, GzSimAndMatlabFilesAreTheLibrarysForTheSameSets) {
  const auto gz = cli({"derivatives", "export", "surge", "sway", "yaw", "--format", "gazebo", "-o", "ship.sdf",
                       "--added-mass", "1,2,3,0.4,0.5,0.6", "--link", "hull", "--json"});
  ASSERT_EQ(gz.exit_code, 0) << gz.err;
  const auto report = nlohmann::json::parse(gz.out);
  EXPECT_EQ(report.at("body"), "ship");
  EXPECT_EQ(report.at("models").size(), 3u);
  DerivativeGazeboOptions options;
  options.link_name = "hull";
  Matrix6 ma = Matrix6::Zero();
  const double diagonal[6] = {1, 2, 3, 0.4, 0.5, 0.6};
  for (int i = 0; i < 6; ++i) ma(i, i) = diagonal[i];
  options.added_mass = ma;
  const DerivativeGazeboExport expected = derivative_gazebo({set_of("surge"), set_of("sway"), set_of("yaw")}, options);
  EXPECT_EQ(read_bytes(dir_ / "ship.sdf"), expected.text);
  EXPECT_NE(expected.text.find("<yVabsV>"), std::string::npos);  // v*|v| in Y
  EXPECT_NE(expected.text.find("<yUV>"), std::string::npos);     // u*v in Y: a cross term
  EXPECT_NE(expected.text.find("<nUR>"), std::string::npos);     // u*r in N

  const auto m = cli({"derivatives", "export", "surge", "sway-rudder", "yaw", "--format", "matlab", "-o", "ship.m",
                      "--mass-diagonal", "60,80,80,3,9,9"});
  ASSERT_EQ(m.exit_code, 0) << m.err;
  EXPECT_NE(m.out.find("function [xdot, U] = ship(x, ui)"), std::string::npos) << m.out;
  EXPECT_NE(m.out.find("ui = [delta]'"), std::string::npos) << m.out;
  Matrix6 mass = Matrix6::Zero();
  const double masses[6] = {60, 80, 80, 3, 9, 9};
  for (int i = 0; i < 6; ++i) mass(i, i) = masses[i];
  EXPECT_EQ(read_bytes(dir_ / "ship.m"),
            derivative_matlab("ship", {set_of("surge"), set_of("sway-rudder"), set_of("yaw")}, mass));
}

TEST_F(CliDerivativesExport, RefusalsAreOneLineExitTwoNothingWritten) {
  const std::string before = read_bytes(dir_ / "hydrocoef.db");
  const auto refused = [&](std::vector<std::string> args, const std::string& expected) {
    args.insert(args.begin(), {"derivatives", "export"});
    const auto result = cli(args);
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_EQ(result.out, "");
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "out.x"));
  };
  refused({"sway", "--format", "xml", "-o", "out.x"}, "--format 'xml': expected csv, json, gazebo or matlab");
  refused({"sway", "yaw", "--format", "csv", "-o", "out.x"}, "--format csv writes one model a file, found 2");
  refused({"sway", "--format", "gazebo", "--form", "prime", "-o", "out.x"},
          "--format gazebo writes dimensional (SI) coefficients only");
  refused({"sway", "--format", "csv", "--form", "prime", "--length", "3", "-o", "out.x"},
          "derivatives export --form prime: the prime system needs reference values that are not given; give --speed "
          "and --density");
  refused({"sway", "--format", "csv", "--form", "bulk", "-o", "out.x"}, "--form 'bulk'");
  refused({"nosuch", "--format", "csv", "-o", "out.x"}, "no derivative model 'nosuch'; expected one of:");
  refused({"sway-rudder", "--format", "gazebo", "-o", "out.x"}, "u^2*delta");
  refused({"sway", "other-yaw", "--format", "gazebo", "-o", "out.x"}, "expected models of one body");
  refused({"sway", "sway-rudder", "--format", "gazebo", "-o", "out.x"}, "a second set of output Y");
  refused({"sway", "--format", "matlab", "-o", "out.x"}, "no mass matrix given");
  refused({"sway", "--format", "matlab", "--mass-diagonal", "1,2,3,4,5,6", "-o", "out.x"},
          "a MATLAB function is written to NAME.m");
  refused({"sway", "--format", "matlab", "--mass-diagonal", "1,2,3", "-o", "out.m"},
          "--mass-diagonal '1,2,3': 3 numbers");
  refused({"sway", "--format", "matlab", "--mass-diagonal", "1,2,3,4,5,6", "-o", "1bad.m"},
          "MATLAB function name '1bad'");
  refused({"sway", "--format", "matlab", "--mass-diagonal", "1,2,3,4,5,-6", "-o", "ok.m"}, "mass");
  refused({"sway", "--format", "csv", "--added-mass", "1,2,3,4,5,6", "-o", "out.x"}, "apply to --format gazebo only");
  refused({"sway", "--format", "csv", "-o", "missing/dir/out.x"}, "missing/dir/out.x");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out.m"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "ok.m"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "1bad.m"));
  EXPECT_EQ(read_bytes(dir_ / "hydrocoef.db"), before);
}

TEST_F(CliDerivativesExport, HostileNamesAreDataInEveryFormat) {
  const std::string name = kHostile;
  ASSERT_EQ(
      cli({"import", "captive.csv", "--body", name, "--disturbance", "delta", "--sign", "on-body", "--also", "hostile"})
          .exit_code,
      0);
  fit(name, "Y", "v, r, v*|v|", name + " Y");
  fit(name, "N", "v, r", name + " N");

  ASSERT_EQ(cli({"derivatives", "export", name + " Y", "--format", "json", "-o", "h.json"}).exit_code, 0);
  EXPECT_EQ(nlohmann::json::parse(read_bytes(dir_ / "h.json")).at("name"), name + " Y");

  ASSERT_EQ(cli({"derivatives", "export", name + " Y", "--format", "csv", "-o", "h.csv"}).exit_code, 0);
  const std::string csv = read_bytes(dir_ / "h.csv");
  for (const std::string_view line : split(csv, '\n'))
    if (line.find("<!--") != std::string_view::npos) EXPECT_EQ(line.front(), '#') << line;

  const auto gz = cli({"derivatives", "export", name + " Y", name + " N", "--format", "gazebo", "-o", "h.sdf"});
  ASSERT_EQ(gz.exit_code, 0) << gz.err;
  const std::string sdf = read_bytes(dir_ / "h.sdf");
  // Every comment closes where it was meant to (no "--" inside one), and the names are in comments only.
  std::string outside;
  std::size_t from = 0;
  for (std::size_t open = sdf.find("<!--"); open != std::string::npos; open = sdf.find("<!--", from)) {
    const std::size_t close = sdf.find("-->", open + 4);
    ASSERT_NE(close, std::string::npos);
    EXPECT_EQ(sdf.substr(open + 4, close - open - 4).find("--"), std::string::npos) << sdf.substr(open, close - open);
    outside += sdf.substr(from, open - from);
    from = close + 3;
  }
  outside += sdf.substr(from);
  EXPECT_NE(sdf.find("$(rm)"), std::string::npos);                 // the name is in the file ...
  EXPECT_EQ(outside.find("$(rm)"), std::string::npos) << outside;  // ... in comments only
  EXPECT_EQ(outside.find("]]>"), std::string::npos) << outside;

  const auto m = cli({"derivatives", "export", name + " Y", name + " N", "--format", "matlab", "-o", "h.m",
                      "--mass-diagonal", "60,80,80,3,9,9"});
  ASSERT_EQ(m.exit_code, 0) << m.err;
  const std::string matlab = read_bytes(dir_ / "h.m");
  for (const std::string_view line : split(matlab, '\n'))
    if (line.find("<!--") != std::string_view::npos) EXPECT_EQ(line.substr(0, 2), "% ") << line;
  // The report prints the names on one line each.
  EXPECT_EQ(std::count(m.out.begin(), m.out.end(), '\n'), 4) << m.out;
}

}  // namespace
}  // namespace hydrocoef
