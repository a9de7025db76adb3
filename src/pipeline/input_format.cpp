// input_format: the format an input is read as, the one requested or found
// by its extension and first bytes (a table whose header names a time or
// iteration column is a force history).
#include <algorithm>
#include <cctype>
#include <fstream>

#include "importers/openfoam_forces.hpp"
#include "src/core/error.hpp"
#include "src/core/text.hpp"
#include "src/pipeline/import_files.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

std::string head_of(const fs::path& file, std::size_t bytes = 4096) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(SourceLocation{file.string()}, "cannot open the file");
  std::string head(bytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

/// A table whose header names a time or iteration column is a history. The
/// header is the first line that is not blank or a comment, or the last
/// comment before numbers ("# Time Fx Fy Fz").
bool looks_like_time_history(std::string_view head) {
  std::string header;
  std::size_t start = 0;
  while (start < head.size()) {
    const auto end = head.find('\n', start);
    const std::string line(head.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    start = end == std::string_view::npos ? head.size() : end + 1;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    if (line[first] == '#') {
      header = line.substr(first + 1);
      continue;
    }
    const char c = line[first];
    if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.')) header = line;
    break;
  }
  const auto is_abscissa = [](const std::string& name) {
    std::string compact;
    for (const char c : lower(name.substr(0, name.find('['))))
      if (std::isalnum(static_cast<unsigned char>(c))) compact += c;
    for (const char* known : {"time", "t", "flowtime", "physicaltime", "solutiontime", "iteration", "iter", "step",
                              "timestep", "accumulatedtimestep", "outeriteration"})
      if (compact == known) return true;
    return false;
  };
  std::string cell;
  for (const char c : header + ",") {
    if (c == ',' || c == ';' || c == '\t') {
      if (is_abscissa(cell)) return true;
      cell.clear();
    } else {
      cell += c;
    }
  }
  // Blank-separated: the first word.
  std::string first_word;
  for (const char c : header) {
    if (c == ' ' && !first_word.empty()) break;
    if (c != ' ') first_word += c;
  }
  return is_abscissa(first_word);
}

}  // namespace

std::string input_format(const PlannedInput& input, const std::string& requested) {
  static const std::vector<std::string> known = {"auto",  "cfdpost", "vtk",     "monitor",
                                                 "table", "history", "cfx-out", "captive-table"};
  if (std::find(known.begin(), known.end(), requested) == known.end())
    throw InputError("--format '" + requested +
                     "': expected one of auto, table, monitor, history, cfdpost, vtk, cfx-out, captive-table");
  if (input.kind == InputKind::OpenFoamCase) return "openfoam-case";
  std::error_code ec;
  if (fs::is_directory(input.path, ec)) return "openfoam-forces";  // a function object's folder
  if (requested == "history") {
    const std::string name = lower(input.path.filename().string());
    return is_force_history_name(input.path) || name == "forcecoeffs.dat" || name.rfind("moment", 0) == 0
               ? "openfoam-forces"
               : "force-history";
  }
  if (requested != "auto") return requested;
  const std::string extension = lower(input.path.extension().string());
  if (extension == ".out") return "cfx-out";  // a CFX solver output read for its wall force summary
  if (extension == ".csv" || extension == ".txt" || extension == ".tsv" || extension == ".dat") {
    const std::string head = head_of(input.path);
    if (is_force_history_name(input.path) || lower(input.path.filename().string()) == "forcecoeffs.dat" ||
        looks_like_openfoam_forces(head))
      return "openfoam-forces";
    const std::string format = detect_format(input.path, "auto");
    if (format != "table") return format;
    return looks_like_time_history(head) ? "force-history" : "table";
  }
  return detect_format(input.path, "auto");
}

}  // namespace hydrocoef
