// CSG module (3216-3712) and the list primitives of the tList module
// (7867-7983) that it uses, emulated on TList.
//
// Notation in the comments: A = *tList (left operand, receives the result),
// B = *tList1 (right operand); a0/a1 = the val of A's front pair (entry/exit),
// b0/b1 the same for B. The branch ids U1..U13, D1..D13, I1..I13 are the ones
// used in docs/prime/port-notes/csg.md and in the unit tests.
#include "src/prime/geom/csg_1991.h"

#include <string>
#include <utility>

namespace prime {
namespace {

// `*pt` of the listing: the node a TListPt points to, inside one operand.
// `head` indexes *pt; (*pt)->next is head + 1 (Add and Kill move two nodes at
// a time, so a pair is never split).
struct Ptr {
  TList* list;
  std::size_t head = 0;

  [[nodiscard]] bool isNull() const { return head >= list->size(); }  // *pt == NULL
  [[nodiscard]] TNode& node() const { return (*list)[head]; }         // **pt
  [[nodiscard]] TNode& next() const { return (*list)[head + 1]; }     // *(*pt)->next
  [[nodiscard]] double val() const { return node().t; }               // (*pt)->val
  [[nodiscard]] double nextVal() const { return next().t; }           // (*pt)->next->val
};

// The state one operator call of the listing works on. The Malloc'd dummy
// head `tmpPtDummy` and the global tail pointer `tListPos` (Global module,
// E14) become the local output list `out`; nothing is global.
class Roth {
 public:
  Roth(TList& a, TList& b) : tList{&a}, tList1{&b} {
    if (!a.wellFormed() || !b.wellFormed())
      throw CsgError(CsgError::Kind::kOddList,
                     "CSG operator: tList with an odd number of nodes (not a list of pairs)");
    out.reserve(a.size() + b.size());
  }

  // Add (7949-7961): `tListPos->next = *pt; tListPos = (*pt)->next;
  // *pt = (*pt)->next->next; tListPos->next = NULL;` -- the front pair of *pt
  // moves, unchanged, to the end of the output list.
  void Add(Ptr& pt) {
    if (pt.isNull())  // a NULL dereference in the listing; no printed branch reaches it
      throw CsgError(CsgError::Kind::kAddEmptyList, "Add() of an empty tList");
    out.pushPair(pt.node(), pt.next());
    pt.head += 2;
  }

  // Kill (7963-7975): `tmp = *pt; *pt = (*pt)->next->next; Free(tmp->next);
  // Free(tmp);` -- drops the front pair. E57: with *pt == NULL the original hit
  // Free()'s fatal Error (5767); the port throws that error.
  void Kill(Ptr& pt) {
    if (pt.isNull())
      throw CsgError(CsgError::Kind::kKillEmptyList,
                     "Kill() of an empty tList (errata E57): Free(): Attempt to Free a block "
                     "currently not Malloced");
    pt.head += 2;
  }

  // Copy(from, to) (7932-7947): val, primNum, surfType and norm -- every field
  // but `next`, i.e. the whole TNode.
  static void Copy(const TNode& from, TNode& to) { to = from; }

  // `*tList = tmpPtDummy->next;` (3434, 3580, 3710). *tList1 is NULL by then.
  void finish() {
    *tList.list = std::move(out);
    tList1.list->clear();
  }

  Ptr tList;
  Ptr tList1;
  TList out;
};

}  // namespace

// Union (3306-3436). The header comment says "tList1 is unchanged"; in fact
// every node of both lists is Added or Killed.
void union1991(TList& a, TList& b) {
  Roth r(a, b);
  Ptr& tList = r.tList;
  Ptr& tList1 = r.tList1;
  while (!tList.isNull() && !tList1.isNull()) {  // 3322
    if (tList1.val() < tList.val()) {            // 3324 (E12)
      if (tList1.nextVal() < tList.val()) {      // 3326 (E12)
        // U1: b0 < a0, b1 < a0 (B before A).
        r.Add(tList1);                              // 3333
      } else if (tList1.nextVal() > tList.val()) {  // 3337
        if (tList1.nextVal() < tList.nextVal()) {   // 3339
          // U2: b0 < a0 < b1 < a1. A becomes [b1, a1] (its entry node is a copy
          // of B's exit node), B is output.
          Roth::Copy(tList1.next(), tList.node());        // 3341
          r.Add(tList1);                                  // 3342
        } else if (tList1.nextVal() > tList.nextVal()) {  // 3346
          // U3 (Q3): b0 < a0, b1 > a1 (B covers A). Outputs [b0, a1] and leaves
          // B = [b1, b1]: (a1, b1) is lost.
          Roth::Copy(tList1.node(), tList.node());   // 3348
          Roth::Copy(tList1.next(), tList1.node());  // 3349
          r.Add(tList);                              // 3350
        } else {  // 3352 (*tList1)->next->val == (*tList)->next->val
          // U4: b0 < a0, b1 == a1.
          r.Add(tList1);  // 3354
          r.Kill(tList);  // 3355
        }
      } else {  // 3359 (*tList1)->next->val == (*tList)->val
        // U5: b0 < a0, b1 == a0 (B touches A from before).
        r.Add(tList1);  // 3361
      }
    } else if (tList1.val() > tList.val()) {     // 3367
      if (tList1.nextVal() < tList.nextVal()) {  // 3369
        // U6: a0 < b0, b1 < a1 (B inside A).
        r.Add(tList);                                   // 3371
        r.Kill(tList1);                                 // 3372
      } else if (tList1.nextVal() > tList.nextVal()) {  // 3376
        if (tList1.val() > tList.nextVal()) {           // 3378
          // U7: b0 > a1 (B after A).
          r.Add(tList);                               // 3380
        } else if (tList1.val() < tList.nextVal()) {  // 3384
          // U8 (Q3): a0 < b0 < a1 < b1. B becomes [b1, b1]: (a1, b1) is lost.
          Roth::Copy(tList1.next(), tList1.node());  // 3386
          r.Add(tList);                              // 3387
        } else {                                     // 3389 (*tList1)->val == (*tList)->next->val
          // U9: b0 == a1 (B touches A from after).
          r.Add(tList);  // 3391
        }
      } else {  // 3395 (*tList1)->next->val == (*tList)->next->val
        // U10: a0 < b0, b1 == a1.
        r.Add(tList);    // 3397
        r.Kill(tList1);  // 3398
      }
    } else {                                     // 3402 (*tList1)->val == (*tList)->val
      if (tList1.nextVal() < tList.nextVal()) {  // 3404
        // U11: b0 == a0, b1 < a1. A becomes [b1, a1], B is output.
        Roth::Copy(tList1.next(), tList.node());        // 3406
        r.Add(tList1);                                  // 3407
      } else if (tList1.nextVal() > tList.nextVal()) {  // 3411
        // U12 (Q3): b0 == a0, b1 > a1. B becomes [b1, b1]: (a1, b1) is lost.
        Roth::Copy(tList1.next(), tList1.node());  // 3413
        r.Add(tList);                              // 3414
      } else {  // 3416 (*tList1)->next->val == (*tList)->next->val
        // U13: equal pairs.
        r.Add(tList);    // 3418
        r.Kill(tList1);  // 3419
      }
    }
  }
  while (!tList.isNull()) r.Add(tList);    // 3426-3429
  while (!tList1.isNull()) r.Add(tList1);  // 3430-3433
  r.finish();
}

// Difference (3442-3582), read with E12 throughout. A is never Added or Killed
// inside the loop, so the loop only ends when B is exhausted (or E57), every A
// pair reaches the result (possibly rewritten), and the trailing Kill loop
// (3576-3579) runs only when A was empty from the start.
void difference1991(TList& a, TList& b) {
  Roth r(a, b);
  Ptr& tList = r.tList;
  Ptr& tList1 = r.tList1;
  while (!tList.isNull() && !tList1.isNull()) {  // 3461
    if (tList1.val() < tList.val()) {            // 3463
      if (tList1.nextVal() < tList.val()) {      // 3465
        // D1: B before A.
        r.Kill(tList1);                             // 3467
      } else if (tList1.nextVal() > tList.val()) {  // 3471
        if (tList1.nextVal() < tList.nextVal()) {   // 3473
          // D2: b0 < a0 < b1 < a1. A becomes [b1, a1]; its entry node is B's
          // exit node as it is (surfType In, B's exit normal).
          Roth::Copy(tList1.next(), tList.node());        // 3475
          r.Kill(tList1);                                 // 3476
        } else if (tList1.nextVal() > tList.nextVal()) {  // 3480
          // D3 (Q3, the author's /*?*/): b0 < a0, b1 > a1 (B covers A). A
          // becomes the inverted pair [b1, a1] and B is dropped.
          Roth::Copy(tList1.next(), tList.node());  // 3482
          r.Kill(tList1);                           // 3483
        } else {  // 3485 (*tList1)->next->val == (*tList)->next->val
          // D4 (Q3, E57): b0 < a0, b1 == a1. Kills B's front pair and the one
          // after it; A survives. E57 when B had a single pair.
          r.Kill(tList1);  // 3487
          r.Kill(tList1);  // 3488
        }
      } else {  // 3493 (*tList1)->next->val == (*tList)->val
        // D5: b1 == a0 (B touches A from before).
        r.Kill(tList1);  // 3495
      }
    } else if (tList1.val() > tList.val()) {     // 3501
      if (tList1.nextVal() < tList.nextVal()) {  // 3503
        // D6 (K31): a0 < b0, b1 < a1 (B inside A). Outputs [a0, b0] made of
        // B's nodes (entry: val a0 and A's primNum, but B's surfType and entry
        // normal; exit: a copy of B's entry node), and A becomes [b1, a1]
        // with B's exit node as its entry.
        const double tmpVal = tList.val();              // 3505
        const int tmpPrimNum = tList.node().prim;       // 3506
        Roth::Copy(tList1.next(), tList.node());        // 3507
        Roth::Copy(tList1.node(), tList1.next());       // 3508
        tList1.node().t = tmpVal;                       // 3509
        tList1.node().prim = tmpPrimNum;                // 3510
        r.Add(tList1);                                  // 3511
      } else if (tList1.nextVal() > tList.nextVal()) {  // 3515
        if (tList1.val() > tList.nextVal()) {           // 3517
          // D7 (Q3, /*?*/): b0 > a1 (B after A). Outputs B; A stays.
          r.Add(tList1);                              // 3519
        } else if (tList1.val() < tList.nextVal()) {  // 3523
          // D8 (Q3): a0 < b0 < a1 < b1. A becomes [a0, b0] (its exit node is
          // B's entry node), and B is output.
          Roth::Copy(tList1.node(), tList.next());  // 3525
          r.Add(tList1);                            // 3526
        } else {                                    // 3528 (*tList1)->val == (*tList)->next->val
          // D9 (Q3): b0 == a1 (B touches A from after). Outputs B.
          r.Add(tList1);  // 3530
        }
      } else {  // 3535 (*tList1)->next->val == (*tList)->next->val
        // D10 (Q3, E57): a0 < b0, b1 == a1. A becomes [a0, b0], B's front pair
        // is output and the pair after it is Killed (E57 if there is none).
        Roth::Copy(tList1.node(), tList.next());  // 3537
        r.Add(tList1);                            // 3538
        r.Kill(tList1);                           // 3539
      }
    } else {                                     // 3543 (*tList1)->val == (*tList)->val
      if (tList1.nextVal() < tList.nextVal()) {  // 3545
        // D11: b0 == a0, b1 < a1. A becomes [b1, a1].
        Roth::Copy(tList1.next(), tList.node());        // 3547
        r.Kill(tList1);                                 // 3548
      } else if (tList1.nextVal() > tList.nextVal()) {  // 3552
        // D12 (Q3): b0 == a0, b1 > a1. A becomes the inverted pair [b1, a1].
        Roth::Copy(tList1.next(), tList.node());  // 3554
        r.Kill(tList1);                           // 3555
      } else {  // 3557 (*tList1)->next->val == (*tList)->next->val
        // D13 (Q3, E57): equal pairs. Kills B's front pair and the next one;
        // A survives. E57 when B had a single pair.
        r.Kill(tList1);  // 3559
        r.Kill(tList1);  // 3560
      }
    }
  }
  while (!tList.isNull()) r.Add(tList);     // 3572-3575
  while (!tList1.isNull()) r.Kill(tList1);  // 3576-3579 (only if A was empty)
  r.finish();
}

// Intersection (3584-3712), read with E13 (`copy` at 3611 = `Copy`).
void intersection1991(TList& a, TList& b) {
  Roth r(a, b);
  Ptr& tList = r.tList;
  Ptr& tList1 = r.tList1;
  while (!tList.isNull() && !tList1.isNull()) {  // 3597
    if (tList1.val() < tList.val()) {            // 3599
      if (tList1.nextVal() < tList.val()) {      // 3601
        // I1: B before A.
        r.Kill(tList1);                             // 3603
      } else if (tList1.nextVal() > tList.val()) {  // 3607
        if (tList1.nextVal() < tList.nextVal()) {   // 3609
          // I2: b0 < a0 < b1 < a1. Outputs [a0, b1] (A's entry node, B's exit
          // node); A becomes [b1, a1].
          Roth::Copy(tList.node(), tList1.node());        // 3611 (E13)
          Roth::Copy(tList1.next(), tList.node());        // 3612
          r.Add(tList1);                                  // 3613
        } else if (tList1.nextVal() > tList.nextVal()) {  // 3617
          // I3 (Q3): b0 < a0, b1 > a1 (B covers A). B becomes [a1, b1] and is
          // output instead of A; A stays.
          Roth::Copy(tList.next(), tList1.node());  // 3619
          r.Add(tList1);                            // 3620
        } else {  // 3622 (*tList1)->next->val == (*tList)->next->val
          // I4: b0 < a0, b1 == a1.
          r.Add(tList);    // 3624
          r.Kill(tList1);  // 3625
        }
      } else {  // 3631 (*tList1)->next->val == (*tList)->val
        // I5: b1 == a0 (touching: nothing in common).
        r.Kill(tList1);  // 3633
      }
    } else if (tList1.val() > tList.val()) {     // 3638
      if (tList1.nextVal() < tList.nextVal()) {  // 3640
        // I6: a0 < b0, b1 < a1 (B inside A). A becomes [b1, a1], B is output.
        Roth::Copy(tList1.next(), tList.node());        // 3642
        r.Add(tList1);                                  // 3643
      } else if (tList1.nextVal() > tList.nextVal()) {  // 3647
        if (tList1.val() > tList.nextVal()) {           // 3649
          // I7: b0 > a1 (B after A).
          r.Kill(tList);                              // 3651
        } else if (tList1.val() < tList.nextVal()) {  // 3655
          // I8: a0 < b0 < a1 < b1. Outputs [b0, a1]; B becomes [b1, b1], so
          // (a1, b1) is lost for A's later pairs (not listed in Q3; see
          // docs/prime/port-notes/csg.md).
          Roth::Copy(tList1.node(), tList.node());   // 3657
          Roth::Copy(tList1.next(), tList1.node());  // 3658
          r.Add(tList);                              // 3659
        } else {                                     // 3661 (*tList1)->val == (*tList)->next->val
          // I9: b0 == a1 (touching).
          r.Kill(tList);  // 3663
        }
      } else {  // 3669 (*tList1)->next->val == (*tList)->next->val
        // I10: a0 < b0, b1 == a1.
        r.Add(tList1);  // 3671
        r.Kill(tList);  // 3672
      }
    } else {                                     // 3676 (*tList1)->val == (*tList)->val
      if (tList1.nextVal() < tList.nextVal()) {  // 3678
        // I11: b0 == a0, b1 < a1. A becomes [b1, a1], B is output.
        Roth::Copy(tList1.next(), tList.node());        // 3680
        r.Add(tList1);                                  // 3681
      } else if (tList1.nextVal() > tList.nextVal()) {  // 3685
        // I12: b0 == a0, b1 > a1. B becomes [a1, b1], A is output.
        Roth::Copy(tList.next(), tList1.node());  // 3691
        r.Add(tList);                             // 3692
      } else {  // 3694 (*tList1)->next->val == (*tList)->next->val
        // I13: equal pairs.
        r.Add(tList);    // 3696
        r.Kill(tList1);  // 3697
      }
    }
  }
  while (!tList.isNull()) r.Kill(tList);    // 3702-3705
  while (!tList1.isNull()) r.Kill(tList1);  // 3706-3709
  r.finish();
}

namespace {

[[noreturn]] void badIndex(int index, std::size_t count) {
  throw CsgError(CsgError::Kind::kBadEntryIndex,
                 "ReadObj(): Invalid read attempt: CSG entry " + std::to_string(index) +
                     " is outside the object's " + std::to_string(count) + " entries");
}

void checkIndex(int index, std::size_t count) {
  if (index < 0 || static_cast<std::size_t>(index) >= count) badIndex(index, count);
}

// One activation of the listing's recursive CSG(): the entry, how far the
// evaluation has got, and the left operand once it is known.
struct Frame {
  // A constructor, not aggregate initialisation: GCC zero-fills an aggregate
  // temporary (the 400-byte inline list) before copying it onto the stack.
  explicit Frame(int e) noexcept : entry(e) {}
  int entry;
  int stage = 0;  // 0: start; 1: left subtree done; 2: right subtree done
  TList left;
};

}  // namespace

// CSG (3248-3304). The recursion of the listing becomes an explicit stack:
//   while(!IsPrim(obj)) { ReadObj(l); ReadObj(r); CSG(objL, tList);
//     if((op == '+') || (tList != NULL)) { CSG(objR, &newTList); Union/Difference/Intersection }
//     return; }
//   IntersectPrim(ray, obj->l, tList);
// The `while` runs at most once (it returns), so it is an `if`.
TList csg1991(std::span<const CsgEntry> entries, LeafFn leaf, const Csg1991Options& options,
              int root) {
  checkIndex(root, entries.size());
  SmallVec<Frame, 8> stack;
  TList ret;  // the tList the last finished activation produced

  // A tree of n entries has no root path longer than n; a longer one
  // revisits an entry, and the listing would recurse until the stack overflowed.
  // Shared subtrees (an entry referenced twice) are legal for the listing and
  // evaluated once per reference, but nested sharing grows exponentially:
  // options.maxVisits bounds the work.
  std::size_t visits = 0;
  auto push = [&](int entry) {
    if (stack.size() >= entries.size())
      throw CsgError(CsgError::Kind::kCycle,
                     "CSG(): the object's tree has a cycle through entry " + std::to_string(entry));
    if (++visits > options.maxVisits)
      throw CsgError(CsgError::Kind::kTooManyVisits, "CSG(): more than " +
                                                         std::to_string(options.maxVisits) +
                                                         " tree entries visited (shared subtrees)");
    stack.emplace_back(entry);
  };

  push(root);
  while (!stack.empty()) {
    Frame& f = stack.back();
    const CsgEntry& e = entries[static_cast<std::size_t>(f.entry)];
    if (e.op == 'P') {  // IsPrim (6449-6460)
      // IntersectPrim (4508-4570): AddToTList only when the ray hits. The
      // listing's *tList is always NULL here (the caller starts from NULL,
      // and right subtrees from the fresh newTList), so the leaf's list is
      // exactly its pair or empty.
      ret.clear();
      if (const std::optional<PrimHit> hit = leaf(e.l))
        ret.addPair(hit->tIn, hit->tOut, hit->nIn, hit->nOut, e.l);
      stack.pop_back();
      continue;
    }
    switch (f.stage) {
      case 0:
        checkIndex(e.l, entries.size());  // ReadObj(obj->l, objL) 3268
        checkIndex(e.r, entries.size());  // ReadObj(obj->r, objR) 3269
        f.stage = 1;
        push(e.l);  // CSG(objL, tList) 3270 (may reallocate: `f` is not used after)
        break;
      case 1:
        f.left = std::move(ret);
        ret.clear();
        // 3271: printed `(tList != NULL)` is always true (K29); Q4's
        // `(*tList != NULL)` is the option.
        if (e.op == '+' || !options.skipRightWhenLeftEmpty || !f.left.empty()) {
          f.stage = 2;
          push(e.r);  // ReadObj(obj->r) again (3273), CSG(objR, &newTList) 3274
        } else {
          ret = std::move(f.left);  // empty
          stack.pop_back();
        }
        break;
      default: {
        TList& newTList = ret;
        switch (e.op) {  // 3275-3297
          case '+':
            union1991(f.left, newTList);
            break;
          case '-':
            difference1991(f.left, newTList);
            break;
          case '&':
            intersection1991(f.left, newTList);
            break;
          default:
            throw CsgError(CsgError::Kind::kBadOpcode,
                           std::string("switch case fell to default. Module Roth. Program CSG "
                                       "(opcode '") +
                               e.op + "' at entry " + std::to_string(f.entry) + ")");
        }
        ret = std::move(f.left);
        stack.pop_back();
        break;
      }
    }
  }
  return ret;
}

}  // namespace prime
