// Loads a modelled scene directory into a Scene and checks everything that
// the renderer relies on, so that bad data is reported once, up front, naming
// the object, primitive and file — never a crash or a silent black pixel.
#pragma once
#include <string>
#include <vector>

#include "legacy_io/prime/scene_dir.h"
#include "src/prime/scene/scene.h"

namespace prime {

Scene loadScene(const io::SceneDir& dir);

// Databases that are missing or older than a text input they are built from.
// Empty when the scene is ready to trace.
std::vector<std::string> staleDatabases(const io::SceneDir& dir);

}  // namespace prime
