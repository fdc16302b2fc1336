// prime probe SCENE.cgl X Y: one primary ray through the screen point (X, Y)
// of a CGL scene (a pixel's integer corner, as the build without
// anti-aliasing traced it; fractions reach the sub-pixel corners of Figure
// 44), and everything it did: every ray it spawned, what each hit, the
// texture indices, each light's terms (Cook-Torrance: D, G, the
// Fresnel row and S, and the reflected and transmitted rays as lights) and why a light was skipped,
// the colour-vector, XYZ and the RGB ToRGB made of it.
#include <cstdio>
#include <iostream>

#include "src/cli/cgl/commands.h"
#include "src/cli/cgl/options.h"

namespace prime::cli::cgl {

namespace {

const char* rayName(RayKind k) {
  switch (k) {
    case RayKind::Primary:
      return "primary";
    case RayKind::Reflected:
      return "reflected";
    case RayKind::Transmitted:
      return "refracted";
    case RayKind::Shadow:
      return "shadow";
  }
  return "?";
}

void printSpectrum(const char* indent, const prime::cgl::Spectrum& c) {
  for (int i = 0; i < prime::cgl::kSpectrumSamples; ++i) {
    if (i % 11 == 0) std::printf("%s%3d nm:", indent, 380 + 10 * i);
    std::printf(" %.5g", c[static_cast<std::size_t>(i)]);
    if (i % 11 == 10 || i + 1 == prime::cgl::kSpectrumSamples) std::printf("\n");
  }
}

void printReport(const prime::cgl::ProbeReport& r, const prime::cgl::Scene& scene) {
  std::printf("screen point (%g, %g)\n", r.x, r.y);
  for (const auto& ray : r.rays) {
    std::string indent(static_cast<std::size_t>(2 * ray.level + 2), ' ');
    std::printf("%s%s ray, level %d: origin (%.6g, %.6g, %.6g) direction (%.6g, %.6g, %.6g)\n",
                indent.c_str(), rayName(ray.kind), ray.level, ray.origin[0], ray.origin[1],
                ray.origin[2], ray.direction[0], ray.direction[1], ray.direction[2]);
    if (!ray.hit) {
      std::printf("%s  hits nothing: the background\n", indent.c_str());
      continue;
    }
    std::printf(
        "%s  hits object %d (%s, scene node %d, surface %d) at t = %.9g, point (%.6g, %.6g, "
        "%.6g), normal facing the viewer (%.6g, %.6g, %.6g)\n",
        indent.c_str(), ray.object, prime::cgl::kindName(ray.objectKind), ray.node, ray.surface,
        ray.t, ray.point[0], ray.point[1], ray.point[2], ray.normal[0], ray.normal[1],
        ray.normal[2]);
    if (ray.facet >= 0)
      std::printf("%s  the fractal's facet %d (leaf order, section 5.6)\n", indent.c_str(),
                  ray.facet);
    if (ray.objectKind == prime::cgl::ObjectKind::Spline)
      std::printf(
          "%s  spline (u-bar, v-bar) = (%.9g, %.9g): Newton from the leaf's start (%.6g, "
          "%.6g), %d iteration(s)\n",
          indent.c_str(), ray.splineU, ray.splineV, ray.newtonU0, ray.newtonV0,
          ray.newtonIterations);
    if (ray.textured)
      std::printf("%s  texture u %.6f v %.6f: texel row %d, column %d\n", indent.c_str(), ray.u,
                  ray.v, ray.ui, ray.vi);
    if (ray.atDepthLimit)
      std::printf("%s  at the depth limit: reflected and refracted colours are the background\n",
                  indent.c_str());
    for (const auto& l : ray.lights) {
      if (l.light == prime::cgl::ProbeLight::kReflectedLight)
        std::printf("%s  reflected ray as a light (R, dw = k_r %.6g)", indent.c_str(), l.dw);
      else if (l.light == prime::cgl::ProbeLight::kTransmittedLight)
        std::printf("%s  transmitted ray as a light (T, dw = k_t %.6g)", indent.c_str(), l.dw);
      else
        std::printf("%s  light %d", indent.c_str(), l.light + 1);
      std::printf(": L (%.6g, %.6g, %.6g), N.L %.6g", l.l[0], l.l[1], l.l[2], l.nl);
      if (!l.skipped.empty()) {
        std::printf(", skipped: %s", l.skipped.c_str());
        if (l.shadowedBy >= 0)
          std::printf(" by object %d (scene node %d)", l.shadowedBy,
                      scene.objects[static_cast<std::size_t>(l.shadowedBy)].node);
        std::printf("\n");
      } else if (l.cook) {
        std::printf(
            ", Cook-Torrance: D %.6g, G %.6g, Fresnel row %d, S/F = DG/(pi(N.L)(N.V)) %.6g, "
            "diffuse k_d(N.L) %.6g, specular k_s(N.L)S/F %.6g\n",
            l.d, l.g, l.fresnel, l.s, l.diffuse, l.specular);
      } else {
        std::printf(", diffuse k_d(N.L) %.6g, specular k_s(P.V)^e %.6g\n", l.diffuse, l.specular);
      }
    }
    std::printf("%s  colour-vector returned:\n", indent.c_str());
    printSpectrum((indent + "    ").c_str(), ray.colour);
  }
  std::printf("colour-vector: \n");
  printSpectrum("  ", r.colour);
  std::printf("XYZ (1360 sum c x-bar ...): %.6g %.6g %.6g\n", r.xyz.x, r.xyz.y, r.xyz.z);
  std::printf("RGB (ToRGB: (1/15) M^-1 XYZ, clipped, truncated): %d %d %d%s\n", r.rgb.r, r.rgb.g,
              r.rgb.b, r.background ? " (the background: the primary ray hit nothing)" : "");
}

}  // namespace

void addProbeCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(kProbeCommand, "Trace one screen point of a CGL scene, verbosely");
  cmd->group("");  // reached through `prime probe FILE X Y` (src/cli/main.cpp)
  auto o = std::make_shared<CglOptions>();
  auto x = std::make_shared<double>(256.0);
  auto y = std::make_shared<double>(256.0);
  addCglOptions(cmd, *o);
  cmd->add_option("X", *x, "Screen x, 0..512 (a pixel's left edge; the package's pixel x)")
      ->required()
      ->check(CLI::Range(0.0, 512.0));
  cmd->add_option("Y", *y, "Screen y, 0..512 (0 the bottom scanline's lower edge)")
      ->required()
      ->check(CLI::Range(0.0, 512.0));
  cmd->callback([=, &action] {
    action = [=] {
      const prime::cgl::SceneFile file = readCgl(*o, false);
      const prime::cgl::Scene scene = buildCgl(*o, file);
      const prime::cgl::ProbeReport report =
          prime::cgl::probe(scene, renderSettings(*o, file), *x, *y);
      printReport(report, scene);
      return 0;
    };
  });
}

}  // namespace prime::cli::cgl
