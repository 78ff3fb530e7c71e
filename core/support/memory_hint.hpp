// SPDX-License-Identifier: GPL-3.0-or-later
// A hint for the large buffers of a planned job (the moves of a 10 MB drawing take some 200 MB):
// ask the kernel to back them with transparent huge pages, so that first writes take one page
// fault per 2 MB instead of one per 4 KB (tens of thousands of faults, a third of a second on a
// virtual machine). Only a hint: nothing changes where the system does not support it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace fivebar {

inline void adviseHugePages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kPage = 4096;
  constexpr std::size_t kWorthIt = std::size_t{8} << 20;  // below this, faults cost little
  if (bytes < kWorthIt) return;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kPage - 1) & ~(kPage - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kPage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

// reserve(n), with the hint for the reserved buffer (before anything is written to it).
template <typename T>
void reserveWithHugePages(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
  adviseHugePages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace fivebar
