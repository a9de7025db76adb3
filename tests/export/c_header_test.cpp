// The generated C header, compiled by the machine's C compiler (C99, all
// warnings as errors, pedantic) and C++ compiler into a driver program that
// evaluates it at 10,000 points per table (in range, on breakpoints, out of
// range on one to three axes, NaN), against GridTable: to 1e-12 in double,
// 1e-5 relative in float, with the same refusals, on every method and
// out-of-range policy.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "src/export/c_header_export.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::shell_quote;
using test::TempDir;

// Reads the points file, evaluates, writes "status" or "0 y0 y1 ..." per line
// (hexadecimal floats, exact).
constexpr const char* kDriver = R"C(#include <stdio.h>
#include <stdlib.h>
#include "table.h"

int main(int argc, char** argv)
{
  FILE* in;
  FILE* out;
  char token[128];
  tbl_real x[tbl_N_AXES];
  tbl_real y[tbl_N_OUTPUTS];
  int a;
  int k;
  int status;
  if (argc != 3) return 2;
  in = fopen(argv[1], "r");
  out = fopen(argv[2], "w");
  if (!in || !out) return 3;
  for (;;) {
    for (a = 0; a < tbl_N_AXES; ++a) {
      if (fscanf(in, "%127s", token) != 1) goto done;
      x[a] = (tbl_real)strtod(token, NULL);
    }
    status = tbl_eval(x, y);
    fprintf(out, "%d", status);
    if (status == 0) {
      for (k = 0; k < tbl_N_OUTPUTS; ++k) fprintf(out, " %a", (double)y[k]);
    }
    fprintf(out, "\n");
  }
done:
  fclose(in);
  fclose(out);
  return 0;
}
)C";

enum class Language { C, Cxx };

bool compilers_present() {
  return std::filesystem::exists(HYDROCOEF_C_COMPILER) && std::filesystem::exists(HYDROCOEF_CXX_COMPILER);
}

// Compiles driver.c + table.h in `dir`; returns the executable, or "" after
// reporting the compiler's output as a test failure.
std::filesystem::path compile(const std::filesystem::path& dir, Language language, const std::string& name) {
  const std::filesystem::path exe = dir / name;
  const std::filesystem::path log = dir / (name + ".log");
  std::string command =
      language == Language::C
          ? shell_quote(HYDROCOEF_C_COMPILER) + " -std=c99 -Wall -Wextra -Werror -pedantic -O2"
          : shell_quote(HYDROCOEF_CXX_COMPILER) + " -x c++ -std=c++17 -Wall -Wextra -Werror -pedantic -O2";
  command += " -I" + shell_quote(dir.string()) + " " + shell_quote((dir / "driver.c").string()) + " -o " +
             shell_quote(exe.string()) + " >" + shell_quote(log.string()) + " 2>&1";
  if (std::system(command.c_str()) != 0) {
    ADD_FAILURE() << (language == Language::C ? "C" : "C++") << " compilation failed:\n" << test::read_text(log);
    return {};
  }
  return exe;
}

std::string hex(double value) {
  if (std::isnan(value)) return "nan";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%a", value);
  return buffer;
}

// A 3-D table with two outputs that stay well away from zero (so relative
// errors mean something), on uneven and even axes.
GridTable make_table(Interpolation method, std::array<Extrapolation, 3> policies) {
  std::vector<GridAxis> axes = {
      {"u", {-1.5, -0.9, -0.2, 0.0, 0.35, 1.1, 2.0, 2.4}, policies[0]},
      {"v", {-0.5, -0.25, 0.0, 0.25, 0.5, 0.75}, policies[1]},
      {"r", {-0.3, -0.1, 0.05, 0.1, 0.3, 0.35, 0.6}, policies[2]},
  };
  std::vector<double> values;
  for (double r : axes[2].breakpoints)
    for (double v : axes[1].breakpoints)
      for (double u : axes[0].breakpoints) {
        values.push_back(60.0 + 8.0 * u * std::abs(u) - 3.0 * v + 2.0 * std::sin(3.0 * u * v) + 5.0 * r);
        values.push_back(-40.0 + 2.0 * std::cos(u + 2.0 * r) + (u > 0.3 ? 4.0 : 0.0) + v * r * 10.0);
      }
  return GridTable(std::move(axes), {"X", "N"}, std::move(values), method);
}

std::vector<std::vector<double>> make_points(const GridTable& table, std::size_t count, bool ties, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::size_t n = table.axis_count();
  std::vector<std::vector<double>> points;
  for (std::size_t i = 0; i < count; ++i) {
    std::vector<double> point(n);
    const double kind = unit(random);
    for (std::size_t a = 0; a < n; ++a) {
      const std::vector<double>& x = table.axes()[a].breakpoints;
      const double lo = x.front();
      const double hi = x.back();
      point[a] = lo + (hi - lo) * unit(random);
      if (ties && kind < 0.05) {
        // A breakpoint, or (for nearest's tie rule) a cell's midpoint.
        const std::size_t j = static_cast<std::size_t>(unit(random) * static_cast<double>(x.size() - 1));
        point[a] = unit(random) < 0.5 ? x[j] : 0.5 * (x[j] + x[j + 1]);
      }
    }
    if (kind >= 0.7) {
      // One to three axes outside by up to 20 % of the span.
      for (std::size_t a = 0; a < n; ++a) {
        if (unit(random) < 0.5 && !(a + 1 == n && kind < 0.85)) continue;
        const std::vector<double>& x = table.axes()[a].breakpoints;
        const double span = x.back() - x.front();
        const double beyond = span * (0.001 + 0.2 * unit(random));
        point[a] = unit(random) < 0.5 ? x.front() - beyond : x.back() + beyond;
      }
    }
    if (kind > 0.998) point[static_cast<std::size_t>(unit(random) * static_cast<double>(n))] = std::nan("");
    points.push_back(std::move(point));
  }
  return points;
}

struct CResult {
  int status = 0;
  std::vector<double> values;
};

std::vector<CResult> run_driver(const std::filesystem::path& exe, const std::filesystem::path& dir,
                                const std::vector<std::vector<double>>& points) {
  const std::filesystem::path in = dir / "points.txt";
  const std::filesystem::path out = dir / "results.txt";
  {
    std::string text;
    for (const auto& point : points) {
      for (double x : point) text += hex(x) + " ";
      text += "\n";
    }
    write_file_atomically(in, text);
  }
  const std::string command =
      shell_quote(exe.string()) + " " + shell_quote(in.string()) + " " + shell_quote(out.string());
  EXPECT_EQ(std::system(command.c_str()), 0);
  std::vector<CResult> results;
  std::istringstream lines(test::read_text(out));
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream fields(line);
    CResult result;
    fields >> result.status;
    std::string token;
    while (fields >> token) result.values.push_back(std::strtod(token.c_str(), nullptr));
    results.push_back(std::move(result));
  }
  return results;
}

// Compares the driver's answers with the library's at every point. Returns
// the largest error seen (relative for float, absolute-or-relative for double).
void compare(const GridTable& table, const std::vector<std::vector<double>>& points,
             const std::vector<CResult>& results, bool single, const std::string& label) {
  ASSERT_EQ(results.size(), points.size()) << label;
  const std::size_t n_out = table.output_count();
  std::vector<double> expected(n_out);
  std::size_t refused = 0;
  std::size_t evaluated = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::string message;
    try {
      table.evaluate(points[i], expected);
    } catch (const InputError& error) {
      message = error.what();
    }
    const CResult& result = results[i];
    if (!message.empty()) {
      ++refused;
      ASSERT_GT(result.status, 0) << label << ": point " << i << " refused by the library (" << message
                                  << ") but not by the header";
      const std::string axis = "axis '" + table.axes()[static_cast<std::size_t>(result.status - 1)].name + "'";
      EXPECT_NE(message.find(axis), std::string::npos)
          << label << ": point " << i << ": header refused on " << axis << ", library said: " << message;
      continue;
    }
    ++evaluated;
    ASSERT_EQ(result.status, 0) << label << ": point " << i << " evaluated by the library, refused by the header";
    ASSERT_EQ(result.values.size(), n_out) << label;
    for (std::size_t k = 0; k < n_out; ++k) {
      const double error = std::abs(result.values[k] - expected[k]);
      const double scale = single ? std::abs(expected[k]) : std::max(1.0, std::abs(expected[k]));
      worst = std::max(worst, error / scale);
      ASSERT_LE(error, (single ? 1e-5 : 1e-12) * scale)
          << label << ": point " << i << " output " << table.outputs()[k] << ": header " << result.values[k]
          << ", library " << expected[k];
    }
  }
  EXPECT_GT(evaluated, points.size() / 2) << label;
  ::testing::Test::RecordProperty(label + "_worst", std::to_string(worst));
  (void)refused;
}

void check_header(const GridTable& table, const std::string& label, bool with_cxx, bool with_float) {
  TempDir dir;
  ExportMetadata metadata = metadata_for_table(table, "test/" + label);
  write_file_atomically(dir / "driver.c", kDriver);
  const auto points_with_ties = make_points(table, 10000, true, 17);
  const auto points_plain = make_points(table, 10000, false, 23);
  CHeaderOptions options;
  options.identifier = "tbl";
  write_file_atomically(dir / "table.h", c_header_text(table, metadata, options));
  const auto c_exe = compile(dir.path(), Language::C, "driver_c");
  ASSERT_FALSE(c_exe.empty());
  compare(table, points_with_ties, run_driver(c_exe, dir.path(), points_with_ties), false, label + "_c_double");
  if (with_cxx) {
    const auto cxx_exe = compile(dir.path(), Language::Cxx, "driver_cxx");
    ASSERT_FALSE(cxx_exe.empty());
    compare(table, points_with_ties, run_driver(cxx_exe, dir.path(), points_with_ties), false, label + "_cxx_double");
  }
  if (with_float) {
    options.single_precision = true;
    write_file_atomically(dir / "table.h", c_header_text(table, metadata, options));
    const auto float_exe = compile(dir.path(), Language::C, "driver_float");
    ASSERT_FALSE(float_exe.empty());
    // Without exact breakpoints and midpoints: rounding the point to float may
    // move it across a nearest-neighbour tie.
    compare(table, points_plain, run_driver(float_exe, dir.path(), points_plain), true, label + "_c_float");
  }
}

class CHeaderMethods : public ::testing::TestWithParam<Interpolation> {};

TEST_P(CHeaderMethods, CompiledHeaderAgreesWithTheLibraryUnderEveryPolicy) {
  if (!compilers_present()) GTEST_SKIP() << "no C or C++ compiler at " << HYDROCOEF_C_COMPILER;
  const Interpolation method = GetParam();
  const std::vector<std::array<Extrapolation, 3>> policy_sets = {
      {Extrapolation::Clamp, Extrapolation::Linear, Extrapolation::Method},
      {Extrapolation::Method, Extrapolation::Error, Extrapolation::Linear},
      {Extrapolation::Linear, Extrapolation::Clamp, Extrapolation::Error},
  };
  for (std::size_t i = 0; i < policy_sets.size(); ++i) {
    SCOPED_TRACE("policy set " + std::to_string(i));
    const GridTable table = make_table(method, policy_sets[i]);
    check_header(table, std::string(interpolation_name(method)) + "_" + std::to_string(i), true, true);
  }
}

INSTANTIATE_TEST_SUITE_P(AllMethods, CHeaderMethods,
                         ::testing::Values(Interpolation::Nearest, Interpolation::Linear, Interpolation::Pchip,
                                           Interpolation::Akima, Interpolation::NaturalSpline),
                         [](const auto& param_info) {
                           std::string name(interpolation_name(param_info.param));
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

TEST(CHeader, OneAxisAndFourAxesAgreeToo) {
  if (!compilers_present()) GTEST_SKIP() << "no C or C++ compiler at " << HYDROCOEF_C_COMPILER;
  const GridTable one({{"w", {-1.0, -0.3, 0.0, 0.4, 1.0}, Extrapolation::Linear}}, {"Z"}, {30.0, 4.0, 0.0, -5.0, -31.0},
                      Interpolation::Pchip);
  check_header(one, "pchip_1d", true, false);

  std::vector<GridAxis> axes = {{"u", {0.0, 0.5, 1.0, 2.0}, Extrapolation::Method},
                                {"v", {-1.0, 0.0, 1.0}, Extrapolation::Clamp},
                                {"w", {-1.0, -0.5, 0.5, 1.0}, Extrapolation::Linear},
                                {"q", {-0.2, 0.0, 0.2}, Extrapolation::Error}};
  std::vector<double> values;
  for (double q : axes[3].breakpoints)
    for (double w : axes[2].breakpoints)
      for (double v : axes[1].breakpoints)
        for (double u : axes[0].breakpoints) values.push_back(100.0 + u * u * 3.0 - v * w + q * 10.0 + u * q);
  const GridTable four(std::move(axes), {"M"}, std::move(values), Interpolation::Akima);
  check_header(four, "makima_4d", false, true);
}

TEST(CHeader, DocumentsUnitsRangesPoliciesLayoutAndProvenance) {
  const GridTable table =
      make_table(Interpolation::Pchip, {Extrapolation::Clamp, Extrapolation::Error, Extrapolation::Linear});
  ExportMetadata metadata = metadata_for_table(table, "asr-v:uvr");
  metadata.body = "asr-v";
  metadata.run_ids = {3, 4, 9};
  const std::string header = c_header_text(table, metadata);
  for (const std::string& piece : std::vector<std::string>{
           "x[0] u [m/s]: 8 breakpoints in [-1.5, 2.4], outside: clamp", "x[1] v [m/s]", "outside: error",
           "out[1] N [N m]", "on-body", "runs [3,4,9]", metadata.content_sha256, "surface 'asr-v:uvr' of body 'asr-v'",
           "node * 2^n + S", "static inline int hc_asr_v_uvr_eval(", "#define hc_asr_v_uvr_OUT_X 0",
           "#define hc_asr_v_uvr_AXIS_R 2", "x forward, y starboard, z down"}) {
    EXPECT_NE(header.find(piece), std::string::npos) << "header lacks '" << piece << "'";
  }
}

TEST(CHeader, RefusesABadIdentifierAndValuesTooLargeForFloat) {
  const GridTable table({{"u", {0.0, 1.0}, Extrapolation::Clamp}}, {"X"}, {0.0, 1e300}, Interpolation::Linear);
  const ExportMetadata metadata = metadata_for_table(table, "big");
  CHeaderOptions options;
  options.identifier = "9lives";
  test::expect_input_error([&] { c_header_text(table, metadata, options); }, {"'9lives'", "C identifier"});
  options.identifier = "ok";
  options.single_precision = true;
  test::expect_input_error([&] { c_header_text(table, metadata, options); }, {"1e+300", "float"});
  options.single_precision = false;
  EXPECT_NE(c_header_text(table, metadata, options).find("1e+300"), std::string::npos);
}

TEST(CHeader, HostileNamesStayInsideComments) {
  const GridTable table({{"u", {0.0, 1.0}, Extrapolation::Clamp}}, {"X"}, {1.0, 2.0}, Interpolation::Linear);
  const ExportMetadata metadata = metadata_for_table(table,
                                                     "evil */ int x; /* ?"
                                                     "?/");
  const std::string header = c_header_text(table, metadata);
  EXPECT_EQ(header.find("evil */"), std::string::npos);
  EXPECT_EQ(header.find("?"
                        "?/"),
            std::string::npos);
  if (!compilers_present()) return;
  check_header(table, "hostile", false, false);  // and it compiles and agrees
}

}  // namespace
}  // namespace hydrocoef
