// Interval lists built by hand for the CSG tests (csg_1991_test.cpp,
// csg_sets_test.cpp), as IntersectPrim/AddToTList and Add() would chain them.
// en(t,p) = an entry node for prim p (surfType Out, norm nIn(p));
// ex(t,p) = an exit node (surfType In, nOut(p)).
#pragma once
#include <initializer_list>

#include "src/prime/geom/interval_list.h"

namespace prime::tlist_builders {

inline Vec3 nIn(int prim) {
  return {static_cast<double>(prim), 1.0, 0.0};
}
inline Vec3 nOut(int prim) {
  return {static_cast<double>(prim), 2.0, 0.0};
}
inline TNode en(double t, int prim) {
  return TNode{t, prim, kSurfOut, nIn(prim)};
}
inline TNode ex(double t, int prim) {
  return TNode{t, prim, kSurfIn, nOut(prim)};
}

struct Span {
  double t0;
  double t1;
  int prim;
};
inline TList L(std::initializer_list<Span> spans) {
  TList l;
  for (const Span& s : spans) l.addPair(s.t0, s.t1, nIn(s.prim), nOut(s.prim), s.prim);
  return l;
}

}  // namespace prime::tlist_builders
