// libFuzzer target: the force-table parser (importers/force_table, with the
// line and field splitting of importers/text_table).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "importers/force_table.hpp"
#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hydrocoef;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  ForceTableOptions options;
  options.disturbance_columns = {"current_v"};
  options.ignored_columns = {"note"};
  try {
    const auto runs = parse_force_table(text, "fuzz.csv", options);
    if (runs.empty()) fuzz::finding("a table accepted without runs");
    for (const auto& run : runs) {
      for (const auto v : run.key.nu_b)
        if (!std::isfinite(v)) fuzz::finding("non-finite velocity accepted");
      for (const auto& component : run.tau_b)
        if (component && !std::isfinite(component->total)) fuzz::finding("non-finite force accepted");
      if (run.source_line == 0) fuzz::finding("a run without its source line");
    }
  } catch (const InputError& error) {
    fuzz::check_error(error);
  }
  return 0;
}
