// How the VTK surface importer reads a file: read_file picks the reader by
// the file's extension (VTK's legacy and XML readers for .vtk, .vtp, .vtu and
// .vtm; the checked EnSight Gold reader of ensight_check.hpp for .case; VTK's
// CGNS reader for .cgns) and returns the datasets it holds, each named after
// its location (block, part, zone or patch). Internal to the importer, not
// part of the public API.
#pragma once

#include "importers/vtk_messages.hpp"
#include "importers/vtk_reading_internal.hpp"

namespace hydrocoef::vtk_detail {

/// Reads the file with the VTK reader its extension calls for. The caller
/// holds a ScopedVtkMessageCapture. Throws InputError naming the file when it
/// is missing, empty, has an unknown extension or VTK cannot read it.
FileContents read_file(const fs::path& file, const ScopedVtkMessageCapture& capture);

}  // namespace hydrocoef::vtk_detail
