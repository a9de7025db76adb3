#include "src/export/vtk_export.hpp"

#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkRectilinearGrid.h>
#include <vtkRectilinearGridWriter.h>
#include <vtkStringArray.h>
#include <vtkXMLRectilinearGridWriter.h>

#include <nlohmann/json.hpp>

#include "src/core/atomic_file.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/version.hpp"

namespace hydrocoef {

namespace {

void add_strings(vtkFieldData* field_data, const char* name, const std::vector<std::string>& values) {
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  for (const std::string& value : values) array->InsertNextValue(value);
  field_data->AddArray(array);
}

}  // namespace

void write_vtk(const GridTable& table, const ExportMetadata& metadata, const std::filesystem::path& path) {
  check_metadata(table, metadata);
  const std::size_t n = table.axis_count();
  const std::size_t n_out = table.output_count();
  if (n > 3) {
    std::string names;
    for (std::size_t a = 0; a < n; ++a) names += (a ? ", " : "") + table.axes()[a].name;
    throw InputError("format vtk: surface '" + metadata.surface_name + "' has " + std::to_string(n) + " axes (" +
                     names +
                     "); a VTK grid has at most 3 dimensions; expected 1 to 3 axes (use --format csv, json "
                     "or c for more)");
  }
  vtkNew<vtkRectilinearGrid> grid;
  int dims[3] = {1, 1, 1};
  vtkNew<vtkDoubleArray> coordinates[3];
  for (std::size_t a = 0; a < 3; ++a) {
    // Named, so the file does not carry VTK's default name (the array's address) and two exports are equal.
    coordinates[a]->SetName(a < n ? table.axes()[a].name.c_str() : (std::string("unused_") + "xyz"[a]).c_str());
    if (a < n) {
      const std::vector<double>& x = table.axes()[a].breakpoints;
      dims[a] = static_cast<int>(x.size());
      for (double value : x) coordinates[a]->InsertNextValue(value);
    } else {
      coordinates[a]->InsertNextValue(0.0);
    }
  }
  grid->SetDimensions(dims);
  grid->SetXCoordinates(coordinates[0]);
  grid->SetYCoordinates(coordinates[1]);
  grid->SetZCoordinates(coordinates[2]);
  for (std::size_t k = 0; k < n_out; ++k) {
    vtkNew<vtkDoubleArray> array;
    array->SetName(table.outputs()[k].c_str());
    array->SetNumberOfTuples(static_cast<vtkIdType>(table.node_count()));
    for (std::size_t node = 0; node < table.node_count(); ++node)
      array->SetValue(static_cast<vtkIdType>(node), table.values()[node * n_out + k]);
    grid->GetPointData()->AddArray(array);
  }
  std::vector<std::string> axis_names;
  std::vector<std::string> policies;
  for (const GridAxis& axis : table.axes()) {
    axis_names.push_back(axis.name);
    policies.push_back(std::string(extrapolation_name(axis.extrapolation)));
  }
  nlohmann::json info = {{"surface", metadata.surface_name},
                         {"body", metadata.body},
                         {"method", std::string(interpolation_name(table.method()))},
                         {"axis_names", axis_names},
                         {"axis_units", metadata.axis_units},
                         {"extrapolation", policies},
                         {"outputs", table.outputs()},
                         {"output_units", metadata.output_units},
                         {"sign_convention", metadata.sign_convention},
                         {"frame", "body axes x forward, y starboard, z down (SNAME); SI units"},
                         {"runs", metadata.run_ids},
                         {"content_sha256", metadata.content_sha256},
                         {"created_at", metadata.created_at},
                         {"exported_by", std::string("hydrocoef ") + kVersion}};
  vtkFieldData* field_data = grid->GetFieldData();
  add_strings(field_data, "axis_names", axis_names);
  add_strings(field_data, "axis_units", metadata.axis_units);
  add_strings(field_data, "output_units", metadata.output_units);
  add_strings(field_data, "hydrocoef_info", {escape::json_text(info)});

  // VTK writes into memory and AtomicFile writes the bytes: no path is handed
  // to VTK, and a full disk is reported as for every other hydrocoef file.
  std::string bytes;
  int written = 0;
  unsigned long error_code = 0;
  if (path.extension() == ".vtk") {
    vtkNew<vtkRectilinearGridWriter> writer;
    writer->WriteToOutputStringOn();
    writer->SetInputData(grid);
    writer->SetFileTypeToBinary();
    writer->SetHeader(("hydrocoef surface " + metadata.surface_name).substr(0, 200).c_str());
    written = writer->Write();
    error_code = writer->GetErrorCode();
    if (writer->GetOutputString())
      bytes.assign(writer->GetOutputString(), static_cast<std::size_t>(writer->GetOutputStringLength()));
  } else {
    vtkNew<vtkXMLRectilinearGridWriter> writer;
    writer->WriteToOutputStringOn();
    writer->SetInputData(grid);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    written = writer->Write();
    error_code = writer->GetErrorCode();
    bytes = writer->GetOutputString();
  }
  if (written != 1 || error_code != 0 || bytes.empty())
    throw InputError("cannot write '" + path.string() + "': VTK's writer failed (" +
                     (error_code ? vtkErrorCode::GetStringFromErrorCode(error_code) : "no output") + ")");
  write_file_atomically(path, bytes);
}

}  // namespace hydrocoef
