// modelDescription.xml of hydrocoef's FMI 2.0 Co-Simulation FMUs (FMI 2.0.x,
// section 2.2; docs/fmu.md). Every name and unit is data: written through
// escape::xml_text, the project's one XML escaper. The variables' value
// references are those of the FMU binary's model kind (fmu/src/fmu_surface.c).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hydrocoef {

/// One Real variable of an FMU.
struct FmuVariableSpec {
  std::string name;
  std::uint32_t value_reference = 0;
  std::string causality;    ///< input, output or parameter
  std::string variability;  ///< continuous, fixed, ...
  std::string unit;         ///< "" for none
  std::string description;
  std::optional<double> start;              ///< inputs and parameters
  std::vector<std::uint32_t> dependencies;  ///< outputs: the value references of the inputs they depend on
  /// outputs: what they depend on in initialisation mode (InitialUnknowns), when more than `dependencies`
  /// (a state's initial value set by parameters)
  std::optional<std::vector<std::uint32_t>> initial_dependencies;
};

struct FmuModelSpec {
  std::string model_name;
  std::string model_identifier;  ///< a C identifier (fmu_model_identifier)
  std::string guid;
  std::string description;
  std::string generation_tool;
  std::string generation_time;             ///< UTC, ISO 8601
  std::vector<FmuVariableSpec> variables;  ///< in value-reference order
};

/// A valid C identifier for modelIdentifier (and the binary's file name),
/// derived deterministically from a name: "hc_" followed by the name's bytes,
/// each byte outside [A-Za-z0-9_] as '_', at most 64 bytes in all.
std::string fmu_model_identifier(const std::string& name);

/// The GUID of an FMU whose resource is a runtime file of this content hash:
/// "hcrt-xxh64-" and the hash as 16 lowercase hexadecimal digits (the FMU
/// binary checks it at fmi2Instantiate; fmu/src/fmu_internal.h).
std::string fmu_guid(std::uint64_t content_hash);

/// The document. InputError when two variables share a name (FMI requires
/// unique names).
std::string fmu_model_description(const FmuModelSpec& model);

}  // namespace hydrocoef
