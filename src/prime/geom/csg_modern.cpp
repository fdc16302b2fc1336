#include "src/prime/geom/csg_modern.h"

#include <limits>

namespace prime {

CsgProgram1991 compileModern(std::span<const CsgEntry> entries) {
  Csg1991Options options;
  options.skipRightWhenLeftEmpty = true;
  options.maxVisits = std::numeric_limits<std::size_t>::max();
  return CsgProgram1991::compileChecked(entries, options);
}

TList csgModern(std::span<const CsgEntry> entries, LeafFn leaf) {
  return compileModern(entries).runModern(leaf);
}

}  // namespace prime
