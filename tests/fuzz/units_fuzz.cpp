// libFuzzer target: unit strings (src/core/units): parse_unit and the
// "Name [ unit ]" header split.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "src/core/units.hpp"
#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hydrocoef;
  // Units reach the parser from one header field or one option value: one line.
  std::string_view text(reinterpret_cast<const char*>(data), size);
  text = text.substr(0, text.find('\n'));
  try {
    const Unit unit = parse_unit(text);
    if (!std::isfinite(unit.scale) || unit.scale == 0.0) fuzz::finding("unit with a non-finite or zero scale", text);
    (void)si_unit_name(unit.dimension);
    (void)dimension_matches(unit.dimension, kForce);
  } catch (const InputError& error) {
    fuzz::check_error(error);
  }
  try {
    const NameAndUnit header = split_name_and_unit(text);
    if (header.has_unit) (void)parse_unit(header.unit);
  } catch (const InputError& error) {
    fuzz::check_error(error);
  }
  return 0;
}
