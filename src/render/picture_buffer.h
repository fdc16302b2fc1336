// The buffers a run builds once and then touches in full (pictures, the
// CGL spline and fractal trees, texture maps): megabytes whose first touch
// is mostly the kernel's work, one page fault per 4 KiB page; on a virtual
// machine that is about 12 us a page (an 8.5 MB graph file at 4x the
// listing's size: 25-30 ms, longer than a tenth of a short render on two
// threads). Asking for huge pages (Linux transparent huge pages, where the
// system grants them on request: "madvise" mode) before the first touch
// makes that a handful of faults. The bytes are the same either way.
#pragma once
#include <cstddef>
#include <new>
#include <vector>

namespace prime {

// LargeBuffer: a vector whose storage, for a quarter megabyte or more, is
// rounded up to whole, aligned 2 MiB pages and advised before the first
// touch. One page fault then backs 2 MiB instead of 512 faults of 4 KiB
// (3 ms for the CGL package's 1 MiB frame alone); the rest of the last page
// is zeroed by the system, not faulted. Smaller requests are ordinary.
void* allocateLargeBuffer(std::size_t bytes);
void freeLargeBuffer(void* p, std::size_t bytes) noexcept;

template <class T>
struct LargeBufferAllocator {
  using value_type = T;
  LargeBufferAllocator() = default;
  template <class U>
  LargeBufferAllocator(const LargeBufferAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(allocateLargeBuffer(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept { freeLargeBuffer(p, n * sizeof(T)); }
  template <class U>
  bool operator==(const LargeBufferAllocator<U>&) const noexcept {
    return true;
  }
};
template <class T>
using LargeBuffer = std::vector<T, LargeBufferAllocator<T>>;

}  // namespace prime
