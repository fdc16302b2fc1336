// The CGL package's pictures (legacy_io/cgl/frame.h; Sweeney 1985, Appendix 1
// "output" and Appendix 3 `encode`): RLE and raw round trips, hand-built
// bytes, every error with its byte offset, the files; the texture maps that
// stand in for the document's lost ones (scenes/cgl/textures, made by
// tools/cgl/textures.py; CGL-D21) decode with the texels the generator promises.
#include "legacy_io/cgl/frame.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "legacy_io/common/bytes.h"
#include "legacy_io/common/error.h"

namespace prime::cgl {
namespace {

using Bytes = std::vector<std::uint8_t>;

void putWord(Bytes& out, std::uint32_t w) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<std::uint8_t>(w >> (8 * k)));
}
std::uint32_t wordAt(const Bytes& bytes, std::size_t i) {
  return static_cast<std::uint32_t>(bytes[4 * i]) |
         static_cast<std::uint32_t>(bytes[4 * i + 1]) << 8 |
         static_cast<std::uint32_t>(bytes[4 * i + 2]) << 16 |
         static_cast<std::uint32_t>(bytes[4 * i + 3]) << 24;
}
// One black scanline as the encoder writes it: 255 + 255 + 2 pixels.
void putBlackLine(Bytes& out) {
  putWord(out, 0xff000000u);
  putWord(out, 0xff000000u);
  putWord(out, 0x02000000u);
}

io::InputError decodeError(const Bytes& bytes, bool raw = false) {
  try {
    if (raw)
      (void)decodeRaw(bytes, "pic.raw");
    else
      (void)decodeRle(bytes, "pic.rle");
  } catch (const io::InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error";
  return io::InputError({"none"}, "none");
}

TEST(CglFrame, PackingAsAppendix3) {
  // "8 bits blue, 8 bits green and the low 8 bits red".
  EXPECT_EQ(packPixel(0x12, 0x34, 0x56), 0x00563412u);
  EXPECT_EQ(redOf(0xff563412u), 0x12);
  EXPECT_EQ(greenOf(0xff563412u), 0x34);
  EXPECT_EQ(blueOf(0xff563412u), 0x56);
  Frame f;
  f.at(511, 0) = 7;  // the top scanline is the first row held
  EXPECT_EQ(f.words[0], 7u);
  f.at(0, 511) = 9;  // the bottom right pixel the last
  EXPECT_EQ(f.words.back(), 9u);
}

TEST(CglFrame, HandBuiltBytesDecode) {
  // Scanline 511: 2 red, 255 green, 255 blue (2 + 255 + 255 = 512 pixels),
  // each word little-endian: red 0x020000ff is ff 00 00 02.
  Bytes bytes = {0xff, 0x00, 0x00, 0x02,   // count 2, red 255
                 0x00, 0xff, 0x00, 0xff,   // count 255, green 255
                 0x00, 0x00, 0xff, 0xff};  // count 255, blue 255
  // Scanline 510: 1 pixel (r 1, g 2, b 3), then 511 black (255 + 255 + 1).
  const Bytes line510 = {0x01, 0x02, 0x03, 0x01, 0x00, 0x00, 0x00, 0xff,
                         0x00, 0x00, 0x00, 0xff, 0x00, 0x00, 0x00, 0x01};
  bytes.insert(bytes.end(), line510.begin(), line510.end());
  for (int line = 509; line >= 0; --line) putBlackLine(bytes);
  const Frame f = decodeRle(bytes, "hand.rle");
  EXPECT_EQ(f.at(511, 0), packPixel(255, 0, 0));
  EXPECT_EQ(f.at(511, 1), packPixel(255, 0, 0));
  EXPECT_EQ(f.at(511, 2), packPixel(0, 255, 0));
  EXPECT_EQ(f.at(511, 256), packPixel(0, 255, 0));
  EXPECT_EQ(f.at(511, 257), packPixel(0, 0, 255));
  EXPECT_EQ(f.at(511, 511), packPixel(0, 0, 255));
  EXPECT_EQ(f.at(510, 0), packPixel(1, 2, 3));
  EXPECT_EQ(f.at(510, 1), 0u);
  EXPECT_EQ(f.at(0, 511), 0u);
  // And it encodes back to the same bytes (the encoder's runs are maximal).
  EXPECT_EQ(encodeRle(f), bytes);
}

TEST(CglFrame, UniformFrameIsThreeWordsPerScanline) {
  Frame f;
  for (auto& w : f.words) w = packPixel(10, 200, 30);
  const Bytes bytes = encodeRle(f);
  ASSERT_EQ(bytes.size(), 512u * 3 * 4);  // 512 = 255 + 255 + 2
  EXPECT_EQ(wordAt(bytes, 0), 0xff1ec80au);
  EXPECT_EQ(wordAt(bytes, 1), 0xff1ec80au);
  EXPECT_EQ(wordAt(bytes, 2), 0x021ec80au);
  EXPECT_EQ(wordAt(bytes, 3), 0xff1ec80au);  // the next scanline starts afresh
  EXPECT_EQ(decodeRle(bytes, "u.rle").words, f.words);
}

TEST(CglFrame, OnePixelRunAtTheEndOfEachLine) {
  Frame f;
  for (int y = 0; y < Frame::kSize; ++y) {
    for (int x = 0; x < Frame::kSize - 1; ++x) f.at(y, x) = packPixel(1, 1, 1);
    f.at(y, Frame::kSize - 1) = packPixel(y & 0xff, 0, 9);
  }
  const Bytes bytes = encodeRle(f);
  ASSERT_EQ(bytes.size(), 512u * 4 * 4);  // 255 + 255 + 1, then 1
  EXPECT_EQ(wordAt(bytes, 2), 0x01010101u);
  EXPECT_EQ(wordAt(bytes, 3), 0x010900ffu);  // scanline 511: red 0xff
  EXPECT_EQ(decodeRle(bytes, "e.rle").words, f.words);
}

TEST(CglFrame, RandomFramesRoundTrip) {
  std::mt19937 rng(1985);
  for (int trial = 0; trial < 4; ++trial) {
    Frame f;
    // Runs of random length (1 to 600, so some cross lines and exceed 255)
    // from a palette of 4 colours (neighbouring runs may share a colour).
    std::size_t i = 0;
    while (i < f.words.size()) {
      const std::uint32_t colour = packPixel(static_cast<int>(rng() % 4) * 80, 7, trial);
      const std::size_t n = 1 + rng() % 600;
      for (std::size_t k = 0; k < n && i < f.words.size(); ++k) f.words[i++] = colour;
    }
    const Bytes bytes = encodeRle(f);
    EXPECT_EQ(bytes.size() % 4, 0u);
    EXPECT_EQ(decodeRle(bytes, "r.rle").words, f.words) << trial;
    for (std::size_t w = 0; w < bytes.size() / 4; ++w) EXPECT_NE(wordAt(bytes, w) >> 24, 0u);
  }
  // Every pixel different: one word per pixel, 1 MiB, the largest RLE file.
  Frame noisy;
  for (std::size_t k = 0; k < noisy.words.size(); ++k)
    noisy.words[k] = static_cast<std::uint32_t>(k * 2654435761u) & 0xffffffu;
  noisy.words[1] = noisy.words[0] ^ 1;
  const Bytes bytes = encodeRle(noisy);
  EXPECT_EQ(decodeRle(bytes, "n.rle").words, noisy.words);
  EXPECT_LE(bytes.size(), 512u * 512 * 4);
}

TEST(CglFrame, EncodeDropsTheUnusedByte) {
  Frame f;
  f.words[0] = 0xab000001u;  // "8 bits unused"
  const Frame back = decodeRle(encodeRle(f), "t.rle");
  EXPECT_EQ(back.words[0], 0x00000001u);
}

TEST(CglFrame, ZeroCountIsRefusedAtItsByte) {
  Bytes bytes;
  putBlackLine(bytes);
  putWord(bytes, 0x000000ffu);  // count 0, at byte 12
  const io::InputError e = decodeError(bytes);
  EXPECT_EQ(e.where().byte, 12u);
  EXPECT_EQ(e.field(), "run count");
  EXPECT_NE(std::string(e.what()).find("pic.rle (byte 12)"), std::string::npos) << e.what();
}

TEST(CglFrame, RunPastTheEndOfItsScanlineIsRefused) {
  Bytes bytes;
  putWord(bytes, 0xff000000u);
  putWord(bytes, 0xff000000u);
  putWord(bytes, 0x03000000u);  // 255 + 255 + 3 = 513: at byte 8
  const io::InputError e = decodeError(bytes);
  EXPECT_EQ(e.where().byte, 8u);
  EXPECT_EQ(e.field(), "run");
  EXPECT_NE(std::string(e.what()).find("scanline 511, 2 pixels left"), std::string::npos)
      << e.what();
  EXPECT_NE(std::string(e.what()).find("a run of 3 from x = 510"), std::string::npos) << e.what();
}

TEST(CglFrame, TruncatedWordIsRefused) {
  Frame f;
  Bytes bytes = encodeRle(f);  // 512 * 3 words
  bytes.push_back(0x01);
  bytes.push_back(0x02);
  const io::InputError e = decodeError(bytes);
  EXPECT_EQ(e.where().byte, 512u * 12);
  EXPECT_EQ(e.field(), "word");
  EXPECT_NE(std::string(e.what()).find("2 bytes at the end"), std::string::npos) << e.what();
  // Inside the picture, too: one whole scanline and 3 bytes.
  Bytes short_;
  putBlackLine(short_);
  short_.insert(short_.end(), {0, 0, 0});
  EXPECT_EQ(decodeError(short_).where().byte, 12u);
}

TEST(CglFrame, TooManyScanlinesIsRefused) {
  Bytes bytes = encodeRle(Frame{});
  const std::size_t end = bytes.size();
  putWord(bytes, 0x01000000u);
  const io::InputError e = decodeError(bytes);
  EXPECT_EQ(e.where().byte, end);
  EXPECT_EQ(e.field(), "scanlines");
}

TEST(CglFrame, TooFewScanlinesIsRefusedAtTheEnd) {
  Bytes bytes;
  for (int line = 0; line < 511; ++line) putBlackLine(bytes);
  io::InputError e = decodeError(bytes);
  EXPECT_EQ(e.where().byte, bytes.size());
  EXPECT_EQ(e.field(), "scanlines");
  EXPECT_NE(std::string(e.what()).find("found 511 whole scanlines at the end"), std::string::npos)
      << e.what();
  putWord(bytes, 0x02000000u);  // and 2 pixels of the last
  e = decodeError(bytes);
  EXPECT_EQ(e.where().byte, bytes.size());
  EXPECT_NE(std::string(e.what()).find("511 whole scanlines and 2 pixels of the next"),
            std::string::npos)
      << e.what();
  // An empty file.
  e = decodeError(Bytes{});
  EXPECT_EQ(e.where().byte, 0u);
  EXPECT_NE(std::string(e.what()).find("found 0 whole scanlines"), std::string::npos) << e.what();
}

TEST(CglFrame, RawRoundTripAndSize) {
  std::mt19937 rng(512);
  Frame f;
  for (auto& w : f.words) w = static_cast<std::uint32_t>(rng());  // the top byte kept too
  const Bytes bytes = encodeRaw(f);
  ASSERT_EQ(bytes.size(), 1048576u);
  EXPECT_EQ(wordAt(bytes, 0), f.at(511, 0));  // top scanline first, little-endian
  EXPECT_EQ(wordAt(bytes, 512), f.at(510, 0));
  EXPECT_EQ(decodeRaw(bytes, "r.raw").words, f.words);

  Bytes shorter(bytes.begin(), bytes.end() - 1);
  io::InputError e = decodeError(shorter, true);
  EXPECT_EQ(e.where().byte, 1048575u);  // where the data ran out
  EXPECT_EQ(e.field(), "file size");
  Bytes longer = bytes;
  longer.insert(longer.end(), {0, 0, 0, 0});
  e = decodeError(longer, true);
  EXPECT_EQ(e.where().byte, 1048576u);  // the first byte too many
  EXPECT_NE(std::string(e.what()).find("found 1048580 bytes"), std::string::npos) << e.what();
  EXPECT_EQ(decodeError(Bytes{}, true).where().byte, 0u);
}

TEST(CglFrame, ToRgbImageTopRowFirst) {
  Frame f;
  f.at(511, 3) = packPixel(255, 0, 51);
  f.at(0, 0) = packPixel(0, 102, 0) | 0xff000000u;  // the unused byte is ignored
  const RgbImage image = toRgbImage(f);
  ASSERT_EQ(image.width, 512);
  ASSERT_EQ(image.height, 512);
  EXPECT_EQ(image.at(0, 3), (Rgb{1.0, 0.0, 0.2}));
  EXPECT_EQ(image.at(511, 0), (Rgb{0.0, 0.4, 0.0}));
  EXPECT_EQ(image.at(1, 3), (Rgb{0.0, 0.0, 0.0}));
}

class CglFrameFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device rd;
    dir_ = std::filesystem::temp_directory_path() / ("cgl_frame_" + std::to_string(rd()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_F(CglFrameFiles, WriteAndReadBothFormatsLeavingNoTemporary) {
  Frame f;
  for (int x = 0; x < 512; ++x) f.at(100, x) = packPixel(x & 0xff, 3, 4);
  const std::string rle = (dir_ / "pic.rle").string(), raw = (dir_ / "pic.raw").string();
  writeRleFile(rle, f);
  writeRawFile(raw, f);
  EXPECT_EQ(readRleFile(rle).words, f.words);
  EXPECT_EQ(readRawFile(raw).words, f.words);
  EXPECT_EQ(std::filesystem::file_size(raw), 1048576u);
  // Overwriting goes through a temporary that is renamed into place.
  writeRleFile(rle, Frame{});
  EXPECT_EQ(readRleFile(rle).words, Frame{}.words);
  int entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
    ++entries;
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name == "pic.rle" || name == "pic.raw") << name;
  }
  EXPECT_EQ(entries, 2);
}

TEST_F(CglFrameFiles, ReadingRefusesMissingHugeAndOddFiles) {
  EXPECT_THROW((void)readRleFile((dir_ / "missing.rle").string()), io::InputError);
  const std::string huge = (dir_ / "huge.rle").string();
  {
    std::ofstream out(huge, std::ios::binary);
    out.seekp((4 << 20));  // 4 MiB + 1 byte
    out.put('\0');
  }
  try {
    (void)readRleFile(huge);
    ADD_FAILURE() << "a 4 MiB + 1 file was read";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.where().byte, 4u << 20);
    EXPECT_EQ(e.field(), "file size");
  }
  EXPECT_THROW((void)readRawFile(huge), io::InputError);
  EXPECT_THROW((void)readRleFile(dir_.string()), io::InputError);  // a directory
  const std::string bad = (dir_ / "bad.rle").string();
  {
    std::ofstream out(bad, std::ios::binary);
    out.write("\x01\x02\x03\x00", 4);  // count 0
  }
  try {
    (void)readRleFile(bad);
    ADD_FAILURE() << "a zero count was read";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.where().file, bad);
    EXPECT_EQ(e.where().byte, 0u);
  }
}

const std::string kTextures = std::string(CGL_SCENES) + "/textures/";

TEST(CglTextures, CheckerboardTexels) {
  const std::vector<std::uint8_t> bytes = io::readFileBytes(kTextures + "checkerboard.rle");
  EXPECT_EQ(bytes.size(), 512u * 8 * 4);  // 8 runs of 64 per scanline
  const Frame f = decodeRle(bytes, "checkerboard.rle");
  const std::uint32_t green = packPixel(0, 160, 0), blue = packPixel(0, 0, 200);
  // Image row y from the top is scanline 511 - y; square (y / 64 + x / 64)
  // even is green, so the top left square is green.
  EXPECT_EQ(f.at(511, 0), green);
  EXPECT_EQ(f.at(511, 63), green);
  EXPECT_EQ(f.at(511, 64), blue);
  EXPECT_EQ(f.at(448, 0), green);  // image row 63
  EXPECT_EQ(f.at(447, 0), blue);   // image row 64
  EXPECT_EQ(f.at(447, 64), green);
  EXPECT_EQ(f.at(0, 511), green);  // image row 511, column 511: square (7, 7)
  EXPECT_EQ(f.at(0, 0), blue);     // square (7, 0)
  // The generator's encoder is the package's: the same bytes back.
  EXPECT_EQ(encodeRle(f), bytes);
}

TEST(CglTextures, RingsTexels) {
  const Frame f = readRleFile(kTextures + "rings.rle");
  // The top left corner: twice its offset from the centre (255.5, 255.5) is
  // (-511, 511), on the diagonal, in the green octant; isqrt(2 * 511^2) / 32 =
  // 722 / 32 = ring 22, even, so bright green (30, 170, 40).
  EXPECT_EQ(f.at(511, 0), packPixel(30, 170, 40));
  // Right of the centre, just above it: offsets (1, 1) * 2 - 1 = (1, 1), on the
  // diagonal: octant 1 (orange), ring 0, bright.
  EXPECT_EQ(f.at(256, 256), packPixel(230, 130, 20));
  // Just right of the centre, just above, but further right: x = 300 gives
  // dx = 89, dy = 1: octant 0 (red), ring isqrt(7922) / 32 = 89 / 32 = 2, bright.
  EXPECT_EQ(f.at(256, 300), packPixel(220, 30, 30));
  // x = 280: dx = 49, ring 49 / 32 = 1, dark: (220, 30, 30) * 9 / 20.
  EXPECT_EQ(f.at(256, 280), packPixel(99, 13, 13));
  EXPECT_EQ(encodeRle(f), io::readFileBytes(kTextures + "rings.rle"));
}

}  // namespace
}  // namespace prime::cgl
