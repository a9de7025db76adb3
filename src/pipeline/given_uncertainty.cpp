#include "src/pipeline/given_uncertainty.hpp"

#include <cmath>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/text.hpp"

namespace hydrocoef {

std::array<std::optional<GivenUncertainty>, 6> parse_given_uncertainty(const std::string& text,
                                                                       const std::string& where) {
  std::array<std::optional<GivenUncertainty>, 6> out;
  const auto refuse = [&](std::string_view entry, const std::string& expected) {
    return InputError(where + ": uncertainty '" + escape::one_line(entry) + "': " + expected);
  };
  for (const std::string_view raw : split(text, ',')) {
    const std::string_view entry = trim(raw);
    const auto equals = entry.find('=');
    if (equals == std::string_view::npos)
      throw refuse(entry, "expected COMPONENT=VALUE or COMPONENT=PERCENT%, e.g. X=0.01 or N=2%");
    const auto component = force_index(std::string(trim(entry.substr(0, equals))));
    if (!component) throw refuse(entry, "expected a force component X, Y, Z, K, M or N before '='");
    if (out[*component]) throw refuse(entry, "the component is given twice; expected one value each");
    std::string_view number = trim(entry.substr(equals + 1));
    GivenUncertainty given;
    if (!number.empty() && number.back() == '%') {
      given.relative = true;
      number = trim(number.substr(0, number.size() - 1));
    }
    const auto value = parse_finite_number(number);
    if (!value || *value < 0.0 || (given.relative && *value > 1000.0))
      throw refuse(entry, given.relative ? "expected a percentage from 0 to 1000"
                                         : "expected a finite number >= 0 in the component's unit (N or N m)");
    given.value = given.relative ? *value / 100.0 : *value;
    out[*component] = given;
  }
  return out;
}

void apply_given_uncertainty(ImportBatch& batch, const std::array<std::optional<GivenUncertainty>, 6>& given) {
  for (ImportedRun& run : batch.runs)
    for (std::size_t i = 0; i < 6; ++i)
      if (given[i] && run.tau_b[i])
        run.tau_b[i]->uncertainty =
            given[i]->relative ? given[i]->value * std::abs(run.tau_b[i]->total) : given[i]->value;
}

}  // namespace hydrocoef
