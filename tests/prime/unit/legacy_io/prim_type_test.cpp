// The primitive type enum and the one check of a type byte (io::primType).
#include <gtest/gtest.h>

#include "legacy_io/prime/records.h"
#include "legacy_io/prime/text_inputs.h"

namespace prime::io {
namespace {

TEST(PrimType, TheFiveLettersAreTheTypes) {
  EXPECT_EQ(primType('S'), PrimType::Sphere);
  EXPECT_EQ(primType('B'), PrimType::Cube);
  EXPECT_EQ(primType('C'), PrimType::Cylinder);
  EXPECT_EQ(primType('N'), PrimType::Cone);
  EXPECT_EQ(primType('Y'), PrimType::Pyramid);
  for (const char c : {'S', 'B', 'C', 'N', 'Y'}) {
    ASSERT_TRUE(primType(c).has_value());
    EXPECT_EQ(static_cast<char>(*primType(c)), c);  // the byte on disk
  }
}

TEST(PrimType, AnyOtherByteIsNoType) {
  // Case sensitive, as the listing's switches; 0 and 0xFF as in a recycled
  // block (errata K33).
  for (const char c : {'s', 'b', 'X', 'P', 'O', 'T', '\0', '\xFF'}) {
    SCOPED_TRACE(static_cast<int>(c));
    EXPECT_FALSE(primType(c).has_value());
    EXPECT_FALSE(isPrimTypeLetter(c));
    EXPECT_EQ(surfaceCount(c), 0);
    EXPECT_STREQ(primTypeName(c), "unknown");
  }
}

TEST(PrimType, SurfacesAndNamesAsAddPrim) {
  EXPECT_EQ(surfaceCount(PrimType::Sphere), 1);
  EXPECT_EQ(surfaceCount(PrimType::Cube), 6);
  EXPECT_EQ(surfaceCount(PrimType::Cylinder), 3);
  EXPECT_EQ(surfaceCount(PrimType::Cone), 2);
  EXPECT_EQ(surfaceCount(PrimType::Pyramid), 5);
  EXPECT_EQ(surfaceCount('B'), 6);
  EXPECT_STREQ(primTypeName(PrimType::Cone), "cone");
  EXPECT_STREQ(primTypeName('Y'), "pyramid");
}

}  // namespace
}  // namespace prime::io
