// A deliberate violation: one system including another's scene.
#include "src/cgl/scene.h"
#include "src/prime/scene/scene.h"
