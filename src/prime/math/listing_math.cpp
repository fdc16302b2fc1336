#include "src/prime/math/listing_math.h"

#include <cmath>

namespace prime {

double roundoff(double num) {
  if (num > 0.0) {
    const double floorNum = floorExact(num);
    const double variance = num - floorNum;
    if (variance > 0.9999999999) return floorNum + 1.0;
    if (variance < 0.0000000001) return floorNum;
    return num;
  }
  if (num < 0.0) {
    const double floorNum = floorExact(-num);
    const double variance = -num - floorNum;
    if (variance > 0.999999998) return (floorNum + 1.0) * -1.0;
    if (variance < 0.000000001) return -floorNum;
    return num;
  }
  return 0.0;  // zero, and NaN (both comparisons false)
}

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
