#include "src/geom/camera_path.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace prime {

namespace {

// Points a segment is measured at: the length is the polyline through them
// (64 a segment: well within a pixel of the true length for any path a
// viewer would call smooth, and the same on every machine).
constexpr int kSamples = 64;
// Frames a segment lasts when the path says nothing of its length.
constexpr int kFramesPerSegment = 60;

Vec3 hermite(const Vec3& p0, const Vec3& m0, const Vec3& p1, const Vec3& m1, double u) {
  const double u2 = u * u, u3 = u2 * u;
  const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2,
               h11 = u3 - u2;
  Vec3 r;
  for (int c = 0; c < 3; ++c) r[c] = h00 * p0[c] + h10 * m0[c] + h01 * p1[c] + h11 * m1[c];
  return r;
}
double hermite(double p0, double m0, double p1, double m1, double u) {
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * m0 + (-2 * u3 + 3 * u2) * p1 +
         (u3 - u2) * m1;
}
double distance(const Vec3& a, const Vec3& b) {
  const double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
  return std::sqrt(x * x + y * y + z * z);
}
std::string number(double v) {
  std::string s = std::to_string(v);
  while (s.size() > 1 && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

}  // namespace

int CameraPath::segments() const {
  const int n = static_cast<int>(spec_.keys.size());
  return spec_.loop ? (n > 1 ? n : 0) : n - 1;
}

CameraKey CameraPath::at(int segment, double u) const {
  const int n = static_cast<int>(spec_.keys.size());
  // Key i of the spline, with the loop's wrap or the open ends' phantoms.
  auto key = [&](int i) -> CameraKey {
    if (spec_.loop) return spec_.keys[static_cast<std::size_t>(((i % n) + n) % n)];
    if (i >= 0 && i < n) return spec_.keys[static_cast<std::size_t>(i)];
    // 2 P(end) - P(inside): the one-sided tangent at an open end.
    const CameraKey& e = spec_.keys[static_cast<std::size_t>(i < 0 ? 0 : n - 1)];
    const CameraKey& in = spec_.keys[static_cast<std::size_t>(i < 0 ? 1 : n - 2)];
    CameraKey p;
    for (int c = 0; c < 3; ++c) {
      p.eye[c] = 2 * e.eye[c] - in.eye[c];
      p.lookAt[c] = 2 * e.lookAt[c] - in.lookAt[c];
      p.up[c] = 2 * e.up[c] - in.up[c];
    }
    p.fovY = 2 * e.fovY - in.fovY;
    return p;
  };
  const CameraKey k0 = key(segment - 1), k1 = key(segment), k2 = key(segment + 1),
                  k3 = key(segment + 2);
  // At its ends a segment is its keys, exactly (not through the cubic's
  // terms: 0 x a tangent that overflowed would be NaN).
  if (u == 0.0) return k1;
  if (u == 1.0) return k2;
  auto tangent = [](const Vec3& before, const Vec3& after) {
    return Vec3{(after[0] - before[0]) / 2, (after[1] - before[1]) / 2, (after[2] - before[2]) / 2};
  };
  CameraKey r;
  r.eye = hermite(k1.eye, tangent(k0.eye, k2.eye), k2.eye, tangent(k1.eye, k3.eye), u);
  r.lookAt = hermite(k1.lookAt, tangent(k0.lookAt, k2.lookAt), k2.lookAt,
                     tangent(k1.lookAt, k3.lookAt), u);
  r.up = hermite(k1.up, tangent(k0.up, k2.up), k2.up, tangent(k1.up, k3.up), u);
  r.fovY = hermite(k1.fovY, (k2.fovY - k0.fovY) / 2, k2.fovY, (k3.fovY - k1.fovY) / 2, u);
  return r;
}

CameraPath::CameraPath(CameraPathSpec spec) : spec_(std::move(spec)) {
  const int n = static_cast<int>(spec_.keys.size());
  if (n == 0) throw std::invalid_argument("a camera path needs at least one key");
  const int segs = segments();
  // The length from key 0, kSamples points a segment.
  table_.assign(static_cast<std::size_t>(segs) * kSamples + 1, 0.0);
  for (int s = 0; s < segs; ++s) {
    CameraKey prev = at(s, 0.0);
    for (int i = 1; i <= kSamples; ++i) {
      const CameraKey cur = at(s, static_cast<double>(i) / kSamples);
      const std::size_t j = static_cast<std::size_t>(s) * kSamples + static_cast<std::size_t>(i);
      table_[j] =
          table_[j - 1] + (distance(prev.eye, cur.eye) + distance(prev.lookAt, cur.lookAt)) / 2;
      prev = cur;
    }
  }
  // How many frames.
  const std::optional<double> lastFrame = spec_.keys.back().frame;
  if (spec_.frames)
    frames_ = *spec_.frames;
  else if (!spec_.loop && lastFrame) {
    // The last key's frame, checked before it is made an int (the fuzzer's
    // key at frame 1e79 was undefined behaviour here).
    const double last = std::floor(*lastFrame) + 1;
    if (!(last >= 1 && last <= std::numeric_limits<int>::max()))
      throw std::invalid_argument(
          "a camera path lasts 1 .. " + std::to_string(std::numeric_limits<int>::max()) +
          " frames (its last key is at frame " + std::to_string(*lastFrame) + ")");
    frames_ = static_cast<int>(last);
  } else
    frames_ = segs == 0 ? 1 : segs * kFramesPerSegment + (spec_.loop ? 0 : 1);
  if (frames_ < 1)
    throw std::invalid_argument("a camera path lasts at least one frame (frames " +
                                std::to_string(frames_) + ")");
  // Each point's frame: the given ones, then the rest by length between them.
  // Points are the keys and, for a loop, its closing point (key 0 again).
  const int points = segs + 1;
  std::vector<std::optional<double>> given(static_cast<std::size_t>(points));
  for (int i = 0; i < n && i < points; ++i)
    given[static_cast<std::size_t>(i)] = spec_.keys[static_cast<std::size_t>(i)].frame;
  const double end = spec_.loop ? frames_ : frames_ - 1;
  if (!given.front()) given.front() = 0.0;
  if (points > 1 && !given.back()) given.back() = end;
  for (int i = 0; i < points; ++i) {
    if (!given[static_cast<std::size_t>(i)]) continue;
    const double f = *given[static_cast<std::size_t>(i)];
    if (f < 0 || f > end)
      throw CameraKeyError(i, "key " + std::to_string(i + 1) + " is at frame " + number(f) +
                                  ", outside the path's frames 0 .. " + number(end));
  }
  keyFrames_.assign(static_cast<std::size_t>(points), 0.0);
  int anchor = 0;
  for (int i = 1; i < points; ++i) {
    if (!given[static_cast<std::size_t>(i)]) continue;
    const double fa = *given[static_cast<std::size_t>(anchor)],
                 fb = *given[static_cast<std::size_t>(i)];
    if (!(fb > fa))
      throw CameraKeyError(i, "key " + std::to_string(i + 1) + " is at frame " + number(fb) +
                                  ", not after key " + std::to_string(anchor + 1) + "'s frame " +
                                  number(fa) + ": key frames must increase");
    const double la = table_[static_cast<std::size_t>(anchor) * kSamples],
                 lb = table_[static_cast<std::size_t>(i) * kSamples];
    for (int j = anchor; j <= i; ++j) {
      const double lj = table_[static_cast<std::size_t>(j) * kSamples];
      const double share =
          lb > la ? (lj - la) / (lb - la) : static_cast<double>(j - anchor) / (i - anchor);
      keyFrames_[static_cast<std::size_t>(j)] = fa + share * (fb - fa);
    }
    anchor = i;
  }
  if (points == 1) keyFrames_[0] = *given[0];
}

FreeCameraSettings CameraPath::camera(int k, int width, int height) const {
  const double f = std::clamp(static_cast<double>(k), 0.0, static_cast<double>(frames_ - 1));
  CameraKey c;
  const int segs = segments();
  if (segs == 0 || f <= keyFrames_.front()) {
    c = segs == 0 ? spec_.keys.front() : at(0, 0.0);
  } else if (f >= keyFrames_.back()) {
    c = at(segs - 1, 1.0);
  } else {
    // The segment whose frames hold f, then the point of it at the length
    // that frame has reached.
    int s = 0;
    while (s + 1 < segs && f >= keyFrames_[static_cast<std::size_t>(s) + 1]) ++s;
    const double f0 = keyFrames_[static_cast<std::size_t>(s)],
                 f1 = keyFrames_[static_cast<std::size_t>(s) + 1];
    const double share = (f - f0) / (f1 - f0);
    const std::size_t base = static_cast<std::size_t>(s) * kSamples;
    const double l0 = table_[base], l1 = table_[base + kSamples];
    double u = share;
    if (l1 > l0) {
      const double want = l0 + share * (l1 - l0);
      int i = 0;
      while (i + 1 < kSamples && table_[base + static_cast<std::size_t>(i) + 1] < want) ++i;
      const double a = table_[base + static_cast<std::size_t>(i)],
                   b = table_[base + static_cast<std::size_t>(i) + 1];
      u = (i + (b > a ? (want - a) / (b - a) : 0.0)) / kSamples;
    }
    c = at(s, u);
  }
  FreeCameraSettings out;
  out.eye = c.eye;
  out.lookAt = c.lookAt;
  out.up = c.up;
  out.fovY = c.fovY;
  out.width = width;
  out.height = height;
  return out;
}

}  // namespace prime
