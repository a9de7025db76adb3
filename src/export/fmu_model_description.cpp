// fmu_model_description (fmu_model_description.hpp): the FMI 2.0 XML
// document of a Co-Simulation FMU, its units as UnitDefinitions with their
// SI base-unit exponents where hydrocoef's unit texts are known.
#include "src/export/fmu_model_description.hpp"

#include <cinttypes>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef {
namespace {

std::string attr(const std::string& text) { return escape::xml_text(text); }

// The SI base-unit exponents of the unit texts hydrocoef writes (FMI 2.0
// BaseUnit attributes, and factor for degrees); "" for a unit not known.
std::string base_unit(const std::string& unit) {
  static const std::map<std::string, std::string> known = {{"m/s", R"(m="1" s="-1")"},
                                                           {"rad/s", R"(s="-1" rad="1")"},
                                                           {"rad", R"(rad="1")"},
                                                           {"m", R"(m="1")"},
                                                           {"s", R"(s="1")"},
                                                           {"N", R"(kg="1" m="1" s="-2")"},
                                                           {"N m", R"(kg="1" m="2" s="-2")"},
                                                           {"N*m", R"(kg="1" m="2" s="-2")"},
                                                           {"kg", R"(kg="1")"},
                                                           {"m/s^2", R"(m="1" s="-2")"},
                                                           {"rad/s^2", R"(s="-2" rad="1")"},
                                                           {"1", ""},
                                                           {"deg", R"(rad="1" factor="0.017453292519943295")"}};
  const auto found = known.find(unit);
  return found == known.end() ? std::string() : found->second;
}

}  // namespace

std::string fmu_model_identifier(const std::string& name) {
  std::string out = "hc_";
  for (const char c : name) {
    if (out.size() >= 64) break;
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    out += ok ? c : '_';
  }
  return out;
}

std::string fmu_guid(std::uint64_t content_hash) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "hcrt-xxh64-%016" PRIx64, content_hash);
  return buffer;
}

std::string fmu_model_description(const FmuModelSpec& model) {
  std::set<std::string> names;
  for (const auto& variable : model.variables)
    if (!names.insert(variable.name).second)
      throw InputError("two variables of the FMU are named '" + variable.name +
                       "' (an axis and an output?); expected unique variable names");
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<fmiModelDescription fmiVersion=\"2.0\" modelName=\"" << attr(model.model_name) << "\" guid=\""
      << attr(model.guid) << "\" description=\"" << attr(model.description) << "\" generationTool=\""
      << attr(model.generation_tool) << "\" generationDateAndTime=\"" << attr(model.generation_time)
      << "\" variableNamingConvention=\"flat\" numberOfEventIndicators=\"0\">\n"
      << "  <CoSimulation modelIdentifier=\"" << attr(model.model_identifier)
      << "\" needsExecutionTool=\"false\" canHandleVariableCommunicationStepSize=\"true\" "
         "canInterpolateInputs=\"false\" maxOutputDerivativeOrder=\"0\" canRunAsynchronuously=\"false\" "
         "canBeInstantiatedOnlyOncePerProcess=\"false\" canNotUseMemoryManagementFunctions=\"true\" "
         "canGetAndSetFMUstate=\"false\" canSerializeFMUstate=\"false\" providesDirectionalDerivative=\"false\"/>\n";
  std::set<std::string> units;
  for (const auto& variable : model.variables)
    if (!variable.unit.empty()) units.insert(variable.unit);
  if (!units.empty()) {
    out << "  <UnitDefinitions>\n";
    for (const auto& unit : units) {
      const std::string base = base_unit(unit);
      out << "    <Unit name=\"" << attr(unit) << "\">";
      if (!base.empty()) out << "<BaseUnit " << base << "/>";
      out << "</Unit>\n";
    }
    out << "  </UnitDefinitions>\n";
  }
  out << "  <LogCategories>\n"
      << "    <Category name=\"logStatusError\" description=\"errors: refused calls and failed steps\"/>\n"
      << "    <Category name=\"logStatusWarning\" description=\"warnings\"/>\n"
      << "    <Category name=\"logCalls\" description=\"every FMI call (with logging on)\"/>\n"
      << "  </LogCategories>\n"
      << "  <ModelVariables>\n";
  std::map<std::uint32_t, std::size_t> index_of;  // value reference -> 1-based index
  for (std::size_t i = 0; i < model.variables.size(); ++i) {
    const auto& variable = model.variables[i];
    index_of[variable.value_reference] = i + 1;
    out << "    <!-- index " << i + 1 << " -->\n"
        << "    <ScalarVariable name=\"" << attr(variable.name) << "\" valueReference=\"" << variable.value_reference
        << "\" description=\"" << attr(variable.description) << "\" causality=\"" << variable.causality
        << "\" variability=\"" << variable.variability << "\"";
    if (variable.causality == "output") out << " initial=\"calculated\"";
    out << ">\n      <Real";
    if (!variable.unit.empty()) out << " unit=\"" << attr(variable.unit) << "\"";
    if (variable.start) out << " start=\"" << shortest_number(*variable.start) << "\"";
    out << "/>\n    </ScalarVariable>\n";
  }
  out << "  </ModelVariables>\n  <ModelStructure>\n";
  std::ostringstream unknowns, initial;
  for (std::size_t i = 0; i < model.variables.size(); ++i) {
    const auto& variable = model.variables[i];
    if (variable.causality != "output") continue;
    const auto& at_start = variable.initial_dependencies.value_or(variable.dependencies);
    for (const auto& [stream, dependencies] :
         {std::pair{&unknowns, &variable.dependencies}, std::pair{&initial, &at_start}}) {
      *stream << "      <Unknown index=\"" << i + 1 << "\" dependencies=\"";
      for (std::size_t d = 0; d < dependencies->size(); ++d)
        *stream << (d ? " " : "") << index_of.at((*dependencies)[d]);
      *stream << "\"/>\n";
    }
  }
  if (!unknowns.str().empty())
    out << "    <Outputs>\n"
        << unknowns.str() << "    </Outputs>\n"
        << "    <InitialUnknowns>\n"
        << initial.str() << "    </InitialUnknowns>\n";
  out << "  </ModelStructure>\n</fmiModelDescription>\n";
  return out.str();
}

}  // namespace hydrocoef
