// The project's own FMI 2.0 Co-Simulation host, for the FMU tests: it unzips
// an FMU (its own minimal zip reader: stored entries, every size and offset
// checked, CRC-32 verified), reads modelDescription.xml (a small XML reader:
// well-formedness, entities, attributes), dlopens the binary and resolves
// every fmi2 function of fmu/include/hydrocoef/fmi2_interface.h, then drives
// the instance. It keeps the standard's Co-Simulation state machine (FMI
// 2.0.x section 4.2.4) on its own side: the checked calls refuse a call the
// standard does not allow in the present state (HostRefusal, the FMU never
// called); raw() gives the functions themselves, for the tests that make
// illegal calls on purpose to see the FMU refuse them. Messages of the FMU
// arrive through the logger call-back, in log().
#pragma once

#define HYDROCOEF_FMI2_HOST
#include "hydrocoef/fmi2_interface.h"

#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace hydrocoef::test {

/// The files of a zip archive of stored entries, by name. std::runtime_error
/// naming the entry and what was wrong for anything else: a truncated or
/// inconsistent archive, a compressed entry, a bad CRC, an unsafe name.
std::map<std::string, std::string> unzip_stored(const std::string& bytes);

/// An XML element: its name, attributes (entities decoded) and children.
struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::vector<XmlElement> children;
  /// The attribute; std::runtime_error when absent.
  const std::string& at(const std::string& attribute) const;
  /// The children of that name.
  std::vector<const XmlElement*> all(const std::string& child) const;
};

/// The root element of an XML 1.0 document. std::runtime_error with the
/// byte offset for one that is not well-formed (mismatched or unclosed tags,
/// a bad entity, '<' in an attribute value, a duplicate attribute, text
/// outside the root, ...). No DTD.
XmlElement parse_xml(const std::string& text);

struct FmiVariable {
  std::string name;
  fmi2ValueReference value_reference = 0;
  std::string causality, variability, unit, description;
  std::optional<double> start;
  std::size_t index = 0;  ///< 1-based, in ModelVariables
};

struct ModelDescription {
  std::string fmi_version, model_name, guid, model_identifier;
  std::map<std::string, std::string> co_simulation;  ///< the CoSimulation element's attributes
  std::vector<FmiVariable> variables;
  /// ModelStructure/Outputs: the output's index -> its dependencies' indices.
  std::map<std::size_t, std::vector<std::size_t>> outputs;
  std::vector<std::string> units;  ///< UnitDefinitions' names
};

ModelDescription read_model_description(const std::string& xml);

/// A call the host refuses to make: the standard does not allow it now.
class HostRefusal : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// Every function of a Co-Simulation FMU, resolved by name.
struct Fmi2Functions {
  fmi2GetTypesPlatformTYPE* GetTypesPlatform = nullptr;
  fmi2GetVersionTYPE* GetVersion = nullptr;
  fmi2SetDebugLoggingTYPE* SetDebugLogging = nullptr;
  fmi2InstantiateTYPE* Instantiate = nullptr;
  fmi2FreeInstanceTYPE* FreeInstance = nullptr;
  fmi2SetupExperimentTYPE* SetupExperiment = nullptr;
  fmi2EnterInitializationModeTYPE* EnterInitializationMode = nullptr;
  fmi2ExitInitializationModeTYPE* ExitInitializationMode = nullptr;
  fmi2TerminateTYPE* Terminate = nullptr;
  fmi2ResetTYPE* Reset = nullptr;
  fmi2GetRealTYPE* GetReal = nullptr;
  fmi2GetIntegerTYPE* GetInteger = nullptr;
  fmi2GetBooleanTYPE* GetBoolean = nullptr;
  fmi2GetStringTYPE* GetString = nullptr;
  fmi2SetRealTYPE* SetReal = nullptr;
  fmi2SetIntegerTYPE* SetInteger = nullptr;
  fmi2SetBooleanTYPE* SetBoolean = nullptr;
  fmi2SetStringTYPE* SetString = nullptr;
  fmi2GetFMUstateTYPE* GetFMUstate = nullptr;
  fmi2SetFMUstateTYPE* SetFMUstate = nullptr;
  fmi2FreeFMUstateTYPE* FreeFMUstate = nullptr;
  fmi2SerializedFMUstateSizeTYPE* SerializedFMUstateSize = nullptr;
  fmi2SerializeFMUstateTYPE* SerializeFMUstate = nullptr;
  fmi2DeSerializeFMUstateTYPE* DeSerializeFMUstate = nullptr;
  fmi2GetDirectionalDerivativeTYPE* GetDirectionalDerivative = nullptr;
  fmi2SetRealInputDerivativesTYPE* SetRealInputDerivatives = nullptr;
  fmi2GetRealOutputDerivativesTYPE* GetRealOutputDerivatives = nullptr;
  fmi2DoStepTYPE* DoStep = nullptr;
  fmi2CancelStepTYPE* CancelStep = nullptr;
  fmi2GetStatusTYPE* GetStatus = nullptr;
  fmi2GetRealStatusTYPE* GetRealStatus = nullptr;
  fmi2GetIntegerStatusTYPE* GetIntegerStatus = nullptr;
  fmi2GetBooleanStatusTYPE* GetBooleanStatus = nullptr;
  fmi2GetStringStatusTYPE* GetStringStatus = nullptr;
};

struct LogEntry {
  std::string instance;
  fmi2Status status = fmi2OK;
  std::string category;
  std::string message;
};

class FmiHost {
 public:
  /// Unzips `fmu` into `dir` (which must exist), reads its model
  /// description and loads binaries/linux64/<modelIdentifier>.so.
  /// std::runtime_error for anything missing or malformed.
  FmiHost(const std::filesystem::path& fmu, const std::filesystem::path& dir);
  ~FmiHost();
  FmiHost(const FmiHost&) = delete;
  FmiHost& operator=(const FmiHost&) = delete;

  const ModelDescription& model() const { return model_; }
  const Fmi2Functions& raw() const { return functions_; }
  /// The callbacks the host gives fmi2Instantiate (its logger).
  const fmi2CallbackFunctions* callbacks() const { return &callbacks_; }
  /// The resources directory as a file URI (percent-encoded).
  std::string resource_uri() const;
  fmi2Component component() const { return component_; }
  const std::vector<LogEntry>& log() const { return log_; }
  void clear_log() { log_.clear(); }
  /// The host's view of the instance's state ("startAndEnd" before
  /// instantiation and after fmi2FreeInstance).
  std::string state() const;

  // The checked calls: HostRefusal for a call the standard does not allow in
  // the present state; otherwise the FMU's status (the state follows it: an
  // fmi2Error puts the instance in the error state).
  fmi2Status instantiate(const std::string& name = "instance", std::optional<std::string> guid = std::nullopt,
                         std::optional<std::string> resources = std::nullopt);
  fmi2Status setup_experiment(double start_time = 0.0);
  fmi2Status enter_initialization_mode();
  fmi2Status exit_initialization_mode();
  fmi2Status set_real(const std::vector<fmi2ValueReference>& vr, const std::vector<double>& values);
  fmi2Status get_real(const std::vector<fmi2ValueReference>& vr, std::vector<double>& values);
  fmi2Status do_step(double time, double step);
  fmi2Status terminate();
  fmi2Status reset();
  void free_instance();

 private:
  enum State : unsigned;
  void allow(const char* function, unsigned allowed) const;
  fmi2Status after(fmi2Status status, unsigned next);
  static void logger(fmi2ComponentEnvironment environment, fmi2String instance, fmi2Status status, fmi2String category,
                     fmi2String message, ...);

  std::filesystem::path dir_;
  ModelDescription model_;
  void* library_ = nullptr;
  Fmi2Functions functions_;
  fmi2CallbackFunctions callbacks_;
  fmi2Component component_ = nullptr;
  unsigned state_;
  std::vector<LogEntry> log_;
};

}  // namespace hydrocoef::test
