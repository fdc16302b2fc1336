// POV-Ray 3.7 scene-language text for every system's `export-pov`: numbers,
// vectors and matrices written the one way (shortest round-trip decimal, no
// -0, no Inf or NaN, which POV-Ray cannot read). What a scene becomes is each
// system's own (src/<system>/pov_export.*).
#pragma once
#include <array>
#include <string>

#include "src/math/vec.h"

namespace prime {

// The shortest decimal that reads back as v ("0" for 0, -0 and a value that
// is not finite: callers check first).
std::string povNumber(double v);
// <x, y, z>
std::string povVector(const Vec3& v);
// matrix <...>: the 4 x 3 rows (the images of the local x, y and z axes, then
// the translation), row by row.
std::string povMatrix(const std::array<double, 12>& rows);
std::string povMatrix(const Vec3& x, const Vec3& y, const Vec3& z, const Vec3& translation);

}  // namespace prime
