#include "src/prime/plate1/plate1.h"

#include <cmath>

#include "legacy_io/common/text_reader.h"

namespace prime::spline {

KnotFile readKnotFile(const std::string& path, const std::string& display) {
  io::TextReader in = io::TextReader::open(path, display);
  const int rows = in.int16("rows");
  const int cols = in.int16("cols");
  if (rows < 4 || cols < 4 || rows > 256 || cols > 256)
    in.fail("rows cols", "4..256 control vertices each way",
            std::to_string(rows) + " x " + std::to_string(cols));
  BetaShape shape;
  shape.beta1 = in.number("beta1 (bias, skew)");
  shape.beta2 = in.number("beta2 (tension)");
  if (!(shape.beta1 > 0.0) || !(shape.beta2 >= 0.0))
    in.fail("beta1 beta2", "beta1 > 0 and beta2 >= 0",
            std::to_string(shape.beta1) + " " + std::to_string(shape.beta2));
  std::vector<Vec3> knots;
  knots.reserve(static_cast<std::size_t>(rows) * cols);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const std::string k = "knot " + std::to_string(r) + "," + std::to_string(c);
      Vec3 v{};
      v[X] = in.number(k + " x");
      v[Y] = in.number(k + " y");
      v[Z] = in.number(k + " z");
      knots.push_back(v);
    }
  if (!in.atEnd()) in.fail("end of file", "nothing after the last knot", "more text");
  return {shape, KnotGrid(rows, cols, std::move(knots))};
}

Projection::Projection(const CameraSettings& camera) : camera_(camera) {
  const auto& s = camera_.settings();
  for (int i = 0; i < 3; ++i) {
    stepAcross_[i] =
        (s.windowRight[i] - s.windowLeft[i]) / static_cast<double>(camera_.numPixAcross());
    stepDown_[i] =
        -s.windowLeft[i] / static_cast<double>(camera_.numPixDown());  // K23, as the camera steps
  }
}

bool Projection::project(const Vec3& p, double& x, double& y) const {
  // eye + t (p - eye) = windowLeft + a stepAcross + b stepDown, by Cramer's rule
  // on the columns d, -stepAcross, -stepDown.
  const auto& s = camera_.settings();
  const Vec3 d = p - s.eye;
  const Vec3 rhs = s.windowLeft - s.eye;
  const Vec3 ca = -stepAcross_, cb = -stepDown_;
  const double det = dot(d, cross(ca, cb));
  if (det == 0.0) return false;
  const double t = dot(rhs, cross(ca, cb)) / det;
  if (!(t > 0.0)) return false;  // the window plane is not between the eye and p's side
  const double a = dot(d, cross(rhs, cb)) / det;
  const double b = dot(d, cross(ca, rhs)) / det;
  x = camera_.screenX(0) + a;
  y = camera_.screenY(0) + b;
  return std::isfinite(x) && std::isfinite(y);
}

namespace {

// The surface at global parameters U in [0, patchCols], V in [0, patchRows].
Vec3 surfaceAt(const KnotFile& k, double U, double V) {
  const int pc = std::min(static_cast<int>(U), k.grid.patchCols() - 1);
  const int pr = std::min(static_cast<int>(V), k.grid.patchRows() - 1);
  return surfacePoint(k.shape, k.grid, pr, pc, U - pc, V - pr);
}

int nearest(double v) {
  return static_cast<int>(std::lround(v));
}

class Pen {
 public:
  Pen(Screen& screen, const Projection& proj, int& lines)
      : screen_(screen), proj_(proj), lines_(lines) {}
  // A polyline through the projected points; a point behind the eye breaks it.
  void polyline(const std::vector<Vec3>& pts, int colour) {
    bool have = false;
    int px = 0, py = 0;
    for (const Vec3& p : pts) {
      double x, y;
      if (!proj_.project(p, x, y) || std::fabs(x) > 1e6 || std::fabs(y) > 1e6) {
        have = false;
        continue;
      }
      const int ix = nearest(x), iy = nearest(y);
      if (have) {
        screen_.line(px, py, ix, iy, colour);
        ++lines_;
      }
      px = ix;
      py = iy;
      have = true;
    }
  }

 private:
  Screen& screen_;
  const Projection& proj_;
  int& lines_;
};

}  // namespace

Plate1Picture drawPlate1(const KnotFile& k, const WireframeOptions& o) {
  if (o.curvesPerPatch < 1 || o.segmentsPerPatch < 1)
    throw std::invalid_argument("curves and segments per patch must be at least 1");
  const Projection proj(o.camera);
  const ListingCamera& cam = proj.camera();
  Plate1Picture pic{Screen(o.camera.screenWidth, o.camera.screenHeight), {}, 0};
  Pen pen(pic.screen, proj, pic.lines);
  const int pr = k.grid.patchRows(), pc = k.grid.patchCols();

  if (o.net) {
    for (int r = 0; r < k.grid.rows(); ++r) {
      std::vector<Vec3> row;
      for (int c = 0; c < k.grid.cols(); ++c) row.push_back(k.grid.at(r, c));
      pen.polyline(row, o.netColour);
    }
    for (int c = 0; c < k.grid.cols(); ++c) {
      std::vector<Vec3> col;
      for (int r = 0; r < k.grid.rows(); ++r) col.push_back(k.grid.at(r, c));
      pen.polyline(col, o.netColour);
    }
  }
  // Curves of constant V, then of constant U; each over the whole surface.
  const int curvesV = pr * o.curvesPerPatch, curvesU = pc * o.curvesPerPatch;
  const int stepsU = pc * o.segmentsPerPatch, stepsV = pr * o.segmentsPerPatch;
  for (int m = 0; m <= curvesV; ++m) {
    const double V = static_cast<double>(m) / o.curvesPerPatch;
    std::vector<Vec3> pts;
    for (int s = 0; s <= stepsU; ++s)
      pts.push_back(surfaceAt(k, static_cast<double>(s) / o.segmentsPerPatch, V));
    pen.polyline(pts, o.uColour);
  }
  for (int m = 0; m <= curvesU; ++m) {
    const double U = static_cast<double>(m) / o.curvesPerPatch;
    std::vector<Vec3> pts;
    for (int s = 0; s <= stepsV; ++s)
      pts.push_back(surfaceAt(k, U, static_cast<double>(s) / o.segmentsPerPatch));
    pen.polyline(pts, o.vColour);
  }

  // The viewport as RayTrace.c writes graph_scr: graphType 1, the header's
  // numPixAcross/Down, and one more column and row than that (K21, K22).
  io::GraphFile& g = pic.graph;
  g.graphType = 1;
  g.numPixAcross = static_cast<std::int16_t>(cam.numPixAcross());
  g.numPixDown = static_cast<std::int16_t>(cam.numPixDown());
  g.inclusive = true;
  g.pixels.reserve(static_cast<std::size_t>(cam.columns()) * cam.rows());
  for (int i = 0; i < cam.rows(); ++i)
    for (int j = 0; j < cam.columns(); ++j)
      g.pixels.push_back(
          static_cast<std::int16_t>(pic.screen.getPixel(cam.screenX(j), cam.screenY(i))));
  return pic;
}

}  // namespace prime::spline
