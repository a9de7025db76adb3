#include "importers/vtk_surface.hpp"

#include <vtkAlgorithm.h>
#include <vtkCGNSReader.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCellTypes.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDataArraySelection.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkDataSetAttributes.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkGenericCell.h>
#include <vtkGenericDataObjectReader.h>
#include <vtkGenericEnSightReader.h>
#include <vtkGeometryFilter.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkLogger.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkPartitionedDataSet.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkDoubleArray.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

#include "importers/vtk_xml_polydata.hpp"
#include "src/core/error.hpp"
#include "src/core/huge_pages.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

// VTK reports a problem to observers of the object that has it or, when there
// are none, both to vtkLogger (which prints it on stderr) and to the
// vtkOutputWindow. Objects created inside a reader (the XML parser, the readers
// of a .vtm's pieces and their pipeline executives) cannot be observed from
// outside, so instead the output window is swapped for one that keeps the
// messages and vtkLogger's stderr output is switched off while VTK works:
// nothing reaches the terminal, and the errors can become part of an
// InputError.
class CollectingOutputWindow : public vtkOutputWindow {
 public:
  vtkTypeMacro(CollectingOutputWindow, vtkOutputWindow)
  static CollectingOutputWindow* New() {
    auto* window = new CollectingOutputWindow;
    window->InitializeObjectBase();
    return window;
  }

  void DisplayText(const char* text) override { add(warnings, text); }
  void DisplayErrorText(const char* text) override { add(errors, text); }
  void DisplayWarningText(const char* text) override { add(warnings, text); }
  void DisplayGenericWarningText(const char* text) override { add(warnings, text); }
  void DisplayDebugText(const char*) override {}

  std::vector<std::string> errors;
  std::vector<std::string> warnings;

 private:
  CollectingOutputWindow() = default;
  static void add(std::vector<std::string>& into, const char* text) {
    if (text != nullptr) into.emplace_back(text);
  }
};

/// Switches vtkLogger's stderr output off and returns the level it had.
/// vtkLogger can set that level but not report it; what it reports is the
/// highest level of all its outputs (stderr, log files, callbacks), so the
/// level is read off by comparing that before and after. When a log file or
/// callback takes at least as much as stderr did, stderr's old level cannot be
/// told apart and loguru's default (INFO) is assumed, or less if that was all.
vtkLogger::Verbosity silence_vtk_logger_stderr() {
  const vtkLogger::Verbosity before = vtkLogger::GetCurrentVerbosityCutoff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  const vtkLogger::Verbosity others = vtkLogger::GetCurrentVerbosityCutoff();
  if (others < before) return before;
  return std::min(before, vtkLogger::VERBOSITY_INFO);
}

/// Collects VTK's messages for its lifetime and then puts VTK's previous
/// output window and stderr logging back, so that the rest of the program
/// keeps VTK's usual behaviour. Process-wide state: one reader at a time.
class ScopedVtkMessageCapture {
 public:
  ScopedVtkMessageCapture()
      : previous_window_(vtkOutputWindow::GetInstance()), previous_stderr_(silence_vtk_logger_stderr()) {
    vtkOutputWindow::SetInstance(window_);
  }
  ~ScopedVtkMessageCapture() {
    vtkOutputWindow::SetInstance(previous_window_);
    vtkLogger::SetStderrVerbosity(previous_stderr_);
  }
  ScopedVtkMessageCapture(const ScopedVtkMessageCapture&) = delete;
  ScopedVtkMessageCapture& operator=(const ScopedVtkMessageCapture&) = delete;

  const std::vector<std::string>& errors() const { return window_->errors; }
  const std::vector<std::string>& warnings() const { return window_->warnings; }

 private:
  vtkSmartPointer<vtkOutputWindow> previous_window_;
  vtkLogger::Verbosity previous_stderr_;
  vtkNew<CollectingOutputWindow> window_;
};

/// One VTK message on one printable line of bounded length, without the source
/// file and line of VTK itself and without object addresses, which mean
/// nothing to a user.
std::string clean_vtk_message(std::string text) {
  if (text.rfind("ERROR: In ", 0) == 0 || text.rfind("Warning: In ", 0) == 0 ||
      text.rfind("Generic Warning: In ", 0) == 0) {
    const auto end_of_line = text.find('\n');
    text = end_of_line == std::string::npos ? std::string() : text.substr(end_of_line + 1);
  }
  // Object addresses "(0x55d0c1e2a3b0)" and the blanks before them go;
  // bytes a garbage file may quote become '?'; runs of blanks become one space.
  std::string cleaned;
  cleaned.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    if (text.compare(i, 3, "(0x") == 0) {
      std::size_t end = i + 3;
      while (end < text.size() && std::isxdigit(static_cast<unsigned char>(text[end]))) ++end;
      if (end > i + 3 && end < text.size() && text[end] == ')') {
        while (!cleaned.empty() && cleaned.back() == ' ') cleaned.pop_back();
        i = end + 1;
        continue;
      }
    }
    const auto byte = static_cast<unsigned char>(text[i++]);
    if (std::isspace(byte) != 0) {
      if (cleaned.empty() || cleaned.back() != ' ') cleaned += ' ';
    } else {
      cleaned += byte < 0x20 || byte >= 0x7f ? '?' : static_cast<char>(byte);
    }
  }
  text = std::move(cleaned);
  const auto first = text.find_first_not_of(' ');
  const auto last = text.find_last_not_of(' ');
  text = first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
  constexpr std::size_t kMaxLength = 200;
  if (text.size() > kMaxLength) {
    text.resize(kMaxLength);
    text += "...";
  }
  return text;
}

/// VTK's messages, as one line. The executive's "returned failure for
/// request" follows every reader failure and only repeats that one happened.
std::string summarize_vtk_messages(const std::vector<std::string>& messages) {
  constexpr std::size_t kMaxMessages = 3;
  std::vector<std::string> kept;
  for (const auto& message : messages) {
    std::string line = clean_vtk_message(message);
    if (line.empty() || line.find("returned failure for request") != std::string::npos) continue;
    if (std::find(kept.begin(), kept.end(), line) == kept.end()) kept.push_back(std::move(line));
  }
  std::string summary;
  for (std::size_t i = 0; i < kept.size() && i < kMaxMessages; ++i) summary += (i > 0 ? "; " : "") + kept[i];
  if (kept.size() > kMaxMessages) summary += "; (" + std::to_string(kept.size() - kMaxMessages) + " more)";
  return summary;
}

std::string lower_case(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::string in_quotes(std::string_view text) {
  std::string out = "'";
  out += text;
  out += '\'';
  return out;
}

std::string join_quoted(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + in_quotes(name);
  return text.empty() ? "none" : text;
}

/// Throws the InputError for a file VTK could not read when the reader failed,
/// made no output or reported an error, or a warning if `warnings_are_errors`.
void throw_if_vtk_failed(vtkAlgorithm* reader, bool no_output, const ScopedVtkMessageCapture& capture,
                         const fs::path& file, const std::string& format, bool warnings_are_errors) {
  const bool warned = warnings_are_errors && !capture.warnings().empty();
  if (reader->GetErrorCode() == 0 && !no_output && capture.errors().empty() && !warned) return;
  std::vector<std::string> messages = capture.errors();
  if (warnings_are_errors) messages.insert(messages.end(), capture.warnings().begin(), capture.warnings().end());
  std::string message = "VTK could not read the file as " + format;
  const std::string details = summarize_vtk_messages(messages);
  if (!details.empty()) message += ": " + details;
  throw InputError(SourceLocation{file.string()}, message);
}

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

// --- EnSight Gold ------------------------------------------------------------
//
// VTK 9.1's EnSight Gold readers do not look for the end of a file: a
// truncated geometry or variable file makes them read on past it, which ends in
// a segmentation fault or, worse, in parts silently cut short, and a variable
// file that names a part the geometry lacks makes them use a null block. So
// before VTK reads a case, the importer walks every file VTK is going to read
// (the geometry and the scalar and vector variables, at the time step read)
// and checks that it is complete and consistent with the geometry; afterwards
// it checks the parts VTK made against what it found. The walk follows the
// EnSight Gold format as VTK reads it: ASCII files line by line (one value per
// line, one element per line, lines of at most 255 characters), binary files
// as "C Binary" or "Fortran Binary" with 80-character strings, 32-bit integers
// and 32-bit floats.

namespace ensight {

constexpr std::size_t kMaxLineLength = 255;  // VTK reads EnSight lines into char[256]
constexpr long long kMaxPartNumber = 65536;  // VTK's limit, which it also uses to tell the byte order
constexpr long long kMaxCount = std::numeric_limits<std::int32_t>::max();

std::string trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n\v\f");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r\n\v\f");
  return std::string(text.substr(first, last - first + 1));
}

std::vector<std::string> split_words(std::string_view text) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])) != 0) ++i;
    const std::size_t start = i;
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])) == 0) ++i;
    if (i > start) words.emplace_back(text.substr(start, i - start));
  }
  return words;
}

bool starts_with(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

/// The sum of counts already checked to be positive.
std::size_t sum(const std::vector<long long>& counts) {
  return std::accumulate(counts.begin(), counts.end(), std::size_t{0},
                         [](std::size_t total, long long count) { return total + static_cast<std::size_t>(count); });
}

std::optional<long long> parse_integer(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

std::optional<double> parse_real(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

/// What a quoted excerpt of a file may show: printable, and short.
std::string excerpt(std::string_view text) {
  std::string out(text.substr(0, 40));
  std::replace_if(
      out.begin(), out.end(),
      [](char c) { return static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f; }, '?');
  if (text.size() > 40) out += "...";
  return in_quotes(out);
}

// --- the case file

struct TimeSet {
  std::optional<long long> steps;
  std::vector<double> times;
  std::vector<long long> file_numbers;
  std::optional<long long> start;
  std::optional<long long> increment;
};

/// A scalar or vector variable per node or per element: the ones read.
struct Variable {
  std::string description;
  FieldAssociation association = FieldAssociation::Point;
  int components = 1;
  int time_set = 0;  // 0: none
  std::string pattern;
  std::size_t line = 0;
  fs::path file;          // the file at the time step read
  std::set<long long> parts;  // the parts the file gives values for
};

struct Case {
  std::string geometry_pattern;
  int geometry_time_set = 0;
  std::size_t geometry_line = 0;
  fs::path geometry_file;
  std::vector<Variable> variables;
  std::map<long long, TimeSet> time_sets;
  std::optional<double> last_time;
};

bool is_case_section(const std::string& line) {
  static const std::set<std::string> sections{"FORMAT", "GEOMETRY", "VARIABLE", "TIME", "FILE",
                                              "MATERIAL", "BLOCK_CONTINUATION", "SCRIPTS"};
  return sections.count(line) > 0;
}

/// The file name `pattern` gives at file number `number`: its run of '*'
/// replaced by the number, padded with zeros to the run's length, as VTK does.
std::string replace_wildcards(const std::string& pattern, long long number, const fs::path& case_file,
                              std::size_t line) {
  const auto first = pattern.find('*');
  if (first == std::string::npos) return pattern;
  const auto end = std::min(pattern.find_first_not_of('*', first), pattern.size());
  if (pattern.find('*', end) != std::string::npos)
    throw InputError(SourceLocation{case_file.string(), line},
                     "file name " + in_quotes(pattern) + " has several runs of '*'; expected one");
  std::string digits = std::to_string(number);
  if (digits.size() < end - first) digits.insert(0, end - first - digits.size(), '0');
  return pattern.substr(0, first) + digits + pattern.substr(end);
}

Case parse_case(const fs::path& case_file) {
  const std::string name = case_file.string();
  std::ifstream in(case_file, std::ios::binary);
  Case result;
  std::string section;
  bool gold = false;
  TimeSet* time_set = nullptr;
  std::vector<double>* continued_times = nullptr;
  std::vector<long long>* continued_numbers = nullptr;
  std::string raw;
  std::size_t line_number = 0;
  const auto fail = [&](const std::string& message) -> InputError {
    return InputError(SourceLocation{name, line_number}, message);
  };
  const auto integer = [&](const std::string& word, const char* what) {
    const auto value = parse_integer(word);
    if (!value) throw fail("found " + excerpt(word) + "; expected " + what + " (an integer)");
    return *value;
  };
  // Time values and file numbers may run on over the following lines.
  const auto append_numbers = [&](const std::vector<std::string>& words) {
    for (const auto& word : words) {
      if (continued_times != nullptr) {
        const auto value = parse_real(word);
        if (!value) throw fail("found " + excerpt(word) + "; expected a time value");
        continued_times->push_back(*value);
      } else {
        continued_numbers->push_back(integer(word, "a file number"));
      }
    }
  };

  while (std::getline(in, raw)) {
    ++line_number;
    if (raw.size() > kMaxLineLength)
      throw fail("line of " + std::to_string(raw.size()) + " characters; VTK's EnSight reader reads at most " +
                 std::to_string(kMaxLineLength));
    const std::string line = trim(raw);
    if (line.empty() || line.front() == '#') continue;
    if (is_case_section(line)) {
      section = line;
      continued_times = nullptr;
      continued_numbers = nullptr;
      if (section == "FILE")
        throw fail("single-file transient EnSight data (a FILE section) is not supported; expected one file per "
                   "time step");
      continue;
    }
    const auto colon = line.find(':');
    if (colon == std::string::npos) {
      if (section == "TIME" && (continued_times != nullptr || continued_numbers != nullptr)) {
        append_numbers(split_words(line));
        continue;
      }
      if (section == "MATERIAL" || section == "BLOCK_CONTINUATION" || section == "SCRIPTS") continue;
      throw fail("found " + excerpt(line) + "; expected 'keyword: values'");
    }
    continued_times = nullptr;
    continued_numbers = nullptr;
    const std::string key = lower_case(trim(line.substr(0, colon)));
    const std::vector<std::string> words = split_words(std::string_view(line).substr(colon + 1));
    std::string normal_key;
    for (const auto& word : split_words(key)) normal_key += (normal_key.empty() ? "" : " ") + word;

    if (section == "FORMAT") {
      if (normal_key != "type") continue;
      std::string type;
      for (const auto& word : words) type += (type.empty() ? "" : " ") + lower_case(word);
      if (type == "ensight gold") {
        gold = true;
      } else {
        throw fail("EnSight format " + in_quotes(type) + " is not supported; expected 'ensight gold' (cfx5export "
                   "-ensight writes EnSight Gold)");
      }
    } else if (section == "GEOMETRY") {
      if (normal_key != "model")
        throw fail("geometry " + in_quotes(normal_key) + " is not supported; expected only 'model:'");
      if (std::find(words.begin(), words.end(), "change_coords_only") != words.end())
        throw fail("'change_coords_only' geometry is not supported; expected a full geometry file per time step");
      if (words.size() == 3) throw fail("file sets ('model: ts fs file') are not supported");
      if (words.empty() || words.size() > 3) throw fail("expected 'model: [time set] file'");
      result.geometry_pattern = words.back();
      result.geometry_line = line_number;
      if (words.size() == 2) result.geometry_time_set = static_cast<int>(integer(words[0], "a time set number"));
    } else if (section == "VARIABLE") {
      Variable variable;
      if (normal_key == "scalar per node" || normal_key == "vector per node") {
        variable.association = FieldAssociation::Point;
      } else if (normal_key == "scalar per element" || normal_key == "vector per element") {
        variable.association = FieldAssociation::Face;
      } else {
        continue;  // constants, tensors, complex and measured variables: not read (see read_ensight)
      }
      variable.components = starts_with(normal_key, "vector") ? 3 : 1;
      if (words.size() == 4) throw fail("file sets ('" + normal_key + ": ts fs description file') are not supported");
      if (words.size() < 2 || words.size() > 4)
        throw fail("expected '" + normal_key + ": [time set] description file'");
      if (words.size() == 3) variable.time_set = static_cast<int>(integer(words[0], "a time set number"));
      variable.description = words[words.size() - 2];
      variable.pattern = words.back();
      variable.line = line_number;
      result.variables.push_back(std::move(variable));
    } else if (section == "TIME") {
      if (normal_key == "time set") {
        if (words.empty()) throw fail("expected 'time set: number'");
        time_set = &result.time_sets[integer(words[0], "a time set number")];
        continue;
      }
      if (time_set == nullptr) throw fail("found " + in_quotes(normal_key) + " before 'time set:'");
      if (normal_key == "number of steps") {
        if (words.size() != 1) throw fail("expected 'number of steps: n'");
        time_set->steps = integer(words[0], "the number of steps");
      } else if (normal_key == "filename start number") {
        if (words.size() != 1) throw fail("expected 'filename start number: n'");
        time_set->start = integer(words[0], "the first file number");
      } else if (normal_key == "filename increment") {
        if (words.size() != 1) throw fail("expected 'filename increment: n'");
        time_set->increment = integer(words[0], "the file number increment");
      } else if (normal_key == "time values") {
        continued_times = &time_set->times;
        append_numbers(words);
      } else if (normal_key == "filename numbers") {
        continued_numbers = &time_set->file_numbers;
        append_numbers(words);
      } else {
        throw fail("time set entry " + in_quotes(normal_key) + " is not supported");
      }
    } else if (section.empty()) {
      throw fail("found " + excerpt(line) + " before the FORMAT section");
    }
  }
  line_number = 0;
  if (!gold) throw fail("no 'type: ensight gold' in a FORMAT section; expected an EnSight Gold case file");
  if (result.geometry_pattern.empty()) throw fail("no 'model:' line in a GEOMETRY section");

  // Every time set must be complete; the last time is the one read.
  for (const auto& [number, set] : result.time_sets) {
    const std::string which = "time set " + std::to_string(number);
    if (!set.steps || *set.steps < 1) throw fail(which + ": no 'number of steps:' of at least 1");
    const auto steps = static_cast<std::size_t>(*set.steps);
    if (set.times.size() != steps)
      throw fail(which + ": " + std::to_string(set.times.size()) + " time values; expected " + std::to_string(steps));
    if (!set.file_numbers.empty() && set.file_numbers.size() != steps)
      throw fail(which + ": " + std::to_string(set.file_numbers.size()) + " file numbers; expected " +
                 std::to_string(steps));
    for (std::size_t i = 1; i < steps; ++i)
      if (!(set.times[i] > set.times[i - 1]))
        throw fail(which + ": time value " + std::to_string(i + 1) + " does not follow its predecessor; expected "
                   "increasing time values");
    result.last_time = std::max(result.last_time.value_or(set.times.back()), set.times.back());
  }
  // The file each entry names at the last step of its time set: VTK, asked
  // for the last time of all sets, reads every file at its set's last step.
  const auto file_at_last_step = [&](const std::string& pattern, int set_number, std::size_t line) {
    std::string file_name = pattern;
    if (set_number != 0) {
      const auto set = result.time_sets.find(set_number);
      if (set == result.time_sets.end())
        throw InputError(SourceLocation{name, line}, "time set " + std::to_string(set_number) + " is not defined");
      if (pattern.find('*') != std::string::npos) {
        const TimeSet& steps = set->second;
        const auto last = static_cast<long long>(steps.times.size()) - 1;
        long long number = 0;
        if (!steps.file_numbers.empty())
          number = steps.file_numbers.back();
        else if (steps.start && steps.increment)
          number = *steps.start + last * *steps.increment;
        else
          throw InputError(SourceLocation{name, line},
                           "time set " + std::to_string(set_number) +
                               " has neither 'filename numbers:' nor 'filename start number:' and "
                               "'filename increment:' for the '*' in " + in_quotes(pattern));
        file_name = replace_wildcards(pattern, number, case_file, line);
      }
    }
    const fs::path path(file_name);
    return path.is_absolute() ? path : case_file.parent_path() / path;
  };
  result.geometry_file = file_at_last_step(result.geometry_pattern, result.geometry_time_set, result.geometry_line);
  for (auto& variable : result.variables)
    variable.file = file_at_last_step(variable.pattern, variable.time_set, variable.line);
  return result;
}

// --- the data files

/// An element section of a part: its type and number of elements.
struct Section {
  std::string type;
  std::size_t count = 0;
};

struct PartShape {
  long long number = 0;
  std::string description;
  std::size_t nodes = 0;
  std::vector<Section> sections;
  std::size_t cells = 0;  // VTK makes one cell of every element

  std::size_t count_of(const std::string& type) const {
    return std::accumulate(sections.begin(), sections.end(), std::size_t{0},
                           [&type](std::size_t sum, const Section& section) {
                             return section.type == type ? sum + section.count : sum;
                           });
  }
};

enum class Encoding { Ascii, CBinary, FortranBinary };

struct Geometry {
  std::string file_name;  // for messages
  Encoding encoding = Encoding::Ascii;
  bool big_endian = false;
  std::vector<PartShape> parts;

  const PartShape* find(long long number) const {
    const auto found =
        std::find_if(parts.begin(), parts.end(), [number](const PartShape& part) { return part.number == number; });
    return found == parts.end() ? nullptr : &*found;
  }
};

/// Nodes per element of the element types VTK reads (0: per element, as in
/// nsided and nfaced), or -1 for anything else.
int nodes_per_element(std::string_view type) {
  static const std::map<std::string_view, int> table{
      {"point", 1},  {"bar2", 2},     {"bar3", 3},   {"tria3", 3},     {"tria6", 6},   {"quad4", 4},
      {"quad8", 8},  {"tetra4", 4},   {"tetra10", 10}, {"pyramid5", 5}, {"pyramid13", 13}, {"penta6", 6},
      {"penta15", 15}, {"hexa8", 8},  {"hexa20", 20}, {"nsided", 0},   {"nfaced", 0}};
  const auto found = table.find(type);
  return found == table.end() ? -1 : found->second;
}

/// An ASCII EnSight file read as VTK reads it: line by line, blank lines and
/// lines starting with '#' skipped where VTK skips them. Its last line must
/// end with a line end.
class AsciiFile {
 public:
  explicit AsciiFile(fs::path path) : path_(std::move(path)), in_(path_, std::ios::binary) {
    if (!in_) throw InputError(SourceLocation{path_.string()}, "cannot be opened for reading");
  }

  /// What the messages say the file is at (e.g. "part 2 ('fin')").
  void set_context(std::string context) { context_ = std::move(context); }

  /// True when only blank lines and comments are left.
  bool at_end() { return !fill_data_line(); }
  /// The next line that is not blank and not a comment, trimmed.
  std::string text(const std::string& expected) {
    if (!fill_data_line()) throw ends(expected);
    std::string line = std::move(*pending_);
    pending_.reset();
    return line;
  }
  /// The file's own description lines: the first is read as a data line, the
  /// second as it is, as VTK does.
  void descriptions() {
    text("a description line");
    raw_line("a second description line");
  }
  long long integer(const std::string& expected) {
    const std::string line = text(expected);
    const auto value = parse_integer(line);
    if (!value) throw found(line, expected + " (an integer)");
    return *value;
  }
  /// `rows` lines of `per_row` integers each, every one in [low, high].
  void integers(std::size_t rows, std::size_t per_row, long long low, long long high, const std::string& expected) {
    for (std::size_t row = 0; row < rows; ++row) integer_row(per_row, low, high, expected);
  }
  /// A line per entry of `per_row`, holding that many integers in [low, high].
  void integer_rows(const std::vector<long long>& per_row, long long low, long long high,
                    const std::string& expected) {
    for (const long long count : per_row) integer_row(static_cast<std::size_t>(count), low, high, expected);
  }
  /// `count` lines of one integer each, in [low, high].
  std::vector<long long> counts(std::size_t count, long long low, long long high, const std::string& expected) {
    std::vector<long long> values;
    for (std::size_t i = 0; i < count; ++i) {
      const long long value = integer(expected);
      if (value < low || value > high) throw out_of_range(value, low, high, expected);
      values.push_back(value);
    }
    return values;
  }
  /// `count` lines of one real number each.
  void reals(std::size_t count, const std::string& expected) {
    for (std::size_t i = 0; i < count; ++i) {
      const std::string line = text(expected);
      if (!parse_real(line)) throw found(line, expected + " (a number, one per line)");
    }
  }
  void extents() {
    for (int i = 0; i < 3; ++i) text("an extents line");
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(SourceLocation{path_.string(), line_}, prefix() + message);
  }

 private:
  std::string prefix() const { return context_.empty() ? std::string() : context_ + ": "; }

  bool read_line(std::string& line) {
    if (!std::getline(in_, line)) return false;
    ++line_;
    if (line.size() > kMaxLineLength)
      fail("line of " + std::to_string(line.size()) + " characters; VTK's EnSight reader reads at most " +
           std::to_string(kMaxLineLength));
    // EnSight writers end every line; a file cut inside a number ("1.25e+00"
    // cut to "1.2") would otherwise read as a valid one.
    if (in_.eof() && !trim(line).empty()) fail("the last line has no line end: the file is cut short");
    return true;
  }
  bool fill_data_line() {
    if (pending_) return true;
    std::string line;
    while (read_line(line)) {
      if (line.empty() || line.front() == '#') continue;
      std::string trimmed = trim(line);
      if (trimmed.empty()) continue;
      pending_ = std::move(trimmed);
      return true;
    }
    return false;
  }
  void raw_line(const std::string& expected) {
    if (pending_) {
      pending_.reset();
      return;
    }
    std::string line;
    if (!read_line(line)) throw ends(expected);
  }
  void integer_row(std::size_t count, long long low, long long high, const std::string& expected) {
    const std::string line = text(expected);
    const std::string_view rest(line);
    std::size_t words = 0;
    std::size_t i = 0;
    while (i < rest.size()) {
      while (i < rest.size() && std::isspace(static_cast<unsigned char>(rest[i])) != 0) ++i;
      const std::size_t start = i;
      while (i < rest.size() && std::isspace(static_cast<unsigned char>(rest[i])) == 0) ++i;
      if (i == start) break;
      const std::string_view word = rest.substr(start, i - start);
      const auto value = parse_integer(word);
      if (!value) throw found(std::string(word), expected + " (an integer)");
      if (*value < low || *value > high) throw out_of_range(*value, low, high, expected);
      ++words;
    }
    if (words != count) throw found(line, std::to_string(count) + " integers on one line (" + expected + ")");
  }
  InputError ends(const std::string& expected) const {
    return InputError(SourceLocation{path_.string(), line_},
                      prefix() + "the file ends where " + expected + " was expected (truncated?)");
  }
  InputError found(const std::string& text, const std::string& expected) const {
    return InputError(SourceLocation{path_.string(), line_}, prefix() + "found " + excerpt(text) + "; expected " + expected);
  }
  InputError out_of_range(long long value, long long low, long long high, const std::string& expected) const {
    return InputError(SourceLocation{path_.string(), line_}, prefix() + "found " + std::to_string(value) +
                                                                  "; expected " + expected + " in " +
                                                                  std::to_string(low) + ".." + std::to_string(high));
  }

  fs::path path_;
  std::ifstream in_;
  std::size_t line_ = 0;
  std::optional<std::string> pending_;
  std::string context_;
};

/// A binary EnSight file: "C Binary" (items one after the other) or "Fortran
/// Binary" (each item a record between two 32-bit lengths), 80-character
/// strings, 32-bit integers and floats in one byte order.
class BinaryFile {
 public:
  BinaryFile(fs::path path, Encoding encoding, std::optional<bool> big_endian)
      : path_(std::move(path)), in_(path_, std::ios::binary), fortran_(encoding == Encoding::FortranBinary),
        big_endian_(big_endian) {
    if (!in_) throw InputError(SourceLocation{path_.string()}, "cannot be opened for reading");
    std::error_code error;
    size_ = std::filesystem::file_size(path_, error);
    if (error) throw InputError(SourceLocation{path_.string()}, "cannot be read: " + error.message());
  }

  void set_context(std::string context) { context_ = std::move(context); }
  std::optional<bool> big_endian() const { return big_endian_; }

  bool at_end() const { return position_ >= size_; }
  /// An 80-character string, up to its first NUL, trimmed.
  std::string text(const std::string& expected) {
    std::array<char, 80> buffer{};
    begin_record(buffer.size(), expected);
    read(buffer.data(), buffer.size());
    end_record(buffer.size(), expected);
    const auto end = std::find(buffer.begin(), buffer.end(), '\0');
    return trim(std::string_view(buffer.data(), static_cast<std::size_t>(end - buffer.begin())));
  }
  /// The format line and the file's two description lines.
  void descriptions() {
    text("the format line");
    text("a description line");
    text("a second description line");
  }
  /// A 32-bit integer. The first one a C binary geometry file holds is a part
  /// number, which tells its byte order as VTK tells it: little-endian if
  /// that reads as 0..65536.
  long long integer(const std::string& expected) {
    std::array<unsigned char, 4> bytes{};
    begin_record(4, expected);
    read(reinterpret_cast<char*>(bytes.data()), 4);
    end_record(4, expected);
    if (!big_endian_) {
      const long long little = decode(bytes.data(), false);
      big_endian_ = !(little >= 0 && little <= kMaxPartNumber);
    }
    return decode(bytes.data(), *big_endian_);
  }
  /// `rows` x `per_row` integers in one record, every one in [low, high].
  void integers(std::size_t rows, std::size_t per_row, long long low, long long high, const std::string& expected) {
    scan_integers(rows * per_row, low, high, expected, nullptr);
  }
  void integer_rows(const std::vector<long long>& per_row, long long low, long long high,
                    const std::string& expected) {
    scan_integers(sum(per_row), low, high, expected, nullptr);
  }
  std::vector<long long> counts(std::size_t count, long long low, long long high, const std::string& expected) {
    std::vector<long long> values;
    scan_integers(count, low, high, expected, &values);
    return values;
  }
  /// `count` floats in one record; their values do not matter here.
  void reals(std::size_t count, const std::string& expected) {
    const std::uint64_t bytes = 4 * static_cast<std::uint64_t>(count);
    begin_record(bytes, expected);
    position_ += bytes;
    in_.seekg(static_cast<std::streamoff>(position_));
    end_record(bytes, expected);
  }
  void extents() { reals(6, "the extents"); }
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(SourceLocation{path_.string()}, prefix() + message + " (at byte " + std::to_string(position_) + ")");
  }

 private:
  std::string prefix() const { return context_.empty() ? std::string() : context_ + ": "; }

  static long long decode(const unsigned char* bytes, bool big_endian) {
    std::uint32_t value = 0;
    for (int i = 0; i < 4; ++i) {
      const int shift = big_endian ? 8 * (3 - i) : 8 * i;
      value |= static_cast<std::uint32_t>(bytes[i]) << shift;
    }
    return static_cast<std::int32_t>(value);
  }
  void read(char* into, std::size_t bytes) {
    if (position_ + bytes > size_) fail_end("data");
    in_.read(into, static_cast<std::streamsize>(bytes));
    if (!in_) fail("read error");
    position_ += bytes;
  }
  [[noreturn]] void fail_end(const std::string& expected) const {
    fail("the file ends where " + expected + " was expected (truncated?)");
  }
  /// Checks that `bytes` bytes of `expected` follow and, in a Fortran file,
  /// reads the record's leading length.
  void begin_record(std::uint64_t bytes, const std::string& expected) {
    if (fortran_) {
      if (position_ + 4 > size_) fail_end(expected);
      std::array<unsigned char, 4> marker{};
      read(reinterpret_cast<char*>(marker.data()), 4);
      const long long length = decode(marker.data(), big_endian_.value_or(false));
      if (length < 0 || static_cast<std::uint64_t>(length) != bytes)
        fail("a Fortran record of " + std::to_string(length) + " bytes where " + expected + " (" +
             std::to_string(bytes) + " bytes) was expected");
    }
    if (position_ + bytes > size_) fail_end(expected);
  }
  void end_record(std::uint64_t bytes, const std::string& expected) {
    if (!fortran_) return;
    if (position_ + 4 > size_) fail_end("the end of a Fortran record of " + expected);
    std::array<unsigned char, 4> marker{};
    read(reinterpret_cast<char*>(marker.data()), 4);
    const long long length = decode(marker.data(), big_endian_.value_or(false));
    if (length < 0 || static_cast<std::uint64_t>(length) != bytes)
      fail("a Fortran record of " + expected + " ends with the length " + std::to_string(length) + "; expected " +
           std::to_string(bytes));
  }
  void scan_integers(std::size_t count, long long low, long long high, const std::string& expected,
                     std::vector<long long>* values) {
    const std::uint64_t bytes = 4 * static_cast<std::uint64_t>(count);
    begin_record(bytes, expected);
    if (values != nullptr) values->reserve(count);
    const bool big = big_endian_.value_or(false);
    std::vector<unsigned char> chunk;
    std::size_t left = count;
    while (left > 0) {
      const std::size_t n = std::min<std::size_t>(left, 1 << 16);
      chunk.resize(4 * n);
      read(reinterpret_cast<char*>(chunk.data()), chunk.size());
      for (std::size_t i = 0; i < n; ++i) {
        const long long value = decode(chunk.data() + 4 * i, big);
        if (value < low || value > high)
          fail("found " + std::to_string(value) + "; expected " + expected + " in " + std::to_string(low) + ".." +
               std::to_string(high));
        if (values != nullptr) values->push_back(value);
      }
      left -= n;
    }
    end_record(bytes, expected);
  }

  fs::path path_;
  std::ifstream in_;
  std::uint64_t size_ = 0;
  std::uint64_t position_ = 0;
  bool fortran_ = false;
  std::optional<bool> big_endian_;
  std::string context_;
};

/// How the geometry file is written, told from its first bytes as VTK tells
/// it: "<x> Binary" in the first 80 bytes (or in the first record of a
/// Fortran file) means binary, anything else ASCII.
std::pair<Encoding, std::optional<bool>> detect_encoding(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::array<char, 84> head{};
  in.read(head.data(), head.size());
  const auto got = static_cast<std::size_t>(in.gcount());
  const auto holds_binary = [](std::string_view text) {
    const auto words = split_words(text.substr(0, text.find('\0')));
    return words.size() >= 2 && starts_with(words[1], "Binary");
  };
  if (got >= 84) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(head.data());
    const bool little = bytes[0] == 80 && bytes[1] == 0 && bytes[2] == 0 && bytes[3] == 0;
    const bool big = bytes[0] == 0 && bytes[1] == 0 && bytes[2] == 0 && bytes[3] == 80;
    if ((little || big) && holds_binary(std::string_view(head.data() + 4, 80)))
      return {Encoding::FortranBinary, big};
  }
  if (holds_binary(std::string_view(head.data(), std::min<std::size_t>(got, 80)))) return {Encoding::CBinary, {}};
  return {Encoding::Ascii, false};
}

std::string part_context(const PartShape& part) {
  return "part " + std::to_string(part.number) + (part.description.empty() ? "" : " (" + in_quotes(part.description) + ")");
}

/// Walks a geometry file; fails on anything VTK would misread.
template <typename File>
std::vector<PartShape> scan_geometry(File& file) {
  file.descriptions();
  const auto id_line = [&file](const char* what) {
    const std::string line = file.text(std::string("'") + what + " id <off|given|assign|ignore>'");
    const auto words = split_words(line);
    if (words.size() < 3 || words[0] != what || words[1] != "id")
      file.fail("found " + excerpt(line) + "; expected '" + what + " id <off|given|assign|ignore>'");
    return words[2] == "given" || words[2] == "ignore";
  };
  const bool node_ids = id_line("node");
  const bool element_ids = id_line("element");

  std::vector<PartShape> parts;
  const auto next_keyword = [&file](const char* expected) -> std::optional<std::string> {
    if (file.at_end()) return std::nullopt;
    return file.text(expected);
  };
  std::optional<std::string> keyword = next_keyword("'extents' or 'part'");
  if (keyword && starts_with(*keyword, "extents")) {
    file.extents();
    keyword = next_keyword("'part'");
  }
  while (keyword) {
    if (!starts_with(*keyword, "part")) file.fail("found " + excerpt(*keyword) + "; expected 'part'");
    PartShape part;
    part.number = file.integer("a part number");
    if (part.number < 1 || part.number > kMaxPartNumber)
      file.fail("part number " + std::to_string(part.number) + "; expected 1.." + std::to_string(kMaxPartNumber));
    for (const auto& other : parts)
      if (other.number == part.number) file.fail("part " + std::to_string(part.number) + " appears twice");
    part.description = file.text("a part description");
    file.set_context(part_context(part));
    const std::string coordinates = file.text("'coordinates'");
    if (starts_with(coordinates, "block"))
      file.fail("structured ('block') parts are not supported; expected 'coordinates'");
    if (!starts_with(coordinates, "coordinates")) file.fail("found " + excerpt(coordinates) + "; expected 'coordinates'");
    const long long nodes = file.integer("the number of nodes");
    if (nodes < 0 || nodes > kMaxCount) file.fail("number of nodes " + std::to_string(nodes) + " is out of range");
    part.nodes = static_cast<std::size_t>(nodes);
    if (node_ids) file.integers(part.nodes, 1, std::numeric_limits<std::int32_t>::min(), kMaxCount, "a node id");
    for (const char* axis : {"an x coordinate", "a y coordinate", "a z coordinate"}) file.reals(part.nodes, axis);

    keyword = next_keyword("an element type or 'part'");
    while (keyword && !starts_with(*keyword, "part")) {
      const std::string type = split_words(*keyword).front();
      if (starts_with(type, "g_")) file.fail("ghost elements (" + in_quotes(type) + ") are not supported");
      const int per_element = nodes_per_element(type);
      if (per_element < 0) file.fail("found " + excerpt(*keyword) + "; expected an element type or 'part'");
      const long long elements = file.integer("the number of " + type + " elements");
      if (elements < 0 || elements > kMaxCount)
        file.fail("number of " + type + " elements " + std::to_string(elements) + " is out of range");
      const auto count = static_cast<std::size_t>(elements);
      if (element_ids) file.integers(count, 1, std::numeric_limits<std::int32_t>::min(), kMaxCount, "an element id");
      const std::string connectivity = "a node index of a " + type + " element";
      if (type == "nsided") {
        const auto sizes = file.counts(count, 3, kMaxCount, "the number of nodes of an nsided element");
        file.integer_rows(sizes, 1, nodes, connectivity);
      } else if (type == "nfaced") {
        const auto faces = file.counts(count, 1, kMaxCount, "the number of faces of an nfaced element");
        const auto sizes = file.counts(sum(faces), 3, kMaxCount, "the number of nodes of an nfaced face");
        file.integer_rows(sizes, 1, nodes, connectivity);
      } else {
        file.integers(count, static_cast<std::size_t>(per_element), 1, nodes, connectivity);
      }
      part.sections.push_back({type, count});
      part.cells += count;
      keyword = next_keyword("an element type or 'part'");
    }
    file.set_context("");
    parts.push_back(std::move(part));
  }
  return parts;
}

/// Walks a variable file against the geometry; records the parts it covers.
template <typename File>
void scan_variable(File& file, Variable& variable, const Geometry& geometry) {
  const std::string values = variable.components == 1 ? "a value" : "a vector component";
  file.text("the description line");
  const auto next_keyword = [&file](const char* expected) -> std::optional<std::string> {
    if (file.at_end()) return std::nullopt;
    return file.text(expected);
  };
  const auto check_plain = [&file](const std::string& keyword) {
    const auto words = split_words(keyword);
    for (std::size_t i = 1; i < words.size(); ++i)
      if (words[i] == "undef" || words[i] == "partial")
        file.fail("'" + words[i] + "' values are not supported; expected a value for every node or element");
  };
  std::optional<std::string> keyword = next_keyword("'part'");
  // A file cut after its description would otherwise pass as one that
  // gives no values anywhere.
  if (!keyword) file.fail("no 'part' after the description line; expected values for at least one part (truncated?)");
  while (keyword) {
    if (!starts_with(*keyword, "part")) file.fail("found " + excerpt(*keyword) + "; expected 'part'");
    const long long number = file.integer("a part number");
    const PartShape* part = geometry.find(number);
    if (part == nullptr) {
      std::string known;
      for (const auto& other : geometry.parts) known += (known.empty() ? "" : ", ") + std::to_string(other.number);
      file.fail("part " + std::to_string(number) + " is not in " + geometry.file_name + ", which has part" +
                (geometry.parts.size() == 1 ? " " : "s ") + (known.empty() ? "none" : known));
    }
    if (variable.parts.count(number) > 0) file.fail("part " + std::to_string(number) + " appears twice");
    file.set_context(part_context(*part));
    // VTK reads nothing more of a part without nodes or elements.
    const std::string in_geometry = " in " + geometry.file_name;
    if (variable.association == FieldAssociation::Point) {
      if (part->nodes == 0 && !file.at_end()) {
        const std::string next = file.text("'part'");
        if (!starts_with(next, "part")) file.fail("values for nodes, but the part has none" + in_geometry);
        keyword = next;
        file.set_context("");
        continue;
      }
      if (part->nodes > 0) {
        const std::string coordinates = file.text("'coordinates'");
        if (!starts_with(coordinates, "coordinates"))
          file.fail("found " + excerpt(coordinates) + "; expected 'coordinates'");
        check_plain(coordinates);
        for (int c = 0; c < variable.components; ++c) file.reals(part->nodes, values);
        variable.parts.insert(number);
      }
      keyword = next_keyword("'part'");
    } else {
      keyword = next_keyword("an element type or 'part'");
      if (part->cells == 0 && keyword && !starts_with(*keyword, "part"))
        file.fail("values for " + excerpt(*keyword) + " elements, but the part has none" + in_geometry);
      if (part->cells > 0) {
        // VTK leaves the values of elements the file skips undefined.
        std::set<std::string> types;
        std::size_t covered = 0;
        while (keyword && !starts_with(*keyword, "part")) {
          check_plain(*keyword);
          const std::string type = split_words(*keyword).front();
          if (nodes_per_element(type) < 0) file.fail("found " + excerpt(*keyword) + "; expected an element type");
          const std::size_t count = part->count_of(type);
          if (count == 0) file.fail("values for " + type + " elements, which the part does not have" + in_geometry);
          if (!types.insert(type).second) file.fail("values for " + type + " elements appear twice");
          for (int c = 0; c < variable.components; ++c) file.reals(count, values);
          covered += count;
          keyword = next_keyword("an element type or 'part'");
        }
        if (covered != part->cells)
          file.fail("values for " + std::to_string(covered) + " of the part's " + std::to_string(part->cells) +
                    " elements" + in_geometry + "; expected all of them");
        variable.parts.insert(number);
      }
    }
    file.set_context("");
  }
}

Geometry check_geometry(const fs::path& path) {
  std::error_code error;
  if (!fs::is_regular_file(path, error))
    throw InputError(SourceLocation{path.string()}, "geometry file not found (named by the case file)");
  Geometry geometry;
  geometry.file_name = path.filename().string();
  std::optional<bool> big_endian;
  std::tie(geometry.encoding, big_endian) = detect_encoding(path);
  if (geometry.encoding == Encoding::Ascii) {
    AsciiFile file(path);
    geometry.parts = scan_geometry(file);
  } else {
    BinaryFile file(path, geometry.encoding, big_endian);
    geometry.parts = scan_geometry(file);
    geometry.big_endian = file.big_endian().value_or(false);
  }
  if (geometry.parts.empty()) throw InputError(SourceLocation{path.string()}, "no parts; expected at least one 'part'");
  return geometry;
}

void check_variable(Variable& variable, const Geometry& geometry, const fs::path& case_file) {
  std::error_code error;
  if (!fs::is_regular_file(variable.file, error))
    throw InputError(SourceLocation{variable.file.string()},
                     "file of variable " + in_quotes(variable.description) + " not found (named by " +
                         case_file.filename().string() + ":" + std::to_string(variable.line) + ")");
  if (geometry.encoding == Encoding::Ascii) {
    AsciiFile file(variable.file);
    scan_variable(file, variable, geometry);
  } else {
    BinaryFile file(variable.file, geometry.encoding, geometry.big_endian);
    scan_variable(file, variable, geometry);
  }
}

/// VTK 9.1's ASCII reader stores the nodes of an nsided element in reverse
/// order (its binary reader does not), which turns the face inside out: put
/// them back in the file's order.
void restore_nsided_order(vtkDataSet* data, const PartShape& part) {
  auto* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (grid == nullptr) return;
  vtkNew<vtkIdList> ids;
  vtkIdType first = 0;
  for (const auto& section : part.sections) {
    const auto count = static_cast<vtkIdType>(section.count);
    if (section.type == "nsided") {
      for (vtkIdType cell = first; cell < first + count; ++cell) {
        if (grid->GetCellType(cell) != VTK_POLYGON) continue;
        grid->GetCellPoints(cell, ids);
        std::vector<vtkIdType> points(ids->GetPointer(0), ids->GetPointer(0) + ids->GetNumberOfIds());
        std::reverse(points.begin(), points.end());
        grid->ReplaceCell(cell, static_cast<int>(points.size()), points.data());
      }
    }
    first += count;
  }
}

/// The parts VTK made, checked against the geometry and variable files, as
/// leaves named by their descriptions.
std::vector<Leaf> checked_parts(vtkDataObject* output, const Case& spec, const Geometry& geometry,
                                const fs::path& case_file) {
  const SourceLocation where{case_file.string()};
  auto* blocks = vtkMultiBlockDataSet::SafeDownCast(output);
  if (blocks == nullptr || blocks->GetNumberOfBlocks() != geometry.parts.size())
    throw InputError(where, "VTK read " + std::to_string(blocks == nullptr ? 0 : blocks->GetNumberOfBlocks()) +
                                " parts; the geometry file " + spec.geometry_file.filename().string() + " has " +
                                std::to_string(geometry.parts.size()));
  std::vector<Leaf> leaves;
  for (unsigned int i = 0; i < blocks->GetNumberOfBlocks(); ++i) {
    const PartShape& part = geometry.parts[i];
    auto* data = vtkDataSet::SafeDownCast(blocks->GetBlock(i));
    const auto points = data == nullptr ? 0 : static_cast<std::size_t>(data->GetNumberOfPoints());
    const auto cells = data == nullptr ? 0 : static_cast<std::size_t>(data->GetNumberOfCells());
    if (points != part.nodes || cells != part.cells)
      throw InputError(where, part_context(part) + ": VTK read " + std::to_string(points) + " nodes and " +
                                  std::to_string(cells) + " elements; the geometry file has " +
                                  std::to_string(part.nodes) + " and " + std::to_string(part.cells));
    for (const auto& variable : spec.variables) {
      if (variable.parts.count(part.number) == 0) continue;
      const bool per_node = variable.association == FieldAssociation::Point;
      vtkDataSetAttributes* attributes = per_node ? static_cast<vtkDataSetAttributes*>(data->GetPointData())
                                                  : static_cast<vtkDataSetAttributes*>(data->GetCellData());
      vtkDataArray* array = attributes->GetArray(variable.description.c_str());
      const auto expected = static_cast<vtkIdType>(per_node ? part.nodes : part.cells);
      if (array == nullptr || array->GetNumberOfComponents() != variable.components ||
          array->GetNumberOfTuples() != expected)
        throw InputError(where, part_context(part) + ": VTK did not read variable " + in_quotes(variable.description) +
                                    " from " + variable.file.filename().string());
    }
    if (geometry.encoding == Encoding::Ascii) restore_nsided_order(data, part);
    const std::string name = part.description.empty() ? "part" + std::to_string(part.number) : part.description;
    leaves.push_back({name, data});
  }
  return leaves;
}

}  // namespace ensight

FileContents read_ensight(const fs::path& case_file, const ScopedVtkMessageCapture& capture) {
  ensight::Case spec = ensight::parse_case(case_file);
  const ensight::Geometry geometry = ensight::check_geometry(spec.geometry_file);
  for (auto& variable : spec.variables) ensight::check_variable(variable, geometry, case_file);

  vtkNew<vtkGenericEnSightReader> reader;
  reader->SetCaseFileName(case_file.string().c_str());
  reader->UpdateInformation();
  throw_if_vtk_failed(reader, false, capture, case_file, "EnSight Gold", true);
  // Only the variables checked above: VTK would read the others (tensors,
  // complex values) as carelessly as the rest.
  reader->GetPointDataArraySelection()->DisableAllArrays();
  reader->GetCellDataArraySelection()->DisableAllArrays();
  for (const auto& variable : spec.variables)
    (variable.association == FieldAssociation::Point ? reader->GetPointDataArraySelection()
                                                      : reader->GetCellDataArraySelection())
        ->EnableArray(variable.description.c_str());
  // The last time of all time sets: VTK then reads each file at the last step
  // of its own time set.
  if (spec.last_time)
    reader->UpdateTimeStep(*spec.last_time);
  else
    reader->Update();

  FileContents contents;
  contents.object = reader->GetOutputDataObject(0);
  throw_if_vtk_failed(reader, contents.object == nullptr, capture, case_file, "EnSight Gold", true);
  contents.leaves = ensight::checked_parts(contents.object, spec, geometry, case_file);
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
            leaves.push_back({zone_name + "/" + block_name(patches, q),
                              vtkDataSet::SafeDownCast(patches->GetBlock(q)), true});
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

  const std::string extension = lower_case(file.extension().string());
  const std::string expected = extension == ".case" ? "an EnSight Gold case file"
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

std::vector<std::string> unique_locations(const std::vector<Leaf>& leaves) {
  std::vector<std::string> names;
  for (const auto& leaf : leaves)
    if (std::find(names.begin(), names.end(), leaf.location) == names.end()) names.push_back(leaf.location);
  return names;
}

/// Checks every point index of every cell before any filter walks the cells:
/// VTK's readers do not, and a filter would read out of bounds.
void check_point_indices(vtkDataSet* data, const std::string& file, const std::string& location) {
  const vtkIdType point_count = data->GetNumberOfPoints();
  vtkNew<vtkIdList> ids;
  for (vtkIdType cell = 0; cell < data->GetNumberOfCells(); ++cell) {
    data->GetCellPoints(cell, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
      const vtkIdType id = ids->GetId(k);
      if (id < 0 || id >= point_count)
        throw InputError(SourceLocation{file}, "block '" + location + "': cell " + std::to_string(cell) +
                                                   " refers to point " + std::to_string(id) + "; expected 0.." +
                                                   std::to_string(point_count - 1) + " (the block has " +
                                                   std::to_string(point_count) + " points)");
    }
  }
}

bool has_volume_cells(vtkDataSet* data) {
  vtkNew<vtkCellTypes> types;
  data->GetCellTypes(types);
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType i = 0; i < types->GetNumberOfTypes(); ++i) {
    cell->SetCellType(types->GetCellType(i));
    if (cell->GetCellDimension() == 3) return true;
  }
  return false;
}

/// The boundary faces of a dataset with volume cells, ordered outward as VTK
/// orders a cell's faces and carrying the cell data of their volume cell.
vtkSmartPointer<vtkPolyData> boundary_surface(vtkDataSet* data) {
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  auto* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (grid == nullptr) {
    vtkNew<vtkDataSetSurfaceFilter> filter;
    filter->SetInputData(data);
    filter->Update();
    surface->ShallowCopy(filter->GetOutput());
    return surface;
  }
  // Run through the pipeline, VTK 9.1's surface filters leak the summary of
  // the grid they make (LeakSanitizer fails the tests on it); their direct
  // execution methods take one that stays ours. Linear cells go to
  // vtkGeometryFilter, quadratic ones to vtkDataSetSurfaceFilter, which splits
  // their faces into linear triangles: the choice the filters make themselves.
  const std::unique_ptr<vtkGeometryFilterHelper> summary(vtkGeometryFilterHelper::CharacterizeUnstructuredGrid(grid));
  if (summary->IsLinear) {
    vtkNew<vtkGeometryFilter> filter;
    filter->UnstructuredGridExecute(grid, surface, summary.get(), nullptr);
  } else {
    vtkNew<vtkDataSetSurfaceFilter> filter;
    filter->UnstructuredGridExecute(grid, surface, summary.get());
  }
  return surface;
}

/// A CGNS boundary patch as its faces and the points they use (in the zone's
/// order) with their point data: VTK 9.1 gives a patch every point of its
/// zone, volume points included.
vtkSmartPointer<vtkDataSet> patch_surface(vtkDataSet* patch, const std::string& file, const std::string& location) {
  const vtkIdType point_count = patch->GetNumberOfPoints();
  std::vector<vtkIdType> new_index(static_cast<std::size_t>(point_count), -1);
  vtkNew<vtkIdList> ids;
  for (vtkIdType cell = 0; cell < patch->GetNumberOfCells(); ++cell) {
    // VTK makes cells of unknown type of a boundary condition it misreads
    // (one given by a list of vertices, for example).
    const int type = patch->GetCellType(cell);
    if (type != VTK_TRIANGLE && type != VTK_QUAD && type != VTK_POLYGON && type != VTK_LINE && type != VTK_VERTEX)
      throw InputError(SourceLocation{file},
                       "boundary patch '" + location + "': VTK read cell " + std::to_string(cell) + " as cell type " +
                           std::to_string(type) + "; expected triangles or quadrilaterals (VTK 9.1 reads a patch "
                           "given as face elements: PointRange, PointList or ElementRange at FaceCenter)");
    patch->GetCellPoints(cell, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) new_index[static_cast<std::size_t>(ids->GetId(k))] = 0;
  }
  vtkIdType kept = 0;
  std::for_each(new_index.begin(), new_index.end(), [&kept](vtkIdType& index) {
    if (index == 0) index = kept++;
  });

  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  if (auto* point_set = vtkPointSet::SafeDownCast(patch); point_set != nullptr && point_set->GetPoints() != nullptr)
    points->SetDataType(point_set->GetPoints()->GetDataType());
  points->SetNumberOfPoints(kept);
  grid->GetPointData()->CopyAllocate(patch->GetPointData(), kept);
  double xyz[3];
  for (vtkIdType p = 0; p < point_count; ++p) {
    const vtkIdType index = new_index[static_cast<std::size_t>(p)];
    if (index < 0) continue;
    patch->GetPoint(p, xyz);
    points->SetPoint(index, xyz);
    grid->GetPointData()->CopyData(patch->GetPointData(), p, index);
  }
  grid->SetPoints(points);
  grid->Allocate(patch->GetNumberOfCells());
  for (vtkIdType cell = 0; cell < patch->GetNumberOfCells(); ++cell) {
    patch->GetCellPoints(cell, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      ids->SetId(k, new_index[static_cast<std::size_t>(ids->GetId(k))]);
    grid->InsertNextCell(patch->GetCellType(cell), ids);
  }
  grid->GetCellData()->PassData(patch->GetCellData());
  return grid;
}

/// The faces one dataset contributes, with the cell each face came from (a
/// triangle strip gives several faces of one cell).
struct Part {
  vtkSmartPointer<vtkDataSet> surface;
  std::uint32_t location = 0;
  std::vector<std::uint32_t> offsets{0};
  std::vector<std::uint32_t> indices;
  std::vector<vtkIdType> face_cell;  ///< the cell each face came from, unless cells_are_faces
  bool cells_are_faces = false;      ///< face f is cell f (polygon-only polydata)

  std::size_t face_count() const { return offsets.size() - 1; }
};

/// Closes the face whose point indices were just appended; they came from `cell`.
void end_face(Part& part, vtkIdType cell) {
  part.offsets.push_back(static_cast<std::uint32_t>(part.indices.size()));
  part.face_cell.push_back(cell);
}

void add_face(Part& part, vtkIdType cell, std::initializer_list<vtkIdType> ids) {
  for (const vtkIdType id : ids) part.indices.push_back(static_cast<std::uint32_t>(id));
  end_face(part, cell);
}

/// The common case, a polydata of polygons only (what foamToVTK, ParaView and
/// most exporters write): faces read straight from the cell array's offsets
/// and connectivity, point indices checked on the way, instead of one
/// virtual GetCellPoints call per cell.
bool polygons_only(vtkDataSet* data) {
  auto* poly = vtkPolyData::SafeDownCast(data);
  return poly != nullptr && poly->GetNumberOfVerts() == 0 && poly->GetNumberOfLines() == 0 &&
         poly->GetNumberOfStrips() == 0 && poly->GetPolys() != nullptr;
}

template <typename IdArray>
void copy_polygons(IdArray* offsets, IdArray* connectivity, vtkIdType point_count, Part& part,
                   const std::string& file, const std::string& location_name) {
  const auto* off = offsets->GetPointer(0);
  const auto* ids = connectivity->GetPointer(0);
  const vtkIdType cells = offsets->GetNumberOfValues() - 1;
  reserve_with_huge_pages(part.indices, static_cast<std::size_t>(connectivity->GetNumberOfValues()));
  part.indices.resize(static_cast<std::size_t>(connectivity->GetNumberOfValues()));
  part.offsets.resize(static_cast<std::size_t>(cells) + 1);
  part.cells_are_faces = true;
  std::uint32_t* out = part.indices.data();
  for (vtkIdType cell = 0; cell < cells; ++cell) {
    const auto begin = off[cell], end = off[cell + 1];
    if (end - begin < 3)
      throw InputError(SourceLocation{file}, "block '" + location_name + "': cell " + std::to_string(cell) +
                                                 " is a polygon with " + std::to_string(end - begin) +
                                                 " points; expected at least 3");
    for (auto k = begin; k < end; ++k) {
      const auto id = ids[k];
      if (id < 0 || id >= point_count)
        throw InputError(SourceLocation{file}, "block '" + location_name + "': cell " + std::to_string(cell) +
                                                   " refers to point " + std::to_string(id) + "; expected 0.." +
                                                   std::to_string(point_count - 1) + " (the block has " +
                                                   std::to_string(point_count) + " points)");
      *out++ = static_cast<std::uint32_t>(id);
    }
    part.offsets[static_cast<std::size_t>(cell) + 1] = static_cast<std::uint32_t>(end);
  }
}

Part extract_polygons(vtkSmartPointer<vtkDataSet> surface, std::uint32_t location, const std::string& file,
                      const std::string& location_name) {
  Part part;
  part.surface = std::move(surface);
  part.location = location;
  vtkCellArray* polys = vtkPolyData::SafeDownCast(part.surface)->GetPolys();
  const vtkIdType point_count = part.surface->GetNumberOfPoints();
  if (polys->IsStorage64Bit())
    copy_polygons(polys->GetOffsetsArray64(), polys->GetConnectivityArray64(), point_count, part, file,
                  location_name);
  else
    copy_polygons(polys->GetOffsetsArray32(), polys->GetConnectivityArray32(), point_count, part, file,
                  location_name);
  return part;
}

Part extract_faces(vtkSmartPointer<vtkDataSet> surface, std::uint32_t location, const std::string& file,
                   const std::string& location_name) {
  Part part;
  part.surface = std::move(surface);
  part.location = location;
  vtkDataSet* data = part.surface;
  vtkNew<vtkIdList> ids;
  for (vtkIdType cell = 0; cell < data->GetNumberOfCells(); ++cell) {
    const int type = data->GetCellType(cell);
    data->GetCellPoints(cell, ids);
    const vtkIdType n = ids->GetNumberOfIds();
    const auto id = [&ids](vtkIdType k) { return ids->GetId(k); };
    switch (type) {
      case VTK_TRIANGLE:
      case VTK_QUAD:
      case VTK_POLYGON:
        if (n < 3)
          throw InputError(SourceLocation{file}, "block '" + location_name + "': cell " + std::to_string(cell) +
                                                     " is a polygon with " + std::to_string(n) +
                                                     " points; expected at least 3");
        for (vtkIdType k = 0; k < n; ++k) part.indices.push_back(static_cast<std::uint32_t>(id(k)));
        end_face(part, cell);
        break;
      case VTK_PIXEL:
        // A pixel numbers its corners row by row, not around the face.
        add_face(part, cell, {id(0), id(1), id(3), id(2)});
        break;
      case VTK_TRIANGLE_STRIP:
        // Every other triangle of a strip is flipped so that all keep the
        // strip's orientation; repeated points (strip joints) make no face.
        for (vtkIdType k = 0; k + 2 < n; ++k) {
          if (id(k) == id(k + 1) || id(k + 1) == id(k + 2) || id(k) == id(k + 2)) continue;
          if (k % 2 == 0)
            add_face(part, cell, {id(k), id(k + 1), id(k + 2)});
          else
            add_face(part, cell, {id(k + 1), id(k), id(k + 2)});
        }
        break;
      case VTK_EMPTY_CELL:
      case VTK_VERTEX:
      case VTK_POLY_VERTEX:
      case VTK_LINE:
      case VTK_POLY_LINE:
        break;
      default: {
        const char* class_name = vtkCellTypes::GetClassNameFromTypeId(type);
        throw InputError(SourceLocation{file},
                         "block '" + location_name + "': cell " + std::to_string(cell) + " is a " +
                             (class_name != nullptr ? std::string(class_name) : "cell of type " + std::to_string(type)) +
                             "; expected triangles, quads, pixels, polygons or triangle strips on a surface");
      }
    }
  }
  return part;
}

/// The arrays of a dataset's point or cell data that become FieldArrays.
std::vector<vtkDataArray*> usable_arrays(vtkDataSetAttributes* attributes) {
  std::vector<vtkDataArray*> arrays;
  for (int i = 0; i < attributes->GetNumberOfArrays(); ++i) {
    vtkDataArray* array = attributes->GetArray(i);  // null for string and other non-numeric arrays
    if (array == nullptr || array->GetName() == nullptr || *array->GetName() == '\0') continue;
    if (std::string(array->GetName()) == vtkDataSetAttributes::GhostArrayName()) continue;
    const int components = array->GetNumberOfComponents();
    if (components == 1 || components == 3) arrays.push_back(array);
  }
  return arrays;
}

vtkDataSetAttributes* attributes_of(vtkDataSet* data, FieldAssociation association) {
  return association == FieldAssociation::Point ? static_cast<vtkDataSetAttributes*>(data->GetPointData())
                                                : static_cast<vtkDataSetAttributes*>(data->GetCellData());
}

void check_tuple_count(vtkDataArray* array, vtkIdType expected, const std::string& file,
                       const std::string& location, const char* per) {
  if (array->GetNumberOfTuples() != expected)
    throw InputError(SourceLocation{file}, "block '" + location + "': array '" + array->GetName() + "' has " +
                                               std::to_string(array->GetNumberOfTuples()) + " tuples; expected " +
                                               std::to_string(expected) + " (one per " + per + ")");
}

/// Appends all values of a float or double array in one pass; false for
/// other value types (the caller then goes through GetComponent).
template <typename Array>
bool append_typed(vtkDataArray* array, std::vector<double>& out) {
  auto* typed = Array::SafeDownCast(array);
  if (typed == nullptr) return false;
  const auto* values = typed->GetPointer(0);
  const auto count = static_cast<std::size_t>(typed->GetNumberOfValues());
  reserve_with_huge_pages(out, out.size() + count);
  out.insert(out.end(), values, values + count);
  return true;
}

bool append_values(vtkDataArray* array, std::vector<double>& out) {
  return append_typed<vtkDoubleArray>(array, out) || append_typed<vtkFloatArray>(array, out);
}

/// The values of the cells that became faces, in face order.
template <typename Array>
bool append_cells_typed(vtkDataArray* array, const std::vector<vtkIdType>& cells, std::vector<double>& out) {
  auto* typed = Array::SafeDownCast(array);
  if (typed == nullptr) return false;
  const auto* values = typed->GetPointer(0);
  const auto components = static_cast<std::size_t>(typed->GetNumberOfComponents());
  out.reserve(out.size() + cells.size() * components);
  for (const vtkIdType cell : cells)
    for (std::size_t c = 0; c < components; ++c) out.push_back(values[static_cast<std::size_t>(cell) * components + c]);
  return true;
}

bool append_cell_values(vtkDataArray* array, const std::vector<vtkIdType>& cells, std::vector<double>& out) {
  return append_cells_typed<vtkDoubleArray>(array, cells, out) || append_cells_typed<vtkFloatArray>(array, cells, out);
}

/// Appends the arrays that every part holds under the same name with the same
/// number of components; the first part decides the order.
void append_fields(const std::vector<Part>& parts, const std::vector<std::string>& location_names,
                   FieldAssociation association, const std::string& file, SurfaceMesh& mesh) {
  for (vtkDataArray* first : usable_arrays(attributes_of(parts.front().surface, association))) {
    const std::string name = first->GetName();
    const int components = first->GetNumberOfComponents();
    std::vector<vtkDataArray*> per_part;
    for (const auto& part : parts) {
      vtkDataArray* array = attributes_of(part.surface, association)->GetArray(name.c_str());
      if (array == nullptr || array->GetNumberOfComponents() != components) break;
      per_part.push_back(array);
    }
    if (per_part.size() != parts.size()) continue;

    FieldArray field;
    field.name = name;
    field.association = association;
    field.components = components;
    for (std::size_t p = 0; p < parts.size(); ++p) {
      const Part& part = parts[p];
      vtkDataArray* array = per_part[p];
      const std::string& location = location_names[part.location];
      if (association == FieldAssociation::Point) {
        check_tuple_count(array, part.surface->GetNumberOfPoints(), file, location, "point");
        if (!append_values(array, field.values))
          for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
            for (int c = 0; c < components; ++c) field.values.push_back(array->GetComponent(t, c));
      } else {
        check_tuple_count(array, part.surface->GetNumberOfCells(), file, location, "cell");
        if (part.cells_are_faces) {
          if (!append_values(array, field.values))
            for (vtkIdType cell = 0; cell < array->GetNumberOfTuples(); ++cell)
              for (int c = 0; c < components; ++c) field.values.push_back(array->GetComponent(cell, c));
        } else if (!append_cell_values(array, part.face_cell, field.values)) {
          for (const vtkIdType cell : part.face_cell)
            for (int c = 0; c < components; ++c) field.values.push_back(array->GetComponent(cell, c));
        }
      }
    }
    mesh.fields.push_back(std::move(field));
  }
}

void check_fits_uint32(std::size_t count, const std::string& file, const char* what) {
  if (count > std::numeric_limits<std::uint32_t>::max())
    throw InputError(SourceLocation{file}, std::to_string(count) + " " + what + "; at most " +
                                               std::to_string(std::numeric_limits<std::uint32_t>::max()) +
                                               " are supported");
}

/// " (VTK: ...)" with the warnings VTK gave while reading, or "".
std::string vtk_warnings_note(const FileContents& contents) {
  const std::string summary = summarize_vtk_messages(contents.warnings);
  return summary.empty() ? std::string() : " (VTK: " + summary + ")";
}

}  // namespace

SurfaceMesh read_vtk_surface(const std::filesystem::path& file, const VtkSurfaceOptions& options) {
  const std::string file_name = file.string();
  if (options.direct_vtp && lower_case(file.extension().string()) == ".vtp" &&
      std::all_of(options.locations.begin(), options.locations.end(),
                  [&file](const std::string& location) { return location == file.stem().string(); }))
    if (std::optional<SurfaceMesh> mesh = read_vtp_surface(file)) return std::move(*mesh);
  ScopedVtkMessageCapture capture;
  const FileContents contents = read_file(file, capture);
  const std::vector<Leaf>& leaves = contents.leaves;
  const std::vector<std::string> available = unique_locations(leaves);

  for (const auto& wanted : options.locations)
    if (std::find(available.begin(), available.end(), wanted) == available.end())
      throw InputError(SourceLocation{file_name}, "no location " + in_quotes(wanted) + "; the file holds " +
                                                      join_quoted(available) + vtk_warnings_note(contents));
  const std::set<std::string> wanted(options.locations.begin(), options.locations.end());
  // Unless asked for, CGNS boundary patches are left out: their faces are
  // faces of their zone's boundary too.
  const auto selected = [&wanted](const Leaf& leaf) {
    return wanted.empty() ? !leaf.patch : wanted.count(leaf.location) > 0;
  };

  SurfaceMesh mesh;
  for (const auto& leaf : leaves)
    if (selected(leaf) &&
        std::find(mesh.location_names.begin(), mesh.location_names.end(), leaf.location) == mesh.location_names.end())
      mesh.location_names.push_back(leaf.location);

  std::vector<Part> parts;
  for (const auto& leaf : leaves) {
    if (leaf.data == nullptr || !selected(leaf)) continue;
    const auto location = static_cast<std::uint32_t>(
        std::find(mesh.location_names.begin(), mesh.location_names.end(), leaf.location) -
        mesh.location_names.begin());
    if (!leaf.patch && polygons_only(leaf.data)) {
      Part part = extract_polygons(leaf.data, location, file_name, leaf.location);
      if (part.face_count() > 0) parts.push_back(std::move(part));
      continue;
    }
    check_point_indices(leaf.data, file_name, leaf.location);
    vtkSmartPointer<vtkDataSet> surface = leaf.data;
    if (leaf.patch) {
      surface = patch_surface(leaf.data, file_name, leaf.location);
    } else if (vtkPolyData::SafeDownCast(leaf.data) == nullptr && has_volume_cells(leaf.data)) {
      surface = boundary_surface(leaf.data);
      if (!capture.errors().empty())
        throw InputError(SourceLocation{file_name}, "block '" + leaf.location +
                                                        "': VTK could not extract the boundary surface: " +
                                                        summarize_vtk_messages(capture.errors()));
    }
    Part part = extract_faces(surface, location, file_name, leaf.location);
    if (part.face_count() > 0) parts.push_back(std::move(part));
  }
  if (parts.empty())
    throw InputError(SourceLocation{file_name},
                     "no faces (triangles, quads, polygons or triangle strips) in " +
                         (options.locations.empty() ? std::string("the file") : join_quoted(options.locations)) +
                         vtk_warnings_note(contents));

  std::size_t point_total = 0;
  std::size_t index_total = 0;
  for (const auto& part : parts) {
    point_total += static_cast<std::size_t>(part.surface->GetNumberOfPoints());
    index_total += part.indices.size();
  }
  check_fits_uint32(point_total, file_name, "points");
  check_fits_uint32(index_total, file_name, "face point indices");

  std::size_t face_total = 0;
  for (const auto& part : parts) face_total += part.face_count();
  reserve_with_huge_pages(mesh.points_xyz, 3 * point_total);
  reserve_with_huge_pages(mesh.face_indices, index_total);
  reserve_with_huge_pages(mesh.face_offsets, face_total + 1);
  reserve_with_huge_pages(mesh.face_location, face_total);
  for (const auto& part : parts) {
    const auto first_point = static_cast<std::uint32_t>(mesh.point_count());
    const auto first_index = static_cast<std::uint32_t>(mesh.face_indices.size());
    vtkPointSet* point_set = vtkPointSet::SafeDownCast(part.surface);
    vtkDataArray* coordinates = point_set && point_set->GetPoints() ? point_set->GetPoints()->GetData() : nullptr;
    if (!coordinates || !append_values(coordinates, mesh.points_xyz)) {
      double xyz[3];
      for (vtkIdType p = 0; p < part.surface->GetNumberOfPoints(); ++p) {
        part.surface->GetPoint(p, xyz);
        mesh.points_xyz.insert(mesh.points_xyz.end(), xyz, xyz + 3);
      }
    }
    for (const auto index : part.indices) mesh.face_indices.push_back(first_point + index);
    for (std::size_t f = 1; f < part.offsets.size(); ++f) mesh.face_offsets.push_back(first_index + part.offsets[f]);
    mesh.face_location.insert(mesh.face_location.end(), part.face_count(), part.location);
  }
  // Face arrays first: where a solver exports both (foamToVTK does by default),
  // the cell values are its own and the point values interpolated, and
  // SurfaceMesh::find_field returns the first array of a name.
  append_fields(parts, mesh.location_names, FieldAssociation::Face, file_name, mesh);
  append_fields(parts, mesh.location_names, FieldAssociation::Point, file_name, mesh);
  return mesh;
}

std::vector<std::string> list_vtk_locations(const std::filesystem::path& file) {
  ScopedVtkMessageCapture capture;
  return unique_locations(read_file(file, capture).leaves);
}

}  // namespace hydrocoef
