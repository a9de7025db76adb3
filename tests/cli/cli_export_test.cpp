// hydrocoef export end to end: the ASR-V surge table imported, a surface
// built, exported in every format; the compiled C header and the JSON agree
// with `hydrocoef query`; bad requests exit 2 with one clear line and write
// nothing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::shell_quote;
using test::TempDir;

const std::string kSurge = HYDROCOEF_SOURCE_DIR "/examples/asr-v/asr-v-surge-damping.csv";

// A database with the ASR-V surge runs and a pchip surface "surge" over u.
void make_database(const TempDir& dir) {
  auto imported = run_cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing", "--rho", "998.2"}, dir.path());
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  auto built = run_cli({"surface", "build", "surge", "--body", "asr-v", "--outputs", "X", "--axes", "u", "--method",
                        "pchip", "--extrapolate", "linear"},
                       dir.path());
  ASSERT_EQ(built.exit_code, 0) << built.err;
}

double query(const TempDir& dir, double u) {
  const auto result = run_cli({"query", "surge", "u=" + std::to_string(u), "--json"}, dir.path());
  EXPECT_EQ(result.exit_code, 0) << result.err;
  return nlohmann::json::parse(result.out).at("values").at("X").get<double>();
}

TEST(CliExport, CHeaderCompiledEvaluatesWhatQueryAnswers) {
  TempDir dir;
  make_database(dir);
  const auto exported =
      run_cli({"export", "surge", "--format", "c", "-o", "surge.h", "--identifier", "surge"}, dir.path());
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  EXPECT_NE(exported.out.find("wrote surge.h"), std::string::npos) << exported.out;
  if (!std::filesystem::exists(HYDROCOEF_C_COMPILER)) GTEST_SKIP() << "no C compiler at " << HYDROCOEF_C_COMPILER;
  const std::vector<double> points = {-0.05, 0.0, 0.013, 0.1, 0.123, 0.25, 0.38, 0.45};
  std::string driver = "#include <stdio.h>\n#include \"surge.h\"\nint main(void)\n{\n  static const double u[] = {";
  for (double u : points) driver += std::to_string(u) + ",";
  driver +=
      "};\n  unsigned i;\n  for (i = 0; i < sizeof u / sizeof u[0]; ++i) {\n    double x[1];\n    double out[1];\n"
      "    x[0] = u[i];\n    if (surge_eval(x, out) != 0) return 1;\n    printf(\"%a\\n\", out[0]);\n  }\n"
      "  return 0;\n}\n";
  {
    std::FILE* file = std::fopen((dir / "main.c").c_str(), "w");
    ASSERT_NE(file, nullptr);
    std::fputs(driver.c_str(), file);
    std::fclose(file);
  }
  const std::string compile = shell_quote(HYDROCOEF_C_COMPILER) + " -std=c99 -Wall -Wextra -Werror -pedantic -I" +
                              shell_quote(dir.path().string()) + " " + shell_quote((dir / "main.c").string()) + " -o " +
                              shell_quote((dir / "main").string()) + " 2>" + shell_quote((dir / "cc.log").string());
  ASSERT_EQ(std::system(compile.c_str()), 0) << test::read_text(dir / "cc.log");
  const std::string run = shell_quote((dir / "main").string()) + " >" + shell_quote((dir / "main.out").string());
  ASSERT_EQ(std::system(run.c_str()), 0);
  std::istringstream lines(test::read_text(dir / "main.out"));
  for (double u : points) {
    std::string line;
    ASSERT_TRUE(std::getline(lines, line));
    const double from_header = std::strtod(line.c_str(), nullptr);
    const double from_query = query(dir, u);
    EXPECT_NEAR(from_header, from_query, 1e-12 * std::max(1.0, std::abs(from_query))) << "u = " << u;
  }
}

TEST(CliExport, EveryTableFormatWritesItsFilesAndJsonReportsThem) {
  TempDir dir;
  make_database(dir);
  for (const auto& [format, file] : std::vector<std::pair<std::string, std::string>>{
           {"csv", "s.csv"}, {"json", "s.json"}, {"c", "s.h"}, {"vtk", "s.vtr"}}) {
    const auto result = run_cli({"export", "surge", "--format", format, "-o", file, "--json"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << format << ": " << result.err;
    const auto out = nlohmann::json::parse(result.out);
    EXPECT_EQ(out.at("format"), format);
    EXPECT_EQ(out.at("files"), nlohmann::json({file}));
    EXPECT_EQ(out.at("axes")[0].at("unit"), "m/s");
    EXPECT_EQ(out.at("outputs")[0].at("unit"), "N");
    EXPECT_EQ(out.at("runs").size(), 20u);
    EXPECT_EQ(out.at("content_sha256").get<std::string>().size(), 64u);
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
  }
  // The JSON's node values are what query answers at the nodes.
  const auto document = nlohmann::json::parse(test::read_text(dir / "s.json"));
  const auto u = document.at("axes")[0].at("breakpoints").get<std::vector<double>>();
  const auto x = document.at("values").at("X").get<std::vector<double>>();
  ASSERT_EQ(u.size(), x.size());
  for (std::size_t i = 0; i < u.size(); i += 5) EXPECT_EQ(x[i], query(dir, u[i])) << "u = " << u[i];
  EXPECT_EQ(document.at("provenance").at("body"), "asr-v");
}

TEST(CliExport, ATableThatRefusesZeroVelocitySaysSoAtExport) {
  TempDir dir;
  make_database(dir);
  // The surge runs above 0.05 m/s only, with the default policy (error).
  ASSERT_EQ(run_cli({"surface", "build", "fast", "--body", "asr-v", "--outputs", "X", "--axes", "u", "--method",
                     "linear", "--where", "u>=0.05"},
                    dir.path())
                .exit_code,
            0);
  const auto fast = run_cli({"export", "fast", "--format", "csv", "-o", "f.csv"}, dir.path());
  ASSERT_EQ(fast.exit_code, 0) << fast.err;
  EXPECT_NE(fast.out.find("note: axis u covers ["), std::string::npos) << fast.out;
  EXPECT_NE(fast.out.find("a query at u = 0 (at rest) fails"), std::string::npos) << fast.out;
  const auto json =
      nlohmann::json::parse(run_cli({"export", "fast", "--format", "csv", "-o", "f.csv", "--json"}, dir.path()).out);
  EXPECT_EQ(json.at("notes").size(), 1u);
  // A table whose range holds zero, or that continues past its ends, has no such note.
  const auto whole = run_cli({"export", "surge", "--format", "csv", "-o", "s.csv"}, dir.path());
  EXPECT_EQ(whole.out.find("at rest"), std::string::npos) << whole.out;
}

TEST(CliExport, BadRequestsExitTwoWithOneLineAndWriteNothing) {
  TempDir dir;
  make_database(dir);
  struct Case {
    std::vector<std::string> args;
    std::string expected;
  };
  std::ofstream(dir / "notes.txt") << "a file, not a folder\n";
  const std::vector<Case> cases = {
      {{"export", "nosuch", "--format", "csv", "-o", "out.csv"}, "no surface named 'nosuch'"},
      {{"export", "surge", "--format", "csv-wide", "-o", "out.csv"}, "expected a 2-D table"},
      {{"export", "surge", "--format", "jsbsim", "-o", "out.xml"}, "JSBSim tables interpolate linearly"},
      {{"export", "surge", "--format", "mat", "-o", "out.mat"}, "n-D Lookup Table block"},
      {{"export", "surge", "--format", "json", "-o", "missing/out.json"}, "'missing' does not exist"},
      {{"export", "surge", "--format", "csv", "-o", "notes.txt/out.csv"}, "'notes.txt' is not a directory"},
      {{"export", "surge", "--format", "json", "-o", "out.json", "--float"}, "--float applies to --format c only"},
      {{"export", "surge", "--format", "xlsx", "-o", "out.xlsx"}, "unknown export format 'xlsx'"},
  };
  for (const Case& c : cases) {
    const auto result = run_cli(c.args, dir.path());
    EXPECT_EQ(result.exit_code, 2) << c.args[3];
    EXPECT_NE(result.err.find(c.expected), std::string::npos) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  }
  for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
    EXPECT_TRUE(entry.path().filename() == "hydrocoef.db" || entry.path().filename() == "notes.txt")
        << "unexpected file " << entry.path();

  auto rbf = run_cli({"surface", "build", "rbf", "--body", "asr-v", "--outputs", "X", "--axes", "u", "--method", "rbf"},
                     dir.path());
  ASSERT_EQ(rbf.exit_code, 0) << rbf.err;
  const auto refused = run_cli({"export", "rbf", "--format", "csv", "-o", "rbf.csv"}, dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--resample"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "rbf.csv"));
}

TEST(CliExport, AnUnwritableDirectoryIsRefused) {
  if (::geteuid() == 0) GTEST_SKIP() << "root can write into a read-only directory";
  TempDir dir;
  make_database(dir);
  std::filesystem::create_directory(dir / "ro");
  std::filesystem::permissions(dir / "ro", std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  const auto result = run_cli({"export", "surge", "--format", "csv", "-o", "ro/out.csv"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("cannot write 'ro/out.csv'"), std::string::npos) << result.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir / "ro"));
  std::filesystem::permissions(dir / "ro", std::filesystem::perms::owner_all);
}

// The same refusal where no user, root included, can write: the output's
// directory is a regular file.
TEST(CliExport, AnOutputUnderARegularFileIsRefused) {
  TempDir dir;
  make_database(dir);
  { std::ofstream(dir / "plain") << "kept\n"; }
  const auto result = run_cli({"export", "surge", "--format", "csv", "-o", "plain/out.csv"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("cannot write 'plain/out.csv'"), std::string::npos) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  std::ifstream in(dir / "plain");
  const std::string kept((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(kept, "kept\n");
}

// make_database plus a linear surface "surge-linear", which Simulink's
// lookup table (--format mat) can reproduce.
void make_database_with_linear(const TempDir& dir) {
  make_database(dir);
  auto built = run_cli({"surface", "build", "surge-linear", "--body", "asr-v", "--outputs", "X", "--axes", "u",
                        "--method", "linear", "--extrapolate", "linear"},
                       dir.path());
  ASSERT_EQ(built.exit_code, 0) << built.err;
}

// A shell prefix that plants links at the temporary names the CLI will use
// for `file` (".FILE.tmp-PID-N", counters 0 to 198 in steps of `step`) and
// then execs the CLI, so that PID is the shell's $$.
std::string plant_links_then_exec(const std::string& file, int step) {
  return "for n in $(seq 0 " + std::to_string(step) + " 198); do ln -s victim ." + file +
         ".tmp-$$-$n || exit 9; done; exec ";
}

// Links planted at every other temporary name are skipped: the export lands
// at its target and the victim keeps its bytes. Links at every name make the
// export refuse with one line.
TEST(CliExport, LinksAtTheTemporaryNamesAreNeverWrittenThrough) {
  // The shell prefix execs the CLI itself (its PID names the temporaries), so
  // the PostgreSQL location cannot be put before it; the files are what count.
  if (test::on_postgresql()) GTEST_SKIP() << "file writes, not the database";
  TempDir dir;
  make_database_with_linear(dir);
  for (const std::string file : {"s.vtr", "s.vtk", "s.mat"}) {
    { std::ofstream(dir / "victim") << "precious\n"; }
    const std::string format = file == "s.mat" ? "mat" : "vtk";
    const std::string surface = file == "s.mat" ? "surge-linear" : "surge";
    const auto some = run_cli({"export", surface, "--format", format, "-o", file}, dir.path(), "/dev/null",
                              plant_links_then_exec(file, 2));
    EXPECT_EQ(some.exit_code, 0) << file << ": " << some.err;
    EXPECT_EQ(test::read_text(dir / "victim"), "precious\n") << file;
    EXPECT_FALSE(std::filesystem::is_symlink(dir / file));
    EXPECT_GT(std::filesystem::file_size(dir / file), 100u) << file;
    std::filesystem::remove(dir / file);
    for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
      if (entry.is_symlink()) std::filesystem::remove(entry.path());

    const auto all = run_cli({"export", surface, "--format", format, "-o", file}, dir.path(), "/dev/null",
                             plant_links_then_exec(file, 1));
    EXPECT_EQ(all.exit_code, 2) << file << ": " << all.err;
    EXPECT_NE(all.err.find("cannot write '" + file + "'"), std::string::npos) << all.err;
    EXPECT_EQ(std::count(all.err.begin(), all.err.end(), '\n'), 1) << all.err;
    EXPECT_EQ(test::read_text(dir / "victim"), "precious\n") << file;
    EXPECT_FALSE(std::filesystem::exists(dir / file)) << file;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
      if (entry.is_symlink()) std::filesystem::remove(entry.path());
  }
}

// A write that fails part-way (here a one-block file-size limit, which fails
// writes as a full disk does, with SIGXFSZ ignored) is exit 2 with one line,
// and nothing at the target: neither VTK nor libmatio may leave a truncated
// file behind.
TEST(CliExport, AFailedLibraryWriteLeavesNoTruncatedFile) {
  // The shell prefix execs the CLI itself (its PID names the temporaries), so
  // the PostgreSQL location cannot be put before it; the files are what count.
  if (test::on_postgresql()) GTEST_SKIP() << "file writes, not the database";
  TempDir dir;
  make_database_with_linear(dir);
  for (const std::string file : {"s.vtr", "s.vtk", "s.mat"}) {
    const std::string format = file == "s.mat" ? "mat" : "vtk";
    const std::string surface = file == "s.mat" ? "surge-linear" : "surge";
    const auto full = run_cli({"export", surface, "--format", format, "-o", file}, dir.path(), "/dev/null",
                              "trap '' XFSZ; ulimit -f 1; exec ");
    EXPECT_EQ(full.exit_code, 2) << file << ": " << full.err;
    EXPECT_NE(full.err.find("cannot write '" + file + "'"), std::string::npos) << full.err;
    EXPECT_EQ(std::count(full.err.begin(), full.err.end(), '\n'), 1) << full.err;
    EXPECT_FALSE(std::filesystem::exists(dir / file)) << file;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
      EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
    // The same export without the limit is larger than the limit.
    const auto whole = run_cli({"export", surface, "--format", format, "-o", file}, dir.path());
    EXPECT_EQ(whole.exit_code, 0) << whole.err;
    EXPECT_GT(std::filesystem::file_size(dir / file), 1024u) << file;  // a block is 512 or 1024 bytes
    std::filesystem::remove(dir / file);
  }
}

}  // namespace
}  // namespace hydrocoef
