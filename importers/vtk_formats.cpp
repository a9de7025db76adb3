// The file formats the VTK surface importer reads through VTK's readers as
// they come (legacy .vtk, XML .vtp/.vtu/.vtm, CGNS), the blocks of their
// output named as locations, and read_file, which picks the reader by
// extension (EnSight Gold, checked before VTK reads it: ensight_check.cpp).
#include "importers/vtk_formats.hpp"

#include <vtkAlgorithm.h>
#include <vtkCGNSReader.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkGenericDataObjectReader.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPartitionedDataSet.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include "importers/ensight_check.hpp"
#include "src/core/error.hpp"

namespace hydrocoef::vtk_detail {
namespace {

std::string block_name(vtkMultiBlockDataSet* blocks, unsigned int index) {
  if (blocks->HasMetaData(index)) {
    const char* name = blocks->GetMetaData(index)->Get(vtkCompositeDataSet::NAME());
    if (name != nullptr && *name != '\0') return name;
  }
  return "block" + std::to_string(index);
}

void collect_blocks(vtkMultiBlockDataSet* blocks, const std::string& prefix, std::vector<Leaf>& leaves) {
  for (unsigned int i = 0; i < blocks->GetNumberOfBlocks(); ++i) {
    const std::string name = prefix.empty() ? block_name(blocks, i) : prefix + "/" + block_name(blocks, i);
    vtkDataObject* block = blocks->GetBlock(i);
    if (auto* nested = vtkMultiBlockDataSet::SafeDownCast(block)) {
      collect_blocks(nested, name, leaves);
    } else if (auto* pieces = vtkPartitionedDataSet::SafeDownCast(block)) {
      // The pieces of a multipiece block are parts of one location.
      for (unsigned int p = 0; p < pieces->GetNumberOfPartitions(); ++p)
        leaves.push_back({name, vtkDataSet::SafeDownCast(pieces->GetPartitionAsDataObject(p))});
      if (pieces->GetNumberOfPartitions() == 0) leaves.push_back({name, nullptr});
    } else {
      leaves.push_back({name, vtkDataSet::SafeDownCast(block)});
    }
  }
}

std::vector<Leaf> collect_leaves(vtkDataObject* object, const fs::path& file) {
  std::vector<Leaf> leaves;
  if (auto* blocks = vtkMultiBlockDataSet::SafeDownCast(object)) {
    collect_blocks(blocks, "", leaves);
  } else if (auto* data = vtkDataSet::SafeDownCast(object)) {
    leaves.push_back({file.stem().string(), data});
  } else {
    throw InputError(SourceLocation{file.string()},
                     std::string("holds a ") + object->GetClassName() +
                         "; expected polydata, an unstructured grid or a multiblock dataset");
  }
  return leaves;
}

// --- the VTK formats ---------------------------------------------------------

template <typename Reader>
vtkSmartPointer<vtkAlgorithm> make_reader(const fs::path& file) {
  auto reader = vtkSmartPointer<Reader>::New();
  reader->SetFileName(file.string().c_str());
  return reader;
}

/// Reads a .vtk, .vtp, .vtu or .vtm file with the VTK reader its extension
/// calls for. The caller holds a ScopedVtkMessageCapture.
FileContents read_vtk_format(const fs::path& file, const std::string& extension,
                             const ScopedVtkMessageCapture& capture) {
  vtkSmartPointer<vtkAlgorithm> reader;
  if (extension == ".vtk")
    reader = make_reader<vtkGenericDataObjectReader>(file);
  else if (extension == ".vtp")
    reader = make_reader<vtkXMLPolyDataReader>(file);
  else if (extension == ".vtu")
    reader = make_reader<vtkXMLUnstructuredGridReader>(file);
  else
    reader = make_reader<vtkXMLMultiBlockDataReader>(file);

  reader->Update();
  FileContents contents;
  contents.object = reader->GetOutputDataObject(0);
  // Readers do not all set an error code, and some recover from a broken file
  // with an empty output and an error message, so every signal counts. The
  // legacy reader reports a truncated array only as a warning and keeps the
  // array half filled, so a warning while reading counts as an error too.
  throw_if_vtk_failed(reader, contents.object == nullptr, capture, file, extension.substr(1), true);
  contents.leaves = collect_leaves(contents.object, file);
  return contents;
}

// --- CGNS ----------------------------------------------------------------------

/// The zones and boundary patches of vtkCGNSReader's output: base / zone for a
/// zone without patches; base / zone / {"Internal", "Patches" / patch} for one
/// with them.
std::vector<Leaf> cgns_leaves(vtkMultiBlockDataSet* root) {
  std::vector<Leaf> leaves;
  unsigned int bases = 0;
  for (unsigned int b = 0; b < root->GetNumberOfBlocks(); ++b) bases += root->GetBlock(b) != nullptr;
  for (unsigned int b = 0; b < root->GetNumberOfBlocks(); ++b) {
    auto* base = vtkMultiBlockDataSet::SafeDownCast(root->GetBlock(b));
    if (base == nullptr) continue;
    const std::string prefix = bases > 1 ? block_name(root, b) + "/" : "";
    for (unsigned int z = 0; z < base->GetNumberOfBlocks(); ++z) {
      const std::string zone_name = prefix + block_name(base, z);
      vtkDataObject* zone = base->GetBlock(z);
      auto* parts = vtkMultiBlockDataSet::SafeDownCast(zone);
      if (parts == nullptr) {
        leaves.push_back({zone_name, vtkDataSet::SafeDownCast(zone)});
        continue;
      }
      for (unsigned int p = 0; p < parts->GetNumberOfBlocks(); ++p) {
        const std::string part_name = block_name(parts, p);
        vtkDataObject* part = parts->GetBlock(p);
        auto* patches = vtkMultiBlockDataSet::SafeDownCast(part);
        if (part_name == "Internal" && patches == nullptr) {
          leaves.push_back({zone_name, vtkDataSet::SafeDownCast(part)});
        } else if (part_name == "Patches" && patches != nullptr) {
          for (unsigned int q = 0; q < patches->GetNumberOfBlocks(); ++q)
            leaves.push_back(
                {zone_name + "/" + block_name(patches, q), vtkDataSet::SafeDownCast(patches->GetBlock(q)), true});
        } else if (patches != nullptr) {
          collect_blocks(patches, zone_name + "/" + part_name, leaves);
        } else {
          leaves.push_back({zone_name + "/" + part_name, vtkDataSet::SafeDownCast(part)});
        }
      }
    }
  }
  return leaves;
}

FileContents read_cgns(const fs::path& file, const ScopedVtkMessageCapture& capture) {
  vtkNew<vtkCGNSReader> reader;
  // VTK 9.1's CGNS reader ends the whole process (cgio_error_exit) when its
  // first pass over the file cannot open it; CanReadFile opens the file the
  // same way but reports a failure as a VTK error.
  if (reader->CanReadFile(file.string().c_str()) == 0 || !capture.errors().empty())
    throw_if_vtk_failed(reader, true, capture, file, "CGNS", false);
  reader->SetFileName(file.string().c_str());
  reader->UpdateInformation();
  throw_if_vtk_failed(reader, false, capture, file, "CGNS", false);
  reader->EnableAllBases();
  reader->EnableAllFamilies();
  // VTK gives the patches of BCWall conditions without a family the family
  // "Wall", which is not one of the file's, so not enabled by the line above.
  reader->SetFamilyArrayStatus("Wall", 1);
  reader->EnableAllPointArrays();
  reader->EnableAllCellArrays();
  reader->LoadMeshOn();
  reader->LoadBndPatchOn();

  vtkInformation* information = reader->GetOutputInformation(0);
  auto* times = vtkStreamingDemandDrivenPipeline::TIME_STEPS();
  if (information->Has(times) && information->Length(times) > 0)
    reader->UpdateTimeStep(information->Get(times)[information->Length(times) - 1]);
  else
    reader->Update();

  FileContents contents;
  contents.object = reader->GetOutputDataObject(0);
  // The reader warns about boundary conditions it skips (types other than
  // FamilySpecified or BCWall) and goes on: those are kept for the message
  // when a patch is asked for that is not there.
  throw_if_vtk_failed(reader, contents.object == nullptr, capture, file, "CGNS", false);
  contents.warnings = capture.warnings();
  auto* root = vtkMultiBlockDataSet::SafeDownCast(contents.object);
  if (root == nullptr) throw InputError(SourceLocation{file.string()}, "VTK read no zones");
  contents.leaves = cgns_leaves(root);
  return contents;
}

}  // namespace

// --- reading any of them -------------------------------------------------------

/// Reads the file with the VTK reader its extension calls for. The caller
/// holds a ScopedVtkMessageCapture.
FileContents read_file(const fs::path& file, const ScopedVtkMessageCapture& capture) {
  const SourceLocation where{file.string()};
  std::error_code error;
  if (!fs::exists(file, error)) throw InputError(where, "file not found");
  if (!fs::is_regular_file(file, error)) throw InputError(where, "not a regular file");
  if (!std::ifstream(file, std::ios::binary)) throw InputError(where, "cannot be opened for reading");
  const auto size = fs::file_size(file, error);
  if (error) throw InputError(where, "cannot be read: " + error.message());

  const std::string extension = lower(file.extension().string());
  const std::string expected = extension == ".case"   ? "an EnSight Gold case file"
                               : extension == ".cgns" ? "a CGNS file"
                                                      : "a VTK file";
  if (size == 0) throw InputError(where, "file is empty; expected " + expected);
  if (extension == ".vtk" || extension == ".vtp" || extension == ".vtu" || extension == ".vtm")
    return read_vtk_format(file, extension, capture);
  if (extension == ".case") return read_ensight(file, capture);
  if (extension == ".cgns") return read_cgns(file, capture);
  throw InputError(where, "unknown extension " + in_quotes(file.extension().string()) +
                              "; expected .vtk, .vtp, .vtu, .vtm, .case (EnSight Gold) or .cgns");
}

}  // namespace hydrocoef::vtk_detail
