// glstate::UniformValue: the value of each uniform a binding map lists, by its spelling.
#include "arbiter/glstate/uniforms.h"

#include <gtest/gtest.h>

#include <string>

#include "glstate_test_state.h"

namespace arbiter::glstate {
namespace {

UniformData Get(const GlState& state, const ProgramParameters& params, const std::string& name) {
  UniformData out;
  out.data.fill(-99.0f);
  EXPECT_TRUE(UniformValue(state, params, name, &out)) << name;
  return out;
}

Vec4 First4(const UniformData& u) { return {u.data[0], u.data[1], u.data[2], u.data[3]}; }

TEST(GlStateUniforms, VectorsAreTheStateValues) {
  const GlState s = test::RichState();
  const ProgramParameters params;
  for (const StateRef& ref : test::AllRefs()) {
    const std::string name = StateSpelling(ref);
    UniformData u;
    const bool ok = UniformValue(s, params, name, &u);
    // Indices past the model's arrays are refused: a host that feeds them has a bug.
    bool in_model = true;
    switch (ref.item) {
      case StateItem::MatrixRow:
        in_model = (ref.matrix != MatrixName::Texture || ref.index < kMaxTextureCoords) &&
                   (ref.matrix != MatrixName::Program || ref.index < kMaxProgramMatrices);
        break;
      case StateItem::LightAmbient:
      case StateItem::LightDiffuse:
      case StateItem::LightSpecular:
      case StateItem::LightPosition:
      case StateItem::LightAttenuation:
      case StateItem::LightSpotDirection:
      case StateItem::LightHalf:
      case StateItem::LightProdAmbient:
      case StateItem::LightProdDiffuse:
      case StateItem::LightProdSpecular:
        in_model = ref.index < kMaxLights;
        break;
      case StateItem::ClipPlane:
        in_model = ref.index < kMaxClipPlanes;
        break;
      case StateItem::TexGenEye:
      case StateItem::TexGenObject:
      case StateItem::TexEnvColor:
        in_model = ref.index < kMaxTextureCoords;
        break;
      default:
        break;
    }
    ASSERT_EQ(ok, in_model) << name;
    if (!ok) continue;
    EXPECT_EQ(u.type, UniformType::Vector) << name;
    EXPECT_EQ(First4(u), StateValue(s, ref)) << name;
  }
}

TEST(GlStateUniforms, MatricesAreColumnMajorWithTheArbRows) {
  const GlState s = test::RichState();
  const ProgramParameters params;
  // The uniform of state.matrix.program[5]: data[4c + r] is row r of column c.
  const UniformData p = Get(s, params, "state.matrix.program[5]");
  ASSERT_EQ(p.type, UniformType::Matrix);
  for (size_t c = 0; c < 4; ++c) {
    for (size_t r = 0; r < 4; ++r) EXPECT_EQ(p.data[4 * c + r], test::kProgramRows[r][c]);
  }
  // Every matrix and modifier: the rows of the mat4 are the vec4 bindings' rows.
  for (const StateMatrixInfo& info : kStateMatrices) {
    for (size_t m = 0; m < std::size(kMatrixModifierSpellings); ++m) {
      const MatrixRef matrix{info.matrix, info.index == MatrixIndex::No ? 0 : 5,
                             static_cast<MatrixModifier>(m)};
      const std::string name = MatrixSpelling(matrix);
      const UniformData u = Get(s, params, name);
      EXPECT_EQ(u.type, UniformType::Matrix) << name;
      for (int r = 0; r < 4; ++r) {
        const UniformData row = Get(s, params, name + ".row[" + std::to_string(r) + "]");
        for (size_t c = 0; c < 4; ++c) {
          EXPECT_EQ(u.data[4 * c + static_cast<size_t>(r)], row.data[c]) << name << " row " << r;
        }
      }
    }
  }
  // The inverse of the modelview (scale (2, 4, 8), translate (1, 2, 3)), column 3.
  const UniformData inverse = Get(s, params, "state.matrix.modelview[0].inverse");
  EXPECT_EQ(inverse.data[12], -0.5f);
  EXPECT_EQ(inverse.data[13], -0.5f);
  EXPECT_EQ(inverse.data[14], -0.375f);
  EXPECT_EQ(inverse.data[15], 1.0f);
}

TEST(GlStateUniforms, ProgramParameters) {
  const GlState s;
  ProgramParameters params;
  params.env[3] = {1, 2, 3, 4};
  params.local[5] = {5, 6, 7, 8};
  params.local[3] = {-1, -2, -3, -4};
  EXPECT_EQ(First4(Get(s, params, "program.env[3]")), (Vec4{1, 2, 3, 4}));
  EXPECT_EQ(First4(Get(s, params, "program.local[5]")), (Vec4{5, 6, 7, 8}));
  EXPECT_EQ(First4(Get(s, params, "program.local[3]")), (Vec4{-1, -2, -3, -4}));
  // GL's initial value.
  EXPECT_EQ(First4(Get(s, params, "program.env[5]")), (Vec4{0, 0, 0, 0}));
  EXPECT_EQ(First4(Get(s, params, "program.local[255]")), (Vec4{0, 0, 0, 0}));
  EXPECT_EQ(Get(s, params, "program.env[0]").type, UniformType::Vector);
}

// The spellings of what the translations emulate and ARB does not bind: a shadow lookup's
// GL_DEPTH_TEXTURE_MODE (each component 0, r or 1 as the selector reads 0, 1 or 2), the
// framebuffer's height, and the clip plane enables.
TEST(GlStateUniforms, EmulatedState) {
  GlState s;
  const ProgramParameters params;
  EXPECT_EQ(First4(Get(s, params, "texture[3].depthmode")), (Vec4{1, 1, 1, 2}));  // LUMINANCE
  s.depth_texture_mode[3] = kDepthModeIntensity;
  EXPECT_EQ(First4(Get(s, params, "texture[3].depthmode")), (Vec4{1, 1, 1, 1}));
  s.depth_texture_mode[3] = kDepthModeAlpha;
  EXPECT_EQ(First4(Get(s, params, "texture[3].depthmode")), (Vec4{0, 0, 0, 1}));
  s.depth_texture_mode[3] = kDepthModeRed;
  EXPECT_EQ(First4(Get(s, params, "texture[3].depthmode")), (Vec4{1, 0, 0, 2}));
  s.framebuffer_height = 250.0f;
  EXPECT_EQ(First4(Get(s, params, "framebuffer.height")), (Vec4{250, 0, 0, 0}));
  EXPECT_EQ(First4(Get(s, params, "clip[5].enabled")), (Vec4{0, 0, 0, 0}));
  s.clip_enabled[5] = true;
  EXPECT_EQ(First4(Get(s, params, "clip[5].enabled")), (Vec4{1, 0, 0, 0}));
  for (const char* bad : {"texture[16].depthmode", "clip[6].enabled", "clip[0].enable"}) {
    UniformData u;
    EXPECT_FALSE(UniformValue(s, params, bad, &u)) << bad;
  }
}

TEST(GlStateUniforms, RefusesWhatItCannotName) {
  const GlState s;
  const ProgramParameters params;
  const char* const bad[] = {
      "program.env[256]",  // kMaxProgramParams
      "program.local[-1]",
      "program.env[03]",
      "program.env",
      "program.env[0].x",
      "state.light[8].half",
      "state.clip[6].plane",
      "state.texenv[8].color",
      "state.matrix.texture[8]",
      "state.matrix.program[8].inverse",
      "state.matrix.program[8].row[0]",
      "state.matrix.modelview.row[0]",
      "state.lightmodel.scenecolor",
      "vertex.position",
      "arb_matrix_program0",
      "",
  };
  for (const char* name : bad) {
    UniformData u;
    u.data.fill(-99.0f);
    EXPECT_FALSE(UniformValue(s, params, name, &u)) << name;
    EXPECT_EQ(u.data[0], -99.0f) << name;  // left alone
  }
}

}  // namespace
}  // namespace arbiter::glstate
