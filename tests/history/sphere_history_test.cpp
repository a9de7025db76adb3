// The real OpenFOAM sphere runs (data/openfoam-sphere): each case folder's
// force history, averaged over the window its case.json states, gives the
// solver-side window means and spreads case.json records (total, pressure and
// viscous force and moment), in every layout the reader takes (ESI files,
// and the Foundation forces.dat and coefficient.dat made from them). The
// automatic window is checked on what the data plainly show: u0.10_v0.00
// drifts over its last 500 iterations (its side force falls from 0.021 N to
// 0.0008 N), so it is not called converged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "importers/openfoam_forces.hpp"
#include "src/history/history_analysis.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

const fs::path kSphere = fs::path(HYDROCOEF_DATA_DIR) / "openfoam-sphere";

struct Case {
  std::string folder;  // under data/openfoam-sphere
  std::string json;    // its case.json
};

const std::vector<Case> kCases{
    {"cases/u0.10_v0.00", "full/u0.10_v0.00/case.json"},    {"cases/u0.10_v0.05", "full/u0.10_v0.05/case.json"},
    {"cases/u0.20_v0.10", "full/u0.20_v0.10/case.json"},    {"cases/u0.30_v0.00", "full/u0.30_v0.00/case.json"},
    {"quarter-cases/U0.1000", "quarter/U0.1000/case.json"}, {"quarter-cases/U0.3000", "quarter/U0.3000/case.json"},
};

nlohmann::json case_json(const Case& c) { return nlohmann::json::parse(test::read_bytes(kSphere / c.json)); }

HistoryWindow window_of(const nlohmann::json& json) {
  const auto& w = json["averaging_window_iterations"];
  return HistoryWindow::range(w[0].get<double>(), w[1].get<double>());
}

// The analysis' means and spreads against case.json's "openfoam_window_mean_*".
// `total_tolerance`: relative, for the totals' means and spreads.
void expect_case_json_window(const HistoryAnalysis& a, const nlohmann::json& json, bool with_parts,
                             double total_tolerance = 1e-12) {
  const std::vector<std::pair<ForcePart, const char*>> parts =
      with_parts ? std::vector<std::pair<ForcePart, const char*>>{{ForcePart::Total, "total"},
                                                                  {ForcePart::Pressure, "pressure"},
                                                                  {ForcePart::Viscous, "viscous"}}
                 : std::vector<std::pair<ForcePart, const char*>>{{ForcePart::Total, "total"}};
  for (const auto& [part, key] : parts)
    for (std::size_t c = 0; c < 6; ++c) {
      const auto& block = json[c < 3 ? "openfoam_window_mean_force_N" : "openfoam_window_mean_moment_Nm"][key];
      const double mean = block["mean"][c % 3];
      const double spread = block["std"][c % 3];
      const auto& stats = a.components[c].parts[static_cast<std::size_t>(part)];
      ASSERT_TRUE(stats) << key << " " << c;
      const double tolerance = part == ForcePart::Total ? total_tolerance : 1e-12;
      EXPECT_NEAR(stats->mean, mean, tolerance * (std::abs(mean) + spread)) << key << " component " << c;
      EXPECT_NEAR(stats->std_dev, spread, std::max(tolerance, 1e-9) * spread) << key << " component " << c;
    }
}

TEST(SphereHistory, WindowMeansAgreeWithCaseJson) {
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.folder);
    const auto json = case_json(c);
    const ForceHistory h = read_openfoam_forces(kSphere / c.folder / "postProcessing" / "forces");
    HistoryAnalysisOptions options;
    options.window = window_of(json);
    const HistoryAnalysis a = analyze_force_history(h, options);
    const auto& w = json["averaging_window_iterations"];
    EXPECT_EQ(a.first_abscissa, w[0].get<double>());
    EXPECT_EQ(a.last_abscissa, w[1].get<double>());
    EXPECT_EQ(a.sample_count, std::size_t(w[1].get<double>() - w[0].get<double>() + 1));
    expect_case_json_window(a, json, true);
    // Every mean comes with a standard error no smaller than the white-noise one.
    for (const ComponentAnalysis& component : a.components) {
      const SeriesStatistics& t = component.total();
      EXPECT_GE(t.standard_error, t.std_dev / std::sqrt(double(t.count)) * (1 - 1e-12));
      EXPECT_LE(t.effective_samples, double(t.count) * (1 + 1e-12));
    }
  }
}

TEST(SphereHistory, TheLastHundredIterationsAgreeWithCaseJson) {
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.folder);
    const auto json = case_json(c);
    HistoryAnalysisOptions options;
    options.window = HistoryWindow::last_samples(100);
    const HistoryAnalysis a =
        analyze_force_history(read_openfoam_forces(kSphere / c.folder / "postProcessing" / "forces"), options);
    for (std::size_t k = 0; k < 3; ++k) {
      const double mean = json["openfoam_last100_force_N"]["total"]["mean"][k];
      EXPECT_NEAR(a.components[k].total().mean, mean, 1e-12 * std::abs(mean));
    }
  }
}

// The same windows from the Foundation's forces.dat and from coefficient.dat,
// made here from the case's own rows.
std::string format17(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

TEST(SphereHistory, OtherLayoutsGiveTheSameWindowMeans) {
  const Case& c = kCases[1];
  const auto json = case_json(c);
  const ForceHistory esi = read_openfoam_forces(kSphere / c.folder / "postProcessing" / "forces");
  HistoryAnalysisOptions options;
  options.window = window_of(json);

  std::string foundation = "# Forces\n# CofR : (0 0 0)\n# Time forces(pressure viscous) moments(pressure viscous)\n";
  const double rho = 998.2, u = 0.1118, area = 0.0706858, l = 0.3, q = 0.5 * rho * u * u;
  std::string coefficients =
      "# Force coefficients\n# dragDir : (1 0 0)\n# sideDir : (0 1 0)\n# liftDir : (0 0 1)\n"
      "# magUInf : 0.1118\n# lRef : 0.3\n# Aref : 0.0706858\n# CofR : (0 0 0)\n"
      "# Time Cd Cs Cl CmRoll CmPitch CmYaw\n";
  for (std::size_t i = 0; i < esi.size(); ++i) {
    const auto v = [&](ForcePart part, std::size_t k) { return format17(esi.values(part, HistoryComponent(k))[i]); };
    foundation += format17(esi.abscissa_values[i]) + "\t((" + v(ForcePart::Pressure, 0) + " " +
                  v(ForcePart::Pressure, 1) + " " + v(ForcePart::Pressure, 2) + ") (" + v(ForcePart::Viscous, 0) + " " +
                  v(ForcePart::Viscous, 1) + " " + v(ForcePart::Viscous, 2) + ")) ((" + v(ForcePart::Pressure, 3) +
                  " " + v(ForcePart::Pressure, 4) + " " + v(ForcePart::Pressure, 5) + ") (" + v(ForcePart::Viscous, 3) +
                  " " + v(ForcePart::Viscous, 4) + " " + v(ForcePart::Viscous, 5) + "))\n";
    coefficients += format17(esi.abscissa_values[i]);
    for (std::size_t k = 0; k < 6; ++k)
      coefficients +=
          " " + format17(esi.values(ForcePart::Total, HistoryComponent(k))[i] / (k < 3 ? q * area : q * area * l));
    coefficients += "\n";
  }
  test::TempDir dir;
  fs::create_directories(dir / "forces/0");
  fs::create_directories(dir / "forceCoeffs/0");
  test::write_bytes(dir / "forces/0/forces.dat", foundation);
  test::write_bytes(dir / "forceCoeffs/0/coefficient.dat", coefficients);

  // Foundation: pressure and viscous exactly; its totals are their sums,
  // which differ from the totals the ESI files wrote (rounded to 11 digits)
  // by up to about 1e-11 of the parts.
  const HistoryAnalysis from_foundation = analyze_force_history(read_openfoam_forces(dir / "forces"), options);
  expect_case_json_window(from_foundation, json, true, 1e-10);
  OpenFoamForcesOptions read_options;
  read_options.rho = rho;
  const HistoryAnalysis from_coefficients =
      analyze_force_history(read_openfoam_forces(dir / "forceCoeffs", read_options), options);
  expect_case_json_window(from_coefficients, json, false);
}

TEST(SphereHistory, TheDriftingCaseIsNotCalledConverged) {
  const ForceHistory h = read_openfoam_forces(kSphere / "cases/u0.10_v0.00/postProcessing/forces");
  HistoryAnalysisOptions forces_only;
  forces_only.deciding_components = {true, true, true, false, false, false};
  const HistoryAnalysis a = analyze_force_history(h, forces_only);
  EXPECT_TRUE(a.flags.not_converged());
  EXPECT_TRUE(a.components[1].flags.drifting);  // Fy
  // Over case.json's own window too: the side force is still falling.
  const auto json = case_json(kCases[0]);
  HistoryAnalysisOptions given = forces_only;
  given.window = window_of(json);
  const HistoryAnalysis g = analyze_force_history(h, given);
  EXPECT_TRUE(g.components[1].flags.drifting);
  EXPECT_LT(g.components[1].total().drift, 0.0);
}

}  // namespace
}  // namespace hydrocoef
