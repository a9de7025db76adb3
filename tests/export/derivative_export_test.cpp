// Exports of a derivative set (src/export/derivative_export.hpp): CSV and
// JSON give back every number bit for bit; the non-dimensional form equals
// the normalisation's own conversion of each coefficient (and its standard
// error and covariance), with the normalisation named; the dimensional
// JSON's model reads back as a vehicle's damping; bad sets and missing
// reference values are refused naming them; hostile names stay data.
#include "src/export/derivative_export.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "src/core/escape.hpp"
#include "src/dynamics/vehicle.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;

// A sway set with numbers that do not print short (1/3, 1e-7 ...).
DerivativeSet sway_set() {
  DerivativeSet set;
  set.name = "mariner-sway";
  set.output = "Y";
  set.terms = parse_terms("v, r, v*|v|, u*v, v^2*r, delta");
  set.coefficients = {-1.0 / 3.0, 0.123456789012345, -11.7, -2.5e-7, 1234.5678, 0.3};
  const std::size_t m = set.terms.size();
  set.covariance.assign(m * m, 0.0);
  for (std::size_t i = 0; i < m; ++i) {
    set.covariance[i * m + i] = 0.01 * static_cast<double>(i + 1) / 7.0;
    if (i + 1 < m) set.covariance[i * m + i + 1] = set.covariance[(i + 1) * m + i] = 0.001 / 3.0;
  }
  set.system = NormalisationSystem::Prime;
  set.reference.length = 160.93;
  set.reference.speed = 7.7175;
  set.reference.density = 1025.0;
  return set;
}

// The CSV's data rows, cells split at commas (the test's names hold none).
std::vector<std::vector<std::string>> csv_rows(const std::string& text, std::vector<std::string>& comments) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.starts_with("#")) {
      comments.push_back(line);
      continue;
    }
    std::vector<std::string> cells;
    std::istringstream fields(line);
    std::string cell;
    while (std::getline(fields, cell, ',')) cells.push_back(cell);
    if (line.ends_with(",")) cells.emplace_back();
    rows.push_back(cells);
  }
  return rows;
}

TEST(DerivativeExport, CsvGivesBackEveryNumber) {
  const DerivativeSet set = sway_set();
  const std::size_t m = set.terms.size();
  std::vector<std::string> comments;
  const auto rows = csv_rows(derivative_csv(set, DerivativeForm::Dimensional), comments);
  ASSERT_EQ(rows.size(), m + 1);
  EXPECT_EQ(rows[0][0], "output");
  EXPECT_EQ(rows[0][4], "unit");
  EXPECT_EQ(rows[0][5], "cov:v");
  EXPECT_EQ(rows[0][5 + 2], "cov:v*|v|");
  for (std::size_t k = 0; k < m; ++k) {
    const auto& row = rows[k + 1];
    ASSERT_EQ(row.size(), 5 + m);
    EXPECT_EQ(row[0], "Y");
    EXPECT_EQ(row[1], set.terms[k].text());
    EXPECT_EQ(std::stod(row[2]), set.coefficients[k]) << row[1];
    EXPECT_EQ(std::stod(row[3]), std::sqrt(set.covariance[k * m + k]));
    for (std::size_t j = 0; j < m; ++j) EXPECT_EQ(std::stod(row[5 + j]), set.covariance[k * m + j]);
  }
  EXPECT_EQ(rows[1][4], "N/(m/s)");
  EXPECT_EQ(rows[3][4], "N/(m/s)^2");
  EXPECT_EQ(rows[5][4], "N/((m/s)^2 (rad/s))");
  EXPECT_EQ(rows[6][4], "N/(rad)");
  bool sign = false;
  for (const auto& c : comments) sign = sign || c.find("sign: on-body") != std::string::npos;
  EXPECT_TRUE(sign);
  // Without a covariance: no covariance columns, standard errors as given.
  DerivativeSet plain = set;
  plain.covariance.clear();
  plain.std_errors = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
  comments.clear();
  const auto plain_rows = csv_rows(derivative_csv(plain, DerivativeForm::Dimensional), comments);
  ASSERT_EQ(plain_rows[0].size(), 5u);
  EXPECT_EQ(std::stod(plain_rows[2][3]), 0.2);
}

TEST(DerivativeExport, JsonGivesBackEveryNumberAndReadsBackAsAVehicleModel) {
  const DerivativeSet set = sway_set();
  const std::size_t m = set.terms.size();
  const auto doc = nlohmann::json::parse(derivative_json(set, DerivativeForm::Dimensional));
  EXPECT_EQ(doc["format"], "hydrocoef-derivative-set");
  EXPECT_EQ(doc["form"], "dimensional");
  EXPECT_EQ(doc["sign"], "on-body");
  EXPECT_EQ(doc["name"], "mariner-sway");
  EXPECT_EQ(parse_terms(doc["terms"].get<std::string>()), set.terms);
  EXPECT_EQ(doc["coefficients"].get<std::vector<double>>(), set.coefficients);
  for (std::size_t i = 0; i < m; ++i) {
    EXPECT_EQ(doc["std_errors"][i].get<double>(), std::sqrt(set.covariance[i * m + i]));
    for (std::size_t j = 0; j < m; ++j) EXPECT_EQ(doc["covariance"][i][j].get<double>(), set.covariance[i * m + j]);
  }
  EXPECT_EQ(doc["units"][2], "N/(m/s)^2");
  // The model part is a vehicle file's "derivatives" object.
  nlohmann::json vehicle = {{"mass", 10.0},
                            {"inertia", {1.0, 2.0, 3.0}},
                            {"center_of_gravity", {0.0, 0.0, 0.05}},
                            {"neutrally_buoyant", true}};
  vehicle["damping"]["Y"] = {
      {"derivatives",
       {{"terms", doc["terms"]}, {"coefficients", doc["coefficients"]}, {"covariance", doc["covariance"]}}},
      {"sign", doc["sign"]}};
  const VehicleDescription v = parse_vehicle(vehicle.dump(), "v.json");
  EXPECT_EQ(v.damping[1].terms, set.terms);
  EXPECT_EQ(v.damping[1].coefficients, set.coefficients);
  EXPECT_EQ(v.damping[1].covariance, set.covariance);
}

TEST(DerivativeExport, NonDimensionalFormIsTheNormalisationsConversion) {
  const DerivativeSet set = sway_set();
  const std::size_t m = set.terms.size();
  const auto doc = nlohmann::json::parse(derivative_json(set, DerivativeForm::NonDimensional));
  EXPECT_EQ(doc["form"], "prime");
  const std::string text = doc["normalisation"]["text"];
  EXPECT_NE(text.find("prime (SNAME 1950): Y' = Y / (1/2 rho U^2 L^2)"), std::string::npos) << text;
  EXPECT_NE(text.find("L = 160.93 m"), std::string::npos) << text;
  EXPECT_EQ(doc["normalisation"]["reference"]["length"].get<double>(), 160.93);
  std::vector<double> scale(m);
  for (std::size_t k = 0; k < m; ++k) {
    const DerivativeKind kind = derivative_kind("Y", set.terms[k]);
    const double expected = to_nondimensional(set.coefficients[k], kind, NormalisationSystem::Prime, set.reference);
    EXPECT_NEAR(doc["coefficients"][k].get<double>(), expected, 1e-15 * std::abs(expected)) << set.terms[k].text();
    scale[k] = set.coefficients[k] / expected;
  }
  // By hand: Y_v' = Y_v / (1/2 rho U L^2), Y_r' = Y_r / (1/2 rho U L^3), delta unscaled.
  const double half_rho = 0.5 * 1025.0, u = 7.7175, l = 160.93;
  EXPECT_NEAR(doc["coefficients"][0].get<double>(), (-1.0 / 3.0) / (half_rho * u * l * l), 1e-15 * 1e-9);
  EXPECT_NEAR(doc["coefficients"][1].get<double>(), 0.123456789012345 / (half_rho * u * l * l * l), 1e-24);
  EXPECT_NEAR(doc["coefficients"][5].get<double>(), 0.3 / (half_rho * u * u * l * l), 1e-20);
  EXPECT_EQ(doc["scales"][0], "1/2 rho U L^2");
  for (std::size_t i = 0; i < m; ++i) {
    EXPECT_NEAR(doc["std_errors"][i].get<double>(), std::sqrt(set.covariance[i * m + i]) / std::abs(scale[i]),
                1e-14 * doc["std_errors"][i].get<double>());
    for (std::size_t j = 0; j < m; ++j) {
      const double expected = set.covariance[i * m + j] / (scale[i] * scale[j]);
      EXPECT_NEAR(doc["covariance"][i][j].get<double>(), expected, 1e-14 * std::abs(expected));
    }
  }
  // The CSV names the normalisation and gives the same numbers.
  std::vector<std::string> comments;
  const auto rows = csv_rows(derivative_csv(set, DerivativeForm::NonDimensional), comments);
  EXPECT_EQ(rows[0][4], "scale");
  for (std::size_t k = 0; k < m; ++k) EXPECT_EQ(std::stod(rows[k + 1][2]), doc["coefficients"][k].get<double>());
  bool named = false;
  for (const auto& c : comments) named = named || c.find("prime (SNAME 1950): Y'") != std::string::npos;
  EXPECT_TRUE(named);
}

TEST(DerivativeExport, BadSetsAndMissingReferencesAreRefusedNamingThem) {
  DerivativeSet set = sway_set();
  set.reference.speed.reset();
  expect_input_error([&] { derivative_json(set, DerivativeForm::NonDimensional); },
                     {"mariner-sway", "reference speed U"});
  EXPECT_NO_THROW(derivative_json(set, DerivativeForm::Dimensional));  // the dimensional form needs no reference
  set = sway_set();
  set.output = "CY";
  expect_input_error([&] { derivative_csv(set, DerivativeForm::NonDimensional); }, {"mariner-sway", "'CY'"});
  set = sway_set();
  set.coefficients.pop_back();
  expect_input_error([&] { derivative_csv(set, DerivativeForm::Dimensional); },
                     {"mariner-sway", "5 coefficients for 6 terms"});
  set = sway_set();
  set.coefficients[2] = std::nan("");
  expect_input_error([&] { derivative_csv(set, DerivativeForm::Dimensional); }, {"v*|v|", "not finite"});
  set = sway_set();
  set.std_errors.assign(6, 1.0);
  expect_input_error([&] { derivative_csv(set, DerivativeForm::Dimensional); }, {"'v'", "covariance's diagonal"});
  set = sway_set();
  set.covariance[1] = 5.0;  // not symmetric
  expect_input_error([&] { derivative_csv(set, DerivativeForm::Dimensional); }, {"mariner-sway", "covariance"});
  set = sway_set();
  set.terms.clear();
  set.coefficients.clear();
  set.covariance.clear();
  expect_input_error([&] { derivative_csv(set, DerivativeForm::Dimensional); }, {"no terms"});
}

TEST(DerivativeExport, HostileNamesStayData) {
  DerivativeSet set = sway_set();
  set.name = "=HYPERLINK(\"x\")\n# forged,line\r\"quoted\"";
  const std::string csv = derivative_csv(set, DerivativeForm::Dimensional);
  // Every line is a comment, the header or a data row: the name forged no line.
  std::istringstream in(csv);
  std::string line;
  std::size_t data = 0;
  while (std::getline(in, line)) {
    EXPECT_EQ(line.find('\r'), std::string::npos);
    if (!line.starts_with("#")) ++data;
    EXPECT_FALSE(line.starts_with("# forged")) << line;
  }
  EXPECT_EQ(data, 1 + set.terms.size());
  const auto doc = nlohmann::json::parse(derivative_json(set, DerivativeForm::Dimensional));
  EXPECT_EQ(doc["name"], set.name);  // JSON keeps it exactly
}

}  // namespace
}  // namespace hydrocoef
