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

// Issue 37: a CGL record's name quoted its keyword as written, so a NUL cut
// the message at "surface 1 (ph" and an escape sequence reached the terminal.
// Whatever the parts hold, what() shows them; its own layout stays.
TEST(InputErrorMessage, ShowsControlBytesOfEveryPartEscaped) {
  const InputError e({"s.cgl", 3, std::nullopt}, std::string("surface 1 (ph\0ng\x1b[31m)", 22),
                     "a model", "'x'");
  EXPECT_EQ(std::string(e.what()),
            "s.cgl:3: surface 1 (ph\\x00ng\\x1b[31m): expected a model, found 'x'");
  const InputError laidOut({"dir", std::nullopt, std::nullopt}, "not up to date:\n\tprim\x07");
  EXPECT_EQ(std::string(laidOut.what()), "dir: not up to date:\n\tprim\\x07");
}

}  // namespace
}  // namespace prime::io
