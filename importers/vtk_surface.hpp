// The VTK surface importer: reads a body surface with its field arrays from the
// files CFD tools export for VTK (foamToVTK, ParaView, CFX/Fluent exports) into a
// SurfaceMesh, through VTK's own readers so that every encoding VTK knows
// (ASCII, binary, base64, appended, compressed) is read the way VTK reads it.
// Nothing is converted: coordinates stay in the file's frame and length unit,
// array units are unknown (""); the caller maps axes and units.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "src/mesh/surface_mesh.hpp"

namespace hydrocoef {

struct VtkSurfaceOptions {
  /// Block (patch) names to keep, as list_vtk_locations gives them; empty = all.
  std::vector<std::string> locations;
};

/// Reads .vtk (legacy: polydata or unstructured grid), .vtp, .vtu and .vtm
/// (multiblock) into one mesh, blocks concatenated in file order.
///
/// Locations: in a .vtm the block names (nested blocks as "parent/child", an
/// unnamed block as "block<i>", i its index in its parent); a file holding one
/// dataset is one location named after the file's stem.
///
/// Faces: a dataset with volume cells is reduced to its boundary surface
/// (outward faces on the boundary points only, each with the cell data of its
/// volume cell). Otherwise triangles, quads, pixels and polygons are the faces,
/// triangle strips are split into triangles (degenerate ones dropped), and
/// lines and vertices are ignored; all points of the block are kept.
///
/// Arrays: every point or cell data array with 1 or 3 components becomes a
/// FieldArray (Point or Face association, values converted to double, unit "");
/// arrays with other component counts, and arrays that not every selected
/// block holds, are left out. Face arrays come first, so that find_field
/// prefers cell values to point values of the same name. Field data (e.g.
/// TimeValue) is ignored.
///
/// Throws InputError naming the file when it is missing, empty or unreadable;
/// has an unknown extension; VTK reports an error or a warning reading it (the
/// legacy reader only warns about a truncated file; VTK's messages are part of
/// the text); holds no faces in the selected blocks; a requested location does
/// not exist (the message lists those that do); a face refers to a point that
/// does not exist or has fewer than 3 points.
///
/// VTK's messages never reach the terminal: while reading, the process-wide
/// vtkOutputWindow is replaced by one that collects them and vtkLogger's
/// stderr output is switched off, so do not use VTK from another thread
/// meanwhile.
SurfaceMesh read_vtk_surface(const std::filesystem::path& file, const VtkSurfaceOptions& options = {});

/// Names of the locations (blocks) the file holds, in file order, named as in
/// read_vtk_surface; for --help/--list output. Reads the whole file; throws
/// InputError as read_vtk_surface does for a missing or broken file.
std::vector<std::string> list_vtk_locations(const std::filesystem::path& file);

}  // namespace hydrocoef
