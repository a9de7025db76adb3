#include "src/export/mat_export.hpp"

#include <matio.h>

#include <cctype>
#include <nlohmann/json.hpp>
#include <set>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/version.hpp"

namespace hydrocoef {

namespace {

struct SimulinkSettings {
  std::string interpolation;
  std::string extrapolation;
  std::string diagnostic;
};

SimulinkSettings simulink_settings(const GridTable& table, const ExportMetadata& metadata) {
  const std::string what = "format mat: surface '" + metadata.surface_name + "'";
  SimulinkSettings settings;
  if (table.method() == Interpolation::Nearest) {
    settings.interpolation = "Nearest";
  } else if (table.method() == Interpolation::Linear) {
    settings.interpolation = "Linear point-slope";
  } else {
    throw InputError(what + " uses " + std::string(interpolation_name(table.method())) +
                     " interpolation; Simulink's n-D Lookup Table block has no method equal to it (its cubic and "
                     "Akima splines differ); expected a nearest or linear surface (rebuild with --method linear, or "
                     "use --format c)");
  }
  for (std::size_t a = 0; a < table.axis_count(); ++a) {
    const GridAxis& axis = table.axes()[a];
    std::string extrapolation = "Clip";
    std::string diagnostic = "None";
    switch (axis.extrapolation) {
      case Extrapolation::Error: diagnostic = "Error"; break;
      case Extrapolation::Clamp: break;
      case Extrapolation::Linear:
      case Extrapolation::Method:
        if (table.method() == Interpolation::Linear) extrapolation = "Linear";
        break;
    }
    if (a == 0) {
      settings.extrapolation = extrapolation;
      settings.diagnostic = diagnostic;
    } else if (extrapolation != settings.extrapolation || diagnostic != settings.diagnostic) {
      throw InputError(what + ": axis '" + axis.name + "' is '" + std::string(extrapolation_name(axis.extrapolation)) +
                       "' outside its range but axis '" + table.axes()[0].name + "' is '" +
                       std::string(extrapolation_name(table.axes()[0].extrapolation)) +
                       "'; the n-D Lookup Table block has one extrapolation for all axes; expected the same policy "
                       "on every axis (or use --format c)");
    }
  }
  return settings;
}

// Owns a matio file handle; closes it on every path.
class MatFile {
 public:
  explicit MatFile(const std::filesystem::path& path) : mat_(Mat_CreateVer(path.c_str(), nullptr, MAT_FT_MAT5)) {}
  ~MatFile() { close(); }
  MatFile(const MatFile&) = delete;
  MatFile& operator=(const MatFile&) = delete;
  bool ok() const { return mat_ != nullptr; }
  bool close() {
    if (!mat_) return true;
    const int status = Mat_Close(mat_);
    mat_ = nullptr;
    return status == 0;
  }
  // data must outlive the call; matio does not copy it (MAT_F_DONT_COPY_DATA).
  bool write(const std::string& name, matio_classes class_type, matio_types data_type, std::vector<std::size_t> dims,
             const void* data) {
    matvar_t* variable = Mat_VarCreate(name.c_str(), class_type, data_type, static_cast<int>(dims.size()), dims.data(),
                                       const_cast<void*>(data), MAT_F_DONT_COPY_DATA);
    if (!variable) return false;
    const int status = Mat_VarWrite(mat_, variable, MAT_COMPRESSION_NONE);
    Mat_VarFree(variable);
    return status == 0;
  }

 private:
  mat_t* mat_;
};

// libmatio does not report every failed fwrite (a full disk, a file-size
// limit), so the closed file is read back: every variable must be there
// whole, with the dimensions written.
bool reads_back(const std::filesystem::path& path, const std::vector<std::pair<std::string, std::size_t>>& expected) {
  mat_t* mat = Mat_Open(path.c_str(), MAT_ACC_RDONLY);
  if (!mat) return false;
  bool ok = true;
  for (const auto& [name, elements] : expected) {
    matvar_t* variable = Mat_VarRead(mat, name.c_str());
    ok = variable && variable->data && variable->nbytes > 0 &&
         static_cast<std::size_t>(variable->nbytes) / Mat_SizeOf(variable->data_type) == elements;
    Mat_VarFree(variable);
    if (!ok) break;
  }
  Mat_Close(mat);
  return ok;
}

std::string script_text(const GridTable& table, const ExportMetadata& metadata, const SimulinkSettings& settings,
                        const std::string& function_name, const std::string& mat_name,
                        const std::vector<std::string>& table_names) {
  const std::size_t n = table.axis_count();
  // Every name and path goes through escape::matlab_comment (comment lines)
  // or escape::matlab_string (literals): none can start a line of its own.
  const auto comment = [](std::string_view text) { return escape::matlab_comment(text); };
  std::string outputs;
  for (std::size_t k = 0; k < table.output_count(); ++k)
    outputs += (k ? ", " : "") + escape::matlab_string(table.outputs()[k]);
  std::string s;
  s += "function " + function_name + "(block, output)\n";
  s += "% " + function_name + "(BLOCK, OUTPUT) sets the n-D Lookup Table block BLOCK (a path such as\n";
  s += "% 'model/Lookup') to hydrocoef surface '" + comment(metadata.surface_name) + "', output OUTPUT (one of " +
       comment(outputs) + "),\n";
  s += "% with the interpolation and out-of-range behaviour hydrocoef uses. Data: " + comment(mat_name) +
       " beside this file.\n";
  s += "% Generated by hydrocoef " + std::string(kVersion) + " from " + comment(provenance_line(metadata)) + ".\n";
  s += "% Sign convention " + sign_convention_text(metadata.sign_convention) +
       "; body axes x forward, y starboard, z down; SI units.\n";
  for (std::size_t a = 0; a < n; ++a) {
    const GridAxis& axis = table.axes()[a];
    s += "% Input " + std::to_string(a + 1) + ": " + comment(axis.name) + " [" + comment(metadata.axis_units[a]) +
         "], valid in [" + shortest_number(axis.breakpoints.front()) + ", " + shortest_number(axis.breakpoints.back()) +
         "], outside: " + std::string(extrapolation_name(axis.extrapolation)) + "\n";
  }
  s += "data = load(fullfile(fileparts(mfilename('fullpath')), " + escape::matlab_string(mat_name) + "));\n";
  s += "names = {" + outputs + "};\n";
  s += "tables = {";
  for (std::size_t k = 0; k < table_names.size(); ++k) s += (k ? ", " : "") + escape::matlab_string(table_names[k]);
  s += "};\n";
  s += "index = find(strcmp(names, output));\n";
  s += "if isempty(index)\n  error('" + function_name +
       ": unknown output ''%s''; expected one of: %s', output, "
       "strjoin(names, ', '));\nend\n";
  s += "set_param(block, 'NumberOfTableDimensions', '" + std::to_string(n) + "');\n";
  for (std::size_t a = 0; a < n; ++a) {
    s += "set_param(block, 'BreakpointsForDimension" + std::to_string(a + 1) + "', mat2str(data.bp" +
         std::to_string(a + 1) + ", 17));\n";
  }
  s += "t = data.(tables{index});\n";
  s += "set_param(block, 'Table', sprintf('reshape(%s, %s)', mat2str(t(:)', 17), mat2str(size(t))));\n";
  if (settings.interpolation == "Linear point-slope") {
    s += "try\n  set_param(block, 'InterpMethod', 'Linear point-slope');\ncatch\n"
         "  set_param(block, 'InterpMethod', 'Linear');  % releases before R2019b\nend\n";
  } else {
    s += "set_param(block, 'InterpMethod', '" + settings.interpolation + "');\n";
  }
  s += "set_param(block, 'ExtrapMethod', '" + settings.extrapolation + "');\n";
  s += "set_param(block, 'DiagnosticForOutOfRangeInput', '" + settings.diagnostic + "');\n";
  s += "end\n";
  return s;
}

}  // namespace

std::string matlab_identifier(std::string_view name) {
  std::string out;
  for (char c : name) {
    const auto u = static_cast<unsigned char>(c);
    out += (u < 128 && std::isalnum(u)) ? c : '_';
  }
  if (out.empty() || !std::isalpha(static_cast<unsigned char>(out.front()))) out = "x" + out;
  if (out.size() > 63) out.resize(63);
  return out;
}

std::filesystem::path simulink_script_path(const std::filesystem::path& mat_path) {
  std::string stem = matlab_identifier(mat_path.stem().string());
  if (stem.size() > 54) stem.resize(54);
  return mat_path.parent_path() / (stem + "_simulink.m");
}

std::vector<std::filesystem::path> write_mat(const GridTable& table, const ExportMetadata& metadata,
                                             const std::filesystem::path& path) {
  check_metadata(table, metadata);
  const SimulinkSettings settings = simulink_settings(table, metadata);
  const std::size_t n = table.axis_count();
  const std::size_t n_out = table.output_count();

  std::vector<std::string> table_names;
  std::set<std::string> used = {"info"};
  for (std::size_t a = 1; a <= n; ++a) used.insert("bp" + std::to_string(a));
  for (std::size_t k = 0; k < n_out; ++k) {
    std::string name = matlab_identifier("table_" + table.outputs()[k]);
    while (!used.insert(name).second) name = matlab_identifier(name + "_");
    table_names.push_back(name);
  }

  nlohmann::json info;
  info["surface"] = metadata.surface_name;
  info["body"] = metadata.body;
  info["method"] = std::string(interpolation_name(table.method()));
  info["sign_convention"] = metadata.sign_convention;
  info["frame"] = "body axes x forward, y starboard, z down (SNAME); SI units";
  info["layout"] = "table_<output>(i1, ..., iN) at (bp1(i1), ..., bpN(iN)); first axis fastest";
  for (std::size_t a = 0; a < n; ++a) {
    const GridAxis& axis = table.axes()[a];
    info["axes"].push_back({{"variable", "bp" + std::to_string(a + 1)},
                            {"name", axis.name},
                            {"unit", metadata.axis_units[a]},
                            {"valid_range", {axis.breakpoints.front(), axis.breakpoints.back()}},
                            {"extrapolation", std::string(extrapolation_name(axis.extrapolation))}});
  }
  for (std::size_t k = 0; k < n_out; ++k)
    info["outputs"].push_back(
        {{"variable", table_names[k]}, {"name", table.outputs()[k]}, {"unit", metadata.output_units[k]}});
  info["far_from_data"] = nlohmann::json::array();
  for (const auto& point : metadata.far_from_data) {
    nlohmann::json node = nlohmann::json::object();
    for (std::size_t a = 0; a < point.size(); ++a) node[table.axes()[a].name] = point[a];
    info["far_from_data"].push_back(node);
  }
  info["provenance"] = {{"runs", metadata.run_ids},
                        {"content_sha256", metadata.content_sha256},
                        {"created_at", metadata.created_at},
                        {"stale", metadata.stale},
                        {"exported_by", std::string("hydrocoef ") + kVersion}};
  const std::string info_text = escape::json_text(info);

  const std::filesystem::path script_path = simulink_script_path(path);
  const std::string function_name = script_path.stem().string();
  const std::string script =
      script_text(table, metadata, settings, function_name, path.filename().string(), table_names);

  // Both files go through temporaries; the .mat is renamed first, the script
  // second. libmatio truncates and fills the temporary TemporaryFile created.
  TemporaryFile mat_file(path);
  std::vector<std::pair<std::string, std::size_t>> written;
  {
    MatFile mat(mat_file.temporary());
    if (!mat.ok()) {
      throw InputError("cannot write '" + path.string() +
                       "': libmatio could not create it (is the directory "
                       "writable?)");
    }
    bool ok = true;
    std::vector<std::vector<double>> columns(n_out, std::vector<double>(table.node_count()));
    for (std::size_t a = 0; a < n && ok; ++a) {
      const std::vector<double>& x = table.axes()[a].breakpoints;
      ok = mat.write("bp" + std::to_string(a + 1), MAT_C_DOUBLE, MAT_T_DOUBLE, {x.size(), 1}, x.data());
      written.emplace_back("bp" + std::to_string(a + 1), x.size());
    }
    std::vector<std::size_t> dims;
    for (const GridAxis& axis : table.axes()) dims.push_back(axis.breakpoints.size());
    if (dims.size() == 1) dims.push_back(1);
    for (std::size_t k = 0; k < n_out && ok; ++k) {
      for (std::size_t node = 0; node < table.node_count(); ++node) columns[k][node] = table.values()[node * n_out + k];
      ok = mat.write(table_names[k], MAT_C_DOUBLE, MAT_T_DOUBLE, dims, columns[k].data());
      written.emplace_back(table_names[k], table.node_count());
    }
    if (ok) ok = mat.write("info", MAT_C_CHAR, MAT_T_UINT8, {1, info_text.size()}, info_text.data());
    written.emplace_back("info", info_text.size());
    ok = mat.close() && ok;
    if (!ok) throw InputError("cannot write '" + path.string() + "': libmatio failed while writing it");
  }
  if (!reads_back(mat_file.temporary(), written))
    throw InputError("cannot write '" + path.string() +
                     "': the file libmatio wrote is incomplete (a full disk or a file-size limit?)");
  AtomicFile script_file(script_path);
  script_file.write(script);
  script_file.finish();
  mat_file.commit();
  script_file.commit();
  return {path, script_path};
}

}  // namespace hydrocoef
