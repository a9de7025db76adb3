#include "src/export/jsbsim_export.hpp"

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/version.hpp"

namespace hydrocoef {

std::string jsbsim_text(const GridTable& table, const ExportMetadata& metadata) {
  check_metadata(table, metadata);
  const std::size_t n = table.axis_count();
  const std::size_t n_out = table.output_count();
  const std::string what = "format jsbsim: surface '" + metadata.surface_name + "'";
  if (n > 3) {
    throw InputError(what + " has " + std::to_string(n) +
                     " axes; JSBSim tables have 1 to 3 independent variables; expected at most 3 (use --format c, "
                     "json or csv for more)");
  }
  if (table.method() != Interpolation::Linear) {
    throw InputError(what + " uses " + std::string(interpolation_name(table.method())) +
                     " interpolation; JSBSim tables interpolate linearly; expected a linear surface (rebuild it with "
                     "--method linear, or use --format c)");
  }
  for (const GridAxis& axis : table.axes()) {
    if (axis.extrapolation == Extrapolation::Linear || axis.extrapolation == Extrapolation::Method) {
      throw InputError(what + ": axis '" + axis.name + "' extrapolates (" +
                       std::string(extrapolation_name(axis.extrapolation)) +
                       "); JSBSim holds the end values outside a table; expected clamp or error");
    }
  }
  const std::vector<double>& values = table.values();
  const auto& x = [&](std::size_t a) -> const std::vector<double>& { return table.axes()[a].breakpoints; };
  std::string text = "<?xml version=\"1.0\"?>\n";
  text += "<!-- hydrocoef " + std::string(kVersion) + " export of " + escape::xml_comment(provenance_line(metadata)) +
          " -->\n";
  text += "<!-- outputs in sign convention " + escape::xml_comment(sign_convention_text(metadata.sign_convention)) +
          "; body axes x forward, y starboard, z down (SNAME); SI units -->\n";
  text += "<hydrocoef_tables surface=\"" + escape::xml_text(metadata.surface_name) + "\" body=\"" +
          escape::xml_text(metadata.body) + "\" sha256=\"" + metadata.content_sha256 + "\">\n";
  static const char* kLookup[] = {"row", "column", "table"};
  for (std::size_t k = 0; k < n_out; ++k) {
    const std::string& output = table.outputs()[k];
    text += "  <function name=\"hydrocoef/" + escape::xml_text(metadata.surface_name) + "/" + escape::xml_text(output) +
            "\">\n";
    std::string description = output + " [" + metadata.output_units[k] + "], linear interpolation, end values held";
    for (std::size_t a = 0; a < n; ++a) {
      description += "; " + table.axes()[a].name + " [" + metadata.axis_units[a] + "] valid in [" +
                     shortest_number(x(a).front()) + ", " + shortest_number(x(a).back()) + "] (" +
                     std::string(extrapolation_name(table.axes()[a].extrapolation)) + " outside)";
    }
    text += "    <description>" + escape::xml_text(description) + "</description>\n";
    text += "    <table>\n";
    for (std::size_t a = 0; a < n; ++a) {
      text += "      <independentVar lookup=\"" + std::string(kLookup[a]) + "\">hydrocoef/" +
              escape::xml_text(table.axes()[a].name) + "</independentVar>\n";
    }
    const std::size_t n0 = x(0).size();
    const std::size_t n1 = n >= 2 ? x(1).size() : 1;
    const std::size_t n2 = n >= 3 ? x(2).size() : 1;
    for (std::size_t l = 0; l < n2; ++l) {
      text += n == 3 ? "      <tableData breakPoint=\"" + shortest_number(x(2)[l]) + "\">\n" : "      <tableData>\n";
      if (n >= 2) {
        text += "                ";
        for (std::size_t j = 0; j < n1; ++j) text += " " + shortest_number(x(1)[j]);
        text += "\n";
      }
      for (std::size_t i = 0; i < n0; ++i) {
        text += "        " + shortest_number(x(0)[i]);
        for (std::size_t j = 0; j < n1; ++j) text += " " + shortest_number(values[((l * n1 + j) * n0 + i) * n_out + k]);
        text += "\n";
      }
      text += "      </tableData>\n";
    }
    text += "    </table>\n  </function>\n";
  }
  text += "</hydrocoef_tables>\n";
  return text;
}

}  // namespace hydrocoef
