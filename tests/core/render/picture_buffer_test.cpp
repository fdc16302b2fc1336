// LargeBuffer: a vector like any other (assign gives what std::vector's
// does, for small and large pictures, fresh or reusing a vector: the
// huge-page advice changes no value), its large storage on 2 MiB bounds.
#include "src/render/picture_buffer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include "src/math/rgb.h"

namespace prime {
namespace {

template <class T>
void expectAll(const LargeBuffer<T>& v, std::size_t n, const T& value) {
  ASSERT_EQ(v.size(), n);
  EXPECT_TRUE(std::all_of(v.begin(), v.end(), [&](const T& x) { return x == value; }));
}

TEST(PictureBuffer, AssignsAsVectorAssignDoes) {
  constexpr std::size_t kLarge = (std::size_t{6} << 20) / sizeof(std::int16_t);  // 6 MiB
  for (const std::size_t n : {std::size_t{0}, std::size_t{7}, kLarge, kLarge + 12345}) {
    LargeBuffer<std::int16_t> fresh;
    fresh.assign(n, std::int16_t{0});
    expectAll(fresh, n, std::int16_t{0});

    LargeBuffer<std::int16_t> used(n / 2 + 3, std::int16_t{-5});  // smaller, other values
    used.assign(n, std::int16_t{42});
    expectAll(used, n, std::int16_t{42});

    LargeBuffer<std::int16_t> roomy(n + 100, std::int16_t{9});  // capacity to spare: kept
    const std::int16_t* before = roomy.data();
    roomy.assign(n, std::int16_t{-1});
    expectAll(roomy, n, std::int16_t{-1});
    EXPECT_EQ(roomy.data(), before);
  }
  LargeBuffer<Rgb> colours(3, Rgb{1, 2, 3});
  colours.assign(kLarge / 4, Rgb{});
  expectAll(colours, kLarge / 4, Rgb{});
}

TEST(PictureBuffer, LargeBuffersAreVectorsOnHugePageBounds) {
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  // Below a quarter megabyte, above it, a whole huge page, and more than one.
  for (const std::size_t n : {std::size_t{0}, std::size_t{1000}, std::size_t{70000},
                              std::size_t{1} << 19, std::size_t{600000}}) {
    LargeBuffer<std::uint32_t> v(n, 7u);
    ASSERT_EQ(v.size(), n);
    EXPECT_TRUE(std::all_of(v.begin(), v.end(), [](std::uint32_t x) { return x == 7u; }));
    if (n * sizeof(std::uint32_t) >= (std::size_t{256} << 10)) {
      EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % kHuge, 0u) << n;
    }
    std::iota(v.begin(), v.end(), 0u);
    // Growing moves the contents to new storage, as std::vector does.
    v.resize(n * 2 + 5, 1u);
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(v[i], static_cast<std::uint32_t>(i));
    EXPECT_EQ(v.back(), 1u);
    LargeBuffer<std::uint32_t> copy = v;  // and copies compare equal
    EXPECT_TRUE(copy == v);
  }
}

}  // namespace
}  // namespace prime
