// Loads a modelled scene directory into a Scene and checks everything that
// the renderer relies on, so that bad data is reported once, up front, naming
// the object, primitive and file — never a crash or a silent black pixel.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "legacy_io/prime/scene_dir.h"
#include "src/prime/scene/scene.h"

namespace prime {

Scene loadScene(const io::SceneDir& dir);

// Databases that are missing or older than a text input they are built from.
// Empty when the scene is ready to trace.
std::vector<std::string> staleDatabases(const io::SceneDir& dir);

// M34: objects whose CSG trees share subtrees so much that the listing's
// per-reference walk would visit more than kLargeExpansion entries per ray:
// one warning each, saying what each profile does with it (the 1991 profile
// walks every reference, up to its visit budget; the modern one evaluates
// each shared subtree once per ray).
inline constexpr std::uint64_t kLargeExpansion = 65536;
std::vector<std::string> sharedSubtreeWarnings(const Scene& scene);

}  // namespace prime
