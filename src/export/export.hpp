// Exports of gridded coefficient surfaces for the tools controller and
// simulation engineers use: CSV (long and wide), JSON, a self-contained C99
// header, a MATLAB v5 .mat file with a Simulink set-up script, JSBSim XML
// tables and a VTK rectilinear grid. Every export carries units, the valid
// range and out-of-range policy of each axis, and provenance (surface name,
// body, runs, a content hash), and evaluates to what `hydrocoef query`
// answers. (Gazebo parameters come from damping-law fits, not tables: see
// gazebo_export.hpp.)
//
// This file holds what the formats share: the metadata every export
// carries, the format names, atomic file writing and the dispatcher.
// Exports never mutate the surface; a refused export writes nothing.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "src/core/atomic_file.hpp"
#include "src/store/database.hpp"
#include "src/surface/coefficient_surface.hpp"
#include "src/surface/grid_table.hpp"

namespace hydrocoef {

/// What an export says about where its numbers came from and what they mean.
struct ExportMetadata {
  std::string surface_name;               ///< e.g. "asr-v:surge"
  std::string body;                       ///< the body the runs belong to
  std::vector<std::string> axis_units;    ///< one per table axis, e.g. "m/s"
  std::vector<std::string> output_units;  ///< one per table output, e.g. "N"
  /// Sign convention of the outputs: "on-body" (the force of the fluid on
  /// the body, SNAME; damping is negative) or "opposing".
  std::string sign_convention = "on-body";
  std::vector<std::int64_t> run_ids;  ///< runs the surface was built from
  /// SHA-256 (lower-case hex) of the stored definition JSON followed by the
  /// data doubles' bytes; see content_sha256.
  std::string content_sha256;
  std::string created_at;    ///< when the surface was built (UTC ISO 8601)
  std::string quality_json;  ///< leave-one-out statistics as stored ("" if none)
  bool stale = false;        ///< forces changed since the surface was built
  /// Grid nodes of a resampled RBF surface that are far from every run (the
  /// quality's far_from_data), as axis coordinates: extrapolation, not data.
  std::vector<std::vector<double>> far_from_data;
  /// When the surface states a standard deviation (CoefficientSurface::
  /// has_standard_deviation): that of every output at every node, in the
  /// table's values layout (outputs fastest, then axis 0, ...) and the
  /// outputs' units; empty otherwise.
  std::vector<double> standard_deviation;
};

/// The coordinates of grid nodes listed by flat index (axis 0 fastest), for
/// messages and exports. InputError for an index outside the grid (a
/// received database's quality record is untrusted).
std::vector<std::vector<double>> grid_node_coordinates(const GridTable& table, const std::vector<std::size_t>& indices);

/// SHA-256 of a surface record's content: the definition JSON's bytes, then
/// the data's doubles as stored in memory (little-endian IEEE 754 on every
/// platform hydrocoef runs on).
std::string content_sha256(const SurfaceRecord& record);

/// The metadata of a stored surface. Throws InputError, suggesting
/// `hydrocoef surface build ... --resample`, when the surface is not a grid
/// (only gridded tables can be exported as tables).
ExportMetadata metadata_from_record(const SurfaceRecord& record, const CoefficientSurface& surface);

/// Metadata for a table that is not in a database (tests, library users):
/// units from default_unit of each name, hash of the values.
ExportMetadata metadata_for_table(const GridTable& table, std::string surface_name);

enum class ExportFormat { Csv, CsvWide, Json, CHeader, Mat, Jsbsim, Vtk, Daveml, Runtime };

/// "csv", "csv-wide", "json", "c", "mat", "jsbsim", "vtk", "daveml", "runtime"
/// (libhydrocoef_runtime's file: src/export/runtime_export.hpp); and back
/// (InputError listing the names).
std::string_view export_format_name(ExportFormat format);
ExportFormat parse_export_format(std::string_view text);

struct ExportOptions {
  /// C header: tables and arithmetic in float instead of double
  /// (for microcontrollers without a double-precision FPU).
  bool single_precision = false;
  /// C header: prefix of every identifier; empty = from the surface name.
  std::string c_identifier;
};

/// Writes `table` in `format` to `path` (and, for mat, a set-up script
/// beside it). Returns the files written. Throws InputError, having written
/// nothing, when the format cannot express the table (too many axes, a
/// method or policy the target lacks), the metadata does not match the
/// table, or the path cannot be written.
std::vector<std::filesystem::path> export_table(const GridTable& table, const ExportMetadata& metadata,
                                                ExportFormat format, const std::filesystem::path& path,
                                                const ExportOptions& options = {});

/// Checks that the metadata has one unit per axis and output of the table;
/// InputError otherwise.
void check_metadata(const GridTable& table, const ExportMetadata& metadata);

/// One line of provenance for file comments: surface, body, runs, hash, date.
std::string provenance_line(const ExportMetadata& metadata);

/// A human description of the sign convention for file comments.
std::string sign_convention_text(const std::string& convention);

}  // namespace hydrocoef
