// libFuzzer target: the CFX monitor parser (importers/cfx_monitor). The first
// byte chooses the averaging window (1 to 4 iterations); the rest is the file.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "importers/cfx_monitor.hpp"
#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hydrocoef;
  if (size == 0) return 0;
  CfxMonitorOptions options;
  options.key.body = "fuzz";
  options.average_last = 1 + data[0] % 4;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  (void)looks_like_cfx_monitor(text);
  try {
    const MonitorImport result = parse_cfx_monitor(text, "fuzz.csv", options);
    if (result.batch.runs.size() != 1) fuzz::finding("a monitor file gives one run");
    bool any = false;
    for (const auto& component : result.batch.runs.front().tau_b)
      if (component) {
        any = true;
        if (!std::isfinite(component->total)) fuzz::finding("non-finite force accepted");
      }
    if (!any) fuzz::finding("a run without any force component");
  } catch (const InputError& error) {
    fuzz::check_error(error);
  }
  // The same text as a force history (what import reads): samples strictly
  // increasing and finite, or one InputError.
  try {
    const ForceHistory history = parse_cfx_monitor_history(text, "fuzz.csv", options);
    check_force_history(history);
    if (history.size() == 0) fuzz::finding("a monitor history without samples");
  } catch (const InputError& error) {
    fuzz::check_error(error);
  } catch (const std::invalid_argument&) {
    fuzz::finding("a monitor history that breaks the history invariants");
  }
  return 0;
}
