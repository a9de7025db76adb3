// The forceCoeffs writer (src/export/openfoam_forcecoeffs.hpp):
// - its layout is OpenFOAM v1912's to the byte: given the forces behind the
//   coefficient.dat OpenFOAM wrote for data/openfoam-sphere/forcecoeffs/
//   M1-U0.1000 (writePrecision 10, the case's reference values), it writes
//   that file again, front/rear columns included (formed before rounding,
//   as OpenFOAM forms them);
// - importers/openfoam_forces reads what it writes (precision 16) back into
//   the forces it was given: each value itself where a double coefficient
//   gives it back through the reader's F = C * (q Aref), else the double next
//   to it, and the writer's counts say which;
// - inverse_of_product finds such a coefficient whenever one exists (checked
//   against a search of every double near value / scale);
// - it refuses what a reader would misread.
#include "src/export/openfoam_forcecoeffs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include "importers/openfoam_forces.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
const fs::path kOpenFoamFile = fs::path(HYDROCOEF_SOURCE_DIR) /
                               "data/openfoam-sphere/forcecoeffs/M1-U0.1000/postProcessing/forceCoeffs/199/"
                               "coefficient.dat";

std::string file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

/// The numbers of the one data row of OpenFOAM's file.
std::vector<double> openfoam_row(const std::string& text) {
  std::istringstream lines(text);
  std::vector<double> values;
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && line[0] != '#') {
      std::istringstream words(line);
      for (double v; words >> v;) values.push_back(v);
    }
  return values;
}

TEST(OpenFoamForceCoeffs, WritesOpenFoamsOwnFileAgainByteForByte) {
  const std::string theirs = file_text(kOpenFoamFile);
  const auto row = openfoam_row(theirs);
  ASSERT_EQ(row.size(), 13u) << kOpenFoamFile;  // time and 12 columns
  ForceCoeffsInput input;
  input.rho = 998.2;
  input.mag_u_inf = 0.1;
  input.l_ref = 0.3;
  input.a_ref = 0.01767145867644259;
  input.precision = 10;  // the case's writePrecision
  input.time = {row[0]};
  // OpenFOAM forms Cd(f) ... from its unrounded coefficients. Its Cs (printed 8.1263458211e-01) lies in
  // [0.812634582105, 0.812634582106) for its Cs(f) and Cs(r) to round as printed: one value of that range.
  std::vector<double> coefficients(row.begin() + 1, row.begin() + 7);
  ASSERT_EQ(coefficients[1], 0.81263458211);
  coefficients[1] = 0.8126345821055;
  const double q = 0.5 * input.rho * input.mag_u_inf * input.mag_u_inf;
  for (std::size_t k = 0; k < 6; ++k) input.load[k] = {coefficients[k] * q * input.a_ref * (k < 3 ? 1.0 : input.l_ref)};
  const auto written = openfoam_forcecoeffs(input);
  EXPECT_EQ(written.text, theirs);
  EXPECT_EQ(written.values, 6u);
  EXPECT_EQ(written.exact + written.one_ulp, 0u);  // counted at precision 16 only
  EXPECT_DOUBLE_EQ(written.coefficient[0][0], row[1]);
}

TEST(OpenFoamForceCoeffs, ReadsBackAsTheForcesToTheLastBitWhereADoubleGivesThem) {
  std::mt19937_64 random(36);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  ForceCoeffsInput input;
  input.rho = 1025.0;
  input.mag_u_inf = 1.7320508075688772;
  input.l_ref = 2.5;
  input.a_ref = 0.7853981633974483;
  input.cofr = {0.25, -0.5, 1e-3};
  const std::size_t n = 200;
  for (std::size_t i = 0; i < n; ++i) {
    input.time.push_back(0.0125 * static_cast<double>(i + 1));
    for (std::size_t k = 0; k < 6; ++k) input.load[k].push_back(unit(random) * std::pow(10.0, 3.0 * unit(random)));
  }
  const auto written = openfoam_forcecoeffs(input);
  ASSERT_EQ(written.values, 6 * n);
  EXPECT_EQ(written.exact + written.one_ulp, written.values);
  EXPECT_GT(written.exact, written.values * 8 / 10);  // most values have a coefficient that gives them back

  OpenFoamForcesOptions options;
  options.rho = input.rho;
  options.abscissa = HistoryAbscissa::Time;
  const ForceHistory history = parse_openfoam_force_file(written.text, "coefficient.dat", options);
  ASSERT_EQ(history.abscissa_values, input.time);
  ASSERT_TRUE(history.frame.moment_centre);
  EXPECT_EQ(*history.frame.moment_centre, input.cofr);
  ASSERT_TRUE(history.frame.axes_in_global);
  const std::array<std::array<double, 3>, 3> identity{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  EXPECT_EQ(*history.frame.axes_in_global, identity);
  std::size_t exact = 0, next = 0;
  for (std::size_t k = 0; k < 6; ++k) {
    const auto& series = history.series[0][k];
    ASSERT_EQ(series.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      const double v = input.load[k][i];
      if (series[i] == v) {
        ++exact;
      } else {
        EXPECT_TRUE(series[i] == std::nextafter(v, 2 * v) || series[i] == std::nextafter(v, -2 * v))
            << "component " << k << " row " << i << ": " << series[i] << " for " << v;
        ++next;
      }
    }
  }
  EXPECT_EQ(exact, written.exact);
  EXPECT_EQ(next, written.one_ulp);
}

TEST(OpenFoamForceCoeffs, InverseOfProductFindsACoefficientWheneverOneExists) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(1.0, 2.0);
  std::size_t exact = 0, none = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double value = unit(random) * std::pow(2.0, trial % 40 - 20);
    const double scale = unit(random) * 48.7;
    bool found = false;
    const double c = inverse_of_product(value, scale, found);
    // Every double within 8 ulps of value / scale.
    bool exists = false;
    double probe = value / scale;
    for (int i = 0; i < 8; ++i) probe = std::nextafter(probe, 0.0);
    for (int i = 0; i < 17 && !exists; ++i, probe = std::nextafter(probe, 1e300)) exists = probe * scale == value;
    ASSERT_EQ(found, exists) << value << " / " << scale;
    if (found) {
      ASSERT_EQ(c * scale, value);
      ++exact;
    } else {
      const double product = c * scale;
      ASSERT_TRUE(product == std::nextafter(value, 0.0) || product == std::nextafter(value, 1e300));
      ++none;
    }
  }
  EXPECT_GT(exact, 0u);
  EXPECT_GT(none, 0u);  // the product does skip doubles: exactness cannot always be had
}

TEST(OpenFoamForceCoeffs, TimesAreNamedAsTheyReadBack) {
  EXPECT_EQ(openfoam_time_name(199.0), "199");
  EXPECT_EQ(openfoam_time_name(0.0125), "0.0125");
  EXPECT_EQ(openfoam_time_name(-0.0), "0");
  EXPECT_EQ(openfoam_time_name(0.1 + 0.2), "0.30000000000000004");
}

TEST(OpenFoamForceCoeffs, RefusesWhatAReaderWouldMisread) {
  ForceCoeffsInput good;
  good.rho = 998.2;
  good.mag_u_inf = 0.1;
  good.l_ref = 0.3;
  good.a_ref = 0.07;
  good.time = {1.0, 2.0};
  for (auto& column : good.load) column = {1.0, 2.0};
  EXPECT_NO_THROW(openfoam_forcecoeffs(good));
  auto bad = good;
  bad.a_ref = 0.0;
  test::expect_input_error([&] { openfoam_forcecoeffs(bad); }, {"Aref", "positive"});
  bad = good;
  bad.rho = std::numeric_limits<double>::quiet_NaN();
  test::expect_input_error([&] { openfoam_forcecoeffs(bad); }, {"rho"});
  bad = good;
  bad.time = {2.0, 2.0};
  test::expect_input_error([&] { openfoam_forcecoeffs(bad); }, {"time 2 is not after 2", "increasing"});
  bad = good;
  bad.load[4] = {1.0};
  test::expect_input_error([&] { openfoam_forcecoeffs(bad); }, {"1 values", "2 times"});
  bad = good;
  bad.load[2][1] = std::numeric_limits<double>::infinity();
  test::expect_input_error([&] { openfoam_forcecoeffs(bad); }, {"not finite"});
  bad = good;
  bad.precision = 17;
  test::expect_input_error([&] { openfoam_forcecoeffs(bad); }, {"--precision 17", "1 to 16"});
  for (const std::string line : {"magUInf : 5", "two\nlines", "bell\a"}) {
    bad = good;
    bad.comments = {line};
    test::expect_input_error([&] { openfoam_forcecoeffs(bad); }, {"comment"});
  }
}

}  // namespace
}  // namespace hydrocoef
