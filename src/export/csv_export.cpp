#include "src/export/csv_export.hpp"
#include "src/surface/grid_nodes.hpp"

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef {

namespace {

// Names reach the file only through escape::csv_text (header cells) and
// escape::csv_comment ('#' lines): none adds a row or a column.
std::string column_text(const std::string& name, const std::string& unit) {
  return unit.empty() ? name : name + " [" + unit + "]";
}
std::string column(const std::string& name, const std::string& unit) {
  return escape::csv_text(column_text(name, unit));
}
std::string axis_names(const GridTable& table) {
  std::string names;
  for (std::size_t a = 0; a < table.axis_count(); ++a) names += (a ? ", " : "") + table.axes()[a].name;
  return names;
}

}  // namespace

std::string csv_comment_block(const GridTable& table, const ExportMetadata& metadata) {
  std::string text = "# hydrocoef export of " + escape::csv_comment(provenance_line(metadata)) + "\n";
  text += "# method " + std::string(interpolation_name(table.method())) +
          " (tensor product along the axes); outputs in sign convention " +
          sign_convention_text(metadata.sign_convention) + "\n";
  text += "# body axes x forward, y starboard, z down (SNAME); SI units\n";
  for (std::size_t a = 0; a < table.axis_count(); ++a) {
    const GridAxis& axis = table.axes()[a];
    text += "# axis " + std::to_string(a) + " " + escape::csv_comment(column_text(axis.name, metadata.axis_units[a])) +
            ": " + std::to_string(axis.breakpoints.size()) + " breakpoints, valid range [" +
            shortest_number(axis.breakpoints.front()) + ", " + shortest_number(axis.breakpoints.back()) +
            "], out of range: " + std::string(extrapolation_name(axis.extrapolation)) + "\n";
  }
  for (std::size_t k = 0; k < table.output_count(); ++k)
    text += "# output " + escape::csv_comment(column_text(table.outputs()[k], metadata.output_units[k])) + "\n";
  return text;
}

std::string csv_long_text(const GridTable& table, const ExportMetadata& metadata) {
  check_metadata(table, metadata);
  const std::size_t n = table.axis_count();
  const std::size_t n_out = table.output_count();
  std::string text = csv_comment_block(table, metadata);
  text += "# one row per grid node, axis 0 varying fastest\n";
  for (std::size_t a = 0; a < n; ++a) text += (a ? "," : "") + column(table.axes()[a].name, metadata.axis_units[a]);
  for (std::size_t k = 0; k < n_out; ++k) text += "," + column(table.outputs()[k], metadata.output_units[k]);
  text += "\n";
  const std::vector<double>& values = table.values();
  std::vector<double> point(n);
  for (std::size_t node = 0; node < table.node_count(); ++node) {
    grid_node_point(table.axes(), node, point);
    for (std::size_t a = 0; a < n; ++a) text += (a ? "," : "") + shortest_number(point[a]);
    for (std::size_t k = 0; k < n_out; ++k) text += "," + shortest_number(values[node * n_out + k]);
    text += "\n";
  }
  return text;
}

std::string csv_wide_text(const GridTable& table, const ExportMetadata& metadata) {
  check_metadata(table, metadata);
  if (table.axis_count() != 2) {
    throw InputError("format csv-wide: surface '" + metadata.surface_name + "' has " +
                     std::to_string(table.axis_count()) + " axes (" + axis_names(table) +
                     "); expected a 2-D table (use --format csv, the long form, for any number of axes)");
  }
  const std::vector<double>& x0 = table.axes()[0].breakpoints;
  const std::vector<double>& x1 = table.axes()[1].breakpoints;
  const std::size_t n_out = table.output_count();
  std::string text = csv_comment_block(table, metadata);
  text += "# per output, one row per " + escape::csv_comment(table.axes()[0].name) + " breakpoint, one column per " +
          escape::csv_comment(table.axes()[1].name) + " breakpoint\n";
  text += "output," + escape::csv_text(column_text(table.axes()[0].name, metadata.axis_units[0]) + " \\ " +
                                       column_text(table.axes()[1].name, metadata.axis_units[1]));
  for (double x : x1) text += "," + shortest_number(x);
  text += "\n";
  for (std::size_t k = 0; k < n_out; ++k) {
    for (std::size_t i = 0; i < x0.size(); ++i) {
      text += escape::csv_text(table.outputs()[k]) + "," + shortest_number(x0[i]);
      for (std::size_t j = 0; j < x1.size(); ++j)
        text += "," + shortest_number(table.values()[(j * x0.size() + i) * n_out + k]);
      text += "\n";
    }
  }
  return text;
}

}  // namespace hydrocoef
