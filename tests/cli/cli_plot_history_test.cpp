// hydrocoef plot history RUN from the command line: the image, its values and
// script written (by default history-run-ID.png, one panel of 260 px per
// averaged component), the text output naming them, --json naming them, the
// help; an unknown run and a run without a history refused with one line and
// exit code 2, writing nothing; a hostile body name printed as one line of
// printable text and kept inside gnuplot's single quotes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>

#include "tests/support/hostile_names.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::read_text;
using test::run_cli;
using test::TempDir;

const std::string kHostileBody = "<b>\"hull\"</b> 'q' `touch PWNED` @m $(touch PWNED)";

bool one_line(const std::string& text) { return !text.empty() && text.find('\n') == text.size() - 1; }

std::pair<unsigned, unsigned> png_size(const std::string& bytes) {
  if (bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) return {0, 0};
  auto be32 = [&](std::size_t at) {
    unsigned v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
    return v;
  };
  return {be32(16), be32(20)};
}

class CliPlotHistory : public ::testing::Test {
 protected:
  void SetUp() override {
    // Run 1: a transient history of X and Y; run 2: a force table (no history).
    std::ofstream history(dir / "transient.csv");
    history << std::setprecision(17) << "Time [s],X [N],Y [N]\n";
    for (int k = 0; k <= 1000; ++k) {
      const double t = 0.01 * k;
      history << t << ',' << 2.0 + std::exp(-t) + 0.05 * std::sin(7.3 * t) << ',' << 0.1 * std::cos(5.1 * t) << '\n';
    }
    history.close();
    std::ofstream(dir / "table.csv") << "u [m s^-1],X [N]\n0.3,1.5\n";
    for (const auto& args : std::vector<std::vector<std::string>>{
             {"import", "transient.csv", "--body", kHostileBody, "--set", "u=0.5", "--set", "v=0", "--quiet"},
             {"import", "table.csv", "--body", "table", "--quiet"}}) {
      const auto r = run_cli(args, dir.path());
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
  }
  TempDir dir;
};

TEST_F(CliPlotHistory, WritesTheImageAndSaysWhatWasWritten) {
  const auto text = run_cli({"plot", "history", "1"}, dir.path());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  const fs::path image = dir / "history-run-1.png";
  ASSERT_TRUE(fs::exists(image));
  // Two averaged components: two panels of 260 px, and 200 px for the titles and legends.
  EXPECT_EQ(png_size(read_text(image)), (std::pair<unsigned, unsigned>{900, 720}));
  EXPECT_TRUE(fs::exists(dir / "history-run-1.dat"));
  EXPECT_TRUE(fs::exists(dir / "history-run-1.gp"));
  EXPECT_NE(text.out.find("transient-window: the history in brief, the window and the stored value"), std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("wrote " + (dir / "history-run-1.png").string() + " (png, 900x720 px)"), std::string::npos)
      << text.out;
  EXPECT_TRUE(test::terminal_safe(text.out)) << text.out;
  EXPECT_EQ(std::count(text.out.begin(), text.out.end(), '\n'), 3) << text.out;
  // The body name only inside gnuplot's single quotes; no command ran.
  const std::string script = read_text(dir / "history-run-1.gp");
  EXPECT_NE(script.find("'run 1 (<b>\"hull\"</b> '.\"'\".'q'.\"'\".' `touch PWNED` @m $(touch PWNED) u=0.5)"),
            std::string::npos)
      << script.substr(0, 600);
  EXPECT_FALSE(fs::exists(dir / "PWNED"));
}

TEST_F(CliPlotHistory, JsonNamesTheFilesAndSizeAndOutputAreHonoured) {
  const auto result = run_cli({"plot", "history", "1", "-o", "sub/h.svg", "--size", "700x500", "--json"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto out = json::parse(result.out);
  EXPECT_EQ(out["image"], (dir / "sub/h.svg").string());
  EXPECT_EQ(out["data"], (dir / "sub/h.dat").string());
  EXPECT_EQ(out["script"], (dir / "sub/h.gp").string());
  EXPECT_EQ(out["format"], "svg");
  EXPECT_EQ(out["width"], 700);
  EXPECT_EQ(out["height"], 500);
  EXPECT_NE(out["title"].get<std::string>().find(kHostileBody), std::string::npos);
  ASSERT_TRUE(fs::exists(dir / "sub/h.svg"));
  EXPECT_GT(fs::file_size(dir / "sub/h.svg"), 1000u);
  std::size_t x_panels = 0;
  for (const auto& series : out["series"])
    x_panels += series["panel"].get<std::string>().rfind("X: mean over time", 0) == 0;
  EXPECT_EQ(x_panels, 6u);  // the history (its trace), the band, the value, the two spread lines, the trend
  // The history is the imported record in brief: its 1001 samples in 256 bins.
  std::size_t traces = 0;
  for (const auto& series : out["series"])
    if (series["title"].get<std::string>().rfind("history: least and largest", 0) == 0) {
      ++traces;
      EXPECT_EQ(series["points"], 256);
    }
  EXPECT_EQ(traces, 2u) << out["series"].dump();  // X and Y
}

TEST_F(CliPlotHistory, AnUnknownRunOrOneWithoutAHistoryIsOneLineAndExitCode2) {
  const auto unknown = run_cli({"plot", "history", "99"}, dir.path());
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_TRUE(one_line(unknown.err)) << unknown.err;
  EXPECT_NE(unknown.err.find("no run 99"), std::string::npos) << unknown.err;
  const auto table = run_cli({"plot", "history", "2"}, dir.path());
  EXPECT_EQ(table.exit_code, 2);
  EXPECT_TRUE(one_line(table.err)) << table.err;
  EXPECT_NE(table.err.find("run 2: no force component is a mean over a force history"), std::string::npos) << table.err;
  const auto word = run_cli({"plot", "history", "one"}, dir.path());
  EXPECT_EQ(word.exit_code, 2);
  EXPECT_TRUE(one_line(word.err)) << word.err;
  EXPECT_FALSE(fs::exists(dir / "history-run-99.png"));
  EXPECT_FALSE(fs::exists(dir / "history-run-2.png"));
  EXPECT_FALSE(fs::exists(dir / "history-run-2.dat"));
  const auto help = run_cli({"plot", "history", "--help"}, dir.path());
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--json"), std::string::npos);
  EXPECT_NE(help.out.find("--size"), std::string::npos);
}

}  // namespace
}  // namespace hydrocoef
