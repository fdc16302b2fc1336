// The numerical stress suite (issue 7): adversarial rays against every
// primitive and CSG operator, traced by the 1991 and the modern profile and
// compared with a reference computed in long double and __float128 from
// the same double inputs. docs/prime/numerics.md explains every figure.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace prime::stress {

// A histogram of non-negative errors on a log10 scale (0.1 decades from
// 1e-20 to 1e+4), with the exact maximum: mergeable, deterministic.
struct ErrorHistogram {
  static constexpr int kBins = 241;
  std::array<std::uint64_t, kBins> bins{};
  std::uint64_t count = 0, zeros = 0;
  double max = 0;
  void add(double e);
  // Upper edge of the bin holding the q-quantile (0 for the zeros).
  double quantile(double q) const;
  ErrorHistogram& operator+=(const ErrorHistogram& o);
};

// What one profile did on one class.
struct Figures {
  std::uint64_t rays = 0;      // rays measured (primary and chain rays)
  std::uint64_t refHits = 0;   // of which the reference hits something ahead
  std::uint64_t compared = 0;  // both hit, same decisions: t, normal, uv measured
  std::uint64_t wrongHitMiss = 0, ambiguousHitMiss = 0;
  std::uint64_t wrongInOut = 0, ambiguousInOut = 0;
  std::uint64_t wrongSurface = 0, ambiguousSurface = 0;  // hit a surface other than the nearest
  std::uint64_t nanInf = 0;  // NaN/Inf in t, hit point or normal of a reported hit
  std::uint64_t uvNan = 0;   // NaN/Inf (u, v) from the listing's inverse mapping
  std::uint64_t secondary = 0, selfHits = 0, wrongSide = 0;  // secondary rays
  std::uint64_t semanticK7 = 0;     // 1991: the reference hits, the listing by design does not (K7)
  std::uint64_t semanticCsg = 0;    // 1991: printed Roth operators (Q3, K30) differ from set ops
  std::uint64_t semanticK4 = 0;     // 1991: forward-matrix normal off the true one by > 1e-6 rad
  std::uint64_t listingErrors = 0;  // 1991: CsgError (E57) thrown
  std::uint64_t uvFaceChanges = 0;  // (u, v) on another face than the reference's
  std::uint64_t refDisagree = 0;    // long double and __float128 references disagree
  std::uint64_t chains = 0, chainSteps = 0, chainsComplete = 0;  // TIR / mirror chains
  ErrorHistogram tRel, normalAngle, uv;

  std::uint64_t wrongDecisions() const { return wrongHitMiss + wrongInOut + wrongSurface; }
  Figures& operator+=(const Figures& o);
};

struct ClassInfo {
  std::string name;
  std::string description;
};
const std::vector<ClassInfo>& stressClasses();

struct StressOptions {
  std::uint64_t seed = 1991;
  std::uint64_t raysPerClass = 20000;  // per class and profile (spread over the subjects)
  std::vector<std::string> classes;    // empty: all
  bool run1991 = true, runModern = true;
  int threads = 1;
  bool quad = true;           // also evaluate the __float128 reference
  double toleranceUlps = 64;  // C of the conditioning tolerance (docs/prime/numerics.md)
  std::function<void(const std::string&)> log;
};

struct ClassResult {
  std::string name;
  Figures f1991, modern;
};

std::vector<ClassResult> runStress(const StressOptions& options);

// The same measurements for rays of your own against one primitive ('S',
// 'B', 'C', 'N', 'Y') placed by the row-vector matrix m (for tests).
struct RayCase {
  std::array<double, 3> o, d;
};
Figures measureRays(char type, const std::array<std::array<double, 4>, 4>& m,
                    const std::vector<RayCase>& rays, bool listing,
                    const StressOptions& options = {});

// Whole-image stability: every scene rendered after a world transform.
struct StabilityRow {
  std::string scene, transform;
  std::uint64_t pixels = 0, changed1991 = 0, changedModern = 0;
  std::uint64_t big1991 = 0, bigModern = 0;  // of those, colour moved by > 0.01 in a channel
  std::uint64_t nan1991 = 0, nanModern = 0;
};
struct StabilityOptions {
  std::string scenesDir;
  std::vector<std::string> scenes;  // only these scene directories (empty: all)
  int screenDivisor = 4;            // CameraSettings screen size divided by this
  int threads = 0;
  bool run1991 = true, runModern = true;
  std::function<void(const std::string&)> log;
};
std::vector<StabilityRow> runStability(const StabilityOptions& options);

// Reporting.
std::string formatTable(const std::vector<ClassResult>& results, bool markdown);
std::string formatCsv(const std::vector<ClassResult>& results);
std::string formatStability(const std::vector<StabilityRow>& rows, bool markdown);

}  // namespace prime::stress
