// libFuzzer target: the CFD-Post Generic export parser
// (importers/cfdpost_export) on arbitrary bytes, with and without a location
// filter.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "importers/cfdpost_export.hpp"
#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hydrocoef;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  (void)looks_like_cfdpost_export(text);
  try {
    fuzz::check_mesh(parse_cfdpost_export(text, "fuzz.csv"));
  } catch (const InputError& error) {
    fuzz::check_error(error);
  }
  try {
    const auto locations = list_cfdpost_locations(text, "fuzz.csv");
    if (!locations.empty()) {
      // Only the last location: exercises the block filter and the index
      // offsets.
      CfdPostOptions options;
      options.locations = {locations.back()};
      fuzz::check_mesh(parse_cfdpost_export(text, "fuzz.csv", options));
    }
  } catch (const InputError& error) {
    fuzz::check_error(error);
  }
  return 0;
}
