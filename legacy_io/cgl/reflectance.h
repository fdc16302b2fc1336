// The normal reflectance R that `prime cook` makes a Cook-Torrance surface's
// Fresnel table from (Sweeney 1985, section 9.9; the package's cook prompted
// for it on stdin): 33 numbers, 380 to 700 nm every 10 nm, each 0 <= R < 1,
// given on the command line or in a file, any number of them to a line, where
// blank lines and lines whose first non-blank character is '*' are comments
// (as in a scene file).
#pragma once
#include <string>
#include <vector>

#include "legacy_io/cgl/scene_file.h"
#include "legacy_io/common/error.h"

namespace prime::cgl {

// One number as read, and where (a file's line, or the option).
struct ReflectanceNumber {
  double value = 0.0;
  io::InputLocation where;
};

// True when `word` is a whole real number (as an istream reads one); `value`
// is set.
bool isReflectanceNumber(const std::string& word, double& value);

// Exactly 33 numbers, each 0 <= R < 1: throws io::InputError at the first one
// out of range, at the 34th, or at `end` when there are fewer.
Spectrum normalReflectance(const std::vector<ReflectanceNumber>& numbers,
                           const io::InputLocation& end);

// A reflectance file's text (`display` names it in messages; line breaks of
// any kind, a ^Z ends it). Throws io::InputError naming the file and the line:
// of a word that is not a number, of the 34th number, of one out of range,
// or the last line when there are fewer than 33.
Spectrum readReflectance(const std::string& text, const std::string& display);

}  // namespace prime::cgl
