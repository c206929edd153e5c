// The GLSL verify's inputs (GenerateGlslInputs) and tolerance model (WithinTolerance): every
// input the shaders read gets values, uniforms element by element and member by member,
// integers small, clamped colours in [0, 1], the same batches for a seed; and the relative
// bounds of docs/verify.md.
#include "arbiter/arbvp/generate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/runtime/glsl_verify.h"
#include "glsl_verify/internal.h"

namespace arbiter::runtime {
namespace {

struct Shader {
  std::unique_ptr<compiler::SourceFile> file;
  glsl::Reflection reflection;
};

Shader Load(glsl::Stage stage, const std::string& text) {
  Shader s;
  s.file = std::make_unique<compiler::SourceFile>("g.glsl", text);
  compiler::DiagnosticSink sink(0);
  s.reflection = glsl::ReflectShader(stage, {s.file.get()}, &sink);
  EXPECT_TRUE(s.reflection.ok);
  return s;
}

const char* kVertex =
    "#version 120\n"
    "struct Light { vec4 color; float k[2]; };\n"
    "uniform Light lights[2];\n"
    "uniform int count;\n"
    "uniform bool on;\n"
    "uniform mat3 m;\n"
    "uniform float w[3];\n"
    "uniform sampler2D tex;\n"
    "attribute vec3 tangent;\n"
    "void main() {\n"
    "  vec4 c = vec4(0.0);\n"
    "  for (int i = 0; i < count; ++i) c += lights[i].color * lights[i].k[1];\n"
    "  if (on) c.xyz += m * tangent;\n"
    "  gl_Position = gl_Vertex + c + vec4(w[2]) + texture2DLod(tex, gl_Vertex.xy, 0.0);\n"
    "}\n";

TEST(GlslVerifyGenerate, EveryInputGetsValues) {
  Shader v = Load(glsl::Stage::Vertex, kVertex);
  GlslVerifySubject subject{"g.vert", v.file.get(), nullptr, &v.reflection, nullptr};
  arbvp::GenerateOptions options;
  options.random_vectors = 70;  // two random batches: 64 and 6
  std::string error;
  const std::vector<GlslBatch> batches = GenerateGlslInputs(subject, options, &error);
  ASSERT_EQ(batches.size(), 3u) << error;
  EXPECT_EQ(batches[0].name, "edge");
  EXPECT_EQ(batches[0].inputs.vectors.size(), arbvp::FiniteEdgeValues().size());
  EXPECT_EQ(batches[1].inputs.vectors.size(), 64u);
  EXPECT_EQ(batches[2].name, "random 2");
  EXPECT_EQ(batches[2].inputs.vectors.size(), 6u);
  for (const GlslBatch& b : batches) {
    std::map<std::string, std::vector<float>> uniforms(b.inputs.uniforms.begin(),
                                                       b.inputs.uniforms.end());
    std::set<std::string> names;
    for (const auto& [name, values] : uniforms) names.insert(name);
    const std::set<std::string> want = {"lights[0].color",
                                        "lights[0].k[0]",
                                        "lights[0].k[1]",
                                        "lights[1].color",
                                        "lights[1].k[0]",
                                        "lights[1].k[1]",
                                        "count",
                                        "on",
                                        "m",
                                        "w[0]",
                                        "w[1]",
                                        "w[2]",
                                        "tex"};
    EXPECT_EQ(names, want) << b.name;
    EXPECT_EQ(uniforms["m"].size(), 9u);
    EXPECT_EQ(uniforms["lights[1].color"].size(), 4u);
    EXPECT_EQ(uniforms["tex"], std::vector<float>{0.0f});
    ASSERT_EQ(b.inputs.textures.count(0), 1u);
    EXPECT_EQ(b.inputs.textures.at(0).dim, arbvp::TexDim::Tex2D);
    // Integers count loops and index arrays: 0..3; booleans 0 or 1.
    EXPECT_GE(uniforms["count"][0], 0.0f);
    EXPECT_LE(uniforms["count"][0], 3.0f);
    EXPECT_EQ(uniforms["count"][0], std::floor(uniforms["count"][0]));
    EXPECT_TRUE(uniforms["on"][0] == 0.0f || uniforms["on"][0] == 1.0f);
    for (size_t u = 0; u < b.inputs.uniforms.size(); ++u) {
      const std::string& name = b.inputs.uniforms[u].first;
      EXPECT_EQ(b.float_uniforms[u], name != "count" && name != "on" && name != "tex") << name;
    }
    for (const auto& vector : b.inputs.vectors) {
      ASSERT_EQ(vector.count("tangent"), 1u);
      ASSERT_EQ(vector.count("gl_Vertex"), 1u);
      for (bool enabled : b.inputs.state.clip_enabled) EXPECT_FALSE(enabled);
      for (const auto& [name, values] : vector) {
        for (float x : values) {
          EXPECT_TRUE(std::isfinite(x)) << name;
          EXPECT_LE(std::fabs(x), 0x1p32f) << name;
        }
      }
    }
  }
  // The edge batch takes its values from the finite edge values.
  const std::vector<float>& edge = arbvp::FiniteEdgeValues();
  for (const auto& vector : batches[0].inputs.vectors) {
    for (float x : vector.at("tangent")) {
      EXPECT_NE(std::find(edge.begin(), edge.end(), x), edge.end()) << x;
    }
  }
  // Deterministic.
  const std::vector<GlslBatch> again = GenerateGlslInputs(subject, options, &error);
  ASSERT_EQ(again.size(), batches.size());
  for (size_t b = 0; b < batches.size(); ++b) {
    EXPECT_EQ(again[b].inputs.vectors, batches[b].inputs.vectors);
    EXPECT_EQ(again[b].inputs.uniforms, batches[b].inputs.uniforms);
  }
}

TEST(GlslVerifyGenerate, FragmentColoursComeClamped) {
  Shader f = Load(glsl::Stage::Fragment,
                  "varying vec2 uv;\n"
                  "void main() { gl_FragColor = gl_Color + vec4(uv, gl_FragCoord.z, 0.0); }\n");
  GlslVerifySubject subject{"g.frag", nullptr, f.file.get(), nullptr, &f.reflection};
  std::string error;
  const std::vector<GlslBatch> batches = GenerateGlslInputs(subject, {}, &error);
  ASSERT_FALSE(batches.empty()) << error;
  bool big_uv = false;
  for (const GlslBatch& b : batches) {
    for (const auto& vector : b.inputs.vectors) {
      for (float x : vector.at("gl_Color")) {
        EXPECT_GE(x, 0.0f);
        EXPECT_LE(x, 1.0f);
      }
      const float near = std::min(b.inputs.state.depth_near, b.inputs.state.depth_far);
      const float far = std::max(b.inputs.state.depth_near, b.inputs.state.depth_far);
      for (float x : vector.at("gl_FragCoord.z")) {
        EXPECT_GE(x, near);  // within the depth range
        EXPECT_LE(x, far);
      }
      for (float x : vector.at("uv")) big_uv |= std::fabs(x) > 1.0f;
    }
  }
  EXPECT_TRUE(big_uv);  // user varyings take the whole range
}

TEST(GlslVerifyGenerate, UniformTypeSpellings) {
  std::vector<glsl_verify::UniformLeaf> leaves;
  glsl_verify::ExpandUniform("s", "struct S { struct T { vec2 a; } t[2]; mat2 m; }", 0, &leaves);
  ASSERT_EQ(leaves.size(), 3u);
  EXPECT_EQ(leaves[0].name, "s.t[0].a");
  EXPECT_EQ(leaves[1].name, "s.t[1].a");
  EXPECT_EQ(leaves[2].name, "s.m");
  EXPECT_EQ(leaves[2].components, 4);
  EXPECT_EQ(glsl_verify::BasicComponents("mat3x2"), 6);
  EXPECT_EQ(glsl_verify::BasicComponents("sampler2D"), 0);
}

TEST(GlslVerifyTolerance, RelativeBounds) {
  const GlslTolerance exact;
  GlslTolerance loose;
  loose.loose = true;
  GlslTolerance textured;
  textured.textured = true;
  // 2^-14 of the larger magnitude (or of the inputs' scale), 2^-10 with imprecise built-ins,
  // 2^-7 with texture lookups.
  EXPECT_TRUE(WithinTolerance(1.0f, 1.0f + 0x1p-15f, 1.0f, exact));
  EXPECT_FALSE(WithinTolerance(1.0f, 1.0f + 0x1p-13f, 1.0f, exact));
  EXPECT_TRUE(WithinTolerance(1024.0f, 1024.0f + 0x1p-5f, 1.0f, exact));
  EXPECT_FALSE(WithinTolerance(1024.0f, 1024.0f + 0x1p-3f, 1.0f, exact));
  EXPECT_TRUE(WithinTolerance(0.0f, 0x1p-11f, 16.0f, exact));  // inputs' scale 16
  EXPECT_FALSE(WithinTolerance(0.0f, 0x1p-9f, 16.0f, exact));
  EXPECT_TRUE(WithinTolerance(1.0f, 1.0f + 0x1p-11f, 1.0f, loose));
  EXPECT_FALSE(WithinTolerance(1.0f, 1.0f + 0x1p-9f, 1.0f, loose));
  EXPECT_TRUE(WithinTolerance(0.5f, 0.5f + 0x1p-8f, 1.0f, textured));
  EXPECT_FALSE(WithinTolerance(0.5f, 0.5f + 0x1p-6f, 1.0f, textured));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_TRUE(WithinTolerance(nan, nan, 1.0f, exact));
  EXPECT_FALSE(WithinTolerance(nan, 1.0f, 1.0f, loose));
  EXPECT_TRUE(WithinTolerance(inf, inf, 1.0f, exact));
  EXPECT_FALSE(WithinTolerance(inf, -inf, 1.0f, exact));
  EXPECT_FALSE(WithinTolerance(inf, 3e38f, 1.0f, loose));
  EXPECT_TRUE(WithinTolerance(0.0f, -0.0f, 1.0f, exact));
}

}  // namespace
}  // namespace arbiter::runtime
