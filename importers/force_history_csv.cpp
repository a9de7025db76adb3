#include "importers/force_history_csv.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "importers/history_text.hpp"
#include "importers/text_table.hpp"
#include "src/core/error.hpp"
#include "src/core/text.hpp"
#include "src/core/units.hpp"

namespace hydrocoef {
namespace {

std::string shown(std::string_view text) { return history_text::quoted_text(text); }

constexpr Dimension kTime{{0, 0, 1, 0}};
// A cell or header of a CSV line: a \r left by CRLF line ends is a blank too.
constexpr std::string_view kCellBlanks = " \t\r";

std::string normalized(std::string_view name) {
  std::string out;
  for (const char c : name)
    if (c != ' ' && c != '_' && c != '-' && c != '.' && c != '\t')
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

struct Cell {
  std::string text;  // as written, unquoted
  std::size_t column = 0;
  NameAndUnit name;
};

struct HeaderFound {
  std::vector<Cell> cells;
  char delimiter = 0;
  std::size_t line = 0;
  std::size_t data_offset = 0;  // byte offset after the header line
};

bool starts_with_number(std::string_view text) {
  text = trim(text, kCellBlanks);
  if (!text.empty() && text.front() == '"') text.remove_prefix(1);
  if (!text.empty() && (text.front() == '+' || text.front() == '-')) text.remove_prefix(1);
  return !text.empty() && (std::isdigit(static_cast<unsigned char>(text.front())) || text.front() == '.');
}

char delimiter_of(std::string_view line) {
  bool quoted = false;
  bool tab = false, semicolon = false;
  for (const char c : line) {
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    if (c == ',') return ',';
    if (c == '\t') tab = true;
    if (c == ';') semicolon = true;
  }
  return tab ? '\t' : semicolon ? ';' : 0;
}

// Blank-separated cells; a "[unit]" (which may hold blanks) joins the name
// before it.
std::vector<Cell> split_blank_cells(std::string_view line) {
  std::vector<Cell> cells;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    if (i >= line.size()) break;
    std::size_t j = i;
    if (line[i] == '[') {
      j = line.find(']', i);
      j = j == std::string_view::npos ? line.size() : j + 1;
      if (!cells.empty()) {
        cells.back().text += " " + std::string(line.substr(i, j - i));
        i = j;
        continue;
      }
    } else {
      while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
    }
    cells.push_back({std::string(line.substr(i, j - i)), i + 1, {}});
    i = j;
  }
  return cells;
}

HeaderFound find_header(std::string_view text, const std::string& file) {
  std::size_t offset = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
  std::size_t line = 1;
  std::string_view last_comment;
  std::size_t last_comment_line = 0;
  std::size_t last_comment_end = 0;
  std::size_t last_comment_base = 0;
  while (offset < text.size()) {
    const std::size_t newline = text.find('\n', offset);
    const std::size_t stop = newline == std::string_view::npos ? text.size() : newline;
    const std::size_t next = newline == std::string_view::npos ? text.size() : newline + 1;
    std::string_view raw = text.substr(offset, stop - offset);
    if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
    const std::string_view content = trim(raw, kCellBlanks);
    if (content.empty()) {
      offset = next;
      ++line;
      continue;
    }
    std::string_view header_text = raw;
    std::size_t header_line = line;
    std::size_t base = 0;
    std::size_t data_offset = next;
    if (content.front() == '#') {
      last_comment = content.substr(1);
      last_comment_line = line;
      last_comment_end = next;
      last_comment_base = static_cast<std::size_t>(content.data() + 1 - raw.data());
      offset = next;
      ++line;
      continue;
    }
    if (starts_with_number(content)) {
      if (last_comment_line == 0)
        throw InputError(SourceLocation{file, line, 1},
                         "the first line holds numbers, not column names; expected a header such as 'Time, Fx [N], "
                         "Fy [N]' (or '# Time Fx Fy' as a comment)");
      header_text = last_comment;
      header_line = last_comment_line;
      base = last_comment_base;
      data_offset = last_comment_end;
    }
    HeaderFound header;
    header.line = header_line;
    header.data_offset = data_offset;
    header.delimiter = delimiter_of(header_text);
    if (header.delimiter != 0) {
      const auto fields = split_fields(TextLine{header_text, header_line}, header.delimiter, file);
      for (const auto& field : fields) header.cells.push_back({field.text, field.column + base, {}});
    } else {
      header.cells = split_blank_cells(header_text);
      for (Cell& cell : header.cells) cell.column += base;
    }
    while (!header.cells.empty() && trim(header.cells.back().text, kCellBlanks).empty()) header.cells.pop_back();
    for (Cell& cell : header.cells) cell.name = split_name_and_unit(cell.text);
    return header;
  }
  throw InputError(SourceLocation{file}, "no header and no rows; expected a table of time and forces");
}

std::optional<HistoryAbscissa> abscissa_kind(const std::string& name) {
  static const std::array<const char*, 6> times{"time",          "t", "flowtime", "physicaltime", "solutiontime",
                                                "simulationtime"};
  static const std::array<const char*, 9> iterations{"iteration",      "iterations",      "iter",
                                                     "step",           "timestep",        "accumulatedtimestep",
                                                     "outeriteration", "iterationnumber", "it"};
  const std::string n = normalized(name);
  for (const char* t : times)
    if (n == t) return HistoryAbscissa::Time;
  for (const char* t : iterations)
    if (n == t) return HistoryAbscissa::Iteration;
  return std::nullopt;
}

struct Target {
  std::size_t component = 0;
  ForcePart part = ForcePart::Total;
  ComponentNaming naming = ComponentNaming::SourceAxes;
};

std::optional<ForcePart> part_word(std::string_view word) {
  if (word == "total") return ForcePart::Total;
  if (word == "pressure") return ForcePart::Pressure;
  if (word == "viscous") return ForcePart::Viscous;
  if (word == "porous") return ForcePart::Porous;
  return std::nullopt;
}

std::optional<Target> recognise(const std::string& name) {
  static const std::array<std::pair<const char*, std::size_t>, 18> source{{
      {"fx", 0},
      {"fy", 1},
      {"fz", 2},
      {"forcex", 0},
      {"forcey", 1},
      {"forcez", 2},
      {"mx", 3},
      {"my", 4},
      {"mz", 5},
      {"momentx", 3},
      {"momenty", 4},
      {"momentz", 5},
      {"tx", 3},
      {"ty", 4},
      {"tz", 5},
      {"torquex", 3},
      {"torquey", 4},
      {"torquez", 5},
  }};
  static const std::array<const char*, 5> parts{"", "total", "pressure", "viscous", "porous"};
  const std::string n = normalized(name);
  for (const auto& [comp, index] : source) {
    for (const char* part : parts) {
      const std::string p(part);
      if (n == std::string(comp) + p || (!p.empty() && n == p + comp))
        return Target{index, part_word(p).value_or(ForcePart::Total), ComponentNaming::SourceAxes};
    }
  }
  // SNAME letters, upper case, with an optional part word before or after.
  std::string rest(trim(name, kCellBlanks));
  std::string lower = rest;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  ForcePart part = ForcePart::Total;
  for (const char* word : parts) {
    const std::string w(word);
    if (w.empty()) continue;
    if (lower.size() > w.size() && lower.substr(lower.size() - w.size()) == w) {
      rest.resize(rest.size() - w.size());
      part = *part_word(w);
      break;
    }
    if (lower.size() > w.size() && lower.substr(0, w.size()) == w) {
      rest = rest.substr(w.size());
      part = *part_word(w);
      break;
    }
  }
  const std::string_view letter = trim(std::string_view(rest), kCellBlanks);
  std::string_view stripped = letter;
  while (!stripped.empty() && (stripped.front() == '_' || stripped.front() == '-')) stripped.remove_prefix(1);
  while (!stripped.empty() && (stripped.back() == '_' || stripped.back() == '-')) stripped.remove_suffix(1);
  stripped = trim(stripped, kCellBlanks);
  if (stripped.size() == 1) {
    const std::string_view letters = "XYZKMN";
    const std::size_t index = letters.find(stripped[0]);
    if (index != std::string_view::npos) return Target{index, part, ComponentNaming::BodyAxes};
  }
  return std::nullopt;
}

// "Fx", "Fx:pressure", "N", "N:viscous" -> target.
Target mapping_key(const std::string& key) {
  const std::size_t colon = key.find(':');
  const std::string name = key.substr(0, colon);
  const std::string part_text = colon == std::string::npos ? "" : key.substr(colon + 1);
  const auto part = part_text.empty() ? std::optional<ForcePart>(ForcePart::Total) : part_word(part_text);
  static const std::array<const char*, 6> source{"Fx", "Fy", "Fz", "Mx", "My", "Mz"};
  static const std::array<const char*, 6> body{"X", "Y", "Z", "K", "M", "N"};
  for (std::size_t c = 0; c < 6 && part; ++c) {
    if (name == source[c]) return {c, *part, ComponentNaming::SourceAxes};
    if (name == body[c]) return {c, *part, ComponentNaming::BodyAxes};
  }
  throw InputError("unknown component " + shown(key) +
                   " in a column mapping; expected Fx Fy Fz Mx My Mz or X Y Z K M N, optionally with :total, "
                   ":pressure, :viscous or :porous");
}

std::string column_list(const std::vector<Cell>& cells) {
  std::string text;
  for (std::size_t i = 0; i < cells.size(); ++i) text += (i ? ", " : "") + shown(cells[i].text);
  return text;
}

std::string key_of(const Target& t) {
  std::string key(component_name(static_cast<HistoryComponent>(t.component), t.naming));
  if (t.part != ForcePart::Total) key += ":" + std::string(part_name(t.part));
  return key;
}

struct Used {
  std::size_t cell;
  Target target;
};

// The header read and the places the rows go; the sink points into it, so it
// is made on the heap and never moved.
struct CsvState {
  std::string file;
  HeaderFound header;
  HistoryAbscissa kind = HistoryAbscissa::Time;
  std::vector<Used> used;
  std::vector<std::string> notes;
  history_text::FileLayout rows;
  ForceHistory history;
  std::vector<std::uint32_t> lines;
  std::vector<double> scale_of_field;   // per parsed field
  std::vector<std::size_t> field_cell;  // per parsed field
};

std::unique_ptr<CsvState> prepare(std::string_view text, const std::string& file,
                                  const ForceHistoryCsvOptions& options) {
  auto state = std::make_unique<CsvState>();
  state->file = file;
  state->header = find_header(text, file);
  const HeaderFound& header = state->header;
  const std::vector<Cell>& cells = header.cells;
  const auto at = [&](const Cell& cell) { return SourceLocation{file, header.line, cell.column}; };
  if (cells.size() < 2)
    throw InputError(SourceLocation{file, header.line, 0},
                     "the header names " + std::to_string(cells.size()) +
                         " column; expected a time or iteration column and force or moment columns");

  // Which cell matches a header text (whole, or the name without its unit).
  const auto matching = [&](const std::string& wanted, const std::string& what) -> std::size_t {
    std::vector<std::size_t> found;
    for (std::size_t c = 0; c < cells.size(); ++c)
      if (cells[c].text == wanted || cells[c].name.name == wanted) found.push_back(c);
    if (found.empty())
      throw InputError(SourceLocation{file, header.line, 0},
                       what + ": no column " + shown(wanted) + "; the columns are " + column_list(cells));
    if (found.size() > 1)
      throw InputError(at(cells[found[1]]), what + ": " + shown(wanted) + " matches column " +
                                                std::to_string(found[0] + 1) + " and column " +
                                                std::to_string(found[1] + 1) + "; expected one");
    return found.front();
  };

  // The abscissa.
  std::optional<std::size_t> abscissa_column;
  HistoryAbscissa kind = HistoryAbscissa::Time;
  if (options.abscissa_column) {
    abscissa_column = matching(*options.abscissa_column, "the abscissa column");
    kind = abscissa_kind(cells[*abscissa_column].name.name).value_or(HistoryAbscissa::Time);
  } else {
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const auto k = abscissa_kind(cells[c].name.name);
      if (!k) continue;
      if (abscissa_column)
        throw InputError(at(cells[c]), "a second time or iteration column " + shown(cells[c].text) + " after " +
                                           shown(cells[*abscissa_column].text) +
                                           "; expected one (name it with abscissa_column)");
      abscissa_column = c;
      kind = *k;
    }
    if (!abscissa_column)
      throw InputError(SourceLocation{file, header.line, 0},
                       "no time or iteration column among " + column_list(cells) +
                           "; expected one named Time, t, Flow Time, Iteration, Iter, Step or Accumulated Time Step");
  }
  if (options.abscissa) kind = *options.abscissa;

  // The components.
  std::vector<Used>& used = state->used;
  if (!options.columns.empty()) {
    for (const auto& [key, header_text] : options.columns) {
      const Target target = mapping_key(key);
      used.push_back({matching(header_text, "the column for " + key), target});
    }
  } else {
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (c == *abscissa_column) continue;
      if (const auto target = recognise(cells[c].name.name)) used.push_back({c, *target});
    }
    if (used.empty())
      throw InputError(SourceLocation{file, header.line, 0},
                       "no force or moment column among " + column_list(cells) +
                           "; expected names such as Fx, Force X, Mz, Torque Z (or X Y Z K M N), or a mapping");
  }
  for (std::size_t i = 0; i < used.size(); ++i) {
    if (used[i].cell == *abscissa_column)
      throw InputError(at(cells[used[i].cell]),
                       shown(cells[used[i].cell].text) + " is the abscissa column; expected a force or moment column");
    if (used[i].target.naming != used.front().target.naming)
      throw InputError(at(cells[used[i].cell]),
                       "column " + shown(cells[used[i].cell].text) + " names a " +
                           (used[i].target.naming == ComponentNaming::BodyAxes ? "body-axis" : "solver-axis") +
                           " component but " + shown(cells[used.front().cell].text) +
                           " does not; expected Fx..Mz (solver axes) or X..N (body axes), not both");
    for (std::size_t j = 0; j < i; ++j) {
      if (used[j].target.component == used[i].target.component && used[j].target.part == used[i].target.part)
        throw InputError(at(cells[used[i].cell]), "column " + shown(cells[used[i].cell].text) + " gives " +
                                                      key_of(used[i].target) + " as column " +
                                                      shown(cells[used[j].cell].text) + " does; expected one");
      if (used[j].cell == used[i].cell)
        throw InputError(at(cells[used[i].cell]),
                         "column " + shown(cells[used[i].cell].text) + " is mapped twice; expected one component each");
    }
  }

  // Units.
  std::vector<std::string>& notes = state->notes;
  const auto scale_of = [&](const Cell& cell, const std::string& unit_key, const Dimension& expected,
                            const char* kind_name) -> double {
    std::string unit_text = cell.name.has_unit ? cell.name.unit : "";
    bool given = cell.name.has_unit;
    if (!given) {
      if (const auto u = options.units.find(unit_key); u != options.units.end()) {
        unit_text = u->second;
        given = true;
      }
    }
    if (!given) {
      if (expected != kDimensionless)
        notes.push_back("column " + shown(cell.text) + " has no unit: SI (" + si_unit_name(expected) + ") assumed");
      return 1.0;
    }
    Unit unit;
    try {
      unit = parse_unit(unit_text);
    } catch (const InputError& error) {
      throw InputError(at(cell), "column " + shown(cell.text) + ": " + error.what());
    }
    if (!dimension_matches(unit.dimension, expected))
      throw InputError(at(cell), "column " + shown(cell.text) + ": the unit " + shown(unit_text) + " is " +
                                     si_unit_name(unit.dimension) + "; expected " + kind_name + " (" +
                                     si_unit_name(expected) + ")");
    return unit.scale;
  };
  const double abscissa_scale =
      scale_of(cells[*abscissa_column], "time", kind == HistoryAbscissa::Time ? kTime : kDimensionless,
               kind == HistoryAbscissa::Time ? "a time" : "an iteration count");
  std::vector<double> scales;
  for (const Used& u : used)
    scales.push_back(scale_of(cells[u.cell], key_of(u.target), u.target.component < 3 ? kForce : kMoment,
                              u.target.component < 3 ? "a force" : "a moment"));

  // Rows.
  state->kind = kind;
  history_text::RowSyntax& syntax = state->rows.syntax;
  syntax.columns = cells.size();
  syntax.delimiter = header.delimiter;
  syntax.skip.assign(cells.size(), true);
  syntax.skip[*abscissa_column] = false;
  for (const Used& u : used) syntax.skip[u.cell] = false;
  for (const Cell& cell : cells) syntax.names.push_back(cell.text);
  state->rows.data_offset = header.data_offset;
  state->rows.first_line = header.line + 1;
  ForceHistory& history = state->history;
  history.abscissa = kind;
  history_text::RowSink& sink = state->rows.sink;
  sink.lines = &state->lines;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (syntax.skip[c]) continue;
    state->field_cell.push_back(c);
    if (c == *abscissa_column) {
      sink.columns.push_back(&history.abscissa_values);
      state->scale_of_field.push_back(abscissa_scale);
      continue;
    }
    for (std::size_t k = 0; k < used.size(); ++k)
      if (used[k].cell == c) {
        sink.columns.push_back(
            &history.values(used[k].target.part, static_cast<HistoryComponent>(used[k].target.component)));
        state->scale_of_field.push_back(scales[k]);
      }
  }
  return state;
}

history_text::RowOptions row_options_of(const ForceHistoryCsvOptions& options) {
  history_text::RowOptions row_options;
  row_options.drop_incomplete_last_row = options.drop_incomplete_last_row;
  row_options.threads = options.threads;
  return row_options;
}

ForceHistory finish(CsvState& state, const history_text::ParsedRows& rows, std::uint64_t size_bytes) {
  const std::string& file = state.file;
  const HeaderFound& header = state.header;
  const std::vector<Cell>& cells = header.cells;
  const history_text::RowSyntax& syntax = state.rows.syntax;
  const history_text::RowSink& sink = state.rows.sink;
  const std::vector<std::uint32_t>& lines = state.lines;
  const std::vector<Used>& used = state.used;
  const HistoryAbscissa kind = state.kind;
  std::vector<std::string>& notes = state.notes;
  const auto& scale_of_field = state.scale_of_field;
  const auto& field_cell = state.field_cell;
  if (rows.rows == 0)
    throw InputError(SourceLocation{file, header.line, 0}, "no rows after the header; expected at least one sample");
  const std::size_t n = rows.rows;

  // To SI, in place (the sink points into state.history).
  for (std::size_t k = 0; k < sink.columns.size(); ++k) {
    if (scale_of_field[k] == 1.0) continue;
    std::vector<double>& values = *sink.columns[k];
    for (std::size_t i = 0; i < n; ++i) {
      values[i] *= scale_of_field[k];
      if (!std::isfinite(values[i]))
        throw InputError(SourceLocation{file, lines[i], 0},
                         "column " + shown(cells[field_cell[k]].text) + " overflows when converted to SI");
    }
  }
  ForceHistory history = std::move(state.history);
  for (std::size_t i = 1; i < n; ++i)
    if (!(history.abscissa_values[i] > history.abscissa_values[i - 1])) {
      char values[64];
      std::snprintf(values, sizeof values, "%.9g is not after %.9g", history.abscissa_values[i],
                    history.abscissa_values[i - 1]);
      throw InputError(SourceLocation{file, lines[i], 0}, std::string(abscissa_name(kind)) + " " + values +
                                                              " on line " + std::to_string(lines[i - 1]) +
                                                              "; expected increasing values");
    }
  bool any_force = false, any_moment = false;
  for (const Used& u : used) (u.target.component < 3 ? any_force : any_moment) = true;
  // Totals from parts where the table gives only parts.
  for (std::size_t component = 0; component < kHistoryComponents; ++component) {
    if (!history.series[0][component].empty()) continue;
    std::vector<std::string> parts;
    for (std::size_t part = 1; part < kForceParts; ++part)
      if (!history.series[part][component].empty()) parts.emplace_back(part_name(static_cast<ForcePart>(part)));
    if (parts.empty()) continue;
    auto& total = history.series[0][component];
    total.assign(n, 0.0);
    for (std::size_t part = 1; part < kForceParts; ++part)
      if (!history.series[part][component].empty())
        for (std::size_t i = 0; i < n; ++i) total[i] += history.series[part][component][i];
    std::string list;
    for (const auto& p : parts) list += (list.empty() ? "" : " + ") + p;
    notes.push_back(std::string(component_name(static_cast<HistoryComponent>(component), used.front().target.naming)) +
                    ": total = " + list + " (the table gives no total)");
  }

  history.frame.naming = used.front().target.naming;
  history.frame.description = history.frame.naming == ComponentNaming::BodyAxes
                                  ? "body axes (SNAME X Y Z K M N) as the table names them; moment centre not stated"
                                  : "the source's axes as written; moment centre not stated";
  HistorySourceFile source;
  source.path = file;
  source.format = std::string(kForceHistoryCsvImporter);
  source.size_bytes = size_bytes;
  source.rows = n;
  source.rows_used = n;
  history.files.push_back(std::move(source));
  std::vector<SampleOrigin> origins(n);
  for (std::size_t i = 0; i < n; ++i) origins[i] = {0, lines[i]};
  if (any_force) history.force_origin = origins;
  if (any_moment) history.moment_origin = std::move(origins);

  std::vector<std::string> unused;
  for (std::size_t c = 0; c < cells.size(); ++c)
    if (syntax.skip[c]) unused.push_back(shown(cells[c].text));
  if (!unused.empty()) {
    std::string list;
    for (const auto& u : unused) list += (list.empty() ? "" : ", ") + u;
    notes.push_back("columns not read: " + list);
  }
  if (rows.dropped_last_row) notes.push_back(file + ": the last row was cut short and is left out");
  history.notes = std::move(notes);
  check_force_history(history);
  return history;
}

}  // namespace

ForceHistory parse_force_history_csv(std::string_view text, const std::string& file,
                                     const ForceHistoryCsvOptions& options) {
  const std::unique_ptr<CsvState> state = prepare(text, file, options);
  const history_text::ParsedRows rows =
      history_text::parse_rows(text.substr(state->rows.data_offset), state->rows.first_line, state->rows.syntax, file,
                               state->rows.sink, row_options_of(options));
  return finish(*state, rows, text.size());
}

ForceHistory read_force_history_csv(const std::filesystem::path& file, const ForceHistoryCsvOptions& options) {
  std::unique_ptr<CsvState> state;
  const history_text::StreamedRows streamed = history_text::parse_file_rows(
      file,
      [&](std::string_view head) {
        state = prepare(head, file.string(), options);
        return state->rows;
      },
      row_options_of(options), options.compute_sha256);
  ForceHistory history = finish(*state, streamed.rows, streamed.size_bytes);
  history.files.front().sha256 = streamed.sha256;
  return history;
}

}  // namespace hydrocoef
