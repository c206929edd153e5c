// GLSL shaders run on Mesa (RunGlsl), with values from the GLSL and GL specs' formulas.
// ARBITER_TEST_BACKEND (osmesa, egl) and ARBITER_TEST_DRIVER (softpipe, llvmpipe) choose the
// context; one process per combination (tests/glsl_exec/CMakeLists.txt).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "glsl_run.h"

namespace arbiter::runtime {
namespace {

using testing::GlslRun;

using V = std::vector<float>;

// GLSL 1.10 7.5: gl_ModelViewProjectionMatrix = projection * modelview. The --state
// matrices are row-major: modelview translates by (1, 2, 3), projection scales by (2, 3, 4).
TEST(GlslExecTest, PositionFromTheModelViewProjectionMatrix) {
  GlslRun run("void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }\n", "");
  run.State("state.matrix.modelview=1,0,0,1, 0,1,0,2, 0,0,1,3, 0,0,0,1");
  run.State("state.matrix.projection=2,0,0,0, 0,3,0,0, 0,0,4,0, 0,0,0,1");
  run.Set("gl_Vertex=1,1,1,1");
  run.Run();
  // modelview: (2, 3, 4, 1); projection: (4, 9, 16, 1).
  EXPECT_EQ(run.Output("gl_Position"), (V{4, 9, 16, 1}));
}

// GLSL 1.10 8.4, 8.3, 8.2: dot, clamp, mix (x (1 - a) + y a), pow (exact here: 2^3), and
// normalize (x / length(x)) within the precision GLSL leaves to the implementation.
TEST(GlslExecTest, BuiltinFunctionsInAVarying) {
  GlslRun run(
      "attribute vec3 tangent;\n"
      "varying vec4 f;\n"
      "varying vec3 n;\n"
      "void main() {\n"
      "  gl_Position = gl_Vertex;\n"
      "  f = vec4(dot(tangent, vec3(4.0, 5.0, 6.0)), clamp(tangent.z, 0.0, 1.0),\n"
      "           mix(2.0, 4.0, 0.25), pow(2.0, tangent.z));\n"
      "  n = normalize(vec3(0.0, tangent.y * 1.5, tangent.y * 2.0));\n"
      "}\n",
      "");
  run.Set("tangent=1,2,3");
  run.Run();
  EXPECT_EQ(run.Output("f"), (V{32, 1, 2.5f, 8}));
  const V n = run.Output("n");
  ASSERT_EQ(n.size(), 3u);
  EXPECT_EQ(n[0], 0.0f);
  EXPECT_NEAR(n[1], 0.6f, 1e-6f);  // (0, 3, 4) / 5
  EXPECT_NEAR(n[2], 0.8f, 1e-6f);
}

// A structure's members and an array's elements are uniforms of their own (GL 2.0 2.15.3).
TEST(GlslExecTest, StructAndArrayUniforms) {
  GlslRun run(
      "struct Light { vec3 pos; float k; };\n"
      "uniform Light light;\n"
      "uniform float w[3];\n"
      "varying vec4 v;\n"
      "void main() { gl_Position = gl_Vertex; v = vec4(light.pos * light.k, w[1] + w[2]); }\n",
      "");
  run.Uniform("light.pos=1,2,3");
  run.Uniform("light.k=0.5");
  run.Uniform("w=10,20,30");
  run.Uniform("w[2]=40");  // later assignments win
  const GlslRunResult& result = run.Run();
  EXPECT_EQ(run.Output("v"), (V{0.5f, 1, 1.5f, 60}));
  EXPECT_TRUE(result.notes.empty());
}

// gl_FrontColor, gl_TexCoord[n] and gl_PointSize are read back as written (no clamping).
TEST(GlslExecTest, BuiltinVaryingsUnclamped) {
  GlslRun run(
      "void main() {\n"
      "  gl_Position = gl_Vertex;\n"
      "  gl_FrontColor = gl_Color * 4.0;\n"
      "  gl_TexCoord[2] = gl_MultiTexCoord1.wzyx;\n"
      "  gl_PointSize = 3.0;\n"
      "}\n",
      "");
  run.Set("gl_Color=0.5,-1,0");  // alpha: 1
  run.Set("gl_MultiTexCoord1=1,2");
  run.Run();
  EXPECT_EQ(run.Output("gl_FrontColor"), (V{2, -4, 0, 4}));
  EXPECT_EQ(run.Output("gl_TexCoord[2]"), (V{1, 0, 2, 1}));
  EXPECT_EQ(run.Output("gl_PointSize"), (V{3}));
}

// A fragment shader alone: its inputs from --set, gl_FragData[n] on colour attachment n,
// gl_FragDepth from the depth buffer, gl_FragCoord = (x + 0.5, y + 0.5, depth) of the
// vector's pixel (vector 1: x = 1).
TEST(GlslExecTest, FragmentDataDepthAndDiscard) {
  GlslRun run("",
              "varying vec3 t;\n"
              "void main() {\n"
              "  if (gl_TexCoord[0].x < 0.0) discard;\n"
              "  gl_FragData[0] = gl_Color;\n"
              "  gl_FragData[1] = vec4(t, gl_FragCoord.x);\n"
              "  gl_FragDepth = gl_FragCoord.z * 0.5;\n"
              "}\n");
  run.Vectors(3);
  run.Set("gl_Color=0.5,0.25,2,1", 0);
  run.Set("t=1,2,3", 0);
  run.Set("gl_FragCoord.z=0.75", 0);
  run.Set("gl_TexCoord[0]=-1", 1);
  run.Set("t=-4,5,6", 2);
  const GlslRunResult& result = run.Run();
  ASSERT_EQ(result.vectors.size(), 3u);
  EXPECT_FALSE(result.vectors[0].discarded);
  EXPECT_EQ(run.Output("gl_FragData[0]"), (V{0.5f, 0.25f, 2, 1}));
  EXPECT_EQ(run.Output("gl_FragData[1]"), (V{1, 2, 3, 0.5f}));
  EXPECT_EQ(run.Output("gl_FragDepth"), (V{0.375f}));
  EXPECT_TRUE(result.vectors[1].discarded);
  EXPECT_TRUE(result.vectors[1].outputs.empty());
  EXPECT_EQ(run.Output("gl_FragData[1]", 2), (V{-4, 5, 6, 2.5f}));
  EXPECT_EQ(run.Output("gl_FragDepth", 2), (V{0.25f}));  // default window depth 0.5
}

// A pair: the vertex outputs by transform feedback, then the fragment shader fed by the
// vertex shader, with GL's vertex colour clamping to [0, 1] (GL 2.0 2.14.6) on the way.
TEST(GlslExecTest, PairClampsColoursBetweenTheStages) {
  GlslRun run(
      "varying float k;\n"
      "void main() { gl_Position = gl_Vertex; gl_FrontColor = vec4(2.0, -1.0, 0.5, 1.0);\n"
      "  k = gl_Vertex.x * 3.0; }\n",
      "varying float k;\n"
      "void main() { gl_FragColor = vec4(gl_Color.xyz, k); }\n");
  run.Set("gl_Vertex=0.5,0,0,1");
  run.Run();
  EXPECT_EQ(run.Output("gl_FrontColor"), (V{2, -1, 0.5f, 1}));
  EXPECT_EQ(run.Output("k"), (V{1.5f}));
  EXPECT_EQ(run.Output("gl_FragColor"), (V{1, 0, 0.5f, 1.5f}));
}

// A sampler reads the texture of the unit its uniform holds; bvec, ivec arrays and matrix
// arrays take their values element by element (GL 2.0 2.15.3, Uniform*).
TEST(GlslExecTest, SamplersBoolsIntsAndMatrixArrays) {
  GlslRun run("",
              "#version 120\n"
              "uniform sampler2D tex;\n"
              "uniform bvec2 flags;\n"
              "uniform ivec3 counts[2];\n"
              "uniform mat2 ms[2];\n"
              "void main() {\n"
              "  vec4 c = texture2D(tex, gl_TexCoord[0].xy);\n"
              "  gl_FragColor = c + vec4(flags.y ? 1.0 : 0.0, float(counts[1].z), ms[1][1][0],\n"
              "                          flags.x ? 1.0 : 0.0);\n"
              "}\n");
  // "gradient": each texel's centre coordinates as r and g; the texel at (0.25, 0.75) of a
  // 2x2 texture is (0.25, 0.75, 0.5, 1) (nearest).
  run.Texture("1=2d:gradient:2x2");
  run.Uniform("tex=1");
  run.Uniform("flags=0,1");
  run.Uniform("counts[1]=4,5,6");
  run.Uniform("ms=1,2,3,4,5,6,7,8");  // ms[1] = mat2(5, 6, 7, 8): ms[1][1][0] = 7
  run.Set("gl_TexCoord[0]=0.25,0.75");
  const GlslRunResult& result = run.Run();
  EXPECT_EQ(run.Output("gl_FragColor"), (V{1.25f, 6.75f, 7.5f, 1}));
  EXPECT_TRUE(result.notes.empty());
}

// Non-finite values and -0 survive the worker's JSON (GLSL 1.10 leaves x / 0 undefined;
// Mesa computes x * (1 / 0)).
TEST(GlslExecTest, NonFiniteValuesThroughTheWorker) {
  GlslRun run(
      "uniform vec4 u;\n"
      "varying vec4 v;\n"
      "void main() { gl_Position = gl_Vertex; v = u; }\n",
      "");
  run.Uniform("u=inf,-inf,nan,-0");
  const GlslRunResult& result = run.RunInWorker();
  ASSERT_EQ(result.vectors.size(), 1u);
  const V v = run.Output("v");
  ASSERT_EQ(v.size(), 4u);
  EXPECT_EQ(v[0], std::numeric_limits<float>::infinity());
  EXPECT_EQ(v[1], -std::numeric_limits<float>::infinity());
  EXPECT_TRUE(std::isnan(v[2]));
  EXPECT_EQ(v[3], 0.0f);
  EXPECT_TRUE(std::signbit(v[3]));
  EXPECT_FALSE(result.description.empty());
}

// Uniforms the shader uses that no --uniform sets are named, not silently zero.
TEST(GlslExecTest, UnsetUniformIsANote) {
  GlslRun run(
      "uniform vec3 lightDir;\n"
      "uniform sampler2D tex;\n"
      "varying vec4 c;\n"
      "void main() { gl_Position = gl_Vertex;\n"
      "  c = vec4(lightDir, 1.0) + texture2DLod(tex, vec2(0.5), 0.0); }\n",
      "");
  const GlslRunResult& result = run.Run();
  EXPECT_EQ(result.notes, (std::vector<std::string>{"uniform lightDir not set: read as zero",
                                                    "sampler tex not set: reads texture unit 0"}));
  // An incomplete texture (none on unit 0) reads (0, 0, 0, 1).
  EXPECT_EQ(run.Output("c"), (V{0, 0, 0, 2}));
}

TEST(GlslExecTest, UniformErrorsAreUsageErrors) {
  const std::string shader =
      "uniform vec3 lightDir;\nuniform int n;\nuniform float w[2];\nvarying vec4 c;\n"
      "void main() { gl_Position = gl_Vertex; c = vec4(lightDir, float(n) + w[1]); }\n";
  struct Case {
    std::string assignment;
    std::string error;
  };
  for (const Case& c : std::vector<Case>{
           {"lightDr=1,2,3",
            "--uniform lightDr: the shaders have no uniform 'lightDr'; active uniforms: lightDir, "
            "n, w[0]"},
           {"lightDir=1,2", "--uniform lightDir: lightDir is a vec3 and takes 3 value(s), not 2"},
           {"n=1.5", "--uniform n: n is of type int: its values are integers"},
           {"w=1,2,3",
            "--uniform w: w is a float[2] and takes 1 value(s) per element, for 1 to 2 elements, "
            "not 3 value(s)"},
       }) {
    GlslRun run(shader, "");
    run.Uniform(c.assignment);
    const GlslRunResult& result = run.Run();
    EXPECT_EQ(result.usage_error, c.error);
    EXPECT_TRUE(result.vectors.empty());
  }
}

}  // namespace
}  // namespace arbiter::runtime
