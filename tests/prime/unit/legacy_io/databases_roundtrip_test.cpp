// write -> read -> write gives the same bytes for every database type, and the
// reader recognises both Prim layouts and both graph-file pixel counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "legacy_io/common/error.h"
#include "legacy_io/prime/graph_file.h"
#include "legacy_io/prime/map_file.h"
#include "legacy_io/prime/obj_file.h"
#include "legacy_io/prime/obj_list.h"
#include "legacy_io/prime/prim_file.h"
#include "src/prime/math/listing_matrix.h"

namespace prime::io {
namespace {

PrimRecord samplePrim(char type, double shift) {
  PrimRecord p;
  p.type = type;
  p.transform = identity4();
  scale(p.transform, {2, 3, 4});
  translate(p.transform, {shift, -1.25, 7});
  EXPECT_TRUE(inverse(p.transform, p.inverse));
  p.map[0] = {1, 2};
  p.map[1] = {3, 4};
  p.priority = 9;
  return p;
}

TEST(RoundTrip, PrimFile) {
  PrimFile f;
  f.prims = {samplePrim('B', 1.0), samplePrim('S', -3.5), samplePrim('Y', 1e-300)};
  const auto bytes = toBytes(f);
  ASSERT_EQ(bytes.size(), 3 * 291u);
  const PrimFile back = primFileFromBytes(bytes, "PrimFile");
  EXPECT_EQ(back.layout, PrimLayout::Packed);
  ASSERT_EQ(back.prims.size(), 3u);
  EXPECT_EQ(back.prims[1], f.prims[1]);
  EXPECT_EQ(toBytes(back), bytes);
}

TEST(RoundTrip, WordAlignedPrimFileIsReadAndRewrittenPacked) {
  ByteWriter w;
  const PrimRecord a = samplePrim('C', 2.0), b = samplePrim('N', 5.0);
  encode(w, a, PrimLayout::WordAligned);
  encode(w, b, PrimLayout::WordAligned);
  const PrimFile back = primFileFromBytes(w.bytes(), "PrimFile");
  EXPECT_EQ(back.layout, PrimLayout::WordAligned);
  ASSERT_EQ(back.prims.size(), 2u);
  EXPECT_EQ(back.prims[0], a);
  EXPECT_EQ(back.prims[1], b);
  EXPECT_EQ(toBytes(back).size(), 2 * 291u);
}

TEST(RoundTrip, AmbiguousSizeIsDecidedByTheAffineColumn) {
  // 292 packed records and 291 aligned ones have the same size: 84972 bytes.
  PrimFile packed;
  packed.prims.assign(292, samplePrim('B', 1.0));
  EXPECT_EQ(primFileFromBytes(toBytes(packed), "PrimFile").layout, PrimLayout::Packed);
  ByteWriter w;
  for (int i = 0; i < 291; ++i) encode(w, samplePrim('B', 1.0), PrimLayout::WordAligned);
  ASSERT_EQ(w.bytes().size(), 84972u);
  EXPECT_EQ(primFileFromBytes(w.bytes(), "PrimFile").layout, PrimLayout::WordAligned);
}

TEST(RoundTrip, ObjFile) {
  ObjFile f;
  f.header.numEntries = 3;
  f.header.boundVol = 4;
  f.header.hue.kDR = 0.25;
  f.header.hue.indx = 1.5;
  ObjRecord u;
  u.opCode = {'+', 0, 0, 0};
  u.l = 1;
  u.r = 2;
  ObjRecord p1;
  p1.opCode = {'P', 0, 0, 0};
  p1.l = 0;
  ObjRecord p2 = p1;
  p2.l = 3;
  f.entries = {u, p1, p2};
  const auto bytes = toBytes(f);
  ASSERT_EQ(bytes.size(), 76u + 3 * 8);
  const ObjFile back = objFileFromBytes(bytes, "O1");
  EXPECT_EQ(back.header, f.header);
  EXPECT_EQ(back.entries, f.entries);
  EXPECT_EQ(toBytes(back), bytes);
}

// A file whose size is not the one its header counts: cut short (a copy
// that stopped) or with bytes after its records, each said as what it is,
// at the byte where the two part.
TEST(RoundTrip, AnObjFileOfTheWrongSizeSaysHowItDiffersFromItsHeader) {
  ObjFile f;
  f.header.numEntries = 5;
  ObjRecord p;
  p.opCode = {'P', 0, 0, 0};
  f.entries.assign(5, p);
  const auto bytes = toBytes(f);
  ASSERT_EQ(bytes.size(), 116u);
  const auto messageFor = [&](std::size_t size) -> std::string {
    std::vector<std::uint8_t> cut(bytes.begin(), bytes.begin() + std::min(size, bytes.size()));
    cut.resize(size, 0);
    try {
      objFileFromBytes(cut, "O1");
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(messageFor(113),
            "O1 (byte 113): file size: expected 116 bytes (the 76-byte ObjHeader and the 5 "
            "8-byte Obj records its numEntries counts), found 113 bytes (cut short by 3 bytes)");
  EXPECT_EQ(messageFor(100),
            "O1 (byte 100): file size: expected 116 bytes (the 76-byte ObjHeader and the 5 "
            "8-byte Obj records its numEntries counts), found 100 bytes (cut short by 16 bytes)");
  EXPECT_EQ(messageFor(117),
            "O1 (byte 116): file size: expected 116 bytes (the 76-byte ObjHeader and the 5 "
            "8-byte Obj records its numEntries counts), found 117 bytes (1 byte after the last "
            "record)");
  EXPECT_EQ(messageFor(116), "no error");
  std::vector<std::uint8_t> negative = bytes;
  negative[0] = 0xff;
  negative[1] = 0xff;
  try {
    objFileFromBytes(negative, "O1");
    ADD_FAILURE() << "numEntries -1 was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "O1 (byte 0): ObjHeader.numEntries: expected the number of Obj records, 0 or more, "
              "found -1");
  }
}

TEST(RoundTrip, ObjListMapAndGraph) {
  const ObjList list{{1, 7, -3}};
  EXPECT_EQ(toBytes(objListFromBytes(toBytes(list), "List")), toBytes(list));

  MapFile m;
  m.header = {3, 2};
  m.texels = {0, 0.125, 0.25, 0.5, 0.75, 1};
  EXPECT_EQ(toBytes(mapFileFromBytes(toBytes(m), "Map1_R.map")), toBytes(m));

  GraphFile g;
  g.numPixAcross = 2;
  g.numPixDown = 1;
  g.pixels = {1, 2, 3, 4, 5, 6};  // 3 x 2, inclusive
  const GraphFile back = graphFileFromBytes(toBytes(g), "graph_scr");
  EXPECT_TRUE(back.inclusive);
  EXPECT_EQ(back.width(), 3);
  EXPECT_EQ(back.height(), 2);
  EXPECT_EQ(back.at(2, 1), 6);
  EXPECT_EQ(toBytes(back), toBytes(g));

  GraphFile exact = g;
  exact.inclusive = false;
  exact.pixels = {1, 2};  // 2 x 1, as the header says
  const GraphFile exactBack = graphFileFromBytes(toBytes(exact), "graph_scr");
  EXPECT_FALSE(exactBack.inclusive);
  EXPECT_EQ(toBytes(exactBack), toBytes(exact));
}

}  // namespace
}  // namespace prime::io
