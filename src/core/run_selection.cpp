#include "src/core/run_selection.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "src/core/error.hpp"
#include "src/core/names.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef {
namespace {

constexpr double kTolerance = 1e-9;

double tolerance_at(double value) { return kTolerance * std::max(1.0, std::abs(value)); }

[[noreturn]] void refuse(std::string_view clause, const std::string& found, const std::string& expected) {
  throw InputError("--where '" + printable_text(clause, 80) + "': found " + found + ", expected " + expected);
}

double parse_value(std::string_view text, std::string_view clause) {
  const auto value = parse_finite_number(text);
  if (!value) refuse(clause, "'" + printable_text(text, 40) + "'", "a finite number");
  return *value;
}

std::string_view op_text(SelectionClause::Op op) {
  switch (op) {
    case SelectionClause::Op::Equal: return "=";
    case SelectionClause::Op::NotEqual: return "!=";
    case SelectionClause::Op::Less: return "<";
    case SelectionClause::Op::LessEqual: return "<=";
    case SelectionClause::Op::Greater: return ">";
    case SelectionClause::Op::GreaterEqual: return ">=";
    case SelectionClause::Op::Range: return "=";
  }
  return "=";
}

}  // namespace

bool SelectionClause::matches(const RunKey& key) const {
  double x = 0.0;
  if (const auto i = velocity_index(name)) {
    x = key.nu_b[*i];
  } else if (const auto found = key.disturbances.find(name); found != key.disturbances.end()) {
    x = found->second;
  } else {
    return false;
  }
  switch (op) {
    case Op::Equal: return std::abs(x - value) <= tolerance_at(value);
    case Op::NotEqual: return std::abs(x - value) > tolerance_at(value);
    case Op::Less: return x < value - tolerance_at(value);
    case Op::LessEqual: return x <= value + tolerance_at(value);
    case Op::Greater: return x > value + tolerance_at(value);
    case Op::GreaterEqual: return x >= value - tolerance_at(value);
    case Op::Range: return x >= value - tolerance_at(value) && x <= upper + tolerance_at(upper);
  }
  return false;
}

bool RunSelection::matches(const RunKey& key, std::int64_t run_id) const {
  if (std::find(excluded_runs.begin(), excluded_runs.end(), run_id) != excluded_runs.end()) return false;
  return std::all_of(clauses.begin(), clauses.end(), [&](const SelectionClause& c) { return c.matches(key); });
}

std::string RunSelection::text() const {
  std::string out;
  for (const auto& c : clauses) {
    if (!out.empty()) out += ' ';
    out += c.name + std::string(op_text(c.op)) + shortest_number(c.value);
    if (c.op == SelectionClause::Op::Range) out += ":" + shortest_number(c.upper);
  }
  for (const auto id : excluded_runs)
    out += (out.empty() ? "" : " ") + std::string("exclude-run ") + std::to_string(id);
  return out;
}

std::vector<std::pair<std::string, double>> RunSelection::equalities() const {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& c : clauses)
    if (c.op == SelectionClause::Op::Equal) out.emplace_back(c.name, c.value);
  return out;
}

SelectionClause parse_selection_clause(std::string_view text) {
  SelectionClause clause;
  clause.text = std::string(text);
  const auto op_at = text.find_first_of("!<>=");
  if (op_at == std::string_view::npos || op_at == 0)
    refuse(text, "no comparison",
           "NAME=VALUE, NAME!=VALUE, NAME<VALUE, NAME<=VALUE, NAME>VALUE, NAME>=VALUE or NAME=LOW:HIGH");
  std::string_view name = text.substr(0, op_at);
  while (!name.empty() && name.back() == ' ') name.remove_suffix(1);
  while (!name.empty() && name.front() == ' ') name.remove_prefix(1);
  if (!velocity_index(name)) {
    if (const auto problem = name_problem(NameKind::Parameter, name))
      refuse(text, "name '" + printable_text(name, 40) + "' that " + *problem,
             "a velocity component u v w p q r or a disturbance parameter");
  }
  clause.name = std::string(name);
  std::string_view rest = text.substr(op_at);
  using Op = SelectionClause::Op;
  if (rest.rfind("!=", 0) == 0) {
    clause.op = Op::NotEqual, rest.remove_prefix(2);
  } else if (rest.rfind("<=", 0) == 0) {
    clause.op = Op::LessEqual, rest.remove_prefix(2);
  } else if (rest.rfind(">=", 0) == 0) {
    clause.op = Op::GreaterEqual, rest.remove_prefix(2);
  } else if (rest.rfind("==", 0) == 0) {
    clause.op = Op::Equal, rest.remove_prefix(2);
  } else if (rest.front() == '<') {
    clause.op = Op::Less, rest.remove_prefix(1);
  } else if (rest.front() == '>') {
    clause.op = Op::Greater, rest.remove_prefix(1);
  } else if (rest.front() == '=') {
    clause.op = Op::Equal, rest.remove_prefix(1);
  } else {
    refuse(text, "'" + std::string(1, rest.front()) + "'", "one of = != < <= > >=");
  }
  while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
  while (!rest.empty() && rest.back() == ' ') rest.remove_suffix(1);
  const auto colon = rest.find(':');
  if (colon != std::string_view::npos) {
    if (clause.op != Op::Equal)
      refuse(text, "a range after '" + std::string(op_text(clause.op)) + "'", "a range only as NAME=LOW:HIGH");
    clause.op = Op::Range;
    clause.value = parse_value(rest.substr(0, colon), text);
    clause.upper = parse_value(rest.substr(colon + 1), text);
    if (clause.upper < clause.value)
      refuse(text, "the range " + shortest_number(clause.value) + ":" + shortest_number(clause.upper), "LOW <= HIGH");
  } else {
    clause.value = parse_value(rest, text);
  }
  return clause;
}

RunSelection parse_selection(const std::vector<std::string>& where, const std::vector<std::int64_t>& excluded_runs) {
  RunSelection selection;
  for (const auto& text : where) selection.clauses.push_back(parse_selection_clause(text));
  for (const auto id : excluded_runs) {
    if (id <= 0) throw InputError("--exclude-run " + std::to_string(id) + ": expected a run id (a positive integer)");
    if (std::find(selection.excluded_runs.begin(), selection.excluded_runs.end(), id) == selection.excluded_runs.end())
      selection.excluded_runs.push_back(id);
  }
  std::sort(selection.excluded_runs.begin(), selection.excluded_runs.end());
  return selection;
}

RunSelection parse_selection_text(std::string_view text) {
  std::vector<std::string> where;
  std::vector<std::int64_t> excluded;
  std::size_t start = 0;
  std::vector<std::string_view> words;
  while (start < text.size()) {
    const auto space = text.find(' ', start);
    const auto word = text.substr(start, space == std::string_view::npos ? std::string_view::npos : space - start);
    if (!word.empty()) words.push_back(word);
    if (space == std::string_view::npos) break;
    start = space + 1;
  }
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (words[i] == "exclude-run") {
      if (i + 1 == words.size())
        throw InputError("selection '" + printable_text(text, 80) + "': 'exclude-run' without an id");
      std::int64_t id = 0;
      const auto word = words[++i];
      const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), id);
      if (ec != std::errc() || end != word.data() + word.size())
        throw InputError("selection '" + printable_text(text, 80) + "': found run id '" + printable_text(word, 20) +
                         "', expected an integer");
      excluded.push_back(id);
    } else {
      where.emplace_back(words[i]);
    }
  }
  return parse_selection(where, excluded);
}

}  // namespace hydrocoef
