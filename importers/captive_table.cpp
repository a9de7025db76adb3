#include "importers/captive_table.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "importers/text_table.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/core/source_file.hpp"
#include "src/core/text.hpp"
#include "src/core/units.hpp"
#include "src/derivatives/normalisation.hpp"

namespace hydrocoef {
namespace {

enum class Role { Test, Speed, Froude, Beta, Delta, Rate, Force, Ignored };

struct Column {
  Role role = Role::Ignored;
  std::size_t component = 0;  // Force: 0 X, 1 Y, 3 K, 5 N (kForceNames)
  std::string header;         // as written
  std::size_t column = 0;     // 1-based byte column of the header
  double scale = 1.0;         // to SI
};

constexpr Dimension kAngleDimension{{0, 0, 0, 1, 0}};
constexpr std::array<std::string_view, 4> kTests = {"static-drift", "rudder", "drift-rudder", "circular-motion"};
constexpr std::array<std::string_view, 9> kSettings = {
    "form", "drift_convention", "length", "speed", "density", "draft", "mass", "volume", "gravity"};

struct FileSetting {
  std::string text;
  std::size_t line = 0;
};

/// A reference value as used, with where it came from ("--length", "line 3", "the body's reference data").
struct Resolved {
  std::optional<double> value;
  std::string origin;
};

bool is_blank(std::string_view text) { return text.find_first_not_of(" \t") == std::string_view::npos; }

/// "# NAME = VALUE" with NAME one word: the setting's name (lower case, '-'
/// as '_') and value; nullopt for any other comment.
std::optional<std::pair<std::string, std::string>> setting_line(std::string_view text) {
  text = trim(text, " \t");
  if (text.empty() || text.front() != '#') return std::nullopt;
  text = trim(text.substr(1), " \t");
  const auto equals = text.find('=');
  if (equals == std::string_view::npos) return std::nullopt;
  const std::string_view name = trim(text.substr(0, equals), " \t");
  if (name.empty() || !std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == '-';
      }))
    return std::nullopt;
  std::string key = lower(name);
  std::replace(key.begin(), key.end(), '-', '_');
  if (key == "rho") key = "density";
  return std::make_pair(key, std::string(trim(text.substr(equals + 1), " \t")));
}

/// Blank-separated fields; a field starting with '[' belongs to the one
/// before it ("beta [deg]" is one header).
std::vector<TextField> split_blanks(const TextLine& line, const std::string& file, std::size_t max_fields) {
  std::vector<TextField> out;
  const std::string_view text = line.text;
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == ' ' || text[i] == '\t') {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && text[end] != ' ' && text[end] != '\t') ++end;
    if (end - i > kMaxTextFieldBytes)
      throw InputError(
          SourceLocation{file, line.number, i + 1},
          "a field of more than " + std::to_string(kMaxTextFieldBytes) + " bytes; expected a header or number");
    const std::string_view word = text.substr(i, end - i);
    if (word.front() == '[' && !out.empty()) {
      out.back().text += " " + std::string(word);
    } else {
      if (out.size() == max_fields)
        throw InputError(SourceLocation{file, line.number, i + 1},
                         "more than " + std::to_string(max_fields) + " fields on the line");
      out.push_back({std::string(word), i + 1});
    }
    i = end;
  }
  return out;
}

class Reader {
 public:
  Reader(std::string_view text, const std::string& file, const CaptiveTableOptions& options)
      : lines_(split_lines(text)), file_(file), options_(options) {}

  CaptiveTable read();

 private:
  SourceLocation at(std::size_t line, std::size_t column = 0) const { return SourceLocation{file_, line, column}; }
  void read_settings(std::vector<TextLine>::const_iterator header);
  std::vector<TextField> fields_of(const TextLine& line, std::size_t max_fields) const {
    return blank_separated_ ? split_blanks(line, file_, max_fields) : split_fields(line, delimiter_, file_, max_fields);
  }
  Column classify(const TextField& field) const;
  std::optional<double> file_number(const std::string& name) const;
  Resolved resolve(const std::string& name, const CaptiveValue& option, const std::optional<double>& body_value) const;
  void resolve_form_and_convention();
  void check_needs();
  [[noreturn]] void refuse_missing(const Column& column, const std::string& what, const std::string& how) const;
  const Column* first(Role role) const {
    for (const auto& c : columns_)
      if (c.role == role) return &c;
    return nullptr;
  }
  ImportedRun read_row(const TextLine& line, const std::vector<TextField>& fields, std::string& test);

  std::vector<TextLine> lines_;
  const std::string& file_;
  const CaptiveTableOptions& options_;
  std::map<std::string, FileSetting> settings_;
  bool blank_separated_ = false;
  char delimiter_ = ',';
  std::size_t header_line_ = 0;
  std::vector<Column> columns_;
  NormalisationSystem system_ = NormalisationSystem::Prime;
  std::string form_origin_, convention_origin_;
  bool form_known_ = false;
  std::optional<bool> starboard_positive_;  // fossen: v = U sin beta; mmg: v = -U sin beta
  Resolved length_, speed_, density_, draft_, mass_, volume_, gravity_;
};

void Reader::read_settings(std::vector<TextLine>::const_iterator header) {
  for (auto line = lines_.cbegin(); line != header; ++line) {
    const auto setting = setting_line(line->text);
    if (!setting) continue;
    const auto& [name, value] = *setting;
    if (std::find(kSettings.begin(), kSettings.end(), name) == kSettings.end())
      throw InputError(at(line->number), "setting '" + printable_text(name, 40) +
                                             "' is not known; expected one of form, drift_convention, length, "
                                             "speed, density (or rho), draft, mass, volume, gravity (or a comment "
                                             "without '=')");
    const auto [previous, inserted] = settings_.emplace(name, FileSetting{value, line->number});
    if (!inserted)
      throw InputError(at(line->number), "setting '" + name + "' again (first on line " +
                                             std::to_string(previous->second.line) + "); expected each setting once");
    if (name == "form" || name == "drift_convention") continue;
    const auto number = parse_finite_number(value);
    if (!number || !(*number > 0.0))
      throw InputError(at(line->number), "setting '" + name + "': found '" + printable_text(value, 40) +
                                             "', expected a number above 0 (SI: m, m/s, kg/m^3, kg, m^3, m/s^2)");
  }
}

std::optional<double> Reader::file_number(const std::string& name) const {
  const auto found = settings_.find(name);
  if (found == settings_.end()) return std::nullopt;
  return parse_finite_number(found->second.text);
}

Resolved Reader::resolve(const std::string& name, const CaptiveValue& option,
                         const std::optional<double>& body_value) const {
  if (option.value) return {option.value, option.origin};
  if (const auto value = file_number(name)) return {value, "line " + std::to_string(settings_.at(name).line)};
  if (body_value) return {body_value, "the body's reference data"};
  return {};
}

void Reader::resolve_form_and_convention() {
  std::optional<std::string> form;
  if (options_.form) {
    form = options_.form;
    form_origin_ = "--form";
  } else if (const auto found = settings_.find("form"); found != settings_.end()) {
    form = found->second.text;
    form_origin_ = "line " + std::to_string(found->second.line);
  }
  if (form) {
    const std::string text = lower(*form);
    if (text != "prime" && text != "bis" && text != "mmg")
      throw InputError(form_origin_ == "--form" ? at(0) : at(settings_.at("form").line),
                       "form '" + printable_text(*form, 40) + "' (" + form_origin_ +
                           "): expected prime (SNAME 1950), bis (Norrbin 1971) or mmg (Yasukawa and Yoshimura 2015)");
    system_ = parse_normalisation_system(text);
    form_known_ = true;
  }
  std::optional<std::string> convention;
  if (options_.drift_convention) {
    convention = options_.drift_convention;
    convention_origin_ = "--drift-convention";
  } else if (const auto found = settings_.find("drift_convention"); found != settings_.end()) {
    convention = found->second.text;
    convention_origin_ = "line " + std::to_string(found->second.line);
  }
  if (convention) {
    const std::string text = lower(*convention);
    if (text != "mmg" && text != "fossen")
      throw InputError(convention_origin_ == "--drift-convention" ? at(0) : at(settings_.at("drift_convention").line),
                       "drift convention '" + printable_text(*convention, 40) + "' (" + convention_origin_ +
                           "): expected mmg (beta = atan2(-v, u)) or fossen (beta = atan2(v, u))");
    starboard_positive_ = text == "fossen";
  }
}

Column Reader::classify(const TextField& field) const {
  const SourceLocation where = at(header_line_, field.column);
  const auto header = split_name_and_unit(field.text);
  Column column;
  column.header = field.text;
  column.column = field.column;
  if (header.name.empty()) throw InputError(where, "empty column header; expected a name such as 'beta [deg]'");
  if (std::find(options_.ignored_columns.begin(), options_.ignored_columns.end(), header.name) !=
      options_.ignored_columns.end())
    return column;
  const std::string& name = header.name;
  const std::string shown = "column '" + printable_text(field.text, 60) + "'";
  const auto unit_of = [&](const Dimension& expected, const char* example) {
    if (!header.has_unit)
      throw InputError(where, shown + " has no unit; expected e.g. '" + name + " [" + example + "]'");
    Unit unit;
    try {
      unit = parse_unit(header.unit);
    } catch (const InputError& error) {
      throw InputError(where, shown + ": " + error.what());
    }
    if (unit.dimension != expected)
      throw InputError(where, shown + ": unit '" + printable_text(unit.text, 40) + "' is " +
                                  si_unit_name(unit.dimension) + ", expected " + si_unit_name(expected) + " (e.g. " +
                                  example + ")");
    return unit.scale;
  };
  const auto no_unit = [&]() {
    if (!header.has_unit) return;
    const std::string_view unit = trim(header.unit, " \t");
    if (unit.empty() || unit == "-" || unit == "1") return;
    throw InputError(where, shown + " is non-dimensional; found the unit '" + printable_text(unit, 40) +
                                "', expected none (or [-])");
  };
  if (name == "test") {
    column.role = Role::Test;
    no_unit();
  } else if (name == "U" || name == "speed") {
    column.role = Role::Speed;
    column.scale = unit_of(kVelocity, "m/s");
  } else if (name == "Fn") {
    column.role = Role::Froude;
    no_unit();
  } else if (name == "beta" || name == "delta") {
    column.role = name == "beta" ? Role::Beta : Role::Delta;
    column.scale = unit_of(kAngleDimension, "deg");
  } else if (name == "r'") {
    column.role = Role::Rate;
    no_unit();
  } else {
    const bool bis_mark = name.size() == 3 && name.substr(1) == "''";
    const bool prime_mark = name.size() == 2 && name[1] == '\'';
    const auto component = (bis_mark || prime_mark) ? force_index(name.substr(0, 1)) : std::nullopt;
    if (!component || *component == 2 || *component == 4)
      throw InputError(where, shown +
                                  " is not a captive-table column; expected test, U (or speed, Fn), beta, delta, r', "
                                  "X', Y', K', N' (X'' ... in the bis form), or skip it with --ignore " +
                                  printable_text(name, 60));
    if (bis_mark && form_known_ && system_ != NormalisationSystem::Bis)
      throw InputError(where, shown + " is in the bis form (two primes) but the table's form is " +
                                  std::string(to_string(system_)) + " (" + form_origin_ + "); expected " +
                                  name.substr(0, 1) + "' or the form bis");
    column.role = Role::Force;
    column.component = *component;
    no_unit();
  }
  return column;
}

void Reader::refuse_missing(const Column& column, const std::string& what, const std::string& how) const {
  std::string form;
  if (column.role == Role::Force) form = " (" + std::string(to_string(system_)) + ")";
  throw InputError(at(header_line_, column.column), "column " +
                                                        printable_text(split_name_and_unit(column.header).name, 60) +
                                                        form + " needs " + what + ": give " + how);
}

void Reader::check_needs() {
  const Column* force = first(Role::Force);
  if (!force) throw InputError(at(header_line_), "no force or moment column; expected at least one of X' Y' K' N'");
  if (!form_known_)
    throw InputError(at(header_line_, force->column),
                     "column " + printable_text(split_name_and_unit(force->header).name, 60) +
                         ": the form of the forces is not stated; expected --form prime|bis|mmg or a line "
                         "'# form = prime' before the header");
  if (const Column* beta = first(Role::Beta); beta && !starboard_positive_)
    throw InputError(at(header_line_, beta->column),
                     "column " + printable_text(beta->header, 60) +
                         ": the drift-angle convention is not stated; expected --drift-convention mmg (beta = "
                         "atan2(-v, u), the bow to port of the track for beta > 0) or fossen (beta = atan2(v, u)), "
                         "or a line '# drift_convention = mmg' before the header");
  if (first(Role::Speed) && first(Role::Froude))
    throw InputError(at(header_line_, first(Role::Froude)->column),
                     "columns U and Fn both give the speed; expected one of them");
  const std::string body_set = "`hydrocoef body set " + printable_text(options_.body, 60) + " ";
  length_ = resolve("length", options_.length, options_.body_reference.length);
  gravity_ = resolve("gravity", options_.gravity, std::nullopt);
  if (!gravity_.value) gravity_ = {9.80665, "standard gravity"};
  if (!length_.value) {
    const std::string how = "--length, a line '# length = L' before the header or " + body_set + "--length L`";
    refuse_missing(*force, "the reference length", how);
  }
  speed_ = first(Role::Speed) || first(Role::Froude) ? Resolved{} : resolve("speed", options_.speed, std::nullopt);
  if (!first(Role::Speed) && !first(Role::Froude) && !speed_.value)
    refuse_missing(*force, "the speed U of each run",
                   "a column 'U [m/s]' (or 'Fn'), --speed U or a line '# speed = U' before the header");
  density_ = resolve("density", options_.density, std::nullopt);
  const std::string density_how = "--rho (or --density) or a line '# density = RHO' before the header";
  if (system_ != NormalisationSystem::Bis && !density_.value) refuse_missing(*force, "the water density", density_how);
  if (system_ == NormalisationSystem::Mmg) {
    draft_ = resolve("draft", options_.draft, options_.body_reference.draft);
    if (!draft_.value)
      refuse_missing(*force, "the draft d",
                     "--draft, a line '# draft = D' before the header or " + body_set + "--draft D`");
  }
  if (system_ == NormalisationSystem::Bis) {
    mass_ = resolve("mass", options_.mass, std::nullopt);
    if (!mass_.value) {
      volume_ = resolve("volume", options_.volume, options_.body_reference.volume);
      if (!volume_.value)
        refuse_missing(*force, "the mass m",
                       "--mass, a line '# mass = M', or the displaced volume (--volume, '# volume = V' or " + body_set +
                           "--volume V`) with the density");
      if (!density_.value) refuse_missing(*force, "the water density (m = rho times the volume)", density_how);
    }
  }
}

ImportedRun Reader::read_row(const TextLine& line, const std::vector<TextField>& fields, std::string& test) {
  std::optional<double> speed = speed_.value, beta, delta, rate;
  std::array<std::optional<double>, 6> force;
  std::map<Role, std::string> written;  // each value as the row writes it
  test.clear();
  std::size_t test_column = 0;
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    const Column& column = columns_[c];
    const TextField& field = fields[c];
    const SourceLocation where = at(line.number, field.column);
    if (column.role == Role::Ignored) continue;
    if (column.role == Role::Test) {
      test = field.text;
      test_column = field.column;
      if (std::find(kTests.begin(), kTests.end(), test) == kTests.end())
        throw InputError(where, "column test: found '" + printable_text(test, 40) +
                                    "', expected static-drift, rudder, drift-rudder or circular-motion");
      continue;
    }
    const double value = parse_number(field, file_, line.number, column.header) * column.scale;
    if (!std::isfinite(value))
      throw InputError(where, "column '" + printable_text(column.header, 60) + "': '" + printable_text(field.text, 40) +
                                  "' overflows when converted to SI; expected a finite value");
    switch (column.role) {
      case Role::Speed:
      case Role::Froude: {
        const double u = column.role == Role::Speed ? value : value * std::sqrt(*gravity_.value * *length_.value);
        if (!(u > 0.0) || !std::isfinite(u))
          throw InputError(where, "column '" + printable_text(column.header, 60) + "': found '" +
                                      printable_text(field.text, 40) +
                                      "', expected a speed above 0 (the forces are scaled by it)");
        speed = u;
        break;
      }
      case Role::Beta: beta = value; break;
      case Role::Delta: delta = value; break;
      case Role::Rate: rate = value; break;
      case Role::Force: force[column.component] = value; break;
      case Role::Test:
      case Role::Ignored: break;
    }
    written[column.role] = printable_text(field.text, 40);
  }
  if (!test.empty()) {
    const SourceLocation where = at(line.number, test_column);
    const auto expect_zero = [&](const std::optional<double>& value, Role role, const char* name, const char* hint) {
      if (value && *value != 0.0)
        throw InputError(where, "column test: '" + test + "' with " + name + " = " + written[role] + "; expected " +
                                    name + " = 0 in a " + test + " test (" + hint + ")");
    };
    if (test == "static-drift") {
      expect_zero(rate, Role::Rate, "r'", "a circular-motion test has a yaw rate");
      expect_zero(delta, Role::Delta, "delta", "a drift-rudder test has a rudder angle");
    } else if (test == "rudder") {
      expect_zero(beta, Role::Beta, "beta", "a drift-rudder test has a drift angle");
      expect_zero(rate, Role::Rate, "r'", "a circular-motion test has a yaw rate");
    } else if (test == "drift-rudder") {
      expect_zero(rate, Role::Rate, "r'", "a circular-motion test has a yaw rate");
    } else if (!rate || *rate == 0.0) {
      throw InputError(where,
                       "column test: 'circular-motion' without a yaw rate; expected r' other than 0 (a "
                       "static-drift, rudder or drift-rudder test has none)");
    }
  }

  const double U = *speed;
  const double L = *length_.value;
  ImportedRun run;
  run.key.body = options_.body;
  run.key.disturbances = options_.disturbances;
  const double b = beta.value_or(0.0);
  run.key.nu_b[0] = U * std::cos(b);
  run.key.nu_b[1] = (starboard_positive_.value_or(false) ? 1.0 : -1.0) * U * std::sin(b) + 0.0;
  run.key.nu_b[5] = rate.value_or(0.0) * U / L + 0.0;
  if (delta) run.key.disturbances["delta"] = *delta;
  run.fluid.density_kg_m3 = density_.value;
  run.fluid.kinematic_viscosity_m2_s = options_.kinematic_viscosity;
  run.reference_point_b = options_.reference_point_b;
  run.sign = options_.sign;
  run.source_line = line.number;
  NormalisationReference reference;
  reference.length = L;
  reference.speed = U;
  reference.density = density_.value;
  reference.draft = draft_.value;
  reference.mass = mass_.value;
  reference.displaced_volume = volume_.value;
  reference.gravity = *gravity_.value;
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    const Column& column = columns_[c];
    if (column.role != Role::Force) continue;
    const QuantityKind kind = column.component < 3 ? QuantityKind::Force : QuantityKind::Moment;
    const double value = to_dimensional(*force[column.component], kind, system_, reference);
    if (!std::isfinite(value))
      throw InputError(at(line.number, fields[c].column),
                       "column '" + printable_text(column.header, 60) + "': '" + printable_text(fields[c].text, 40) +
                           "' overflows when made dimensional; expected a finite value");
    run.tau_b[column.component] = ForceComponent{value, std::nullopt, std::nullopt};
  }
  for (const double v : run.key.nu_b)
    if (!std::isfinite(v)) throw InputError(at(line.number), "the row's velocity overflows; expected finite u, v, r");
  return run;
}

CaptiveTable Reader::read() {
  const auto header = std::find_if(lines_.cbegin(), lines_.cend(), [](const TextLine& l) {
    const auto first = l.text.find_first_not_of(" \t");
    return first != std::string_view::npos && l.text[first] != '#';
  });
  if (header == lines_.cend())
    throw InputError(at(0), "no header line; expected a header such as 'U [m/s],beta [deg],r',Y',N''");
  read_settings(header);
  resolve_form_and_convention();
  header_line_ = header->number;
  if (header->text.find_first_of(",\t;") != std::string_view::npos)
    delimiter_ = detect_delimiter(header->text);
  else
    blank_separated_ = true;
  std::map<std::string, std::size_t> seen;  // role or force -> header column
  for (const auto& field : fields_of(*header, kMaxTextFields)) {
    Column column = classify(field);
    if (column.role != Role::Ignored) {
      const std::string what = column.role == Role::Force   ? std::string(kForceNames[column.component])
                               : column.role == Role::Speed ? std::string("the speed")
                                                            : split_name_and_unit(column.header).name;
      if (const auto [previous, inserted] = seen.emplace(what, field.column); !inserted)
        throw InputError(at(header_line_, field.column),
                         "column '" + printable_text(field.text, 60) + "' gives " + what + " again (first at column " +
                             std::to_string(previous->second) + "); expected each column once");
    }
    columns_.push_back(std::move(column));
  }
  if (const Column* delta = first(Role::Delta); delta && options_.disturbances.count("delta"))
    throw InputError(at(header_line_, delta->column), "column '" + printable_text(delta->header, 60) +
                                                          "' and --set both give 'delta'; expected one of them");
  check_needs();

  CaptiveTable out;
  std::map<std::string, std::size_t> key_lines;  // the run's key -> line
  std::map<std::string, std::size_t> tests;      // test -> rows
  for (auto line = std::next(header); line != lines_.cend(); ++line) {
    if (is_blank(line->text)) continue;
    if (const auto first = line->text.find_first_not_of(" \t"); line->text[first] == '#') {
      const auto setting = setting_line(line->text);
      if (setting && std::find(kSettings.begin(), kSettings.end(), setting->first) != kSettings.end())
        throw InputError(at(line->number), "setting '" + setting->first + "' after the header (line " +
                                               std::to_string(header_line_) +
                                               "); expected the settings before the header");
      continue;
    }
    // One field more than the header is enough to say how many were found.
    const auto fields = fields_of(*line, columns_.size() + 1);
    if (fields.size() != columns_.size())
      throw InputError(at(line->number), "found " + std::to_string(fields.size()) + " fields, expected " +
                                             std::to_string(columns_.size()) + " (as in the header on line " +
                                             std::to_string(header_line_) + ")");
    std::string test;
    ImportedRun run = read_row(*line, fields, test);
    if (!test.empty()) ++tests[test];
    const std::string key = describe(run.key) + '|' + disturbance_signature(run.key.disturbances);
    if (const auto [previous, inserted] = key_lines.emplace(key, line->number); !inserted)
      throw InputError(at(line->number), "run " + describe(run.key) + " appears twice (also on line " +
                                             std::to_string(previous->second) + "); expected one row per run");
    out.runs.push_back(std::move(run));
  }
  if (out.runs.empty()) throw InputError(at(header_line_), "header but no data rows; expected one row per run");

  // What was used, for the note and the import's identity.
  std::string forces, key = "form=" + std::string(to_string(system_));
  for (const auto& c : columns_)
    if (c.role == Role::Force) forces += (forces.empty() ? "" : ", ") + split_name_and_unit(c.header).name;
  std::string used;
  const auto add = [&](const char* symbol, const Resolved& value, const char* unit) {
    if (!value.value) return;
    used += std::string(", ") + symbol + " = " + shortest_number(*value.value) + " " + unit + " (" + value.origin + ")";
    key += std::string(" ") + symbol + "=" + shortest_number(*value.value);
  };
  add("L", length_, "m");
  if (const Column* speed = first(Role::Speed)) {
    used += ", U from column " + printable_text(speed->header, 60);
    key += " U=column";
  } else if (first(Role::Froude)) {
    used += ", U = Fn sqrt(g L)";
    key += " U=Fn";
  } else {
    add("U", speed_, "m/s");
  }
  add("rho", density_, "kg/m^3");
  add("d", draft_, "m");
  add("m", mass_, "kg");
  add("V", volume_, "m^3");
  if (system_ == NormalisationSystem::Bis || first(Role::Froude)) add("g", gravity_, "m/s^2");
  std::string convention;
  if (starboard_positive_) {
    convention = *starboard_positive_ ? "; beta = atan2(v, u) (fossen, " : "; beta = atan2(-v, u) (mmg, ";
    convention += convention_origin_ + ")";
    key += *starboard_positive_ ? " drift=fossen" : " drift=mmg";
  }
  std::string test_counts;
  for (const auto& [test, count] : tests)
    test_counts += (test_counts.empty() ? " (" : ", ") + std::to_string(count) + " " + test;
  if (!test_counts.empty()) test_counts += ")";
  out.note = printable_text(file_, 200) + ": captive-test table, " + std::to_string(out.runs.size()) + " runs" +
             test_counts + "; " + forces + " in " + std::string(normalisation_system_title(system_)) + " form (" +
             form_origin_ + ") at each row's speed" + used + convention;
  out.settings_key = key;
  return out;
}

}  // namespace

CaptiveTable parse_captive_table(std::string_view text, const std::string& file, const CaptiveTableOptions& options) {
  if (options.body.empty()) throw InputError("empty body name; expected --body NAME");
  return Reader(text, file, options).read();
}

CaptiveTableFile read_captive_table(const std::filesystem::path& file, const CaptiveTableOptions& options) {
  const SourceFile source = load_source_file(file);
  CaptiveTableFile out;
  out.batch.source.path = file.string();
  out.batch.source.sha256 = source.sha256;
  out.batch.source.size_bytes = source.bytes.size();
  out.batch.source.importer = std::string(kCaptiveTableImporter);
  out.batch.source.importer_version = std::string(kCaptiveTableImporterVersion);
  CaptiveTable table = parse_captive_table(source.bytes, file.string(), options);
  out.batch.runs = std::move(table.runs);
  out.note = std::move(table.note);
  out.settings_key = std::move(table.settings_key);
  return out;
}

}  // namespace hydrocoef
