// hydrocoef plot and hydrocoef report from the command line: files written
// where asked, sizes, JSON, help, and one-line errors with exit code 2.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "src/store/database.hpp"
#include "tests/support/backend_under_test.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::read_text;
using test::run_cli;
using test::TempDir;

const std::string kExamples = std::string(HYDROCOEF_SOURCE_DIR) + "/examples/asr-v/";

std::pair<unsigned, unsigned> png_size(const std::string& bytes) {
  if (bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) return {0, 0};
  auto be32 = [&](std::size_t at) {
    unsigned v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
    return v;
  };
  return {be32(16), be32(20)};
}

bool one_line(const std::string& text) { return !text.empty() && text.find('\n') == text.size() - 1; }

class CliPlot : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const auto& args : std::vector<std::vector<std::string>>{
             {"import", kExamples + "asr-v-surge-damping.csv", "--body", "asr-v", "--sign", "opposing"},
             {"import", kExamples + "asr-v-yaw-damping.csv", "--body", "asr-v", "--sign", "on-body"},
             {"fit", "--body", "asr-v", "--dof", "N", "--terms", "1,r,r|r|"},
             {"surface", "build", "asr-v-yaw", "--body", "asr-v", "--outputs", "N", "--axes", "r", "--method",
              "pchip"}}) {
      const auto r = run_cli(args, dir.path());
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
  }
  TempDir dir;
};

TEST_F(CliPlot, FitPngAndSvgWithJson) {
  const auto png = run_cli({"plot", "fit", "asr-v:N(1,r,r|r|)", "-o", "plots/yaw.png"}, dir.path());
  ASSERT_EQ(png.exit_code, 0) << png.err;
  EXPECT_NE(png.out.find("wrote "), std::string::npos);
  EXPECT_NE(png.out.find("plots/yaw.png"), std::string::npos) << png.out;
  EXPECT_EQ(png_size(read_text(dir / "plots/yaw.png")), (std::pair<unsigned, unsigned>{900, 600}));
  // The data file holds the law's curve: evaluate the stored coefficients here.
  const auto fits = nlohmann::json::parse(run_cli({"fits", "--json"}, dir.path()).out);
  const auto& c = fits[0]["coefficients"];
  std::istringstream data(read_text(dir / "plots/yaw.dat"));
  std::string line;
  int block = -1, checked = 0;
  while (std::getline(data, line)) {
    if (line.rfind("# block ", 0) == 0) ++block;
    if (line.empty() || line[0] == '#' || block != 1) continue;
    double r = 0, n = 0;
    std::istringstream(line) >> r >> n;
    EXPECT_NEAR(n, c["1"].get<double>() + c["r"].get<double>() * r + c["r|r|"].get<double>() * r * std::abs(r), 1e-12);
    ++checked;
  }
  EXPECT_EQ(checked, 101);

  const auto svg =
      run_cli({"plot", "fit", "asr-v:N(1,r,r|r|)", "-o", "yaw.svg", "--size", "640x400", "--json"}, dir.path());
  ASSERT_EQ(svg.exit_code, 0) << svg.err;
  const auto out = nlohmann::json::parse(svg.out);
  EXPECT_EQ(out["format"], "svg");
  EXPECT_EQ(out["width"], 640);
  EXPECT_EQ(out["series"].size(), 2u);
  EXPECT_EQ(out["series"][1]["points"], 101);
  EXPECT_NE(read_text(dir / "yaw.svg").find("width=\"640\" height=\"400\""), std::string::npos);
}

TEST_F(CliPlot, SurfaceSimulationSteadyAndReport) {
  const auto surface = run_cli({"plot", "surface", "asr-v-yaw", "--output", "N", "-o", "s.svg"}, dir.path());
  ASSERT_EQ(surface.exit_code, 0) << surface.err;
  EXPECT_NE(read_text(dir / "s.svg").find("outside the surface"), std::string::npos);

  ASSERT_EQ(run_cli({"simulate", "--vehicle", kExamples + "vehicle.json", "--scenario",
                     kExamples + "scenario-yaw-0.0027.json", "--out", "traj.csv"},
                    dir.path())
                .exit_code,
            0);
  std::ofstream(dir / "pool.csv") << "t [s],r [rad s^-1]\n1,0.05\n5,0.14\n20,0.15\n";
  const auto sim = run_cli({"plot", "simulation", "--trajectory", "traj.csv", "--experiment", "pool.csv", "--component",
                            "r", "-o", "sim.png", "--json"},
                           dir.path());
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  EXPECT_EQ(nlohmann::json::parse(sim.out)["series"][1]["points"], 3);
  EXPECT_EQ(png_size(read_text(dir / "sim.png")).first, 900u);

  const auto steady = run_cli({"plot", "steady", "--vehicle", kExamples + "vehicle.json", "--dof", "N", "--tau-from",
                               "0.001", "--tau-to", "0.006", "--count", "6", "-o", "steady.svg"},
                              dir.path());
  ASSERT_EQ(steady.exit_code, 0) << steady.err;
  EXPECT_NE(read_text(dir / "steady.dat").find("\n0.001 0.0"), std::string::npos) << read_text(dir / "steady.dat");

  const auto report = run_cli({"report", "-o", "rep", "--trajectory", "traj.csv"}, dir.path());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  EXPECT_NE(report.out.find("index.html"), std::string::npos);
  EXPECT_NE(read_text(dir / "rep/index.html").find("<section id=\"simulations\">"), std::string::npos);
}

TEST_F(CliPlot, BadInputIsOneLineAndExitCode2) {
  const auto fit = run_cli({"plot", "fit", "asr-v:X(u)"}, dir.path());
  EXPECT_EQ(fit.exit_code, 2);
  EXPECT_TRUE(one_line(fit.err)) << fit.err;
  EXPECT_NE(fit.err.find("asr-v:N(1,r,r|r|)"), std::string::npos) << fit.err;  // names what exists

  const auto surface = run_cli({"plot", "surface", "nope", "-o", "x.png"}, dir.path());
  EXPECT_EQ(surface.exit_code, 2);
  EXPECT_TRUE(one_line(surface.err)) << surface.err;
  EXPECT_NE(surface.err.find("asr-v-yaw"), std::string::npos) << surface.err;

  const auto format = run_cli({"plot", "fit", "asr-v:N(1,r,r|r|)", "-o", "x.jpg"}, dir.path());
  EXPECT_EQ(format.exit_code, 2);
  EXPECT_NE(format.err.find(".png or .svg"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.dat"));

  const auto curves = run_cli({"plot", "curves", "asr-v:N(1,r,r|r|)"}, dir.path());
  EXPECT_EQ(curves.exit_code, 2);
  EXPECT_TRUE(one_line(curves.err)) << curves.err;

  { RunDatabase empty(test::database_location(dir / "empty.db")); }
  const auto empty = run_cli({"--db", "empty.db", "plot", "fit", "x"}, dir.path());
  EXPECT_EQ(empty.exit_code, 2);
  EXPECT_NE(empty.err.find("has no runs"), std::string::npos) << empty.err;
  const auto empty_report = run_cli({"--db", "empty.db", "report", "-o", "r"}, dir.path());
  EXPECT_EQ(empty_report.exit_code, 2);
  EXPECT_TRUE(one_line(empty_report.err)) << empty_report.err;

  for (const auto& sub : {"fit", "curves", "surface", "simulation", "steady"})
    EXPECT_EQ(run_cli({"plot", sub, "--help"}, dir.path()).exit_code, 0) << sub;
  EXPECT_EQ(run_cli({"report", "--help"}, dir.path()).exit_code, 0);
}

}  // namespace
}  // namespace hydrocoef
