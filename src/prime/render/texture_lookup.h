// ReadMap (TextureMp module, lines 7289-7349) on an in-memory texture map.
// The listing opened map/Map<n>_R.map (or _G, _B) on every call, read the
// 4-byte MapHeader (uScale, vScale), then seeked to
//   sizeof(MapHeader) + sizeof(double) * (newU + uScale * newV)
// and read one double. Here the file's doubles are a span; no file I/O.
//
//   newU = (int)Roundoff(u * uScale)   truncation toward zero (K25, K24)
//   newV = (int)Roundoff(v * vScale)
//   if (newU < 0) newU = 0             only newU is clamped (K25)
//   index = newU + uScale * newV       u = 1 reads texel 0 of the next row
//
// index >= number of texels: fread fails and the original returned an
// uninitialised local; the 1991 profile returns 0.0 (E51) and flags it (X3).
// index < 0 (a negative newV): the byte offset is negative, so fseek fails
// and the file position stays just after the header: the read returns
// texel 0 (K25). Flagged separately (see docs/prime/port-notes/shading.md S7).
#pragma once
#include <cstdint>
#include <span>

namespace prime {

// One colour channel of a map: what one Map<n>_<c>.map file holds (a whole
// map, the three files _R, _G, _B of one map number, is a SceneTexture).
struct TextureChannelView {
  int uScale = 0;                  // MapHeader.uScale: texels per row
  int vScale = 0;                  // MapHeader.vScale: rows
  std::span<const double> texels;  // the file's doubles, index u + uScale*v
};

enum class TexelStatus {
  Ok,          // read the texel at `index`
  SeekFailed,  // index < 0: fseek failed, texel 0 was read (K25)
  ReadFailed,  // index past the end (or no texel at all): value 0.0 (E51)
};

struct TexelRead {
  double value = 0.0;
  TexelStatus status = TexelStatus::Ok;
  long long newU = 0;  // after the newU < 0 clamp
  long long newV = 0;
  long long index = 0;  // newU + uScale * newV, in texels
};

// ReadMap's arithmetic for one channel, with the outcome.
TexelRead readMapTexel1991(const TextureChannelView& map, double u, double v);

// X3 diagnostics, to be owned by the caller (e.g. one per render thread).
struct TextureReadCounters {
  std::uint64_t failedReads = 0;  // E51 events
  std::uint64_t failedSeeks = 0;  // K25 negative-offset events
};

// ReadMap(mapNum, lambda, u, v) for an already selected channel: the value
// only; counts failed reads/seeks into `counters` when given.
double readMap1991(const TextureChannelView& map, double u, double v,
                   TextureReadCounters* counters = nullptr);

}  // namespace prime
