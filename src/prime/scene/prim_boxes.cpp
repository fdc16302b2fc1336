#include "src/prime/scene/prim_boxes.h"

#include <cmath>

namespace prime {

std::array<Vec3, 8> primitiveCorners(const ScenePrim& p) {
  Vec3 lo{}, hi{};
  switch (p.type) {
    case io::PrimType::Sphere:
      lo = {-1, -1, -1};
      hi = {1, 1, 1};
      break;
    case io::PrimType::Cylinder:
    case io::PrimType::Cone:
      lo = {-1, -1, 0};
      hi = {1, 1, 1};
      break;
    case io::PrimType::Cube:
    case io::PrimType::Pyramid:
      lo = {0, 0, 0};
      hi = {1, 1, 1};
      break;
  }
  std::array<Vec3, 8> corners;
  for (int c = 0; c < 8; ++c)
    corners[static_cast<std::size_t>(c)] = pointMatrixMul(
        {c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]}, p.transform);
  return corners;
}

std::vector<Vec3> primitiveHullPoints(const ScenePrim& p) {
  // A regular n-gon about the z axis holds the circle of radius rho when its
  // vertices lie at rho / cos(pi / n); the hull of two such n-gons (turned
  // alike) holds every circle between them, as each is a mix of the two.
  constexpr int kSides = 16;
  constexpr double kPi = 3.14159265358979323846;
  const double around = 1.0 / std::cos(kPi / kSides);
  std::vector<Vec3> local;
  auto ring = [&](double rho, double z) {
    for (int j = 0; j < kSides; ++j) {
      const double phi = 2.0 * kPi * j / kSides;
      local.push_back({rho * around * std::cos(phi), rho * around * std::sin(phi), z});
    }
  };
  switch (p.type) {
    case io::PrimType::Sphere: {
      // The meridian circle in a regular octagon (vertices at 1 / cos(pi/8),
      // at 22.5 + 45 k degrees from the pole): its sweep about z is a stack
      // of frusta between the vertices' heights, closed by flat discs.
      constexpr int kMeridian = 8;
      const double out = 1.0 / std::cos(kPi / kMeridian);
      for (int k = 0; k < kMeridian / 2; ++k) {
        const double theta = (k + 0.5) * 2.0 * kPi / kMeridian;
        ring(out * std::sin(theta), out * std::cos(theta));
      }
      break;
    }
    case io::PrimType::Cylinder:
      ring(1.0, 0.0);
      ring(1.0, 1.0);
      break;
    case io::PrimType::Cone:  // x^2 + y^2 <= z^2, 0 <= z <= 1: the apex at 0
      local.push_back({0, 0, 0});
      ring(1.0, 1.0);
      break;
    case io::PrimType::Cube: {  // its own box
      const std::array<Vec3, 8> corners = primitiveCorners(p);
      return {corners.begin(), corners.end()};
    }
    case io::PrimType::Pyramid:  // the unit square at y = 0, the apex above its centre
      local = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 0, 1}, {0.5, 1, 0.5}};
      break;
  }
  std::vector<Vec3> world;
  world.reserve(local.size());
  for (const Vec3& q : local) world.push_back(pointMatrixMul(q, p.transform));
  return world;
}

Aabb primitiveBox(const ScenePrim& p) {
  Aabb box;
  for (const Vec3& corner : primitiveCorners(p)) box.add(corner);
  // Pad by a relative margin far above the rounding of any primitive test
  // (a few ulps of the coordinates) so that the box is conservative.
  double size = 0.0;
  for (int i = 0; i < 3; ++i)
    size = std::max({size, std::abs(box.lo[i]), std::abs(box.hi[i]), box.hi[i] - box.lo[i]});
  const double pad = 1e-7 * size + 1e-9;
  for (int i = 0; i < 3; ++i) {
    box.lo[i] -= pad;
    box.hi[i] += pad;
  }
  return box;
}

}  // namespace prime
