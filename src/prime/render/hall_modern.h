// The modern profile's shading: Hall's model with the errors of the 1991
// coding (hall_1991.h) put right (docs/prime/deviations.md, "Modern profile"):
//   - the light vector l points AT the light (K10), so lit front faces get a
//     positive diffuse term and pow() never sees a negative base (X2);
//   - cosines are clamped to [0, 1] (or [-1, 1] for the reflected term's FSR);
//   - the transmission highlight uses H' = (V + indx L) / (indx - 1), skipped
//     for indx = 1 (K13);
//   - a sum that is not finite gives 0 and is counted; the others are
//     clamped into [0, 0.999999] for ColorNum.
// The geometry is the caller's: `view` is the ray's unit direction
// (eye -> surface), `n` the unit normal facing the ray, `refl` the reflected
// ray's unit direction.
#pragma once
#include <array>
#include <cstdint>
#include <span>

#include "src/prime/render/hall_1991.h"

namespace prime {

// The six terms of Hall's sum per channel (the same split as the 1991 one's,
// so `prime probe` shows both alike); sum() adds them in the same order.
std::array<HallTerms, 3> hallTermsModern(const HallHue& hue, const Rgb& surfColor, const Rgb& iSR,
                                         const Rgb& iST, double sT, const Vec3& point,
                                         const Vec3& view, const Vec3& n, const Vec3& refl,
                                         std::span<const HallLight> lights, const Rgb& ambient);

// The colour of the terms: each channel's sum clamped into [0, 0.999999];
// a NaN or infinite sum gives 0 and adds one to `nonFinite`.
Rgb hallColourModern(const std::array<HallTerms, 3>& terms, std::uint64_t& nonFinite);

}  // namespace prime
