#include "importers/cfx_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <numeric>
#include <utility>
#include <vector>

#include "importers/text_table.hpp"
#include "src/core/error.hpp"
#include "src/core/names.hpp"
#include "src/core/source_file.hpp"
#include "src/core/text.hpp"
#include "src/core/units.hpp"

namespace hydrocoef {
namespace {

constexpr std::string_view kHeaderStart = "accumulated timestep";
constexpr std::string_view kExpectedHeader =
    "a header starting with 'Accumulated Timestep' (cfx5mondata -out or Solver Manager Export Plot Data)";
constexpr std::string_view kTruncated = "the last line looks truncated (is the file still being written?)";
// Accumulated timesteps are whole numbers; beyond 2^53 a double no longer holds them exactly.
constexpr double kLargestTimestep = 9007199254740992.0;
constexpr std::size_t kColumnsListed = 30;
// A library message quoting file text is escaped but never cut.
constexpr std::size_t kWholeMessage = std::string_view::npos;

bool is_alnum(char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_blank(std::string_view text) { return text.find_first_not_of(" \t") == std::string_view::npos; }

std::string printable(std::string_view text, std::size_t max_characters = 200) {
  return printable_text(text, max_characters);
}

// Built by appending: GCC 12 warns falsely (-Wrestrict) on "'" + std::string(x) + "'" in Release builds.
std::string in_quotes(std::string_view text) {
  std::string out;
  out += '\'';
  out += printable(text);
  out += '\'';
  return out;
}

bool is_printable_ascii(std::string_view text) {
  return std::all_of(text.begin(), text.end(), [](char c) { return c >= 0x20 && c < 0x7F; });
}

bool starts_with_header(std::string_view line) {
  const auto first = line.find_first_not_of(" \t");
  if (first == std::string_view::npos) return false;
  line.remove_prefix(first);
  if (line.front() == '"') line.remove_prefix(1);
  if (line.size() < kHeaderStart.size()) return false;
  for (std::size_t i = 0; i < kHeaderStart.size(); ++i)
    if (lower(line[i]) != kHeaderStart[i]) return false;
  return true;
}

/// One header field and the names a user may call it by.
struct HeaderColumn {
  std::string text;        ///< as written, unquoted ("USER POINT,Fx", "Fx1 [N]")
  NameAndUnit split;       ///< name without the unit, and the unit
  std::string short_name;  ///< after the category of a "CATEGORY,Name" header, else the name
  std::size_t column = 0;  ///< 1-based byte column in the header line
};

std::string describe_column(const HeaderColumn& column) {
  return in_quotes(column.text) + " (column " + std::to_string(column.column) + ")";
}

std::string list_columns(const std::vector<HeaderColumn>& columns) {
  std::string out;
  for (std::size_t i = 1; i < columns.size(); ++i) {  // column 0 is the timestep
    if (i > kColumnsListed) {
      out += " and " + std::to_string(columns.size() - i) + " more";
      break;
    }
    if (i > 1) out += ", ";
    out += in_quotes(columns[i].text);
  }
  return out.empty() ? "none besides the timestep" : out;
}

// The component a monitor name stands for by the usual spellings, or nullopt.
// The spelling must start the name or follow a character that is neither a
// letter nor a digit, so that "Flux" or "Max" are never taken for forces.
std::optional<std::size_t> recognise_component(std::string_view name) {
  std::string text;
  for (const char c : name) text += lower(c);
  std::size_t end = text.size();
  while (end > 0 && text[end - 1] >= '0' && text[end - 1] <= '9') --end;
  if (end == 0) return std::nullopt;
  const char axis = text[end - 1];
  if (axis != 'x' && axis != 'y' && axis != 'z') return std::nullopt;
  const auto axis_index = static_cast<std::size_t>(axis - 'x');
  std::string_view stem = std::string_view(text).substr(0, end - 1);
  if (!stem.empty() && (stem.back() == ' ' || stem.back() == '_')) stem.remove_suffix(1);
  // Spelling -> index of its x component.
  static constexpr std::array<std::pair<std::string_view, std::size_t>, 6> kSpellings = {
      {{"force", 0}, {"f", 0}, {"torque", 3}, {"moment", 3}, {"m", 3}, {"t", 3}}};
  for (const auto& [word, first_component] : kSpellings) {
    if (!stem.ends_with(word)) continue;
    const std::size_t start = stem.size() - word.size();
    if (start == 0 || !is_alnum(stem[start - 1])) return first_component + axis_index;
  }
  return std::nullopt;
}

// "USER POINT,Fx" -> "Fx" (cfx5mondata); "Monitor Point: Hull Fx" -> "Hull Fx" (Export Plot Data).
std::string without_category(const std::string& name) {
  if (const auto comma = name.find(','); comma != std::string::npos)
    return std::string(trim(name.substr(comma + 1), kSpaceTab));
  if (const auto colon = name.find(": "); colon != std::string::npos)
    return std::string(trim(name.substr(colon + 2), kSpaceTab));
  return name;
}

bool names_column(const HeaderColumn& column, std::string_view given) {
  return given == column.text || given == column.split.name || given == column.short_name;
}

void check_options(const CfxMonitorOptions& options) {
  if (options.key.body.empty()) throw InputError("empty body name; expected --body NAME");
  if (options.average_last == 0)
    throw InputError("average over the last 0 iterations; expected 1 (the last value) or more");
  for (const auto& [component, monitor] : options.monitors) {
    if (!force_index(component))
      throw InputError("monitor mapping for " + in_quotes(component) + ": expected a component X Y Z K M N");
    if (trim(monitor, kSpaceTab).empty())
      throw InputError("monitor mapping for " + component + " names no monitor; expected e.g. " + component +
                       "=\"USER POINT,Fx\" or " + component + "=Fx1");
  }
  for (const auto& [component, unit] : options.units)
    if (!force_index(component))
      throw InputError("unit for " + in_quotes(component) + ": expected a component X Y Z K M N");
}

// Which header column gives each component: the mapping if any, else by name.
std::array<std::optional<std::size_t>, 6> assign_columns(const std::vector<HeaderColumn>& columns,
                                                         const CfxMonitorOptions& options,
                                                         const SourceLocation& header) {
  std::array<std::optional<std::size_t>, 6> column_of;
  if (!options.monitors.empty()) {
    for (const auto& [component, given] : options.monitors) {
      const std::string_view name = trim(given, kSpaceTab);
      std::vector<std::size_t> matches;
      for (std::size_t i = 1; i < columns.size(); ++i)
        if (names_column(columns[i], name)) matches.push_back(i);
      if (matches.empty())
        throw InputError(header, "no monitor " + in_quotes(name) + " for " + component + "; the columns are " +
                                     list_columns(columns));
      if (matches.size() > 1) {
        std::string list;
        for (const std::size_t i : matches) list += (list.empty() ? "" : ", ") + describe_column(columns[i]);
        throw InputError(header, "monitor " + in_quotes(name) + " for " + component + " matches " + list +
                                     "; expected one: give the whole header");
      }
      const std::size_t index = *force_index(component);
      for (std::size_t other = 0; other < 6; ++other)
        if (column_of[other] == matches.front())
          throw InputError(SourceLocation{header.file, header.line, columns[matches.front()].column},
                           "monitor " + describe_column(columns[matches.front()]) + " is mapped to both " +
                               std::string(kForceNames[other]) + " and " + component +
                               "; expected one component per monitor");
      column_of[index] = matches.front();
    }
    return column_of;
  }
  for (std::size_t i = 1; i < columns.size(); ++i) {
    const auto component = recognise_component(columns[i].split.name);
    if (!component) continue;
    if (column_of[*component].has_value())
      throw InputError(SourceLocation{header.file, header.line, columns[i].column},
                       "columns " + describe_column(columns[*column_of[*component]]) + " and " +
                           describe_column(columns[i]) + " both look like " + std::string(kForceNames[*component]) +
                           "; expected one: choose with --monitor " + std::string(kForceNames[*component]) + "=NAME");
    column_of[*component] = i;
  }
  if (std::none_of(column_of.begin(), column_of.end(), [](const auto& c) { return c.has_value(); }))
    throw InputError(header, "no force or torque monitor among the columns " + list_columns(columns) +
                                 "; expected a name ending in Fx, Force X, force_x, Mx, Tx, Torque x (or y, z), "
                                 "or a mapping such as --monitor X=NAME");
  return column_of;
}

double to_si_scale(const HeaderColumn& column, std::size_t component, const CfxMonitorOptions& options,
                   const SourceLocation& where) {
  const std::string_view name = kForceNames[component];
  std::string unit_text;
  if (const auto given = options.units.find(std::string(name)); given != options.units.end())
    unit_text = given->second;
  else if (column.split.has_unit)
    unit_text = column.split.unit;
  else
    return 1.0;  // cfx5mondata writes no units: values are in the solver's units, SI unless changed
  const bool force = component < 3;
  const Dimension expected = force ? kForce : kMoment;
  Unit unit;
  try {
    unit = parse_unit(unit_text);
  } catch (const InputError& error) {
    throw InputError(where, "column " + in_quotes(column.text) + ": " + printable(error.what(), kWholeMessage));
  }
  if (!dimension_matches(unit.dimension, expected))
    throw InputError(where, "column " + in_quotes(column.text) + " gives " + std::string(name) + ", but its unit " +
                                in_quotes(unit.text) + " is " + si_unit_name(unit.dimension) + "; expected " +
                                (force ? "a force, kg m s^-2 (e.g. N, kN)" : "a moment, kg m^2 s^-2 (e.g. N m, J)"));
  return unit.scale;
}

/// One data row; its fields are kept only while it may fall in the window.
struct Row {
  std::size_t line = 0;
  std::size_t iteration = 0;
  bool truncated = false;  ///< the file's last line, without its newline
  std::vector<TextField> fields;
};

// The message of an error without its "file:line:column: " prefix, to say
// more about where it happened.
std::string message_of(const InputError& error) {
  const std::string text = error.what();
  const std::string prefix = format_location(error.where()) + ": ";
  return text.rfind(prefix, 0) == 0 ? text.substr(prefix.size()) : text;
}

double parse_value(const TextField& field, const std::string& file, const Row& row, std::string_view label) {
  const SourceLocation where{file, row.line, field.column};
  try {
    if (!is_printable_ascii(field.text))
      throw InputError(where,
                       "column " + in_quotes(label) + ": found " + in_quotes(field.text) + ", expected a number");
    return parse_number(field, file, row.line, printable(label));
  } catch (const InputError& error) {
    if (!row.truncated) throw;
    throw InputError(where, std::string(kTruncated) + ": " + message_of(error));
  }
}

std::size_t parse_iteration(const TextField& field, const std::string& file, const Row& row, std::string_view label) {
  const double value = parse_value(field, file, row, label);
  if (value < 0.0 || value > kLargestTimestep || std::floor(value) != value)
    throw InputError(SourceLocation{file, row.line, field.column}, "column " + in_quotes(label) + ": found " +
                                                                       in_quotes(field.text) +
                                                                       ", expected a whole accumulated timestep >= 0");
  return static_cast<std::size_t>(value);
}

}  // namespace

bool looks_like_cfx_monitor(std::string_view head) {
  // Export Plot Data has four preamble lines; allow a few more.
  constexpr std::size_t kLinesSearched = 10;
  const auto lines = split_lines(head);
  const std::size_t n = std::min(lines.size(), kLinesSearched);
  return std::any_of(lines.begin(), lines.begin() + static_cast<std::ptrdiff_t>(n),
                     [](const TextLine& line) { return starts_with_header(line.text); });
}

namespace {

/// What the header says: where it is, the delimiter, the columns and which
/// column gives each component, and each one's factor to SI.
struct MonitorHeader {
  std::vector<TextLine> lines;
  std::size_t header_index = 0;  ///< into lines
  char delimiter = ',';
  std::vector<HeaderColumn> columns;
  std::array<std::optional<std::size_t>, 6> column_of;
  std::array<double, 6> scale{};
};

MonitorHeader read_monitor_header(std::string_view text, const std::string& file, const CfxMonitorOptions& options) {
  check_options(options);
  if (text.empty()) throw InputError(SourceLocation{file}, "empty file; expected " + std::string(kExpectedHeader));
  if (const auto nul = text.find('\0'); nul != std::string_view::npos) {
    const auto line_start = text.rfind('\n', nul);
    const std::size_t column = line_start == std::string_view::npos ? nul + 1 : nul - line_start;
    const auto line =
        static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(nul), '\n')) + 1;
    throw InputError(SourceLocation{file, line, column},
                     "binary data (a NUL byte); expected a text export with " + std::string(kExpectedHeader));
  }

  MonitorHeader out;
  out.lines = split_lines(text);
  const auto& lines = out.lines;
  const auto header_line =
      std::find_if(lines.begin(), lines.end(), [](const TextLine& line) { return starts_with_header(line.text); });
  if (header_line == lines.end()) {
    const auto first = std::find_if(lines.begin(), lines.end(), [](const TextLine& l) { return !is_blank(l.text); });
    throw InputError(SourceLocation{file}, "no header line; expected " + std::string(kExpectedHeader) + ", found " +
                                               (first == lines.end() ? std::string("only blank lines")
                                                                     : "first " + in_quotes(first->text) + " on line " +
                                                                           std::to_string(first->number)));
  }
  out.header_index = static_cast<std::size_t>(header_line - lines.begin());
  const SourceLocation header{file, header_line->number};
  out.delimiter = detect_delimiter(header_line->text);
  for (auto& field : split_fields(*header_line, out.delimiter, file)) {
    // Monitor names go into messages and --monitor: the name rule applies
    // (an empty column, as a trailing delimiter leaves, is only skipped).
    if (!field.text.empty())
      check_name(NameKind::Field, field.text, SourceLocation{file, header_line->number, field.column},
                 "a monitor column");
    HeaderColumn column;
    column.split = split_name_and_unit(field.text);
    column.short_name = without_category(column.split.name);
    column.text = std::move(field.text);
    column.column = field.column;
    out.columns.push_back(std::move(column));
  }
  out.column_of = assign_columns(out.columns, options, header);
  for (std::size_t c = 0; c < 6; ++c)
    if (out.column_of[c])
      out.scale[c] = to_si_scale(out.columns[*out.column_of[c]], c, options,
                                 {file, header.line, out.columns[*out.column_of[c]].column});
  return out;
}

/// The fields of one data row, checked against the header's column count.
Row read_row(const TextLine& line, bool truncated, const MonitorHeader& header, const std::string& file) {
  Row row;
  row.line = line.number;
  row.truncated = truncated;
  row.fields = split_fields(line, header.delimiter, file);
  const std::size_t expected = header.columns.size();
  if (row.fields.size() != expected) {
    const std::string found = "found " + std::to_string(row.fields.size()) + " fields, expected " +
                              std::to_string(expected) + " (as in the header on line " +
                              std::to_string(header.lines[header.header_index].number) + ")";
    if (row.truncated && row.fields.size() < expected)
      throw InputError(SourceLocation{file, row.line}, std::string(kTruncated) + ": " + found);
    const std::size_t column = row.fields.size() > expected ? row.fields[expected].column : 0;
    throw InputError(SourceLocation{file, row.line, column}, found);
  }
  row.iteration = parse_iteration(row.fields.front(), file, row, header.columns.front().text);
  return row;
}

}  // namespace

MonitorImport parse_cfx_monitor(std::string_view text, const std::string& file, const CfxMonitorOptions& options) {
  const MonitorHeader parsed = read_monitor_header(text, file, options);
  const auto& lines = parsed.lines;
  const auto header_line = lines.begin() + static_cast<std::ptrdiff_t>(parsed.header_index);
  const SourceLocation header{file, header_line->number};
  const auto& columns = parsed.columns;
  const auto& column_of = parsed.column_of;
  const auto& scale = parsed.scale;

  // Rows are checked as they come; only the last average_last keep their fields.
  const bool unterminated = text.back() != '\n';
  std::deque<Row> window;
  std::size_t rows = 0;
  std::size_t first_iteration = 0;
  for (auto line = header_line + 1; line != lines.end(); ++line) {
    if (is_blank(line->text)) continue;
    Row row = read_row(*line, unterminated && line + 1 == lines.end(), parsed, file);
    if (rows++ == 0) first_iteration = row.iteration;
    window.push_back(std::move(row));
    if (window.size() > options.average_last) window.pop_front();
  }
  if (rows == 0) throw InputError(header, "header but no data rows; expected one row per iteration");
  if (rows < options.average_last)
    throw InputError(SourceLocation{file, window.back().line},
                     "found " + std::to_string(rows) + (rows == 1 ? " iteration" : " iterations") +
                         ", expected at least " + std::to_string(options.average_last) + " to average over the last " +
                         std::to_string(options.average_last));

  MonitorImport out;
  MonitorSummary& summary = out.summary;
  summary.iterations = rows;
  summary.first_iteration = first_iteration;
  summary.window_first_iteration = window.front().iteration;
  summary.last_iteration = window.back().iteration;
  summary.window = window.size();

  ImportedRun run;
  run.key = options.key;
  run.fluid = options.fluid;
  run.reference_point_b = options.reference_point_b;
  run.sign = options.sign;
  run.source_line = window.back().line;
  std::vector<double> values(window.size());
  for (std::size_t c = 0; c < 6; ++c) {
    if (!column_of[c]) continue;
    const HeaderColumn& column = columns[*column_of[c]];
    for (std::size_t r = 0; r < window.size(); ++r) {
      const Row& row = window[r];
      const TextField& field = row.fields[*column_of[c]];
      if (field.text.empty()) {
        std::string message = "column " + in_quotes(column.text) + " (" + std::string(kForceNames[c]) +
                              "): empty cell at accumulated timestep " + std::to_string(row.iteration) +
                              ", within the last " + std::to_string(window.size()) +
                              " iterations that are averaged; expected a value";
        if (row.truncated) message = std::string(kTruncated) + ": " + message;
        throw InputError(SourceLocation{file, row.line, field.column}, message);
      }
      values[r] = parse_value(field, file, row, column.text) * scale[c];
      if (!std::isfinite(values[r]))
        throw InputError(SourceLocation{file, row.line, field.column},
                         "column " + in_quotes(column.text) + ": " + in_quotes(field.text) +
                             " overflows when converted to SI; expected a finite value");
    }
    const double mean = std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
    // About the mean, in a second pass, so that a small spread on a large value is not lost.
    const double squares = std::accumulate(values.begin(), values.end(), 0.0,
                                           [mean](double sum, double v) { return sum + (v - mean) * (v - mean); });
    summary.columns[c] = column.text;
    summary.mean[c] = mean;
    summary.std_dev[c] = std::sqrt(squares / static_cast<double>(values.size()));
    if (mean != 0.0) summary.relative_change[c] = (values.back() - values.front()) / std::abs(mean);
    run.tau_b[c] = ForceComponent{mean, std::nullopt, std::nullopt};
  }

  out.batch.source.path = file;
  out.batch.source.sha256 = sha256_hex(text);
  out.batch.source.size_bytes = text.size();
  out.batch.source.importer = std::string(kCfxMonitorImporter);
  out.batch.source.importer_version = std::string(kCfxMonitorImporterVersion);
  out.batch.runs.push_back(std::move(run));
  return out;
}

ForceHistory parse_cfx_monitor_history(std::string_view text, const std::string& file,
                                       const CfxMonitorOptions& options) {
  const MonitorHeader parsed = read_monitor_header(text, file, options);
  const auto& lines = parsed.lines;
  const bool unterminated = text.back() != '\n';
  ForceHistory history;
  history.abscissa = HistoryAbscissa::Iteration;
  bool forces = false, moments = false;
  for (std::size_t c = 0; c < 6; ++c)
    if (parsed.column_of[c]) (c < 3 ? forces : moments) = true;
  std::size_t rows = 0, leading_empty = 0;
  std::size_t previous_iteration = 0, previous_line = 0;
  for (std::size_t i = parsed.header_index + 1; i < lines.size(); ++i) {
    const TextLine& line = lines[i];
    if (is_blank(line.text)) continue;
    const Row row = read_row(line, unterminated && i + 1 == lines.size(), parsed, file);
    ++rows;
    // Monitors that start after the first iterations leave their leading cells empty.
    bool full = true;
    for (std::size_t c = 0; c < 6; ++c) {
      if (!parsed.column_of[c]) continue;
      const bool blank = row.fields[*parsed.column_of[c]].text.empty();
      full = full && !blank;
    }
    if (!full && history.size() == 0 && !row.truncated) {
      ++leading_empty;
      continue;
    }
    if (history.size() > 0 && row.iteration <= previous_iteration)
      throw InputError(SourceLocation{file, row.line, row.fields.front().column},
                       "accumulated timestep " + std::to_string(row.iteration) + " after " +
                           std::to_string(previous_iteration) + " on line " + std::to_string(previous_line) +
                           "; expected increasing timesteps");
    std::array<double, 6> values{};
    for (std::size_t c = 0; c < 6; ++c) {
      if (!parsed.column_of[c]) continue;
      const HeaderColumn& column = parsed.columns[*parsed.column_of[c]];
      const TextField& field = row.fields[*parsed.column_of[c]];
      if (field.text.empty()) {
        std::string message = "column " + in_quotes(column.text) + " (" + std::string(kForceNames[c]) +
                              "): empty cell at accumulated timestep " + std::to_string(row.iteration) +
                              " after values on earlier rows; expected a value (a history has no gaps)";
        if (row.truncated) message = std::string(kTruncated) + ": " + message;
        throw InputError(SourceLocation{file, row.line, field.column}, message);
      }
      values[c] = parse_value(field, file, row, column.text) * parsed.scale[c];
      if (!std::isfinite(values[c]))
        throw InputError(SourceLocation{file, row.line, field.column},
                         "column " + in_quotes(column.text) + ": " + in_quotes(field.text) +
                             " overflows when converted to SI; expected a finite value");
    }
    history.abscissa_values.push_back(static_cast<double>(row.iteration));
    for (std::size_t c = 0; c < 6; ++c)
      if (parsed.column_of[c]) history.values(ForcePart::Total, kAllHistoryComponents[c]).push_back(values[c]);
    const SampleOrigin origin{0, static_cast<std::uint32_t>(std::min<std::size_t>(row.line, UINT32_MAX))};
    if (forces) history.force_origin.push_back(origin);
    if (moments) history.moment_origin.push_back(origin);
    previous_iteration = row.iteration;
    previous_line = row.line;
  }
  if (rows == 0)
    throw InputError(SourceLocation{file, lines[parsed.header_index].number},
                     "header but no data rows; expected one row per iteration");
  if (history.size() == 0)
    throw InputError(SourceLocation{file, lines.back().number},
                     "no row has a value in every monitor used; expected the monitors' values");
  if (history.size() < options.average_last)
    throw InputError(SourceLocation{file, previous_line},
                     "found " + std::to_string(history.size()) + (history.size() == 1 ? " iteration" : " iterations") +
                         ", expected at least " + std::to_string(options.average_last) + " to average over the last " +
                         std::to_string(options.average_last));
  if (leading_empty > 0)
    history.notes.push_back(std::to_string(leading_empty) +
                            " leading rows without a value in every monitor used "
                            "were left out (monitors that start later)");
  HistorySourceFile source;
  source.path = file;
  source.format = "cfx-monitor";
  source.sha256 = sha256_hex(text);
  source.size_bytes = text.size();
  source.rows = rows;
  source.rows_used = history.size();
  history.files.push_back(std::move(source));
  history.frame.naming = ComponentNaming::SourceAxes;
  history.frame.description = "the CFX case's axes; torques about the point the monitors were defined at";
  check_force_history(history);
  return history;
}

ForceHistory read_cfx_monitor_history(const std::filesystem::path& file, const CfxMonitorOptions& options) {
  const SourceFile source = load_source_file(file);
  ForceHistory history = parse_cfx_monitor_history(source.bytes, file.string(), options);
  history.files.front().sha256 = source.sha256;
  return history;
}

MonitorImport read_cfx_monitor(const std::filesystem::path& file, const CfxMonitorOptions& options) {
  const SourceFile source = load_source_file(file);
  MonitorImport out = parse_cfx_monitor(source.bytes, file.string(), options);
  out.batch.source.sha256 = source.sha256;
  out.batch.source.size_bytes = source.bytes.size();
  return out;
}

}  // namespace hydrocoef
