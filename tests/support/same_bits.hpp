// Test support: two doubles equal bit for bit (what "the same numbers" means
// in the tests that compare the library, the runtime library, the FMUs and
// the CLI's output: a NaN equals the same NaN, 0 and -0 differ).
#pragma once

#include <bit>
#include <cstdint>

namespace hydrocoef::test {

inline bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

}  // namespace hydrocoef::test
