#include "importers/force_table.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "importers/text_table.hpp"
#include "src/core/error.hpp"
#include "src/core/names.hpp"
#include "src/core/source_file.hpp"
#include "src/core/units.hpp"

namespace hydrocoef {
namespace {

enum class ColumnRole { Velocity, Force, Disturbance, Ignored };

struct Column {
  ColumnRole role = ColumnRole::Ignored;
  std::size_t component = 0;  // 0..5 for Velocity and Force
  std::string name;           // component or disturbance name
  std::string header;         // as written
  double scale = 1.0;         // to SI
};

bool contains(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

Dimension expected_dimension(ColumnRole role, std::size_t component) {
  if (role == ColumnRole::Velocity) return component < 3 ? kVelocity : kAngularVelocity;
  return component < 3 ? kForce : kMoment;
}

std::string_view expected_example(ColumnRole role, std::size_t component) {
  if (role == ColumnRole::Velocity) return component < 3 ? "m s^-1" : "rad s^-1";
  return component < 3 ? "N" : "N m";
}

Column classify(const TextField& field, const std::string& file, std::size_t line, const ForceTableOptions& options) {
  const SourceLocation where{file, line, field.column};
  const auto header = split_name_and_unit(field.text);
  Column column;
  column.header = field.text;
  if (header.name.empty()) throw InputError(where, "empty column header; expected a name such as 'u [m s^-1]'");
  if (contains(options.ignored_columns, header.name)) return column;

  std::string component = header.name;
  for (const auto& [target, source] : options.columns)
    if (source == header.name) component = target;

  if (contains(options.disturbance_columns, header.name)) {
    // A disturbance may be of any kind (a speed, an angle, a wave height), so
    // its unit is converted to SI but not checked against a kind.
    column.role = ColumnRole::Disturbance;
    // A disturbance becomes part of run keys and --where clauses: an identifier.
    column.name =
        check_name(NameKind::Parameter, header.name, SourceLocation{file, line, field.column}, "the table header");
    std::string unit_text = header.unit;
    if (const auto given = options.units.find(header.name); given != options.units.end()) unit_text = given->second;
    try {
      column.scale = parse_unit(unit_text).scale;
    } catch (const InputError& error) {
      throw InputError(where, "column '" + printable_text(field.text, 60) + "': " + error.what());
    }
    return column;
  }
  if (const auto i = velocity_index(component)) {
    column.role = ColumnRole::Velocity;
    column.component = *i;
  } else if (const auto j = force_index(component)) {
    column.role = ColumnRole::Force;
    column.component = *j;
  } else {
    throw InputError(where, "column '" + field.text +
                                "' is not a velocity (u v w p q r) or a force or moment (X Y Z K M N); map it "
                                "with --column X=" +
                                header.name + ", declare it a disturbance with --disturbance " + header.name +
                                ", or skip it with --ignore " + header.name);
  }
  column.name = component;

  std::string unit_text = header.unit;
  bool has_unit = header.has_unit;
  if (const auto given = options.units.find(component); given != options.units.end()) {
    unit_text = given->second;
    has_unit = true;
  }
  const auto example = expected_example(column.role, column.component);
  if (!has_unit)
    throw InputError(where, "column '" + printable_text(field.text, 60) + "' has no unit; expected e.g. '" + component +
                                " [" + std::string(example) + "]', or give --unit " + component + "=" +
                                std::string(example));
  Unit unit;
  try {
    unit = parse_unit(unit_text);
  } catch (const InputError& error) {
    throw InputError(where, "column '" + printable_text(field.text, 60) + "': " + error.what());
  }
  const Dimension expected = expected_dimension(column.role, column.component);
  if (!dimension_matches(unit.dimension, expected))
    throw InputError(where, "column '" + printable_text(field.text, 60) + "': unit '" + unit.text + "' is " +
                                si_unit_name(unit.dimension) + ", expected " + si_unit_name(expected) + " (e.g. " +
                                std::string(example) + ")");
  column.scale = unit.scale;
  return column;
}

bool is_comment_or_blank(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  return first == std::string_view::npos || text[first] == '#';
}

}  // namespace

std::vector<ImportedRun> parse_force_table(std::string_view text, const std::string& file,
                                           const ForceTableOptions& options) {
  if (options.body.empty()) throw InputError("empty body name; expected --body NAME");
  const auto lines = split_lines(text);
  auto line = std::find_if(lines.begin(), lines.end(), [](const TextLine& l) { return !is_comment_or_blank(l.text); });
  if (line == lines.end())
    throw InputError(SourceLocation{file}, "no header line; expected a header such as 'u [m s^-1],X [N]'");

  const char delimiter = detect_delimiter(line->text);
  const std::size_t header_line = line->number;
  std::vector<Column> columns;
  std::map<std::string, std::size_t> seen;  // name -> header column
  for (const auto& field : split_fields(*line, delimiter, file)) {
    Column column = classify(field, file, header_line, options);
    if (column.role != ColumnRole::Ignored) {
      if (const auto previous = seen.find(column.name); previous != seen.end())
        throw InputError(SourceLocation{file, header_line, field.column},
                         "column '" + printable_text(field.text, 60) + "' gives '" + column.name +
                             "' again (first at column " + std::to_string(previous->second) +
                             "); expected each component once");
      const auto velocity = velocity_index(column.name);
      if (options.disturbances.count(column.name) || (velocity && options.velocity_b[*velocity] != 0.0))
        throw InputError(SourceLocation{file, header_line, field.column},
                         "column '" + printable_text(field.text, 60) + "' and --set both give '" + column.name + "'");
      seen[column.name] = field.column;
    }
    columns.push_back(std::move(column));
  }
  const auto has_role = [&](ColumnRole role) {
    return std::any_of(columns.begin(), columns.end(), [&](const Column& c) { return c.role == role; });
  };
  if (!has_role(ColumnRole::Velocity) && !has_role(ColumnRole::Disturbance))
    throw InputError(SourceLocation{file, header_line},
                     "no velocity column; expected at least one of u v w p q r with its unit, e.g. 'u [m s^-1]'");
  if (!has_role(ColumnRole::Force))
    throw InputError(SourceLocation{file, header_line},
                     "no force or moment column; expected at least one of X Y Z K M N with its unit, e.g. 'X [N]'");

  std::vector<ImportedRun> runs;
  std::map<std::string, std::size_t> key_lines;  // describe(key) -> line, to find duplicate keys
  for (++line; line != lines.end(); ++line) {
    if (is_comment_or_blank(line->text)) continue;
    // One field more than the header is enough to say how many were found.
    const auto fields = split_fields(*line, delimiter, file, columns.size() + 1);
    if (fields.size() != columns.size())
      throw InputError(SourceLocation{file, line->number}, "found " + std::to_string(fields.size()) +
                                                               " fields, expected " + std::to_string(columns.size()) +
                                                               " (as in the header on line " +
                                                               std::to_string(header_line) + ")");
    ImportedRun run;
    run.key.body = options.body;
    run.key.disturbances = options.disturbances;
    run.key.nu_b = options.velocity_b;
    run.fluid = options.fluid;
    run.reference_point_b = options.reference_point_b;
    run.sign = options.sign;
    run.source_line = line->number;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const Column& column = columns[c];
      if (column.role == ColumnRole::Ignored) continue;
      const double value = parse_number(fields[c], file, line->number, column.header) * column.scale;
      if (!std::isfinite(value))
        throw InputError(SourceLocation{file, line->number, fields[c].column},
                         "column '" + column.header + "': '" + fields[c].text +
                             "' overflows when converted to SI; expected a finite value");
      switch (column.role) {
        case ColumnRole::Velocity: run.key.nu_b[column.component] = value; break;
        case ColumnRole::Force: run.tau_b[column.component] = ForceComponent{value, std::nullopt, std::nullopt}; break;
        case ColumnRole::Disturbance: run.key.disturbances[column.name] = value; break;
        case ColumnRole::Ignored: break;
      }
    }
    const std::string key = describe(run.key) + '|' + disturbance_signature(run.key.disturbances);
    if (const auto [previous, inserted] = key_lines.emplace(key, line->number); !inserted)
      throw InputError(SourceLocation{file, line->number},
                       "run " + describe(run.key) + " appears twice (also on line " + std::to_string(previous->second) +
                           "); expected one row per run");
    runs.push_back(std::move(run));
  }
  if (runs.empty())
    throw InputError(SourceLocation{file, header_line}, "header but no data rows; expected one row per run");
  return runs;
}

ImportBatch read_force_table(const std::filesystem::path& file, const ForceTableOptions& options) {
  const SourceFile source = load_source_file(file);
  ImportBatch batch;
  batch.source.path = file.string();
  batch.source.sha256 = source.sha256;
  batch.source.size_bytes = source.bytes.size();
  batch.source.importer = std::string(kForceTableImporter);
  batch.source.importer_version = std::string(kForceTableImporterVersion);
  batch.runs = parse_force_table(source.bytes, file.string(), options);
  return batch;
}

}  // namespace hydrocoef
