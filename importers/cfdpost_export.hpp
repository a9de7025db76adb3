// The CFD-Post "Generic" export importer: reads the text files ANSYS CFD-Post
// writes with File > Export (Export Type = Generic, Export Geometry = On,
// Export Connectivity = On) into a SurfaceMesh of nodal values, converted to
// SI at this edge. It is the route from a CFX wall to integrated loads when no
// CGNS or EnSight export is at hand. Layout and pitfalls:
// docs/reference/cfx-export-formats.md, sections 1 and 5.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "src/mesh/surface_mesh.hpp"

namespace hydrocoef {

struct CfdPostOptions {
  /// [Name] blocks (locations) to keep, as list_cfdpost_locations gives them;
  /// empty = all. Kept blocks stay in file order whatever the order here.
  std::vector<std::string> locations;
};

/// Parses a CFD-Post Generic export held in memory; `file` names it in
/// messages.
///
/// Layout: one or more blocks "[Name]" / location name / "[Data]" / header /
/// one row per node, each optionally followed by "[Faces]" (one face per line,
/// 3 or more 0-based node indices local to the block) or "[Lines]" (read and
/// ignored). Tags are matched after trimming; blank lines separate sections;
/// LF or CRLF; an optional UTF-8 byte-order mark, leading and trailing blank
/// lines; the last line may lack its newline. Header and rows are separated by
/// ", " (or ",") or, when the header holds a tab, by tabs.
///
/// Columns, in any order: "Name [ unit ]" or a bare (dimensionless) name;
/// names may hold dots and phase prefixes ("water.Pressure"). "Node Number" is
/// skipped. X, Y, Z are the coordinates and need a length unit (converted to
/// m). Every other column becomes a scalar Point FieldArray named as in the
/// header without its unit, in the header order of the first kept block,
/// values converted with parse_unit to SI, unit = si_unit_name of its
/// dimension ("kg m^-1 s^-2" for Pa; "" when dimensionless). "Wall Shear X/Y/Z"
/// stay three scalar arrays: the caller picks components by name. The null
/// token "null" becomes NaN (not refused here: the integration refuses NaN
/// where it matters). A column name given twice (e.g. X from Spatial Variables
/// and from the variable list) is accepted only with the same unit and the
/// same value on every row; the first one is kept.
///
/// Blocks: location_names holds the distinct names of the kept blocks in file
/// order (blocks with the same name share one location); the kept blocks'
/// nodes are concatenated in file order and face indices offset accordingly;
/// face_location gives each face's location. Every kept block must hold the
/// same arrays with units of the same kind. A block without [Faces] adds
/// nodes but no faces; a [Faces] section with no lines (file ending right
/// after the tag) is accepted and adds no faces.
///
/// Throws InputError with file:line:column, naming the block, column or
/// array, what was found and what was expected, for: an empty file; a first
/// non-blank line that is not [Name] (binary content is shown escaped); a
/// block without [Data], or [Data] without a header line; an unknown unit or
/// one of the wrong kind for a coordinate; a missing X, Y or Z; a duplicated
/// column with another unit or other values; a row with the wrong number of
/// fields (which is also what a truncated last row gives); text where a number
/// is expected, a non-finite number or one that overflows in SI; a face with
/// fewer than 3 indices or an index that is not an integer in 0..nodes-1 of
/// its block; an unknown location (the message lists the file's); an array
/// that some kept block lacks; and no [Faces] section in any kept block
/// ("export with Export Connectivity = On").
SurfaceMesh parse_cfdpost_export(std::string_view text, const std::string& file, const CfdPostOptions& options = {});

/// Reads the whole file and parses it as parse_cfdpost_export does. Throws
/// InputError naming the path when it is missing, a directory or unreadable.
SurfaceMesh read_cfdpost_export(const std::filesystem::path& file, const CfdPostOptions& options = {});

/// True when the bytes look like a CFD-Post export: the first non-blank line
/// (after an optional byte-order mark) is "[Name]". `head` may be just the
/// start of a file; for format detection.
bool looks_like_cfdpost_export(std::string_view head);

/// The distinct [Name] values of the file's blocks in file order, for
/// --list output and for choosing CfdPostOptions::locations. Checks the
/// block structure (throws InputError as parse_cfdpost_export does for an
/// empty file, a missing [Name] or [Data], a missing header) but not the
/// values.
std::vector<std::string> list_cfdpost_locations(std::string_view text, const std::string& file);

}  // namespace hydrocoef
