#include "palette/gif_film.h"

#include <gif_lib.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "legacy_io/common/output_file.h"

namespace prime {

std::optional<IndexedFrame> exactIndexed(const Image8& image) {
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  const auto key = [&](std::size_t p) {
    return std::uint32_t{image.rgb[3 * p]} << 16 | std::uint32_t{image.rgb[3 * p + 1]} << 8 |
           image.rgb[3 * p + 2];
  };
  // Every 24-bit colour one bit: the distinct colours, counted as they come
  // (a picture of more than 256 stops at the 257th).
  std::vector<std::uint64_t> seen(std::size_t{1} << 18);
  int distinct = 0;
  for (std::size_t p = 0; p < pixels; ++p) {
    const std::uint32_t c = key(p);
    std::uint64_t& word = seen[c >> 6];
    const std::uint64_t bit = std::uint64_t{1} << (c & 63);
    if (word & bit) continue;
    word |= bit;
    if (++distinct > 256) return std::nullopt;
  }
  std::vector<std::uint32_t> colours;  // ascending 0xRRGGBB
  for (std::size_t w = 0; w < seen.size(); ++w)
    for (std::uint64_t bits = seen[w]; bits != 0; bits &= bits - 1)
      colours.push_back(static_cast<std::uint32_t>(w << 6) +
                        static_cast<std::uint32_t>(std::countr_zero(bits)));
  IndexedFrame frame{image.width, image.height, std::vector<std::uint8_t>(pixels), {}};
  for (const std::uint32_t c : colours)
    frame.palette.push_back({static_cast<std::uint8_t>(c >> 16), static_cast<std::uint8_t>(c >> 8),
                             static_cast<std::uint8_t>(c)});
  for (std::size_t p = 0; p < pixels; ++p)
    frame.indices[p] = static_cast<std::uint8_t>(
        std::lower_bound(colours.begin(), colours.end(), key(p)) - colours.begin());
  return frame;
}

int gifDelay(long k, double fps) {
  const auto end = [fps](long n) { return std::floor(100.0 * static_cast<double>(n) / fps + 0.5); };
  return static_cast<int>(end(k + 1) - end(k));
}

int GifFilm::write(GifFileType* gif, const std::uint8_t* bytes, int length) {
  auto* self = static_cast<GifFilm*>(gif->UserData);
  if (self->writeError_) return 0;
  try {  // no exception may cross giflib's C frames: kept, and thrown after
    self->out_.write(std::span<const std::uint8_t>(bytes, static_cast<std::size_t>(length)));
  } catch (...) {
    self->writeError_ = std::current_exception();
    return 0;
  }
  return length;
}

void GifFilm::fail(const char* step, int error) {
  if (writeError_) std::rethrow_exception(writeError_);  // the file's own reason (a full disk)
  throw std::runtime_error(out_.path() + ": giflib failed to write the " + step + ": " +
                           (GifErrorString(error) ? GifErrorString(error) : "unknown error"));
}

GifFilm::GifFilm(io::OutputFile& out, int width, int height, int loopCount)
    : out_(out), width_(width), height_(height) {
  if (width < 1 || height < 1 || width > 65535 || height > 65535)
    throw std::invalid_argument("a GIF's screen is 1..65535 pixels each way, not " +
                                std::to_string(width) + " x " + std::to_string(height));
  if (loopCount < 0 || loopCount > 65535)
    throw std::invalid_argument("a GIF's loop count is 0..65535, not " + std::to_string(loopCount));
  int error = 0;
  gif_ = EGifOpen(this, &GifFilm::write, &error);
  if (gif_ == nullptr) fail("header", error);
  EGifSetGifVersion(gif_, true);  // GIF89a: the extensions below
  if (EGifPutScreenDesc(gif_, width, height, 8, 0, nullptr) == GIF_ERROR)
    fail("logical screen", gif_->Error);
  // NETSCAPE2.0: sub-block 1, the loop count (little-endian).
  const GifByteType loop[3] = {1, static_cast<GifByteType>(loopCount & 0xff),
                               static_cast<GifByteType>(loopCount >> 8)};
  if (EGifPutExtensionLeader(gif_, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
      EGifPutExtensionBlock(gif_, 11, "NETSCAPE2.0") == GIF_ERROR ||
      EGifPutExtensionBlock(gif_, 3, loop) == GIF_ERROR ||
      EGifPutExtensionTrailer(gif_) == GIF_ERROR)
    fail("loop extension", gif_->Error);
}

GifFilm::~GifFilm() {
  if (gif_ != nullptr) EGifCloseFile(gif_, nullptr);  // an unfinished film: its output is dropped
}

void GifFilm::addFrame(const IndexedFrame& frame, int delay) {
  if (frame.width != width_ || frame.height != height_)
    throw std::invalid_argument("a frame of " + std::to_string(frame.width) + " x " +
                                std::to_string(frame.height) + " in a GIF of " +
                                std::to_string(width_) + " x " + std::to_string(height_));
  addFrameAt(frame, 0, 0, delay);
}

void GifFilm::addFrameAt(const IndexedFrame& frame, int left, int top, int delay) {
  if (gif_ == nullptr) throw std::logic_error("GifFilm::addFrame after close");
  if (frame.width < 1 || frame.height < 1 || left < 0 || top < 0 || frame.width > width_ - left ||
      frame.height > height_ - top)
    throw std::invalid_argument("a frame of " + std::to_string(frame.width) + " x " +
                                std::to_string(frame.height) + " at (" + std::to_string(left) +
                                ", " + std::to_string(top) + ") in a GIF of " +
                                std::to_string(width_) + " x " + std::to_string(height_));
  const std::size_t pixels = static_cast<std::size_t>(frame.width) * frame.height;
  if (frame.palette.empty() || frame.palette.size() > 256 || frame.indices.size() != pixels)
    throw std::invalid_argument("a frame needs 1..256 palette entries and one index a pixel");
  if (delay < 0 || delay > 65535)
    throw std::invalid_argument("a GIF frame's delay is 0..65535 hundredths of a second, not " +
                                std::to_string(delay));
  const std::uint8_t most = *std::max_element(frame.indices.begin(), frame.indices.end());
  if (most >= frame.palette.size())
    throw std::invalid_argument("a frame's index " + std::to_string(most) + " is past its " +
                                std::to_string(frame.palette.size()) + " palette entries");

  GraphicsControlBlock control{};
  control.DisposalMode = DISPOSE_DO_NOT;  // the next frame draws over this one
  control.UserInputFlag = false;
  control.DelayTime = delay;
  control.TransparentColor = NO_TRANSPARENT_COLOR;
  GifByteType extension[4];
  const std::size_t length = EGifGCBToExtension(&control, extension);
  if (EGifPutExtension(gif_, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(length), extension) ==
      GIF_ERROR)
    fail("frame's delay", gif_->Error);

  // The colour map: a power of two entries, at least 2, padded with black.
  int size = 2;
  while (size < static_cast<int>(frame.palette.size())) size *= 2;
  std::vector<GifColorType> colours(static_cast<std::size_t>(size), GifColorType{0, 0, 0});
  for (std::size_t i = 0; i < frame.palette.size(); ++i)
    colours[i] = {frame.palette[i][0], frame.palette[i][1], frame.palette[i][2]};
  ColorMapObject* map = GifMakeMapObject(size, colours.data());
  if (map == nullptr) throw std::bad_alloc();
  const int put = EGifPutImageDesc(gif_, left, top, frame.width, frame.height, false, map);
  GifFreeMapObject(map);  // giflib keeps its own copy
  if (put == GIF_ERROR) fail("frame's image descriptor", gif_->Error);
  // EGifPutLine masks the line it is given in place: a copy of each row.
  std::vector<GifPixelType> row(static_cast<std::size_t>(frame.width));
  for (int y = 0; y < frame.height; ++y) {
    const auto from = frame.indices.begin() + static_cast<std::ptrdiff_t>(y) * frame.width;
    std::copy(from, from + frame.width, row.begin());
    if (EGifPutLine(gif_, row.data(), frame.width) == GIF_ERROR)
      fail("frame's pixels", gif_->Error);
  }
  ++frames_;
}

void GifFilm::close() {
  if (gif_ == nullptr) return;
  int error = 0;
  const int closed = EGifCloseFile(gif_, &error);  // writes the trailer; frees gif_
  gif_ = nullptr;
  if (writeError_) std::rethrow_exception(writeError_);
  if (closed == GIF_ERROR) fail("trailer", error);
}

}  // namespace prime
