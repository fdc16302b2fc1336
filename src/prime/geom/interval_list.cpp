#include "src/prime/geom/interval_list.h"

#include <ostream>

namespace prime {

std::ostream& operator<<(std::ostream& os, const TNode& n) {
  os << '{' << n.t << " p" << n.prim << ' ';
  if (n.surfType == kSurfOut)
    os << "Out";
  else if (n.surfType == kSurfIn)
    os << "In";
  else
    os << "surf" << n.surfType;
  return os << " n(" << n.norm[0] << ',' << n.norm[1] << ',' << n.norm[2] << ")}";
}

std::ostream& operator<<(std::ostream& os, const TList& l) {
  os << '[';
  for (std::size_t i = 0; i < l.size(); ++i) {
    if (i != 0) os << (i % 2 == 0 ? " | " : " ");
    os << l[i];
  }
  return os << ']';
}

}  // namespace prime
