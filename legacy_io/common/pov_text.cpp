#include "legacy_io/common/pov_text.h"

#include <charconv>
#include <cmath>

#include "legacy_io/common/charconv.h"

namespace prime {

std::string povNumber(double v) {
  if (!std::isfinite(v)) return "0";  // POV-Ray has no Inf/NaN literal
  if (v == 0.0) return "0";           // also turns -0 into 0
  char buf[64];
  const auto r = io::toChars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string povVector(const Vec3& v) {
  return "<" + povNumber(v[0]) + ", " + povNumber(v[1]) + ", " + povNumber(v[2]) + ">";
}

std::string povMatrix(const std::array<double, 12>& rows) {
  std::string s = "matrix <";
  for (std::size_t i = 0; i < rows.size(); ++i) s += (i ? ", " : "") + povNumber(rows[i]);
  return s + ">";
}

std::string povMatrix(const Vec3& x, const Vec3& y, const Vec3& z, const Vec3& translation) {
  return povMatrix({x[0], x[1], x[2], y[0], y[1], y[2], z[0], z[1], z[2], translation[0],
                    translation[1], translation[2]});
}

}  // namespace prime
