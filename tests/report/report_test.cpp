// The HTML report: every section, the embedded plots equal to the files
// written, no external resources; and the page rendered in headless Chromium
// loads with no script errors and no broken images.
#include "src/report/report.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "src/core/error.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef::report {
namespace {

using test::read_text;
using test::run_cli;
using test::TempDir;

const std::string kExamples = std::string(HYDROCOEF_SOURCE_DIR) + "/examples/asr-v/";
const std::vector<std::string> kSections{"summary", "runs", "quality", "fits", "surfaces", "gci", "pmm", "simulations"};

std::string base64_decode(const std::string& text) {
  static const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  unsigned buffer = 0;
  int bits = 0;
  for (char c : text) {
    if (c == '=') break;
    const auto v = alphabet.find(c);
    if (v == std::string::npos) continue;
    buffer = (buffer << 6) | static_cast<unsigned>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((buffer >> bits) & 0xFF);
    }
  }
  return out;
}

/// A database like the main job's: ASR-V runs, fits, surfaces, a per-level
/// sweep of a second body, and a simulated trajectory.
class ReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto ok = [&](const std::vector<std::string>& args) {
      const auto r = run_cli(args, dir.path());
      ASSERT_EQ(r.exit_code, 0) << r.err;
    };
    ok({"import", kExamples + "asr-v-surge-damping.csv", "--body", "asr-v", "--sign", "opposing"});
    ok({"import", kExamples + "asr-v-yaw-damping.csv", "--body", "asr-v", "--sign", "on-body"});
    ok({"fit", "--body", "asr-v", "--dof", "X", "--terms", "1,u,u|u|"});
    ok({"fit", "--body", "asr-v", "--dof", "N", "--terms", "1,r,r|r|"});
    ok({"surface", "build", "asr-v-yaw", "--body", "asr-v", "--outputs", "N", "--axes", "r", "--method", "pchip"});
    std::ostringstream table;
    table << "u [m s^-1],current_v [m s^-1],X [N]\n";
    for (double c : {0.0, 0.1, 0.2})
      for (double u : {-0.2, 0.1, 0.2, 0.3})
        table << u << "," << c << "," << (0.1 + c) * u + (11 + 5 * c) * u * std::abs(u) << "\n";
    std::ofstream(dir / "sweep.csv") << table.str();
    ok({"import", "sweep.csv", "--body", "b", "--disturbance", "current_v"});
    ok({"fit", "--body", "b", "--dof", "X", "--terms", "u,u|u|", "--by", "current_v"});
    ok({"surface", "build", "b-map", "--body", "b", "--outputs", "X", "--axes", "u,current_v", "--method", "linear"});
    ok({"simulate", "--vehicle", kExamples + "vehicle.json", "--scenario", kExamples + "scenario-yaw-0.0027.json",
        "--out", (dir / "yaw.csv").string()});
  }
  TempDir dir;
};

TEST_F(ReportTest, PageHasEverySectionAndEmbedsThePlotsItWrote) {
  RunDatabase database(dir / "hydrocoef.db", RunDatabase::OpenMode::MustExist);
  ReportOptions options;
  options.trajectories.push_back(dir / "yaw.csv");
  const auto result = write_report(database, dir / "report", options);
  EXPECT_TRUE(result.notes.empty()) << result.notes.front();
  EXPECT_EQ(result.runs, database.runs().size());
  EXPECT_EQ(result.fits, 5u);  // two ASR-V fits, three levels
  EXPECT_EQ(result.surfaces, 2u);
  // Fits: asr-v X, asr-v N, b per level + its coefficient curves; surfaces: 2,
  // and their sigma maps (both state a standard deviation): 2; simulation: 1.
  // The runs come from force tables: no history figures.
  EXPECT_EQ(result.plots.size(), 9u);
  EXPECT_EQ(result.sigma_maps, 2u);
  EXPECT_EQ(result.histories, 0u);
  const std::string html = read_text(result.index);
  for (const auto& id : kSections) EXPECT_NE(html.find("<section id=\"" + id + "\">"), std::string::npos) << id;
  for (const auto& name :
       {"asr-v:X(1,u,u|u|)", "b:X(u,u|u|)[current_v=0.1]", "asr-v-yaw", "b-map", "leave-one-out (along grid lines"})
    EXPECT_NE(html.find(html_escape(name)), std::string::npos) << name;
  // Self-contained: no reference to anything outside the page.
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  EXPECT_EQ(html.find("src=\"plots/"), std::string::npos);
  // Each image is the SVG written beside it.
  const std::string prefix = "src=\"data:image/svg+xml;base64,";
  std::vector<std::string> embedded;
  for (auto at = html.find(prefix); at != std::string::npos; at = html.find(prefix, at + 1)) {
    const auto begin = at + prefix.size();
    embedded.push_back(base64_decode(html.substr(begin, html.find('"', begin) - begin)));
  }
  ASSERT_EQ(embedded.size(), result.plots.size());
  for (std::size_t i = 0; i < embedded.size(); ++i) {
    EXPECT_EQ(embedded[i], read_text(result.plots[i])) << result.plots[i];
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(result.plots[i]).replace_extension(".dat")));
  }
}

TEST_F(ReportTest, WhereKeepsTheSelectedRunsAndWhatWasBuiltFromThemAlone) {
  RunDatabase database(dir / "hydrocoef.db", RunDatabase::OpenMode::MustExist);
  ReportOptions options;
  options.body = "b";
  options.selection = parse_selection({"current_v=0.1"}, {});
  const auto result = write_report(database, dir / "subset", options);
  EXPECT_EQ(result.runs, 4u);  // the four speeds at current_v = 0.1
  EXPECT_EQ(result.fits, 1u);  // the level current_v = 0.1; the other levels and b-map use other runs
  EXPECT_EQ(result.surfaces, 0u);
  ASSERT_FALSE(result.notes.empty());
  EXPECT_NE(result.notes.front().find("2 fits and 1 surfaces built from other runs too are left out"),
            std::string::npos)
      << result.notes.front();
  const std::string html = read_text(result.index);
  EXPECT_NE(html.find(html_escape("b:X(u,u|u|)[current_v=0.1]")), std::string::npos);
  EXPECT_EQ(html.find(html_escape("b:X(u,u|u|)[current_v=0.2]")), std::string::npos);
  options.selection = parse_selection({"current_v=0.7"}, {});
  EXPECT_THROW(write_report(database, dir / "none", options), InputError);
}

TEST(Report, EmptyDatabaseOrUnknownBodyIsAnError) {
  TempDir dir;
  RunDatabase database(dir / "empty.db");
  EXPECT_THROW(write_report(database, dir / "r"), InputError);
  ReportOptions options;
  options.body = "nobody";
  try {
    write_report(database, dir / "r", options);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no body 'nobody'"), std::string::npos) << e.what();
  }
  EXPECT_EQ(base64("hydrocoef"), "aHlkcm9jb2Vm");
  EXPECT_EQ(base64("ab"), "YWI=");
  EXPECT_EQ(html_escape("<a href=\"x\">&'"), "&lt;a href=&quot;x&quot;&gt;&amp;&apos;");
}

bool have_chromium() { return std::system("command -v chromium >/dev/null 2>&1") == 0; }

/// The DOM after load, as headless Chromium dumps it.
std::string dump_dom(const std::filesystem::path& page, const std::filesystem::path& scratch) {
  const auto out = scratch / "dom.html";
  const auto err = scratch / "chromium.log";
  const std::string command =
      "timeout 180 chromium --headless --no-sandbox --disable-gpu "
      "--no-first-run "
      "--disable-extensions --user-data-dir=" +
      test::shell_quote((scratch / "profile").string()) + " --enable-logging=stderr --v=0 --dump-dom " +
      test::shell_quote("file://" + std::filesystem::absolute(page).string()) + " >" + test::shell_quote(out.string()) +
      " 2>" + test::shell_quote(err.string());
  const int status = std::system(command.c_str());
  EXPECT_EQ(status, 0) << read_text(err);
  return read_text(out);
}

TEST_F(ReportTest, RendersInHeadlessChromiumWithoutErrors) {
  if (!have_chromium()) GTEST_SKIP() << "chromium is not installed (Debian package chromium)";
  RunDatabase database(dir / "hydrocoef.db", RunDatabase::OpenMode::MustExist);
  ReportOptions options;
  options.trajectories.push_back(dir / "yaw.csv");
  const auto result = write_report(database, dir / "report", options);
  const std::string dom = dump_dom(result.index, dir.path());
  for (const auto& id : kSections) EXPECT_NE(dom.find("id=\"" + id + "\""), std::string::npos) << id;
  EXPECT_NE(dom.find("data-ready=\"yes\""), std::string::npos) << "the load handler did not run";
  EXPECT_NE(dom.find("data-images=\"" + std::to_string(result.plots.size()) + "\""), std::string::npos);
  EXPECT_NE(dom.find("data-broken-images=\"0\""), std::string::npos);
  EXPECT_EQ(dom.find("js-error\""), std::string::npos) << dom.substr(dom.find("js-errors"), 400);

  // The checks can fail: the same page with a script error and a broken image.
  std::string broken = read_text(result.index);
  broken.replace(broken.rfind("</body>"), 7,
                 "<img "
                 "src=\"data:image/svg+xml;base64,AAAA\"><script>undefined_function();</"
                 "script></body>");
  std::ofstream(dir / "report/broken.html") << broken;
  const std::string bad = dump_dom(dir / "report/broken.html", dir.path());
  EXPECT_NE(bad.find("class=\"js-error\""), std::string::npos);
  EXPECT_NE(bad.find("undefined_function"), std::string::npos);
  EXPECT_EQ(bad.find("data-broken-images=\"0\""), std::string::npos);
}

// Names that sanitize alike ("S 1", "S_1") get different plot files, and a
// 128-character non-ASCII name still fits a file name.
TEST(Report, PlotFileStemsDoNotCollideAndFit) {
  EXPECT_NE(plot_file_stem("surface", "S 1"), plot_file_stem("surface", "S_1"));
  EXPECT_EQ(plot_file_stem("surface", "S 1"), plot_file_stem("surface", "S 1"));
  std::string long_name;
  for (int i = 0; i < 128; ++i) long_name += "\xc3\xa9";  // 128 × 'é'
  std::string other = long_name;
  other.back() = '\xa8';  // ... 'è' at the end: same sanitized prefix
  const std::string stem = plot_file_stem("surface", long_name);
  EXPECT_LE(stem.size() + 4, 255u) << stem;  // with ".svg"
  EXPECT_NE(stem, plot_file_stem("surface", other));
  EXPECT_EQ(stem.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_"),
            std::string::npos)
      << stem;
}

}  // namespace
}  // namespace hydrocoef::report
