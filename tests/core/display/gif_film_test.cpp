// The GIF film (palette/gif_film.h): written, then read back with giflib's
// own decoder (DGifSlurp): frames, size, exact pixels of a frame of at most
// 256 colours, the delays, the loop extension, and the same bytes each run.
#include "palette/gif_film.h"

#include <gif_lib.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>

#include "legacy_io/common/output_file.h"
#include "tests/support/temp_dir.h"

namespace prime {
namespace {

// A picture of `width` x `height` whose pixel (x, y) is colour(x, y).
template <typename F>
Image8 pictureOf(int width, int height, F colour) {
  Image8 img{width, height, {}};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const GifColour c = colour(x, y);
      img.rgb.insert(img.rgb.end(), c.begin(), c.end());
    }
  return img;
}

// Three frames of 37 x 23: a few colours, 256 colours exactly, and a
// gradient of many more.
std::vector<Image8> threeFrames() {
  const int w = 37, h = 23;
  return {
      pictureOf(w, h,
                [](int x, int y) {
                  return GifColour{static_cast<std::uint8_t>(x < 10 ? 255 : 0),
                                   static_cast<std::uint8_t>(y < 5 ? 200 : 7), 31};
                }),
      pictureOf(w, h,
                [&](int x, int y) {
                  const int i = (y * w + x) % 256;
                  return GifColour{static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(255 - i),
                                   static_cast<std::uint8_t>(i * 7)};
                }),
      pictureOf(w, h,
                [](int x, int y) {
                  return GifColour{static_cast<std::uint8_t>(x * 7),
                                   static_cast<std::uint8_t>(y * 11),
                                   static_cast<std::uint8_t>(x * y % 256)};
                }),
  };
}

// A frame of more than 256 colours as 3-3-2 bits (the top bits of each
// channel, shown as the low end of their range): 256 entries at most. (The
// command quantizes with median cut, src/cli/cmd_film.cpp.)
IndexedFrame by332(const Image8& img) {
  IndexedFrame f{img.width, img.height, {}, {}};
  for (int i = 0; i < 256; ++i)
    f.palette.push_back({static_cast<std::uint8_t>(i >> 5 << 5),
                         static_cast<std::uint8_t>((i >> 2 & 7) << 5),
                         static_cast<std::uint8_t>((i & 3) << 6)});
  for (std::size_t p = 0; p < img.rgb.size(); p += 3)
    f.indices.push_back(static_cast<std::uint8_t>(
        (img.rgb[p] >> 5) << 5 | (img.rgb[p + 1] >> 5) << 2 | img.rgb[p + 2] >> 6));
  return f;
}

// The film of `frames` at `fps`: each frame exact when it can be.
std::vector<std::uint8_t> filmBytes(const std::filesystem::path& path,
                                    const std::vector<Image8>& frames, double fps, int loop) {
  {
    io::OutputFile out(path.string());
    GifFilm film(out, frames[0].width, frames[0].height, loop);
    for (std::size_t k = 0; k < frames.size(); ++k) {
      const std::optional<IndexedFrame> f = exactIndexed(frames[k]);
      film.addFrame(f ? *f : by332(frames[k]), gifDelay(static_cast<long>(k), fps));
    }
    film.close();
    out.commit();
  }
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// giflib's decoder over bytes in memory.
struct Reader {
  const std::vector<std::uint8_t>* bytes;
  std::size_t at = 0;
};
int readBytes(GifFileType* gif, GifByteType* into, int length) {
  auto* r = static_cast<Reader*>(gif->UserData);
  const std::size_t n =
      std::min<std::size_t>(static_cast<std::size_t>(length), r->bytes->size() - r->at);
  std::memcpy(into, r->bytes->data() + r->at, n);
  r->at += n;
  return static_cast<int>(n);
}

struct Decoded {
  GifFileType* gif = nullptr;
  ~Decoded() {
    if (gif) DGifCloseFile(gif, nullptr);
  }
};

// The picture frame `i` shows (every frame covers the screen).
Image8 shown(const GifFileType* gif, int i) {
  const SavedImage& s = gif->SavedImages[i];
  const ColorMapObject* map = s.ImageDesc.ColorMap ? s.ImageDesc.ColorMap : gif->SColorMap;
  Image8 img{s.ImageDesc.Width, s.ImageDesc.Height, {}};
  for (int p = 0; p < s.ImageDesc.Width * s.ImageDesc.Height; ++p) {
    const GifColorType c = map->Colors[s.RasterBits[p]];
    img.rgb.insert(img.rgb.end(), {c.Red, c.Green, c.Blue});
  }
  return img;
}

TEST(GifFilm, ReadsBackWithGiflib) {
  test::TempDir dir;
  const std::vector<Image8> frames = threeFrames();
  const double fps = 29.97;
  const std::vector<std::uint8_t> bytes = filmBytes(dir / "film.gif", frames, fps, 3);
  ASSERT_GT(bytes.size(), 6u);
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 6), "GIF89a");

  Reader reader{&bytes};
  int error = 0;
  Decoded d{DGifOpen(&reader, readBytes, &error)};
  ASSERT_NE(d.gif, nullptr) << GifErrorString(error);
  ASSERT_EQ(DGifSlurp(d.gif), GIF_OK) << GifErrorString(d.gif->Error);
  EXPECT_EQ(d.gif->SWidth, 37);
  EXPECT_EQ(d.gif->SHeight, 23);
  ASSERT_EQ(d.gif->ImageCount, 3);
  EXPECT_EQ(d.gif->SColorMap, nullptr);  // local colour maps only

  // The frames of at most 256 colours come back exactly; the third has more
  // and comes back near (median cut, 256 entries).
  EXPECT_EQ(shown(d.gif, 0).rgb, frames[0].rgb);
  EXPECT_EQ(shown(d.gif, 1).rgb, frames[1].rgb);
  EXPECT_EQ(d.gif->SavedImages[0].ImageDesc.ColorMap->ColorCount, 4);  // 4 colours
  EXPECT_EQ(d.gif->SavedImages[1].ImageDesc.ColorMap->ColorCount, 256);
  Image8 third = frames[2];  // as 3-3-2 shows it
  for (std::size_t i = 0; i < third.rgb.size(); ++i)
    third.rgb[i] =
        static_cast<std::uint8_t>(i % 3 == 2 ? third.rgb[i] >> 6 << 6 : third.rgb[i] >> 5 << 5);
  EXPECT_EQ(shown(d.gif, 2).rgb, third.rgb);

  // Delays: 3, 4, 3 hundredths at 29.97 fps, 10 in all = round(300 / 29.97).
  int total = 0;
  for (int i = 0; i < d.gif->ImageCount; ++i) {
    GraphicsControlBlock gcb{};
    ASSERT_EQ(DGifSavedExtensionToGCB(d.gif, i, &gcb), GIF_OK) << "frame " << i;
    EXPECT_EQ(gcb.TransparentColor, NO_TRANSPARENT_COLOR);
    total += gcb.DelayTime;
  }
  EXPECT_EQ(total, static_cast<int>(std::lround(100.0 * 3 / fps)));

  // NETSCAPE2.0 with the loop count, before the first frame.
  const SavedImage& first = d.gif->SavedImages[0];
  bool loopFound = false;
  for (int e = 0; e + 1 < first.ExtensionBlockCount; ++e) {
    const ExtensionBlock& app = first.ExtensionBlocks[e];
    const ExtensionBlock& sub = first.ExtensionBlocks[e + 1];
    if (app.Function == APPLICATION_EXT_FUNC_CODE && app.ByteCount == 11 &&
        std::memcmp(app.Bytes, "NETSCAPE2.0", 11) == 0) {
      ASSERT_EQ(sub.ByteCount, 3);
      EXPECT_EQ(sub.Bytes[0], 1);
      EXPECT_EQ(sub.Bytes[1] | sub.Bytes[2] << 8, 3);
      loopFound = true;
    }
  }
  EXPECT_TRUE(loopFound);

  // The same frames, the same bytes.
  EXPECT_EQ(filmBytes(dir / "again.gif", frames, fps, 3), bytes);
}

TEST(GifFilm, DelaysAddUpToTheFilmsLength) {
  for (const double fps : {30.0, 29.97, 12.5, 24.0, 7.0, 60.0, 1.0 / 3}) {
    int total = 0;
    for (long k = 0; k < 1000; ++k) {
      const int d = gifDelay(k, fps);
      EXPECT_GE(d, 0);
      EXPECT_LE(std::abs(d - 100.0 / fps), 1.0) << fps << " fps, frame " << k;
      total += d;
      ASSERT_EQ(total, std::lround(100.0 * static_cast<double>(k + 1) / fps))
          << fps << " fps, frame " << k;
    }
  }
  EXPECT_EQ(gifDelay(0, 30), 3);  // 3.33 -> 3, then 6.67 -> 7: 3, 4, 3, 3, 4, 3, ...
  EXPECT_EQ(gifDelay(1, 30), 4);
  EXPECT_EQ(gifDelay(2, 30), 3);
  EXPECT_EQ(gifDelay(0, 12.5), 8);
}

TEST(GifFilm, ExactPaletteIsTheSortedDistinctColours) {
  const Image8 img = pictureOf(3, 2, [](int x, int y) {
    return x == 0 ? GifColour{9, 0, 0} : GifColour{0, static_cast<std::uint8_t>(y), 200};
  });
  const std::optional<IndexedFrame> f = exactIndexed(img);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->palette, (std::vector<GifColour>{{0, 0, 200}, {0, 1, 200}, {9, 0, 0}}));
  EXPECT_EQ(f->indices, (std::vector<std::uint8_t>{2, 0, 0, 2, 1, 1}));
  // 257 colours: none.
  EXPECT_FALSE(exactIndexed(pictureOf(257, 1, [](int x, int) {
    return GifColour{static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(x >> 8), 0};
  })));
}

TEST(GifFilm, RefusesWhatGifCannotHold) {
  test::TempDir dir;
  io::OutputFile out((dir / "bad.gif").string());
  EXPECT_THROW(GifFilm(out, 0, 5, 0), std::invalid_argument);
  EXPECT_THROW(GifFilm(out, 5, 5, 70000), std::invalid_argument);
  GifFilm film(out, 2, 1, 0);
  EXPECT_THROW(film.addFrame({3, 1, {0, 0, 0}, {{0, 0, 0}}}, 3), std::invalid_argument);  // size
  EXPECT_THROW(film.addFrame({2, 1, {0, 1}, {{0, 0, 0}}}, 3), std::invalid_argument);     // index
  EXPECT_THROW(film.addFrame({2, 1, {0, 0}, {{0, 0, 0}}}, 70000), std::invalid_argument);
  film.addFrame({2, 1, {0, 0}, {{5, 6, 7}}}, 3);  // one colour: a map of 2
  EXPECT_EQ(film.frames(), 1);
}

}  // namespace
}  // namespace prime
