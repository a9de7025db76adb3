// hydrocoef import --format captive-table, end to end: captive runs generated
// from a published derivative set, written as captive-test tables in the
// prime and the bis forms, imported, fitted with `derivatives fit` and shown
// with `derivatives show --form prime`, give the printed derivatives back;
// the body's stored reference data stand in for a length the table and the
// options do not give, and the import says so; each refusal is one line
// naming the file, line and column, exit 2, the database unchanged.
//
// The set: the Mariner class vessel's sway force and yaw moment (Chislett and
// Strom-Tejsen 1965, Technical Report Hy-5, Hydro- and Aerodynamics
// Laboratory, Lyngby; as printed, times 1e-5, in the MSS toolbox's
// CRAFT/SHIP/models/mariner.m, github.com/cybergalactic/MSS, commit 6bca7942;
// the same numbers as tests/derivatives/mariner_captive_runs_test.cpp). The
// runs are a captive programme at the reference speed (static drift, rudder
// angle, drift and rudder, circular motion with drift; u = U0, so the terms
// in the surge perturbation du are not among those fitted), each row written
// at its own speed U = |(u, v)| with its forces normalised by that speed, as
// a towing tank states them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hydrocoef/database.hpp"
#include "hydrocoef/error.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/sqlite_dump.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using nlohmann::json;
using test::CliResult;
using test::TempDir;

constexpr double kLength = 160.93;   // L [m]
constexpr double kSpeed = 7.7175;    // U0 [m/s]
constexpr double kDensity = 1025.0;  // rho [kg/m^3]
constexpr double kVolume = 18541.0;  // displaced volume [m^3] for the bis form (Mariner: 18541 m^3)
constexpr double kGravity = 9.80665;
constexpr double kPi = 3.14159265358979323846;

struct Printed {
  const char* term;  // in v', r', delta
  double value_e5;
};
// The printed derivatives free of the surge perturbation du (prime, times 1e5).
// clang-format off
const std::vector<Printed> kSway{{"1", -4}, {"v", -1160}, {"r", -499}, {"v^3", -8078}, {"v^2*r", 15356},
                                 {"delta", 278}, {"delta^3", -90}, {"v*delta^2", -4}, {"v^2*delta", 1190}};
const std::vector<Printed> kYaw{{"1", 3}, {"v", -264}, {"r", -166}, {"v^3", 1636}, {"v^2*r", -5483},
                                {"delta", -139}, {"delta^3", 45}, {"v*delta^2", 13}, {"v^2*delta", -489}};
// clang-format on

double term_value(const std::string& term, double v, double r, double delta) {
  if (term == "1") return 1.0;
  if (term == "v") return v;
  if (term == "r") return r;
  if (term == "v^3") return v * v * v;
  if (term == "v^2*r") return v * v * r;
  if (term == "delta") return delta;
  if (term == "delta^3") return delta * delta * delta;
  if (term == "v*delta^2") return v * delta * delta;
  if (term == "v^2*delta") return v * v * delta;
  ADD_FAILURE() << term;
  return 0.0;
}

/// The Mariner's Y' or N' (normalised at U0) at v' = v/U0, r' = r L/U0, delta.
double mariner(const std::vector<Printed>& set, double v, double r, double delta) {
  double sum = 0.0;
  for (const auto& p : set) sum += p.value_e5 * 1e-5 * term_value(p.term, v, r, delta);
  return sum;
}

struct Point {
  const char* test;
  double v, r, delta;  // prime at U0
};

std::vector<Point> programme() {
  std::vector<Point> points;
  for (const double v : {-0.3, -0.2, -0.1, 0.0, 0.1, 0.2, 0.3}) points.push_back({"static-drift", v, 0.0, 0.0});
  for (const double delta : {-0.5, -0.3, -0.1, 0.1, 0.3, 0.5}) points.push_back({"rudder", 0.0, 0.0, delta});
  for (const double v : {-0.2, 0.2})
    for (const double delta : {-0.4, -0.2, 0.2, 0.4}) points.push_back({"drift-rudder", v, 0.0, delta});
  for (const double r : {-0.4, -0.2, 0.2, 0.4})
    for (const double v : {-0.2, -0.1, 0.0, 0.1, 0.2}) points.push_back({"circular-motion", v, r, 0.0});
  return points;
}

std::string number(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

/// The programme as a captive table in `form` (prime or bis), each row at its
/// own speed, the drift angle by the MMG convention.
std::string captive_table(const std::string& form) {
  const double mg = kDensity * kVolume * kGravity;
  std::string text = "# The Mariner's Y' and N' (Chislett and Strom-Tejsen 1965) at U0 = 7.7175 m/s\n";
  text += "# form = " + form + "\n# drift_convention = mmg\n# density = 1025\n";
  if (form == "bis") text += "# volume = " + number(kVolume) + "\n";
  text += "test,U [m/s],beta [deg],delta [rad],r'," + std::string(form == "bis" ? "Y'',N''" : "Y',N'") + "\n";
  for (const auto& p : programme()) {
    const double u = kSpeed, v = p.v * kSpeed, r = p.r * kSpeed / kLength;
    const double U = std::hypot(u, v);
    const double beta = std::atan2(-v, u);
    const double Y = 0.5 * kDensity * kSpeed * kSpeed * kLength * kLength * mariner(kSway, p.v, p.r, p.delta);
    const double N = 0.5 * kDensity * kSpeed * kSpeed * std::pow(kLength, 3) * mariner(kYaw, p.v, p.r, p.delta);
    const double y = form == "bis" ? Y / mg : Y / (0.5 * kDensity * U * U * kLength * kLength);
    const double n = form == "bis" ? N / (mg * kLength) : N / (0.5 * kDensity * U * U * std::pow(kLength, 3));
    text += std::string(p.test) + "," + number(U) + "," + number(beta * 180.0 / kPi) + "," + number(p.delta) + "," +
            number(r * kLength / U) + "," + number(y) + "," + number(n) + "\n";
  }
  return text;
}

std::string terms_of(const std::vector<Printed>& set) {
  std::string out;
  for (const auto& p : set) out += (out.empty() ? "" : ", ") + std::string(p.term);
  return out;
}

class CliCaptiveTable : public ::testing::Test {
 protected:
  CliResult cli(std::vector<std::string> args) {
    args.insert(args.begin(), {"--db", "hydrocoef.db"});
    return test::run_cli(args, dir_.path());
  }
  std::string out(const std::vector<std::string>& args) {
    const auto result = cli(args);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return result.out;
  }
  void write(const std::string& name, const std::string& text) { test::write_bytes(dir_.path() / name, text); }
  /// exit 2 and one line holding `message`, the database byte for byte as it was.
  void refused(const std::vector<std::string>& args, const std::string& message) {
    SCOPED_TRACE(testing::PrintToString(args));
    const std::string bytes = test::read_bytes(dir_.path() / "hydrocoef.db");
    const std::string dump = test::dump_database(dir_.path() / "hydrocoef.db");
    const auto result = cli(args);
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find(message), std::string::npos) << result.err;
    EXPECT_EQ(test::read_bytes(dir_.path() / "hydrocoef.db"), bytes);
    EXPECT_EQ(test::dump_database(dir_.path() / "hydrocoef.db"), dump);
  }
  /// Fits Y and N of the body with the Mariner's terms and checks `show --form prime`.
  void expect_mariner_back(const std::string& body) {
    for (const bool sway : {true, false}) {
      const auto& set = sway ? kSway : kYaw;
      const std::string name = body + (sway ? "-Y" : "-N");
      out({"derivatives", "fit", "--body", body, "--output", sway ? "Y" : "N", "--terms", terms_of(set), "--name",
           name});
      const json shown = json::parse(out({"derivatives", "show", name, "--form", "prime", "--length", number(kLength),
                                          "--speed", number(kSpeed), "--density", "1025", "--json"}));
      const auto& coefficients = shown.at("coefficients");
      ASSERT_EQ(coefficients.size(), set.size());
      for (std::size_t k = 0; k < set.size(); ++k) {
        EXPECT_EQ(coefficients[k].at("term").get<std::string>(), set[k].term);
        const double printed = set[k].value_e5 * 1e-5;
        EXPECT_NEAR(coefficients[k].at("value").get<double>(), printed, 1e-9 * std::abs(printed))
            << name << " " << set[k].term;
      }
    }
  }

  TempDir dir_;
};

TEST_F(CliCaptiveTable, MarinerPrimeTableGivesThePrintedDerivativesBack) {
  write("mariner-prime.csv", captive_table("prime"));
  const std::string imported = out(
      {"import", "--format", "captive-table", "mariner-prime.csv", "--body", "mariner", "--length", number(kLength)});
  EXPECT_NE(imported.find("captive-test table, 41 runs (20 circular-motion, 8 drift-rudder, 6 rudder, "
                          "7 static-drift)"),
            std::string::npos)
      << imported;
  EXPECT_NE(imported.find("L = 160.93 m (--length)"), std::string::npos) << imported;
  expect_mariner_back("mariner");
}

TEST_F(CliCaptiveTable, MarinerBisTableGivesThePrintedDerivativesBack) {
  write("mariner-bis.csv", captive_table("bis"));
  out({"import", "--format", "captive-table", "mariner-bis.csv", "--body", "mariner", "--length", number(kLength)});
  expect_mariner_back("mariner");
}

TEST_F(CliCaptiveTable, TheExampleTableInDataGivesThePrintedDerivativesBack) {
  // data/captive-mariner/mariner-prime.csv, written by its make_mariner_table.py: the same programme.
  const std::string table = std::string(HYDROCOEF_DATA_DIR) + "/captive-mariner/mariner-prime.csv";
  const std::string imported = out({"import", "--format", "captive-table", table, "--body", "example"});
  EXPECT_NE(imported.find("L = 160.93 m (line 5)"), std::string::npos) << imported;
  expect_mariner_back("example");
}

TEST_F(CliCaptiveTable, TheBodysStoredLengthStandsInAndIsNamed) {
  std::string table = captive_table("prime");
  write("first.csv", table);
  out({"import", "--format", "captive-table", "first.csv", "--body", "mariner", "--length", number(kLength)});
  out({"body", "set", "mariner", "--length", number(kLength)});
  // The same runs again from a copy with other bytes (a comment): already there, no length given.
  write("second.csv", "# copy\n" + table);
  const std::string again =
      out({"import", "--format", "captive-table", "second.csv", "--body", "mariner", "--replace"});
  EXPECT_NE(again.find("L = 160.93 m (the body's reference data)"), std::string::npos) << again;
}

TEST_F(CliCaptiveTable, TheApiImportUsesItsOwnDatabasesBodyReference) {
  write("first.csv", captive_table("prime"));
  out({"import", "--format", "captive-table", "first.csv", "--body", "mariner", "--length", number(kLength)});
  out({"body", "set", "mariner", "--length", number(kLength)});
  write("second.csv", "# copy\n" + captive_table("prime"));
  auto database = hydrocoef::Database::open(test::database_location(dir_.path() / "hydrocoef.db"));
  hydrocoef::ImportOptions options;
  options.format = "captive-table";
  options.body = "mariner";
  options.replace = true;
  const auto summary = database.import_files({(dir_.path() / "second.csv").string()}, options);
  EXPECT_NE(summary.text().find("L = 160.93 m (the body's reference data)"), std::string::npos) << summary.text();
  // Without the stored length the same call is refused naming the column, nothing stored.
  options.body = "another";
  try {
    (void)database.import_files({(dir_.path() / "second.csv").string()}, options);
    ADD_FAILURE() << "imported without a length";
  } catch (const hydrocoef::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("second.csv:6:40: column Y' (prime) needs the reference length"),
              std::string::npos)
        << error.what();
  }
}

TEST_F(CliCaptiveTable, RefusalsAreOneLineAndLeaveTheDatabaseAsItWas) {
  write("good.csv", captive_table("prime"));
  out({"import", "--format", "captive-table", "good.csv", "--body", "mariner", "--length", number(kLength)});
  const std::vector<std::string> import = {"import", "--format", "captive-table", "--body", "other"};
  const auto with = [&](const std::string& file, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = import;
    args.push_back(file);
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  // No reference length anywhere (the body "other" has none stored).
  refused(with("good.csv"), "good.csv:5:40: column Y' (prime) needs the reference length: give --length");
  write("no-convention.csv", "# form = prime\n# length = 3\n# density = 1000\nU [m/s],beta [deg],Y'\n1,2,0.01\n");
  refused(with("no-convention.csv"),
          "no-convention.csv:4:9: column beta [deg]: the drift-angle convention is not stated");
  write("bad-unit.csv", "# form = prime\n# length = 3\n# density = 1000\nU [m/s],delta [m],Y'\n1,2,0.01\n");
  refused(with("bad-unit.csv"), "bad-unit.csv:4:9: column 'delta [m]': unit 'm' is m, expected rad");
  write("not-finite.csv", "# form = prime\n# length = 3\n# density = 1000\nU [m/s],r',Y'\n1,0.1,nan\n");
  refused(with("not-finite.csv"), "not-finite.csv:5:7: column 'Y'': found 'nan', expected a finite number");
  write("test-type.csv", "# form = prime\n# length = 3\n# density = 1000\ntest,U [m/s],Y'\npmm,1,0.01\n");
  refused(with("test-type.csv"), "test-type.csv:5:1: column test: found 'pmm', expected static-drift, rudder");
  // Options: checked before any file is read.
  refused(with("good.csv", {"--form", "sname"}), "--form 'sname': expected prime (SNAME 1950), bis");
  refused(with("good.csv", {"--length", "-1"}), "--length must be a finite number above 0, not -1");
  refused(with("good.csv", {"--drift-convention", "port"}), "--drift-convention 'port': expected mmg");
  refused(with("good.csv", {"--rho", "1000", "--density", "1025"}), "--rho and --density both give the density");
  refused({"import", "good.csv", "--length", "3"},
          "--length is for captive-test tables; expected --format captive-table with it");
}

TEST_F(CliCaptiveTable, HelpNamesTheOptions) {
  const auto help = test::run_cli({"import", "--help"}, dir_.path());
  ASSERT_EQ(help.exit_code, 0);
  for (const char* option : {"captive-table", "--form", "--drift-convention", "--length", "--speed", "--density",
                             "--draft", "--mass", "--volume", "--gravity"})
    EXPECT_NE(help.out.find(option), std::string::npos) << option;
}

}  // namespace
}  // namespace hydrocoef
