// The Hall shading model as the listing codes it (lines 3967-4218; E16, E17,
// E18, K10-K15, Q8). The three ProcessWavelength cases below are worked by
// hand; every step is written out. Notation: I = the light's intensity in
// this channel, s = surfColor, c = cos of the angle FSR receives.
//
// Two facts used throughout:
//  * FSR with f0 = s != 0 and f90 = 0: tmp = (c*s - s)/(0 - s) = 1 - c, so
//    FSR = I*(s + (1 - s)*(1 - c)) (tmp < 0 would need c > 1). K12.
//  * ACos/Cos go through degrees with Radient = 57.29578 and back, which
//    returns c to within ~1e-16, far inside the 1e-12 tolerance.
#include "src/prime/render/hall_1991.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "src/prime/math/listing_vec.h"

namespace prime {
namespace {

constexpr double kTol = 1e-12;

double pw(int lambda, double s, const HallHue& h, double iSR, double iST, double sT,
          const HallGeometry& g, const std::vector<HallLight>& lights, const Rgb& ia) {
  const auto k = static_cast<std::size_t>(lambda);
  return processWavelength1991(lambda, s, h.kDR, h.kDT, iSR, iST, h.fDR[k], h.tT, sT, h.kRH, h.kTH,
                               h.indx, g, lights, ia);
}

// ----------------------------------------------------------- building blocks

TEST(HallFsr, ZeroSurfaceColourGivesZeroAndFstOne) {
  // K12: f90 - f0 == 0 -> tmp = 0 -> f = I*(0 + 1*0) = 0.
  EXPECT_EQ(fsr1991(0.0, 5.0, 30.0), 0.0);
  EXPECT_EQ(fst1991(0.0, 5.0, 30.0), 1.0);
}

TEST(HallFsr, AngleZeroAndNinetyAndSixty) {
  // ang 0: c = 1, tmp = (s - s)/(-s) = -0.0 (not < 0) -> f = I*s.
  EXPECT_DOUBLE_EQ(fsr1991(0.4, 0.5, 0.0), 0.2);
  EXPECT_DOUBLE_EQ(fst1991(0.4, 0.5, 0.0), 0.8);
  // ang 60: Cos(60) = cos(60/57.29578) = 0.5000000077071 (Radient, K3):
  // f = 1*(0.5 + 0.5*(1 - 0.5000000077071)) = 0.7499999961464.
  EXPECT_NEAR(fsr1991(0.5, 1.0, 60.0), 0.7499999961464396, kTol);
  // s = 1: f = I*(1 + 0*tmp) = I whatever the angle.
  EXPECT_DOUBLE_EQ(fsr1991(1.0, 0.7, 45.0), 0.7);
  // FST can be negative: ang 180 -> c = -1, tmp = 2, FSR = 1*(0.5 + 1) = 1.5.
  EXPECT_NEAR(fst1991(0.5, 1.0, 180.0), -0.5, kTol);
}

TEST(HallHj, HalfwayVectors) {
  // Hj: l = (0,0,1), v = (0.6,0,0.8): (0.6,0,1.8)/|.| = (1,0,3)/sqrt(10).
  const Vec3 h = hj1991({0, 0, 1}, {0.6, 0, 0.8});
  EXPECT_NEAR(h[0], 1.0 / std::sqrt(10.0), kTol);
  EXPECT_NEAR(h[1], 0.0, kTol);
  EXPECT_NEAR(h[2], 3.0 / std::sqrt(10.0), kTol);
  // Hj_: (v + indx*l)/(indx - 1). l = v = (0,0,1), indx 3: (0,0,4)/2 -> (0,0,1).
  const Vec3 t = hjPrime1991({0, 0, 1}, {0, 0, 1}, 3.0);
  EXPECT_DOUBLE_EQ(t[2], 1.0);
  // indx 0.5: (0,0,1.5)/(-0.5) = (0,0,-3) -> (0,0,-1): the direction flips.
  EXPECT_DOUBLE_EQ(hjPrime1991({0, 0, 1}, {0, 0, 1}, 0.5)[2], -1.0);
  // K13: indx 1 divides by zero: (0,0,2)/0 = inf, then inf/inf = NaN.
  EXPECT_TRUE(std::isnan(hjPrime1991({0, 0, 1}, {0, 0, 1}, 1.0)[2]));
}

// ------------------------------------------------------- case 1: one light

// Eye looks along +z (v = (0,0,1)) at pt = 0 on a face with n = (0,0,-1);
// one light straight in front at (0,0,-10).
HallGeometry headOn() {
  HallGeometry g;
  g.pt = {0, 0, 0};
  g.v = {0, 0, 1};
  g.n = {0, 0, -1};
  g.r = {0, 0, -1};  // v - 2(v.n)n
  g.t = {0, 0, 1};   // unused
  return g;
}

TEST(HallProcessWavelength, CaseOneLightHeadOn) {
  // hue: kDR .5 (kSR .5), kDT 1 (kST 0), fDR .8 (fDT .2), kRH = kTH = 1,
  // indx 2, tT .9. s = .5, IA = .2, iSR = iST = 0, sT = 0.
  // l = pt - light = (0,0,10) -> (0,0,1)            (K10: light -> surface)
  // hj = (l+v)/|l+v| = (0,0,2)/2 = (0,0,1); dotHj = n.hj = -1
  // hj_ = (v + 2l)/(2-1) = (0,0,3) -> (0,0,1); dotHj_ = -1
  // vD = n.l = -1
  // lambda 0, I = 1:
  //   FSR(.5,1,ACos(-1)): c = -1, tmp = 2, f = .5 + .5*2 = 1.5
  //   a = 1 * 1.5 * pow(-1,1) = -1.5
  //   b = 1 * (1 - 1.5) * pow(-1,1) = 0.5
  //   c = 1 * -1 = -1; d = +1
  //   kSR*a = -.75; kST*b = 0; kDR*fDR*(IA+c) = .4*(-.8) = -.32;
  //   kDT*fDT*(IA+d) = .2*1.2 = .24; kSR*iSR*FSR(..) = 0;
  //   kST*iST*FST(..)*pow(.9,0) = 0
  //   total = -.75 - .32 + .24 = -0.83      (K10: the lit face is NEGATIVE)
  const HallHue hue{0.5, 1.0, {0.8, 0.8, 0.8}, 0.9, 1.0, 1.0, 2.0};
  const std::vector<HallLight> lights = {{{0, 0, -10}, {1.0, 0.5, 0.25}}};
  const Rgb ia = {0.2, 0.2, 0.2};
  EXPECT_NEAR(pw(0, 0.5, hue, 0, 0, 0, headOn(), lights, ia), -0.83, kTol);
  // lambda 1, I = .5: FSR = .5*1.5 = .75, a = .5*.75*(-1) = -.375;
  //   c = -.5, d = .5: -.1875 + .4*(.2-.5) + .2*(.2+.5) = -.1875 - .12 + .14
  //   = -0.1675
  EXPECT_NEAR(pw(1, 0.5, hue, 0, 0, 0, headOn(), lights, ia), -0.1675, kTol);
  // lambda 2, I = .25: FSR = .375, a = -.09375; c = -.25, d = .25:
  //   -.046875 + .4*(-.05) + .2*(.45) = -.046875 - .02 + .09 = 0.023125
  EXPECT_NEAR(pw(2, 0.5, hue, 0, 0, 0, headOn(), lights, ia), 0.023125, kTol);
  // ProcessColor: the same three values; negatives are not clamped (K15).
  const Rgb col =
      processColor1991(hue, {0.5, 0.5, 0.5}, {0, 0, 0}, {0, 0, 0}, 0.0, headOn(), lights, ia);
  EXPECT_NEAR(col[0], -0.83, kTol);
  EXPECT_NEAR(col[1], -0.1675, kTol);
  EXPECT_NEAR(col[2], 0.023125, kTol);
}

// ------------------------------------------------------ case 2: two lights

TEST(HallProcessWavelength, CaseTwoLights) {
  // Geometry as case 1. hue: kDR .25 (kSR .75), kDT .5 (kST .5), fDR .6
  // (fDT .4), kRH = kTH = 2, indx 3. s = .5, IA = .1, iSR = iST = 0.
  // Light A at (0,0,-10), I = 1; light B at (-6,0,-8), I = .5.
  //
  // A: l = (0,0,1); hj = (0,0,1), dotHj = -1, pow(-1,2) = 1;
  //    FSR = 1*(.5 + .5*2) = 1.5 -> a_A = 1.5
  //    hj_ = (v+3l)/2 = (0,0,2) -> (0,0,1), dotHj_ = -1, pow = 1;
  //    FST = 1 - 1.5 = -.5 -> b_A = -.5;  c_A = -1, d_A = 1
  // B: l = (6,0,8)/10 = (.6,0,.8)
  //    l+v = (.6,0,1.8) -> hj = (1,0,3)/sqrt10, dotHj = -3/sqrt10
  //      = -0.9486832980505; pow(dotHj,2) = .9
  //    FSR(.5,.5,.) = .5*(.5 + .5*(1 + .9486832980505)) = 0.7371708245126
  //    a_B = .5 * 0.7371708245126 * .9 = 0.3317268710307
  //    v+3l = (1.8,0,3.4), /2 = (.9,0,1.7) -> dotHj_ = -1.7/sqrt3.7
  //      = -0.8837879163471; pow(dotHj_,2) = 2.89/3.7 = 0.7810810810811
  //    FST = 1 - .5*(.5 + .5*(1 + .8837879163471)) = 0.2790530209132
  //    b_B = .5 * 0.2790530209132 * 0.7810810810811 = 0.1089815176269
  //    vD = n.l = -.8: c_B = -.4, d_B = .4
  // a = 1.8317268710307, b = -0.3910184823731, c = -1.4, d = 1.4
  // total = .75a + .5b + .25*.6*(.1 - 1.4) + .5*.4*(.1 + 1.4)
  //       = 1.3737951532730 - 0.1955092411865 - .195 + .3 = 1.2832859120865
  const HallHue hue{0.25, 0.5, {0.6, 0.6, 0.6}, 0.9, 2.0, 2.0, 3.0};
  const std::vector<HallLight> lights = {{{0, 0, -10}, {1.0, 0, 0}}, {{-6, 0, -8}, {0.5, 0, 0}}};
  const Rgb ia = {0.1, 0.1, 0.1};
  EXPECT_NEAR(pw(0, 0.5, hue, 0, 0, 0, headOn(), lights, ia), 1.2832859120865, 1e-11);
  // ProcessColor clamps the >= 1 value (K15).
  const Rgb col =
      processColor1991(hue, {0.5, 0.5, 0.5}, {0, 0, 0}, {0, 0, 0}, 0.0, headOn(), lights, ia);
  EXPECT_EQ(col[0], 0.999999);
}

// ------------------------------------- case 3: reflection and transmission

TEST(HallProcessWavelength, CaseReflectionAndTransmission) {
  // pt = (1,2,3), light at (1,2,-2): l = (0,0,5) -> (0,0,1). Oblique eye ray
  // v = (.6,0,.8); n = (0,0,-1); r = v - 2(v.n)n = (.6,0,-.8), n.r = .8.
  // hue: kDR .2 (kSR .8), kDT .3 (kST .7), fDR .5 (fDT .5), tT .9, kRH 3,
  // kTH 1, indx 1.5. s = .4, I = .8, IA = .1, iSR = .6, iST = .3, sT = 2.
  //
  // hj = (.6,0,1.8)/|.| = (1,0,3)/sqrt10, dotHj = -0.9486832980505
  //   pow(dotHj,3) = -27/(10 sqrt10) = -0.8538149682455
  //   FSR(.4,.8,.) = .8*(.4 + .6*1.9486832980505) = 1.2553679830642
  //   a = .8 * 1.2553679830642 * -0.8538149682455 = -0.8574815796771
  // hj_ = (v + 1.5l)/.5 = (1.2,0,4.6) -> dotHj_ = -4.6/sqrt22.6
  //   = -0.9676172723968; pow(.,1) = itself
  //   FST = 1 - .8*(.4 + .6*1.9676172723968) = -0.2644562907505
  //   b = .8 * -0.2644562907505 * -0.9676172723968 = 0.2047139797793
  // vD = -1: c = -.8, d = .8
  // kSR*a = -0.6859852637417;  kST*b = 0.1433 (0.1432997858455)
  // kDR*fDR*(IA+c) = .1*(-.7) = -.07;  kDT*fDT*(IA+d) = .15*.9 = .135
  // reflection: kSR*iSR*FSR(.4,.1,ACos(.8)) = .48 * .1*(.4 + .6*.2)
  //   = .48 * .052 = .02496
  // transmission (E17): kST*iST*FST(.4,.1,0)*pow(.9,2)
  //   = .21 * (1 - .04) * .81 = .163296
  // total = -0.6859852637417 + 0.1432997858455 - .07 + .135 + .02496
  //       + .163296 = -0.2894294778962
  HallGeometry g;
  g.pt = {1, 2, 3};
  g.v = {0.6, 0, 0.8};
  g.n = {0, 0, -1};
  g.r = {0.6, 0, -0.8};
  g.t = {0, 0, 1};
  const HallHue hue{0.2, 0.3, {0.5, 0.5, 0.5}, 0.9, 3.0, 1.0, 1.5};
  const std::vector<HallLight> lights = {{{1, 2, -2}, {0.8, 0.8, 0.8}}};
  const Rgb ia = {0.1, 0.1, 0.1};
  EXPECT_NEAR(pw(0, 0.4, hue, 0.6, 0.3, 2.0, g, lights, ia), -0.2894294778962, 1e-11);
  // Only the two ray terms change with iSR/iST: with both 0 the total drops
  // by .02496 + .163296 = .188256 -> -0.4776854778962.
  EXPECT_NEAR(pw(0, 0.4, hue, 0.0, 0.0, 2.0, g, lights, ia), -0.4776854778962, 1e-11);
  // K14: pow(tT, sT) uses the path length: sT = 0 -> factor 1 instead of
  // .81: the transmission term is .21*.96 = .2016, i.e. +.038304.
  EXPECT_NEAR(pw(0, 0.4, hue, 0.6, 0.3, 0.0, g, lights, ia), -0.2894294778962 + 0.038304, 1e-11);
}

// ------------------------------------------------------ ambient only, clamp

TEST(HallProcessWavelength, NoLightsLeavesAmbientAndRayTerms) {
  // kDR .5 (kSR .5), kDT .25 (kST .75), fDR .8 (fDT .2), IA .4, a=b=c=d=0.
  // Diffuse: .5*.8*(.4+0) = .16 and .25*.2*(.4+0) = .02. s = 0, so FSR = 0
  // and FST = 1 (K12): reflection .5*.9*0 = 0; transmission
  // .75*.2*1*pow(1,5) = .15. Total .16 + .02 + .15 = .33.
  const HallHue hue{0.5, 0.25, {0.8, 0.8, 0.8}, 1.0, 1.0, 1.0, 2.0};
  const Rgb ia = {0.4, 0.4, 0.4};
  EXPECT_NEAR(pw(0, 0.0, hue, 0.9, 0.2, 5.0, headOn(), {}, ia), 0.33, kTol);
}

TEST(HallProcessColor, ClampsOnlyAtOrAboveOne) {
  // No lights, kDR = kDT = 1 (kSR = kST = 0), fDR 1 (fDT 0): each channel is
  // exactly kDR*fDR*IA = IA.
  const HallHue hue{1.0, 1.0, {1.0, 1.0, 1.0}, 0.9, 1.0, 1.0, 2.0};
  const std::vector<HallLight> none;
  Rgb col = processColor1991(hue, {0.5, 0.5, 0.5}, {0, 0, 0}, {0, 0, 0}, 1.0, headOn(), none,
                             {1.0, 0.999999999, -2.0});
  EXPECT_EQ(col[0], 0.999999);     // exactly 1.0 is clamped
  EXPECT_EQ(col[1], 0.999999999);  // below 1.0: kept
  EXPECT_EQ(col[2], -2.0);         // negative: kept (K15)
  const double nan = std::numeric_limits<double>::quiet_NaN();
  col = processColor1991(hue, {0.5, 0.5, 0.5}, {0, 0, 0}, {0, 0, 0}, 1.0, headOn(), none,
                         {1.5, nan, 0.0});
  EXPECT_EQ(col[0], 0.999999);
  EXPECT_TRUE(std::isnan(col[1]));  // NaN >= 1.0 is false: not clamped
  EXPECT_EQ(col[2], 0.0);
}

TEST(HallProcessWavelength, DomainErrorsGiveNaN) {
  // K10/X2: pow(-1, 1.5) = NaN for the head-on light.
  const HallHue hue{0.5, 1.0, {0.8, 0.8, 0.8}, 0.9, 1.5, 1.0, 2.0};
  const std::vector<HallLight> lights = {{{0, 0, -10}, {1.0, 1.0, 1.0}}};
  EXPECT_TRUE(std::isnan(pw(0, 0.5, hue, 0, 0, 0, headOn(), lights, {0.2, 0.2, 0.2})));
  // K13: indx 1 -> Hj_ is NaN -> b is NaN -> the sum is NaN even with kST 0.
  const HallHue one{0.5, 1.0, {0.8, 0.8, 0.8}, 0.9, 1.0, 1.0, 1.0};
  EXPECT_TRUE(std::isnan(pw(0, 0.5, one, 0, 0, 0, headOn(), lights, {0.2, 0.2, 0.2})));
}

// ----------------------------------------------- zero terms skipped (issue 6)

// Same value, or both NaN; +0 and -0 count as the same (see HallShortcut).
bool sameColour(double a, double b) {
  return a == b || (std::isnan(a) && std::isnan(b));
}

TEST(HallShortcut, TakenWhenTheFactorsAreFiniteAndSameColours) {
  // kDR = kDT = 1 (kSR = kST = 0), integer exponents, a light in front: every
  // N.H is in [-1, 1] and the powers are finite, so all four terms are zero.
  const HallHue hue{1.0, 1.0, {0.8, 0.6, 0.4}, 0.9, 10.0, 3.0, 1.5};
  const std::vector<HallLight> lights = {{{3, -2, -10}, {0.7, 0.8, 0.9}},
                                         {{-5, 4, -8}, {0.3, 0.2, 0.1}}};
  const Rgb ia = {0.2, 0.3, 0.4};
  HallGeometry g = headOn();
  g.pt = {0.25, -0.5, 0.0};
  const HallPrepared p =
      prepareHall1991(g, lights, hue.indx, hue.kRH, hue.kTH, hue.tT, 0.0, {true, true, true, true});
  EXPECT_TRUE(p.zeroSpecularReflection);
  EXPECT_TRUE(p.zeroSpecularTransmission);
  EXPECT_TRUE(p.zeroReflected);
  EXPECT_TRUE(p.zeroTransmitted);
  const Rgb full =
      processColor1991(hue, {0.5, 0.25, 0.125}, {0, 0, 0}, {0, 0, 0}, 0.0, g, lights, ia, {});
  const Rgb fast = processColor1991(hue, {0.5, 0.25, 0.125}, {0, 0, 0}, {0, 0, 0}, 0.0, g, lights,
                                    ia, HallSkipping::forScene(lights, ia));
  for (int k = 0; k < 3; ++k)
    EXPECT_TRUE(sameColour(full[k], fast[k])) << k << ": " << full[k] << " " << fast[k];
  // The diffuse terms are all that is left. By hand for channel 0, with
  // c = sum I*N.L and N.L = -l_z/|l| (n = -z, l = pt - light, K10):
  // kDR*fDR*(IA + c) + kDT*fDT*(IA - c) = 0.8*(0.2 + c) + 0.2*(0.2 - c).
  const double nl1 = -10.0 / std::sqrt(2.75 * 2.75 + 1.5 * 1.5 + 100.0);
  const double nl2 = -8.0 / std::sqrt(5.25 * 5.25 + 4.5 * 4.5 + 64.0);
  const double c = 0.7 * nl1 + 0.3 * nl2;
  EXPECT_NEAR(full[0], 0.8 * (0.2 + c) + 0.2 * (0.2 - c), 1e-12);
}

TEST(HallShortcut, NotTakenWhereTheListingGetsNaN) {
  // kSR = 0 but pow(N.Hj, 1.5) with N.Hj = -1 is NaN (K10): 0 * NaN = NaN,
  // so the term must be computed and the colour stays NaN.
  const HallHue hue{1.0, 1.0, {0.8, 0.8, 0.8}, 0.9, 1.5, 2.0, 2.0};
  const std::vector<HallLight> lights = {{{0, 0, -10}, {1.0, 1.0, 1.0}}};
  const HallPrepared p = prepareHall1991(headOn(), lights, hue.indx, hue.kRH, hue.kTH, hue.tT, 0.0,
                                         {true, true, true, true});
  EXPECT_FALSE(p.zeroSpecularReflection);
  EXPECT_TRUE(
      p.zeroSpecularTransmission);  // kTH = 2: an integer power of a negative base is finite
  const Rgb fast =
      processColor1991(hue, {0.5, 0.5, 0.5}, {0, 0, 0}, {0, 0, 0}, 0.0, headOn(), lights,
                       {0.2, 0.2, 0.2}, HallSkipping::forScene(lights, {0.2, 0.2, 0.2}));
  EXPECT_TRUE(std::isnan(fast[0]));
  // K13: indx 1 makes Hj_ NaN: the transmission shortcut is refused too.
  const HallPrepared q =
      prepareHall1991(headOn(), lights, 1.0, 2.0, 2.0, 0.9, 0.0, {true, true, true, true});
  EXPECT_FALSE(q.zeroSpecularTransmission);
  EXPECT_TRUE(q.zeroSpecularReflection);
  // An unbounded input (an infinite reflected colour) switches the shortcut off.
  EXPECT_FALSE(hallHitInputsBounded({0.5, 0.5, 0.5},
                                    {std::numeric_limits<double>::infinity(), 0, 0}, {0, 0, 0}));
  EXPECT_TRUE(hallHitInputsBounded({0.5, 0.5, 0.5}, {0, 0, 0}, {0, 0, 0}));
  // An unbounded light switches the shortcut off for the whole scene.
  EXPECT_TRUE(HallSkipping::forScene(lights, {0.2, 0.2, 0.2}).on());
  const std::vector<HallLight> blinding = {{{0, 0, -10}, {1e200, 1.0, 1.0}}};
  EXPECT_FALSE(HallSkipping::forScene(blinding, {0.2, 0.2, 0.2}).on());
}

TEST(HallShortcut, RandomHitsGiveTheListingsColours) {
  // Random geometry, coefficients (half of them with kSR or kST exactly 0),
  // exponents (integer and not), indices (including 1), colours and
  // lights: the colour with the shortcut equals the listing's, NaN for NaN.
  std::uint64_t state = 1991;
  auto rnd = [&] {  // xorshift64*: a fixed sequence on every platform
    state ^= state >> 12;
    state ^= state << 25;
    state ^= state >> 27;
    return static_cast<double>((state * 2685821657736338717ULL) >> 11) * 0x1.0p-53;
  };
  auto unit = [&] {
    Vec3 v{rnd() * 2 - 1, rnd() * 2 - 1, rnd() * 2 - 1};
    unitVector(v, v);
    return v;
  };
  int shortcuts = 0, nans = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double exps[] = {0.0, 1.0, 2.0, 7.0, 0.5, 2.5, 40.0};
    const HallHue hue{rnd() < 0.5 ? 1.0 : rnd(),
                      rnd() < 0.5 ? 1.0 : rnd(),
                      {rnd(), rnd(), rnd()},
                      rnd(),
                      exps[trial % 7],
                      exps[(trial / 7) % 7],
                      trial % 11 == 0 ? 1.0 : 1.0 + rnd()};
    HallGeometry g;
    g.pt = {rnd() * 10, rnd() * 10, rnd() * 10};
    g.v = unit();
    g.n = trial % 5 == 0 ? g.v : unit();  // n == v: N.H can round past 1
    g.r = trial % 3 == 0 ? g.n : unit();
    std::vector<HallLight> lights;
    for (int i = 0, n = 1 + trial % 4; i < n; ++i)
      lights.push_back({{rnd() * 40 - 20, rnd() * 40 - 20, -20}, {rnd(), rnd(), rnd()}});
    const Rgb surf{rnd(), trial % 13 == 0 ? 0.0 : rnd(), rnd()}, ia{rnd(), rnd(), rnd()};
    const double sT = trial % 2 ? 0.0 : rnd() * 5;
    // The colours the reflected and transmitted rays returned: often black
    // (a ray that met nothing), sometimes black in one channel only.
    const Rgb iSR = trial % 3 == 0   ? Rgb{rnd(), 0.0, rnd()}
                    : trial % 3 == 1 ? Rgb{}
                                     : Rgb{rnd(), rnd(), rnd()};
    const Rgb iST = trial % 4 == 0 ? Rgb{rnd(), rnd(), rnd()} : Rgb{};
    const Rgb full = processColor1991(hue, surf, iSR, iST, sT, g, lights, ia, {});
    const Rgb fast = processColor1991(hue, surf, iSR, iST, sT, g, lights, ia,
                                      HallSkipping::forScene(lights, ia));
    for (int k = 0; k < 3; ++k)
      ASSERT_TRUE(sameColour(full[k], fast[k])) << "trial " << trial << " channel " << k;
    nans += std::isnan(full[0]);
    const HallPrepared p = prepareHall1991(
        g, lights, hue.indx, hue.kRH, hue.kTH, hue.tT, sT,
        {1.0 - hue.kDR == 0.0, 1.0 - hue.kDT == 0.0, 1.0 - hue.kDR == 0.0, 1.0 - hue.kDT == 0.0});
    shortcuts += p.zeroSpecularReflection + p.zeroSpecularTransmission;
  }
  EXPECT_GT(shortcuts, 5000);  // the shortcut is taken often ...
  EXPECT_GT(nans, 100);        // ... and the NaN cases were met
}

TEST(HallShortcut, BlackReflectedColourNeedsNoReflectionAngle) {
  // kSR = 0.7, but the reflected ray came back black: kSR * 0 * FSR = 0, so
  // Cos(ACos(N.R)) is not needed; one non-black channel needs it again.
  const HallHue hue{0.3, 1.0, {0.8, 0.6, 0.4}, 0.9, 10.0, 3.0, 1.5};
  const std::vector<HallLight> lights = {{{3, -2, -10}, {0.7, 0.8, 0.9}}};
  const Rgb ia = {0.2, 0.3, 0.4};
  const HallPrepared p = prepareHall1991(headOn(), lights, hue.indx, hue.kRH, hue.kTH, hue.tT, 0.0,
                                         {false, true, true, true});
  EXPECT_TRUE(p.zeroReflected);
  EXPECT_FALSE(p.zeroSpecularReflection);
  for (const Rgb& iSR : {Rgb{0, 0, 0}, Rgb{0, 0, 0.5}}) {
    const Rgb full =
        processColor1991(hue, {0.5, 0.25, 0.125}, iSR, {0, 0, 0}, 0.0, headOn(), lights, ia, {});
    const Rgb fast = processColor1991(hue, {0.5, 0.25, 0.125}, iSR, {0, 0, 0}, 0.0, headOn(),
                                      lights, ia, HallSkipping::forScene(lights, ia));
    for (int k = 0; k < 3; ++k)
      EXPECT_TRUE(sameColour(full[k], fast[k])) << k << ": " << full[k] << " " << fast[k];
  }
  // Channel 2 with iSR = 0.5: the reflected term kSR * iSR * FSR(s, IA, 0 deg)
  // (N.R = 1: FSR = IA*s) = 0.7 * 0.5 * 0.4 * 0.125 = 0.0175; channel 0 has 0.
  const auto terms = hallTermsRgb1991(hue, {0.5, 0.25, 0.125}, {0, 0, 0.5}, {0, 0, 0}, 0.0,
                                      headOn(), lights, ia, HallSkipping::forScene(lights, ia));
  EXPECT_NEAR(terms[2].reflected, 0.7 * 0.5 * 0.4 * 0.125, 1e-12);
  EXPECT_EQ(terms[0].reflected, 0.0);
}

}  // namespace
}  // namespace prime
