// The inputs of a GLSL run (no GL): the slots a --set may name, --set and --uniform parsing,
// and the JSON vectors file.
#include <gtest/gtest.h>

#include <memory>

#include "arbiter/glsl/reflect.h"
#include "arbiter/runtime/glsl_exec.h"

namespace arbiter::runtime {
namespace {

glsl::Reflection Reflect(glsl::Stage stage, const std::string& text) {
  compiler::SourceFile file(stage == glsl::Stage::Vertex ? "t.vert" : "t.frag", text);
  compiler::DiagnosticSink sink(20);
  glsl::Reflection r = glsl::ReflectShader(stage, {&file}, &sink);
  EXPECT_EQ(sink.error_count(), 0u);
  return r;
}

const char* const kVertex =
    "attribute vec3 tangent;\nattribute mat2 m;\n"
    "void main() { gl_Position = gl_Vertex + vec4(tangent, m[1][0]); }\n";

TEST(GlslExecInputsTest, SetParsesAndFills) {
  const glsl::Reflection r = Reflect(glsl::Stage::Vertex, kVertex);
  const std::vector<GlslInputSlot> slots = GlslInputSlots(&r, nullptr);
  std::string name;
  std::vector<float> values;
  std::string error;
  ASSERT_TRUE(ParseGlslSet(slots, "gl_Vertex=1,2", &name, &values, &error)) << error;
  EXPECT_EQ(name, "gl_Vertex");
  EXPECT_EQ(values, (std::vector<float>{1, 2, 0, 1}));  // (0, 0, 0, 1) fills z and w
  ASSERT_TRUE(ParseGlslSet(slots, "m=1,2,3,4", &name, &values, &error)) << error;
  EXPECT_EQ(values, (std::vector<float>{1, 2, 3, 4}));
  ASSERT_TRUE(ParseGlslSet(slots, "gl_MultiTexCoord3=inf,-inf", &name, &values, &error));
  EXPECT_TRUE(std::isinf(values[0]) && values[0] > 0 && values[1] < 0);
}

TEST(GlslExecInputsTest, SetErrors) {
  const glsl::Reflection r = Reflect(glsl::Stage::Vertex, kVertex);
  const std::vector<GlslInputSlot> slots = GlslInputSlots(&r, nullptr);
  std::string name;
  std::vector<float> values;
  std::string error;
  EXPECT_FALSE(ParseGlslSet(slots, "tangnt=1,2,3", &name, &values, &error));
  EXPECT_EQ(error,
            "--set tangnt=1,2,3: the run has no input 'tangnt'; its inputs: gl_Vertex, tangent, m");
  EXPECT_FALSE(ParseGlslSet(slots, "tangent=1,2", &name, &values, &error));
  EXPECT_EQ(error, "--set tangent=1,2: tangent is a vec3 and takes 3 value(s), not 2");
  EXPECT_FALSE(ParseGlslSet(slots, "gl_Normal=1,2,3,4", &name, &values, &error));
  EXPECT_EQ(error, "--set gl_Normal=1,2,3,4: gl_Normal is a vec3 and takes 3 value(s), not 4");
  EXPECT_FALSE(ParseGlslSet(slots, "tangent=1,x,3", &name, &values, &error));
  EXPECT_EQ(error, "--set tangent=1,x,3: 'x' is not a number (decimal, inf, -inf or nan)");
}

TEST(GlslExecInputsTest, FragmentShaderAloneTakesItsInputs) {
  const glsl::Reflection r = Reflect(glsl::Stage::Fragment,
                                     "varying vec2 uv[2];\n"
                                     "void main() { gl_FragColor = gl_Color + gl_TexCoord[1] + "
                                     "vec4(uv[1], gl_FragCoord.z, 0.0); }\n");
  const std::vector<GlslInputSlot> slots = GlslInputSlots(nullptr, &r);
  std::vector<std::string> read;
  for (const GlslInputSlot& s : slots) {
    if (s.read) read.push_back(s.name);
  }
  EXPECT_EQ(read, (std::vector<std::string>{"gl_Color", "gl_TexCoord[1]", "gl_FragCoord.z", "uv[0]",
                                            "uv[1]"}));
  std::string name;
  std::vector<float> values;
  std::string error;
  EXPECT_FALSE(ParseGlslSet(slots, "gl_FragCoord=1,2,3", &name, &values, &error));
  EXPECT_NE(error.find("gl_FragCoord.xy is the vector's pixel: set gl_FragCoord.z only"),
            std::string::npos)
      << error;
  ASSERT_TRUE(ParseGlslSet(slots, "uv[1]=0.5,0.25", &name, &values, &error)) << error;
  EXPECT_EQ(values, (std::vector<float>{0.5f, 0.25f}));
}

// gl_TexCoord indexed by a variable: every element of its declared size is read, no other.
TEST(GlslExecInputsTest, TexCoordIndexedByAVariable) {
  const glsl::Reflection r = Reflect(glsl::Stage::Fragment,
                                     "#version 120\n"
                                     "varying vec4 gl_TexCoord[2];\n"
                                     "uniform int i;\n"
                                     "void main() { gl_FragColor = gl_TexCoord[i]; }\n");
  std::vector<std::string> read;
  for (const GlslInputSlot& s : GlslInputSlots(nullptr, &r)) {
    if (s.read) read.push_back(s.name);
  }
  EXPECT_EQ(read, (std::vector<std::string>{"gl_TexCoord[0]", "gl_TexCoord[1]"}));
}

TEST(GlslExecInputsTest, VectorsFile) {
  const glsl::Reflection r = Reflect(glsl::Stage::Vertex, kVertex);
  GlslExecInputs inputs;
  inputs.slots = GlslInputSlots(&r, nullptr);
  std::string error;
  ASSERT_TRUE(ParseGlslVectorsJson(
      R"({"set": {"tangent": [1, 2, 3], "state.fog.density": 2},
          "uniforms": {"lightDir": [0, 0, 1]},
          "textures": {"0": {"target": "2d", "pattern": "checker", "size": [2, 2]}},
          "vectors": [{"gl_Vertex": [1, 2, 3, 4]}, {"tangent": [4, 5, 6]}]})",
      &inputs, &error))
      << error;
  ASSERT_EQ(inputs.vectors.size(), 2u);
  EXPECT_EQ(inputs.vectors[0]["gl_Vertex"], (std::vector<float>{1, 2, 3, 4}));
  EXPECT_EQ(inputs.vectors[0]["tangent"], (std::vector<float>{1, 2, 3}));
  EXPECT_EQ(inputs.vectors[1]["gl_Vertex"], (std::vector<float>{0, 0, 0, 1}));
  EXPECT_EQ(inputs.vectors[1]["tangent"], (std::vector<float>{4, 5, 6}));
  ASSERT_EQ(inputs.uniforms.size(), 1u);
  EXPECT_EQ(inputs.uniforms[0].first, "lightDir");
  EXPECT_EQ(inputs.state.fog_density, 2.0f);
  EXPECT_EQ(inputs.textures.count(0), 1u);
  EXPECT_FALSE(ParseGlslVectorsJson(R"({"vectors": [{"tangnt": [1, 2, 3]}]})", &inputs, &error));
  EXPECT_NE(error.find("no input 'tangnt'"), std::string::npos) << error;
}

}  // namespace
}  // namespace arbiter::runtime
