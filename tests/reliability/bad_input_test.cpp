// The malformed-input corpus (tests/data/bad, listed in manifest.tsv) through
// `hydrocoef import`: every file must be refused with exit code 2 and one
// line on stderr naming the file, the line or array, and what was expected,
// and the database, which already holds a good import, must stay exactly as
// it was (same content, same bytes). A crash, an ASan/UBSan report or a
// second line fails the test.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_cli.hpp"
#include "tests/support/sqlite_dump.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef::test {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = fs::path(HYDROCOEF_SOURCE_DIR) / "tests" / "data" / "bad";

struct BadInput {
  std::string file;                   ///< relative to kCorpus
  std::vector<std::string> args;      ///< extra import arguments
  std::vector<std::string> expected;  ///< fragments the error line must hold
};

std::vector<std::string> split(const std::string& text, char delimiter) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, delimiter)) parts.push_back(part);
  return parts;
}

std::vector<BadInput> read_manifest() {
  std::vector<BadInput> inputs;
  std::ifstream in(kCorpus / "manifest.tsv");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto columns = split(line, '\t');
    if (columns.size() < 3) throw std::runtime_error("manifest.tsv: fewer than 3 columns in: " + line);
    BadInput input{columns[0], {}, {columns.begin() + 2, columns.end()}};
    if (columns[1] != "-") input.args = split(columns[1], ' ');
    inputs.push_back(std::move(input));
  }
  return inputs;
}

const std::vector<BadInput>& corpus() {
  static const std::vector<BadInput> inputs = read_manifest();
  return inputs;
}

/// A good surge table, imported first so that the database is not empty.
void write_good_table(const fs::path& path) {
  std::ofstream out(path);
  out << "# surge damping\nu [m s^-1],X [N],N [N "
         "m]\n0.0,0.0,0.0\n0.1,-0.2,0.01\n0.2,-0.7,0.02\n0.3,-1.5,0.03\n";
}

std::string file_bytes(const fs::path& path) { return read_text(path); }

/// What the import printed, with the corpus folder taken out of paths.
std::string shown(const std::string& err) {
  std::string out = err;
  const std::string prefix = kCorpus.string() + "/";
  for (auto at = out.find(prefix); at != std::string::npos; at = out.find(prefix)) out.erase(at, prefix.size());
  return out;
}

/// Valid UTF-8 without control characters: what a terminal or a log shows as
/// one readable line.
bool printable_line(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f) return false;
    std::size_t length = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
    if (length == 0 || i + length > text.size()) return false;
    for (std::size_t k = 1; k < length; ++k)
      if ((static_cast<unsigned char>(text[i + k]) >> 6) != 0x2) return false;
    i += length;
  }
  return true;
}

class BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputTest, IsRefusedWithOneLineAndTheDatabaseUnchanged) {
  const BadInput& input = GetParam();
  TempDir dir;
  write_good_table(dir / "good.csv");
  const auto good = run_cli({"--db", "runs.db", "import", "good.csv"}, dir.path());
  ASSERT_EQ(good.exit_code, 0) << good.err;
  const std::string dump_before = dump_database(dir / "runs.db");
  const std::string bytes_before = on_postgresql() ? "" : file_bytes(dir / "runs.db");
  // dump_database's read-only connection may leave an empty WAL beside the
  // file.
  const bool wal_before = fs::exists(dir / "runs.db-wal");
  const std::string wal_bytes_before = wal_before ? file_bytes(dir / "runs.db-wal") : "";
  ASSERT_NE(dump_before.find("good.csv"), std::string::npos);

  std::vector<std::string> args = {"--db", "runs.db", "import", (kCorpus / input.file).string()};
  args.insert(args.end(), input.args.begin(), input.args.end());
  const auto result = run_cli(args, dir.path());

  EXPECT_EQ(result.exit_code, 2) << shown(result.err);
  EXPECT_EQ(result.out, "");
  ASSERT_FALSE(result.err.empty());
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << shown(result.err);
  EXPECT_EQ(result.err.back(), '\n');
  EXPECT_EQ(result.err.rfind("hydrocoef: error: ", 0), 0u) << shown(result.err);
  // The full path of the file (or of the file at fault beside it) is named.
  EXPECT_NE(result.err.find(kCorpus.string() + "/" + input.file.substr(0, input.file.find('/'))), std::string::npos)
      << shown(result.err);
  for (const auto& fragment : input.expected)
    EXPECT_NE(shown(result.err).find(fragment), std::string::npos)
        << "expected '" << fragment << "' in: " << shown(result.err);

  // Printable: binary garbage, UTF-16, NUL bytes and stray carriage returns
  // must reach the terminal escaped, as the CFD-Post, monitor and VTK
  // importers already do.
  EXPECT_TRUE(printable_line(result.err.substr(0, result.err.size() - 1)))
      << "the error line holds raw bytes: " << ::testing::PrintToString(shown(result.err));

  if (!on_postgresql()) {  // the SQLite file and what lies beside it
    EXPECT_EQ(fs::exists(dir / "runs.db-wal"), wal_before);
    if (wal_before) {
      EXPECT_TRUE(file_bytes(dir / "runs.db-wal") == wal_bytes_before);
    }
    EXPECT_FALSE(fs::exists(dir / "runs.db-journal"));
    EXPECT_TRUE(file_bytes(dir / "runs.db") == bytes_before) << "the database file's bytes changed";
  }
  EXPECT_EQ(dump_database(dir / "runs.db"), dump_before);
}

std::string test_name(const ::testing::TestParamInfo<BadInput>& info) {
  std::string name = info.param.file;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInputTest, ::testing::ValuesIn(corpus()), test_name);

TEST(BadInputCorpus, EveryFileIsListedAndEveryImporterIsCovered) {
  std::set<std::string> listed;
  for (const auto& input : corpus()) {
    EXPECT_TRUE(fs::is_regular_file(kCorpus / input.file)) << input.file;
    EXPECT_TRUE(listed.insert(input.file.substr(0, input.file.find('/'))).second) << "listed twice: " << input.file;
    EXPECT_FALSE(input.expected.empty()) << input.file;
  }
  for (const auto& entry : fs::directory_iterator(kCorpus)) {
    const std::string name = entry.path().filename().string();
    if (name == "README.md" || name == "manifest.tsv" || name == "fuzz-regressions") continue;
    EXPECT_TRUE(listed.count(name)) << name << " is in tests/data/bad but not in manifest.tsv";
  }
  EXPECT_GE(corpus().size(), 40u);
  // Each importer has its share: force tables, CFX monitors, CFD-Post exports,
  // and the VTK family (legacy, XML, multiblock, EnSight, CGNS).
  for (const std::string prefix : {"table-", "monitor-", "cfdpost-", "vtk-", "vtp-", "vtm-", "ensight-", "cgns-"}) {
    const auto count = std::count_if(corpus().begin(), corpus().end(),
                                     [&](const BadInput& input) { return input.file.rfind(prefix, 0) == 0; });
    EXPECT_GE(count, 1) << prefix;
  }
}

// A folder import is one transaction: a bad file anywhere in it keeps the
// good files of the same call out of the database too.
TEST(BadInputCorpus, AFolderWithOneBadFileAddsNothing) {
  TempDir dir;
  write_good_table(dir / "good.csv");
  ASSERT_EQ(run_cli({"--db", "runs.db", "import", "good.csv"}, dir.path()).exit_code, 0);
  const std::string before = dump_database(dir / "runs.db");
  fs::create_directory(dir / "batch");
  for (int i = 0; i < 6; ++i) {
    std::ofstream out(dir / "batch" / ("a" + std::to_string(i) + ".csv"));
    out << "u [m s^-1],X [N]\n" << 1.0 + i << ",-3\n";
  }
  fs::copy_file(kCorpus / "table-nan.csv", dir / "batch" / "b-nan.csv");
  const auto result = run_cli({"--db", "runs.db", "import", "batch", "--jobs", "3"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("b-nan.csv:3:5"), std::string::npos) << result.err;
  EXPECT_EQ(dump_database(dir / "runs.db"), before);
}

void sql(const fs::path& db_path, const std::string& statements) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(db_path.c_str(), &db), SQLITE_OK);
  char* error = nullptr;
  EXPECT_EQ(sqlite3_exec(db, statements.c_str(), nullptr, nullptr, &error), SQLITE_OK) << (error ? error : "");
  sqlite3_free(error);
  sqlite3_close(db);
}

/// Imports a good file into a database that must be refused: exit 2, one line
/// naming the database and holding `expected`, and the file's bytes untouched
/// (no WAL switch, no migration, nothing left beside it).
void expect_refused(const TempDir& dir, const std::string& expected) {
  const std::string bytes_before = file_bytes(dir / "runs.db");
  const auto result = run_cli({"--db", "runs.db", "import", "good.csv"}, dir.path());
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_NE(result.err.find("runs.db"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
  EXPECT_TRUE(file_bytes(dir / "runs.db") == bytes_before) << "the refused database was changed";
  EXPECT_FALSE(fs::exists(dir / "runs.db-wal"));
  EXPECT_FALSE(fs::exists(dir / "runs.db-journal"));
}

TEST(DatabaseRefusals, ANewerSchemaIsRefusedAndLeftInItsJournalMode) {
  HYDROCOEF_SQLITE_FILE_ONLY("an SQLite file of a newer schema, left in its journal mode");
  TempDir dir;
  write_good_table(dir / "good.csv");
  ASSERT_EQ(run_cli({"--db", "runs.db", "import", "good.csv"}, dir.path()).exit_code, 0);
  // As a newer hydrocoef might leave it: rollback journal, higher version.
  sql(dir / "runs.db", "PRAGMA journal_mode = DELETE; PRAGMA user_version = 999;");
  expect_refused(dir, "schema version 999");
  // Bytes 18 and 19 of the header say rollback journal (1), not WAL (2).
  const std::string header = file_bytes(dir / "runs.db").substr(0, 20);
  EXPECT_EQ(header[18], 1);
  EXPECT_EQ(header[19], 1);
}

TEST(DatabaseRefusals, ADamagedPageIsRefused) {
  HYDROCOEF_SQLITE_FILE_ONLY("a damaged page of an SQLite file");
  TempDir dir;
  {
    std::ofstream big(dir / "big.csv");
    big << "u [m s^-1],X [N]\n";
    for (int i = 0; i < 600; ++i) big << 0.001 * (i + 10) << ',' << -0.5 * i << '\n';
  }
  ASSERT_EQ(run_cli({"--db", "runs.db", "import", "big.csv"}, dir.path()).exit_code, 0);
  write_good_table(dir / "good.csv");
  const auto size = fs::file_size(dir / "runs.db");
  ASSERT_GT(size, 4 * 4096u);
  {
    std::fstream file(dir / "runs.db", std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(static_cast<std::streamoff>(size / 2 / 4096 * 4096));
    for (int i = 0; i < 4096; ++i) file.put(static_cast<char>(0x5A));
  }
  expect_refused(dir, "runs.db");
}

TEST(DatabaseRefusals, AFileThatIsNotADatabaseIsRefused) {
  HYDROCOEF_SQLITE_FILE_ONLY("an SQLite file that is not a database");
  TempDir dir;
  write_good_table(dir / "good.csv");
  std::ofstream(dir / "runs.db") << "u [m s^-1],X [N]\n0.1,0.2\n";
  expect_refused(dir, "not a database");
}

}  // namespace
}  // namespace hydrocoef::test
