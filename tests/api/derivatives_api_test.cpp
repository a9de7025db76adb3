// Derivative models through the public API (include/hydrocoef/derivatives.hpp)
// against the CLI on the same database: fit (terms, template refused for want
// of its names, selection), list, show in the SI and prime forms, evaluate and
// delete give the numbers `hydrocoef derivatives ... --json` prints and the
// same text; validate() refuses each bad option with the CLI's message; a
// read-only Database refuses the writes and leaves the file byte-identical.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hydrocoef/hydrocoef.hpp"
#include "tests/support/api_errors.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

using hydrocoef::Database;
using hydrocoef::OpenMode;
using hydrocoef::test::cli_error;
using hydrocoef::test::error_of;
using hydrocoef::test::run_cli;
using hydrocoef::test::TempDir;

class DerivativesApiTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::ofstream out(dir_ / "runs.csv");
    out << std::setprecision(17) << "u [m s^-1],v [m s^-1],r [rad s^-1],N [N m]\n";
    int i = 0;
    for (const double u : {1.0, 2.0})
      for (const double v : {-0.2, -0.1, 0.0, 0.1, 0.2})
        for (const double r : {-0.1, -0.05, 0.0, 0.05, 0.1}) {
          const double noise = 0.01 * std::sin(1.7 * ++i);  // deterministic scatter: finite errors
          out << u << "," << v << "," << r << "," << -4 * v - 9 * r - 30 * r * std::abs(r) + 2 * u * v + noise << "\n";
        }
    out.close();
    path_ = (dir_ / "d.db").string();
    ASSERT_EQ(
        run_cli({"--db", "d.db", "import", "runs.csv", "--body", "b", "--sign", "on-body"}, dir_.path()).exit_code, 0);
  }
  nlohmann::json cli_json(std::vector<std::string> args) {
    args.insert(args.begin(), {"--db", "d.db", "derivatives"});
    args.emplace_back("--json");
    const auto result = run_cli(args, dir_.path());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return nlohmann::json::parse(result.out);
  }
  std::string cli_message(std::vector<std::string> args) {
    args.insert(args.begin(), {"--db", "d.db", "derivatives"});
    return cli_error(run_cli(args, dir_.path()));
  }
  TempDir dir_;
  std::string path_;
};

void expect_same_model(const hydrocoef::DerivativeModel& api, const nlohmann::json& cli) {
  EXPECT_EQ(api.name, cli.at("name"));
  EXPECT_EQ(api.terms, cli.at("terms"));
  EXPECT_EQ(api.form, cli.at("form"));
  EXPECT_EQ(api.n, cli.at("n"));
  EXPECT_EQ(api.rmse, cli.at("rmse").get<double>());
  EXPECT_EQ(api.condition_number, cli.at("condition_number").get<double>());
  ASSERT_EQ(api.coefficients.size(), cli.at("coefficients").size());
  for (std::size_t k = 0; k < api.coefficients.size(); ++k) {
    const auto& c = cli.at("coefficients")[k];
    EXPECT_EQ(api.coefficients[k].term, c.at("term"));
    EXPECT_EQ(api.coefficients[k].value, c.at("value").get<double>());
    EXPECT_EQ(api.coefficients[k].std_error, c.at("std_error").get<double>());
    EXPECT_EQ(api.coefficients[k].vif, c.at("vif").get<double>());
  }
  ASSERT_EQ(api.covariance.size(), cli.at("covariance").size());
  for (std::size_t i = 0; i < api.covariance.size(); ++i)
    EXPECT_EQ(api.covariance[i], cli.at("covariance")[i].get<double>());
  EXPECT_EQ(api.json(), cli.dump(2) + "\n");
}

TEST_F(DerivativesApiTest, FitListShowEvaluateAndDeleteGiveTheCliNumbers) {
  const auto cli = cli_json({"fit", "--body", "b", "--output", "N", "--terms", "v, r, r*|r|, u*v", "--name", "yaw"});
  {
    auto db = Database::open(path_, OpenMode::ReadWrite);
    hydrocoef::DerivativeModelOptions options;
    options.body = "b";
    options.output = "N";
    options.terms = "v, r, r*|r|, u*v";
    options.name = "yaw-api";
    const auto api = hydrocoef::fit_derivative_model(db, options);
    EXPECT_EQ(api.coefficients.size(), 4u);
    for (std::size_t k = 0; k < 4; ++k)
      EXPECT_EQ(api.coefficients[k].value, cli.at("coefficients")[k].at("value").get<double>());
    EXPECT_NEAR(api.coefficients[2].value, -30.0, 1.0);
    EXPECT_EQ(api.coefficients[2].unit, "N m/(rad/s)^2");
    hydrocoef::delete_derivative_model(db, "yaw-api");
  }
  const auto db = Database::open(path_, OpenMode::ReadOnly);
  hydrocoef::DerivativeShowOptions show;
  show.name = "yaw";
  expect_same_model(hydrocoef::show_derivative_model(db, show), cli_json({"show", "yaw"}));
  const auto list = hydrocoef::list_derivative_models(db);
  ASSERT_EQ(list.models.size(), 1u);
  EXPECT_EQ(list.json(), cli_json({"list"}).dump(2) + "\n");
  EXPECT_EQ(list.text(), run_cli({"--db", "d.db", "derivatives", "list"}, dir_.path()).out);

  show.form = "prime";
  show.length = 2.5;
  show.speed = 1.5;
  show.density = 1025.0;
  expect_same_model(
      hydrocoef::show_derivative_model(db, show),
      cli_json({"show", "yaw", "--form", "prime", "--length", "2.5", "--speed", "1.5", "--density", "1025"}));
  EXPECT_EQ(hydrocoef::show_derivative_model(db, show).text(),
            run_cli({"--db", "d.db", "derivatives", "show", "yaw", "--form", "prime", "--length", "2.5", "--speed",
                     "1.5", "--density", "1025"},
                    dir_.path())
                .out);

  hydrocoef::DerivativeEvaluationOptions at;
  at.name = "yaw";
  at.at = {{"u", 1.5}, {"v", 0.05}, {"r", -0.02}};
  const auto value = hydrocoef::evaluate_derivative_model(db, at);
  const auto cli_value = cli_json({"evaluate", "yaw", "--at", "u=1.5", "--at", "v=0.05", "--at", "r=-0.02"});
  EXPECT_EQ(value.value, cli_value.at("value").get<double>());
  EXPECT_EQ(value.std_error, cli_value.at("std_error").get<double>());
  EXPECT_GT(value.std_error, 0.0);
  // sqrt(b^T C b) from the covariance shown.
  const auto model = hydrocoef::show_derivative_model(db, {.name = "yaw"});
  double variance = 0.0;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) variance += value.basis[i] * model.covariance[i * 4 + j] * value.basis[j];
  EXPECT_NEAR(value.std_error, std::sqrt(variance), 1e-15 + 1e-12 * value.std_error);
}

TEST_F(DerivativesApiTest, ValidateRefusesWithTheCliMessages) {
  hydrocoef::DerivativeModelOptions fit;
  fit.body = "b";
  EXPECT_EQ(error_of([&] { fit.validate(); }), cli_message({"fit", "--body", "b", "--terms", "v"}));
  fit.output = "Q";
  fit.terms = "v";
  EXPECT_EQ(error_of([&] { fit.validate(); }), cli_message({"fit", "--body", "b", "--output", "Q", "--terms", "v"}));
  fit.output = "N";
  fit.model_template = "abkowitz";
  EXPECT_EQ(error_of([&] { fit.validate(); }),
            cli_message({"fit", "--body", "b", "--output", "N", "--terms", "v", "--template", "abkowitz"}));
  fit.model_template.clear();
  fit.select = "kfold:1";
  EXPECT_EQ(error_of([&] { fit.validate(); }),
            cli_message({"fit", "--body", "b", "--output", "N", "--terms", "v", "--select", "kfold:1"}));
  fit.select.clear();
  fit.where = {"v>=abc"};
  EXPECT_EQ(error_of([&] { fit.validate(); }),
            cli_message({"fit", "--body", "b", "--output", "N", "--terms", "v", "--where", "v>=abc"}));
  hydrocoef::DerivativeShowOptions show;
  show.name = "x";
  show.form = "metric";
  EXPECT_EQ(error_of([&] { show.validate(); }), cli_message({"show", "x", "--form", "metric"}));
  show.form = "prime";
  show.length = -1.0;
  EXPECT_EQ(error_of([&] { show.validate(); }), cli_message({"show", "x", "--form", "prime", "--length", "-1"}));
  hydrocoef::DerivativeEvaluationOptions at;
  at.name = "x";
  EXPECT_EQ(error_of([&] { at.validate(); }), "derivatives evaluate: expected the point (--at NAME=VALUE, repeatable)");
  // The library's refusals too: a template whose names the runs lack, and a name that is not there.
  auto db = Database::open(path_, OpenMode::ReadWrite);
  fit.where.clear();
  fit.terms.clear();
  fit.model_template = "abkowitz";
  EXPECT_EQ(error_of([&] { hydrocoef::fit_derivative_model(db, fit); }),
            cli_message({"fit", "--body", "b", "--output", "N", "--template", "abkowitz"}));
  // The database is named as each opened it (here by its absolute path, the CLI by --db d.db).
  const auto after_path = [](const std::string& message) { return message.substr(message.find(": ")); };
  EXPECT_EQ(after_path(error_of([&] { hydrocoef::delete_derivative_model(db, "none"); })),
            after_path(cli_message({"delete", "none"})));
}

TEST_F(DerivativesApiTest, AReadOnlyDatabaseRefusesWritesAndStaysByteIdentical) {
  cli_json({"fit", "--body", "b", "--output", "N", "--terms", "v, r", "--name", "m"});
  const std::string before = hydrocoef::test::read_bytes(path_);
  {
    auto db = Database::open(path_, OpenMode::ReadOnly);
    hydrocoef::DerivativeModelOptions fit;
    fit.body = "b";
    fit.output = "N";
    fit.terms = "v, r";
    EXPECT_NE(error_of([&] { hydrocoef::fit_derivative_model(db, fit); }).find("database is open read-only"),
              std::string::npos);
    EXPECT_NE(error_of([&] { hydrocoef::delete_derivative_model(db, "m"); }).find("database is open read-only"),
              std::string::npos);
    fit.store = false;
    EXPECT_EQ(hydrocoef::fit_derivative_model(db, fit).id, 0);
    EXPECT_EQ(hydrocoef::list_derivative_models(db).models.size(), 1u);
  }
  EXPECT_EQ(hydrocoef::test::read_bytes(path_), before);
}

}  // namespace
