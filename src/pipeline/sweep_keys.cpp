#include "src/pipeline/sweep_keys.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "importers/text_table.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/names.hpp"
#include "src/core/source_file.hpp"
#include "src/core/units.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

fs::path normalized(const fs::path& path) {
  std::error_code ec;
  fs::path absolute = fs::absolute(path, ec);
  if (ec) absolute = path;
  fs::path out = absolute.lexically_normal();
  if (!out.has_filename() && out.has_parent_path()) out = out.parent_path();  // "a/b/" -> "a/b"
  return out;
}

const Dimension& dimension_of(std::string_view name) {
  static const Dimension none = kDimensionless;
  if (const auto i = velocity_index(name)) return *i < 3 ? kVelocity : kAngularVelocity;
  if (name == "rho") return kDensity;
  if (name == "nu") return kKinematicViscosity;
  if (name == "p_ref") return kPressure;
  if (name == "flow_x" || name == "flow_y" || name == "flow_z") return kVelocity;
  return none;
}

/// The SI scale of a unit written for a quantity `name`; InputError when the
/// unit is not of its kind. Disturbances take any unit (their kind is theirs).
double si_scale(std::string_view name, std::string_view unit, const SourceLocation& where) {
  if (unit.empty()) return 1.0;
  const Unit parsed = parse_unit(unit);
  const bool known =
      velocity_index(name) || name == "rho" || name == "nu" || name == "p_ref" || name.rfind("flow_", 0) == 0;
  if (known && !dimension_matches(parsed.dimension, dimension_of(name)))
    throw InputError(where, "unit '" + std::string(unit) + "' of '" + std::string(name) + "' is " +
                                si_unit_name(parsed.dimension) + "; expected " + si_unit_name(dimension_of(name)));
  return parsed.scale;
}

bool is_text_column(std::string_view name) {
  return name == "path" || name == "body" || name == "axes" || name == "sign" || name == "window" || name == "symmetry";
}

}  // namespace

Manifest Manifest::read(const fs::path& file) {
  const std::string where = file.string();
  const SourceFile source = load_source_file(file);
  const std::string_view bytes(source.bytes.data(), source.bytes.size());
  const auto lines = split_lines(bytes);
  std::size_t first = 0;
  while (first < lines.size() && (lines[first].text.empty() || lines[first].text.front() == '#')) ++first;
  if (first == lines.size()) throw InputError(SourceLocation{where}, "manifest has no header row; expected 'path,...'");
  const char delimiter = detect_delimiter(lines[first].text);
  const auto header = split_fields(lines[first], delimiter, where);

  struct Column {
    std::string name;
    double scale = 1.0;
  };
  std::vector<Column> columns;
  std::optional<std::size_t> path_column;
  for (const auto& field : header) {
    const SourceLocation at{where, lines[first].number, field.column};
    const NameAndUnit parts = split_name_and_unit(field.text);
    const std::string name = parts.name;
    if (name.empty())
      throw InputError(at, "empty column name; expected path, body, u..r, rho, nu, ... or a disturbance");
    const bool known = is_text_column(name) || velocity_index(name) || name == "rho" || name == "nu" ||
                       name == "p_ref" || name == "flow_x" || name == "flow_y" || name == "flow_z";
    if (!known) check_name(NameKind::Parameter, name, at, "the manifest header");
    if (std::any_of(columns.begin(), columns.end(), [&](const Column& c) { return c.name == name; }))
      throw InputError(at, "column '" + name + "' appears twice");
    if (is_text_column(name) && parts.has_unit) throw InputError(at, "column '" + name + "' is text; it takes no unit");
    if (name == "path") path_column = columns.size();
    columns.push_back({name, is_text_column(name) ? 1.0 : si_scale(name, parts.unit, at)});
  }
  if (!path_column) throw InputError(SourceLocation{where, lines[first].number}, "no 'path' column; expected one");
  const auto flows =
      std::count_if(columns.begin(), columns.end(), [](const Column& c) { return c.name.rfind("flow_", 0) == 0; });
  if (flows != 0 && flows != 3)
    throw InputError(SourceLocation{where, lines[first].number}, "flow needs all three columns flow_x, flow_y, flow_z");

  Manifest manifest;
  manifest.file_ = file;
  const fs::path base = file.has_parent_path() ? file.parent_path() : fs::path(".");
  for (std::size_t i = first + 1; i < lines.size(); ++i) {
    const auto& line = lines[i];
    if (line.text.empty() || line.text.front() == '#') continue;
    const auto fields = split_fields(line, delimiter, where);
    if (fields.size() != columns.size())
      throw InputError(SourceLocation{where, line.number}, std::to_string(fields.size()) + " fields; expected " +
                                                               std::to_string(columns.size()) + " as in the header");
    SettingsLayer layer;
    layer.origin = SettingOrigin{SettingSource::Manifest, where + ":" + std::to_string(line.number)};
    std::vector<double> flow(3, 0.0);
    bool has_flow = false;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const auto& field = fields[c];
      const auto& name = columns[c].name;
      if (field.text.empty() || name == "path") continue;
      const SourceLocation at{where, line.number, field.column};
      if (is_text_column(name)) {
        // Without the quote escape::csv_text puts before a formula-like text ("'=x" is "=x").
        const std::string text = escape::csv_text_value(field.text);
        if (name == "body") check_name(NameKind::Body, text, at, "the manifest");
        layer.set(name, text);
        continue;
      }
      const double value = parse_number(field, where, line.number, name) * columns[c].scale;
      if (name.rfind("flow_", 0) == 0) {
        flow[static_cast<std::size_t>(name[5] - 'x')] = value;
        has_flow = true;
      } else if (velocity_index(name) || name == "rho" || name == "nu" || name == "p_ref") {
        layer.set(name, value);
      } else {
        layer.set("disturbance." + name, value);
      }
    }
    if (has_flow) layer.set("flow", flow);
    const auto& path_field = fields[*path_column];
    if (path_field.text.empty())
      throw InputError(SourceLocation{where, line.number, path_field.column}, "empty path; expected a file or folder");
    const fs::path target =
        normalized(fs::path(path_field.text).is_absolute() ? fs::path(path_field.text) : base / path_field.text);
    if (!manifest.rows_.emplace(target, std::move(layer)).second)
      throw InputError(SourceLocation{where, line.number, path_field.column},
                       "path '" + printable_text(path_field.text, 80) + "' is listed twice");
  }
  return manifest;
}

const SettingsLayer* Manifest::find(const fs::path& path) const {
  for (fs::path at = normalized(path);; at = at.parent_path()) {
    if (const auto it = rows_.find(at); it != rows_.end()) return &it->second;
    if (!at.has_relative_path() || at == at.parent_path()) return nullptr;
  }
}

std::vector<fs::path> Manifest::paths() const {
  std::vector<fs::path> out;
  for (const auto& [path, layer] : rows_) out.push_back(path);
  return out;
}

NamePattern::NamePattern(std::string pattern) : pattern_(std::move(pattern)) {
  const auto refuse = [&](const std::string& what) {
    throw InputError("--key-from-name '" + printable_text(pattern_, 80) + "': " + what);
  };
  std::string literal;
  for (std::size_t i = 0; i < pattern_.size(); ++i) {
    const char c = pattern_[i];
    if (c == '}') refuse("'}' without '{'");
    if (c != '{') {
      literal += c;
      continue;
    }
    const auto close = pattern_.find('}', i);
    if (close == std::string::npos) refuse("'{' without '}'");
    const std::string inside = pattern_.substr(i + 1, close - i - 1);
    const NameAndUnit parts = split_name_and_unit(inside);
    std::string name = parts.name;
    if (name.empty()) refuse("an empty field {}; expected {u}, {r [deg s^-1]} or {current_v}");
    if (!velocity_index(name)) check_name(NameKind::Parameter, name, {}, "--key-from-name");
    for (const auto& field : fields_)
      if (field.name == name) refuse("field {" + name + "} appears twice");
    if (!fields_.empty() && literal.empty()) refuse("two fields with nothing between them cannot be told apart");
    Field field{name, si_scale(name, parts.unit, SourceLocation{"--key-from-name"})};
    literals_.push_back(literal);
    literal.clear();
    fields_.push_back(field);
    i = close;
  }
  literals_.push_back(literal);
  if (fields_.empty()) refuse("no field in braces; expected e.g. 'u{u}_v{v}'");
  spans_folders_ = pattern_.find('/') != std::string::npos;
}

namespace {

/// Whether c can be part of a finite number std::from_chars reads (digits,
/// sign, point, exponent): a number ends before the first other character.
bool number_char(char c) { return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-'; }

}  // namespace

std::optional<std::vector<double>> NamePattern::match_text(std::string_view text) const {
  std::vector<double> values(fields_.size());
  // Literal, number, literal, ...: each number is tried longest first, so
  // that "u0.20_v0.05" reads 0.20 then 0.05, and backtracks when the literal
  // after a number begins with a digit or 'e'. The first match in that order
  // is taken. Trying is bounded: a (field, position) that failed once fails
  // again, so it is remembered (without that, crafted names such as
  // "1e1e1e...x" against "{a}e{b}e{c}..." took exponential time: 10 fields
  // over a minute); the numbers that may start at a position are read once.
  // Work: O(fields x length x longest number), each number parsed once per
  // end.
  const std::size_t n = text.size();
  const std::size_t fields = fields_.size();
  std::vector<char> failed((fields + 1) * (n + 1), 0);
  struct Candidate {
    std::size_t end;
    double value;
  };
  std::vector<std::optional<std::vector<Candidate>>> numbers_at(n + 1);
  const auto numbers_from = [&](std::size_t at) -> const std::vector<Candidate>& {
    auto& slot = numbers_at[at];
    if (slot) return *slot;
    slot.emplace();
    std::size_t run = at;
    while (run < n && number_char(text[run])) ++run;
    for (std::size_t end = run; end > at; --end) {  // longest first
      std::string_view number = text.substr(at, end - at);
      if (number.front() == '+') number.remove_prefix(1);
      double value = 0.0;
      const auto [ptr, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
      if (number.empty() || ec != std::errc() || ptr != number.data() + number.size() || !std::isfinite(value))
        continue;
      slot->push_back({end, value});
    }
    return *slot;
  };
  const auto match_from = [&](const auto& self, std::size_t field, std::size_t at) -> bool {
    char& known_failure = failed[field * (n + 1) + at];
    if (known_failure) return false;
    const std::string& literal = literals_[field];
    if (text.substr(at, literal.size()) == literal) {
      const std::size_t after = at + literal.size();
      if (field == fields) return after == n;
      for (const Candidate& candidate : numbers_from(after)) {
        values[field] = candidate.value * fields_[field].scale;
        if (self(self, field + 1, candidate.end)) return true;
      }
    }
    known_failure = 1;
    return false;
  };
  if (!match_from(match_from, 0, 0)) return std::nullopt;
  return values;
}

std::optional<SettingsLayer> NamePattern::match(const fs::path& relative, bool names_a_file) const {
  std::vector<std::string> names;
  for (const auto& part : relative.lexically_normal()) {
    const std::string name = part.string();
    if (!name.empty() && name != "." && name != "/") names.push_back(name);
  }
  // A file's name is matched without its extension; a folder's whole (a
  // folder "u0.20_v0.05" has no extension, though ".05" looks like one).
  if (names_a_file && !names.empty()) names.back() = fs::path(names.back()).stem().string();
  std::optional<std::vector<double>> found;
  std::string found_in;
  const auto consider = [&](const std::string& text) {
    const auto values = match_text(text);
    if (!values) return;
    if (found && *found != *values)
      throw InputError(SourceLocation{relative.string()},
                       "--key-from-name '" + pattern_ + "' matches both '" + found_in + "' and '" + text +
                           "' with different values; expected one match on the path");
    found = values;
    found_in = text;
  };
  if (spans_folders_) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      std::string joined;
      for (std::size_t j = i; j < names.size(); ++j) {
        joined += (j > i ? "/" : "") + names[j];
        consider(joined);
      }
    }
  } else {
    for (const auto& name : names) consider(name);
  }
  if (!found) return std::nullopt;
  SettingsLayer layer;
  layer.origin = SettingOrigin{SettingSource::NamePattern, "'" + found_in + "' by --key-from-name '" + pattern_ + "'"};
  for (std::size_t i = 0; i < fields_.size(); ++i) {
    const auto& name = fields_[i].name;
    layer.set(velocity_index(name) ? name : "disturbance." + name, (*found)[i]);
  }
  return layer;
}

}  // namespace hydrocoef
