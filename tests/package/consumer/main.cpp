// A program that uses hydrocoef as an installed library (tests/package: scripts/package-test.sh builds it
// against `cmake --install`'s tree with find_package and with pkg-config). It opens a database, queries a
// surface at one point and checks the values against the ones given (what `hydrocoef query --json` answered
// for the same point), and checks that a missing surface is an InputError.
//   consumer DATABASE SURFACE AXIS=VALUE... --expect OUTPUT=VALUE...
// Prints one line per check; exits 1 when one fails.
#include <hydrocoef/hydrocoef.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace {

std::map<std::string, double> parse_assignments(const std::vector<std::string>& words) {
  std::map<std::string, double> values;
  for (const std::string& word : words) {
    const auto equals = word.find('=');
    if (equals == std::string::npos) throw std::runtime_error("expected NAME=VALUE, found '" + word + "'");
    values[word.substr(0, equals)] = std::strtod(word.c_str() + equals + 1, nullptr);
  }
  return values;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: consumer DATABASE SURFACE AXIS=VALUE... --expect OUTPUT=VALUE...\n");
    return 2;
  }
  std::vector<std::string> point_words, expect_words;
  bool expecting = false;
  for (int i = 3; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (word == "--expect") {
      expecting = true;
    } else {
      (expecting ? expect_words : point_words).emplace_back(word);
    }
  }
  int failures = 0;
  try {
    std::printf("consumer: hydrocoef %s\n", hydrocoef::kVersion);
    const hydrocoef::Database db = hydrocoef::Database::open(argv[1], hydrocoef::OpenMode::ReadOnly);
    const hydrocoef::Surface surface = db.surface(argv[2]);

    // The point in the order of the surface's axes.
    const auto given = parse_assignments(point_words);
    std::vector<double> point;
    for (const std::string& axis : surface.axes()) {
      const auto found = given.find(axis);
      if (found == given.end()) throw std::runtime_error("no value given for the axis '" + axis + "'");
      point.push_back(found->second);
    }
    const std::vector<double> values = surface.evaluate(point);
    if (values.size() != surface.outputs().size()) {
      std::printf("consumer: FAILED %zu values for %zu outputs\n", values.size(), surface.outputs().size());
      ++failures;
    }
    const auto expected = parse_assignments(expect_words);
    if (expected.empty()) {
      std::printf("consumer: FAILED nothing to compare (--expect OUTPUT=VALUE)\n");
      ++failures;
    }
    for (const auto& [output, value] : expected) {
      std::size_t index = 0;
      while (index < surface.outputs().size() && surface.outputs()[index] != output) ++index;
      if (index >= values.size()) {
        std::printf("consumer: FAILED the surface has no output '%s'\n", output.c_str());
        ++failures;
        continue;
      }
      const bool same = std::abs(values[index] - value) <= 1e-12 * std::max(1.0, std::abs(value));
      std::printf("consumer: %s %s = %.17g, the CLI's query %.17g\n", same ? "ok" : "FAILED", output.c_str(),
                  values[index], value);
      if (!same) ++failures;
    }

    // A surface the database does not have is an InputError naming it.
    try {
      (void)db.surface("no-such-surface");
      std::printf("consumer: FAILED opening a missing surface did not throw\n");
      ++failures;
    } catch (const hydrocoef::InputError& error) {
      const bool named = std::string(error.what()).find("no-such-surface") != std::string::npos;
      std::printf("consumer: %s a missing surface is an InputError: %s\n", named ? "ok" : "FAILED", error.what());
      if (!named) ++failures;
    }
  } catch (const std::exception& error) {
    std::printf("consumer: FAILED %s\n", error.what());
    return 1;
  }
  return failures == 0 ? 0 : 1;
}
