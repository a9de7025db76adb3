#include "src/export/json_export.hpp"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "src/core/escape.hpp"
#include "src/core/version.hpp"

namespace hydrocoef {

std::string json_text(const GridTable& table, const ExportMetadata& metadata) {
  using nlohmann::json;
  check_metadata(table, metadata);
  const std::size_t n_out = table.output_count();
  json document;
  document["format"] = "hydrocoef-grid-table";
  document["format_version"] = 1;
  document["surface"] = metadata.surface_name;
  document["body"] = metadata.body;
  document["method"] = std::string(interpolation_name(table.method()));
  document["axes"] = json::array();
  for (std::size_t a = 0; a < table.axis_count(); ++a) {
    const GridAxis& axis = table.axes()[a];
    document["axes"].push_back({{"name", axis.name},
                                {"unit", metadata.axis_units[a]},
                                {"breakpoints", axis.breakpoints},
                                {"valid_range", {axis.breakpoints.front(), axis.breakpoints.back()}},
                                {"extrapolation", std::string(extrapolation_name(axis.extrapolation))}});
  }
  document["outputs"] = json::array();
  document["values"] = json::object();
  for (std::size_t k = 0; k < n_out; ++k) {
    document["outputs"].push_back({{"name", table.outputs()[k]}, {"unit", metadata.output_units[k]}});
    std::vector<double> column(table.node_count());
    for (std::size_t node = 0; node < column.size(); ++node) column[node] = table.values()[node * n_out + k];
    document["values"][table.outputs()[k]] = std::move(column);
  }
  // Each output's standard deviation at each node, when the surface states
  // one (CoefficientSurface::with_run_uncertainty has the formula).
  if (!metadata.standard_deviation.empty()) {
    if (metadata.standard_deviation.size() != table.values().size())
      throw std::invalid_argument("json_text: one standard deviation per node and output expected");
    document["sigma"] = json::object();
    for (std::size_t k = 0; k < n_out; ++k) {
      std::vector<double> column(table.node_count());
      for (std::size_t node = 0; node < column.size(); ++node)
        column[node] = metadata.standard_deviation[node * n_out + k];
      document["sigma"][table.outputs()[k]] = std::move(column);
    }
    document["sigma_definition"] =
        "one standard deviation per node in the output's unit, laid out as values: the runs' standard uncertainty "
        "(statistical and given, in quadrature) interpolated as the surface interpolates the runs' values, and the "
        "surface's leave-one-out RMS error, in quadrature";
  }
  document["layout"] =
      "values[output][((i_{n-1} * n_{n-2} + ... + i_1) * n_0 + i_0)]: axis 0 varies fastest (column-major, as "
      "MATLAB and Simulink)";
  document["extrapolation_rules"] =
      "error: a query outside the range is refused; clamp: the end value; linear: end value plus the end slope "
      "times the distance; method: the end cell's own polynomial";
  document["sign_convention"] = metadata.sign_convention;
  document["frame"] = "body axes x forward, y starboard, z down (SNAME); SI units";
  document["fit_statistics"] =
      metadata.quality_json.empty() ? json() : json::parse(metadata.quality_json, nullptr, false);
  if (document["fit_statistics"].is_discarded()) document["fit_statistics"] = metadata.quality_json;
  // Grid nodes far from every run: extrapolation of the RBF, not data.
  document["far_from_data"] = json::array();
  for (const auto& point : metadata.far_from_data) {
    json node = json::object();
    for (std::size_t a = 0; a < point.size(); ++a) node[table.axes()[a].name] = point[a];
    document["far_from_data"].push_back(node);
  }
  std::vector<std::int64_t> runs = metadata.run_ids;
  document["provenance"] = {{"surface", metadata.surface_name},
                            {"body", metadata.body},
                            {"runs", runs},
                            {"content_sha256", metadata.content_sha256},
                            {"created_at", metadata.created_at},
                            {"stale", metadata.stale},
                            {"exported_by", std::string("hydrocoef ") + kVersion}};
  return escape::json_text(document, 1) + "\n";
}

}  // namespace hydrocoef
