// The canonical spellings of state bindings: written from the tables, read back, and the
// same as the interpreter's names (arbvp::BindingName) and the binding map's.
#include "arbiter/glstate/spelling.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "arbiter/arbvp/ir.h"
#include "glstate_test_state.h"

namespace arbiter::glstate {
namespace {

// The fields a spelling shows; the others keep StateRef's defaults when it is read back.
StateRef Shown(const StateRef& ref) {
  const std::string_view spelling = GetStateItemInfo(ref.item).spelling;
  StateRef shown;
  shown.item = ref.item;
  const bool matrix = test::Shows(spelling, "{m}");
  if (matrix) {
    shown.matrix = ref.matrix;
    shown.modifier = ref.modifier;
    shown.row = ref.row;
  }
  if (test::Shows(spelling, "{i}") ||
      (matrix && test::Shows(GetStateMatrixInfo(ref.matrix).spelling, "{i}"))) {
    shown.index = ref.index;
  }
  if (test::Shows(spelling, "{f}")) shown.face = ref.face;
  if (test::Shows(spelling, "{c}")) shown.coord = ref.coord;
  return shown;
}

void ExpectSameRef(const StateRef& a, const StateRef& b, const std::string& spelling) {
  EXPECT_EQ(a.item, b.item) << spelling;
  EXPECT_EQ(a.index, b.index) << spelling;
  EXPECT_EQ(a.face, b.face) << spelling;
  EXPECT_EQ(a.coord, b.coord) << spelling;
  EXPECT_EQ(a.matrix, b.matrix) << spelling;
  EXPECT_EQ(a.modifier, b.modifier) << spelling;
  EXPECT_EQ(a.row, b.row) << spelling;
}

TEST(GlStateSpelling, EveryItemFaceCoordMatrixModifierAndRowRoundTrips) {
  std::set<StateItem> items;
  std::set<MatrixName> matrices;
  std::set<MatrixModifier> modifiers;
  std::set<Face> faces;
  std::set<uint8_t> coords;
  std::set<std::string> spellings;
  for (const StateRef& ref : test::AllRefs()) {
    const std::string spelling = StateSpelling(ref);
    EXPECT_TRUE(spellings.insert(spelling).second) << "spelled twice: " << spelling;
    StateRef back;
    back.item = StateItem::DepthRange;  // overwritten
    ASSERT_TRUE(ParseStateSpelling(spelling, &back)) << spelling;
    ExpectSameRef(back, Shown(ref), spelling);
    // As the interpreter and the binding map write it.
    EXPECT_EQ(spelling, arbvp::BindingName(test::BindingOf(ref), arbvp::ProgramKind::Vertex));
    items.insert(back.item);
    if (back.item == StateItem::MatrixRow) {
      matrices.insert(back.matrix);
      modifiers.insert(back.modifier);
    }
    faces.insert(back.face);
    coords.insert(back.coord);
  }
  EXPECT_EQ(items.size(), std::size(kStateItems));
  EXPECT_EQ(matrices.size(), std::size(kStateMatrices));
  EXPECT_EQ(modifiers.size(), std::size(kMatrixModifierSpellings));
  EXPECT_EQ(faces.size(), 2u);
  EXPECT_EQ(coords.size(), 4u);
}

TEST(GlStateSpelling, WholeMatricesRoundTrip) {
  std::set<std::string> spellings;
  for (const StateMatrixInfo& info : kStateMatrices) {
    for (size_t m = 0; m < std::size(kMatrixModifierSpellings); ++m) {
      const bool numbered = test::Shows(info.spelling, "{i}");
      for (const int32_t index : numbered ? std::vector<int32_t>{0, 3, 10} : std::vector{0}) {
        const MatrixRef matrix{info.matrix, index, static_cast<MatrixModifier>(m)};
        const std::string spelling = MatrixSpelling(matrix);
        EXPECT_TRUE(spellings.insert(spelling).second) << spelling;
        MatrixRef back{MatrixName::Palette, 99, MatrixModifier::Transpose};
        ASSERT_TRUE(ParseMatrixSpelling(spelling, &back)) << spelling;
        EXPECT_EQ(back.matrix, matrix.matrix) << spelling;
        EXPECT_EQ(back.index, matrix.index) << spelling;
        EXPECT_EQ(back.modifier, matrix.modifier) << spelling;
        // A whole matrix is not a vec4 binding, and a row is not a whole matrix.
        StateRef ref;
        EXPECT_FALSE(ParseStateSpelling(spelling, &ref)) << spelling;
        EXPECT_FALSE(ParseMatrixSpelling(spelling + ".row[0]", &back)) << spelling;
      }
    }
  }
  EXPECT_EQ(MatrixSpelling({MatrixName::Program, 0, MatrixModifier::Inverse}),
            "state.matrix.program[0].inverse");
  EXPECT_EQ(MatrixSpelling({MatrixName::Mvp, 0, MatrixModifier::None}), "state.matrix.mvp");
}

TEST(GlStateSpelling, ReadsTheBindingMapsSpellings) {
  StateRef ref;
  ASSERT_TRUE(ParseStateSpelling("state.matrix.modelview[0].invtrans.row[2]", &ref));
  EXPECT_EQ(ref.item, StateItem::MatrixRow);
  EXPECT_EQ(ref.matrix, MatrixName::Modelview);
  EXPECT_EQ(ref.index, 0);
  EXPECT_EQ(ref.modifier, MatrixModifier::InvTrans);
  EXPECT_EQ(ref.row, 2);
  ASSERT_TRUE(ParseStateSpelling("state.light[1].half", &ref));
  EXPECT_EQ(ref.item, StateItem::LightHalf);
  EXPECT_EQ(ref.index, 1);
  ASSERT_TRUE(ParseStateSpelling("state.material.back.shininess", &ref));
  EXPECT_EQ(ref.item, StateItem::MaterialShininess);
  EXPECT_EQ(ref.face, Face::Back);
  ASSERT_TRUE(ParseStateSpelling("state.texgen[0].eye.s", &ref));
  EXPECT_EQ(ref.item, StateItem::TexGenEye);
  EXPECT_EQ(ref.index, 0);
  EXPECT_EQ(ref.coord, 0);
  ASSERT_TRUE(ParseStateSpelling("state.lightprod[7].back.specular", &ref));
  EXPECT_EQ(ref.item, StateItem::LightProdSpecular);
  EXPECT_EQ(ref.index, 7);
  EXPECT_EQ(ref.face, Face::Back);
  ASSERT_TRUE(ParseStateSpelling("state.matrix.texture[12].transpose.row[3]", &ref));
  EXPECT_EQ(ref.matrix, MatrixName::Texture);
  EXPECT_EQ(ref.index, 12);
  EXPECT_EQ(ref.modifier, MatrixModifier::Transpose);
  EXPECT_EQ(ref.row, 3);
  MatrixRef matrix;
  ASSERT_TRUE(ParseMatrixSpelling("state.matrix.program[0].inverse", &matrix));
  EXPECT_EQ(matrix.matrix, MatrixName::Program);
  EXPECT_EQ(matrix.index, 0);
  EXPECT_EQ(matrix.modifier, MatrixModifier::Inverse);
}

TEST(GlStateSpelling, RejectsWhatIsNotCanonical) {
  const char* const bad[] = {
      "",
      "state",
      "state.",
      "state.matrix.modelview.row[0]",  // modelview without its number
      "state.matrix.modelview[0]",      // a whole matrix, not a row
      "state.matrix.projection[0].row[0]",
      "state.matrix.mvp.row[4]",
      "state.matrix.mvp.row[01]",
      "state.matrix.mvp.row[]",
      "state.matrix.mvp.inverse.transpose.row[0]",
      "state.matrix.palette.row[0]",
      "state.lightmodel.scenecolor",  // the face is spelled
      "state.lightmodel.front.ambient",
      "state.material.ambient",
      "state.material.side.ambient",
      "state.light.half",
      "state.light[01].half",
      "state.light[-1].half",
      "state.light[+1].half",
      "state.light[2147483648].half",
      "state.light[1].half ",
      " state.light[1].half",
      "state.light[1].spot",
      "state.texgen[0].eye",
      "state.texgen[0].eye.x",
      "state.texgen[0].eye.st",
      "state.fog.params.x",
      "state.depth.range[0]",
      "program.env[0]",
      "vertex.position",
      "State.fog.color",
  };
  for (const char* text : bad) {
    StateRef ref;
    ref.item = StateItem::DepthRange;
    ref.index = 42;
    EXPECT_FALSE(ParseStateSpelling(text, &ref)) << text;
    EXPECT_EQ(ref.item, StateItem::DepthRange) << text;  // left alone
    EXPECT_EQ(ref.index, 42) << text;
  }
  StateRef ref;
  EXPECT_TRUE(ParseStateSpelling("state.light[2147483647].half", &ref));
  EXPECT_EQ(ref.index, 2147483647);
  MatrixRef matrix;
  EXPECT_FALSE(ParseMatrixSpelling("state.matrix.modelview", &matrix));
  EXPECT_FALSE(ParseMatrixSpelling("state.matrix.mvp.", &matrix));
  EXPECT_FALSE(ParseMatrixSpelling("state.matrix.program[0].inverse ", &matrix));
  EXPECT_FALSE(ParseMatrixSpelling("state.fog.color", &matrix));
}

}  // namespace
}  // namespace arbiter::glstate
