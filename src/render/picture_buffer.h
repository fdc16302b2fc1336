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
#include <vector>

namespace prime {

// Advise the kernel that [data, data + bytes) is worth backing with huge
// pages (only the 2 MiB-aligned part inside it; nothing where the system
// has no such advice).
void adviseHugePages(void* data, std::size_t bytes);

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
