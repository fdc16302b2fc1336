// Render (src/cgl/render.h; Sweeney 1985 sections 8.2 and 8.6, Figures 41
// and 44): the corner table traces every distinct corner once and gives the
// pixels of a plain recursive Subdivid over one global table; the picture
// does not depend on the thread count; and the document's checkerboard
// (scenes/cgl/checkerboard.cgl, Figure 59) comes out as the text describes
// it: the floor seen from above, the ball left of centre, the light from
// the upper left.
#include "src/cgl/render.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <utility>

#include "tests/cgl/unit/scene_text.h"

namespace prime::cgl {
namespace {

const std::string kScenes = CGL_SCENES;

struct Loaded {
  SceneFile file;
  Scene scene;
};

Loaded checkerboard() {
  Loaded l;
  l.file = readSceneFile(kScenes + "/checkerboard.cgl");
  l.scene = buildScene(l.file);
  return l;
}

RenderSettings settingsOf(const SceneFile& f, int threads = 1) {
  RenderSettings s;
  s.program = f.program;
  s.threads = threads;
  return s;
}

// Figure 44 as printed (with CGL-E41), over one table for the whole screen
// keyed by the corner in eighths of a pixel.
class ReferenceSubdivid {
 public:
  ReferenceSubdivid(const Tracer& tracer, double threshold)
      : tracer_(tracer), threshold_(threshold) {}
  Rgb8 pixel(int x, int y, int aalevel) {
    return sub(8 * x, 8 * (y + 1), 8 * (x + 1), 8 * y, aalevel);
  }
  std::size_t corners() const { return table_.size(); }

 private:
  Rgb8 corner(int x8, int y8) {
    const auto key = std::make_pair(x8, y8);
    auto it = table_.find(key);
    if (it == table_.end())
      it = table_.emplace(key, tracer_.screenPoint(x8 / 8.0, y8 / 8.0, stats_)).first;
    return it->second;
  }
  Rgb8 sub(int xl, int yu, int xr, int yl, int level) {
    Rgb8 ul = corner(xl, yu), ur = corner(xr, yu), ll = corner(xl, yl), lr = corner(xr, yl);
    level /= 2;
    const int spread = std::max({ul.r, ur.r, ll.r, lr.r}) - std::min({ul.r, ur.r, ll.r, lr.r}) +
                       std::max({ul.g, ur.g, ll.g, lr.g}) - std::min({ul.g, ur.g, ll.g, lr.g}) +
                       std::max({ul.b, ur.b, ll.b, lr.b}) - std::min({ul.b, ur.b, ll.b, lr.b});
    if (level > 0 && spread > threshold_) {
      const int xm = (xl + xr) / 2, ym = (yu + yl) / 2;
      ul = sub(xl, yu, xm, ym, level);
      ur = sub(xm, yu, xr, ym, level);
      ll = sub(xl, ym, xm, yl, level);
      lr = sub(xm, ym, xr, yl, level);
    }
    return Rgb8{(ul.r + ur.r + ll.r + lr.r) / 4, (ul.g + ur.g + ll.g + lr.g) / 4,
                (ul.b + ur.b + ll.b + lr.b) / 4};
  }
  const Tracer& tracer_;
  double threshold_;
  TraceStats stats_;
  std::map<std::pair<int, int>, Rgb8> table_;
};

TEST(CglRender, CornerTableTracesEachDistinctCornerOnce) {
  // A 50 x 40 window over the ball's left edge and the floor's checks.
  const Loaded l = checkerboard();
  RenderSettings s = settingsOf(l.file);
  s.program.xleft = 170;
  s.program.xright = 219;
  s.program.ylow = 200;
  s.program.yhigh = 239;
  s.recordCorners = true;
  const Tracer tracer(l.scene, traceSettings(s));
  std::uint64_t previous = 0;
  for (int level : {1, 2, 4, 8}) {
    s.program.aalevel = level;
    const RenderResult r = render(l.scene, s);
    const std::set<std::pair<int, int>> distinct(r.corners.begin(), r.corners.end());
    EXPECT_EQ(distinct.size(), r.corners.size())
        << "aalevel " << level << ": a corner traced twice";
    EXPECT_EQ(r.stats.rays.primaryRays, r.corners.size()) << "aalevel " << level;
    if (level == 1)
      EXPECT_EQ(r.stats.rays.primaryRays, 51u * 41u);  // (50 + 1) x (40 + 1)
    else
      EXPECT_GT(r.stats.rays.primaryRays, previous) << "aalevel " << level;
    previous = r.stats.rays.primaryRays;
    // The same pixels, and the same corners, as one global table.
    ReferenceSubdivid ref(tracer, s.program.aathreshold);
    int differing = 0;
    for (int y = s.program.yhigh; y >= s.program.ylow; --y)
      for (int x = s.program.xleft; x <= s.program.xright; ++x) {
        const Rgb8 c = ref.pixel(x, y, level);
        if (r.frame.at(y, x) != packPixel(c.r, c.g, c.b)) ++differing;
      }
    EXPECT_EQ(differing, 0) << "aalevel " << level;
    EXPECT_EQ(ref.corners(), r.corners.size()) << "aalevel " << level;
    // Outside the window: black.
    EXPECT_EQ(r.frame.at(250, 100), 0u);
  }
  // aalevel 0 (CGL-Q1): one ray per pixel, at its corner (x, y).
  s.program.aalevel = 0;
  const RenderResult plain = render(l.scene, s);
  EXPECT_EQ(plain.stats.rays.primaryRays, 50u * 40u);
  TraceStats stats;
  const Rgb8 c = tracer.screenPoint(190, 220, stats);
  EXPECT_EQ(plain.frame.at(220, 190), packPixel(c.r, c.g, c.b));
}

TEST(CglRender, SameBytesForAnyThreadCount) {
  const Loaded l = checkerboard();
  const RenderResult one = render(l.scene, settingsOf(l.file, 1));
  const RenderResult two = render(l.scene, settingsOf(l.file, 2));
  const RenderResult three = render(l.scene, settingsOf(l.file, 3));
  EXPECT_TRUE(one.frame.words == two.frame.words);
  EXPECT_TRUE(one.frame.words == three.frame.words);
  EXPECT_TRUE(one.image.empty());  // no window: no 6 MiB of doubles
  // A strip not continuing the thread's previous one is traced afresh, so
  // more threads may trace a shared edge twice: never fewer rays.
  EXPECT_GE(two.stats.rays.primaryRays, one.stats.rays.primaryRays);
  // One thread: 450 x 286 pixels (xleft 31..480, ylow 0..yhigh 286) have at
  // least (450 + 1) x (287 + 1) corners.
  EXPECT_GE(one.stats.rays.primaryRays, 451u * 288u);
}

// Pixel helpers for the checkerboard picture.
int brightness(const Frame& f, int x, int y) {
  const std::uint32_t w = f.at(y, x);
  return redOf(w) + greenOf(w) + blueOf(w);
}

TEST(CglRender, CheckerboardAsTheDocumentDescribesIt) {
  const Loaded l = checkerboard();
  const RenderSettings s = settingsOf(l.file, 0);
  const auto start = std::chrono::steady_clock::now();
  const RenderResult r = render(l.scene, s);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("render_seconds", std::to_string(seconds));

  // The window: xleft 31, xright 480, yhigh 286; the rest black.
  EXPECT_EQ(r.frame.at(300, 256), 0u);
  EXPECT_EQ(r.frame.at(100, 20), 0u);
  EXPECT_EQ(r.frame.at(100, 490), 0u);

  // The ball (world x = +0.3) appears left of centre: its centre projects to
  // x = 256 + 2.5 (-0.3/3.5) 256 = 201.1, y = 256 + 2.5 (-0.18/3.5) 256 =
  // 223.1 (screen-right is world -x); the mirror-image place right of centre
  // is background (the floor's far edge, y' = -0.367 at z' = -1.227, projects
  // to y = 256 - 2.5 (0.367/4.727) 256 = 206).
  ProbeReport ball = probe(l.scene, s, 201, 223);
  ASSERT_TRUE(ball.rays.at(0).hit);
  EXPECT_EQ(ball.rays[0].objectKind, ObjectKind::Sphere);
  ProbeReport other = probe(l.scene, s, 311, 223);
  EXPECT_FALSE(other.rays.at(0).hit);
  EXPECT_TRUE(other.background);

  // The floor is seen from above: at the bottom centre the floor's normal,
  // turned to face the viewer, points up (+y), and it is textured.
  ProbeReport floor = probe(l.scene, s, 256, 60);
  ASSERT_TRUE(floor.rays.at(0).hit);
  EXPECT_EQ(floor.rays[0].objectKind, ObjectKind::Polygon);
  EXPECT_GT(floor.rays[0].normal[1], 0.9);  // (0, cos 22, sin 22) = (0, 0.927, 0.375)
  EXPECT_TRUE(floor.rays[0].textured);

  // The light (0.6, 1, 0.6) is "to the upper left and behind the observer":
  // the ball's shadow falls to its lower right. The centre pushed along -L
  // meets the floor at s = 0.5496: (-0.030, -0.730, -0.330), on the screen
  // x = 256 + 2.5 (0.030/3.830) 256 = 261, y = 256 - 2.5 (0.730/3.830) 256 =
  // 134. There the light is shadowed by the ball; at the mirror place left
  // of the ball's centre (x = 141) it is not.
  ProbeReport shadow = probe(l.scene, s, 261, 134);
  ASSERT_EQ(shadow.rays.at(0).lights.size(), 1u);
  EXPECT_EQ(shadow.rays[0].lights[0].skipped, "shadowed");
  EXPECT_EQ(l.scene.objects[static_cast<std::size_t>(shadow.rays[0].lights[0].shadowedBy)].kind,
            ObjectKind::Sphere);
  ProbeReport lit = probe(l.scene, s, 141, 134);
  EXPECT_EQ(lit.rays.at(0).lights.at(0).skipped, "");
  // ... and the same in the picture: the shadowed floor is darker than the
  // lit floor of the same check colour nearby. The Phong highlight (the
  // brightest ball pixel) is up and to the left of the ball's centre.
  int best = -1, bx = 0, by = 0;
  for (int y = 195; y <= 252; ++y)
    for (int x = 172; x <= 230; ++x) {
      const double dx = x - 201.1, dy = y - 223.1;
      if (dx * dx + dy * dy > 27.0 * 27.0) continue;
      const int b = brightness(r.frame, x, y);
      if (b > best) {
        best = b;
        bx = x;
        by = y;
      }
    }
  EXPECT_LT(bx, 201) << "highlight at " << bx << ", " << by;
  EXPECT_GT(by, 223) << "highlight at " << bx << ", " << by;
  // Brighter than the ball's lower right, which mirrors the dark floor.
  EXPECT_GT(best, brightness(r.frame, 215, 209) + 100);

  // Secondary rays: depth 3 with a perfect reflector.
  EXPECT_GT(r.stats.rays.reflectedRays, 0u);
  EXPECT_GT(r.stats.rays.shadowRays, 0u);
  EXPECT_EQ(r.stats.rays.transmittedRays, 0u);
}

TEST(CglRender, SelfIntersectionNeedsASmallEpsilon) {
  // CGL-Q44, measured: with the document's rule alone (reject t <= 0) the
  // floor's shadow rays and the ball's reflected rays meet their own surface
  // at t of about 1e-16 and speckle the picture ("acne"): tens of thousands
  // of the window's 129,150 pixels change (52,733 at aalevel 0). Any epsilon
  // from 1e-9 to 1e-4 gives the same picture.
  const Loaded l = checkerboard();
  RenderSettings s = settingsOf(l.file, 0);
  s.program.aalevel = 0;
  const RenderResult chosen = render(l.scene, s);
  s.epsilon = 0.0;
  const RenderResult document = render(l.scene, s);
  s.epsilon = 1e-4;
  const RenderResult larger = render(l.scene, s);
  int acne = 0, moved = 0;
  for (std::size_t i = 0; i < chosen.frame.words.size(); ++i) {
    acne += chosen.frame.words[i] != document.frame.words[i];
    moved += chosen.frame.words[i] != larger.frame.words[i];
  }
  EXPECT_GT(acne, 20000);
  EXPECT_EQ(moved, 0);
}

TEST(CglRender, RefusesABadWindowOrLevel) {
  const Loaded l = checkerboard();
  RenderSettings s = settingsOf(l.file);
  s.program.aalevel = 3;
  EXPECT_THROW(render(l.scene, s), io::InputError);
  s.program.aalevel = 2;
  s.program.xleft = 300;
  s.program.xright = 200;
  EXPECT_THROW(render(l.scene, s), io::InputError);
}

// With a window (a rowDone callback) the picture is also kept as doubles,
// each row handed over as it finishes: the same pixels as the frame.
TEST(CglRender, TheWindowsRowsAreTheFramesPixels) {
  const Loaded l = checkerboard();
  RenderCallbacks cb;
  int rowsSeen = 0;
  cb.rowDone = [&](int, std::span<const Rgb>) { ++rowsSeen; };
  const RenderResult r = render(l.scene, settingsOf(l.file, 2), cb);
  EXPECT_EQ(rowsSeen, l.file.program.yhigh - l.file.program.ylow + 1);
  const RgbImage fromFrame = toRgbImage(r.frame);
  ASSERT_EQ(r.image.pixels.size(), fromFrame.pixels.size());
  EXPECT_TRUE(r.image.pixels == fromFrame.pixels);
}

}  // namespace
}  // namespace prime::cgl
