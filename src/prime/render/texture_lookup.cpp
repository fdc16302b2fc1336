#include "src/prime/render/texture_lookup.h"

#include <cmath>

#include "src/prime/math/listing_math.h"

namespace prime {

namespace {

// `(int)x` for the already Roundoff'ed product: truncation toward zero.
// Values beyond +-2^40 are saturated there so that the C++ conversion is
// defined; every such value is already far outside any map (a map holds at
// most 32767 texels), so the in-range / past-the-end / negative outcome is
// the one the listing's arithmetic gives for it (shading.md S8). NaN cannot
// reach here: Roundoff(NaN) is 0.0 (K24).
long long truncToIndex(double x) {
  constexpr double kLimit = 1099511627776.0;  // 2^40
  if (x >= kLimit) return static_cast<long long>(kLimit);
  if (x <= -kLimit) return -static_cast<long long>(kLimit);
  return static_cast<long long>(x);  // truncation toward zero, as C's (int)
}

}  // namespace

TexelRead readMapTexel1991(const TextureChannelView& map, double u, double v) {
  TexelRead r;
  r.newU = truncToIndex(roundoff(u * static_cast<double>(map.uScale)));
  r.newV = truncToIndex(roundoff(v * static_cast<double>(map.vScale)));
  if (r.newU < 0) {
    r.newU = 0;
  }
  r.index = r.newU + static_cast<long long>(map.uScale) * r.newV;
  const auto count = static_cast<long long>(map.texels.size());
  if (r.index < 0) {
    // fseek(SEEK_SET) to a negative offset fails; the position is still
    // sizeof(MapHeader), i.e. at texel 0 (K25).
    if (count > 0) {
      r.value = map.texels[0];
      r.status = TexelStatus::SeekFailed;
    } else {
      r.value = 0.0;  // nothing after the header: fread fails too (E51)
      r.status = TexelStatus::ReadFailed;
    }
    return r;
  }
  if (r.index >= count) {
    r.value = 0.0;  // E51: failed read yields 0.0
    r.status = TexelStatus::ReadFailed;
    return r;
  }
  r.value = map.texels[static_cast<std::size_t>(r.index)];
  return r;
}

double readMap1991(const TextureChannelView& map, double u, double v,
                   TextureReadCounters* counters) {
  const TexelRead r = readMapTexel1991(map, u, v);
  if (counters != nullptr) {
    if (r.status == TexelStatus::ReadFailed) ++counters->failedReads;
    if (r.status == TexelStatus::SeekFailed) ++counters->failedSeeks;
  }
  return r.value;
}

}  // namespace prime
