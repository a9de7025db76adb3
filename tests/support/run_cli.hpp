// Test support: runs the hydrocoef binary with arguments and captures its
// exit code, standard output and standard error. When the binary runs on
// PostgreSQL (tests/support/backend_under_test.hpp), the database file names
// given to --db, and the default hydrocoef.db of the working folder, stand for
// schemas on the test server.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/backend_under_test.hpp"

namespace hydrocoef::test {

struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'')
      out += "'\\''";
    else
      out += c;
  }
  return out + "'";
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The binary the CLI tests run: HYDROCOEF_CLI (this build's), or in the
/// PostgreSQL run the one $HYDROCOEF_TEST_POSTGRESQL_CLI names when set:
/// scripts/test.sh runs the PostgreSQL repeats of the CLI suites on the
/// optimized build's CLI (the store's PostgreSQL code itself runs under the
/// sanitizers in the store and reliability suites), as the SQLite run covers
/// the sanitizer build's.
inline std::string cli_under_test() {
  if (on_postgresql()) {
    if (const char* cli = std::getenv("HYDROCOEF_TEST_POSTGRESQL_CLI"); cli != nullptr && *cli != '\0') return cli;
  }
  return HYDROCOEF_CLI;
}

/// Runs the CLI (cli_under_test) with `args` in directory `cwd`; scratch files go in
/// `cwd`. Standard input is `stdin_path`, or empty. `shell_prefix` runs
/// before the program in the same shell (e.g. "ulimit -v 3000000 && ").
inline CliResult run_cli(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                         const std::filesystem::path& stdin_path = "/dev/null", const std::string& shell_prefix = "") {
  std::string command = "cd " + shell_quote(cwd.string()) + " && " + shell_prefix;
  std::vector<std::string> arguments = args;
  if (on_postgresql()) {
    command.append("HYDROCOEF_DB=").append(shell_quote(database_location(cwd / "hydrocoef.db"))).append(" ");
    for (std::size_t i = 0; i < arguments.size(); ++i) {
      if (arguments[i] == "--db" && i + 1 < arguments.size())
        arguments[i + 1] = database_location(cwd / arguments[i + 1]);
      else if (arguments[i].rfind("--db=", 0) == 0)
        arguments[i] = "--db=" + database_location(cwd / arguments[i].substr(5));
    }
  }
  command.append(shell_quote(cli_under_test()));
  for (const auto& arg : arguments) command.append(" ").append(shell_quote(arg));
  const auto out_path = cwd / ".cli-stdout";
  const auto err_path = cwd / ".cli-stderr";
  // Appended piece by piece: GCC 12 at -O3 warns falsely (stringop-overflow)
  // on "literal" + std::string temporaries.
  command.append(" >").append(shell_quote(out_path.string()));
  command.append(" 2>").append(shell_quote(err_path.string()));
  command.append(" <").append(shell_quote(stdin_path.string()));
  const int status = std::system(command.c_str());
  CliResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_text(out_path);
  result.err = read_text(err_path);
  std::filesystem::remove(out_path);
  std::filesystem::remove(err_path);
  return result;
}

}  // namespace hydrocoef::test
