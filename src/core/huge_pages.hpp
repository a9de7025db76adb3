// Big arrays (a surface of millions of faces) are written once, right after
// they are allocated. With 4 KiB pages every 4 KiB costs a page fault, which
// on virtual machines takes longer than computing the bytes that fill it;
// 2 MiB pages (transparent huge pages in "madvise" mode) make that 512 times
// rarer. Only a hint: where it is refused, memory is paged as usual.
#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hydrocoef {

inline void prefer_huge_pages(const void* data, std::size_t bytes) {
  constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t last = (begin + bytes) & ~(kHugePage - 1);
  if (last > first) ::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

/// reserve() and the hint, before the first write touches the memory.
template <class T>
void reserve_with_huge_pages(std::vector<T>& values, std::size_t count) {
  values.reserve(count);
  prefer_huge_pages(values.data(), values.capacity() * sizeof(T));
}

}  // namespace hydrocoef
