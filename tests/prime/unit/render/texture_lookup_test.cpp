// ReadMap's index arithmetic (listing lines 7289-7349; K24, K25, E51, X3).
// Fixture: a 4 x 2 map whose texel i holds 10 + i, i.e. row 0 = 10 11 12 13,
// row 1 = 14 15 16 17. Index = newU + 4*newV with newU = (int)Roundoff(4u),
// newV = (int)Roundoff(2v). Every expected index is worked out by hand.
#include "src/prime/render/texture_lookup.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "src/prime/scene/scene.h"

namespace prime {
namespace {

const std::vector<double> kTexels = {10, 11, 12, 13, 14, 15, 16, 17};
const TextureChannelView kMap{4, 2, kTexels};

void expectRead(double u, double v, double value, long long index, TexelStatus status) {
  const TexelRead r = readMapTexel1991(kMap, u, v);
  EXPECT_EQ(r.value, value) << "u=" << u << " v=" << v;
  EXPECT_EQ(r.index, index) << "u=" << u << " v=" << v;
  EXPECT_EQ(r.status, status) << "u=" << u << " v=" << v;
}

TEST(ReadMap, ZeroAndInteriorPoints) {
  expectRead(0.0, 0.0, 10, 0, TexelStatus::Ok);
  expectRead(0.5, 0.5, 16, 2 + 4 * 1, TexelStatus::Ok);   // 2 + 4*1
  expectRead(0.75, 0.5, 17, 3 + 4 * 1, TexelStatus::Ok);  // last texel
  expectRead(0.25, 0.0, 11, 1, TexelStatus::Ok);
}

TEST(ReadMap, TruncatesInsteadOfRounding) {
  expectRead(0.125, 0.0, 10, 0, TexelStatus::Ok);  // 4*0.125 = 0.5 -> 0
  expectRead(0.375, 0.0, 11, 1, TexelStatus::Ok);  // 1.5 -> 1
  expectRead(0.0, 0.74, 14, 4, TexelStatus::Ok);   // 2*0.74 = 1.48 -> 1
}

TEST(ReadMap, UOneReadsTexelZeroOfTheNextRow) {
  // K25: u = 1 -> newU = uScale = 4; index 4 + 4*0 = 4, the first texel of row 1.
  expectRead(1.0, 0.0, 14, 4, TexelStatus::Ok);
  // On the last row it runs past the end: 4 + 4*1 = 8 >= 8 -> 0.0 (E51).
  expectRead(1.0, 0.5, 0.0, 8, TexelStatus::ReadFailed);
  // u > 1 keeps walking along the file: u = 1.75 -> 7.
  expectRead(1.75, 0.0, 17, 7, TexelStatus::Ok);
  expectRead(2.0, 0.0, 0.0, 8, TexelStatus::ReadFailed);
}

TEST(ReadMap, VOneRunsPastTheEnd) {
  // newV = vScale = 2: index 0 + 4*2 = 8 (E51): failed read, 0.0.
  expectRead(0.0, 1.0, 0.0, 8, TexelStatus::ReadFailed);
  expectRead(0.5, 1.0, 0.0, 10, TexelStatus::ReadFailed);
}

TEST(ReadMap, JustBelowOne) {
  // 4*0.99 = 3.96 -> 3; 4*(1-1e-9) = 3.999999996: variance .999999996 is
  // not > .9999999999, so no snap -> 3.
  expectRead(0.99, 0.0, 13, 3, TexelStatus::Ok);
  expectRead(1.0 - 1e-9, 0.0, 13, 3, TexelStatus::Ok);
  // 4*(1-1e-12) = 3.999999999996: Roundoff snaps it to 4 (K24) -> index 4.
  expectRead(1.0 - 1e-12, 0.0, 14, 4, TexelStatus::Ok);
  // Same in v: 2*0.99 = 1.98 -> row 1; 2*(1-1e-12) snaps to 2 -> past end.
  expectRead(0.0, 0.99, 14, 4, TexelStatus::Ok);
  expectRead(0.0, 1.0 - 1e-12, 0.0, 8, TexelStatus::ReadFailed);
}

TEST(ReadMap, RoundoffRescuesProductsJustUnderAnInteger) {
  // 0.29*100 = 28.999999999999996 in doubles; Roundoff makes it 29.
  std::vector<double> texels(100);
  for (int i = 0; i < 100; ++i) texels[static_cast<std::size_t>(i)] = i;
  const TextureChannelView m{100, 1, texels};
  const TexelRead r = readMapTexel1991(m, 0.29, 0.0);
  EXPECT_EQ(r.newU, 29);
  EXPECT_EQ(r.value, 29.0);
}

TEST(ReadMap, NegativeU) {
  // -0.1*4 = -0.4 truncates to 0; -0.3*4 = -1.2 -> -1, clamped to 0 (K25).
  expectRead(-0.1, 0.0, 10, 0, TexelStatus::Ok);
  expectRead(-0.3, 0.0, 10, 0, TexelStatus::Ok);
  // -0.3 on row 1: newU clamped to 0 -> index 4.
  expectRead(-0.3, 0.5, 14, 4, TexelStatus::Ok);
  // 4*(-0.24999999999999) = -0.99999999999996: the negative Roundoff snaps
  // it to -1 (variance > .999999998) -> clamped to 0.
  const TexelRead r = readMapTexel1991(kMap, -0.24999999999999, 0.0);
  EXPECT_EQ(r.newU, 0);
  EXPECT_EQ(r.index, 0);
}

TEST(ReadMap, NegativeVFailsTheSeekAndReadsTexelZero) {
  // v = -0.5 -> newV = -1; u = 0.5 -> newU = 2; index 2 - 4 = -2 < 0: the
  // byte offset 4 + 8*(-2) = -12 makes fseek fail; the file position is
  // still just after the header, so texel 0 (value 10) is read (K25).
  expectRead(0.5, -0.5, 10, -2, TexelStatus::SeekFailed);
  // With u = 1.5 (newU = 6) the index is 6 - 4 = 2: an ordinary read.
  expectRead(1.5, -0.5, 12, 2, TexelStatus::Ok);
  // v = -0.4 -> -0.8 truncates to 0: no failure.
  expectRead(0.5, -0.4, 12, 2, TexelStatus::Ok);
}

TEST(ReadMap, NaNAndInfinities) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  // Roundoff(NaN) = 0 (K24).
  expectRead(nan, nan, 10, 0, TexelStatus::Ok);
  expectRead(nan, 0.5, 14, 4, TexelStatus::Ok);
  // +inf (and huge values) run past the end; -inf in u clamps to 0; -inf in
  // v is a negative offset.
  EXPECT_EQ(readMapTexel1991(kMap, inf, 0.0).status, TexelStatus::ReadFailed);
  EXPECT_EQ(readMapTexel1991(kMap, 1e300, 0.0).status, TexelStatus::ReadFailed);
  EXPECT_EQ(readMapTexel1991(kMap, 0.0, 1e300).status, TexelStatus::ReadFailed);
  expectRead(-inf, 0.0, 10, 0, TexelStatus::Ok);
  EXPECT_EQ(readMapTexel1991(kMap, 0.0, -inf).status, TexelStatus::SeekFailed);
  EXPECT_EQ(readMapTexel1991(kMap, 0.0, -inf).value, 10);
}

TEST(ReadMap, TheBoundIsTheNumberOfTexelsPresent) {
  // A short channel (6 doubles for a 4 x 2 header): index 6 fails.
  const std::vector<double> shortTexels = {10, 11, 12, 13, 14, 15};
  const TextureChannelView m{4, 2, shortTexels};
  EXPECT_EQ(readMapTexel1991(m, 0.25, 0.5).value, 15);  // index 5
  EXPECT_EQ(readMapTexel1991(m, 0.5, 0.5).status, TexelStatus::ReadFailed);
  // No texels at all: every read fails, even a failed seek.
  const TextureChannelView empty{4, 2, {}};
  EXPECT_EQ(readMapTexel1991(empty, 0.0, 0.0).status, TexelStatus::ReadFailed);
  EXPECT_EQ(readMapTexel1991(empty, 0.5, -0.5).status, TexelStatus::ReadFailed);
  EXPECT_EQ(readMapTexel1991(empty, 0.5, -0.5).value, 0.0);
}

TEST(ReadMap, CountersForX3) {
  TextureReadCounters c;
  EXPECT_EQ(readMap1991(kMap, 0.5, 0.5, &c), 16);
  EXPECT_EQ(readMap1991(kMap, 0.0, 1.0, &c), 0.0);
  EXPECT_EQ(readMap1991(kMap, 1.0, 0.5, &c), 0.0);
  EXPECT_EQ(readMap1991(kMap, 0.5, -0.5, &c), 10);
  EXPECT_EQ(c.failedReads, 2u);
  EXPECT_EQ(c.failedSeeks, 1u);
  EXPECT_EQ(readMap1991(kMap, 0.0, 1.0), 0.0);  // no counters: fine
}

TEST(ReadMap, SceneTextureChannels) {
  SceneTexture map;
  map.uScale = 2;
  map.vScale = 1;
  map.channel = {std::vector<double>{0.1, 0.2}, std::vector<double>{0.3, 0.4},
                 std::vector<double>{0.5, 0.6}};
  // A channel view as Tracer1991::castRay makes it.
  auto channel = [&](int c) { return TextureChannelView{map.uScale, map.vScale, map.channel[c]}; };
  EXPECT_EQ(readMap1991(channel(0), 0.5, 0.0), 0.2);
  EXPECT_EQ(readMap1991(channel(1), 0.0, 0.0), 0.3);
  EXPECT_EQ(readMap1991(channel(2), 0.5, 0.0), 0.6);
}

}  // namespace
}  // namespace prime
