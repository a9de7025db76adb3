// VTK's messages while the VTK surface importer reads a file: kept from the
// terminal (ScopedVtkMessageCapture) and, when the read failed, turned into an
// InputError (throw_if_vtk_failed). Internal to the importer, not part of the
// public API.
#pragma once

#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

#include <filesystem>
#include <string>
#include <vector>

class vtkAlgorithm;

namespace hydrocoef::vtk_detail {

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
  vtkTypeMacro(CollectingOutputWindow, vtkOutputWindow) static CollectingOutputWindow* New() {
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

/// Switches vtkLogger's stderr output off and returns the level it had (how
/// that level is found: vtk_messages.cpp).
vtkLogger::Verbosity silence_vtk_logger_stderr();

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

/// VTK's messages, as one line: each cleaned of VTK's source locations and
/// object addresses, repeats and the executive's "returned failure for
/// request" left out, at most three and how many more.
std::string summarize_vtk_messages(const std::vector<std::string>& messages);

/// Throws the InputError for a file VTK could not read when the reader failed,
/// made no output or reported an error, or a warning if `warnings_are_errors`.
void throw_if_vtk_failed(vtkAlgorithm* reader, bool no_output, const ScopedVtkMessageCapture& capture,
                         const std::filesystem::path& file, const std::string& format, bool warnings_are_errors);

}  // namespace hydrocoef::vtk_detail
