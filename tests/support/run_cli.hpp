// Test support: runs the hydrocoef binary with arguments and captures its
// exit code, standard output and standard error.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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

/// Runs HYDROCOEF_CLI with `args` in directory `cwd`; scratch files go in
/// `cwd`. Standard input is `stdin_path`, or empty. `shell_prefix` runs
/// before the program in the same shell (e.g. "ulimit -v 3000000 && ").
inline CliResult run_cli(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                         const std::filesystem::path& stdin_path = "/dev/null", const std::string& shell_prefix = "") {
  std::string command = "cd " + shell_quote(cwd.string()) + " && " + shell_prefix + shell_quote(HYDROCOEF_CLI);
  for (const auto& arg : args) command.append(" ").append(shell_quote(arg));
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
