// A picture's pixel buffer sized in one go: megabytes that every pixel of
// the render then writes. Zeroing them is the largest serial piece of work
// between reading the scene and the render threads, and most of its time is
// the kernel's, one page fault per 4 KiB page; on a virtual machine that is
// several microseconds a page (an 8.5 MB graph file at 4x the listing's
// size: 25-30 ms, longer than a tenth of a short render on two threads).
// Asking for huge pages (Linux transparent huge pages, where the system
// grants them on request: "madvise" mode) before the first touch makes that
// a handful of faults. The bytes are the same either way: the vector is
// filled with `value` as assign fills it.
#pragma once
#include <cstddef>
#include <new>
#include <vector>

namespace prime {

// Advise the kernel that [data, data + bytes) is worth backing with huge
// pages (only the 2 MiB-aligned part inside it; nothing where the system
// has no such advice).
void adviseHugePages(void* data, std::size_t bytes);

// For the large buffers every run builds and touches at once (the CGL
// package's 1 MiB frame, too small for assignPicture's advice to find a
// whole huge page inside it; a spline surface's tree and packets): storage
// of a quarter megabyte or more rounded up to whole, aligned 2 MiB pages and
// advised before the first touch. One page fault then backs 2 MiB instead
// of 512 faults of 4 KiB (about 12 us each on a virtual machine: 3 ms for
// the CGL frame alone); the rest of the last page is zeroed by the system,
// not faulted. Smaller requests are ordinary.
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

// v.assign(n, value), with the storage advised (adviseHugePages) between
// its allocation and its first touch when it is large.
template <class T>
void assignPicture(std::vector<T>& v, std::size_t n, const T& value) {
  constexpr std::size_t kLarge = std::size_t{4} << 20;
  if (n * sizeof(T) >= kLarge && v.capacity() < n) {
    std::vector<T>().swap(v);  // (nothing kept: a fresh allocation, untouched)
    v.reserve(n);
    adviseHugePages(v.data(), n * sizeof(T));
  }
  v.assign(n, value);
}

}  // namespace prime
