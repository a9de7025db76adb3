// Every option the documents show exists. README.md and docs/*.md are read for command lines: each line of a
// fenced code block that runs `hydrocoef COMMAND [SUBCOMMAND] ...` (with its indented continuation lines, as
// the synopses wrap; `#` starts a comment), and each inline code span of the prose that starts with
// `hydrocoef COMMAND` or with a command's name (`surface build --mirror v`). Every `--option` and `-x` short
// option of such a line must appear in `hydrocoef COMMAND [SUBCOMMAND] --help` (or in `hydrocoef --help`:
// --db, --version), and every value a line lists for `--format` (`--format csv|json|c`) must be named in
// that option's help. In a synopsis, `| show ...` or `| pmm-runs delete ...` switches to that (sub)command.
// A made-up line shows that the check fails when a document names an option or a format that does not
// exist.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
using test::run_cli;
using test::TempDir;

// `hydrocoef PATH... --help`, each asked once per test program.
class HelpTexts {
 public:
  const std::string& of(const std::vector<std::string>& path) {
    auto found = texts_.find(path);
    if (found != texts_.end()) return found->second;
    std::vector<std::string> args = path;
    args.emplace_back("--help");
    const auto result = run_cli(args, dir_.path());
    EXPECT_EQ(result.exit_code, 0) << "hydrocoef --help of " << testing::PrintToString(path) << ": " << result.err;
    return texts_.emplace(path, result.out).first->second;
  }

  /// The names listed under "Subcommands:" in the help of `path` (the top-level commands for {}).
  std::vector<std::string> subcommands(const std::vector<std::string>& path) {
    std::vector<std::string> names;
    std::istringstream lines(of(path));
    bool inside = false;
    static const std::regex listed("^  ([a-z][a-z0-9-]*)( .*)?$");
    for (std::string line; std::getline(lines, line);) {
      std::smatch match;
      if (line == "Subcommands:" || line == "SUBCOMMANDS:")
        inside = true;
      else if (inside && std::regex_match(line, match, listed))
        names.push_back(match[1]);
      else if (inside && !line.empty() && line[0] != ' ')
        inside = false;
    }
    return names;
  }

 private:
  TempDir dir_;
  std::map<std::vector<std::string>, std::string> texts_;
};

HelpTexts& help() {
  static HelpTexts texts;
  return texts;
}

bool contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

/// A piece of a document that may show a command: where it is and its text.
struct Piece {
  std::string where;  ///< FILE:LINE
  std::string text;
  bool inline_span;  ///< from the prose (may start with a command's name), not from a code block
};

/// The text before a shell comment (a '#' at the start or after a blank).
std::string without_comment(const std::string& line) {
  for (std::size_t i = 0; i < line.size(); ++i)
    if (line[i] == '#' && (i == 0 || line[i - 1] == ' ' || line[i - 1] == '\t')) return line.substr(0, i);
  return line;
}

/// The lines of fenced code blocks (indented continuation lines joined to the line they continue) and the
/// inline code spans of the prose (a span may wrap onto the next line).
std::vector<Piece> code_pieces(const std::string& markdown, const std::string& file) {
  std::vector<Piece> pieces;
  std::istringstream lines(markdown);
  bool fenced = false;
  bool continuable = false;  // the last fenced line runs a command that the next indented line may continue
  std::string prose;         // the current paragraph, lines joined with spaces
  std::vector<std::pair<std::size_t, int>> prose_lines;  // where each of its lines starts in it, and its number
  auto line_at = [&](std::size_t offset) {
    int line = 0;
    for (const auto& [start, number] : prose_lines)
      if (start <= offset) line = number;
    return line;
  };
  auto flush_prose = [&] {
    std::size_t start = 0;
    while ((start = prose.find('`', start)) != std::string::npos) {
      std::size_t ticks = prose.find_first_not_of('`', start) - start;
      const std::string fence(ticks, '`');
      const std::size_t end = prose.find(fence, start + ticks);
      if (end == std::string::npos) break;
      pieces.push_back(
          {file + ":" + std::to_string(line_at(start)), prose.substr(start + ticks, end - start - ticks), true});
      start = end + ticks;
    }
    prose.clear();
    prose_lines.clear();
  };
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    if (line.rfind("```", 0) == 0) {
      flush_prose();
      fenced = !fenced;
      continuable = false;
      continue;
    }
    if (fenced) {
      const std::string code = without_comment(line);
      const bool indented = !code.empty() && (code[0] == ' ' || code[0] == '\t');
      if (continuable && indented && code.find("hydrocoef ") == std::string::npos) {
        pieces.back().text += " " + code;
      } else {
        pieces.push_back({file + ":" + std::to_string(number), code, false});
        continuable = code.find("hydrocoef ") != std::string::npos;
      }
      continue;
    }
    if (line.find_first_not_of(" \t") == std::string::npos) {
      flush_prose();
      continue;
    }
    if (!prose.empty()) prose += ' ';
    prose_lines.emplace_back(prose.size(), number);
    prose += line;
  }
  flush_prose();
  return pieces;
}

/// Blank-separated words, a single-quoted string kept as one word (its content never read as options).
std::vector<std::string> words_of(const std::string& text) {
  std::vector<std::string> words;
  std::string word;
  bool quoted = false;
  for (char c : text) {
    if (c == '\'') quoted = !quoted;
    if (!quoted && (c == ' ' || c == '\t')) {
      if (!word.empty()) words.push_back(word);
      word.clear();
    } else {
      word += quoted && c == '-' ? '_' : c;
    }
  }
  if (!word.empty()) words.push_back(word);
  return words;
}

/// One command as a document shows it: the (sub)command path and the words after it.
struct ShownCommand {
  std::string where;
  std::vector<std::string> path;
  std::vector<std::string> words;
};

/// The commands of a piece: each `hydrocoef COMMAND [SUBCOMMAND]` in it (after global options such as
/// --db URL), or the piece itself when it starts with a command's name (an inline span); `| NAME` switches
/// to the subcommand NAME of the current command, or to the command NAME.
std::vector<ShownCommand> commands_of(const Piece& piece) {
  const auto commands = help().subcommands({});
  std::vector<ShownCommand> shown;
  const auto words = words_of(piece.text);
  auto start_command = [&](std::size_t& i) {
    // words[i] is a command name: take a subcommand after it.
    ShownCommand command{piece.where, {words[i]}, {}};
    if (i + 1 < words.size() && contains(help().subcommands({words[i]}), words[i + 1]))
      command.path.push_back(words[++i]);
    shown.push_back(command);
  };
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string& word = words[i];
    if (word == "hydrocoef" || (i == 0 && piece.inline_span)) {
      std::size_t j = word == "hydrocoef" ? i + 1 : i;
      while (j < words.size() && (words[j] == "--db" || words[j].rfind("--db=", 0) == 0))
        j += words[j] == "--db" ? 2 : 1;
      if (j < words.size() && contains(commands, words[j])) {
        i = j;
        start_command(i);
      } else if (i == 0 && piece.inline_span) {
        return shown;  // a span that is not a command
      }
      continue;
    }
    if (shown.empty()) continue;
    if (word == "|" && i + 1 < words.size()) {
      const auto& current = shown.back().path.front();
      if (contains(help().subcommands({current}), words[i + 1])) {
        shown.push_back({piece.where, {current, words[i + 1]}, {}});
        ++i;
        continue;
      }
      if (contains(commands, words[i + 1])) {
        ++i;
        start_command(i);
        continue;
      }
    }
    shown.back().words.push_back(word);
  }
  return shown;
}

/// The options a command's words name: --long (before any '=') and -x.
std::vector<std::string> options_in(const std::vector<std::string>& words) {
  std::vector<std::string> options;
  static const std::regex long_option("(^|[\\[(|])(--[A-Za-z][A-Za-z0-9-]*)");
  static const std::regex short_option("^[\\[(|]?(-[A-Za-z])([\\])|=].*)?$");
  for (const auto& word : words) {
    for (std::sregex_iterator it(word.begin(), word.end(), long_option), end; it != end; ++it)
      options.push_back((*it)[2]);
    std::smatch match;
    if (std::regex_match(word, match, short_option)) options.push_back(match[1]);
  }
  return options;
}

/// Whether `help_text` names `option` as an option ("--body TEXT", "-o,--output", "--json ").
bool help_names_option(const std::string& help_text, const std::string& option) {
  std::size_t at = 0;
  while ((at = help_text.find(option, at)) != std::string::npos) {
    const std::size_t after = at + option.size();
    const bool starts = at == 0 || help_text[at - 1] == ' ' || help_text[at - 1] == ',' || help_text[at - 1] == '\n';
    const bool ends = after == help_text.size() || !(std::isalnum(static_cast<unsigned char>(help_text[after])) ||
                                                     help_text[after] == '-' || help_text[after] == '_');
    if (starts && ends) return true;
    at = after;
  }
  return false;
}

/// The line of `help_text` that describes `option` (from the option to the end of its line).
std::string option_help_line(const std::string& help_text, const std::string& option) {
  std::istringstream lines(help_text);
  for (std::string line; std::getline(lines, line);) {
    const auto first = line.find_first_not_of(' ');
    if (first == std::string::npos || line[first] != '-') continue;
    const auto names_end = line.find(' ', first);
    const std::string names = line.substr(first, names_end - first);
    if (help_names_option(names, option)) return line;
  }
  return "";
}

/// The values a document lists for --format ("csv|json|c", "auto"; placeholders such as FORMAT and "..."
/// are not values).
std::vector<std::string> format_values(const std::vector<std::string>& words) {
  std::vector<std::string> values;
  static const std::regex value("[a-z][a-z0-9-]*");
  for (std::size_t i = 0; i < words.size(); ++i) {
    std::string list;
    std::string word = words[i];
    word.erase(0, word.find_first_not_of("[("));
    if (word == "--format" && i + 1 < words.size())
      list = words[i + 1];
    else if (word.rfind("--format=", 0) == 0)
      list = word.substr(9);
    else
      continue;
    while (!list.empty() && (list.back() == ']' || list.back() == ')')) list.pop_back();
    std::istringstream alternatives(list);
    for (std::string alternative; std::getline(alternatives, alternative, '|');)
      if (std::regex_match(alternative, value)) values.push_back(alternative);
  }
  return values;
}

/// What a document shows that the CLI does not have, one line each ("FILE:LINE: hydrocoef import: --x").
std::vector<std::string> undocumented(const std::string& markdown, const std::string& file) {
  std::vector<std::string> problems;
  for (const auto& piece : code_pieces(markdown, file)) {
    for (const auto& command : commands_of(piece)) {
      const std::string& help_text = help().of(command.path);
      const std::string& global_help = help().of({});
      std::string name = "hydrocoef";
      for (const auto& part : command.path) name += " " + part;
      for (const auto& option : options_in(command.words))
        if (!help_names_option(help_text, option) && !help_names_option(global_help, option))
          problems.push_back(command.where + ": " + name + ": " + option + " is not an option of '" + name +
                             " --help'");
      const std::string format_line = option_help_line(help_text, "--format");
      for (const auto& value : format_values(command.words))
        if (!help_names_option(" " + format_line + " ", value))
          problems.push_back(command.where + ": " + name + ": --format " + value + " is not a format of '" + name +
                             " --help'");
    }
  }
  return problems;
}

std::string read_file(const fs::path& path) { return test::read_text(path); }

TEST(CliDocumentedOptions, AnOptionThatDoesNotExistIsFound) {
  const std::string made_up =
      "Import a table:\n\n```sh\nhydrocoef import table.csv --body hull --no-such-option 3\n```\n";
  const auto problems = undocumented(made_up, "made-up.md");
  ASSERT_EQ(problems.size(), 1u) << testing::PrintToString(problems);
  EXPECT_EQ(problems[0],
            "made-up.md:4: hydrocoef import: --no-such-option is not an option of 'hydrocoef import --help'");
}

TEST(CliDocumentedOptions, OptionsOfAllShapesAreCheckedAgainstTheirSubcommand) {
  // A wrapped synopsis, a subcommand, '|' switching to another subcommand, a short option, --opt=value,
  // a global --db before the command, an inline span without "hydrocoef", and a comment that is not read.
  const std::string made_up =
      "```\n"
      "hydrocoef surface build NAME --body B --outputs X --axes u\n"
      "                 [--resample u=0:1:5] [--no-such-build-option]\n"
      "hydrocoef surface rebuild [NAME|--stale] | list [--body B] | show NAME [--json] [--outputs X]\n"
      "hydrocoef --db 'postgresql:///team?options=-csearch_path' plot fit NAME -o fit.png -z\n"
      "hydrocoef import case --axes=-x,y,-z   # --not-read: a comment\n"
      "```\n"
      "Then `fit --by current_v --made-up` and `query --uncertainty`, `--free-standing` and `fits`.\n";
  const auto problems = undocumented(made_up, "made-up.md");
  EXPECT_EQ(problems, (std::vector<std::string>{
                          "made-up.md:2: hydrocoef surface build: --no-such-build-option is not an option of "
                          "'hydrocoef surface build --help'",
                          "made-up.md:4: hydrocoef surface show: --outputs is not an option of "
                          "'hydrocoef surface show --help'",
                          "made-up.md:5: hydrocoef plot fit: -z is not an option of 'hydrocoef plot fit --help'",
                          "made-up.md:8: hydrocoef fit: --made-up is not an option of 'hydrocoef fit --help'",
                      }));
}

TEST(CliDocumentedOptions, AFormatThatDoesNotExistIsFound) {
  const std::string made_up =
      "```\n"
      "hydrocoef import FILE [--format auto|table|openfoam-forces|...]\n"
      "hydrocoef export NAME --format csv|c|daveml -o PATH\n"
      "```\n"
      "`hydrocoef export NAME --format excel`\n";
  EXPECT_EQ(undocumented(made_up, "made-up.md"),
            (std::vector<std::string>{
                "made-up.md:2: hydrocoef import: --format openfoam-forces is not a format of 'hydrocoef import --help'",
                "made-up.md:5: hydrocoef export: --format excel is not a format of 'hydrocoef export --help'",
            }));
}

TEST(CliDocumentedOptions, EveryOptionInTheReadmeAndTheGuideExists) {
  const fs::path root = HYDROCOEF_SOURCE_DIR;
  std::vector<fs::path> documents{root / "README.md"};
  for (const auto& entry : fs::directory_iterator(root / "docs"))
    if (entry.path().extension() == ".md") documents.push_back(entry.path());
  std::sort(documents.begin() + 1, documents.end());
  ASSERT_GE(documents.size(), 2u) << "no docs/*.md";
  std::vector<std::string> problems;
  std::size_t commands = 0;
  for (const auto& document : documents) {
    const std::string text = read_file(document);
    const std::string name = fs::relative(document, root).string();
    for (const auto& piece : code_pieces(text, name)) commands += commands_of(piece).size();
    const auto found = undocumented(text, name);
    problems.insert(problems.end(), found.begin(), found.end());
  }
  EXPECT_GT(commands, 100u) << "the documents show fewer commands than expected: is the scan reading them?";
  std::string all;
  for (const auto& problem : problems) all += problem + "\n";
  EXPECT_TRUE(problems.empty()) << all;
}

}  // namespace
}  // namespace hydrocoef
