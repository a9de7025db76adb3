// hydrocoef::pmm_derivatives (include/hydrocoef/pmm_derivatives.hpp) driven
// through the public C++ API and through `hydrocoef derivatives pmm` on the
// same database: the real OpenFOAM sphere runs of
// examples/openfoam-sphere/pmm read as sway runs give the same numbers, the
// same JSON and the same text both ways; validate() and the operation refuse
// bad input with the CLI's message; the database file is not changed.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hydrocoef/hydrocoef.hpp"
#include "tests/support/api_errors.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/run_cli.hpp"
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

const fs::path kPmm = fs::path(HYDROCOEF_SOURCE_DIR) / "examples/openfoam-sphere/pmm";

class PmmDerivativesApiTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (hydrocoef::test::on_postgresql()) GTEST_SKIP() << "the API and the CLI share an SQLite file here";
    path_ = (dir_ / "pmm.db").string();
    // The sphere moved along the case's x, read as sway (body y = case x).
    ASSERT_EQ(cli({"pmm", (kPmm / "surge-A0.015-T2").string(), (kPmm / "surge-A0.045-T2").string(), "--body", "sphere",
                   "--axes", "y,x,-z", "--rho", "998.2"})
                  .exit_code,
              0);
    ASSERT_EQ(cli({"body", "set", "sphere", "--length", "0.3"}).exit_code, 0);
  }

  hydrocoef::test::CliResult cli(std::vector<std::string> args) {
    args.insert(args.begin(), {"--db", path_});
    return run_cli(args, dir_.path());
  }

  TempDir dir_;
  std::string path_;
};

TEST_F(PmmDerivativesApiTest, TheApiGivesTheCliNumbersAndDocuments) {
  const std::string before = hydrocoef::test::read_bytes(path_);
  hydrocoef::PmmDerivativeOptions options;
  options.body = "sphere";
  options.speed = 0.5;
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  const hydrocoef::PmmDerivatives result = hydrocoef::pmm_derivatives(db, options);
  const auto cli_json = cli({"derivatives", "pmm", "sphere", "--speed", "0.5", "--json"});
  ASSERT_EQ(cli_json.exit_code, 0) << cli_json.err;
  EXPECT_EQ(result.json() + "\n", cli_json.out);
  const auto cli_text = cli({"derivatives", "pmm", "sphere", "--speed", "0.5"});
  ASSERT_EQ(cli_text.exit_code, 0) << cli_text.err;
  EXPECT_EQ(result.text(), cli_text.out);

  const json theirs = json::parse(cli_json.out);
  ASSERT_EQ(result.sets.size(), 1u);
  ASSERT_EQ(theirs["sets"].size(), 1u);
  const auto& set = result.sets[0];
  EXPECT_EQ(set.motion, "pure sway");
  EXPECT_EQ(set.speed, 0.5);
  ASSERT_TRUE(set.omega_prime.has_value());
  EXPECT_NEAR(*set.omega_prime, 3.14159265358979 * 0.3 / 0.5, 1e-9);  // omega = pi rad/s
  EXPECT_EQ(*set.omega_prime, theirs["sets"][0]["omega_prime"].get<double>());
  ASSERT_EQ(set.derivatives.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    const auto& d = set.derivatives[k];
    const json& c = theirs["sets"][0]["derivatives"][k];
    EXPECT_EQ(d.name, c["name"]);
    EXPECT_EQ(d.value, c["value"].get<double>()) << d.name;
    EXPECT_EQ(d.std_error, c["std_error"].get<double>()) << d.name;
    ASSERT_TRUE(d.prime.has_value()) << d.name;  // L from the body, rho from the runs, U given
    EXPECT_EQ(*d.prime, c["prime"].get<double>()) << d.name;
  }
  EXPECT_EQ(result.length_from, "body reference");
  EXPECT_EQ(result.density_from, "the runs");
  // Y_vdot is -M_A[sway][sway] of the added-mass matrix on the same database.
  hydrocoef::AddedMassMatrixOptions matrix_options;
  matrix_options.body = "sphere";
  const auto matrix = hydrocoef::added_mass_matrix(db, matrix_options);
  EXPECT_EQ(set.derivatives[1].value, -matrix.added_mass[1][1]);
  // Y_vdot' = Y_vdot / (1/2 rho L^3).
  EXPECT_NEAR(*set.derivatives[1].prime, set.derivatives[1].value / (0.5 * 998.2 * 0.027),
              1e-12 * std::abs(*set.derivatives[1].prime));
  EXPECT_EQ(hydrocoef::test::read_bytes(path_), before);
}

TEST_F(PmmDerivativesApiTest, BadOptionsAreRefusedWithTheCliMessage) {
  const std::string before = hydrocoef::test::read_bytes(path_);
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  struct Case {
    std::vector<std::string> args;
    hydrocoef::PmmDerivativeOptions options;
  };
  hydrocoef::PmmDerivativeOptions base;
  base.body = "sphere";
  std::vector<Case> cases;
  cases.push_back({{"--length", "-1"}, base});
  cases.back().options.length = -1.0;
  cases.push_back({{"--density", "0"}, base});
  cases.back().options.density = 0.0;
  cases.push_back({{"--prime"}, base});  // U = 0: the runs' u
  cases.back().options.prime = true;
  cases.push_back({{"--run", "12345"}, base});
  cases.back().options.runs = {12345};
  for (const auto& c : cases) {
    std::vector<std::string> args = {"derivatives", "pmm", "sphere"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const std::string expected = cli_error(cli(args));
    EXPECT_FALSE(expected.empty());
    EXPECT_EQ(error_of([&] { (void)hydrocoef::pmm_derivatives(db, c.options); }), expected) << expected;
  }
  hydrocoef::PmmDerivativeOptions no_body;
  EXPECT_NE(error_of([&] { no_body.validate(); }).find("expected the body"), std::string::npos);
  hydrocoef::PmmDerivativeOptions bad_length = base;
  bad_length.length = -1.0;
  EXPECT_EQ(error_of([&] { bad_length.validate(); }), "--length -1: expected a finite number > 0 (m)");
  EXPECT_EQ(hydrocoef::test::read_bytes(path_), before);
}

}  // namespace
