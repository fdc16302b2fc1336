// Byte layouts of one record of each type, against bytes worked out by hand
// from the Turbo C rules (errata E05): int = 2 bytes little-endian, double =
// 8 bytes little-endian IEEE, char = 1 byte, no padding.
#include <gtest/gtest.h>

#include "legacy_io/prime/graph_file.h"
#include "legacy_io/prime/map_file.h"
#include "legacy_io/prime/obj_file.h"
#include "legacy_io/prime/obj_list.h"
#include "legacy_io/prime/prim_file.h"

namespace prime::io {
namespace {

using Bytes = std::vector<std::uint8_t>;

// IEEE-754 doubles by hand: 1.0 = 0x3FF0000000000000, 0.5 = 0x3FE0..., 2.0 =
// 0x4000..., -5.0 = 0xC014000000000000, 0.25 = 0x3FD0..., 1.5 = 0x3FF8...
const Bytes kOne = {0, 0, 0, 0, 0, 0, 0xF0, 0x3F};
const Bytes kHalf = {0, 0, 0, 0, 0, 0, 0xE0, 0x3F};
const Bytes kTwo = {0, 0, 0, 0, 0, 0, 0x00, 0x40};
const Bytes kMinusFive = {0, 0, 0, 0, 0, 0, 0x14, 0xC0};
const Bytes kQuarter = {0, 0, 0, 0, 0, 0, 0xD0, 0x3F};
const Bytes kOneAndHalf = {0, 0, 0, 0, 0, 0, 0xF8, 0x3F};
const Bytes kZero(8, 0);

Bytes slice(const Bytes& b, std::size_t at, std::size_t n) {
  return Bytes(b.begin() + at, b.begin() + at + n);
}

TEST(RecordLayout, ObjRecordIsEightBytes) {
  ObjRecord o;
  o.opCode = {'+', 0, 0, 0};
  o.l = 1;
  o.r = -2;  // 0xFFFE
  ByteWriter w;
  encode(w, o);
  EXPECT_EQ(w.bytes(), (Bytes{'+', 0, 0, 0, 0x01, 0x00, 0xFE, 0xFF}));
}

TEST(RecordLayout, ObjHeaderIs76BytesWithHueAtOffset4) {
  ObjHeader h;
  h.numEntries = 5;
  h.boundVol = -1;
  h.hue.kDR = 0.5;
  h.hue.fDR = {1.0, 2.0, 0.25};
  h.hue.indx = 1.5;
  ByteWriter w;
  encode(w, h);
  const Bytes& b = w.bytes();
  ASSERT_EQ(b.size(), 76u);
  EXPECT_EQ(slice(b, 0, 4), (Bytes{0x05, 0x00, 0xFF, 0xFF}));
  EXPECT_EQ(slice(b, 4, 8), kHalf);         // kDR
  EXPECT_EQ(slice(b, 12, 8), kZero);        // kDT
  EXPECT_EQ(slice(b, 20, 8), kOne);         // fDR[R]
  EXPECT_EQ(slice(b, 28, 8), kTwo);         // fDR[G]
  EXPECT_EQ(slice(b, 36, 8), kQuarter);     // fDR[B]
  EXPECT_EQ(slice(b, 68, 8), kOneAndHalf);  // indx, last of 9 doubles: 4 + 8*8
}

TEST(RecordLayout, PrimIs291BytesPacked) {
  PrimRecord p;
  p.type = 'B';
  p.transform = identity4();
  p.transform[3][0] = -5.0;
  p.inverse = identity4();
  p.inverse[0][0] = 0.5;
  p.map[0] = {3, 4};
  p.map[5] = {-1, 7};
  p.priority = 258;  // 0x0102
  p.indx = 0.0;
  ByteWriter w;
  encode(w, p);
  const Bytes& b = w.bytes();
  ASSERT_EQ(b.size(), 291u);
  EXPECT_EQ(b[0], 'B');
  EXPECT_EQ(slice(b, 1, 8), kOne);                         // transform[0][0]
  EXPECT_EQ(slice(b, 1 + 8 * 12, 8), kMinusFive);          // transform[3][0] = element 12
  EXPECT_EQ(slice(b, 1 + 8 * 15, 8), kOne);                // transform[3][3]
  EXPECT_EQ(slice(b, 129, 8), kHalf);                      // inverse[0][0] at 1 + 128
  EXPECT_EQ(slice(b, 257, 4), (Bytes{3, 0, 4, 0}));        // map[0][Out], map[0][In]
  EXPECT_EQ(slice(b, 277, 4), (Bytes{0xFF, 0xFF, 7, 0}));  // map[5] at 257 + 5*4
  EXPECT_EQ(slice(b, 281, 2), (Bytes{0x02, 0x01}));        // priority
  EXPECT_EQ(slice(b, 283, 8), kZero);                      // indx
}

TEST(RecordLayout, PrimIs292BytesWordAligned) {
  PrimRecord p;
  p.type = 'S';
  ByteWriter w;
  encode(w, p, PrimLayout::WordAligned);
  const Bytes& b = w.bytes();
  ASSERT_EQ(b.size(), 292u);
  EXPECT_EQ(b[0], 'S');
  EXPECT_EQ(b[1], 0);                 // alignment byte
  EXPECT_EQ(slice(b, 2, 8), kOne);    // transform[0][0] on an even offset
  EXPECT_EQ(slice(b, 130, 8), kOne);  // inverse[0][0]
}

TEST(RecordLayout, MapHeaderIsFourBytes) {
  ByteWriter w;
  encode(w, MapHeader{2, 300});  // 300 = 0x012C
  EXPECT_EQ(w.bytes(), (Bytes{2, 0, 0x2C, 0x01}));
}

TEST(RecordLayout, ObjListIsSixteenBitInts) {
  EXPECT_EQ(toBytes(ObjList{{1, 2, 300}}), (Bytes{1, 0, 2, 0, 0x2C, 0x01}));
}

TEST(RecordLayout, GraphFileHeaderThenInclusivePixels) {
  GraphFile g;
  g.graphType = 1;
  g.numPixAcross = 1;  // header says 1 x 1 ...
  g.numPixDown = 1;
  g.pixels = {1, 2, 3, -4};  // ... the inclusive loops write 2 x 2
  EXPECT_EQ(toBytes(g), (Bytes{1, 0, 1, 0, 1, 0, 1, 0, 2, 0, 3, 0, 0xFC, 0xFF}));
}

TEST(RecordLayout, GraphFilePiecesAreTheFilesBytes) {
  // writeGraphFile and the companion's hash take the file in pieces, without
  // building it: the pieces, joined, must be toBytes to the byte (the bytes
  // by hand above; here a picture of 70,000 pixels, more than one block).
  GraphFile g;
  g.numPixAcross = 349;
  g.numPixDown = 199;
  g.pixels.resize(350 * 200);
  for (std::size_t i = 0; i < g.pixels.size(); ++i)
    g.pixels[i] = static_cast<std::int16_t>(i * 40503u);  // every byte value, signs too
  Bytes joined;
  int pieces = 0;
  forEachGraphFileBytes(g, [&](std::span<const std::uint8_t> b) {
    joined.insert(joined.end(), b.begin(), b.end());
    ++pieces;
  });
  EXPECT_GE(pieces, 2);  // the header apart from the pixels
  EXPECT_EQ(joined, toBytes(g));
}

TEST(RecordLayout, MapFileIsHeaderThenDoubles) {
  MapFile m;
  m.header = {1, 2};
  m.texels = {0.5, 1.0};
  Bytes expected = {1, 0, 2, 0};
  expected.insert(expected.end(), kHalf.begin(), kHalf.end());
  expected.insert(expected.end(), kOne.begin(), kOne.end());
  EXPECT_EQ(toBytes(m), expected);
}

}  // namespace
}  // namespace prime::io
