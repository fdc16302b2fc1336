// The normal reflectance of `prime cook` (legacy_io/cgl/reflectance.h): 33
// numbers, any number to a line, '*' lines and blank lines comments; every
// error names the file and the line (the count and range errors named only
// the file before the reader moved out of the command).
#include "legacy_io/cgl/reflectance.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace prime::cgl {
namespace {

using ::testing::HasSubstr;

// 33 values 0.01, 0.02 ... 0.33, ten to a line.
std::string values(int count = 33, int from = 1) {
  std::string out;
  for (int k = 0; k < count; ++k)
    out += std::to_string((from + k) / 100.0).substr(0, 4) + ((k + 1) % 10 == 0 ? "\n" : " ");
  return out + "\n";
}

io::InputError reflectanceError(const std::string& text) {
  try {
    readReflectance(text, "r.txt");
  } catch (const io::InputError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted: " << text;
  return io::InputError({}, "none");
}

TEST(CglReflectance, ReadsNumbersAnyNumberToALineWithComments) {
  const Spectrum r = readReflectance("* copper-ish\r\n\r\n   * indented\r\n" + values(), "r.txt");
  EXPECT_DOUBLE_EQ(r[0], 0.01);
  EXPECT_DOUBLE_EQ(r[32], 0.33);
  // A ^Z ends the text.
  EXPECT_DOUBLE_EQ(readReflectance(values() + "\x1a" + "junk", "r.txt")[20], 0.21);
}

TEST(CglReflectance, EveryErrorNamesTheLine) {
  // A word that is not a number: its line.
  io::InputError e = reflectanceError("* c\n0.1 0.2x\n");
  EXPECT_EQ(e.where().line, 2);
  EXPECT_EQ(e.found(), "'0.2x'");
  // Too many: the line of the 34th (comment, then 4 lines of values).
  e = reflectanceError("*\n" + values() + "0.5\n");
  EXPECT_EQ(e.where().line, 6);
  EXPECT_EQ(e.found(), "a 34th, '0.5'");
  EXPECT_EQ(std::string(e.what()).rfind("r.txt:6: normal reflectance: expected 33 numbers", 0), 0u);
  // Too few: the last line.
  e = reflectanceError(values(32) + "* end\n");
  EXPECT_EQ(e.where().line, 5);
  EXPECT_EQ(e.found(), "32 numbers");
  EXPECT_EQ(reflectanceError("").where().line, 1);
  // Out of range: the line of the number and its wavelength (580 nm, the 21st).
  e = reflectanceError(values(20) + "1.0 " + values(12, 22));  // after a blank line 3
  EXPECT_EQ(e.where().line, 4);
  EXPECT_EQ(e.field(), "normal reflectance at 580 nm");
  EXPECT_THAT(e.expected(), HasSubstr("0 <= R < 1"));
}

TEST(CglReflectance, CommandLineNumbersAreCheckedAlike) {
  std::vector<ReflectanceNumber> numbers(33, {0.5, {"--reflectance"}});
  EXPECT_DOUBLE_EQ(normalReflectance(numbers, {"--reflectance"})[32], 0.5);
  numbers[3].value = -0.1;
  EXPECT_THROW(normalReflectance(numbers, {"--reflectance"}), io::InputError);
  numbers.resize(2);
  EXPECT_THROW(normalReflectance(numbers, {"--reflectance"}), io::InputError);
  double v = 0;
  EXPECT_TRUE(isReflectanceNumber("2.5E-1", v));
  EXPECT_DOUBLE_EQ(v, 0.25);
  EXPECT_FALSE(isReflectanceNumber("0.25 ", v));
  EXPECT_FALSE(isReflectanceNumber("nan", v));
}

}  // namespace
}  // namespace prime::cgl
