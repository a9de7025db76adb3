// The whole chain through the library alone, as another C++ program or the
// Python module drives it (no CLI): the ASR-V tables imported
// (src/pipeline/import_files), the surge damping law fitted and made again
// (src/pipeline/fit_stored_runs), a surface built and rebuilt
// (src/pipeline/surface_build) and a batch of points answered from a CSV
// (src/surface/batch_query).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "src/core/error.hpp"
#include "src/pipeline/fit_stored_runs.hpp"
#include "src/pipeline/import_files.hpp"
#include "src/pipeline/surface_build.hpp"
#include "src/surface/batch_query.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
using test::expect_input_error;
const fs::path kExample = fs::path(HYDROCOEF_SOURCE_DIR) / "examples" / "asr-v";

/// The rows of a two-column table of the example: (velocity, force as printed).
std::vector<std::pair<double, double>> table_rows(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::vector<std::pair<double, double>> rows;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || !std::isdigit(static_cast<unsigned char>(line[0]))) continue;
    const auto comma = line.find(',');
    rows.emplace_back(std::stod(line.substr(0, comma)), std::stod(line.substr(comma + 1)));
  }
  return rows;
}

ImportRequest request_for(const fs::path& file, const std::string& sign) {
  ImportRequest request;
  request.inputs = {file};
  request.command_line = settings_from_json({{"body", "asr-v"}, {"sign", sign}, {"rho", 998.2}},
                                            SettingOrigin{SettingSource::CommandLine, "command line"});
  request.jobs = 2;
  return request;
}

TEST(LibraryPipeline, ImportFitSurfaceRebuildAndBatchWithoutTheCli) {
  test::TempDir dir;
  RunDatabase database(dir / "asr-v.db");
  const auto surge_file = kExample / "asr-v-surge-damping.csv";
  const auto imported = import_into(database, request_for(surge_file, "opposing"), ImportPolicy{});
  const auto rows = table_rows(surge_file);
  ASSERT_GT(rows.size(), 5u);
  EXPECT_EQ(imported.runs, rows.size());
  EXPECT_EQ(imported.runs_created, rows.size());
  // The same bytes with the same settings again: nothing added.
  const auto again = import_into(database, request_for(surge_file, "opposing"), ImportPolicy{});
  EXPECT_EQ(again.already_imported, 1u);
  EXPECT_EQ(again.runs_created, 0u);

  // The law X = c0 + c1 u + c2 u|u| by least squares over the table: the same
  // coefficients as the normal equations solved here independently.
  FitRequest request;
  request.body = "asr-v";
  request.dof = "X";
  request.terms = "1,u,u|u|";
  const FitResult fit = fit_stored_runs(database, request);
  ASSERT_TRUE(fit.fit_id);
  EXPECT_EQ(fit.setup.samples.sign, SignConvention::OpposingMotion);
  double s[3][3] = {}, b[3] = {};
  for (const auto& [u, x] : rows) {
    const double t[3] = {1.0, u, u * std::abs(u)};
    for (int i = 0; i < 3; ++i) {
      b[i] += t[i] * x;
      for (int j = 0; j < 3; ++j) s[i][j] += t[i] * t[j];
    }
  }
  // Cramer's rule on the 3x3 normal equations.
  const auto det = [](double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const double d = det(s);
  for (int k = 0; k < 3; ++k) {
    double m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = j == k ? b[i] : s[i][j];
    EXPECT_NEAR(fit.fit.coefficients[static_cast<std::size_t>(k)], det(m) / d, 1e-8 * (1.0 + std::abs(det(m) / d)))
        << k;
  }
  EXPECT_EQ(fit.setup.coefficient_units[2], "N/(m/s)^2");
  expect_input_error([&] { fit_stored_runs(database, request); }, {"exists"});

  // A PCHIP surface through the runs: forces on the body, so minus the table.
  SurfaceBuildSpec spec;
  spec.surface.axes = {"u"};
  spec.surface.outputs = {"X"};
  spec.surface.method = "pchip";
  spec.surface.out_of_range = {"error"};
  const auto built = build_and_store_surface(database, "surge", "asr-v", spec);
  EXPECT_EQ(built.stored.record.run_ids.size(), rows.size());
  std::vector<double> out(1);
  for (const auto& [u, x] : rows) {
    built.stored.surface.evaluate(std::vector<double>{u}, out);
    EXPECT_NEAR(out[0], -x, 1e-12) << u;
  }

  // A batch of points from a CSV (columns in any order, blank lines skipped).
  const auto points = dir / "points.csv";
  std::ofstream(points) << "u\n" << rows[1].first << "\n\n" << rows[3].first << "\n";
  const auto answers = dir / "answers.csv";
  EXPECT_EQ(query_csv_batch(built.stored.surface, CsvBatchRequest{"surge", points.string(), answers.string(), true}),
            2u);
  std::ifstream in(answers);
  std::string header, first;
  std::getline(in, header);
  std::getline(in, first);
  EXPECT_EQ(header, "u,X,dX/du");
  EXPECT_NEAR(std::stod(first.substr(first.find(',') + 1)), -rows[1].second, 1e-12);
  // A point out of range: the surface's message with the line, and no file.
  std::ofstream(points) << "u\n" << rows.back().first + 1.0 << "\n";
  fs::remove(answers);
  expect_input_error(
      [&] {
        query_csv_batch(built.stored.surface, CsvBatchRequest{"surge", points.string(), answers.string(), false});
      },
      {"points.csv:2", "outside"});
  EXPECT_FALSE(fs::exists(answers));

  // A run changes: the fit and the surface go stale; both are made again.
  std::ofstream(dir / "changed.csv") << "u [m s^-1],X [N]\n" << rows[2].first << ",0.5\n";
  ImportPolicy replace;
  replace.components = ConflictPolicy::Replace;
  import_into(database, request_for(dir / "changed.csv", "opposing"), replace);
  const auto refit = refit_stored_fits(database, std::nullopt, std::nullopt);
  ASSERT_EQ(refit.made.size(), 1u);
  EXPECT_NE(refit.made[0].coefficients[0].value, refit.previous[0].coefficients[0].value);
  const auto stale = surfaces_to_rebuild(database, std::nullopt, std::nullopt, true);
  ASSERT_EQ(stale.size(), 1u);
  const auto rebuilt = rebuild_surface(database, stale[0]);
  rebuilt.stored.surface.evaluate(std::vector<double>{rows[2].first}, out);
  EXPECT_EQ(out[0], -0.5);
  EXPECT_FALSE(rebuilt.stored.record.stale);
}

}  // namespace
}  // namespace hydrocoef
