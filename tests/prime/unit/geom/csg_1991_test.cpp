// Unit tests of the 1991 tList module emulation (interval_list.h) and of the
// CSG module as printed (csg_1991.h).
//
// Every expected list below was obtained by tracing the printed C of the
// listing by hand (CSG.c and tList.c of Appendix A of O'Reilly's 1991 DCU
// thesis; the numbers are OCR line numbers of its transcription, see
// docs/prime/listing-errata.md; read with errata E12/E13), never by running
// the port. Trace notation:
//   A = *tList (left operand), B = *tList1 (right); a0/a1, b0/b1 = the val of
//   their front pairs; "out" = the list hung off tmpPtDummy (tListPos).
//   Copy(x->y) copies node x's data (val, primNum, surfType, norm) onto y.
//   Add(X) moves X's front pair to out; Kill(X) drops it.
// Node shorthand: en(t,p) = an entry node as AddToTList builds it for prim p
// (surfType Out, norm nIn(p)); ex(t,p) = an exit node (surfType In, nOut(p)).
// Branch ids U1..U13, D1..D13, I1..I13 are those of docs/prime/port-notes/csg.md.
#include "src/prime/geom/csg_1991.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <vector>

#include "src/prime/geom/interval_list.h"
#include "tests/prime/unit/geom/tlist_builders.h"

namespace prime {
namespace {

using namespace tlist_builders;

using Op = void (*)(TList&, TList&);
TList run(Op op, TList a, TList b) {
  op(a, b);
  EXPECT_TRUE(b.empty()) << "*tList1 must be NULL after the operator";
  return a;
}
TList uni(TList a, TList b) {
  return run(&union1991, std::move(a), std::move(b));
}
TList dif(TList a, TList b) {
  return run(&difference1991, std::move(a), std::move(b));
}
TList isect(TList a, TList b) {
  return run(&intersection1991, std::move(a), std::move(b));
}

// The A of all single-pair branch tests: [2,4], prim 1. B is prim 2.
TList A() {
  return L({{2, 4, 1}});
}

void expectE57(Op op, TList a, TList b) {
  try {
    op(a, b);
    ADD_FAILURE() << "expected the E57 error";
  } catch (const CsgError& e) {
    EXPECT_EQ(e.kind(), CsgError::Kind::kKillEmptyList);
    EXPECT_NE(std::string(e.what()).find("E57"), std::string::npos);
  }
}

// ---------------------------------------------------------------------------
// tList module (7867-7983): AddToTList, TListDel, storage.

TEST(TListModule, AddToTListBuildsEntryOutThenExitIn) {
  // 7898-7911: node 1 = {t1, primNum, Out, nIn}, node 2 = {t2, primNum, In, nOut}.
  const TList l = TList::pair(1.5, 2.5, nIn(7), nOut(7), 7);
  ASSERT_EQ(l.size(), 2u);
  EXPECT_EQ(l[0], (TNode{1.5, 7, kSurfOut, nIn(7)}));
  EXPECT_EQ(l[1], (TNode{2.5, 7, kSurfIn, nOut(7)}));
  EXPECT_EQ(l.pairCount(), 1u);
  EXPECT_EQ(l.entry(0), en(1.5, 7));
  EXPECT_EQ(l.exit(0), ex(2.5, 7));
  EXPECT_EQ(kSurfOut, 0);  // Define.h 2357
  EXPECT_EQ(kSurfIn, 1);   // Define.h 2358
}

TEST(TListModule, TListDelEmptiesTheList) {
  TList l = L({{0, 1, 1}, {2, 3, 2}});
  l.clear();
  EXPECT_TRUE(l.empty());
}

TEST(TListModule, SmallBufferSpillsToHeapAndCopiesAndMovesKeepNodes) {
  TList small = L({{0, 1, 1}, {2, 3, 2}, {4, 5, 3}, {6, 7, 4}});  // 8 nodes: inline
  EXPECT_FALSE(small.usesHeap());
  TList big = small;
  big.addPair(8, 9, nIn(5), nOut(5), 5);  // 10 nodes: heap
  EXPECT_TRUE(big.usesHeap());
  EXPECT_EQ(big.size(), 10u);
  EXPECT_EQ(big[8], en(8, 5));
  EXPECT_EQ(big[3], ex(3, 2));

  TList bigCopy = big;
  EXPECT_EQ(bigCopy, big);
  TList bigMoved = std::move(bigCopy);
  EXPECT_EQ(bigMoved, big);
  TList smallMoved = std::move(small);
  EXPECT_EQ(smallMoved, L({{0, 1, 1}, {2, 3, 2}, {4, 5, 3}, {6, 7, 4}}));
  smallMoved = big;  // copy-assign heap into inline
  EXPECT_EQ(smallMoved, big);
  big = L({{0, 1, 9}});  // move-assign inline into heap
  EXPECT_EQ(big, L({{0, 1, 9}}));
  EXPECT_FALSE(big.usesHeap());
}

// ---------------------------------------------------------------------------
// Union (3306-3436).

TEST(Union1991, U1_L3326_BBeforeA) {
  // 3324 b0=0<a0=2; 3326 b1=1<2 -> 3333 Add(B): out=[en0/2 ex1/2], B=NULL.
  // 3426 Add(A): out+=[en2/1 ex4/1].
  EXPECT_EQ(uni(A(), L({{0, 1, 2}})), (TList{en(0, 2), ex(1, 2), en(2, 1), ex(4, 1)}));
}

TEST(Union1991, U2_L3339_BOverlapsAFromBefore) {
  // 3324 1<2; 3326 3<2 no; 3337 3>2; 3339 3<4 -> 3341 Copy(B.next->A.first):
  // A=[ex3/2 ex4/1]; 3342 Add(B): out=[en1/2 ex3/2]; 3426 Add(A).
  // Point-set correct, but two pairs meeting at 3, the second opening with an In node.
  EXPECT_EQ(uni(A(), L({{1, 3, 2}})), (TList{en(1, 2), ex(3, 2), ex(3, 2), ex(4, 1)}));
}

TEST(Union1991, U3_L3348_Q3_BCoversA_DegenerateB1B1) {
  // Q3 (3348-3349). 3339 5<4 no; 3346 5>4 -> 3348 Copy(B.first->A.first):
  // A=[en1/2 ex4/1]; 3349 Copy(B.next->B.first): B=[ex5/2 ex5/2]; 3350 Add(A):
  // out=[en1/2 ex4/1]; A=NULL. 3430 Add(B): out+=[ex5/2 ex5/2]. (4,5) is lost.
  EXPECT_EQ(uni(A(), L({{1, 5, 2}})), (TList{en(1, 2), ex(4, 1), ex(5, 2), ex(5, 2)}));
}

TEST(Union1991, U3_L3348_Q3_LossAcrossANextPair) {
  // A=[2,4]/1,[4.5,4.8]/3, B=[1,5]/2. iter1 = U3: out=[en1/2 ex4/1], B=[ex5/2 ex5/2].
  // iter2 A=[4.5,4.8] B=[5,5]: 3324 no; 3367 5>4.5; 3369 5<4.8 no; 3376 5>4.8;
  // 3378 5>4.8 -> 3380 Add(A): out+=[en4.5/3 ex4.8/3]. 3430 Add(B): [ex5/2 ex5/2].
  EXPECT_EQ(uni(L({{2, 4, 1}, {4.5, 4.8, 3}}), L({{1, 5, 2}})),
            (TList{en(1, 2), ex(4, 1), en(4.5, 3), ex(4.8, 3), ex(5, 2), ex(5, 2)}));
}

TEST(Union1991, U4_L3352_BStartsBeforeSameEnd) {
  // 3346 4>4 no -> 3352: 3354 Add(B): out=[en1/2 ex4/2]; 3355 Kill(A).
  EXPECT_EQ(uni(A(), L({{1, 4, 2}})), (TList{en(1, 2), ex(4, 2)}));
}

TEST(Union1991, U5_L3359_BTouchesAFromBefore) {
  // 3326 2<2 no; 3337 2>2 no -> 3359: 3361 Add(B). 3426 Add(A).
  EXPECT_EQ(uni(A(), L({{1, 2, 2}})), (TList{en(1, 2), ex(2, 2), en(2, 1), ex(4, 1)}));
}

TEST(Union1991, U6_L3369_BInsideA) {
  // 3367 2.5>2; 3369 3.5<4 -> 3371 Add(A); 3372 Kill(B).
  EXPECT_EQ(uni(A(), L({{2.5, 3.5, 2}})), (TList{en(2, 1), ex(4, 1)}));
}

TEST(Union1991, U7_L3378_BAfterA) {
  // 3369 6<4 no; 3376 6>4; 3378 5>4 -> 3380 Add(A). A=NULL; 3430 Add(B).
  EXPECT_EQ(uni(A(), L({{5, 6, 2}})), (TList{en(2, 1), ex(4, 1), en(5, 2), ex(6, 2)}));
}

TEST(Union1991, U8_L3386_Q3_BOverlapsAFromAfter_DegenerateB1B1) {
  // Q3 (3386). 3376 5>4; 3378 3>4 no; 3384 3<4 -> 3386 Copy(B.next->B.first):
  // B=[ex5/2 ex5/2]; 3387 Add(A): out=[en2/1 ex4/1]; 3430 Add(B). (4,5) lost.
  EXPECT_EQ(uni(A(), L({{3, 5, 2}})), (TList{en(2, 1), ex(4, 1), ex(5, 2), ex(5, 2)}));
}

TEST(Union1991, U8_L3386_Q3_LossAcrossANextPair) {
  // A=[0,2]/1,[3,5]/3, B=[1,6]/2. iter1: 3367 1>0; 3369 6<2 no; 3376 6>2;
  // 3378 1>2 no; 3384 1<2 -> U8: B=[ex6/2 ex6/2]; Add(A): out=[en0/1 ex2/1].
  // iter2 A=[3,5] B=[6,6]: 3367 6>3; 3369 6<5 no; 3376 6>5; 3378 6>5 -> U7
  // Add(A): out+=[en3/3 ex5/3]. A=NULL; 3430 Add(B): [ex6/2 ex6/2]. True union: [0,6].
  EXPECT_EQ(uni(L({{0, 2, 1}, {3, 5, 3}}), L({{1, 6, 2}})),
            (TList{en(0, 1), ex(2, 1), en(3, 3), ex(5, 3), ex(6, 2), ex(6, 2)}));
}

TEST(Union1991, U9_L3389_BTouchesAFromAfter) {
  // 3378 4>4 no; 3384 4<4 no -> 3389: 3391 Add(A). 3430 Add(B).
  EXPECT_EQ(uni(A(), L({{4, 6, 2}})), (TList{en(2, 1), ex(4, 1), en(4, 2), ex(6, 2)}));
}

TEST(Union1991, U10_L3395_BStartsInsideSameEnd) {
  // 3369 4<4 no; 3376 4>4 no -> 3395: 3397 Add(A); 3398 Kill(B).
  EXPECT_EQ(uni(A(), L({{3, 4, 2}})), (TList{en(2, 1), ex(4, 1)}));
}

TEST(Union1991, U11_L3404_SameStartBShorter) {
  // 3324 no; 3367 no -> 3402; 3404 3<4 -> 3406 Copy(B.next->A.first):
  // A=[ex3/2 ex4/1]; 3407 Add(B): out=[en2/2 ex3/2]; 3426 Add(A).
  EXPECT_EQ(uni(A(), L({{2, 3, 2}})), (TList{en(2, 2), ex(3, 2), ex(3, 2), ex(4, 1)}));
}

TEST(Union1991, U12_L3413_Q3_SameStartBLonger_DegenerateB1B1) {
  // Q3 (3413). 3404 no; 3411 5>4 -> 3413 Copy(B.next->B.first): B=[ex5/2 ex5/2];
  // 3414 Add(A): out=[en2/1 ex4/1]; 3430 Add(B). (4,5) lost.
  EXPECT_EQ(uni(A(), L({{2, 5, 2}})), (TList{en(2, 1), ex(4, 1), ex(5, 2), ex(5, 2)}));
}

TEST(Union1991, U13_L3416_EqualPairs) {
  // 3404 no; 3411 no -> 3416: 3418 Add(A); 3419 Kill(B).
  EXPECT_EQ(uni(A(), L({{2, 4, 2}})), (TList{en(2, 1), ex(4, 1)}));
}

TEST(Union1991, MultiPairDisjointComesOutSorted) {
  // A=[0,1]/1,[4,5]/3, B=[2,3]/2. iter1: 3367 2>0; 3369 3<1 no; 3376 3>1;
  // 3378 2>1 -> U7 Add(A): out=[en0/1 ex1/1]. iter2 A=[4,5]: 3324 2<4; 3326 3<4
  // -> U1 Add(B): out+=[en2/2 ex3/2]. B=NULL; 3426 Add(A): [en4/3 ex5/3].
  EXPECT_EQ(uni(L({{0, 1, 1}, {4, 5, 3}}), L({{2, 3, 2}})),
            (TList{en(0, 1), ex(1, 1), en(2, 2), ex(3, 2), en(4, 3), ex(5, 3)}));
}

TEST(Union1991, EmptyOperands) {
  // Loop skipped; 3426/3430 Add whatever is left.
  EXPECT_EQ(uni(A(), TList{}), A());
  EXPECT_EQ(uni(TList{}, L({{1, 3, 2}})), L({{1, 3, 2}}));
  EXPECT_EQ(uni(TList{}, TList{}), TList{});
}

TEST(Union1991, NaNComparisonsFallToTheEqualBranches) {
  // Comparisons as printed: with b0 = b1 = NaN every < and > is false, so
  // 3324 no, 3367 no -> 3402; 3404 no, 3411 no -> U13 3416: Add(A); Kill(B).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  TList b;
  b.addPair(nan, nan, nIn(2), nOut(2), 2);
  EXPECT_EQ(uni(A(), b), (TList{en(2, 1), ex(4, 1)}));
}

// ---------------------------------------------------------------------------
// Difference (3442-3582).

TEST(Difference1991, D1_L3465_BBeforeA) {
  // 3463 0<2; 3465 1<2 -> 3467 Kill(B). B=NULL; 3572 Add(A).
  EXPECT_EQ(dif(A(), L({{0, 1, 2}})), (TList{en(2, 1), ex(4, 1)}));
}

TEST(Difference1991, D2_L3473_BOverlapsAFromBefore) {
  // 3465 3<2 no; 3471 3>2; 3473 3<4 -> 3475 Copy(B.next->A.first):
  // A=[ex3/2 ex4/1]; 3476 Kill(B); 3572 Add(A). Right interval; the entry node
  // is B's exit node as it is (surfType In, B's exit normal).
  EXPECT_EQ(dif(A(), L({{1, 3, 2}})), (TList{ex(3, 2), ex(4, 1)}));
}

TEST(Difference1991, D3_L3482_Q3_BCoversA_InvertedPair) {
  // Q3 (3482, /*?*/). 3473 5<4 no; 3480 5>4 -> 3482 Copy(B.next->A.first):
  // A=[ex5/2 ex4/1]; 3483 Kill(B); 3572 Add(A): the inverted pair [5,4].
  EXPECT_EQ(dif(A(), L({{1, 5, 2}})), (TList{ex(5, 2), ex(4, 1)}));
}

TEST(Difference1991, D4_L3487_Q3_E57_SameEndSingleBPairKillsEmptyList) {
  // Q3/E57 (3487-3488). 3480 4>4 no -> 3485: 3487 Kill(B): B=NULL;
  // 3488 Kill(NULL) -> Free() Error (E57).
  expectE57(&difference1991, A(), L({{1, 4, 2}}));
}

TEST(Difference1991, D4_L3487_Q3_SameEndKillsTheNextBPairToo) {
  // Q3 (3487-3488). A=[2,4]/1,[5,7]/4, B=[1,4]/2,[6,8]/3. iter1 = D4: both B
  // pairs Killed; B=NULL. 3572 Add(A) twice. True difference: [5,6].
  EXPECT_EQ(dif(L({{2, 4, 1}, {5, 7, 4}}), L({{1, 4, 2}, {6, 8, 3}})),
            (TList{en(2, 1), ex(4, 1), en(5, 4), ex(7, 4)}));
}

TEST(Difference1991, D5_L3493_BTouchesAFromBefore) {
  // 3465 2<2 no; 3471 2>2 no -> 3493: 3495 Kill(B). 3572 Add(A).
  EXPECT_EQ(dif(A(), L({{1, 2, 2}})), (TList{en(2, 1), ex(4, 1)}));
}

TEST(Difference1991, D6_L3503_K31_BInsideA) {
  // K31 (3505-3511). 3501 2.5>2; 3503 3.5<4 -> tmpVal=2, tmpPrimNum=1;
  // 3507 Copy(B.next->A.first): A=[ex3.5/2 ex4/1];
  // 3508 Copy(B.first->B.next): B=[en2.5/2 en2.5/2];
  // 3509-3510 B.first.val=2, .primNum=1: B.first={2, p1, Out, nIn(2)};
  // 3511 Add(B): out=[{2,p1,Out,nIn(2)} en2.5/2]; 3572 Add(A): [ex3.5/2 ex4/1].
  EXPECT_EQ(dif(A(), L({{2.5, 3.5, 2}})),
            (TList{TNode{2, 1, kSurfOut, nIn(2)}, en(2.5, 2), ex(3.5, 2), ex(4, 1)}));
}

TEST(Difference1991, D7_L3519_Q3_K30_BAfterAIsOutputFirst) {
  // Q3 (3519, /*?*/), K30. 3503 6<4 no; 3515 6>4; 3517 5>4 -> 3519 Add(B):
  // out=[en5/2 ex6/2]; B=NULL; 3572 Add(A). The FIRST node (what IntersectObj
  // reports) is B's entry at t=5, not A's at t=2.
  const TList r = dif(A(), L({{5, 6, 2}}));
  EXPECT_EQ(r, (TList{en(5, 2), ex(6, 2), en(2, 1), ex(4, 1)}));
  EXPECT_EQ(r.front(), en(5, 2));
}

TEST(Difference1991, D7_L3519_Q3_EveryLaterBPairIsOutput) {
  // A=[2,4]/1, B=[0,1]/2,[5,6]/3,[7,8]/4. iter1 D1 (3465 1<2): Kill. iter2 D7:
  // Add(B) [en5/3 ex6/3]. iter3 D7: Add(B) [en7/4 ex8/4]. B=NULL; 3572 Add(A).
  EXPECT_EQ(dif(A(), L({{0, 1, 2}, {5, 6, 3}, {7, 8, 4}})),
            (TList{en(5, 3), ex(6, 3), en(7, 4), ex(8, 4), en(2, 1), ex(4, 1)}));
}

TEST(Difference1991, D8_L3525_Q3_BOverlapsAFromAfter) {
  // Q3 (3525-3526). 3517 3>4 no; 3523 3<4 -> 3525 Copy(B.first->A.next):
  // A=[en2/1 en3/2]; 3526 Add(B): out=[en3/2 ex5/2]; 3572 Add(A).
  EXPECT_EQ(dif(A(), L({{3, 5, 2}})), (TList{en(3, 2), ex(5, 2), en(2, 1), en(3, 2)}));
}

TEST(Difference1991, D8_L3525_Q3_WithASecondPair) {
  // A=[0,2]/1,[3,5]/3, B=[1,4]/2. iter1: 3463 1<0 no; 3501 1>0; 3503 4<2 no;
  // 3515 4>2; 3517 1>2 no; 3523 1<2 -> D8: A=[en0/1 en1/2],[3,5]; Add(B):
  // out=[en1/2 ex4/2]. B=NULL; 3572 Add(A) twice. True difference: [0,1],[4,5].
  EXPECT_EQ(dif(L({{0, 2, 1}, {3, 5, 3}}), L({{1, 4, 2}})),
            (TList{en(1, 2), ex(4, 2), en(0, 1), en(1, 2), en(3, 3), ex(5, 3)}));
}

TEST(Difference1991, D9_L3530_Q3_BTouchesAFromAfterIsOutput) {
  // Q3 (3530). 3517 4>4 no; 3523 4<4 no -> 3528: 3530 Add(B); 3572 Add(A).
  EXPECT_EQ(dif(A(), L({{4, 6, 2}})), (TList{en(4, 2), ex(6, 2), en(2, 1), ex(4, 1)}));
}

TEST(Difference1991, D10_L3537_Q3_E57_SameEndSingleBPairKillsEmptyList) {
  // Q3/E57 (3537-3539). 3503 4<4 no; 3515 4>4 no -> 3535: 3537 Copy; 3538
  // Add(B): B=NULL; 3539 Kill(NULL) -> E57.
  expectE57(&difference1991, A(), L({{3, 4, 2}}));
}

TEST(Difference1991, D10_L3537_Q3_SameEndOutputsBAndKillsNextBPair) {
  // Q3 (3537-3539). B=[3,4]/2,[5,6]/3. 3537 Copy(B.first->A.next):
  // A=[en2/1 en3/2]; 3538 Add(B): out=[en3/2 ex4/2]; 3539 Kill(B): [5,6] gone.
  // B=NULL; 3572 Add(A).
  EXPECT_EQ(dif(A(), L({{3, 4, 2}, {5, 6, 3}})), (TList{en(3, 2), ex(4, 2), en(2, 1), en(3, 2)}));
}

TEST(Difference1991, D11_L3545_SameStartBShorter) {
  // 3463 no; 3501 no -> 3543; 3545 3<4 -> 3547 Copy(B.next->A.first):
  // A=[ex3/2 ex4/1]; 3548 Kill(B); 3572 Add(A).
  EXPECT_EQ(dif(A(), L({{2, 3, 2}})), (TList{ex(3, 2), ex(4, 1)}));
}

TEST(Difference1991, D12_L3554_Q3_SameStartBLonger_InvertedPair) {
  // Q3 (3554-3555). 3545 no; 3552 5>4 -> 3554 Copy(B.next->A.first):
  // A=[ex5/2 ex4/1]; 3555 Kill(B); 3572 Add(A): inverted [5,4].
  EXPECT_EQ(dif(A(), L({{2, 5, 2}})), (TList{ex(5, 2), ex(4, 1)}));
}

TEST(Difference1991, D13_L3559_Q3_E57_EqualSingleBPairKillsEmptyList) {
  // Q3/E57 (3559-3560). 3545 no; 3552 no -> 3557: 3559 Kill(B): B=NULL;
  // 3560 Kill(NULL) -> E57.
  expectE57(&difference1991, A(), L({{2, 4, 2}}));
}

TEST(Difference1991, D13_L3559_Q3_EqualPairsASurvives) {
  // Q3 (3559-3560). B=[2,4]/2,[5,6]/3: both Killed; 3572 Add(A). True result: empty.
  EXPECT_EQ(dif(A(), L({{2, 4, 2}, {5, 6, 3}})), (TList{en(2, 1), ex(4, 1)}));
}

TEST(Difference1991, EmptyOperands) {
  // A=NULL: loop skipped, 3572 nothing, 3576 Kill(B) until NULL -> empty.
  EXPECT_EQ(dif(TList{}, L({{1, 2, 2}, {3, 4, 3}})), TList{});
  // B=NULL: 3572 Add(A).
  EXPECT_EQ(dif(A(), TList{}), A());
}

// ---------------------------------------------------------------------------
// Intersection (3584-3712).

TEST(Intersection1991, I1_L3601_BBeforeA) {
  // 3599 0<2; 3601 1<2 -> 3603 Kill(B). 3702 Kill(A). -> NULL.
  EXPECT_EQ(isect(A(), L({{0, 1, 2}})), TList{});
}

TEST(Intersection1991, I2_L3609_E13_BOverlapsAFromBefore) {
  // E13. 3601 3<2 no; 3607 3>2; 3609 3<4 -> 3611 Copy(A.first->B.first):
  // B=[en2/1 ex3/2]; 3612 Copy(B.next->A.first): A=[ex3/2 ex4/1];
  // 3613 Add(B): out=[en2/1 ex3/2]. 3702 Kill(A).
  EXPECT_EQ(isect(A(), L({{1, 3, 2}})), (TList{en(2, 1), ex(3, 2)}));
}

TEST(Intersection1991, I3_L3619_Q3_BCoversAOutputsA1B1) {
  // Q3 (3619-3620). 3609 5<4 no; 3617 5>4 -> 3619 Copy(A.next->B.first):
  // B=[ex4/1 ex5/2]; 3620 Add(B): out=[ex4/1 ex5/2]. B=NULL; 3702 Kill(A).
  EXPECT_EQ(isect(A(), L({{1, 5, 2}})), (TList{ex(4, 1), ex(5, 2)}));
}

TEST(Intersection1991, I3_L3619_Q3_LaterAPairsAreKilled) {
  // Q3. A=[2,4]/1,[4.5,6]/3, B=[1,5]/2. iter1 = I3: out=[ex4/1 ex5/2], B=NULL.
  // 3702 Kill(A) twice. True intersection: [2,4],[4.5,5].
  EXPECT_EQ(isect(L({{2, 4, 1}, {4.5, 6, 3}}), L({{1, 5, 2}})), (TList{ex(4, 1), ex(5, 2)}));
}

TEST(Intersection1991, I4_L3622_BStartsBeforeSameEnd) {
  // 3617 4>4 no -> 3622: 3624 Add(A); 3625 Kill(B).
  EXPECT_EQ(isect(A(), L({{1, 4, 2}})), (TList{en(2, 1), ex(4, 1)}));
}

TEST(Intersection1991, I5_L3631_BTouchesAFromBefore) {
  // 3601 2<2 no; 3607 2>2 no -> 3631: 3633 Kill(B). 3702 Kill(A).
  EXPECT_EQ(isect(A(), L({{1, 2, 2}})), TList{});
}

TEST(Intersection1991, I6_L3640_BInsideA) {
  // 3638 2.5>2; 3640 3.5<4 -> 3642 Copy(B.next->A.first): A=[ex3.5/2 ex4/1];
  // 3643 Add(B): out=[en2.5/2 ex3.5/2]. 3702 Kill(A).
  EXPECT_EQ(isect(A(), L({{2.5, 3.5, 2}})), (TList{en(2.5, 2), ex(3.5, 2)}));
}

TEST(Intersection1991, I7_L3649_BAfterA) {
  // 3640 6<4 no; 3647 6>4; 3649 5>4 -> 3651 Kill(A). 3706 Kill(B).
  EXPECT_EQ(isect(A(), L({{5, 6, 2}})), TList{});
}

TEST(Intersection1991, I8_L3655_BOverlapsAFromAfter) {
  // 3649 3>4 no; 3655 3<4 -> 3657 Copy(B.first->A.first): A=[en3/2 ex4/1];
  // 3658 Copy(B.next->B.first): B=[ex5/2 ex5/2]; 3659 Add(A): out=[en3/2 ex4/1].
  // A=NULL; 3706 Kill(B).
  EXPECT_EQ(isect(A(), L({{3, 5, 2}})), (TList{en(3, 2), ex(4, 1)}));
}

TEST(Intersection1991, I8_L3658_DegenerateB1B1MeetsTheNextAPair) {
  // Not in Q3's list, same pattern as Union 3349 (docs/prime/port-notes/csg.md).
  // A=[2,4]/1,[4.5,6]/3, B=[3,5]/2. iter1 = I8: out=[en3/2 ex4/1], B=[ex5/2 ex5/2].
  // iter2 A=[4.5,6] B=[5,5]: 3599 5<4.5 no; 3638 5>4.5; 3640 5<6 -> I6:
  // 3642 Copy(B.next->A.first): A=[ex5/2 ex6/3]; 3643 Add(B): out+=[ex5/2 ex5/2].
  // B=NULL; 3702 Kill(A). True intersection: [3,4],[4.5,5].
  EXPECT_EQ(isect(L({{2, 4, 1}, {4.5, 6, 3}}), L({{3, 5, 2}})),
            (TList{en(3, 2), ex(4, 1), ex(5, 2), ex(5, 2)}));
}

TEST(Intersection1991, I9_L3661_BTouchesAFromAfter) {
  // 3649 4>4 no; 3655 4<4 no -> 3661: 3663 Kill(A). 3706 Kill(B).
  EXPECT_EQ(isect(A(), L({{4, 6, 2}})), TList{});
}

TEST(Intersection1991, I10_L3669_BStartsInsideSameEnd) {
  // 3640 4<4 no; 3647 4>4 no -> 3669: 3671 Add(B); 3672 Kill(A).
  EXPECT_EQ(isect(A(), L({{3, 4, 2}})), (TList{en(3, 2), ex(4, 2)}));
}

TEST(Intersection1991, I11_L3678_SameStartBShorter) {
  // 3599 no; 3638 no -> 3676; 3678 3<4 -> 3680 Copy(B.next->A.first):
  // A=[ex3/2 ex4/1]; 3681 Add(B): out=[en2/2 ex3/2]. 3702 Kill(A).
  EXPECT_EQ(isect(A(), L({{2, 3, 2}})), (TList{en(2, 2), ex(3, 2)}));
}

TEST(Intersection1991, I12_L3685_SameStartBLonger) {
  // 3678 no; 3685 5>4 -> 3691 Copy(A.next->B.first): B=[ex4/1 ex5/2];
  // 3692 Add(A): out=[en2/1 ex4/1]. A=NULL; 3706 Kill(B).
  EXPECT_EQ(isect(A(), L({{2, 5, 2}})), (TList{en(2, 1), ex(4, 1)}));
}

TEST(Intersection1991, I13_L3694_EqualPairs) {
  // 3694: 3696 Add(A); 3697 Kill(B).
  EXPECT_EQ(isect(A(), L({{2, 4, 2}})), (TList{en(2, 1), ex(4, 1)}));
}

TEST(Intersection1991, MultiPairCorrectCase) {
  // A=[2,6]/1, B=[1,3]/2,[4,5]/3. iter1 = I2: B=[en2/1 ex3/2], A=[ex3/2 ex6/1],
  // out=[en2/1 ex3/2]. iter2 A=[3,6] B=[4,5]: 3599 4<3 no; 3638 4>3; 3640 5<6
  // -> I6: A=[ex5/3 ex6/1]; out+=[en4/3 ex5/3]. B=NULL; 3702 Kill(A).
  EXPECT_EQ(isect(L({{2, 6, 1}}), L({{1, 3, 2}, {4, 5, 3}})),
            (TList{en(2, 1), ex(3, 2), en(4, 3), ex(5, 3)}));
}

TEST(Intersection1991, EmptyOperands) {
  // Loop skipped; 3702/3706 Kill everything.
  EXPECT_EQ(isect(A(), TList{}), TList{});
  EXPECT_EQ(isect(TList{}, A()), TList{});
}

// ---------------------------------------------------------------------------
// Operand checks.

TEST(Operators1991, OddNodeCountIsRejected) {
  TList odd{en(1, 1)};
  TList b = A();
  try {
    union1991(odd, b);
    ADD_FAILURE() << "expected kOddList";
  } catch (const CsgError& e) {
    EXPECT_EQ(e.kind(), CsgError::Kind::kOddList);
  }
}

// ---------------------------------------------------------------------------
// CSG() tree walk (3248-3304).

// A leaf callback over a table of hits; records the primitive numbers asked for.
struct Leaves {
  std::map<int, std::pair<double, double>> hits;
  std::vector<int> calls;
  std::optional<PrimHit> operator()(int prim) {
    calls.push_back(prim);
    const auto it = hits.find(prim);
    if (it == hits.end()) return std::nullopt;
    return PrimHit{it->second.first, it->second.second, nIn(prim), nOut(prim)};
  }
};

TEST(Csg1991, SingleLeafHitIsAddToTListPair) {
  // 3264 IsPrim -> 3303 IntersectPrim -> AddToTList(tList, tIn, tOut, nIn, nOut, obj->l).
  Leaves leaves{{{7, {1.0, 2.0}}}, {}};
  const std::vector<CsgEntry> tree{{'P', 7, 0}};
  EXPECT_EQ(csg1991(tree, leaves), (TList{en(1, 7), ex(2, 7)}));
  EXPECT_EQ(leaves.calls, std::vector<int>{7});
}

TEST(Csg1991, SingleLeafMissIsEmpty) {
  Leaves leaves;
  const std::vector<CsgEntry> tree{{'P', 7, 0}};
  EXPECT_TRUE(csg1991(tree, leaves).empty());
}

TEST(Csg1991, ThesisExampleTree_Sec532) {
  // Sec. 5.3.2: "5 / + 1 4 / - 2 3 / B 1 / B 2 / C 1" (K35) as entries; prims
  // 1, 2, 3 hit [2,6], [3,4], [8,9]. Walk: entry0 -> entry1 -> leaf prim1, leaf
  // prim2 -> Difference([2,6]/1, [3,4]/2) = D6 (K31): out=[{2,p1,Out,nIn(2)}
  // en3/2] + A=[ex4/2 ex6/1]. Then leaf prim3 [8,9]; Union: iter1 A=[2,3]:
  // 3367 8>2; 3369 9<3 no; 3376 9>3; 3378 8>3 -> U7 Add(A). iter2 A=[4,6]:
  // same -> U7 Add(A). 3430 Add(B) [en8/3 ex9/3].
  Leaves leaves{{{1, {2.0, 6.0}}, {2, {3.0, 4.0}}, {3, {8.0, 9.0}}}, {}};
  const std::vector<CsgEntry> tree{{'+', 1, 4}, {'-', 2, 3}, {'P', 1, 0}, {'P', 2, 0}, {'P', 3, 0}};
  EXPECT_EQ(csg1991(tree, leaves), (TList{TNode{2, 1, kSurfOut, nIn(2)}, en(3, 2), ex(4, 2),
                                          ex(6, 1), en(8, 3), ex(9, 3)}));
  EXPECT_EQ(leaves.calls, (std::vector<int>{1, 2, 3}));
}

TEST(Csg1991, K29_RightSubtreeAlwaysEvaluated) {
  // 3271 `(tList != NULL)` is always true: the right leaf is intersected even
  // though the left one missed. Difference(NULL, [1,2]) -> 3576 Kill -> NULL;
  // Intersection(NULL, [1,2]) -> 3706 Kill -> NULL.
  for (char op : {'-', '&'}) {
    Leaves leaves{{{2, {1.0, 2.0}}}, {}};
    const std::vector<CsgEntry> tree{{op, 1, 2}, {'P', 1, 0}, {'P', 2, 0}};
    EXPECT_TRUE(csg1991(tree, leaves).empty()) << op;
    EXPECT_EQ(leaves.calls, (std::vector<int>{1, 2})) << op;
  }
}

TEST(Csg1991, Q4_OptionSkipsRightSubtreeOfEmptyDifferenceOrIntersection) {
  // Q4 alternative `(*tList != NULL)`: same (empty) results, right leaf skipped.
  Csg1991Options q4;
  q4.skipRightWhenLeftEmpty = true;
  for (char op : {'-', '&'}) {
    Leaves leaves{{{2, {1.0, 2.0}}}, {}};
    const std::vector<CsgEntry> tree{{op, 1, 2}, {'P', 1, 0}, {'P', 2, 0}};
    EXPECT_TRUE(csg1991(tree, leaves, q4).empty()) << op;
    EXPECT_EQ(leaves.calls, std::vector<int>{1}) << op;
  }
  // '+' still evaluates the right side: Union(NULL, [1,2]) -> 3430 Add(B).
  Leaves leaves{{{2, {1.0, 2.0}}}, {}};
  const std::vector<CsgEntry> tree{{'+', 1, 2}, {'P', 1, 0}, {'P', 2, 0}};
  EXPECT_EQ(csg1991(tree, leaves, q4), (TList{en(1, 2), ex(2, 2)}));
  EXPECT_EQ(leaves.calls, (std::vector<int>{1, 2}));
}

TEST(Csg1991, E57_DoubleKillInTreeIsReportedAsError) {
  // '-' of two equal single pairs: D13 3559-3560 Kill(B) twice -> E57.
  Leaves leaves{{{1, {2.0, 4.0}}, {2, {2.0, 4.0}}}, {}};
  const std::vector<CsgEntry> tree{{'-', 1, 2}, {'P', 1, 0}, {'P', 2, 0}};
  try {
    (void)csg1991(tree, leaves);
    ADD_FAILURE() << "expected E57";
  } catch (const CsgError& e) {
    EXPECT_EQ(e.kind(), CsgError::Kind::kKillEmptyList);
  }
}

TEST(Csg1991, UnknownOpcodeFailsAfterBothSubtrees) {
  // 3294 default: Error("switch case fell to default. Module Roth. Program CSG"),
  // reached after CSG(objL) and CSG(objR).
  Leaves leaves{{{1, {2.0, 4.0}}}, {}};
  const std::vector<CsgEntry> tree{{'x', 1, 2}, {'P', 1, 0}, {'P', 2, 0}};
  try {
    (void)csg1991(tree, leaves);
    ADD_FAILURE() << "expected kBadOpcode";
  } catch (const CsgError& e) {
    EXPECT_EQ(e.kind(), CsgError::Kind::kBadOpcode);
    EXPECT_NE(std::string(e.what()).find("Module Roth"), std::string::npos);
  }
  EXPECT_EQ(leaves.calls, (std::vector<int>{1, 2}));
}

TEST(Csg1991, BadIndicesAreErrors) {
  Leaves leaves;
  const std::vector<CsgEntry> badChild{{'+', 1, 5}, {'P', 1, 0}};
  const std::vector<CsgEntry> negChild{{'+', -1, 1}, {'P', 1, 0}};
  const std::vector<CsgEntry> one{{'P', 1, 0}};
  for (const auto* tree : {&badChild, &negChild}) {
    try {
      (void)csg1991(*tree, leaves);
      ADD_FAILURE() << "expected kBadEntryIndex";
    } catch (const CsgError& e) {
      EXPECT_EQ(e.kind(), CsgError::Kind::kBadEntryIndex);
    }
  }
  EXPECT_THROW((void)csg1991(one, leaves, {}, 1), CsgError);
  EXPECT_THROW((void)csg1991(std::span<const CsgEntry>{}, leaves), CsgError);
  EXPECT_TRUE(leaves.calls.empty());  // ReadObj of both children (3268-3269) precedes any leaf
}

TEST(Csg1991, CyclesAreErrorsNotHangs) {
  Leaves leaves{{{1, {0.0, 1.0}}}, {}};
  const std::vector<CsgEntry> self{{'+', 0, 1}, {'P', 1, 0}};
  const std::vector<CsgEntry> loop{{'+', 1, 2}, {'-', 2, 0}, {'P', 1, 0}};
  const std::vector<CsgEntry> rightLoop{{'&', 2, 1}, {'+', 2, 0}, {'P', 1, 0}};
  for (const auto* tree : {&self, &loop, &rightLoop}) {
    try {
      (void)csg1991(*tree, leaves);
      ADD_FAILURE() << "expected kCycle";
    } catch (const CsgError& e) {
      EXPECT_EQ(e.kind(), CsgError::Kind::kCycle);
    }
  }
}

TEST(Csg1991, SharedSubtreeIsEvaluatedPerReferenceAndBounded) {
  // '+ 1 1': both children are entry 1; the leaf is intersected twice and
  // Union of two equal pairs is U13 (3418 Add(A); 3419 Kill(B)).
  Leaves leaves{{{5, {1.0, 3.0}}}, {}};
  const std::vector<CsgEntry> twice{{'+', 1, 1}, {'P', 5, 0}};
  EXPECT_EQ(csg1991(twice, leaves), (TList{en(1, 5), ex(3, 5)}));
  EXPECT_EQ(leaves.calls, (std::vector<int>{5, 5}));

  // Doubling chain: entry i = '+ i+1 i+1' (40 levels = 2^41 visits) stops at the budget.
  std::vector<CsgEntry> doubling;
  for (int i = 0; i < 40; ++i) doubling.push_back({'+', i + 1, i + 1});
  doubling.push_back({'P', 5, 0});
  Csg1991Options small;
  small.maxVisits = 10000;
  try {
    (void)csg1991(doubling, leaves, small);
    ADD_FAILURE() << "expected kTooManyVisits";
  } catch (const CsgError& e) {
    EXPECT_EQ(e.kind(), CsgError::Kind::kTooManyVisits);
  }
}

TEST(Csg1991, DeepTreesDoNotOverflowTheStack) {
  // Entries 0..N-1 are '+'; leaves: entry N = prim 100 [0,1], entry N+1 =
  // prim 200 [2,3] (shared by every operator).
  // Left-deep (entry i = '+ i+1 N+1'): innermost Union([0,1]/100, [2,3]/200)
  // = U7 then 3430 Add(B) -> [0,1]/100,[2,3]/200. Each further level:
  // Union(that, [2,3]/200): iter1 U7 Add(A); iter2 equal -> U13 Add(A), Kill(B).
  // Right-deep (entry i = '+ N+1 i+1'): innermost Union([2,3]/200, [0,1]/100)
  // = U1 Add(B), 3426 Add(A) -> same list; each level: Union([2,3]/200, list):
  // U1 Add(B [0,1]); then equal -> U13 Add(A), Kill(B). Same list.
  constexpr int kN = 20000;
  const TList expected{en(0, 100), ex(1, 100), en(2, 200), ex(3, 200)};
  for (bool leftDeep : {true, false}) {
    std::vector<CsgEntry> tree;
    for (int i = 0; i < kN; ++i)
      tree.push_back(leftDeep ? CsgEntry{'+', i + 1, kN + 1} : CsgEntry{'+', kN + 1, i + 1});
    tree.push_back({'P', 100, 0});
    tree.push_back({'P', 200, 0});
    Leaves leaves{{{100, {0.0, 1.0}}, {200, {2.0, 3.0}}}, {}};
    EXPECT_EQ(csg1991(tree, leaves), expected) << (leftDeep ? "left-deep" : "right-deep");
    EXPECT_EQ(leaves.calls.size(), static_cast<std::size_t>(kN + 1));
  }
}

}  // namespace
}  // namespace prime
