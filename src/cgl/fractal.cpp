#include "src/cgl/fractal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "src/cgl/pov_export.h"

namespace prime::cgl {

std::uint64_t FractalRandom::next() {
  // SplitMix64 (Steele, Lea and Flood, OOPSLA 2014; Vigna's reference code).
  state_ += 0x9e3779b97f4a7c15ULL;
  std::uint64_t z = state_;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double FractalRandom::uniform() {
  // The top 53 bits as a multiple of 2^-53 in [0, 1), then [-1, 1): exact.
  const double unit = static_cast<double>(next() >> 11) * 0x1.0p-53;
  return unit * 2.0 - 1.0;
}

double FractalRandom::gaussian() {
  // Marsaglia's polar method: (u, v) uniform in the unit disc (rejecting
  // s = 0 and s >= 1), then u f and v f with f = sqrt(-2 ln s / s) are two
  // independent unit Gaussians; the second is kept for the next call.
  if (haveSpare_) {
    haveSpare_ = false;
    return spare_;
  }
  double u = 0, v = 0, s = 0;
  do {
    u = uniform();
    v = uniform();
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double f = std::sqrt(-2.0 * portableLog(s) / s);
  spare_ = v * f;
  haveSpare_ = true;
  return u * f;
}

namespace {
constexpr double kLn2 = 0.6931471805599453094;  // the double nearest ln 2
}  // namespace

double portableLog(double x) {
  if (!(x > 0.0) || !std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
  // x = m 2^e with m in [sqrt(1/2), sqrt(2)); ln m = 2 atanh(z), z = (m - 1)/(m
  // + 1), |z| < 0.172, z^2 < 0.0295: 14 terms of z^(2k+1)/(2k+1) leave less
  // than 10^-22.
  int e = 0;
  double m = std::frexp(x, &e);  // exact: m in [0.5, 1)
  if (m < 0.70710678118654752440) {
    m *= 2.0;
    --e;
  }
  const double z = (m - 1.0) / (m + 1.0);
  const double z2 = z * z;
  double term = z, sum = 0.0;
  for (int k = 0; k < 14; ++k) {
    sum += term / static_cast<double>(2 * k + 1);
    term *= z2;
  }
  return static_cast<double>(e) * kLn2 + 2.0 * sum;
}

double portableExp2(double x) {
  if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
  if (x > 1023.0) return std::numeric_limits<double>::infinity();
  if (x < -1074.0) return 0.0;
  // 2^x = 2^k e^(f ln 2), k = floor(x), f in [0, 1): 22 Taylor terms of e^y,
  // y < 0.694, leave less than 10^-22.
  const double k = std::floor(x);
  const double y = (x - k) * kLn2;
  double term = 1.0, sum = 1.0;
  for (int n = 1; n <= 22; ++n) {
    term *= y / static_cast<double>(n);
    sum += term;
  }
  return std::ldexp(sum, static_cast<int>(k));  // exact
}

std::vector<double> fractalMatrix(std::int64_t seed, double offset) {
  std::vector<double> g(static_cast<std::size_t>(kFractalMatrixSize) * kFractalMatrixSize);
  FractalRandom random(seed);
  for (double& value : g) value = random.gaussian() + offset;
  return g;
}

int fractalIndex(double coordinate) {
  // CGL-Q122: x, z in [-1, 1] step 0.01 onto 0..200, the nearest index. The
  // midpoints' coordinates are dyadic fractions, so 100 (x + 1) is exact and
  // floor(. + 0.5) rounds halves up on every machine.
  const double i = std::floor(100.0 * (coordinate + 1.0) + 0.5);
  return std::clamp(static_cast<int>(i), 0, kFractalMatrixSize - 1);
}

namespace {

// As the scene's object boxes (src/cgl/scene.cpp): a little slack so that
// rounding in hitFacet cannot put a hit outside its leaf's box.
void padBox(Aabb& box) {
  for (int k = 0; k < 3; ++k) {
    const double slack = 1e-9 * (1.0 + std::max(std::fabs(box.lo[k]), std::fabs(box.hi[k])));
    box.lo[k] -= slack;
    box.hi[k] += slack;
  }
}

void solveXz(const Vec3& v0, const Vec3& e1, const Vec3& ne1, const Vec3& p, double& u, double& v) {
  const double det = e1[0] * ne1[2] - ne1[0] * e1[2];
  const double qx = p[0] - v0[0], qz = p[2] - v0[2];
  u = (qx * ne1[2] - ne1[0] * qz) / det;
  v = (e1[0] * qz - e1[2] * qx) / det;
}

class Builder {
 public:
  Builder(const FractalParams& p, const Matrix4& m, FractalSurface& out)
      : p_(p), m_(m), out_(out), g_(fractalMatrix(p.seed, p.offset)) {
    // CGL-Q123: the level l of s 2^(-h l) G is 1 for the midpoints of the
    // first subdivision, divisions for the last.
    factor_.resize(static_cast<std::size_t>(p.divisions) + 1);
    for (int l = 1; l <= p.divisions; ++l)
      factor_[static_cast<std::size_t>(l)] = p.scale * portableExp2(-p.h * l);
  }

  void build(std::size_t node, const Vec3& p0, const Vec3& p1, const Vec3& p2, bool e01, bool e12,
             bool e20, int level) {
    if (level == p_.divisions) {
      leaf(node, p0, p1, p2);
      return;
    }
    const int l = level + 1;
    const Vec3 m01 = midpoint(p0, p1, e01, l);
    const Vec3 m12 = midpoint(p1, p2, e12, l);
    const Vec3 m20 = midpoint(p2, p0, e20, l);
    // Section 5.2: "the current triangle is subdivided into four smaller
    // triangles by joining the midpoints of its sides"; each keeps the
    // parent's orientation (the centre one is the parent turned by 180
    // degrees and halved), and an edge lies on the perimeter when it is half
    // of a perimeter edge.
    const std::size_t c = 4 * node + 1;
    build(c, p0, m01, m20, e01, false, e20, l);
    build(c + 1, m01, p1, m12, e01, e12, false, l);
    build(c + 2, m20, m12, p2, false, e12, e20, l);
    build(c + 3, m01, m12, m20, false, false, false, l);
    // "ever larger bounding boxes are calculated to contain the bounding
    // boxes of the children"
    Aabb box;
    for (std::size_t k = 0; k < 4; ++k) box.add(out_.boxes[c + k]);
    out_.boxes[node] = box;
  }

 private:
  Vec3 midpoint(const Vec3& a, const Vec3& b, bool perimeter, int level) const {
    // (a + b)/2 is symmetric in a and b, so the two triangles that share an
    // edge make the same point; G depends on the point's x and z alone
    // ("external consistency").
    Vec3 m{(a[0] + b[0]) * 0.5, (a[1] + b[1]) * 0.5, (a[2] + b[2]) * 0.5};
    if (p_.constrained && perimeter) return m;  // section 5.1: the perimeter stays in the plane
    const std::size_t at = static_cast<std::size_t>(fractalIndex(m[0])) * kFractalMatrixSize +
                           static_cast<std::size_t>(fractalIndex(m[2]));
    m[1] += factor_[static_cast<std::size_t>(level)] * g_[at];
    return m;
  }

  void leaf(std::size_t node, const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    // "The current triangle corners are put through the transformation
    // matrix", then A, U, V with F(u, v) = A + uU + vV: corners A, A + U, A +
    // U + V.
    const Vec3 q0 = pointMatrixMul(p0, m_), q1 = pointMatrixMul(p1, m_),
               q2 = pointMatrixMul(p2, m_);
    FractalFacet& f = out_.facets[node - out_.firstLeaf];
    f.a = q0;
    f.u = q1 - q0;
    f.v = q2 - q1;
    Aabb box;
    for (const Vec3& q : {q0, q1, q2}) {
      box.add(q);
      if (out_.textureFrame) {
        double u = 0, v = 0;
        solveXz(out_.v0, out_.e1, out_.ne1, q, u, v);
        out_.umin = std::min(out_.umin, u);
        out_.umax = std::max(out_.umax, u);
        out_.vmin = std::min(out_.vmin, v);
        out_.vmax = std::max(out_.vmax, v);
      }
    }
    padBox(box);
    out_.boxes[node] = box;
  }

  const FractalParams& p_;
  const Matrix4& m_;
  FractalSurface& out_;
  std::vector<double> g_;
  std::vector<double> factor_;
};

struct Active {
  double distance;
  std::uint32_t node;
};

// The active list of the thread's current traversal (section 5.5), kept
// sorted with the nearest node at the back.
thread_local std::vector<Active> tlsActive;

}  // namespace

std::size_t FractalSurface::bytes() const {
  return sizeof(FractalSurface) + boxes.capacity() * sizeof(Aabb) +
         facets.capacity() * sizeof(FractalFacet);
}

FractalWork& FractalWork::operator+=(const FractalWork& o) {
  boxes += o.boxes;
  facets += o.facets;
  activeMax = std::max(activeMax, o.activeMax);
  activeGrowths += o.activeGrowths;
  return *this;
}

FractalSurface buildFractal(const FractalParams& params, const Matrix4& m) {
  if (params.divisions < 0 || params.divisions > 12)
    throw std::invalid_argument("fractal divisions " + std::to_string(params.divisions) +
                                " outside 0..12");
  FractalSurface f;
  f.divisions = params.divisions;
  const std::size_t leaves = std::size_t{1} << (2 * params.divisions);
  f.firstLeaf = (leaves - 1) / 3;
  f.boxes.resize(f.firstLeaf + leaves);
  f.facets.resize(leaves);
  // CGL-Q125: a sorted list longer than this is not met in the port's
  // scenes (FractalWork::activeMax); a longer one grows the buffer once.
  f.activeCapacity = 64 + 8 * (std::size_t{1} << params.divisions);

  // Section 5.3: the standard triangle through the transformation: V0, E1
  // and N_E1 as for a triangle (section 4.1), and the x and z equations'
  // determinant.
  const Vec3 s0{-1.0, 0.0, 1.0}, s1{1.0, 0.0, 1.0}, s2{0.0, 0.0, -1.0};
  f.v0 = pointMatrixMul(s0, m);
  const Vec3 e1 = pointMatrixMul(s1, m) - f.v0, e2 = pointMatrixMul(s2, m) - f.v0;
  const double ee = dot(e1, e1);
  f.e1 = e1;
  f.ne1 = ee > 0.0 ? e2 - e1 * (dot(e1, e2) / ee) : Vec3{};
  // CGL-Q126: "edge-on" within rounding (a rotation by 90 degrees leaves
  // cos 90 = 6e-17) counts as failing.
  const double det = f.e1[0] * f.ne1[2] - f.ne1[0] * f.e1[2];
  f.textureFrame = std::isfinite(det) && std::fabs(det) > 1e-12 * length(f.e1) * length(f.ne1);
  f.umin = f.vmin = std::numeric_limits<double>::infinity();
  f.umax = f.vmax = -std::numeric_limits<double>::infinity();

  Builder builder(params, m, f);
  builder.build(0, s0, s1, s2, true, true, true, 0);
  if (!f.textureFrame) f.umin = f.umax = f.vmin = f.vmax = 0.0;
  return f;
}

bool hitFacet(const FractalFacet& f, const Ray& ray, double tMin, double tMax, double& t) {
  // -t D + u U + v V = O - A by Cramer's rule, each determinant a triple
  // product: det = U.(D x V), u = (O - A).(D x V)/det, v = D.((O - A) x
  // U)/det, t = V.((O - A) x U)/det.
  const Vec3 p = cross(ray.d, f.v);
  const double det = dot(f.u, p);
  if (det == 0.0) return false;  // the ray runs in the facet's plane
  const double inv = 1.0 / det;
  const Vec3 s = ray.o - f.a;
  const double u = dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return false;
  const Vec3 q = cross(s, f.u);
  const double v = dot(ray.d, q) * inv;
  if (v < 0.0 || v > u) return false;
  const double ti = dot(f.v, q) * inv;
  if (ti <= tMin || !(ti < tMax)) return false;
  t = ti;
  return true;
}

bool hitFractal(const FractalSurface& f, const BoxRay& br, double tMin, double tMax, double& t,
                int& facet, FractalWork& work) {
  if (f.boxes.empty()) return false;
  ++work.boxes;
  const double rootEntry = f.boxes[0].entry(br);
  if (!(rootEntry < tMax)) return false;
  std::vector<Active>& list = tlsActive;
  if (list.capacity() < f.activeCapacity) list.reserve(f.activeCapacity);  // once per thread
  list.clear();
  list.push_back({rootEntry, 0});
  double best = tMax;
  int bestFacet = -1;
  while (!list.empty()) {
    const Active top = list.back();
    // "success when the distance to the fractal surface ... is less than the
    // distance to the first (closest) node on the active node list"; no node
    // left can then hold a nearer hit.
    if (!(top.distance < best)) break;
    list.pop_back();
    if (top.node >= f.firstLeaf) {
      ++work.facets;
      const std::size_t k = top.node - f.firstLeaf;
      double th = 0;
      if (hitFacet(f.facets[k], br.ray, tMin, best, th)) {
        best = th;
        bestFacet = static_cast<int>(k);
      }
      continue;
    }
    const std::size_t c = 4 * static_cast<std::size_t>(top.node) + 1;
    for (std::size_t k = 0; k < 4; ++k) {
      ++work.boxes;
      const double d = f.boxes[c + k].entry(br);
      if (!(d < best)) continue;  // missed, or behind the best hit
      if (list.size() == list.capacity()) ++work.activeGrowths;
      list.push_back({d, static_cast<std::uint32_t>(c + k)});
      // Sorted in: decreasing distance towards the back.
      std::size_t i = list.size() - 1;
      while (i > 0 && list[i - 1].distance < d) {
        list[i] = list[i - 1];
        --i;
      }
      list[i] = {d, static_cast<std::uint32_t>(c + k)};
    }
    work.activeMax = std::max<std::uint64_t>(work.activeMax, list.size());
  }
  if (bestFacet < 0) return false;
  t = best;
  facet = bestFacet;
  return true;
}

bool hitFractalBruteForce(const FractalSurface& f, const Ray& ray, double tMin, double tMax,
                          double& t, int& facet) {
  double best = tMax;
  int bestFacet = -1;
  for (std::size_t k = 0; k < f.facets.size(); ++k) {
    double th = 0;
    if (hitFacet(f.facets[k], ray, tMin, best, th)) {
      best = th;
      bestFacet = static_cast<int>(k);
    }
  }
  if (bestFacet < 0) return false;
  t = best;
  facet = bestFacet;
  return true;
}

Vec3 facetNormal(const FractalSurface& f, int facet) {
  const FractalFacet& ff = f.facets[static_cast<std::size_t>(facet)];
  return normalized(cross(ff.u, ff.v));
}

void fractalTextureUv(const Vec3& v0, const Vec3& e1, const Vec3& ne1, double umin, double umax,
                      double vmin, double vmax, const Vec3& point, double& u, double& v) {
  double uu = 0, vv = 0;
  solveXz(v0, e1, ne1, point, uu, vv);
  u = (uu - umin) / (umax - umin);
  v = (vv - vmin) / (vmax - vmin);
}

void fractalUvMap(const Vec3& v0, const Vec3& e1, const Vec3& ne1, double umin, double umax,
                  double vmin, double vmax, Vec3& au, double& bu, Vec3& av, double& bv) {
  // u' = ((Px - V0x) N_E1z - N_E1x (Pz - V0z))/det, v' = (E1x (Pz - V0z) -
  // E1z (Px - V0x))/det, then u = (u' - umin)/(umax - umin), likewise v.
  const double det = e1[0] * ne1[2] - ne1[0] * e1[2];
  const double du = (umax - umin) * det, dv = (vmax - vmin) * det;
  au = Vec3{ne1[2], 0.0, -ne1[0]} * (1.0 / du);
  bu = (ne1[0] * v0[2] - v0[0] * ne1[2]) / du - umin / (umax - umin);
  av = Vec3{-e1[2], 0.0, e1[0]} * (1.0 / dv);
  bv = (e1[2] * v0[0] - e1[0] * v0[2]) / dv - vmin / (vmax - vmin);
}

std::string povFractalMesh(const FractalSurface& f) {
  // mesh2 with three vertices per facet and no sharing: POV-Ray 3.7 parses
  // `mesh { triangle { ... } }` with a vertex search that takes 165 s for
  // 10 divisions, this in 5 s.
  const std::size_t n = f.facets.size();
  std::string s = "mesh2 {\n  vertex_vectors { " + std::to_string(3 * n);
  s.reserve(n * 200);
  for (const FractalFacet& ff : f.facets) {
    const Vec3 b = ff.a + ff.u;
    s += ",\n    " + povVector(ff.a) + ", " + povVector(b) + ", " + povVector(b + ff.v);
  }
  s += "\n  }\n  face_indices { " + std::to_string(n);
  for (std::size_t k = 0; k < n; ++k)
    s += ",\n    <" + std::to_string(3 * k) + ", " + std::to_string(3 * k + 1) + ", " +
         std::to_string(3 * k + 2) + ">";
  return s + "\n  }\n}";
}

}  // namespace prime::cgl
