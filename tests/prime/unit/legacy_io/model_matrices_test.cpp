// Matrices that `prime model` builds through Transform (AddPrim/AddBound),
// CopyPrim (O entries) and TransferObj (CopyObj), against values computed by
// hand from the listing's operation sequence (Transfrm module, lines
// 7788-8044; CopyPrim 6575-6611; TransferObj 6296-6342).
//
// cos/sin go through Roundoff (K3) after converting degrees with Radient =
// 57.29578, so cos(90 deg) is NOT snapped to 0: 90/57.29578 differs from pi/2
// by about 1.37e-8, far more than Roundoff's 1e-10 window. sin(90 deg) is
// within it and becomes exactly 1. The expected values below use
//   c90 = cos(90 / 57.29578) (about 1.3349e-8).
#include <gtest/gtest.h>

#include <cmath>

#include "legacy_io/prime/model_builder.h"
#include "src/prime/math/listing_matrix.h"
#include "tests/support/temp_scene.h"

namespace prime::io {
namespace {

const double c90 = std::cos(90.0 / 57.29578);

// A scene with one object "d1.txt" whose D file is `d` and whose primitives
// are given as name -> text.
void writeObject(const test::TempScene& s, int n, const std::string& d) {
  s.write("obj/H" + std::to_string(n) + ".txt", "0.1 0.2 0.3 0.4 0.5 0.999 2 2 1.5\n");
  s.write("obj/D" + std::to_string(n) + ".txt", d);
}

Model model(const test::TempScene& s, const std::string& modelTxt, ModelOptions o = {}) {
  s.write("Model.txt", modelTxt);
  return buildModel(SceneDir(s.path()), o);
}

void expectMatrix(const Matrix4& m, const Matrix4& expected, double tol = 0.0) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      if (tol == 0.0)
        EXPECT_EQ(m[i][j], expected[i][j]) << "at [" << i << "][" << j << "]";
      else
        EXPECT_NEAR(m[i][j], expected[i][j], tol) << "at [" << i << "][" << j << "]";
    }
}

TEST(Transform, ScaleThenPivotThenTranslate) {
  // s = (2,3,4), t = (10,20,30), pivot = (1,1,1): Scale -> diag(2,3,4);
  // Translate(-pivot*s) -> row 3 = (-2,-3,-4); Translate(t) -> (8,17,26).
  test::TempScene s;
  writeObject(s, 1, "1\nB 1\nNULL\n");
  s.write("prim/B1.txt", "B\n2 3 4\n10 20 30\n0 0 0\n1 1 1\n1 1 1 1 1 1 1 1 1 1 1 1\n0\n");
  const Model m = model(s, "AddObj d1.txt\n");
  ASSERT_EQ(m.prims.prims.size(), 1u);
  expectMatrix(m.prims.prims[0].transform,
               {{{2, 0, 0, 0}, {0, 3, 0, 0}, {0, 0, 4, 0}, {8, 17, 26, 1}}});
  // Gauss-Jordan: row r scaled by 1/a[r][r], then row 3 -= a[3][r] * row r:
  // b[3] = (-8*0.5, -17*(1/3), -26*0.25) = (-4, -17*(1/3), -6.5).
  expectMatrix(
      m.prims.prims[0].inverse,
      {{{0.5, 0, 0, 0}, {0, 1.0 / 3.0, 0, 0}, {0, 0, 0.25, 0}, {-4, -17 * (1.0 / 3.0), -6.5, 1}}});
}

TEST(Transform, RotateX90IsNotSnappedToExactZeroCosine) {
  // RotateX: m[i][Y] = m[i][Y]*c - m[i][Z]*s; m[i][Z] = m[i][Z]*c + m[i][Y]*s,
  // with c = c90 and s = Roundoff(sin) = 1. Row 1 (0,1,0) -> (0, c, 1);
  // row 2 (0,0,1) -> (0, -1, c).
  test::TempScene s;
  writeObject(s, 1, "1\nC 1\nNULL\n");
  s.write("prim/C1.txt", "C\n1 1 1\n0 0 0\n90 0 0\n0 0 0\n1 1 1 1 1 1\n0\n");
  const Model m = model(s, "AddObj d1.txt\n");
  EXPECT_GT(c90, 1e-8);  // the K3 observation: not exact
  expectMatrix(m.prims.prims[0].transform,
               {{{1, 0, 0, 0}, {0, c90, 1, 0}, {0, -1, c90, 0}, {0, 0, 0, 1}}});
  // The inverse of this rotation is its transpose (divided by 1 + c^2). The
  // listing's Gauss-Jordan has no pivoting (K42) and divides by the tiny
  // pivot c90 ~ 1.3e-8, so its result is off by about 1.5e-9 here: only
  // about 9 significant digits survive a 90-degree rotation about X.
  expectMatrix(m.prims.prims[0].inverse,
               {{{1, 0, 0, 0}, {0, c90, -1, 0}, {0, 1, c90, 0}, {0, 0, 0, 1}}}, 5e-9);
}

TEST(Transform, PivotEndsUpAtTranslationAndRotationY30) {
  // s = (2,1,1), r = (0,30,0), pivot = (0.5,0,0), t = (100,0,0).
  // Scale: row0 = (2,0,0). Translate(-pivot*s) = (-1,0,0) on row 3.
  // RotateY with c = cos30', s = sin30' (neither near an integer):
  //   row0 (2,0,0)  -> (2c, 0, -2s);  row2 (0,0,1) -> (s, 0, c);
  //   row3 (-1,0,0) -> (-c, 0, s), then + t -> (100 - c, 0, s).
  test::TempScene s;
  writeObject(s, 1, "1\nY 1\nNULL\n");
  s.write("prim/Y1.txt", "Y\n2 1 1\n100 0 0\n0 30 0\n0.5 0 0\n1 1 1 1 1 1 1 1 1 1\n0\n");
  const Model m = model(s, "AddObj d1.txt\n");
  const double c = std::cos(30 / 57.29578), sn = std::sin(30 / 57.29578);
  expectMatrix(m.prims.prims[0].transform,
               {{{2 * c, 0, -2 * sn, 0}, {0, 1, 0, 0}, {sn, 0, c, 0}, {100 - c, 0, sn, 1}}}, 1e-13);
  EXPECT_EQ(m.prims.prims[0].type, 'Y');
}

// Object 1: "+ 1 2 / B 1 / S 1": B1 is diag(2) moved by (10,20,30). Object 2
// is a single O entry copying object 1 with prim/A5.txt.
void copyScene(const test::TempScene& s, const std::string& a5) {
  writeObject(s, 1, "3\n+ 1 2\nB 1\nS 1\nNULL\n");
  s.write("prim/B1.txt", "B\n2 2 2\n10 20 30\n0 0 0\n0 0 0\n1 2 3 4 5 6 7 8 9 10 11 12\n3\n");
  s.write("prim/S1.txt", "S\n1 1 1\n0 0 0\n0 0 0\n0 0 0\n1 1\n0\n");
  writeObject(s, 2, "1\nO 1 5\nNULL\n");
  s.write("prim/A5.txt", a5);
}

TEST(CopyPrim, TranslationOnlyGivesAUnitPrimitiveMovedByT) {
  // dest = inverse(B1) = diag(.5), row3 (-5,-10,-15); Scale(1); Rotate(0);
  // Translate((4,0,0)) -> row3 (-1,-10,-15); times transform(B1):
  //   3x3 = .5*2 = identity, row3 = (-1*2+10, -10*2+20, -15*2+30) = (8,0,0).
  test::TempScene s;
  copyScene(s, "1 1 1\n4 0 0\n0 0 0\n0 0 0\n");
  const Model m = model(s, "AddObj d1.txt\nAddObj d2.txt\n");
  ASSERT_EQ(m.prims.prims.size(), 4u);  // B1, S1, and their two copies
  const auto& o2 = m.objects.at("O2");
  ASSERT_EQ(o2.entries.size(), 3u);
  EXPECT_EQ(o2.entries[0].op(), '+');  // root of O1, children offset by n-1 = 0
  EXPECT_EQ(o2.entries[0].l, 1);
  EXPECT_EQ(o2.entries[0].r, 2);
  EXPECT_EQ(o2.entries[1].l, 2);  // copy of prim 0
  EXPECT_EQ(o2.entries[2].l, 3);  // copy of prim 1
  expectMatrix(m.prims.prims[2].transform,
               {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {8, 0, 0, 1}}});
  expectMatrix(m.prims.prims[2].inverse,
               {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {-8, 0, 0, 1}}});
  EXPECT_EQ(m.prims.prims[2].map, m.prims.prims[0].map);  // maps and priority copied
  EXPECT_EQ(m.prims.prims[2].priority, 3);
}

TEST(CopyPrim, ScaleMultipliesOnlyTheInverseDiagonal) {
  // Scale((3,1,1)) on inverse(B1): diag (1.5,.5,.5), row3 unchanged
  // (-5,-10,-15); times transform(B1): diag (3,1,1), row3 = (0,0,0).
  test::TempScene s;
  copyScene(s, "3 1 1\n0 0 0\n0 0 0\n0 0 0\n");
  const Model m = model(s, "AddObj d1.txt\nAddObj d2.txt\n");
  expectMatrix(m.prims.prims[2].transform,
               {{{3, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}});
}

TEST(CopyPrim, RotateZ90) {
  // RotateZ on inverse(B1) with c = c90, s = 1:
  //   row0 (.5,0,0) -> (.5c, .5, 0); row1 (0,.5,0) -> (-.5, .5c, 0);
  //   row3 (-5,-10,-15) -> (-5c+10, -10c-5, -15);
  // times transform(B1) (diag 2, row3 (10,20,30)):
  //   row0 (c, 1, 0); row1 (-1, c, 0); row2 (0,0,1);
  //   row3 ((-5c+10)*2+10, (-10c-5)*2+20, -15*2+30) = (30-10c, 10-20c, 0).
  test::TempScene s;
  copyScene(s, "1 1 1\n0 0 0\n0 0 90\n0 0 0\n");
  const Model m = model(s, "AddObj d1.txt\nAddObj d2.txt\n");
  expectMatrix(
      m.prims.prims[2].transform,
      {{{c90, 1, 0, 0}, {-1, c90, 0, 0}, {0, 0, 1, 0}, {30 - 10 * c90, 10 - 20 * c90, 0, 1}}},
      1e-13);
}

TEST(CopyPrim, TypeIsTheRecycledBlocksUnlessFixed) {
  // K33: CopyPrim never sets the type. B1 then S1 were built last, so both
  // copies carry 'S' (our model of the recycled heap block); with
  // copyTypeFromSource the cube copy is a cube again.
  test::TempScene s;
  copyScene(s, "1 1 1\n0 0 0\n0 0 0\n0 0 0\n");
  const Model m = model(s, "AddObj d1.txt\nAddObj d2.txt\n");
  EXPECT_EQ(m.prims.prims[2].type, 'S');
  EXPECT_EQ(m.prims.prims[3].type, 'S');
  ModelOptions fixed;
  fixed.copyTypeFromSource = true;
  const Model f = model(s, "AddObj d1.txt\nAddObj d2.txt\n", fixed);
  EXPECT_EQ(f.prims.prims[2].type, 'B');
  EXPECT_EQ(f.prims.prims[3].type, 'S');
}

// TransferObj re-applies Transform() to each primitive's existing matrix.
Model transferred(const test::TempScene& s, const std::string& copyTxt) {
  writeObject(s, 1, "1\nB 1\nB 2\n");
  s.write("prim/B1.txt", "B\n2 2 2\n10 20 30\n0 0 0\n0 0 0\n1 1 1 1 1 1 1 1 1 1 1 1\n0\n");
  s.write("bound/B2.txt", "B\n4 4 4\n0 0 0\n0 0 0\n0 0 0\n");
  s.write("obj/Copy/c.txt", copyTxt);
  return model(s, "AddObj d1.txt\nAddToObjList 1\nCopyObj O1 O2 c.txt\nAddToObjList 2\n");
}

TEST(TransferObj, ScaleLeavesTheTranslationRowUnscaled) {
  // K1: Scale((3,3,3)) multiplies the diagonal 2 -> 6 but not row 3
  // (10,20,30); Translate((5,0,0)) -> (15,20,30). (A correct composition
  // would give (35,60,90).)
  test::TempScene s;
  const Model m = transferred(s, "3 3 3\n5 0 0\n0 0 0\n0 0 0\n");
  ASSERT_EQ(m.prims.prims.size(), 4u);  // B1 0, bound 1, copies 2 and 3
  const auto& o2 = m.objects.at("O2");
  EXPECT_EQ(o2.entries[0].l, 2);
  EXPECT_EQ(o2.header.boundVol, 3);
  EXPECT_EQ(m.objects.at("O1").header.boundVol, 1);
  expectMatrix(m.prims.prims[2].transform,
               {{{6, 0, 0, 0}, {0, 6, 0, 0}, {0, 0, 6, 0}, {15, 20, 30, 1}}});
  // The bound diag(4) -> diag(12), row 3 (0,0,0) -> (5,0,0).
  expectMatrix(m.prims.prims[3].transform,
               {{{12, 0, 0, 0}, {0, 12, 0, 0}, {0, 0, 12, 0}, {5, 0, 0, 1}}});
  EXPECT_EQ(m.list.objects, (std::vector<std::int16_t>{1, 2}));
}

TEST(TransferObj, PivotIsSubtractedScaled) {
  // s = (1,1,1), pivot = (1,2,3): row 3 += (-1,-2,-3) -> (9,18,27).
  test::TempScene s;
  const Model m = transferred(s, "1 1 1\n0 0 0\n0 0 0\n1 2 3\n");
  expectMatrix(m.prims.prims[2].transform,
               {{{2, 0, 0, 0}, {0, 2, 0, 0}, {0, 0, 2, 0}, {9, 18, 27, 1}}});
}

TEST(TransferObj, RotateY90RotatesTheTranslationRowToo) {
  // RotateY: m[i][X] = m[i][X]*c + m[i][Z]*s; m[i][Z] = m[i][Z]*c - m[i][X]*s.
  //   row0 (2,0,0) -> (2c, 0, -2); row2 (0,0,2) -> (2, 0, 2c);
  //   row3 (10,20,30) -> (10c + 30, 20, 30c - 10).
  test::TempScene s;
  const Model m = transferred(s, "1 1 1\n0 0 0\n0 90 0\n0 0 0\n");
  expectMatrix(m.prims.prims[2].transform,
               {{{2 * c90, 0, -2, 0},
                 {0, 2, 0, 0},
                 {2, 0, 2 * c90, 0},
                 {10 * c90 + 30, 20, 30 * c90 - 10, 1}}},
               1e-13);
}

}  // namespace
}  // namespace prime::io
