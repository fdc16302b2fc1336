// Colour quantization (thesis 4.4.2-4.4.4): a true-colour picture mapped to
// at most 256 palette entries that a DAC of `dacBits` bits per channel can
// load (the IBM 8514/A's: 6), with or without dithering. Shared by every
// system; no system's quirks. docs/prime/quantization.md explains each choice
// (ids T50-T60 in docs/prime/deviations.md).
//
//   popularity   the most frequent colours of the picture (4.4.2, T51)
//   median-cut   Heckbert's boxes, split at the median of their longest side
//                (4.4.3, T52)
//   octree       Gervautz and Purgathofer's octree, built and reduced in one
//                pass over the pixels (4.4.4, T53)
//
// Every palette entry is a DAC level triple (0..2^dacBits-1), shown on an
// 8-bit display as round(v*255/max) (T50); pixels go to the entry whose shown
// colour is nearest in 8-bit sRGB, Euclidean (T54). Dithering (T55, T56) is
// deterministic: the same picture and settings give the same bytes.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "palette/png_image.h"

namespace prime::quantize {

enum class Method { Popularity, MedianCut, Octree };
enum class Dither { None, Ordered, FloydSteinberg };

std::string_view methodName(Method m);  // "popularity", "median-cut", "octree"
std::optional<Method> methodFromName(std::string_view name);
std::string_view ditherName(Dither d);  // "none", "ordered", "floyd-steinberg"
std::optional<Dither> ditherFromName(std::string_view name);

using Levels = std::array<std::uint8_t, 3>;  // one entry as the DAC holds it
using Colour8 = std::array<std::uint8_t, 3>;

struct Palette {
  int dacBits = 6;             // 1..8
  std::vector<Levels> levels;  // at most 256 entries

  int maxLevel() const { return (1 << dacBits) - 1; }
  // The 8-bit colour an entry shows as: round(v * 255 / maxLevel) (T50).
  Colour8 shown(std::size_t i) const;
  // The nearest level to an 8-bit value: round(v * maxLevel / 255).
  std::uint8_t levelOf(double v8) const;
};

struct Settings {
  Method method = Method::MedianCut;
  Dither dither = Dither::None;
  int colours = 256;  // 1..256
  int dacBits = 6;    // 1..8
};

struct Result {
  Palette palette;
  std::vector<std::uint8_t> indices;  // one per pixel, rows from the top
};

// The palette alone (std::invalid_argument for bad settings).
Palette choosePalette(const Image8& image, Method method, int colours, int dacBits);
// Each pixel's entry; `palette` must not be empty.
std::vector<std::uint8_t> mapToPalette(const Image8& image, const Palette& palette, Dither dither);
Result quantize(const Image8& image, const Settings& settings);
// The picture the indices make through the palette's shown colours.
Image8 present(const Result& r, int width, int height);

// Index of the entry whose shown colour is nearest to (r, g, b) in 8-bit RGB
// (squared Euclidean; ties to the lower index).
int nearestEntry(const Palette& palette, int r, int g, int b);

}  // namespace prime::quantize
