// EnSight Gold (.case) for the VTK surface importer: read_ensight walks every
// file of the case before VTK's EnSight reader sees it (ensight_check.cpp says
// why) and then reads the case through VTK. Internal to the importer, not part
// of the public API.
#pragma once

#include "importers/vtk_messages.hpp"
#include "importers/vtk_reading_internal.hpp"

namespace hydrocoef::vtk_detail {

/// Reads an EnSight Gold case (each file at the last step of its time set),
/// one leaf per part named by its description ("part<n>" when blank), once
/// the case file and every geometry and variable file it names have been
/// checked to be complete and consistent. The caller holds a
/// ScopedVtkMessageCapture. Throws InputError naming the file (and line) at
/// fault.
FileContents read_ensight(const fs::path& case_file, const ScopedVtkMessageCapture& capture);

}  // namespace hydrocoef::vtk_detail
