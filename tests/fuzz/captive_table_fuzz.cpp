// libFuzzer target: the captive-test table parser (importers/captive_table,
// with the line and field splitting of importers/text_table and the
// normalisation of src/derivatives/normalisation).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "importers/captive_table.hpp"
#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hydrocoef;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  CaptiveTableOptions options;
  options.ignored_columns = {"note"};
  options.body_reference.draft = 0.4;  // the body's stored draft, for an mmg table that gives none
  try {
    const auto table = parse_captive_table(text, "fuzz.csv", options);
    if (table.runs.empty()) fuzz::finding("a table accepted without runs");
    if (table.note.empty() || table.settings_key.empty()) fuzz::finding("a table accepted without its note");
    for (const auto& run : table.runs) {
      for (const auto v : run.key.nu_b)
        if (!std::isfinite(v)) fuzz::finding("non-finite velocity accepted");
      for (const auto& [name, value] : run.key.disturbances)
        if (!std::isfinite(value)) fuzz::finding("non-finite disturbance accepted");
      for (const auto& component : run.tau_b)
        if (component && !std::isfinite(component->total)) fuzz::finding("non-finite force accepted");
      if (!(std::hypot(run.key.nu_b[0], run.key.nu_b[1]) > 0.0))
        fuzz::finding("a run at rest accepted (its forces were scaled by its speed)");
      if (run.source_line == 0) fuzz::finding("a run without its source line");
    }
  } catch (const InputError& error) {
    fuzz::check_error(error);
  }
  return 0;
}
