#include "src/prime/math/listing_math.h"

#include <cmath>

namespace prime {

double sinDeg(double degrees) {
  return std::sin(degrees / kRadient);
}
double cosDeg(double degrees) {
  return std::cos(degrees / kRadient);
}
double asinDeg(double x) {
  return std::asin(x) * kRadient;
}
double acosDeg(double x) {
  return std::acos(x) * kRadient;
}

}  // namespace prime
