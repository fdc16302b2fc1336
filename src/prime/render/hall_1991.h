// The Hall shading model exactly as the 1991 listing codes it (Hall module,
// lines 3967-4218): ProcessWavelength, FSR, FST, Hj, Hj_, ProcessColor.
// Pure functions: the listing's globals (light[], numLights, IA) are passed in.
//
// Conventions of the caller (CastRay, lines 6850-6866), kept as they are:
//   pt  surface point in world space (surfPt)
//   v   the incident ray direction, unit, eye -> surface (ray->xD, E41)
//   n   the unit world normal (nearestNorm * transform, K4)
//   r   the reflected ray's unit direction (reflectedRay->xD)
//   t   the transmitted ray's direction; UNUSED (its only use is commented
//       out in the listing, E17)
//   surfColor  the texel of the map per channel (ReadMap), K11
//   iSR, iST   the colours returned by the reflected / transmitted CastRays
//   sT  distance travelled inside the object by the transmitted ray (E45)
// K10: l = pt - light (light -> surface), so on lit front faces the diffuse
// reflection term is NEGATIVE and pow() gets negative bases.
// Floating-point domain errors give IEEE NaN/Inf (X2, Q11).
#pragma once
#include <array>
#include <span>

#include "src/math/rgb.h"
#include "src/math/vec.h"

namespace prime {

// Hue.h (the object's shading coefficients), lines 2380-2392.
struct HallHue {
  double kDR = 0.0;   // diffuse reflectance coefficient (kSR = 1 - kDR)
  double kDT = 0.0;   // diffuse transmission coefficient (kST = 1 - kDT)
  Rgb fDR{};          // diffuse reflectance curve per channel (fDT = 1 - fDR)
  double tT = 0.0;    // transmissivity per unit length (K14)
  double kRH = 0.0;   // specular reflection highlight exponent
  double kTH = 0.0;   // specular transmission highlight exponent
  double indx = 0.0;  // refractive index (K13: 1.0 divides by zero)
};

// Lights (Light.h), lines 2396-2403: a point light; intensity per channel.
struct HallLight {
  Vec3 pt{};
  Rgb intensity{};
};

// Geometry at the hit (see the conventions above).
struct HallGeometry {
  Vec3 pt{};
  Vec3 v{};
  Vec3 n{};
  Vec3 r{};
  Vec3 t{};
  // --fix K10: l is light - pt (towards the light) instead of pt - light;
  // the caller passes v towards the eye too.
  bool towardsLight = false;
};

// FSR(surfColor, iL, ang), lines 4078-4114 (K12): with f0 = surfColor and
// f90 = 0, tmp = (Cos(ang)*f0 - f0) / (0 - f0); tmp = 0 when f0 == 0;
// f = iL*f0 if tmp < 0, else iL*(f0 + (1 - f0)*tmp). `ang` in degrees.
double fsr1991(double surfColor, double iL, double ang);
// FST = 1 - FSR (can be negative), lines 4116-4127.
double fst1991(double surfColor, double iL, double ang);
// Hj(l, v): (l + v) / |l + v|, then UnitVector (E18: loop to W).
Vec3 hj1991(const Vec3& l, const Vec3& v);
// Hj_(l, v, indx): (v + indx*l) / (indx - 1), then UnitVector (E18, K13).
Vec3 hjPrime1991(const Vec3& l, const Vec3& v, double indx);

// The six terms of Hall's sum as ProcessWavelength returns it (4065-4071),
// kept apart so `prime probe` can show each; sum() adds them in the listing's
// left-to-right order, so it is bit-identical to the printed expression.
struct HallTerms {
  double specularReflection = 0;    // kSR * sum(Ij * FSR * (N.Hj)^kRH)
  double specularTransmission = 0;  // kST * sum(Ij * FST * (N.Hj')^kTH)
  double diffuseReflection = 0;     // kDR * fDR * (IA + sum(Ij * N.L))   (K10: N.L < 0 when lit)
  double diffuseTransmission = 0;   // kDT * fDT * (IA + sum(Ij * -N.L))
  double reflected = 0;             // kSR * iSR * FSR(surf, IA, acos(N.R))
  double transmitted = 0;           // kST * iST * FST(surf, IA, 0) * tT^sT
  double sum() const {
    return specularReflection + specularTransmission + diffuseReflection + diffuseTransmission +
           reflected + transmitted;
  }
};

// Terms whose coefficient is exactly 0 (kSR = 1 - kDR = 0, kST = 1 - kDT = 0,
// or for the reflected and transmitted terms a returned colour of 0 in every
// channel) may be set to 0 without computing their transcendental factors,
// but only where those factors are provably finite: 0 * x is 0 for finite x
// and NaN for NaN or infinite x, and a NaN must still reach the pixel as in
// the listing. The sign of such a zero term may differ (0 * -x is -0); no
// output can show it (every later use of a colour is a sum, a product or a
// comparison). Off = the listing's arithmetic, every term computed.
struct HallShortcut {
  bool zeroSpecularReflection = false;    // kSR == 0
  bool zeroSpecularTransmission = false;  // kST == 0
  bool zeroReflected = false;             // kSR == 0 or iSR == 0 in every channel
  bool zeroTransmitted = false;           // kST == 0 or iST == 0 in every channel
};

// The channel-independent part of ProcessWavelength for one hit: per light,
// Cos(ACos(N.Hj)) and Cos(ACos(N.Hj')) as FSR/FST see them, (N.Hj)^kRH,
// (N.Hj')^kTH and N.L; the reflected ray's Cos(ACos(N.R)); tT^sT. Identical
// values to computing them per channel, as the listing did.
struct HallPrepared {
  struct Light {
    double cosHj = 0, cosHj_ = 0, powHj = 0, powHj_ = 0, vD = 0;
  };
  std::array<Light, 10> light{};  // Global.c: Light light[10]
  int count = 0;
  double cosReflected = 0, cosZero = 1, transmissivity = 1;  // transmissivity = pow(tT, sT)
  // Set by a HallShortcut: the term is exactly 0 and its factors were not computed.
  bool zeroSpecularReflection = false, zeroSpecularTransmission = false;
  bool zeroReflected = false, zeroTransmitted = false;
};

// `shortcut` asks for zero terms (see HallShortcut); the caller must also
// have checked HallSkipping and hallHitInputsBounded.
HallPrepared prepareHall1991(const HallGeometry& geom, std::span<const HallLight> lights,
                             double indx, double kRH, double kTH, double tT, double sT,
                             HallShortcut shortcut = {});
HallTerms hallTermsPrepared1991(int lambda, double surfColor, double kDR, double kDT, double iSR,
                                double iST, double fDR, const HallPrepared& prepared,
                                std::span<const HallLight> lights, const Rgb& ambient);
// Whether the HallShortcut may be used. Decided once per scene: on only when
// every light intensity and ambient value is finite and at most 1e100 in
// magnitude; each hit then checks its own colours the same way
// (hallHitInputsBounded). With all of them bounded no product or sum of
// Hall's terms can overflow, and a term is finite exactly when its cosines
// and powers are. Default: off, the listing's arithmetic.
class HallSkipping {
 public:
  HallSkipping() = default;
  static HallSkipping forScene(std::span<const HallLight> lights, const Rgb& ambient);
  bool on() const { return on_; }

 private:
  bool on_ = false;
};
bool hallHitInputsBounded(const Rgb& surfColor, const Rgb& iSR, const Rgb& iST);
// FSR with the angle's cosine already taken (FSR computes Cos(ang) first).
double fsrFromCos1991(double surfColor, double iL, double cosAng);

HallTerms hallTerms1991(int lambda, double surfColor, double kDR, double kDT, double iSR,
                        double iST, double fDR, double tT, double sT, double kRH, double kTH,
                        double indx, const HallGeometry& geom, std::span<const HallLight> lights,
                        const Rgb& ambient);

// ProcessWavelength, lines 4000-4076, as repaired by E16 (vD is a double)
// and E17/Q8 (the last term is kST*iST*FST(surfColor, IA, 0.0)*pow(tT, sT)).
// `lambda` selects the channel of the lights' intensities and of IA.
double processWavelength1991(int lambda, double surfColor, double kDR, double kDT, double iSR,
                             double iST, double fDR, double tT, double sT, double kRH, double kTH,
                             double indx, const HallGeometry& geom,
                             std::span<const HallLight> lights, const Rgb& ambient);

// ProcessColor, lines 4178-4210: the three channels; values >= 1.0 become
// 0.999999; negatives and NaN are NOT clamped (K15).
// `skipping`: the HallShortcut for the hue's zero coefficients and black
// returned colours (same pixels; see HallShortcut and HallSkipping).
// `clampNegative` (--fix K15): negatives become 0 as well.
Rgb processColor1991(const HallHue& hue, const Rgb& surfColor, const Rgb& iSR, const Rgb& iST,
                     double sT, const HallGeometry& geom, std::span<const HallLight> lights,
                     const Rgb& ambient, HallSkipping skipping = {}, bool clampNegative = false);

// The terms of all three channels (before ProcessColor's clamp).
std::array<HallTerms, 3> hallTermsRgb1991(const HallHue& hue, const Rgb& surfColor, const Rgb& iSR,
                                          const Rgb& iST, double sT, const HallGeometry& geom,
                                          std::span<const HallLight> lights, const Rgb& ambient,
                                          HallSkipping skipping = {});

}  // namespace prime
