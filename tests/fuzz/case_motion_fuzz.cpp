// libFuzzer target: the imposed motion of a CFX case (importers/case_motion,
// cfx_motion) from arbitrary CCL text: parsed (importers/cfx_ccl), its mesh
// displacements read as A*sin(omega*t + phi) with named expressions expanded.
// The reader may find a motion or throw InputError; a motion found has a
// finite, positive frequency, finite amplitudes and a finite phase, and
// expressions that grow at every level are refused, not expanded.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "importers/case_motion.hpp"
#include "importers/cfx_ccl.hpp"
#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hydrocoef;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const CclDocument document = parse_ccl(text, "fuzz.ccl");
    const auto motion = cfx_motion(document);
    if (!motion) return 0;
    if (!(std::isfinite(motion->omega) && motion->omega > 0.0)) fuzz::finding("a motion without a positive frequency");
    if (!std::isfinite(motion->phase)) fuzz::finding("a motion with a non-finite phase");
    for (const double a : motion->amplitude)
      if (!std::isfinite(a) || a < 0.0) fuzz::finding("a motion with a non-finite or negative amplitude");
  } catch (const InputError& error) {
    fuzz::check_error(error);
  }
  return 0;
}
