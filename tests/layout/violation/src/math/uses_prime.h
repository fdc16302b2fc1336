// A deliberate violation: shared maths including PRIME's listing arithmetic.
#pragma once
#include "src/prime/math/listing_math.h"
