// An animated GIF (GIF89a, giflib) written frame by frame: open, add frames
// (palette indices with their palette, each with its delay), close. Shared
// by every command that makes a film: `prime film` (src/cli/cmd_film.cpp)
// and, later, an animated capture of a display. docs/user-guide.md, "Films".
//
//   - The logical screen is the frame size; a frame covers all of it or a
//     part (addFrameAt), with its own local colour map (no global one), so frames of different
//     palettes (a 256-colour display whose DAC changes, or frames quantized
//     one by one) are each exact.
//   - A NETSCAPE2.0 application extension holds the loop count (0: forever).
//   - Each frame has a graphics control extension with its delay in
//     hundredths of a second (GIF's resolution; gifDelay spreads a frame
//     rate's rounding so the delays add up to the film's length).
//   - The bytes go to an io::OutputFile, which the caller commits after
//     close(): all or nothing. The same frames give the same bytes.
#pragma once
#include <array>
#include <cstdint>
#include <exception>
#include <optional>
#include <vector>

#include "palette/png_image.h"

struct GifFileType;

namespace prime {

namespace io {
class OutputFile;
}

using GifColour = std::array<std::uint8_t, 3>;  // 8-bit R, G, B

// A picture as palette indices: one byte a pixel, rows from the top, each
// index below palette.size() (1..256 entries).
struct IndexedFrame {
  int width = 0, height = 0;
  std::vector<std::uint8_t> indices;
  std::vector<GifColour> palette;
};

// The picture exactly, when it has at most 256 distinct colours: its
// palette is those colours sorted by 0xRRGGBB (the same picture, the same
// palette). std::nullopt when it has more.
std::optional<IndexedFrame> exactIndexed(const Image8& image);

// Frame k's delay in hundredths of a second at `fps` frames a second:
// round(100 (k+1) / fps) - round(100 k / fps), so that the first n frames
// last round(100 n / fps) hundredths together (each frame ends within half
// a hundredth of its true time; no drift over a long film).
int gifDelay(long k, double fps);

class GifFilm {
 public:
  // Writes the header, the logical screen (width x height) and the loop
  // count (0: forever; at most 65535) into `out`. Throws
  // std::invalid_argument for a size or loop count GIF cannot hold.
  GifFilm(io::OutputFile& out, int width, int height, int loopCount);
  ~GifFilm();
  GifFilm(const GifFilm&) = delete;
  GifFilm& operator=(const GifFilm&) = delete;

  // One frame of the screen's size, shown for `delay` hundredths of a second
  // (0..65535). Its colour map is its palette padded with black to the next
  // power of two (at least 2). Throws std::invalid_argument for a frame that
  // does not fit, std::runtime_error when the writing fails.
  void addFrame(const IndexedFrame& frame, int delay);
  // A frame that covers part of the screen, its top-left at (left, top),
  // drawn over what the frames before it left (disposal: do not dispose):
  // what changed since the last frame, as a screen recording needs.
  void addFrameAt(const IndexedFrame& frame, int left, int top, int delay);
  // Writes the trailer; the caller then commits `out`.
  void close();

  int frames() const { return frames_; }

 private:
  static int write(GifFileType* gif, const std::uint8_t* bytes, int length);
  [[noreturn]] void fail(const char* step, int error);
  io::OutputFile& out_;
  GifFileType* gif_ = nullptr;
  int width_, height_, frames_ = 0;
  std::exception_ptr writeError_;  // what the output threw inside giflib's callback
};

}  // namespace prime
