// The EnSight Gold case file parser (ensight_case.hpp) and the text helpers
// it shares with the walk of the geometry and variable files.
#include "importers/ensight_case.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <system_error>
#include <utility>

#include "src/core/error.hpp"
#include "src/core/text.hpp"

namespace hydrocoef::vtk_detail::ensight {

std::vector<std::string> split_words(std::string_view text) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])) != 0) ++i;
    const std::size_t start = i;
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])) == 0) ++i;
    if (i > start) words.emplace_back(text.substr(start, i - start));
  }
  return words;
}

bool starts_with(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

std::optional<long long> parse_integer(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

std::optional<double> parse_real(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

/// What a quoted excerpt of a file may show: printable, and short.
std::string excerpt(std::string_view text) {
  std::string out(text.substr(0, 40));
  std::replace_if(
      out.begin(), out.end(),
      [](char c) { return static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f; }, '?');
  if (text.size() > 40) out += "...";
  return in_quotes(out);
}

// --- the case file

namespace {

bool is_case_section(const std::string& line) {
  static const std::set<std::string> sections{"FORMAT", "GEOMETRY", "VARIABLE",           "TIME",
                                              "FILE",   "MATERIAL", "BLOCK_CONTINUATION", "SCRIPTS"};
  return sections.count(line) > 0;
}

/// The file name `pattern` gives at file number `number`: its run of '*'
/// replaced by the number, padded with zeros to the run's length, as VTK does.
std::string replace_wildcards(const std::string& pattern, long long number, const fs::path& case_file,
                              std::size_t line) {
  const auto first = pattern.find('*');
  if (first == std::string::npos) return pattern;
  const auto end = std::min(pattern.find_first_not_of('*', first), pattern.size());
  if (pattern.find('*', end) != std::string::npos)
    throw InputError(SourceLocation{case_file.string(), line},
                     "file name " + in_quotes(pattern) + " has several runs of '*'; expected one");
  std::string digits = std::to_string(number);
  if (digits.size() < end - first) digits.insert(0, end - first - digits.size(), '0');
  return pattern.substr(0, first) + digits + pattern.substr(end);
}

}  // namespace

Case parse_case(const fs::path& case_file) {
  const std::string name = case_file.string();
  std::ifstream in(case_file, std::ios::binary);
  Case result;
  std::string section;
  bool gold = false;
  TimeSet* time_set = nullptr;
  std::vector<double>* continued_times = nullptr;
  std::vector<long long>* continued_numbers = nullptr;
  std::string raw;
  std::size_t line_number = 0;
  const auto fail = [&](const std::string& message) -> InputError {
    return InputError(SourceLocation{name, line_number}, message);
  };
  const auto integer = [&](const std::string& word, const char* what) {
    const auto value = parse_integer(word);
    if (!value) throw fail("found " + excerpt(word) + "; expected " + what + " (an integer)");
    return *value;
  };
  // Time values and file numbers may run on over the following lines.
  const auto append_numbers = [&](const std::vector<std::string>& words) {
    for (const auto& word : words) {
      if (continued_times != nullptr) {
        const auto value = parse_real(word);
        if (!value) throw fail("found " + excerpt(word) + "; expected a time value");
        continued_times->push_back(*value);
      } else {
        continued_numbers->push_back(integer(word, "a file number"));
      }
    }
  };

  while (std::getline(in, raw)) {
    ++line_number;
    if (raw.size() > kMaxLineLength)
      throw fail("line of " + std::to_string(raw.size()) + " characters; VTK's EnSight reader reads at most " +
                 std::to_string(kMaxLineLength));
    const std::string line(trim(raw));
    if (line.empty() || line.front() == '#') continue;
    if (is_case_section(line)) {
      section = line;
      continued_times = nullptr;
      continued_numbers = nullptr;
      if (section == "FILE")
        throw fail(
            "single-file transient EnSight data (a FILE section) is not supported; expected one file per "
            "time step");
      continue;
    }
    const auto colon = line.find(':');
    if (colon == std::string::npos) {
      if (section == "TIME" && (continued_times != nullptr || continued_numbers != nullptr)) {
        append_numbers(split_words(line));
        continue;
      }
      if (section == "MATERIAL" || section == "BLOCK_CONTINUATION" || section == "SCRIPTS") continue;
      throw fail("found " + excerpt(line) + "; expected 'keyword: values'");
    }
    continued_times = nullptr;
    continued_numbers = nullptr;
    const std::string key = lower(std::string(trim(std::string_view(line).substr(0, colon))));
    const std::vector<std::string> words = split_words(std::string_view(line).substr(colon + 1));
    std::string normal_key;
    for (const auto& word : split_words(key)) normal_key += (normal_key.empty() ? "" : " ") + word;

    if (section == "FORMAT") {
      if (normal_key != "type") continue;
      std::string type;
      for (const auto& word : words) type += (type.empty() ? "" : " ") + lower(word);
      if (type == "ensight gold") {
        gold = true;
      } else {
        throw fail("EnSight format " + in_quotes(type) +
                   " is not supported; expected 'ensight gold' (cfx5export "
                   "-ensight writes EnSight Gold)");
      }
    } else if (section == "GEOMETRY") {
      if (normal_key != "model")
        throw fail("geometry " + in_quotes(normal_key) + " is not supported; expected only 'model:'");
      if (std::find(words.begin(), words.end(), "change_coords_only") != words.end())
        throw fail("'change_coords_only' geometry is not supported; expected a full geometry file per time step");
      if (words.size() == 3) throw fail("file sets ('model: ts fs file') are not supported");
      if (words.empty() || words.size() > 3) throw fail("expected 'model: [time set] file'");
      result.geometry_pattern = words.back();
      result.geometry_line = line_number;
      if (words.size() == 2) result.geometry_time_set = static_cast<int>(integer(words[0], "a time set number"));
    } else if (section == "VARIABLE") {
      Variable variable;
      if (normal_key == "scalar per node" || normal_key == "vector per node") {
        variable.association = FieldAssociation::Point;
      } else if (normal_key == "scalar per element" || normal_key == "vector per element") {
        variable.association = FieldAssociation::Face;
      } else {
        continue;  // constants, tensors, complex and measured variables: not read (see read_ensight)
      }
      variable.components = starts_with(normal_key, "vector") ? 3 : 1;
      if (words.size() == 4) throw fail("file sets ('" + normal_key + ": ts fs description file') are not supported");
      if (words.size() < 2 || words.size() > 4)
        throw fail("expected '" + normal_key + ": [time set] description file'");
      if (words.size() == 3) variable.time_set = static_cast<int>(integer(words[0], "a time set number"));
      variable.description = words[words.size() - 2];
      variable.pattern = words.back();
      variable.line = line_number;
      result.variables.push_back(std::move(variable));
    } else if (section == "TIME") {
      if (normal_key == "time set") {
        if (words.empty()) throw fail("expected 'time set: number'");
        time_set = &result.time_sets[integer(words[0], "a time set number")];
        continue;
      }
      if (time_set == nullptr) throw fail("found " + in_quotes(normal_key) + " before 'time set:'");
      if (normal_key == "number of steps") {
        if (words.size() != 1) throw fail("expected 'number of steps: n'");
        time_set->steps = integer(words[0], "the number of steps");
      } else if (normal_key == "filename start number") {
        if (words.size() != 1) throw fail("expected 'filename start number: n'");
        time_set->start = integer(words[0], "the first file number");
      } else if (normal_key == "filename increment") {
        if (words.size() != 1) throw fail("expected 'filename increment: n'");
        time_set->increment = integer(words[0], "the file number increment");
      } else if (normal_key == "time values") {
        continued_times = &time_set->times;
        append_numbers(words);
      } else if (normal_key == "filename numbers") {
        continued_numbers = &time_set->file_numbers;
        append_numbers(words);
      } else {
        throw fail("time set entry " + in_quotes(normal_key) + " is not supported");
      }
    } else if (section.empty()) {
      throw fail("found " + excerpt(line) + " before the FORMAT section");
    }
  }
  line_number = 0;
  if (!gold) throw fail("no 'type: ensight gold' in a FORMAT section; expected an EnSight Gold case file");
  if (result.geometry_pattern.empty()) throw fail("no 'model:' line in a GEOMETRY section");

  // Every time set must be complete; the last time is the one read.
  for (const auto& [number, set] : result.time_sets) {
    const std::string which = "time set " + std::to_string(number);
    if (!set.steps || *set.steps < 1) throw fail(which + ": no 'number of steps:' of at least 1");
    const auto steps = static_cast<std::size_t>(*set.steps);
    if (set.times.size() != steps)
      throw fail(which + ": " + std::to_string(set.times.size()) + " time values; expected " + std::to_string(steps));
    if (!set.file_numbers.empty() && set.file_numbers.size() != steps)
      throw fail(which + ": " + std::to_string(set.file_numbers.size()) + " file numbers; expected " +
                 std::to_string(steps));
    for (std::size_t i = 1; i < steps; ++i)
      if (!(set.times[i] > set.times[i - 1]))
        throw fail(which + ": time value " + std::to_string(i + 1) +
                   " does not follow its predecessor; expected "
                   "increasing time values");
    result.last_time = std::max(result.last_time.value_or(set.times.back()), set.times.back());
  }
  // The file each entry names at the last step of its time set: VTK, asked
  // for the last time of all sets, reads every file at its set's last step.
  const auto file_at_last_step = [&](const std::string& pattern, int set_number, std::size_t line) {
    std::string file_name = pattern;
    if (set_number != 0) {
      const auto set = result.time_sets.find(set_number);
      if (set == result.time_sets.end())
        throw InputError(SourceLocation{name, line}, "time set " + std::to_string(set_number) + " is not defined");
      if (pattern.find('*') != std::string::npos) {
        const TimeSet& steps = set->second;
        const auto last = static_cast<long long>(steps.times.size()) - 1;
        long long number = 0;
        if (!steps.file_numbers.empty())
          number = steps.file_numbers.back();
        else if (steps.start && steps.increment)
          number = *steps.start + last * *steps.increment;
        else
          throw InputError(SourceLocation{name, line},
                           "time set " + std::to_string(set_number) +
                               " has neither 'filename numbers:' nor 'filename start number:' and "
                               "'filename increment:' for the '*' in " +
                               in_quotes(pattern));
        file_name = replace_wildcards(pattern, number, case_file, line);
      }
    }
    const fs::path path(file_name);
    return path.is_absolute() ? path : case_file.parent_path() / path;
  };
  result.geometry_file = file_at_last_step(result.geometry_pattern, result.geometry_time_set, result.geometry_line);
  for (auto& variable : result.variables)
    variable.file = file_at_last_step(variable.pattern, variable.time_set, variable.line);
  return result;
}

}  // namespace hydrocoef::vtk_detail::ensight
