#include "cli/common.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "src/core/error.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef::cli {
namespace {

double parse_finite(const std::string& text, const std::string& option, const std::string& whole) {
  const auto value = parse_finite_number(text);
  if (!value) throw InputError(option + " '" + whole + "': found '" + text + "', expected a finite number");
  return *value;
}

}  // namespace

std::pair<std::string, std::string> parse_text_assignment(const std::string& text, const std::string& option) {
  const auto equals = text.find('=');
  if (equals == std::string::npos || equals == 0) throw InputError(option + " '" + text + "': expected NAME=VALUE");
  return {text.substr(0, equals), text.substr(equals + 1)};
}

std::pair<std::string, double> parse_assignment(const std::string& text, const std::string& option) {
  auto [name, value] = parse_text_assignment(text, option);
  return {name, parse_finite(value, option, text)};
}

std::array<double, 3> parse_triple(const std::string& text, const std::string& option) {
  std::array<double, 3> out{};
  std::size_t start = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto comma = text.find(',', start);
    if ((i < 2) == (comma == std::string::npos))
      throw InputError(option + " '" + text + "': expected three comma-separated numbers x,y,z");
    out[i] =
        parse_finite(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start), option, text);
    start = comma + 1;
  }
  return out;
}

void add_selection_options(CLI::App& command, SelectionArgs& args) {
  command.add_option("--where", args.where,
                     "Select runs: NAME=VALUE, NAME!=VALUE, NAME<VALUE (<=, >, >=) or NAME=FROM:TO on a velocity "
                     "component (SI) or disturbance; repeatable, all must hold");
  command.add_option("--exclude-run", args.exclude_runs, "Leave out the run with this id (repeatable)");
}

void add_mirror_options(CLI::App& command, std::vector<std::string>& planes, std::vector<std::string>& odd) {
  command.add_option("--mirror", planes,
                     "Let each run also stand for its mirror image in a plane of symmetry of the body: v "
                     "(port-starboard: u,-v,w,-p,q,-r and X,-Y,Z,-K,M,-N), w (top-bottom), u (fore-aft); "
                     "repeatable; images are never stored as runs");
  command.add_option("--mirror-odd", odd,
                     "A disturbance parameter that changes sign in the mirror (e.g. a lateral current); repeatable");
}

}  // namespace hydrocoef::cli
