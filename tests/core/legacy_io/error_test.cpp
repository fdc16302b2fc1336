// quotedWord: how every reader shows an offending word in a message.
#include "legacy_io/common/error.h"

#include <gtest/gtest.h>

#include <string>

namespace prime::io {
namespace {

TEST(QuotedWord, QuotesEscapesControlBytesAndCutsLongWords) {
  EXPECT_EQ(quotedWord("lambert", 40), "'lambert'");
  // A NUL and a tab are shown, not obeyed: a NUL used to cut a message short.
  EXPECT_EQ(quotedWord(std::string("a\0b\tc", 5), 40), "'a\\x00b\\x09c'");
  EXPECT_EQ(quotedWord("\x7f", 40), "'\\x7f'");
  EXPECT_EQ(quotedWord(std::string(50, 'x'), 40), "'" + std::string(40, 'x') + "...'");
  EXPECT_EQ(quotedWord("", 40), "''");
}

}  // namespace
}  // namespace prime::io
