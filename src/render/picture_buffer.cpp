#include "src/render/picture_buffer.h"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace prime {

void adviseHugePages(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (begin + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t last = (begin + bytes) & ~(kHuge - 1);
  if (data != nullptr && last > first)
    (void)madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);  // advice only
#else
  (void)data;
  (void)bytes;
#endif
}

namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kLargeBytes = std::size_t{256} << 10;  // a quarter megabyte or more
}  // namespace

void* allocateLargeBuffer(std::size_t bytes) {
  if (bytes < kLargeBytes) return ::operator new(bytes);
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* p = ::operator new (rounded, std::align_val_t{kHugePage});
  adviseHugePages(p, rounded);
  return p;
}

void freeLargeBuffer(void* p, std::size_t bytes) noexcept {
  if (bytes < kLargeBytes) {
    ::operator delete(p);
    return;
  }
  ::operator delete (p, std::align_val_t{kHugePage});
}

}  // namespace prime
