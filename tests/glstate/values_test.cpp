// glstate::StateValue, StateMatrix and StateUndefined against the formulas of the specs
// (ARBvp 2.14.3.2 tables X.3.2-X.3.8, ARBfp 3.11.3.2), with state whose derived values differ
// from every input, and the interpreter reading the same values through them.
#include "arbiter/glstate/values.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>

#include "arbiter/arbvp/exec.h"
#include "arbiter/glstate/gl_state.h"
#include "arbiter/glstate/spelling.h"
#include "glstate_test_state.h"

namespace arbiter::glstate {
namespace {

Vec4 Value(const GlState& state, std::string_view spelling) {
  StateRef ref;
  EXPECT_TRUE(ParseStateSpelling(spelling, &ref)) << spelling;
  return StateValue(state, ref);
}

void ExpectNear(const Vec4& actual, const Vec4& expected, std::string_view what) {
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_FLOAT_EQ(actual[i], expected[i]) << what << " component " << i;
  }
}

TEST(GlStateValues, InitialStateIsGls) {
  const GlState s;
  EXPECT_EQ(Value(s, "state.material.front.ambient"), (Vec4{0.2f, 0.2f, 0.2f, 1.0f}));
  EXPECT_EQ(Value(s, "state.material.back.diffuse"), (Vec4{0.8f, 0.8f, 0.8f, 1.0f}));
  EXPECT_EQ(Value(s, "state.light[0].diffuse"), (Vec4{1, 1, 1, 1}));
  EXPECT_EQ(Value(s, "state.light[0].specular"), (Vec4{1, 1, 1, 1}));
  EXPECT_EQ(Value(s, "state.light[1].diffuse"), (Vec4{0, 0, 0, 1}));
  EXPECT_EQ(Value(s, "state.light[1].position"), (Vec4{0, 0, 1, 0}));
  EXPECT_EQ(Value(s, "state.light[2].attenuation"), (Vec4{1, 0, 0, 0}));
  // A cutoff of 180 degrees: cos = -1.
  EXPECT_EQ(Value(s, "state.light[3].spot.direction"), (Vec4{0, 0, -1, -1}));
  // The default light at infinity along +z: normalize((0,0,1) + (0,0,1)).
  EXPECT_EQ(Value(s, "state.light[4].half"), (Vec4{0, 0, 1, 1}));
  EXPECT_EQ(Value(s, "state.fog.params"), (Vec4{1, 0, 1, 1}));
  EXPECT_EQ(Value(s, "state.depth.range"), (Vec4{0, 1, 1, 1}));
  EXPECT_EQ(Value(s, "state.texgen[5].eye.s"), (Vec4{1, 0, 0, 0}));
  EXPECT_EQ(Value(s, "state.texgen[5].object.t"), (Vec4{0, 1, 0, 0}));
  EXPECT_EQ(Value(s, "state.texgen[5].eye.q"), (Vec4{0, 0, 0, 0}));
  for (int r = 0; r < 4; ++r) {
    Vec4 row{0, 0, 0, 0};
    row[static_cast<size_t>(r)] = 1.0f;
    const std::string n = std::to_string(r);
    EXPECT_EQ(Value(s, "state.matrix.mvp.row[" + n + "]"), row);
    EXPECT_EQ(Value(s, "state.matrix.texture[7].invtrans.row[" + n + "]"), row);
    EXPECT_EQ(Value(s, "state.matrix.program[7].inverse.row[" + n + "]"), row);
  }
}

TEST(GlStateValues, MaterialsByFace) {
  const GlState s = test::RichState();
  EXPECT_EQ(Value(s, "state.material.front.ambient"), (Vec4{0.5f, 0.5f, 0.25f, 0.125f}));
  EXPECT_EQ(Value(s, "state.material.back.ambient"), (Vec4{1, 0.5f, 0.5f, 0.5f}));
  EXPECT_EQ(Value(s, "state.material.front.emission"), (Vec4{0.25f, 0.125f, 0.5f, 0.0625f}));
  // (s, 0, 0, 1)
  EXPECT_EQ(Value(s, "state.material.front.shininess"), (Vec4{12, 0, 0, 1}));
  EXPECT_EQ(Value(s, "state.material.back.shininess"), (Vec4{64, 0, 0, 1}));
}

TEST(GlStateValues, LightProductsTakeTheMaterialsAlpha) {
  const GlState s = test::RichState();
  // light 1 diffuse (0.5, 2, 4, 0.25) * front diffuse (0.5, 0.25, 0.125, 0.75): rgb the
  // products, alpha the material's (not 0.25 * 0.75).
  EXPECT_EQ(Value(s, "state.lightprod[1].front.diffuse"), (Vec4{0.25f, 0.5f, 0.5f, 0.75f}));
  // back diffuse (0.25, 0.5, 1, 0.5)
  EXPECT_EQ(Value(s, "state.lightprod[1].back.diffuse"), (Vec4{0.125f, 1, 4, 0.5f}));
  // ambient (0.5, 0.25, 0.5, 2) * front ambient (0.5, 0.5, 0.25, 0.125)
  EXPECT_EQ(Value(s, "state.lightprod[1].front.ambient"), (Vec4{0.25f, 0.125f, 0.125f, 0.125f}));
  // specular (1, 0.5, 0.25, 4) * back specular (0.5, 0.5, 0.5, 0.25)
  EXPECT_EQ(Value(s, "state.lightprod[1].back.specular"), (Vec4{0.5f, 0.25f, 0.125f, 0.25f}));
}

TEST(GlStateValues, SceneColor) {
  const GlState s = test::RichState();
  // a_cs * a_cm + e_cm with a_cs = (0.5, 0.25, 2, 1); w = the diffuse alpha of the face.
  // front: (0.5*0.5 + 0.25, 0.25*0.5 + 0.125, 2*0.25 + 0.5, 0.75)
  EXPECT_EQ(Value(s, "state.lightmodel.front.scenecolor"), (Vec4{0.5f, 0.25f, 1, 0.75f}));
  // back: ambient (1, 0.5, 0.5), emission (0.5, 0.5, 0.5)
  EXPECT_EQ(Value(s, "state.lightmodel.back.scenecolor"), (Vec4{1, 0.625f, 1.5f, 0.5f}));
  EXPECT_EQ(Value(s, "state.lightmodel.ambient"), (Vec4{0.5f, 0.25f, 2, 1}));
}

TEST(GlStateValues, LightsAttenuationSpotAndHalf) {
  const GlState s = test::RichState();
  EXPECT_EQ(Value(s, "state.light[1].ambient"), (Vec4{0.5f, 0.25f, 0.5f, 2}));
  EXPECT_EQ(Value(s, "state.light[1].position"), (Vec4{0, 6, 0, -2}));
  // (constant, linear, quadratic, spot exponent)
  EXPECT_EQ(Value(s, "state.light[1].attenuation"), (Vec4{0.5f, 0.25f, 0.125f, 16}));
  // (direction, cos(45 degrees))
  const Vec4 spot = Value(s, "state.light[1].spot.direction");
  EXPECT_EQ(spot[0], 0.0f);
  EXPECT_EQ(spot[1], -1.0f);
  EXPECT_EQ(spot[2], 0.0f);
  EXPECT_FLOAT_EQ(spot[3], std::sqrt(0.5f));
  // cos(90 degrees) is 0 within float rounding of pi/2.
  EXPECT_NEAR(Value(s, "state.light[2].spot.direction")[3], 0.0f, 1e-7f);
  // Local light (0, 6, 0, -2): P is the direction of xyz / w = (0, -3, 0), so
  // h = normalize((0, -1, 0) + (0, 0, 1)).
  const float r = std::sqrt(0.5f);
  ExpectNear(Value(s, "state.light[1].half"), {0, -r, r, 1}, "local light");
  // Light at infinity (3, 0, 4, 0): normalize((0.6, 0, 0.8) + (0, 0, 1)) = (1, 0, 3) / sqrt(10).
  const float t = std::sqrt(10.0f);
  ExpectNear(Value(s, "state.light[2].half"), {1 / t, 0, 3 / t, 1}, "light at infinity");
  // Local light (2, 0, 0, 1): the direction of (2, 0, 0), not the position itself.
  ExpectNear(Value(s, "state.light[3].half"), {r, 0, r, 1}, "local light, w = 1");
}

TEST(GlStateValues, FogPointTexenvClipTexgenDepth) {
  const GlState s = test::RichState();
  EXPECT_EQ(Value(s, "state.fog.color"), (Vec4{0.25f, 0.5f, 0.75f, 1}));
  // (density, start, end, 1 / (end - start))
  EXPECT_EQ(Value(s, "state.fog.params"), (Vec4{0.5f, 2, 6, 0.25f}));
  EXPECT_EQ(Value(s, "state.point.size"), (Vec4{4, 1, 16, 2}));
  EXPECT_EQ(Value(s, "state.point.attenuation"), (Vec4{1, 0.5f, 0.25f, 1}));
  EXPECT_EQ(Value(s, "state.texenv[3].color"), (Vec4{0.125f, 0.25f, 0.375f, 0.5f}));
  EXPECT_EQ(Value(s, "state.texenv[0].color"), (Vec4{0, 0, 0, 0}));
  EXPECT_EQ(Value(s, "state.clip[4].plane"), (Vec4{1, -1, 0.5f, 3}));
  EXPECT_EQ(Value(s, "state.texgen[2].eye.s"), (Vec4{1, 2, 3, 4}));
  EXPECT_EQ(Value(s, "state.texgen[2].eye.r"), (Vec4{9, 10, 11, 12}));
  EXPECT_EQ(Value(s, "state.texgen[2].object.t"), (Vec4{-5, -6, -7, -8}));
  EXPECT_EQ(Value(s, "state.texgen[2].object.q"), (Vec4{-13, -14, -15, -16}));
  // (near, far, far - near, 1)
  EXPECT_EQ(Value(s, "state.depth.range"), (Vec4{0.25f, 0.75f, 0.5f, 1}));
}

TEST(GlStateValues, MatrixRowsAndModifiers) {
  const GlState s = test::RichState();
  // modelview = the rows of test::kModelviewRows; its inverse has these rows (exact in
  // binary: scale by 2, 4, 8, then translate by (1, 2, 3)).
  const Vec4 inverse[4] = {
      {0.5f, 0, 0, -0.5f}, {0, 0.25f, 0, -0.5f}, {0, 0, 0.125f, -0.375f}, {0, 0, 0, 1}};
  for (int r = 0; r < 4; ++r) {
    const std::string row = ".row[" + std::to_string(r) + "]";
    const size_t u = static_cast<size_t>(r);
    EXPECT_EQ(Value(s, "state.matrix.modelview[0]" + row), test::kModelviewRows[u]);
    EXPECT_EQ(Value(s, "state.matrix.modelview[0].inverse" + row), inverse[u]);
    Vec4 column{};
    Vec4 inverse_column{};
    for (size_t c = 0; c < 4; ++c) {
      column[c] = test::kModelviewRows[c][u];
      inverse_column[c] = inverse[c][u];
    }
    EXPECT_EQ(Value(s, "state.matrix.modelview[0].transpose" + row), column);
    EXPECT_EQ(Value(s, "state.matrix.modelview[0].invtrans" + row), inverse_column);
    EXPECT_EQ(Value(s, "state.matrix.projection" + row), test::kProjectionRows[u]);
    EXPECT_EQ(Value(s, "state.matrix.texture[3]" + row), test::kTextureRows[u]);
    EXPECT_EQ(Value(s, "state.matrix.program[5]" + row), test::kProgramRows[u]);
    // Vertex blending and the palette are not in the model: the identity.
    Vec4 identity{0, 0, 0, 0};
    identity[u] = 1.0f;
    EXPECT_EQ(Value(s, "state.matrix.modelview[1]" + row), identity);
    EXPECT_EQ(Value(s, "state.matrix.palette[2]" + row), identity);
  }
}

TEST(GlStateValues, MvpIsProjectionTimesModelview) {
  const GlState s = test::RichState();
  // P rows (1 0 0 0) (0 1 0 0) (0 0 -1 -2) (0 0 -1 0) times M rows (2 0 0 1) (0 4 0 2)
  // (0 0 8 3) (0 0 0 1): row 2 = -M.row2 - 2 M.row3, row 3 = -M.row2.
  const Vec4 mvp[4] = {{2, 0, 0, 1}, {0, 4, 0, 2}, {0, 0, -8, -5}, {0, 0, -8, -3}};
  for (int r = 0; r < 4; ++r) {
    EXPECT_EQ(Value(s, "state.matrix.mvp.row[" + std::to_string(r) + "]"),
              mvp[static_cast<size_t>(r)]);
  }
  const glm::mat4 m = StateMatrix(s, MatrixName::Mvp, 0, MatrixModifier::None);
  EXPECT_EQ(m, s.projection * s.modelview);
  EXPECT_EQ(StateMatrix(s, MatrixName::Mvp, 0, MatrixModifier::Transpose),
            glm::transpose(s.projection * s.modelview));
}

TEST(GlStateValues, OutOfModelIndicesReadZero) {
  const GlState s = test::RichState();
  EXPECT_EQ(Value(s, "state.light[8].diffuse"), (Vec4{0, 0, 0, 0}));
  EXPECT_EQ(Value(s, "state.lightprod[9].front.ambient"), (Vec4{0, 0, 0, 0}));
  EXPECT_EQ(Value(s, "state.clip[6].plane"), (Vec4{0, 0, 0, 0}));
  EXPECT_EQ(Value(s, "state.texgen[8].eye.s"), (Vec4{0, 0, 0, 0}));
  EXPECT_EQ(Value(s, "state.texenv[8].color"), (Vec4{0, 0, 0, 0}));
}

TEST(GlStateValues, InverseOfASingularMatrixIsUndefined) {
  GlState s = test::RichState();
  s.program[1] = glm::mat4(0.0f);
  s.program[1][0][0] = 1.0f;  // rank 1
  StateRef ref;
  ASSERT_TRUE(ParseStateSpelling("state.matrix.program[1].inverse.row[0]", &ref));
  EXPECT_EQ(StateUndefined(s, ref), "the inverse of a singular matrix");
  ASSERT_TRUE(ParseStateSpelling("state.matrix.program[1].invtrans.row[3]", &ref));
  EXPECT_EQ(StateUndefined(s, ref), "the inverse of a singular matrix");
  ASSERT_TRUE(ParseStateSpelling("state.matrix.program[1].transpose.row[0]", &ref));
  EXPECT_EQ(StateUndefined(s, ref), "");
  ASSERT_TRUE(ParseStateSpelling("state.matrix.program[5].inverse.row[0]", &ref));
  EXPECT_EQ(StateUndefined(s, ref), "");
  ASSERT_TRUE(ParseStateSpelling("state.light[0].half", &ref));
  EXPECT_EQ(StateUndefined(s, ref), "");
}

TEST(GlStateValues, ParameterValue) {
  const std::map<int, Vec4> params{{3, Vec4{1, 2, 3, 4}}};
  EXPECT_EQ(ParameterValue(params, 3), (Vec4{1, 2, 3, 4}));
  EXPECT_EQ(ParameterValue(params, 4), (Vec4{0, 0, 0, 0}));
}

// The interpreter reads state through glstate: the same bits for every spelling of every
// item, face, coordinate, matrix, modifier and row.
TEST(GlStateValues, InterpreterReadsTheSameValues) {
  const GlState s = test::RichState();
  int checked = 0;
  for (const StateRef& ref : test::AllRefs()) {
    const Vec4 interpreter = arbvp::ReadStateBinding(s, test::BindingOf(ref));
    const Vec4 host = StateValue(s, ref);
    for (size_t i = 0; i < 4; ++i) {
      EXPECT_EQ(std::bit_cast<uint32_t>(interpreter[i]), std::bit_cast<uint32_t>(host[i]))
          << StateSpelling(ref) << " component " << i;
    }
    ++checked;
  }
  EXPECT_GT(checked, 700);
}

}  // namespace
}  // namespace arbiter::glstate
