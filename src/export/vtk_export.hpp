// The surface as a VTK rectilinear grid, to look at in ParaView: axis 0, 1, 2
// of the table become the grid's x, y and z coordinates (in the axes' SI
// units; a 1-D or 2-D table is a line or a plane with the missing
// coordinates 0), each output a point-data array of doubles named after the
// output. Field data carries the axis names and units ("axis_names",
// "axis_units"), the output units ("output_units"), the method, policies,
// sign convention and provenance ("hydrocoef_info", JSON).
//
// PATH ending in ".vtk" is written as a legacy binary file, anything else as
// VTK XML (".vtr", raw binary appended data). Tables of more than 3 axes are
// refused (a grid has 3 dimensions: slice the surface first).
#pragma once

#include <filesystem>

#include "src/export/export.hpp"

namespace hydrocoef {

void write_vtk(const GridTable& table, const ExportMetadata& metadata, const std::filesystem::path& path);

}  // namespace hydrocoef
