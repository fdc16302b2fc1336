// io::portableFromChars and io::portableToChars (the web build's fromChars and
// toChars, legacy_io/common/charconv.h) against std::from_chars and
// std::to_chars, which the native build uses: the same results on every
// grammar case and on random doubles.
#include "legacy_io/common/charconv.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>

namespace prime::io {
namespace {

struct Parsed {
  std::errc ec;
  std::ptrdiff_t used;
  std::uint64_t bits;
};

Parsed stdParse(const std::string& text) {
  double v = -12345.0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof v);
  return {r.ec, r.ptr - text.data(), bits};
}

Parsed portableParse(const std::string& text) {
  double v = -12345.0;
  const auto r = portableFromChars(text.data(), text.data() + text.size(), v);
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof v);
  return {r.ec, r.ptr - text.data(), bits};
}

std::string stdText(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string portableText(double v) {
  char buf[64];
  const auto r = portableToChars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

TEST(PortableCharconv, ReadsWhatFromCharsReads) {
  for (const std::string text : {"0",
                                 "-0",
                                 "1",
                                 "12.5",
                                 ".5",
                                 "5.",
                                 "-.5",
                                 "1e5",
                                 "1E-5",
                                 "1e",
                                 "1e+",
                                 "1e+x",
                                 "2.5e3x",
                                 "007",
                                 "0x1p3",
                                 "+1",
                                 " 1",
                                 "",
                                 "-",
                                 ".",
                                 "e5",
                                 "inf",
                                 "-INF",
                                 "Infinity",
                                 "infinit",
                                 "nan",
                                 "NaN(123)",
                                 "nan(",
                                 "1e309",
                                 "-1e309",
                                 "1e-400",
                                 "4.9e-324",
                                 "2.2250738585072014e-308",
                                 "1.7976931348623157e308",
                                 "0.1000000000000000055511151231257827",
                                 "123456789012345678901234567890",
                                 "3.14159 rest",
                                 "1,5",
                                 "--1"}) {
    const Parsed a = stdParse(text), b = portableParse(text);
    EXPECT_EQ(a.ec, b.ec) << "'" << text << "'";
    EXPECT_EQ(a.used, b.used) << "'" << text << "'";
    if (a.ec == std::errc() && text.find("nan") == std::string::npos &&
        text.find("NaN") == std::string::npos) {
      EXPECT_EQ(a.bits, b.bits) << "'" << text << "'";
    }
  }
}

TEST(PortableCharconv, WritesWhatToCharsWrites) {
  for (const double v :
       {0.0, -0.0, 1.0, -1.0, 0.1, 12.5, 29.97, 1e22, 1e21, 123456789012345680000.0, 1e-7, 0.0001,
        5e-324, 1.7976931348623157e308, 100.0, 1e15, 1e16, 1234.5678}) {
    EXPECT_EQ(stdText(v), portableText(v)) << v;
  }
}

TEST(PortableCharconv, RandomDoublesRoundTripTheSameWay) {
  std::mt19937_64 random(20261129);
  std::uniform_real_distribution<double> scene(-2000.0, 2000.0);
  for (int i = 0; i < 200000; ++i) {
    double v = 0;
    if (i % 2 == 0) {
      const std::uint64_t bits = random();
      std::memcpy(&v, &bits, sizeof v);
      if (v != v || v - v != 0) continue;  // NaN, Inf: their own cases above
    } else {
      v = scene(random);  // numbers such as scenes hold
    }
    const std::string text = stdText(v);
    ASSERT_EQ(text, portableText(v)) << "bits of " << text;
    const Parsed a = stdParse(text), b = portableParse(text);
    ASSERT_EQ(a.bits, b.bits) << text;
  }
}

}  // namespace
}  // namespace prime::io
