#include "src/export/daveml_export.hpp"

#include <stdexcept>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/version.hpp"

namespace hydrocoef {
namespace {

/// The numbers of one output at every node, the last axis fastest (DAVE-ML's
/// order): one line per row of the last axis, indented.
std::string data_table(const GridTable& table, const std::vector<double>& data, std::size_t output,
                       const std::string& indent) {
  const std::size_t n = table.axis_count(), n_out = table.output_count();
  std::vector<std::size_t> index(n, 0);
  std::string text;
  const std::size_t last = table.axes()[n - 1].breakpoints.size();
  for (std::size_t count = 0; count < table.node_count(); ++count) {
    // Node in hydrocoef's layout (axis 0 fastest) of the DAVE-ML position.
    std::size_t node = 0, stride = 1;
    for (std::size_t a = 0; a < n; ++a) {
      node += index[a] * stride;
      stride *= table.axes()[a].breakpoints.size();
    }
    if (count % last == 0) text += indent;
    append_shortest_number(text, data[node * n_out + output]);
    text += count + 1 == table.node_count() ? "\n" : (count + 1) % last == 0 ? ",\n" : ", ";
    // Advance the last axis fastest.
    for (std::size_t a = n; a-- > 0;) {
      if (++index[a] < table.axes()[a].breakpoints.size()) break;
      index[a] = 0;
    }
  }
  return text;
}

std::string attribute(const std::string& name, const std::string& value) {
  return " " + name + "=\"" + escape::xml_text(value) + "\"";
}

}  // namespace

std::string daveml_text(const GridTable& table, const ExportMetadata& metadata) {
  check_metadata(table, metadata);
  const std::size_t n = table.axis_count(), n_out = table.output_count();
  const std::string what = "format daveml: surface '" + metadata.surface_name + "'";
  if (table.method() != Interpolation::Linear)
    throw InputError(what + " uses " + std::string(interpolation_name(table.method())) +
                     " interpolation; DAVE-ML gridded tables interpolate linearly; expected a linear surface (rebuild "
                     "it with --method linear, or --method rbf --resample ... --resample-method linear)");
  const bool with_sd = !metadata.standard_deviation.empty();
  if (with_sd && metadata.standard_deviation.size() != table.values().size())
    throw std::invalid_argument("daveml_text: one standard deviation per node and output expected");
  const std::string date = metadata.created_at.size() >= 10 ? metadata.created_at.substr(0, 10) : "";
  const std::string provenance = provenance_line(metadata);

  std::string text = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  text +=
      "<!DOCTYPE DAVEfunc PUBLIC \"-//AIAA//DTD for Flight Dynamic Models - Functions 2.0//EN\"\n"
      "  \"http://www.daveml.org/DTDs/2p0/DAVEfunc.dtd\">\n";
  text += "<!-- hydrocoef " + std::string(kVersion) + " export of " + escape::xml_comment(provenance) + " -->\n";
  text += "<DAVEfunc xmlns=\"http://daveml.org/2010/DAVEML\">\n";
  text += "  <fileHeader>\n";
  text += "    <author" + attribute("name", "hydrocoef " + std::string(kVersion)) +
          attribute("org", "hydrocoef (generated from CFD runs)") + "/>\n";
  if (!date.empty()) text += "    <fileCreationDate" + attribute("date", date) + "/>\n";
  text += "    <fileVersion>" + escape::xml_text(metadata.content_sha256) + "</fileVersion>\n";
  text += "    <description>" +
          escape::xml_text("Coefficient surface '" + metadata.surface_name + "' of body '" + metadata.body +
                           "': generalized forces in " + sign_convention_text(metadata.sign_convention) +
                           "; body axes x forward, y starboard, z down (SNAME); SI units" +
                           (metadata.stale ? "; STALE: forces changed since it was built" : "")) +
          "</description>\n";
  text += "    <provenance" + attribute("provID", "runs") + ">\n";
  text += "      <author" + attribute("name", "hydrocoef " + std::string(kVersion)) + "/>\n";
  if (!date.empty()) text += "      <functionCreationDate" + attribute("date", date) + "/>\n";
  text += "      <description>" + escape::xml_text(provenance) + "</description>\n";
  text += "    </provenance>\n";
  text += "  </fileHeader>\n";

  for (std::size_t a = 0; a < n; ++a) {
    const GridAxis& axis = table.axes()[a];
    text += "  <variableDef" + attribute("name", axis.name) + attribute("varID", "u" + std::to_string(a)) +
            attribute("units", metadata.axis_units[a]) + ">\n";
    text +=
        "    <description>" +
        escape::xml_text("input '" + axis.name + "' [" + metadata.axis_units[a] + "], valid in [" +
                         shortest_number(axis.breakpoints.front()) + ", " + shortest_number(axis.breakpoints.back()) +
                         "], " + std::string(extrapolation_name(axis.extrapolation)) + " outside") +
        "</description>\n";
    text += "  </variableDef>\n";
  }
  for (std::size_t k = 0; k < n_out; ++k) {
    const std::string& output = table.outputs()[k];
    text += "  <variableDef" + attribute("name", output) + attribute("varID", "y" + std::to_string(k)) +
            attribute("units", metadata.output_units[k]) + ">\n";
    text += "    <description>" +
            escape::xml_text("output '" + output + "' [" + metadata.output_units[k] + "]" +
                             (with_sd ? "; its standard deviation (one sigma) at each node is the normalPDF bounds "
                                        "table of griddedTableDef gt" +
                                            std::to_string(k)
                                      : std::string())) +
            "</description>\n";
    text += "  </variableDef>\n";
  }
  for (std::size_t a = 0; a < n; ++a) {
    const GridAxis& axis = table.axes()[a];
    text += "  <breakpointDef" + attribute("name", axis.name) + attribute("bpID", "bp" + std::to_string(a)) +
            attribute("units", metadata.axis_units[a]) + ">\n";
    text += "    <bpVals>";
    for (std::size_t i = 0; i < axis.breakpoints.size(); ++i)
      text += (i ? ", " : "") + shortest_number(axis.breakpoints[i]);
    text += "</bpVals>\n  </breakpointDef>\n";
  }
  for (std::size_t k = 0; k < n_out; ++k) {
    const std::string& output = table.outputs()[k];
    text += "  <griddedTableDef" + attribute("name", output) + attribute("gtID", "gt" + std::to_string(k)) +
            attribute("units", metadata.output_units[k]) + ">\n";
    text += "    <description>" + escape::xml_text("'" + output + "' at every node, the last breakpoint fastest") +
            "</description>\n";
    text += "    <provenanceRef" + attribute("provID", "runs") + "/>\n";
    text += "    <breakpointRefs>\n";
    for (std::size_t a = 0; a < n; ++a) text += "      <bpRef" + attribute("bpID", "bp" + std::to_string(a)) + "/>\n";
    text += "    </breakpointRefs>\n";
    if (with_sd) {
      // The stated standard deviation at each node: one sigma of a normal
      // distribution about the value, added to it.
      text +=
          "    <uncertainty effect=\"additive\">\n      <normalPDF numSigmas=\"1\">\n        <bounds>\n"
          "          <dataTable>\n";
      text += data_table(table, metadata.standard_deviation, k, "            ");
      text += "          </dataTable>\n        </bounds>\n      </normalPDF>\n    </uncertainty>\n";
    }
    text += "    <dataTable>\n" + data_table(table, table.values(), k, "      ") + "    </dataTable>\n";
    text += "  </griddedTableDef>\n";
  }
  for (std::size_t k = 0; k < n_out; ++k) {
    const std::string& output = table.outputs()[k];
    text += "  <function" + attribute("name", output) + ">\n";
    text += "    <description>" + escape::xml_text("'" + output + "' of surface '" + metadata.surface_name + "'") +
            "</description>\n";
    for (std::size_t a = 0; a < n; ++a) {
      const GridAxis& axis = table.axes()[a];
      const bool holds = axis.extrapolation == Extrapolation::Clamp || axis.extrapolation == Extrapolation::Error;
      text += "    <independentVarRef" + attribute("varID", "u" + std::to_string(a)) +
              attribute("min", shortest_number(axis.breakpoints.front())) +
              attribute("max", shortest_number(axis.breakpoints.back())) +
              attribute("extrapolate", holds ? "neither" : "both") + "/>\n";
    }
    text += "    <dependentVarRef" + attribute("varID", "y" + std::to_string(k)) + "/>\n";
    text += "    <functionDefn" + attribute("name", output) + ">\n";
    text += "      <griddedTableRef" + attribute("gtID", "gt" + std::to_string(k)) + "/>\n";
    text += "    </functionDefn>\n  </function>\n";
  }
  text += "</DAVEfunc>\n";
  return text;
}

}  // namespace hydrocoef
