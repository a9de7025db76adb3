#include "src/export/export.hpp"
#include "src/surface/grid_nodes.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/source_file.hpp"
#include "src/export/c_header_export.hpp"
#include "src/export/csv_export.hpp"
#include "src/export/daveml_export.hpp"
#include "src/export/jsbsim_export.hpp"
#include "src/export/json_export.hpp"
#include "src/export/mat_export.hpp"
#include "src/export/runtime_export.hpp"
#include "src/export/vtk_export.hpp"

namespace hydrocoef {

namespace {

std::string data_bytes(const std::vector<double>& data) {
  std::string bytes(data.size() * sizeof(double), '\0');
  if (!data.empty()) std::memcpy(bytes.data(), data.data(), bytes.size());
  return bytes;
}

}  // namespace

std::string content_sha256(const SurfaceRecord& record) {
  return sha256_hex(record.definition + data_bytes(record.data));
}

ExportMetadata metadata_from_record(const SurfaceRecord& record, const CoefficientSurface& surface) {
  if (surface.kind() == CoefficientSurface::Kind::Gp)
    throw InputError("surface '" + record.name + "' is a GP surface (scattered samples); only gridded surfaces " +
                     "can be exported as tables; expected a grid: build one from the same runs with --method rbf "
                     "--resample AXIS=FROM:TO:COUNT (one per axis), or query the GP on a grid (query --input)");
  if (surface.kind() != CoefficientSurface::Kind::Grid) {
    throw InputError("surface '" + record.name + "' is an RBF surface (scattered samples); only gridded surfaces " +
                     "can be exported as tables; expected a grid: tabulate it with `hydrocoef surface build NAME ... "
                     "--method rbf --resample AXIS=FROM:TO:COUNT` (one per axis) and export that");
  }
  ExportMetadata metadata;
  metadata.surface_name = record.name;
  metadata.body = record.body;
  metadata.axis_units = surface.axis_units();
  metadata.output_units = surface.output_units();
  metadata.sign_convention = "on-body";
  metadata.run_ids = record.run_ids;
  metadata.content_sha256 = content_sha256(record);
  metadata.created_at = record.created_at;
  metadata.quality_json = record.quality;
  metadata.stale = record.stale;
  const auto quality = nlohmann::json::parse(record.quality.empty() ? "{}" : record.quality, nullptr, false);
  if (quality.is_object() && quality.contains("far_from_data") && quality["far_from_data"].is_array()) {
    std::vector<std::size_t> indices;
    for (const auto& index : quality["far_from_data"]) {
      if (!index.is_number_unsigned())
        throw InputError("surface '" + record.name + "': far_from_data holds " + escape::one_line(index.dump()) +
                         "; expected grid node indices");
      indices.push_back(index.get<std::size_t>());
    }
    metadata.far_from_data = grid_node_coordinates(*surface.grid(), indices);
  }
  if (surface.has_standard_deviation()) {
    // The surface's own standard deviation at each node (at a node the
    // runs' part is that node's own uncertainty; see with_run_uncertainty).
    const GridTable& table = *surface.grid();
    const std::size_t n_axes = table.axis_count(), n_out = table.output_count();
    metadata.standard_deviation.resize(table.values().size());
    std::vector<double> point(n_axes), values(n_out);
    for (std::size_t node = 0; node < table.node_count(); ++node) {
      grid_node_point(table.axes(), node, point);
      surface.evaluate_with_standard_deviation(
          point, values, std::span<double>(metadata.standard_deviation).subspan(node * n_out, n_out));
    }
  }
  return metadata;
}

std::vector<std::vector<double>> grid_node_coordinates(const GridTable& table,
                                                       const std::vector<std::size_t>& indices) {
  std::vector<std::vector<double>> out;
  for (const std::size_t index : indices) {
    if (index >= table.node_count())
      throw InputError("grid node " + std::to_string(index) + " is outside a grid of " +
                       std::to_string(table.node_count()) + " nodes; expected an index below it");
    std::vector<double> point(table.axis_count());
    grid_node_point(table.axes(), index, point);
    out.push_back(std::move(point));
  }
  return out;
}

ExportMetadata metadata_for_table(const GridTable& table, std::string surface_name) {
  ExportMetadata metadata;
  metadata.surface_name = std::move(surface_name);
  for (const GridAxis& axis : table.axes()) metadata.axis_units.push_back(default_unit(axis.name));
  for (const std::string& output : table.outputs()) metadata.output_units.push_back(default_unit(output));
  metadata.content_sha256 = sha256_hex(data_bytes(table.values()));
  return metadata;
}

std::string_view export_format_name(ExportFormat format) {
  switch (format) {
    case ExportFormat::Csv: return "csv";
    case ExportFormat::CsvWide: return "csv-wide";
    case ExportFormat::Json: return "json";
    case ExportFormat::CHeader: return "c";
    case ExportFormat::Mat: return "mat";
    case ExportFormat::Jsbsim: return "jsbsim";
    case ExportFormat::Vtk: return "vtk";
    case ExportFormat::Daveml: return "daveml";
    case ExportFormat::Runtime: return "runtime";
  }
  return "?";
}

ExportFormat parse_export_format(std::string_view text) {
  for (ExportFormat format :
       {ExportFormat::Csv, ExportFormat::CsvWide, ExportFormat::Json, ExportFormat::CHeader, ExportFormat::Mat,
        ExportFormat::Jsbsim, ExportFormat::Vtk, ExportFormat::Daveml, ExportFormat::Runtime}) {
    if (text == export_format_name(format)) return format;
  }
  throw InputError("unknown export format '" + std::string(text) +
                   "'; expected csv, csv-wide, json, c, mat, jsbsim, vtk, daveml or runtime");
}

void check_metadata(const GridTable& table, const ExportMetadata& metadata) {
  if (metadata.axis_units.size() != table.axis_count() || metadata.output_units.size() != table.output_count()) {
    throw InputError("export of '" + metadata.surface_name + "': " + std::to_string(metadata.axis_units.size()) +
                     " axis units and " + std::to_string(metadata.output_units.size()) + " output units; expected " +
                     std::to_string(table.axis_count()) + " and " + std::to_string(table.output_count()));
  }
}

std::vector<std::filesystem::path> export_table(const GridTable& table, const ExportMetadata& metadata,
                                                ExportFormat format, const std::filesystem::path& path,
                                                const ExportOptions& options) {
  check_metadata(table, metadata);
  // Every format's text is made (and every refusal thrown) before a byte is written.
  switch (format) {
    case ExportFormat::Csv: write_file_atomically(path, csv_long_text(table, metadata)); return {path};
    case ExportFormat::CsvWide: write_file_atomically(path, csv_wide_text(table, metadata)); return {path};
    case ExportFormat::Json: write_file_atomically(path, json_text(table, metadata)); return {path};
    case ExportFormat::CHeader: {
      CHeaderOptions c_options;
      c_options.single_precision = options.single_precision;
      c_options.identifier = options.c_identifier;
      write_file_atomically(path, c_header_text(table, metadata, c_options));
      return {path};
    }
    case ExportFormat::Mat: return write_mat(table, metadata, path);
    case ExportFormat::Jsbsim: write_file_atomically(path, jsbsim_text(table, metadata)); return {path};
    case ExportFormat::Vtk: write_vtk(table, metadata, path); return {path};
    case ExportFormat::Daveml: write_file_atomically(path, daveml_text(table, metadata)); return {path};
    case ExportFormat::Runtime: {
      // One table, as given (without a standard deviation: ExportMetadata
      // holds its values at the nodes only, not the runs' sigma table).
      RuntimeSurface surface;
      surface.name = metadata.surface_name;
      surface.table = &table;
      surface.axis_units = metadata.axis_units;
      surface.output_units = metadata.output_units;
      surface.metadata = {{"content_sha256", metadata.content_sha256}, {"source", provenance_line(metadata)}};
      write_file_atomically(path, runtime_file_bytes(runtime_model_texts({{"body", metadata.body}}), {surface}));
      return {path};
    }
  }
  return {};
}

std::string provenance_line(const ExportMetadata& metadata) {
  std::string runs;
  for (std::size_t i = 0; i < metadata.run_ids.size(); ++i)
    runs += (i ? "," : "") + std::to_string(metadata.run_ids[i]);
  return "surface '" + metadata.surface_name + "'" + (metadata.body.empty() ? "" : " of body '" + metadata.body + "'") +
         "; runs [" + runs + "]; content sha256 " + metadata.content_sha256 +
         (metadata.created_at.empty() ? "" : "; built " + metadata.created_at) +
         (metadata.stale ? "; STALE: forces changed since it was built" : "");
}

std::string sign_convention_text(const std::string& convention) {
  if (convention == "opposing") return "opposing: a damping magnitude, positive opposes motion";
  return "on-body: the force of the fluid on the body (SNAME), damping is negative";
}

}  // namespace hydrocoef
