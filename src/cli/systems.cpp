// The systems `prime` replays, one row each (src/cli/system.h). A fourth
// system adds its adapter (src/cli/<system>/adapter.cpp) and one line here.
#include "src/cli/system.h"

namespace prime::cli {
namespace prime_system {
extern const System kSystem;  // src/cli/prime/adapter.cpp
}
namespace malone {
extern const System kSystem;  // src/cli/malone/adapter.cpp
}
namespace cgl {
extern const System kSystem;  // src/cli/cgl/adapter.cpp
}

std::span<const System> systems() {
  // PRIME first: the default for a directory, a graph file, or nothing. CGL
  // before Malone: a CGL file can start with numbers, Malone's never has
  // CGL's keywords.
  static const System kSystems[] = {prime_system::kSystem, cgl::kSystem, malone::kSystem};
  return kSystems;
}

}  // namespace prime::cli
