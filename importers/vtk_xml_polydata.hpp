// A direct reader for VTK XML PolyData files (.vtp), the format foamToVTK,
// ParaView and most CFD tools write a body surface in. VTK's own reader
// decodes and decompresses on one core and then hands its arrays over to be
// copied; this one reads the file once and decodes every array straight into
// a SurfaceMesh on every core (zlib blocks and base64 runs are independent),
// so that a .vtp import costs less than VTK's read alone.
//
// It gives the same SurfaceMesh that read_vtk_surface makes through VTK (the
// tests compare the two on every encoding VTK writes) and leaves to VTK's
// reader whatever it does not handle, so no file is read differently.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "src/mesh/surface_mesh.hpp"

namespace hydrocoef {

/// Reads a .vtp file holding one piece of polygons: points, polygons and the
/// point and cell arrays with 1 or 3 components (converted to double, cell
/// arrays first, the vtkGhostType array left out), as one location named
/// after the file's stem.
///
/// Encodings read: inline binary (base64) and appended data (raw or base64),
/// uncompressed or zlib-compressed (vtkZLibDataCompressor), little- or
/// big-endian, UInt32 or UInt64 headers, every integer and floating-point
/// type.
///
/// Returns nothing when the file holds what VTK's reader is left to read or
/// to refuse: ASCII arrays, LZ4 or LZMA compression, vertices, lines or
/// strips, several pieces, another dataset type, or XML this reader does not
/// parse (VTK then names the line and column of the fault).
///
/// Throws InputError naming the file, and the array where there is one, when
/// the data are cut short, an array holds fewer values than the piece has
/// points or cells, a zlib block does not decompress to its stated size, an
/// offset goes backwards, a polygon has fewer than 3 points, a point index is
/// out of range, or the counts do not fit 32-bit indices.
std::optional<SurfaceMesh> read_vtp_surface(const std::filesystem::path& file);

/// The same for a file's bytes already in memory (tests, fuzzing): messages
/// name `file_name`, the one location is `location`.
std::optional<SurfaceMesh> parse_vtp_surface(std::string_view bytes, const std::string& file_name,
                                             const std::string& location);

}  // namespace hydrocoef
