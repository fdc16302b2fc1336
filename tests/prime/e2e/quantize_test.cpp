// `prime quantize`, `prime trace --quantize`, and the graph file's companion
// file (G7-G11, T59) through the real executable.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "tests/support/run_prime.h"
#include "tests/support/temp_scene.h"

namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;
using prime::test::CommandResult;

using prime::test::runPrime;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

struct Sphere {
  prime::test::TempScene s;
  Sphere() {
    fs::copy(fs::path(PRIME_TEST_DATA) / "sphere", s.path(),
             fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  }
  std::string dir() const { return s.path().string(); }
  fs::path at(const std::string& name) const { return s.path() / name; }
};

TEST(GraphInfo, TraceWritesItAndExportUsesTheFraming) {
  Sphere sc;
  // A render for an 800 x 600 screen: the listing's viewport puts it at
  // ((int)(0.66*800), 0) = (528, 0), which export cannot guess.
  CommandResult r = runPrime("trace --model --no-window -q --screen 800 600 " + sc.dir());
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string info = slurp(sc.at("graph_scr.info"));
  EXPECT_THAT(info, HasSubstr("prime-graph-info 1\n"));
  EXPECT_THAT(info, HasSubstr("\nscreen 800 600\nat 528 0\npalette listing\n"));
  EXPECT_THAT(info, HasSubstr("\nprofile 1991\n"));
  r = runPrime("export " + sc.at("graph_scr").string() + " " + sc.at("a.png").string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("at (528, 0) on a 800 x 600 screen"));
  EXPECT_THAT(r.output, ::testing::Not(HasSubstr("does not fit")));
  // Without it, the 8514/A's default framing, which clips this file.
  r = runPrime("export --no-info " + sc.at("graph_scr").string() + " " + sc.at("b.png").string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("at (675, 0) on a 1024 x 768 screen"));
  // Flags still win over the companion (G10).
  r = runPrime("export --at 0 0 " + sc.at("graph_scr").string() + " " + sc.at("c.png").string());
  EXPECT_THAT(r.output, HasSubstr("at (0, 0) on a 800 x 600 screen"));
}

TEST(GraphInfo, DamagedIsALocatedErrorAndNoInfoStillReads) {
  Sphere sc;
  ASSERT_EQ(runPrime("trace --model --no-window -q " + sc.dir()).status, 0);
  std::string info = slurp(sc.at("graph_scr.info"));
  info.replace(info.find("screen 1024"), 11, "screen wide");
  std::ofstream(sc.at("graph_scr.info"), std::ios::binary) << info;
  CommandResult r =
      runPrime("export " + sc.at("graph_scr").string() + " " + sc.at("a.png").string());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("graph_scr.info:5"));
  EXPECT_THAT(r.output, HasSubstr("screen width"));
  EXPECT_FALSE(fs::exists(sc.at("a.png")));
  r = runPrime("export --no-info " + sc.at("graph_scr").string() + " " + sc.at("a.png").string());
  EXPECT_EQ(r.status, 0) << r.output;
}

TEST(GraphInfo, AStaleCompanionIsIgnoredWithAWarning) {
  Sphere sc;
  ASSERT_EQ(runPrime("trace --model --no-window -q " + sc.dir()).status, 0);
  std::string graph = slurp(sc.at("graph_scr"));
  graph[100] = static_cast<char>(graph[100] ^ 1);  // another program's graph file
  std::ofstream(sc.at("graph_scr"), std::ios::binary) << graph;
  const CommandResult r =
      runPrime("export " + sc.at("graph_scr").string() + " " + sc.at("a.png").string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("describes another graph file"));
}

TEST(Quantize, TraceQuantizedExportsAsTracedAndKeepsTheListingFileWithout) {
  Sphere sc;
  ASSERT_EQ(
      runPrime("trace --model --no-window -q --out " + sc.at("plain").string() + " " + sc.dir())
          .status,
      0);
  CommandResult r =
      runPrime("trace --no-window -q --quantize octree --dither floyd-steinberg --out " +
               sc.at("q").string() + " --png " + sc.at("traced.png").string() +
               " --true-color-png " + sc.at("true.png").string() + " " + sc.dir());
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string info = slurp(sc.at("q.info"));
  EXPECT_THAT(info, HasSubstr("palette inline octree, dither floyd-steinberg"));
  EXPECT_THAT(info, HasSubstr("\ndac 255 "));
  // The same header, other indices.
  const std::string plain = slurp(sc.at("plain")), q = slurp(sc.at("q"));
  ASSERT_EQ(plain.size(), q.size());
  EXPECT_EQ(plain.substr(0, 6), q.substr(0, 6));
  EXPECT_NE(plain, q);
  // export shows exactly what trace showed, through the inline palette.
  r = runPrime("export " + sc.at("q").string() + " " + sc.at("exported.png").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(slurp(sc.at("exported.png")), slurp(sc.at("traced.png")));
  // Ours against the true colours: a report line with all four numbers.
  r = runPrime("quantize " + sc.at("true.png").string() + " " + sc.at("m.png").string() +
               " --method median-cut --report");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("median-cut none: mean dE00 "));
  EXPECT_THAT(r.output, HasSubstr(" dB, CPU "));
}

TEST(Quantize, UsageAndInputErrors) {
  Sphere sc;
  std::ofstream(sc.at("not.png")) << "hello";
  CommandResult r =
      runPrime("quantize " + sc.at("not.png").string() + " " + sc.at("o.png").string());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("not.png"));
  r = runPrime("quantize " + sc.at("not.png").string() + " " + sc.at("o.png").string() +
               " --method listing --dither ordered");
  EXPECT_EQ(r.status, 2) << r.output;
  r = runPrime("quantize " + sc.at("not.png").string() + " o.png --method kmeans");
  EXPECT_EQ(r.status, 2) << r.output;
}

// The PNG bytes of a W x H RGB picture whose data is a few bytes: what a
// hostile file says in its header.
std::string pngClaiming(std::uint32_t w, std::uint32_t h) {
  const auto crc = [](const std::string& data) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (unsigned char b : data) {
      c ^= b;
      for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return c ^ 0xFFFFFFFFu;
  };
  const auto be32 = [](std::uint32_t v) {
    return std::string{static_cast<char>(v >> 24), static_cast<char>(v >> 16),
                       static_cast<char>(v >> 8), static_cast<char>(v)};
  };
  const auto chunk = [&](const std::string& type, const std::string& data) {
    return be32(static_cast<std::uint32_t>(data.size())) + type + data + be32(crc(type + data));
  };
  const std::string ihdr = be32(w) + be32(h) + std::string("\x08\x02\x00\x00\x00", 5);
  const std::string idat("\x78\x9c\x63\x00\x00\x00\x01\x00\x01", 9);
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", idat) +
         chunk("IEND", "");
}

// quantize's input is an input of the run (never its own output, by any
// name), and is read as every input is: a FIFO refused by type, a header
// claiming more pixels than the file can hold refused before allocating.
TEST(Quantize, NeverOverwritesItsInputAndRefusesHostileFiles) {
  Sphere sc;
  ASSERT_EQ(runPrime("trace --model --no-window -q --true-color-png " + sc.at("in.png").string() +
                     " " + sc.dir())
                .status,
            0);
  const std::string before = slurp(sc.at("in.png"));
  fs::create_hard_link(sc.at("in.png"), sc.at("link.png"));
  for (const std::string& out :
       {sc.at("in.png").string(), sc.dir() + "/./in.png", sc.at("link.png").string()}) {
    const CommandResult r = runPrime("quantize " + sc.at("in.png").string() + " " + out);
    EXPECT_EQ(r.status, 1) << out << ": " << r.output;
    EXPECT_THAT(r.output, HasSubstr("input")) << out;
    EXPECT_EQ(slurp(sc.at("in.png")), before) << out << " replaced the input";
  }
  std::ofstream(sc.at("huge.png"), std::ios::binary) << pngClaiming(30000, 30000);
  CommandResult r =
      runPrime("quantize " + sc.at("huge.png").string() + " " + sc.at("o.png").string());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("30000 x 30000 pixels"));
  EXPECT_THAT(r.output, HasSubstr("more than a"));
  EXPECT_FALSE(fs::exists(sc.at("o.png")));
  ASSERT_EQ(::mkfifo(sc.at("pipe.png").c_str(), 0600), 0);
  r = runPrime("quantize " + sc.at("pipe.png").string() + " " + sc.at("o.png").string());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("pipe.png"));
  EXPECT_FALSE(fs::exists(sc.at("o.png")));
}

}  // namespace
