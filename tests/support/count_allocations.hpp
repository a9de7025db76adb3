// Test support: replaces the global operator new so that a test can check a
// code path allocates nothing (test::allocation_count() before and after).
// Include it in exactly one source file of a test executable: it defines the
// replacement functions.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace hydrocoef::test {
inline std::atomic<std::size_t> g_allocation_count{0};
inline std::size_t allocation_count() { return g_allocation_count.load(std::memory_order_relaxed); }
}  // namespace hydrocoef::test

// Not inlined, so that GCC does not pair the free() below with a new-expression
// at the call site (-Wmismatched-new-delete).
[[gnu::noinline]] void* operator new(std::size_t size) {
  hydrocoef::test::g_allocation_count.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }
