#include "palette/prime/graph_info.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"

namespace prime {
namespace {

GraphInfo sample() {
  GraphInfo info;
  info.graphBytes = 538306;
  info.graphHash = 0x0123456789abcdefull;
  info.profile = "modern";
  info.screenWidth = 800;
  info.screenHeight = 600;
  info.at = {527, 0};
  info.palette = *findBuiltinPalette("plate3");
  return info;
}

TEST(GraphInfo, Fnv1a64KnownValues) {
  // The FNV-1a offset basis for no bytes; "a" is 0xaf63dc4c8601ec8c (the
  // published FNV test vector).
  EXPECT_EQ(fnv1a64({}), 0xcbf29ce484222325ull);
  const std::uint8_t a[] = {'a'};
  EXPECT_EQ(fnv1a64(a), 0xaf63dc4c8601ec8cull);
}

TEST(GraphInfo, Xxh3KnownValues) {
  // The published XXH3-64 test vectors (seed 0): xxHash's own sanity check
  // for the empty string; "a" and "abc" as other implementations give them.
  EXPECT_EQ(graphHash(GraphHashKind::Xxh3_64, {}), 0x2d06800538d394c2ull);
  const std::uint8_t a[] = {'a'}, abc[] = {'a', 'b', 'c'};
  EXPECT_EQ(graphHash(GraphHashKind::Xxh3_64, a), 0xe6c632b61e964e1full);
  EXPECT_EQ(graphHash(GraphHashKind::Xxh3_64, abc), 0x78af5f94892f3950ull);
  EXPECT_EQ(graphHash(GraphHashKind::Fnv1a64, a), 0xaf63dc4c8601ec8cull);
}

TEST(GraphInfo, Xxh3StreamIsTheHashOfEverythingGiven) {
  // Pieces of every size across XXH3's internal block boundaries.
  std::vector<std::uint8_t> bytes(100000);
  for (std::size_t i = 0; i < bytes.size(); ++i)
    bytes[i] = static_cast<std::uint8_t>(i * 7 + i / 251);
  Xxh3Stream s;
  std::size_t at = 0, piece = 1;
  while (at < bytes.size()) {
    const std::size_t n = std::min(piece, bytes.size() - at);
    s.add(std::span(bytes).subspan(at, n));
    at += n;
    piece = piece * 3 % 4099 + 1;
  }
  EXPECT_EQ(s.digest(), graphHash(GraphHashKind::Xxh3_64, bytes));
  EXPECT_NE(s.digest(), graphHash(GraphHashKind::Xxh3_64, std::span(bytes).first(99999)));
  EXPECT_EQ(Xxh3Stream().digest(), 0x2d06800538d394c2ull);
}

TEST(GraphInfo, BuiltinPaletteRoundTrip) {
  const GraphInfo info = sample();
  const std::string text = formatGraphInfo(info);
  EXPECT_THAT(text, ::testing::HasSubstr("graph 538306 xxh3-64 0123456789abcdef\n"));
  EXPECT_THAT(text, ::testing::HasSubstr("palette plate3\n"));
  const GraphInfo back = parseGraphInfo(text, "x.info");
  EXPECT_EQ(back.graphBytes, info.graphBytes);
  EXPECT_EQ(back.graphHash, info.graphHash);
  EXPECT_EQ(back.hashKind, GraphHashKind::Xxh3_64);
  EXPECT_EQ(back.profile, "modern");
  EXPECT_EQ(back.screenWidth, 800);
  EXPECT_EQ(back.screenHeight, 600);
  EXPECT_EQ(back.at.left, 527);
  EXPECT_EQ(back.at.top, 0);
  EXPECT_FALSE(back.inline_);
  EXPECT_EQ(back.palette.name, "plate3");
  EXPECT_EQ(back.palette.dac, plate3Dac());
}

TEST(GraphInfo, InlinePaletteRoundTrip) {
  GraphInfo info = sample();
  info.inline_ = true;
  info.palette.description = "median-cut, dither none, 200 colours (thesis 4.4)";
  for (int i = 0; i < 256; ++i)
    info.palette.dac[static_cast<std::size_t>(i)] = {static_cast<std::uint8_t>(i % 64),
                                                     static_cast<std::uint8_t>(i / 4),
                                                     static_cast<std::uint8_t>(63 - i % 64)};
  const GraphInfo back = parseGraphInfo(formatGraphInfo(info), "x.info");
  EXPECT_TRUE(back.inline_);
  EXPECT_EQ(back.palette.dac, info.palette.dac);
  EXPECT_EQ(back.palette.description, info.palette.description);
  EXPECT_EQ(back.palette.name, "x.info");
}

void expectError(const std::string& text, int line, const std::string& field) {
  try {
    parseGraphInfo(text, "g.info");
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.where().file, "g.info");
    if (line > 0)
      EXPECT_EQ(e.where().line, line) << e.what();
    else
      EXPECT_FALSE(e.where().line) << e.what();
    EXPECT_EQ(e.field(), field) << e.what();
  }
}

TEST(GraphInfo, DamagedFilesAreLocatedErrors) {
  const std::string good = formatGraphInfo(sample());
  expectError("", 0, "first line");
  expectError("prime-graph-info 2\n", 1, "first line");
  // Line 2 is the comment, line 3 the graph line.
  std::string t = good;
  t.replace(t.find("xxh3-64 "), 8, "md5 ");
  expectError(t, 3, "graph hash");
  t = good;
  t.replace(t.find("screen 800"), 10, "screen -800");
  expectError(t, 5, "screen width");
  t = good;
  t.replace(t.find("palette plate3"), 14, "palette sunset");
  expectError(t, 7, "palette");
  expectError(good + "zoom 2\n", 8, "keyword");
  expectError(good + "at 1 2\n", 8, "at");  // twice
  t = good;
  t.erase(t.find("at 527 0\n"), 9);
  expectError(t, 0, "at");
  GraphInfo in = sample();
  in.inline_ = true;
  std::string inl = formatGraphInfo(in);
  expectError(inl.substr(0, inl.rfind("dac 255")), 0, "dac");  // 255 entries
  t = inl;
  const std::size_t dac3 = t.find("dac 3 ");
  t.replace(dac3, t.find('\n', dac3) - dac3, "dac 3 0 64 0");
  expectError(t, 11, "dac green");
  t = inl;
  t.replace(t.find("dac 3 "), 6, "dac 4 ");
  expectError(t, 11, "dac index");
  expectError(good + "dac 0 0 0 0\n", 8, "dac");  // not inline
}

TEST(GraphInfo, FoundOnlyBesideTheBytesItDescribes) {
  const auto dir = std::filesystem::temp_directory_path() / "prime_graph_info_test";
  std::filesystem::create_directories(dir);
  const std::string graph = (dir / "graph_scr").string();
  std::filesystem::remove(graphInfoPath(graph));
  const std::vector<std::uint8_t> bytes{1, 0, 2, 0, 3, 0, 9, 9};
  EXPECT_FALSE(findGraphInfo(graph, bytes).info);  // none there
  GraphInfo info = sample();
  info.graphBytes = bytes.size();
  info.graphHash = graphHash(GraphHashKind::Xxh3_64, bytes);
  writeGraphInfo(graphInfoPath(graph), info);
  EXPECT_EQ(graphInfoPath(graph), graph + ".info");
  const FoundGraphInfo found = findGraphInfo(graph, bytes);
  ASSERT_TRUE(found.info);
  EXPECT_EQ(found.info->at.left, 527);
  EXPECT_TRUE(found.stale.empty());
  // A companion written before G12 carries FNV-1a: still recognised, and
  // still told apart from other bytes.
  info.hashKind = GraphHashKind::Fnv1a64;
  info.graphHash = fnv1a64(bytes);
  writeGraphInfo(graphInfoPath(graph), info);
  EXPECT_THAT(io::readInputText(graphInfoPath(graph), {1u << 20, "x", ""}),
              ::testing::HasSubstr(" fnv1a64 "));
  ASSERT_TRUE(findGraphInfo(graph, bytes).info);
  EXPECT_EQ(findGraphInfo(graph, bytes).info->hashKind, GraphHashKind::Fnv1a64);
  info.graphHash = graphHash(GraphHashKind::Xxh3_64, bytes);  // the other algorithm's value
  writeGraphInfo(graphInfoPath(graph), info);
  EXPECT_FALSE(findGraphInfo(graph, bytes).info);
  info.hashKind = GraphHashKind::Xxh3_64;
  writeGraphInfo(graphInfoPath(graph), info);
  std::vector<std::uint8_t> other = bytes;
  other.back() = 8;  // same size, other bytes
  const FoundGraphInfo stale = findGraphInfo(graph, other);
  EXPECT_FALSE(stale.info);
  EXPECT_THAT(stale.stale, ::testing::HasSubstr("describes another graph file"));
  std::ofstream(graphInfoPath(graph)) << "prime-graph-info 1\nscreen 1\n";
  EXPECT_THROW(findGraphInfo(graph, bytes), io::InputError);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace prime
