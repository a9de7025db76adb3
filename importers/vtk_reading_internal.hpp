// What the pieces of the VTK surface importer share: the datasets a file
// holds once VTK has read it (Leaf, FileContents) and small text helpers.
// Internal to importers/vtk_*.cpp and importers/ensight_*.cpp, not part of the
// public API (that is importers/vtk_surface.hpp). The pieces:
// - vtk_messages: VTK's messages kept from the terminal, for InputErrors;
// - vtk_formats: read_file, by extension, through VTK's legacy, XML and CGNS
//   readers, and the datasets named after their locations;
// - ensight_case, ensight_check: EnSight Gold, every file checked before VTK
//   reads it;
// - vtk_surface: faces and arrays of the datasets read, into a SurfaceMesh.
#pragma once

#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "src/core/text.hpp"

namespace hydrocoef::vtk_detail {

namespace fs = std::filesystem;

/// A dataset of the file together with the location (block) it belongs to;
/// data is null for an empty block. A CGNS boundary patch holds all the points
/// of its zone and is not read unless asked for.
struct Leaf {
  std::string location;
  vtkSmartPointer<vtkDataSet> data;
  bool patch = false;
};

/// What a file holds once VTK has read it: the datasets (kept alive by
/// `object`) and the warnings VTK gave that did not stop the read.
struct FileContents {
  vtkSmartPointer<vtkDataObject> object;
  std::vector<Leaf> leaves;
  std::vector<std::string> warnings;
};

inline std::string in_quotes(std::string_view text) {
  std::string out = "'";
  out += text;
  out += '\'';
  return out;
}

}  // namespace hydrocoef::vtk_detail
