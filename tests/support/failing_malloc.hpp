// Test support: SQLite's allocator made to fail on command, SQLite's own
// habit (its malloc tests). install_failing_malloc() shuts SQLite down and
// configures, before it starts again, a wrapper of its default allocator
// (SQLITE_CONFIG_GETMALLOC / SQLITE_CONFIG_MALLOC): once armed at N, the N-th
// allocation or reallocation returns NULL, and, when the fault is
// persistent, every one after it too, until disarmed. It must run before any
// database is open in the process (a gtest Environment, or the start of
// main). Single-threaded.
#pragma once

#include <sqlite3.h>

#include <stdexcept>

namespace hydrocoef::test {

struct AllocFaults {
  bool armed = false;
  bool persistent = false;
  long fail_at = 0;  ///< the counted allocation that fails first (1-based; 0: none)
  long calls = 0;    ///< allocations since armed
  long hits = 0;     ///< allocations failed since armed

  bool fail_now() {
    if (!armed) return false;
    ++calls;
    if (fail_at <= 0) return false;
    if (calls == fail_at || (persistent && calls > fail_at)) {
      ++hits;
      return true;
    }
    return false;
  }
  void arm(long n, bool every_call_after) {
    *this = AllocFaults{};
    armed = true;
    fail_at = n;
    persistent = every_call_after;
  }
  void disarm() { armed = false; }
};

namespace detail {

inline AllocFaults& alloc_faults() {
  static AllocFaults faults;
  return faults;
}
inline sqlite3_mem_methods& default_allocator() {
  static sqlite3_mem_methods methods{};
  return methods;
}
inline void* failing_malloc(int size) {
  if (alloc_faults().fail_now()) return nullptr;
  return default_allocator().xMalloc(size);
}
inline void* failing_realloc(void* old, int size) {
  if (alloc_faults().fail_now()) return nullptr;
  return default_allocator().xRealloc(old, size);
}

}  // namespace detail

/// Installs the failing allocator (once per process) and returns its switch.
inline AllocFaults& install_failing_malloc() {
  static const bool installed = [] {
    if (sqlite3_shutdown() != SQLITE_OK) throw std::runtime_error("sqlite3_shutdown failed");
    if (sqlite3_config(SQLITE_CONFIG_GETMALLOC, &detail::default_allocator()) != SQLITE_OK)
      throw std::runtime_error("SQLITE_CONFIG_GETMALLOC failed");
    static sqlite3_mem_methods failing = detail::default_allocator();
    failing.xMalloc = detail::failing_malloc;
    failing.xRealloc = detail::failing_realloc;
    if (sqlite3_config(SQLITE_CONFIG_MALLOC, &failing) != SQLITE_OK)
      throw std::runtime_error("SQLITE_CONFIG_MALLOC failed: SQLite was in use already");
    if (sqlite3_initialize() != SQLITE_OK) throw std::runtime_error("sqlite3_initialize failed");
    return true;
  }();
  (void)installed;
  return detail::alloc_faults();
}

}  // namespace hydrocoef::test
