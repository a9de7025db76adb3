// The VTK surface importer: reads a body surface with its field arrays from the
// files CFD tools export for VTK (foamToVTK, ParaView, CFX/Fluent exports),
// EnSight Gold and CGNS (cfx5export -ensight / -cgns) into a SurfaceMesh,
// through VTK's own readers so that every encoding VTK knows (ASCII, binary,
// base64, appended, compressed; EnSight ASCII, C and Fortran binary; CGNS on
// HDF5 or ADF) is read the way VTK reads it. Nothing is converted: coordinates
// stay in the file's frame and length unit, array units are unknown (""); the
// caller maps axes and units.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "src/mesh/surface_mesh.hpp"

namespace hydrocoef {

struct VtkSurfaceOptions {
  /// Locations to keep (blocks, EnSight parts, CGNS zones and boundary
  /// patches), named as list_vtk_locations names them; empty = the default
  /// set described at read_vtk_surface.
  std::vector<std::string> locations;
  /// Read .vtp files of one piece of polygons with read_vtp_surface
  /// (importers/vtk_xml_polydata.hpp), which decodes on every core, and only
  /// the others through VTK's reader; false reads every file through VTK.
  bool direct_vtp = true;
};

/// Reads .vtk (legacy: polydata or unstructured grid), .vtp, .vtu, .vtm
/// (multiblock), .case (EnSight Gold) and .cgns (CGNS) files into one mesh,
/// locations concatenated in file order.
///
/// Locations:
/// - .vtm: the block names (nested blocks as "parent/child", an unnamed block
///   as "block<i>", i its index in its parent); a file holding one dataset is
///   one location named after the file's stem.
/// - .case: one location per part, named by the part's description line
///   ("part<n>" when it is blank); parts with the same description are one
///   location.
/// - .cgns: one location per zone, named after the zone ("base/zone" when the
///   file has several bases), and one per boundary patch (BC_t) of a zone,
///   "zone/patch". VTK 9.1 reads a patch only when its BC type is
///   FamilySpecified or BCWall and it is given as face elements (PointRange,
///   PointList or ElementRange at FaceCenter); it skips the others with a
///   warning, which the "no location" error quotes.
/// With no locations requested, all are read except CGNS boundary patches,
/// whose faces are also faces of their zone's boundary and would count twice.
///
/// Time: an EnSight case or CGNS file with several time steps is read at its
/// last one (each EnSight file at the last step of its time set).
///
/// Faces: a dataset with volume cells (a .vtu, an EnSight part or a CGNS zone)
/// is reduced to its boundary surface (outward faces on the boundary points
/// only, each with the cell data of its volume cell). A CGNS boundary patch is
/// its faces on the points they use. Otherwise triangles, quads, pixels and
/// polygons are the faces, triangle strips are split into triangles
/// (degenerate ones dropped), and lines and vertices are ignored; all points of
/// the block are kept. EnSight parts keep their element order, which groups
/// faces by element type (all tria3, then all quad4, ...).
///
/// Arrays: every point or cell data array with 1 or 3 components becomes a
/// FieldArray (Point or Face association, values converted to double, unit "");
/// arrays with other component counts, and arrays that not every selected
/// location holds, are left out. Face arrays come first, so that find_field
/// prefers cell values to point values of the same name. Field data (e.g.
/// TimeValue) is ignored.
/// - EnSight: the scalar and vector variables per node (Point) and per element
///   (Face), named by their descriptions in the case file; EnSight stores
///   coordinates and values as float32. Tensor, complex and constant variables
///   are not read.
/// - CGNS: the FlowSolution fields at Vertex (Point) and CellCenter (Face);
///   VTK joins fields named <name>X, <name>Y, <name>Z into one vector <name>.
///   A boundary patch carries its zone's point arrays and no face arrays (VTK
///   9.1 does not read BCDataSet values).
///
/// Throws InputError naming the file when it is missing, empty or unreadable;
/// has an unknown extension; VTK reports an error or a warning reading it (the
/// legacy reader only warns about a truncated file; VTK's messages are part of
/// the text; the CGNS reader's warnings about skipped boundary conditions do
/// not count); holds no faces in the selected locations; a requested location
/// does not exist (the message lists those that do); a face refers to a point
/// that does not exist or has fewer than 3 points.
///
/// EnSight: before VTK reads anything (VTK 9.1's EnSight readers crash or cut
/// parts short on a truncated file), the case file and every geometry and
/// variable file it names at the step read are checked to be complete and
/// consistent with each other, and the error names the file (and line) at
/// fault. An ASCII file whose last line has no line end counts as cut short. A
/// variable file cut exactly between two parts cannot be told from one that
/// leaves the later parts out; the variable is then missing there. Rejected:
/// EnSight6, structured ("block") parts, ghost elements, undefined or partial
/// values, single-file transient data (FILE section), change_coords_only
/// geometry, lines over 255 characters. VTK 9.1 puts the case file's folder in
/// front of every file name the case file gives, absolute ones too, so those
/// fail. The ASCII reader's reversal of nsided elements is undone.
///
/// VTK's messages never reach the terminal: while reading, the process-wide
/// vtkOutputWindow is replaced by one that collects them and vtkLogger's
/// stderr output is switched off, so do not use VTK from another thread
/// meanwhile.
SurfaceMesh read_vtk_surface(const std::filesystem::path& file, const VtkSurfaceOptions& options = {});

/// Names of the locations (blocks, parts, zones and patches) the file holds, in
/// file order, named as in read_vtk_surface (CGNS patches included); for
/// --help/--list output. Reads the whole file; throws InputError as
/// read_vtk_surface does for a missing or broken file.
std::vector<std::string> list_vtk_locations(const std::filesystem::path& file);

}  // namespace hydrocoef
