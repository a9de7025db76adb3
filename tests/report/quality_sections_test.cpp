// The report's quality at a glance, through the CLI on a database of runs of
// every convergence kind (a converged OpenFOAM case, a steady case averaged
// over its window, a transient CSV history, one with a given window), a mesh
// study, a forced-oscillation run and a GP and a grid surface: each averaged
// run is in the quality table with its kind and the reason stored with it and
// has its history figure (a non-empty SVG beside the page, embedded and
// named by its id); each surface has its calibration and a sigma map; the
// mesh study's rows and the forced-oscillation fit are there. A hostile body
// name, and a case folder whose name holds a line break, come out escaped in
// the HTML and in the gnuplot scripts, and no command they hold runs.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "src/report/report.hpp"
#include "tests/support/hostile_names.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef::report {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::read_text;
using test::run_cli;
using test::TempDir;

const fs::path kSource = HYDROCOEF_SOURCE_DIR;
const std::string kHostileBody = "<script>alert(\"x\")</script> 'q' `touch PWNED` @m $(touch PWNED) ]]>";
const std::string kHostileFolder = "case\n<b>\"q\"`touch PWNED`";

/// A transient force history: a start-up transient, then X and Y about
/// 2 and -0.5 N with two incommensurate oscillations.
void write_history(const fs::path& path, double phase) {
  std::ofstream out(path);
  out << std::setprecision(17) << "Time [s],X [N],Y [N]\n";
  for (int k = 0; k <= 2000; ++k) {
    const double t = 0.005 * k;
    out << t << ',' << 2.0 + 1.5 * std::exp(-t / 0.4) + 0.05 * std::sin(7.3 * t + phase) + 0.02 * std::sin(23.1 * t)
        << ',' << -0.5 + 0.03 * std::cos(11.7 * t + phase) << '\n';
  }
}

/// A forced surge oscillation of amplitude 0.05 m, period 1.6 s.
void write_pmm_history(const fs::path& path) {
  std::ofstream out(path);
  const double omega = 2.0 * std::numbers::pi / 1.6, a = 0.05;
  out << std::setprecision(17) << "Time [s],X [N]\n";
  for (int k = 0; k <= 3200; ++k) {
    const double t = 0.02 * k;
    const double x_dot = a * omega * std::cos(omega * t), x_ddot = -a * omega * omega * std::sin(omega * t);
    out << t << ',' << -5.0 * x_ddot - 1.5 * x_dot + 2.0 * std::exp(-t / 1.5) << '\n';
  }
}

/// A mesh study of one key at three levels (cells 8e6, 1e6, 125000).
void write_mesh_table(const fs::path& path) {
  std::ofstream out(path);
  out << std::setprecision(17) << "u [m s^-1],mesh,cells,X [N]\n";
  const double cells[] = {8e6, 1e6, 125000}, h[] = {0.005, 0.01, 0.02};
  for (int level = 0; level < 3; ++level)
    out << 0.2 << ',' << level + 1 << ',' << cells[level] << ',' << -0.9 + 40.0 * std::pow(h[level], 1.7) << '\n';
}

class ReportQuality : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    const fs::path& d = dir_->path();
    auto ok = [&](const std::vector<std::string>& args) {
      const auto r = run_cli(args, d);
      ASSERT_EQ(r.exit_code, 0) << args[0] << ": " << r.err;
    };
    fs::copy(kSource / "data/openfoam-sphere/quarter-cases/U0.1000", d / kHostileFolder, fs::copy_options::recursive);
    ok({"import", (d / kHostileFolder).string(), "--body", kHostileBody, "--axes=-x,y,-z", "--quiet"});
    ok({"import", (kSource / "data/openfoam-sphere/cases/u0.10_v0.00").string(), "--body", "ball", "--quiet"});
    write_history(d / "transient.csv", 0.0);
    write_history(d / "given.csv", 0.7);
    ok({"import", "transient.csv", "--body", "hull", "--set", "u=0.5", "--set", "v=0", "--quiet"});
    ok({"import", "given.csv", "--body", "hull", "--set", "u=0.6", "--set", "v=0", "--window", "4:10", "--quiet"});
    write_mesh_table(d / "mesh.csv");
    ok({"import", "mesh.csv", "--body", "mesh-hull", "--sign", "on-body", "--disturbance", "mesh", "--disturbance",
        "cells", "--quiet"});
    ok({"gci", "--body", "mesh-hull"});
    write_pmm_history(d / "surge.csv");
    ok({"pmm", "surge.csv", "--body", "hull", "--motion", "surge", "--amplitude", "0.05", "--period", "1.6"});
    ok({"import", (kSource / "examples/asr-v/asr-v-yaw-damping.csv").string(), "--body", "asr-v", "--sign", "on-body",
        "--quiet"});
    ok({"surface", "build", "yaw-gp", "--body", "asr-v", "--outputs", "N", "--axes", "r", "--method", "gp"});
    ok({"surface", "build", "yaw-grid", "--body", "asr-v", "--outputs", "N", "--axes", "r", "--method", "pchip"});
    const auto report = run_cli({"report", "-o", "report", "--json"}, d);
    ASSERT_EQ(report.exit_code, 0) << report.err;
    result_ = new json(json::parse(report.out));
    html_ = new std::string(read_text(d / "report/index.html"));
    runs_ = new json(json::parse(run_cli({"runs", "--json"}, d).out));
  }
  static void TearDownTestSuite() {
    delete dir_;
    delete result_;
    delete html_;
    delete runs_;
  }
  /// The HTML of one element: from `<tag id="ID"` to its closing tag.
  static std::string element(const std::string& tag, const std::string& id) {
    const auto begin = html_->find("<" + tag + " id=\"" + id + "\"");
    if (begin == std::string::npos) return "";
    return html_->substr(begin, html_->find("</" + tag + ">", begin) - begin);
  }
  static inline TempDir* dir_ = nullptr;
  static inline json* result_ = nullptr;
  static inline std::string* html_ = nullptr;
  static inline json* runs_ = nullptr;
};

TEST_F(ReportQuality, EachAveragedRunHasItsKindReasonFlagsAndStandardErrors) {
  std::map<std::string, int> kinds;
  std::size_t averaged = 0;
  for (const auto& run : *runs_) {
    const int id = run["id"];
    const auto show = json::parse(run_cli({"runs", "show", std::to_string(id), "--json"}, dir_->path()).out);
    if (!show.contains("convergence") || show["convergence"].is_null()) {
      EXPECT_EQ(element("tr", "quality-run-" + std::to_string(id)), "") << "a run without a history is listed";
      continue;
    }
    ++averaged;
    const std::string kind = show["convergence"];
    ++kinds[kind];
    const std::string row = element("tr", "quality-run-" + std::to_string(id));
    ASSERT_FALSE(row.empty()) << "run " << id;
    EXPECT_NE(row.find("<strong class=\"kind\">" + kind + "</strong>"), std::string::npos) << row;
    const std::string reason = show["convergence_reason"];
    ASSERT_FALSE(reason.empty()) << "run " << id;
    EXPECT_NE(row.find(html_escape(reason)), std::string::npos) << "run " << id << ": " << reason;
    // X's value ± its standard error as stored.
    const auto& x = show["forces"]["X"];
    std::ostringstream se;
    se.precision(3);
    se << x["statistics"]["standard_error"].get<double>();
    EXPECT_NE(row.find(" ± " + se.str()), std::string::npos) << row;
  }
  EXPECT_EQ(averaged, 4u);
  EXPECT_EQ(kinds, (std::map<std::string, int>{
                       {"converged", 1}, {"steady-window", 1}, {"transient-window", 1}, {"given-window", 1}}));
  // The steady case's flags are shown.
  EXPECT_NE(html_->find("<span class=\"stale\">no-steady-window"), std::string::npos);
}

TEST_F(ReportQuality, EachAveragedRunHasItsHistoryFigureWrittenAndEmbedded) {
  EXPECT_EQ((*result_)["histories"], 4);
  for (const auto& run : *runs_) {
    const int id = run["id"];
    const std::string stem = plot_file_stem("history", "run-" + std::to_string(id));
    const fs::path svg = dir_->path() / "report/plots" / (stem + ".svg");
    const bool listed = !element("tr", "quality-run-" + std::to_string(id)).empty();
    EXPECT_EQ(fs::exists(svg), listed) << svg;
    if (!listed) continue;
    EXPECT_GT(fs::file_size(svg), 1000u);
    const std::string figure = element("figure", stem);
    ASSERT_FALSE(figure.empty()) << stem;
    EXPECT_NE(figure.find("data:image/svg+xml;base64," + base64(read_text(svg)) + "\""), std::string::npos);
    EXPECT_NE(figure.find("plots/" + stem + ".dat"), std::string::npos);
    EXPECT_NE(html_->find("<a href=\"#history-run-" + std::to_string(id) + "\">"), std::string::npos);
  }
}

TEST_F(ReportQuality, SurfacesHaveTheirCalibrationAndASigmaMap) {
  EXPECT_EQ((*result_)["sigma_maps"], 2);
  for (const std::string name : {"yaw-gp", "yaw-grid"}) {
    const std::string stem = plot_file_stem("sigma", name);
    EXPECT_FALSE(element("figure", stem).empty()) << name;
    EXPECT_GT(fs::file_size(dir_->path() / "report/plots" / (stem + ".svg")), 1000u) << name;
  }
  // The GP's leave-one-out standardized residuals, as surface show --json gives them.
  const auto show = json::parse(run_cli({"surface", "show", "yaw-gp", "--json"}, dir_->path()).out);
  const double rms = show["gp"]["outputs"]["N"]["loo_rms_z"];
  std::ostringstream text;
  text.precision(3);
  text << "N: RMS " << rms << ", largest ";
  EXPECT_NE(html_->find(text.str()), std::string::npos) << text.str();
  EXPECT_NE(html_->find("stated sd² = (runs' uncertainty interpolated)² + leave-one-out RMS²"), std::string::npos);
}

TEST_F(ReportQuality, TheMeshStudyAndTheForcedOscillationFitAreThere) {
  const std::string gci = element("section", "gci");
  ASSERT_FALSE(gci.empty());
  EXPECT_EQ((*result_)["mesh_study_rows"], 1);
  std::size_t rows = 0;
  for (auto at = gci.find("<tr class=\"gci-row\">"); at != std::string::npos;
       at = gci.find("<tr class=\"gci-row\">", at + 1))
    ++rows;
  EXPECT_EQ(rows, 1u);
  EXPECT_NE(gci.find("mesh-hull u=0.2"), std::string::npos) << gci;
  EXPECT_NE(gci.find("monotonic"), std::string::npos) << gci;
  const std::string pmm = element("section", "pmm");
  EXPECT_EQ((*result_)["pmm_fits"], 1);
  EXPECT_NE(pmm.find("surge 0.05 m, T = 1.6 s"), std::string::npos) << pmm.substr(0, 2000);
  EXPECT_NE(pmm.find("force history and harmonic fit: hull, surge"), std::string::npos);
}

TEST_F(ReportQuality, HostileNamesAreEscapedInTheHtmlAndTheGnuplotScripts) {
  EXPECT_EQ(html_->find("<script>alert"), std::string::npos);
  EXPECT_NE(html_->find(html_escape(kHostileBody)), std::string::npos);
  EXPECT_EQ(html_->find("<b>\"q\""), std::string::npos);
  EXPECT_NE(html_->find("case\n&lt;b&gt;&quot;q&quot;`touch PWNED`/system/fvSolution:44"), std::string::npos);
  // The converged run's history script: the name only inside single quotes.
  bool seen = false;
  for (const auto& entry : fs::directory_iterator(dir_->path() / "report/plots")) {
    if (entry.path().extension() != ".gp") continue;
    const std::string script = read_text(entry.path());
    if (script.find("touch PWNED") == std::string::npos) continue;
    seen = true;
    EXPECT_NE(
        script.find("'run 1 (<script>alert(\"x\")</script> '.\"'\".'q'.\"'\".' `touch PWNED` @m $(touch PWNED) ]] >"),
        std::string::npos)
        << script.substr(0, 800);
  }
  EXPECT_TRUE(seen);
  EXPECT_FALSE(fs::exists(dir_->path() / "PWNED"));
  EXPECT_FALSE(fs::exists(dir_->path() / "report/plots/PWNED"));
}

TEST_F(ReportQuality, TheTextOutputIsOneLineOfPrintableTextPerItem) {
  const auto text = run_cli({"report", "-o", "again"}, dir_->path());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_TRUE(test::terminal_safe(text.out)) << text.out;
  EXPECT_NE(text.out.find("4 force histories drawn"), std::string::npos) << text.out;
}

}  // namespace
}  // namespace hydrocoef::report
