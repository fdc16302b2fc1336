// The thesis profile's shading: Hall's model as the thesis writes it
// (sections 4.7-4.8, Table 4.1), with what the listing's coding (hall_1991.h)
// and the modern profile (hall_modern.h) do differently put as the thesis
// says (docs/prime/deviations.md, "The thesis renderer"):
//   - L points at the light and V at the viewer (K10, as N10): lit faces get
//     a positive diffuse reflection term, and the diffuse transmission term
//     takes the light from behind the surface (T4);
//   - every light term is multiplied by the light's visibility from the
//     shadow rays (thesis 2.3.2; T2, T3);
//   - the Fresnel factor is the Fresnel equation of 4.7.3 at the angle's
//     cosine, with the index of refraction derived from F(0) as the thesis
//     does, eta = (1 + sqrt F(0)) / (1 - sqrt F(0)); F(0) is the texel (T5,
//     T6); F_st = 1 - F_sr;
//   - one intensity factor per light term, I_j F(theta), not the listing's
//     FSR(iL) * iL (T7);
//   - the texel is the surface's colour: with `texelInDiffuse` it also
//     multiplies F_dr and F_dt (K11 corrected; T8);
//   - the transmitted term carries F_st(theta_t) at the ray's angle of
//     incidence and the transmissivity tT^sT (4.7.6); the reflected ray
//     travels in air, T_r = 1 (T9).
// The geometry is the caller's: `view` is the ray's unit direction
// (eye -> surface), `n` the unit normal facing the ray.
#pragma once
#include <array>
#include <span>

#include "src/prime/render/hall_1991.h"

namespace prime {

// One light as a shaded point sees it: the point on the light the shadow ray
// went to (the light's centre, or a sample of its disc), its intensity, and
// the fraction of it that reaches the point per channel (0 in shadow).
struct ThesisLight {
  Vec3 pt{};
  Rgb intensity{};
  Rgb visibility{1.0, 1.0, 1.0};
  // normalized(pt - point) when the caller has worked it out already (for
  // its shadow ray): the same bits, not computed again.
  Vec3 dir{};
  bool hasDir = false;
};

// eta from F(0), thesis 4.7.3: F(0) = ((eta - 1)/(eta + 1))^2. F(0) is
// clamped into [0, 1]; F(0) = 1 gives +Inf (a perfect mirror).
double etaFromF0(double f0);
// The Fresnel reflectance F(g, c) of thesis 4.7.3 for c = cos(theta) in
// [0, 1] (clamped), g^2 = eta^2 + c^2 - 1, with eta from F(0); the
// denominator's sign is Cook and Torrance's, [c(g - c) + 1]^2 (T6). 0 for
// F(0) = 0, 1 for F(0) = 1 and where g^2 < 0.
double fresnelThesis(double f0, double c);

std::array<HallTerms, 3> hallTermsThesis(const HallHue& hue, const Rgb& texel, const Rgb& iSR,
                                         const Rgb& iST, double sT, const Vec3& view, const Vec3& n,
                                         const Vec3& point, std::span<const ThesisLight> lights,
                                         const Rgb& ambient, bool texelInDiffuse);

}  // namespace prime
