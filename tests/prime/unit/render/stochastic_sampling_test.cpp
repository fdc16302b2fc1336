// Stochastic (jittered, thesis 2.6.2) and statistical (thesis 2.6.3)
// supersampling in the shared sampler, and the counter-based random numbers
// behind them.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "src/prime/render/pixel_sampling.h"
#include "src/prime/render/sample_random.h"

namespace prime {
namespace {

TEST(SampleRandom, APureFunctionOfItsKeyUniformInUnitInterval) {
  EXPECT_EQ(sampleBits(1, 2, 3, 4, 0), sampleBits(1, 2, 3, 4, 0));
  // Changing any word of the key changes the bits.
  const std::uint64_t b = sampleBits(1, 2, 3, 4, 0);
  EXPECT_NE(b, sampleBits(2, 2, 3, 4, 0));
  EXPECT_NE(b, sampleBits(1, 3, 3, 4, 0));
  EXPECT_NE(b, sampleBits(1, 2, 4, 4, 0));
  EXPECT_NE(b, sampleBits(1, 2, 3, 5, 0));
  EXPECT_NE(b, sampleBits(1, 2, 3, 4, 1));
  EXPECT_NE(sampleBits(1, 2, 3, 0, 0), sampleBits(1, 3, 2, 0, 0));  // row and column not symmetric
  // 100,000 draws: in [0, 1), mean 1/2 and variance 1/12 within 4 standard errors.
  double sum = 0, sumSq = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double u = sampleUniform(7, static_cast<std::uint64_t>(i) / 300, i % 300, 0, 0);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    sumSq += u * u;
  }
  const double mean = sum / n, var = sumSq / n - mean * mean;
  EXPECT_NEAR(mean, 0.5, 4 * std::sqrt(1.0 / 12 / n));
  EXPECT_NEAR(var, 1.0 / 12, 4 * std::sqrt(1.0 / 180 / n));  // var of U^2-ish: (1/80 - 1/144)
}

TEST(SampleRandom, RadicalInversesByHand) {
  // base 2: 1 -> 0.1b = 0.5, 2 -> 0.01b = 0.25, 3 -> 0.11b = 0.75, 6 -> 0.011b = 0.375
  EXPECT_EQ(radicalInverse2(0), 0.0);
  EXPECT_EQ(radicalInverse2(1), 0.5);
  EXPECT_EQ(radicalInverse2(2), 0.25);
  EXPECT_EQ(radicalInverse2(3), 0.75);
  EXPECT_EQ(radicalInverse2(6), 0.375);
  // base 3: 1 -> 1/3, 3 -> 0.01 (base 3) = 1/9, 5 = 12 (base 3) -> 0.21 = 2/3 + 1/9
  EXPECT_NEAR(radicalInverse3(1), 1.0 / 3, 1e-15);
  EXPECT_NEAR(radicalInverse3(3), 1.0 / 9, 1e-15);
  EXPECT_NEAR(radicalInverse3(5), 2.0 / 3 + 1.0 / 9, 1e-15);
}

TEST(StudentQuantile, AgreesWithTheTables) {
  // Two-sided 95%: t(0.975, nu) from the standard tables.
  const std::pair<int, double> table[] = {{1, 12.706}, {2, 4.303},  {3, 3.182}, {4, 2.776},
                                          {7, 2.365},  {15, 2.131}, {63, 1.998}};
  for (const auto& [nu, t] : table) EXPECT_NEAR(studentQuantile(0.975, nu), t, 0.005) << nu;
  EXPECT_NEAR(normalQuantile(0.975), 1.959964, 1e-6);
  EXPECT_NEAR(normalQuantile(0.995), 2.575829, 1e-6);
}

TEST(JitteredSampling, OneRandomPointInEachStratumSameForTheSameKey) {
  Sampling s;
  s.mode = Sampling::Mode::Jittered;
  s.gridN = 3;
  s.seed = 42;
  auto points = [&](PixelKey key) {
    std::vector<std::pair<double, double>> p;
    std::vector<int> ks;
    samplePixel(
        s, nullptr, key, nullptr, [] { return Rgb{}; },
        [&](double fx, double fy, int k) {
          p.push_back({fx, fy});
          ks.push_back(k);
          return Rgb{};
        });
    EXPECT_EQ(ks, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
    return p;
  };
  const auto a = points({42, 5, 7});
  ASSERT_EQ(a.size(), 9u);
  for (int k = 0; k < 9; ++k) {  // sample k = a*3 + b lies in stratum (column b, row a)
    const double fx = a[k].first + 0.5, fy = a[k].second + 0.5;
    EXPECT_GE(fx, (k % 3) / 3.0);
    EXPECT_LT(fx, (k % 3 + 1) / 3.0);
    EXPECT_GE(fy, (k / 3) / 3.0);
    EXPECT_LT(fy, (k / 3 + 1) / 3.0);
  }
  EXPECT_EQ(points({42, 5, 7}), a);  // the same key: the same points
  EXPECT_NE(points({42, 5, 8}), a);  // another pixel: other points
  EXPECT_NE(points({43, 5, 7}), a);  // another seed: other points
}

TEST(StatisticalSampling, StopsAfterFourForAFlatPixelAndAtTheMaximumForANoisyOne) {
  Sampling s;
  s.mode = Sampling::Mode::Statistical;
  s.bound = 0.01;
  s.maxSamples = 32;
  const MeanBound bounds(s);
  int count = 0, calls = 0;
  Rgb c = samplePixel(
      s, nullptr, PixelKey{1, 0, 0}, &bounds, [] { return Rgb{}; },
      [&](double, double, int) {
        ++calls;
        return Rgb{0.3, 0.3, 0.3};
      },
      &count);
  EXPECT_EQ(count, 4);  // the thesis' first four rays agree exactly: stop
  EXPECT_EQ(calls, 4);
  EXPECT_DOUBLE_EQ(c[0], 0.3);
  // Black or white at random (s = 0.5): t s / sqrt(n) > 0.01 for every n <= 32.
  calls = 0;
  c = samplePixel(
      s, nullptr, PixelKey{1, 0, 0}, &bounds, [] { return Rgb{}; },
      [&](double, double, int k) {
        ++calls;
        const double v = k % 2 ? 1.0 : 0.0;
        return Rgb{v, v, v};
      },
      &count);
  EXPECT_EQ(count, 32);
  EXPECT_EQ(calls, 32);
  EXPECT_DOUBLE_EQ(c[0], 0.5);
}

TEST(StatisticalSampling, EachBatchOfFourHasOnePointInEachQuarter) {
  Sampling s;
  s.mode = Sampling::Mode::Statistical;
  s.bound = 1e-6;
  s.maxSamples = 16;
  const MeanBound bounds(s);
  std::vector<std::pair<double, double>> p;
  samplePixel(
      s, nullptr, PixelKey{3, 1, 2}, &bounds, [] { return Rgb{}; },
      [&](double fx, double fy, int k) {
        p.push_back({fx, fy});
        return Rgb{k * 0.1, 0, 0};  // never agrees: all 16
      });
  ASSERT_EQ(p.size(), 16u);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int q = static_cast<int>(i % 4);
    EXPECT_EQ(p[i].first >= 0.0, (q & 1) == 1) << i;
    EXPECT_EQ(p[i].second >= 0.0, (q >> 1) == 1) << i;
  }
}

// The stopping rule meets its bound. Synthetic pixels whose samples are
// independent draws of a known distribution with mean mu: after stopping,
// the fraction of pixels with |mean - mu| > bound should be about
// 1 - confidence (it is a 95% interval). The sequential test stops early
// when the first samples happen to agree, which costs some coverage; the
// rule is accepted if at most 1.5 x (1 - confidence) of the pixels miss.
struct Coverage {
  double missRate = 0, meanCount = 0;
};
template <class Draw>
Coverage coverage(double bound, double mu, Draw draw, int pixels = 20000, int minSamples = 4) {
  Sampling s;
  s.mode = Sampling::Mode::Statistical;
  s.bound = bound;
  s.confidence = 0.95;
  s.minSamples = minSamples;
  s.maxSamples = 4096;  // high enough never to be what stops the pixel
  s.seed = 9;
  const MeanBound bounds(s);
  int misses = 0;
  double counts = 0;
  for (int p = 0; p < pixels; ++p) {
    const PixelKey key{9, static_cast<std::uint32_t>(p / 200), static_cast<std::uint32_t>(p % 200)};
    int count = 0;
    const Rgb c = samplePixel(
        s, nullptr, key, &bounds, [] { return Rgb{}; },
        [&](double, double, int k) {
          const double v = draw(key, k);
          return Rgb{v, mu, mu};  // green and blue exact: the red channel decides
        },
        &count);
    counts += count;
    if (std::abs(c[0] - mu) > bound) ++misses;
  }
  return {static_cast<double>(misses) / pixels, counts / pixels};
}

TEST(StatisticalSampling, MeetsItsBoundOnGaussianPixels) {
  // N(0.5, 0.1^2) by Box-Muller from the key's uniforms; bound 0.02:
  // about (1.96 * 0.1 / 0.02)^2 = 96 samples a pixel.
  const auto gauss = [](const PixelKey& key, int k) {
    const double u1 = 1.0 - sampleUniform(1234, key.row, key.column, k, 0);
    const double u2 = sampleUniform(1234, key.row, key.column, k, 1);
    return 0.5 + 0.1 * std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  };
  const Coverage c = coverage(0.02, 0.5, gauss);
  EXPECT_GT(c.meanCount, 80);
  EXPECT_LT(c.meanCount, 120);
  EXPECT_LE(c.missRate, 1.5 * 0.05) << "mean count " << c.meanCount;
  EXPECT_GE(c.missRate, 0.02) << "an interval far wider than asked wastes rays";
}

TEST(StatisticalSampling, EdgePixelsNeedMoreThanFourFirstRays_T14) {
  // A pixel across an edge: each sample 1 with probability 0.3, else 0 (an
  // object covering 30% of it); sigma = sqrt(0.21) = 0.458; bound 0.05:
  // about (1.96 * 0.458 / 0.05)^2 = 323 samples once the spread is seen.
  const auto edge = [](const PixelKey& key, int k) {
    return sampleUniform(555, key.row, key.column, k, 0) < 0.3 ? 1.0 : 0.0;
  };
  // The thesis' first four rays all miss the object with probability
  // 0.7^4 = 0.24: their spread is 0 and the rule stops at once with the
  // mean 0, 0.3 away (T14). So with --min-samples 4 about a quarter of such
  // pixels miss the bound, far more than 5%: the limit of any rule that
  // trusts the spread of four samples.
  const Coverage four = coverage(0.05, 0.3, edge, 5000, 4);
  EXPECT_GT(four.missRate, 0.7 * 0.7 * 0.7 * 0.7 - 0.02);
  EXPECT_LT(four.missRate, 0.35);
  // With 16 first rays, all agree with probability 0.7^16 = 0.003, and the
  // rule meets its bound at about its confidence.
  const Coverage sixteen = coverage(0.05, 0.3, edge, 5000, 16);
  EXPECT_GT(sixteen.meanCount, 250);
  EXPECT_LE(sixteen.missRate, 1.5 * 0.05) << "mean count " << sixteen.meanCount;
}

}  // namespace
}  // namespace prime
