#include "src/render/picture_buffer.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace prime {

namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kLargeBytes = std::size_t{256} << 10;  // a quarter megabyte or more
}  // namespace

void* allocateLargeBuffer(std::size_t bytes) {
  if (bytes < kLargeBytes) return ::operator new(bytes);
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* p = ::operator new (rounded, std::align_val_t{kHugePage});
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  (void)madvise(p, rounded, MADV_HUGEPAGE);  // advice only: nothing where the system has none
#endif
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
