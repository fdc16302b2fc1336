// `prime check DIR` (and the warnings of `prime model`): the hue values that
// the 1991 listing turns into NaN, a division by zero or an invisible object,
// each named by file, line and field with its errata id.
#pragma once
#include <string>
#include <vector>

#include "legacy_io/prime/scene_dir.h"

namespace prime::cli {

// One problem: the located message (as InputError formats it).
struct SceneProblem {
  std::string message;
};

// Checks every hue file (obj/H<n>.txt, found without regard to case: M40) of
// the scene. A hue file that does not parse is a problem too.
std::vector<SceneProblem> checkHues(const io::SceneDir& scene);

}  // namespace prime::cli
