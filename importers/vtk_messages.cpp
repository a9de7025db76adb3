// VTK's messages (vtk_messages.hpp): vtkLogger's stderr output switched off
// and back, and the messages VTK gave made into one line for an InputError.
#include "importers/vtk_messages.hpp"

#include <vtkAlgorithm.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "src/core/error.hpp"

namespace hydrocoef::vtk_detail {
namespace {

namespace fs = std::filesystem;

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

}  // namespace

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

}  // namespace hydrocoef::vtk_detail
