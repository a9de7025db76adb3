// libFuzzer target: vehicle description files (src/dynamics/vehicle, JSON).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "src/dynamics/vehicle.hpp"
#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hydrocoef;
  try {
    (void)parse_vehicle(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const InputError& error) {
    fuzz::check_error(error);
  }
  return 0;
}
