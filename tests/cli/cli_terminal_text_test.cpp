// Text a terminal would obey never reaches it. File names given on the
// command line and text read back from a received database (source paths,
// importer versions, timestamps, selection filters, coefficient terms) hold
// escape sequences here ("\x1b]0;pwned\x07" sets a terminal's title,
// "\x1b[2J" clears its screen); every command that prints them must print
// them through escape::one_line (errors through printable_text): no byte
// below 0x20 but the line feed, and no DEL, on standard output or standard
// error, and the text still shown (U+FFFD where a control character was).
// --json keeps the text exactly, as JSON escapes (\u001b).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "src/core/escape.hpp"
#include "tests/support/backend_under_test.hpp"
#include "tests/support/hostile_names.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::CliResult;
using test::run_cli;
using test::TempDir;

const std::string kSurge = HYDROCOEF_SOURCE_DIR "/examples/asr-v/asr-v-surge-damping.csv";
const std::string kSphereVtp = HYDROCOEF_DATA_DIR "/openfoam-sphere/full/u0.10_v0.05/u0.10_v0.05_sphere_t1000.vtp";
// A title, a screen clear, a carriage return and a backspace.
const std::string kHostile = "a\x1b]0;pwned\x07-b\x1b[2J-\r\x08z";
const std::string kReplacement = "\xEF\xBF\xBD";  // U+FFFD
// kHostile as the terminal gets it.
const std::string kShown = escape::one_line(kHostile);

std::string joined(const std::vector<std::string>& args) {
  std::string out;
  for (const auto& arg : args) out += test::shell_quote(arg) + " ";
  return out;
}

/// Runs the command and checks that nothing it printed is a control character.
CliResult run_safely(const std::vector<std::string>& args, const TempDir& dir) {
  CliResult result = run_cli(args, dir.path());
  EXPECT_TRUE(test::terminal_safe(result.out)) << joined(args) << ": a control character on stdout:\n" << result.out;
  EXPECT_TRUE(test::terminal_safe(result.err)) << joined(args) << ": a control character on stderr:\n" << result.err;
  return result;
}

/// What the SQLite file (or the PostgreSQL schema) of `dir` holds, tampered:
/// every free text the store reads back without a name rule gets kHostile.
void tamper(const TempDir& dir) {
  store::Connection db = test::connect_database(dir / "hydrocoef.db");
  db.prepare("UPDATE source_file SET path = ?, importer_version = ?, imported_at = ?")
      .bind(1, std::string_view("/cases/" + kHostile + ".csv"))
      .bind(2, std::string_view(kHostile))
      .bind(3, std::string_view(kHostile))
      .run();
  db.prepare(
        "UPDATE import SET path = ?, resolved_path = ?, importer_version = ?, hydrocoef_version = ?, imported_at = ?")
      .bind(1, std::string_view("/cases/" + kHostile + ".csv"))
      .bind(2, std::string_view(kHostile))
      .bind(3, std::string_view(kHostile))
      .bind(4, std::string_view(kHostile))
      .bind(5, std::string_view(kHostile))
      .run();
  db.prepare("UPDATE fit SET run_filter = ?, created_at = ?")
      .bind(1, std::string_view(kHostile))
      .bind(2, std::string_view(kHostile))
      .run();
  db.prepare("UPDATE fit_coefficient SET term = ? WHERE position = 0").bind(1, std::string_view(kHostile)).run();
  db.prepare("UPDATE surface SET created_at = ?").bind(1, std::string_view(kHostile)).run();
}

// A database whose runs came from a file named with escape sequences, with a
// fit and a surface, tampered as a received database could be: the text
// commands show every tampered text, made printable; --json keeps it exactly.
TEST(TerminalText, TextFromAReceivedDatabaseIsPrintable) {
  TempDir dir;
  const auto table = dir / ("surge" + kHostile + ".csv");
  std::filesystem::copy_file(kSurge, table);
  const auto imported =
      run_safely({"import", table.string(), "--body", "asr-v", "--sign", "opposing", "--rho", "998.2"}, dir);
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  EXPECT_NE(imported.out.find("surge" + kShown), std::string::npos) << imported.out;
  const auto fitted = run_safely(
      {"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u|u|", "--where", "u>=0", "--name", "surge-fit"}, dir);
  ASSERT_EQ(fitted.exit_code, 0) << fitted.err;
  const auto built = run_safely({"surface", "build", "surge", "--body", "asr-v", "--outputs", "X", "--axes", "u",
                                 "--method", "pchip", "--extrapolate", "linear"},
                                dir);
  ASSERT_EQ(built.exit_code, 0) << built.err;

  tamper(dir);
  const auto runs = nlohmann::json::parse(run_cli({"runs", "--json"}, dir.path()).out);
  ASSERT_FALSE(runs.empty());
  const std::string run_id = std::to_string(runs[0].at("id").get<std::int64_t>());
  // Each command prints the tampered text (as U+FFFD where the controls were).
  for (const std::vector<std::string>& args : {std::vector<std::string>{"runs"},
                                               {"runs", "show", run_id},
                                               {"fits"},
                                               {"surface", "list"},
                                               {"surface", "show", "surge"},
                                               {"query", "surge", "u=0.2"},
                                               {"runs", "--body", "asr-v"}}) {
    const auto result = run_safely(args, dir);
    EXPECT_EQ(result.exit_code, 0) << joined(args) << result.err;
  }
  EXPECT_NE(run_cli({"runs", "show", run_id}, dir.path()).out.find(kReplacement), std::string::npos);
  const auto fits = run_cli({"fits"}, dir.path());
  EXPECT_NE(fits.out.find("where " + kShown), std::string::npos) << fits.out;  // the filter
  EXPECT_NE(fits.out.find("\n    " + kShown), std::string::npos) << fits.out;  // the first term
  EXPECT_NE(run_cli({"surface", "show", "surge"}, dir.path()).out.find("built: " + kShown), std::string::npos);

  // JSON escapes the controls and keeps the text.
  const auto fits_json = run_safely({"fits", "--json"}, dir);
  ASSERT_EQ(fits_json.exit_code, 0) << fits_json.err;
  EXPECT_NE(fits_json.out.find("\\u001b"), std::string::npos) << fits_json.out;
  const auto listed = nlohmann::json::parse(fits_json.out);
  ASSERT_EQ(listed.size(), 1u);
  EXPECT_EQ(listed[0].at("where"), kHostile);
  EXPECT_EQ(listed[0].at("created_at"), kHostile);
  const auto shown = run_safely({"runs", "show", run_id, "--json"}, dir);
  ASSERT_EQ(shown.exit_code, 0) << shown.err;
  EXPECT_EQ(nlohmann::json::parse(shown.out).at("imports").at(0).at("importer_version"), kHostile) << shown.out;
}

// File names with escape sequences given on the command line: the lines that
// name them (written, compared, read) show them printable, and a refusal
// that quotes one does too.
TEST(TerminalText, FileNamesOnTheCommandLineArePrintable) {
  TempDir dir;
  ASSERT_EQ(
      run_cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing", "--rho", "998.2"}, dir.path()).exit_code, 0);
  ASSERT_EQ(run_cli({"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u|u|"}, dir.path()).exit_code, 0);
  ASSERT_EQ(run_cli({"surface", "build", "surge", "--body", "asr-v", "--outputs", "X", "--axes", "u", "--method",
                     "pchip", "--extrapolate", "linear"},
                    dir.path())
                .exit_code,
            0);
  const std::string csv = "table" + kHostile + ".csv";
  const auto exported = run_safely({"export", "surge", "--format", "csv", "-o", csv}, dir);
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  EXPECT_NE(exported.out.find("wrote table" + kShown), std::string::npos) << exported.out;
  EXPECT_TRUE(std::filesystem::exists(dir / csv));  // the file itself has the name asked for

  const std::string sdf = "gz" + kHostile + ".sdf";
  const auto gazebo = run_safely({"export-gazebo", "asr-v", "--flavor", "gz", "-o", sdf, "--drop-constant",
                                  "--allow-missing", "--sphere-radius", "0.15", "--rho", "998.2"},
                                 dir);
  ASSERT_EQ(gazebo.exit_code, 0) << gazebo.err;
  EXPECT_NE(gazebo.out.find("wrote gz" + kShown), std::string::npos) << gazebo.out;

  std::ofstream(dir / "points.csv") << "u\n0.1\n0.2\n";
  const std::string answers = "answers" + kHostile + ".csv";
  const auto queried = run_safely({"query", "surge", "--input", "points.csv", "--output", answers}, dir);
  ASSERT_EQ(queried.exit_code, 0) << queried.err;
  EXPECT_NE(queried.err.find("answers" + kShown), std::string::npos) << queried.err;

  const auto sphere = dir / ("sphere" + kHostile + ".vtp");
  std::filesystem::copy_file(kSphereVtp, sphere);
  const auto integrated = run_safely({"integrate", sphere.string(), "--rho", "998.2"}, dir);
  ASSERT_EQ(integrated.exit_code, 0) << integrated.err;
  EXPECT_NE(integrated.out.find("sphere" + kShown), std::string::npos) << integrated.out;
  const auto sphere_import = run_safely(
      {"import", sphere.string(), "--body", "sphere", "--rho", "998.2", "--nu", "1.004e-6", "--flow", "0.1,0.05,0"},
      dir);
  ASSERT_EQ(sphere_import.exit_code, 0) << sphere_import.err;

  // Refusals that quote what was given.
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"query", "s" + kHostile, "u=0.1"},
        {"surface", "show", "s" + kHostile},
        {"integrate", (dir / ("missing" + kHostile + ".vtp")).string()},
        {"import", (dir / ("missing" + kHostile + ".csv")).string(), "--body", "asr-v"},
        {"export", "surge", "--format", "csv", "-o", "no-such-folder" + kHostile + "/out.csv"},
        {"runs", "--where", kHostile},
        {"runs", "--bogus-option" + kHostile}}) {
    const auto refused = run_safely(args, dir);
    EXPECT_EQ(refused.exit_code, 2) << joined(args) << refused.err;
    EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << joined(args) << refused.err;
  }
  if (!test::on_postgresql()) {  // a database file named with escape sequences
    const auto named = run_safely(
        {"--db", "db" + kHostile + ".sqlite", "import", kSurge, "--body", "asr-v", "--sign", "opposing"}, dir);
    ASSERT_EQ(named.exit_code, 0) << named.err;
    EXPECT_NE(named.out.find("into db" + kShown), std::string::npos) << named.out;
    const auto none = run_safely({"--db", "db" + kHostile + ".sqlite", "fits"}, dir);
    EXPECT_EQ(none.exit_code, 0) << none.err;
    EXPECT_NE(none.out.find("no fits in db" + kShown), std::string::npos) << none.out;
  }
}

}  // namespace
}  // namespace hydrocoef
