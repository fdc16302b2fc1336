#include "legacy_io/prime/graph_file.h"

#include <algorithm>
#include <bit>
#include <optional>
#include <string_view>

#include "legacy_io/common/bytes.h"
#include "legacy_io/common/output_file.h"

namespace prime::io {

std::vector<std::uint8_t> toBytes(const GraphFile& f) {
  ByteWriter w;
  w.reserve(2 * (3 + f.pixels.size()));
  w.putInt16(f.graphType);
  w.putInt16(f.numPixAcross);
  w.putInt16(f.numPixDown);
  w.putInt16s(f.pixels);
  return w.take();
}

std::optional<std::string> pictureKindOf(std::span<const std::uint8_t> bytes) {
  const auto starts = [&](std::string_view magic) {
    return bytes.size() >= magic.size() &&
           std::equal(magic.begin(), magic.end(), bytes.begin(),
                      [](char m, std::uint8_t b) { return static_cast<std::uint8_t>(m) == b; });
  };
  if (starts("\x89PNG\r\n\x1a\n")) return "a PNG picture";
  if (starts("GIF87a") || starts("GIF89a")) return "a GIF picture";
  if (starts("\xFF\xD8\xFF")) return "a JPEG picture";
  if (starts("P6") || starts("P3")) return "a PPM picture";
  if (starts("BM")) return "a BMP picture";
  return std::nullopt;
}

namespace {

// A picture of another kind (a PNG given to `prime view`) is said to be one,
// not read as a graph file and called truncated: a graph file has no magic
// of its own, but its header (graphType, then two sizes below 8192) never
// begins with one of these signatures.
void refuseOtherPictures(std::span<const std::uint8_t> bytes, const std::string& name) {
  if (const auto kind = pictureKindOf(bytes))
    throw InputError({name, std::nullopt, 0}, "file",
                     "a PRIME graph file (graph_scr, or the .partial of an aborted trace: a "
                     "header of three Turbo C ints and a palette index per pixel)",
                     *kind);
}

}  // namespace

GraphFile graphFileFromBytes(std::span<const std::uint8_t> bytes, const std::string& name) {
  refuseOtherPictures(bytes, name);
  ByteReader r(bytes, name);
  GraphFile f;
  f.graphType = r.getInt16("graphType");
  f.numPixAcross = r.getInt16("numPixAcross");
  f.numPixDown = r.getInt16("numPixDown");
  if (f.numPixAcross < 0 || f.numPixDown < 0)
    throw InputError({name, std::nullopt, 2}, "numPixAcross/numPixDown", "non-negative sizes",
                     std::to_string(f.numPixAcross) + " x " + std::to_string(f.numPixDown));
  const std::size_t pixelBytes = r.remaining();
  const std::size_t inclusiveCount =
      static_cast<std::size_t>(f.numPixAcross + 1) * (f.numPixDown + 1);
  const std::size_t exactCount = static_cast<std::size_t>(f.numPixAcross) * f.numPixDown;
  if (pixelBytes == inclusiveCount * kTurboInt) {
    f.inclusive = true;
  } else if (pixelBytes == exactCount * kTurboInt) {
    f.inclusive = false;
  } else {
    throw InputError({name, std::nullopt, bytes.size()}, "pixel data",
                     std::to_string(inclusiveCount) + " pixels (" +
                         std::to_string(f.numPixAcross + 1) + " x " +
                         std::to_string(f.numPixDown + 1) + ", the listing's inclusive loops) or " +
                         std::to_string(exactCount) + " pixels",
                     std::to_string(pixelBytes) + " bytes (" + std::to_string(pixelBytes / 2) +
                         " pixels" + (pixelBytes % 2 ? " and an odd byte" : "") + ")");
  }
  f.pixels.reserve(pixelBytes / 2);
  while (r.remaining() > 0) f.pixels.push_back(r.getInt16("pixel"));
  return f;
}

GraphFile readGraphFile(const std::string& path) {
  return graphFileFromBytes(readFileBytes(path), path);
}

GraphFilePrefix graphFilePrefixFromBytes(std::span<const std::uint8_t> bytes,
                                         const std::string& name) {
  refuseOtherPictures(bytes, name);
  ByteReader r(bytes, name);
  GraphFile f;
  f.graphType = r.getInt16("graphType");
  f.numPixAcross = r.getInt16("numPixAcross");
  f.numPixDown = r.getInt16("numPixDown");
  const std::size_t present = r.remaining() / kTurboInt;
  const std::size_t inclusiveCount = f.numPixAcross < 0 || f.numPixDown < 0
                                         ? 0
                                         : static_cast<std::size_t>(f.numPixAcross + 1) *
                                               static_cast<std::size_t>(f.numPixDown + 1);
  if (f.numPixAcross < 0 || f.numPixDown < 0 || present >= inclusiveCount ||
      present ==
          static_cast<std::size_t>(f.numPixAcross) * static_cast<std::size_t>(f.numPixDown)) {
    GraphFile whole = graphFileFromBytes(bytes, name);  // complete, or the usual error
    const std::size_t n = whole.pixels.size();
    return {std::move(whole), n};
  }
  // A cut-short file is padded to the size its header claims: bound that
  // claim (a 6-byte file must not make us allocate gigabytes).
  constexpr std::size_t kMaxPartialPixels = std::size_t{8192} * 8192;
  if (inclusiveCount > kMaxPartialPixels)
    throw InputError({name, std::nullopt, 2}, "numPixAcross/numPixDown of a partial graph file",
                     "at most 8192 x 8192 pixels",
                     std::to_string(f.numPixAcross + 1) + " x " + std::to_string(f.numPixDown + 1));
  f.inclusive = true;
  f.pixels.reserve(inclusiveCount);
  for (std::size_t i = 0; i < present; ++i) f.pixels.push_back(r.getInt16("pixel"));
  f.pixels.resize(inclusiveCount, 0);
  return {std::move(f), present};
}

GraphFilePrefix readGraphFilePrefix(const std::string& path) {
  return graphFilePrefixFromBytes(readFileBytes(path), path);
}

void forEachGraphFileBytes(const GraphFile& f,
                           const std::function<void(std::span<const std::uint8_t>)>& piece) {
  ByteWriter header;
  header.putInt16(f.graphType);
  header.putInt16(f.numPixAcross);
  header.putInt16(f.numPixDown);
  piece(header.bytes());
  forEachPixelBytes(f.pixels, piece);
}

void forEachPixelBytes(std::span<const std::int16_t> pixels,
                       const std::function<void(std::span<const std::uint8_t>)>& piece) {
  if constexpr (std::endian::native == std::endian::little) {
    piece({reinterpret_cast<const std::uint8_t*>(pixels.data()), 2 * pixels.size()});
  } else {
    constexpr std::size_t kBlock = 1 << 15;
    for (std::size_t at = 0; at < pixels.size(); at += kBlock) {
      ByteWriter block;
      block.putInt16s(pixels.subspan(at, std::min(kBlock, pixels.size() - at)));
      piece(block.bytes());
    }
  }
}

void writeGraphFile(const std::string& path, const GraphFile& f) {
  OutputFile out(path);
  forEachGraphFileBytes(f, [&out](std::span<const std::uint8_t> bytes) { out.write(bytes); });
  out.commit();
}

}  // namespace prime::io
