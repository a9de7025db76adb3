// Reads the wall force and moment summary of a CFX solver output file (see
// cfx_out.hpp).
#include "importers/cfx_out.hpp"

#include "importers/cfx_ccl.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>

#include "src/core/error.hpp"
#include "src/core/file_bytes.hpp"
#include "src/core/names.hpp"
#include "src/core/text.hpp"
#include "src/core/units.hpp"

namespace hydrocoef {
namespace {

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

/// A banner's title line: "| ... Force ... Moment ... |".
bool is_summary_banner(std::string_view line) {
  const std::string_view t = trim(line);
  if (t.size() < 2 || t.front() != '|' || t.back() != '|') return false;
  const std::string title = lower(t.substr(1, t.size() - 2));
  return title.find("force") != std::string::npos && title.find("moment") != std::string::npos &&
         title.find("summary") != std::string::npos;
}

/// A banner border or a rule of '=': the end of a section.
bool is_section_rule(std::string_view line) {
  const std::string_view t = trim(line);
  if (t.size() < 10) return false;
  if (t.front() == '+') return t.find_first_not_of("+-") == std::string_view::npos;
  return t.find_first_not_of('=') == std::string_view::npos;
}

bool is_dash_rule(std::string_view t) { return !t.empty() && t.find_first_not_of("- ") == std::string_view::npos; }

struct Line {
  std::string_view text;
  std::size_t number = 0;  ///< 1-based
  std::size_t offset = 0;  ///< of the line in the file
};

std::vector<Line> split_lines(std::string_view text) {
  std::vector<Line> lines;
  std::size_t start = 0, number = 1;
  while (start < text.size()) {
    auto end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back({line, number++, start});
    start = end + 1;
  }
  return lines;
}

std::optional<double> number_of(std::string_view token) {
  double value = 0.0;
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec != std::errc() || end != token.data() + token.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

/// Runs of blanks as one space, as CFX compares names.

enum class Part { Pressure, Viscous };
enum class Quantity { Force, Moment };

struct Table {
  Part part = Part::Pressure;
  Quantity quantity = Quantity::Force;
  double scale = 1.0;
  std::size_t line = 0;
};

std::optional<std::array<double, 3>>& slot(CfxWallLoads& loads, const Table& table) {
  if (table.quantity == Quantity::Force)
    return table.part == Part::Pressure ? loads.pressure_force : loads.viscous_force;
  return table.part == Part::Pressure ? loads.pressure_moment : loads.viscous_moment;
}

class SummaryParser {
 public:
  SummaryParser(std::string_view text, std::string file) : text_(text) { out_.file = std::move(file); }

  CfxWallForceSummary parse() {
    const auto lines = split_lines(text_);
    std::size_t banner = lines.size();
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (is_summary_banner(lines[i].text)) {
        banner = i;
        ++out_.summaries;
      }
    if (banner == lines.size())
      throw InputError(SourceLocation{out_.file},
                       "no wall force and moment summary; expected a CFX solver output file of a finished run (its "
                       "'Wall Force and Moment Summary' with Pressure Force and Viscous Force tables), or the "
                       "run's monitors exported with cfx5mondata beside it");
    out_.line = lines[banner].number;
    std::size_t i = banner + 1;
    if (i < lines.size() && is_section_rule(lines[i].text)) ++i;  // the banner's closing border
    for (; i < lines.size(); ++i) {
      const Line& line = lines[i];
      if (is_section_rule(line.text)) break;
      read_line(line);
    }
    finish_table();
    if (!table_seen_)
      throw InputError(SourceLocation{out_.file, out_.line, 0},
                       "a wall force and moment summary without tables; expected 'Pressure Force (N)' and "
                       "'Viscous Force (N)' tables of boundaries");
    for (const auto& group : out_.groups)
      if (!group.totals.pressure_force && !group.totals.viscous_force)
        throw InputError(SourceLocation{out_.file, out_.line, 0},
                         "domain group '" + printable_text(group.name, 80) +
                             "' has no 'Domain Group Totals' row; expected one after its boundaries");
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(const Line& line, std::string_view at, const std::string& message) const {
    const std::size_t column =
        at.data() >= line.text.data() ? static_cast<std::size_t>(at.data() - line.text.data()) + 1 : 1;
    throw InputError(SourceLocation{out_.file, line.number, column}, message);
  }

  /// "Pressure Force (N)", "Viscous Moment [N m]": the table that follows.
  std::optional<Table> table_title(const Line& line, std::string_view t) const {
    const std::string l = lower(t);
    Table table;
    std::size_t at = 0;
    if (l.rfind("pressure", 0) == 0) {
      table.part = Part::Pressure;
      at = 8;
    } else if (l.rfind("viscous", 0) == 0) {
      table.part = Part::Viscous;
      at = 7;
    } else {
      return std::nullopt;
    }
    const std::string rest = collapse_blanks(l.substr(at));
    if (rest.rfind("force", 0) == 0)
      table.quantity = Quantity::Force;
    else if (rest.rfind("moment", 0) == 0)
      table.quantity = Quantity::Moment;
    else
      return std::nullopt;
    const auto open = t.find_first_of("([");
    const auto close = t.find_last_of(")]");
    const char* expected =
        table.quantity == Quantity::Force ? "a force unit (N, kN ...)" : "a moment unit (N m, kN m ...)";
    if (open == std::string_view::npos || close == std::string_view::npos || close < open)
      fail(line, t,
           "table title '" + printable_text(t, 60) + "' without a unit; expected " + expected + " in parentheses");
    const std::string_view unit_text = t.substr(open + 1, close - open - 1);
    Unit unit;
    try {
      unit = parse_unit(unit_text);
    } catch (const InputError& e) {
      fail(line, unit_text, std::string("table unit: ") + e.what());
    }
    if (!dimension_matches(unit.dimension, table.quantity == Quantity::Force ? kForce : kMoment))
      fail(line, unit_text, "table unit '" + printable_text(unit_text, 30) + "' is not " + expected);
    table.scale = unit.scale;
    table.line = line.number;
    return table;
  }

  void finish_table() { seen_in_table_.clear(); }

  CfxDomainGroup& group_named(const std::string& name) {
    for (auto& g : out_.groups)
      if (g.name == name) return g;
    out_.groups.push_back(CfxDomainGroup{name, {}, {}});
    return out_.groups.back();
  }

  void read_line(const Line& line) {
    const std::string_view t = trim(line.text);
    if (t.empty() || is_dash_rule(t)) return;
    if (auto table = table_title(line, t)) {
      finish_table();
      table_ = *table;
      table_seen_ = true;
      group_ = nullptr;
      return;
    }
    if (!table_seen_) return;  // notes before the first table
    const std::string l = lower(t);
    if (l.find("x-comp") != std::string::npos) return;  // the component header
    if (l.rfind("domain group totals", 0) == 0) {
      if (!group_) fail(line, t, "'Domain Group Totals' before any 'Domain Group:' line; expected the group first");
      std::string_view values = t.substr(std::string_view("domain group totals").size());
      values = trim(values);
      if (!values.empty() && values.front() == ':') values.remove_prefix(1);
      auto& target = slot(group_->totals, table_);
      if (target) fail(line, t, "a second 'Domain Group Totals' row in one table; expected one per group");
      target = three_numbers(line, values, "'Domain Group Totals :' and three numbers");
      if (group_->totals.line == 0) group_->totals.line = line.number;
      return;
    }
    if (l.rfind("domain group", 0) == 0) {
      const auto colon = t.find(':');
      if (colon == std::string_view::npos)
        fail(line, t, "'" + printable_text(t, 60) + "'; expected 'Domain Group: NAME'");
      const std::string name = collapse_blanks(t.substr(colon + 1));
      if (name.empty()) fail(line, t, "a 'Domain Group:' line without a name; expected the group's name");
      check_name(NameKind::Field, name, SourceLocation{out_.file, line.number, 0}, "a domain group");
      group_ = &group_named(name);
      return;
    }
    // A boundary row: a name, then three numbers.
    std::vector<std::string_view> tokens;
    std::size_t start = 0;
    while (start < t.size()) {
      const auto first = t.find_first_not_of(" \t", start);
      if (first == std::string_view::npos) break;
      auto end = t.find_first_of(" \t", first);
      if (end == std::string_view::npos) end = t.size();
      tokens.push_back(t.substr(first, end - first));
      start = end;
    }
    if (tokens.size() < 4)
      fail(line, t,
           "'" + printable_text(t, 60) + "' in the " + table_name() +
               " table; expected a boundary name and three numbers (x, y, z)");
    const std::string_view numbers(tokens[tokens.size() - 3].data(),
                                   static_cast<std::size_t>(t.data() + t.size() - tokens[tokens.size() - 3].data()));
    const std::string_view name_text(t.data(), static_cast<std::size_t>(tokens[tokens.size() - 3].data() - t.data()));
    const auto values = three_numbers(line, numbers, "a boundary name and three numbers (x, y, z)");
    if (!group_)
      fail(line, t,
           "boundary row before any 'Domain Group:' line in the " + table_name() +
               " table; expected 'Domain Group: NAME' first");
    const std::string name = collapse_blanks(name_text);
    check_name(NameKind::Field, name, SourceLocation{out_.file, line.number, 1}, "a boundary");
    if (std::find(seen_in_table_.begin(), seen_in_table_.end(), group_->name + "\n" + name) != seen_in_table_.end())
      fail(line, t,
           "boundary '" + printable_text(name, 80) + "' twice in the " + table_name() + " table of domain group '" +
               printable_text(group_->name, 80) + "'; expected each once");
    seen_in_table_.push_back(group_->name + "\n" + name);
    auto it = std::find_if(group_->boundaries.begin(), group_->boundaries.end(),
                           [&](const auto& b) { return b.first == name; });
    if (it == group_->boundaries.end()) {
      group_->boundaries.emplace_back(name, CfxWallLoads{});
      it = std::prev(group_->boundaries.end());
      it->second.line = line.number;
    }
    slot(it->second, table_) = values;
  }

  std::array<double, 3> three_numbers(const Line& line, std::string_view text, const std::string& expected) const {
    std::array<double, 3> out{};
    std::size_t count = 0, start = 0;
    text = trim(text);
    while (start < text.size()) {
      const auto first = text.find_first_not_of(" \t", start);
      if (first == std::string_view::npos) break;
      auto end = text.find_first_of(" \t", first);
      if (end == std::string_view::npos) end = text.size();
      const std::string_view token = text.substr(first, end - first);
      const auto value = number_of(token);
      if (!value || count == 3)
        fail(line, token,
             "'" + printable_text(token, 30) + "' in the " + table_name() + " table; expected " + expected);
      out[count++] = *value * table_.scale;
      start = end;
    }
    if (count != 3)
      fail(line, text, std::to_string(count) + " numbers in the " + table_name() + " table; expected " + expected);
    return out;
  }

  std::string table_name() const {
    return std::string(table_.part == Part::Pressure ? "Pressure " : "Viscous ") +
           (table_.quantity == Quantity::Force ? "Force" : "Moment");
  }

  std::string_view text_;
  CfxWallForceSummary out_;
  Table table_;
  bool table_seen_ = false;
  CfxDomainGroup* group_ = nullptr;
  std::vector<std::string> seen_in_table_;
};

}  // namespace

CfxWallForceSummary parse_cfx_wall_forces(std::string_view text, const std::string& file) {
  return SummaryParser(text, file).parse();
}

CfxWallForceSummary read_cfx_wall_forces(const std::filesystem::path& file) {
  const FileBytes bytes(file);
  return parse_cfx_wall_forces(bytes.view(), file.string());
}

bool has_cfx_wall_forces(std::string_view text) {
  for (const auto& line : split_lines(text))
    if (is_summary_banner(line.text)) return true;
  return false;
}

bool file_has_cfx_wall_forces(const std::filesystem::path& file) {
  try {
    const FileBytes bytes(file);
    return has_cfx_wall_forces(bytes.view());
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace hydrocoef
