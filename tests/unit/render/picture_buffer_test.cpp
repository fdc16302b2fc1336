// assignPicture: what std::vector::assign gives, for small and large
// pictures, fresh or reusing a vector (the huge-page advice changes no value).
#include "src/render/picture_buffer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "src/math/rgb.h"

namespace prime {
namespace {

template <class T>
void expectAll(const std::vector<T>& v, std::size_t n, const T& value) {
  ASSERT_EQ(v.size(), n);
  EXPECT_TRUE(std::all_of(v.begin(), v.end(), [&](const T& x) { return x == value; }));
}

TEST(PictureBuffer, AssignsAsVectorAssignDoes) {
  constexpr std::size_t kLarge = (std::size_t{6} << 20) / sizeof(std::int16_t);  // 6 MiB
  for (const std::size_t n : {std::size_t{0}, std::size_t{7}, kLarge, kLarge + 12345}) {
    std::vector<std::int16_t> fresh;
    assignPicture(fresh, n, std::int16_t{0});
    expectAll(fresh, n, std::int16_t{0});

    std::vector<std::int16_t> used(n / 2 + 3, std::int16_t{-5});  // smaller, other values
    assignPicture(used, n, std::int16_t{42});
    expectAll(used, n, std::int16_t{42});

    std::vector<std::int16_t> roomy(n + 100, std::int16_t{9});  // capacity to spare: kept
    const std::int16_t* before = roomy.data();
    assignPicture(roomy, n, std::int16_t{-1});
    expectAll(roomy, n, std::int16_t{-1});
    EXPECT_EQ(roomy.data(), before);
  }
  std::vector<Rgb> colours(3, Rgb{1, 2, 3});
  assignPicture(colours, kLarge / 4, Rgb{});
  expectAll(colours, kLarge / 4, Rgb{});
}

}  // namespace
}  // namespace prime
