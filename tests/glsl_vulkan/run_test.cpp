// GLSL shaders run on the Vulkan engine (RunGlslVulkan: lowered to 4.50, lavapipe) and on Mesa
// GL (RunGlsl, softpipe), each checked against values from the GLSL and GL specs' formulas,
// and the two results compared output by output.
#include <gtest/gtest.h>

#include <cmath>

#include "../glsl_exec/glsl_run.h"
#include "arbiter/runtime/glsl_vulkan.h"

namespace arbiter::runtime {
namespace {

using testing::GlslRun;
using V = std::vector<float>;

// The Vulkan run of `run`'s shaders and inputs; the GL run stays in run.result().
GlslRunResult RunVulkan(GlslRun& run) {
  GlslRunResult result;
  std::string not_applicable;
  std::string error;
  EXPECT_TRUE(RunGlslVulkan(run.shaders(), run.inputs(), &result, &not_applicable, &error))
      << not_applicable << error;
  EXPECT_TRUE(not_applicable.empty()) << not_applicable;
  return result;
}

std::vector<float> Output(const GlslRunResult& result, const std::string& name, size_t v = 0) {
  for (const GlslOutput& o : result.vectors.at(v).outputs) {
    if (o.name == name) return o.value;
  }
  return {};
}

// Both engines: every output of `expected` as given, and the two results alike output by
// output (same names, stages, types, order, values and discards).
void ExpectBoth(GlslRun& run, const std::vector<std::pair<std::string, V>>& expected,
                size_t vector = 0) {
  const GlslRunResult vk = RunVulkan(run);
  const GlslRunResult& gl = run.Run();
  for (const auto& [name, value] : expected) {
    EXPECT_EQ(Output(vk, name, vector), value) << "vulkan " << name;
    EXPECT_EQ(Output(gl, name, vector), value) << "mesa " << name;
  }
  ASSERT_EQ(vk.vectors.size(), gl.vectors.size());
  for (size_t v = 0; v < vk.vectors.size(); ++v) {
    EXPECT_EQ(vk.vectors[v].discarded, gl.vectors[v].discarded) << "vector " << v;
    ASSERT_EQ(vk.vectors[v].outputs.size(), gl.vectors[v].outputs.size()) << "vector " << v;
    for (size_t o = 0; o < vk.vectors[v].outputs.size(); ++o) {
      const GlslOutput& a = vk.vectors[v].outputs[o];
      const GlslOutput& b = gl.vectors[v].outputs[o];
      EXPECT_EQ(a.name, b.name);
      EXPECT_EQ(a.stage, b.stage);
      EXPECT_EQ(a.type, b.type);
      EXPECT_EQ(a.value, b.value) << a.name;
    }
  }
  EXPECT_EQ(vk.usage_error, gl.usage_error);
}

// GLSL 1.10 7.5: gl_ModelViewProjectionMatrix = projection * modelview; ftransform() the same
// product with gl_Vertex.
TEST(GlslVulkanTest, MatricesAndFtransform) {
  GlslRun run(
      "varying vec4 p;\n"
      "void main() { gl_Position = ftransform(); p = gl_ModelViewMatrix * gl_Vertex; }\n",
      "");
  run.State("state.matrix.modelview=1,0,0,1, 0,1,0,2, 0,0,1,3, 0,0,0,1");
  run.State("state.matrix.projection=2,0,0,0, 0,3,0,0, 0,0,4,0, 0,0,0,1");
  run.Set("gl_Vertex=1,1,1,1");
  ExpectBoth(run, {{"gl_Position", {4, 9, 16, 1}}, {"p", {2, 3, 4, 1}}});
}

// GLSL 1.10 7.5: gl_NormalMatrix is the inverse transpose of the modelview's upper-left 3x3;
// for modelview = diag(2, 4, 8, 1): diag(1/2, 1/4, 1/8). gl_NormalScale (Mesa: 1 / the
// length of the inverse modelview's third row) is 8.
TEST(GlslVulkanTest, NormalMatrixAndScale) {
  GlslRun run(
      "varying vec3 n;\n"
      "varying float s;\n"
      "void main() { gl_Position = gl_Vertex; n = gl_NormalMatrix * gl_Normal;"
      " s = gl_NormalScale; }\n",
      "");
  run.State("state.matrix.modelview=2,0,0,0, 0,4,0,0, 0,0,8,0, 0,0,0,1");
  run.Set("gl_Normal=1,1,1");
  ExpectBoth(run, {{"n", {0.5f, 0.25f, 0.125f}}, {"s", {8}}});
}

// Lights, materials, their products (GL 2.0 2.14.1: light diffuse * material diffuse), the
// light model, fog (scale = 1 / (end - start)), point and depth range parameters.
TEST(GlslVulkanTest, BuiltinUniformState) {
  GlslRun run(
      "varying vec4 a;\n"
      "varying vec4 b;\n"
      "varying vec4 c;\n"
      "varying vec4 d;\n"
      "void main() {\n"
      "  gl_Position = gl_Vertex;\n"
      "  a = gl_LightSource[1].diffuse + vec4(gl_LightSource[1].spotExponent);\n"
      "  b = gl_FrontLightProduct[1].diffuse;\n"
      "  c = vec4(gl_Fog.density, gl_Fog.start, gl_Fog.end, gl_Fog.scale);\n"
      "  d = vec4(gl_Point.size, gl_DepthRange.near, gl_DepthRange.far, gl_DepthRange.diff);\n"
      "}\n",
      "");
  run.State("state.light[1].diffuse=0.5,0.25,1,1");
  run.State("state.light[1].spot.exponent=2");
  run.State("state.material.front.diffuse=0.5,0.5,0.5,0.75");
  run.State("state.fog.density=2");
  run.State("state.fog.start=1");
  run.State("state.fog.end=5");
  run.State("state.point.size=3");
  run.State("state.depth.range=0.25,0.75");
  ExpectBoth(run, {{"a", {2.5f, 2.25f, 3, 3}},
                   {"b", {0.25f, 0.125f, 0.5f, 0.75f}},
                   {"c", {2, 1, 5, 0.25f}},
                   {"d", {3, 0.25f, 0.75f, 0.5f}}});
}

// Attributes (user, built-in, a matrix attribute column by column) and varyings of every
// float type, with user identifiers that GLSL 4.50 reserves renamed consistently.
TEST(GlslVulkanTest, AttributesVaryingsAndRenamedIdentifiers) {
  GlslRun run(
      "attribute vec3 texture;\n"
      "attribute mat2 sample;\n"
      "varying vec4 filter;\n"
      "varying mat2 layout;\n"
      "varying float smooth[2];\n"
      "void main() {\n"
      "  gl_Position = gl_Vertex;\n"
      "  filter = vec4(texture, gl_MultiTexCoord3.w);\n"
      "  layout = sample * 2.0;\n"
      "  smooth[0] = gl_FogCoord; smooth[1] = gl_Color.g;\n"
      "  gl_TexCoord[2] = gl_SecondaryColor;\n"
      "}\n",
      "");
  run.Set("texture=1,2,3");
  run.Set("sample=1,2,3,4");
  run.Set("gl_MultiTexCoord3=0,0,0,7");
  run.Set("gl_FogCoord=9");
  run.Set("gl_Color=0,0.5,0,1");
  run.Set("gl_SecondaryColor=0.25,0.5,0.75");
  ExpectBoth(run, {{"filter", {1, 2, 3, 7}},
                   {"layout", {2, 4, 6, 8}},
                   {"smooth[0]", {9}},
                   {"smooth[1]", {0.5f}},
                   {"gl_TexCoord[2]", {0.25f, 0.5f, 0.75f, 1}}});
}

// Structures, arrays and matrices as uniforms, set by name (a matrix column by column), and
// the note on an unset uniform.
TEST(GlslVulkanTest, StructArrayAndMatrixUniforms) {
  GlslRun run(
      "struct Light { vec3 pos; float k; };\n"
      "uniform Light light;\n"
      "uniform float w[3];\n"
      "uniform mat3 m;\n"
      "uniform vec4 unset;\n"
      "varying vec4 v;\n"
      "varying vec3 r;\n"
      "void main() {\n"
      "  gl_Position = gl_Vertex + unset;\n"
      "  v = vec4(light.pos * light.k, w[1] + w[2]);\n"
      "  r = m * vec3(1.0, 10.0, 100.0);\n"
      "}\n",
      "");
  run.Uniform("light.pos=1,2,3");
  run.Uniform("light.k=0.5");
  run.Uniform("w=10,20,30");
  run.Uniform("w[2]=40");
  run.Uniform("m=1,2,3,4,5,6,7,8,9");
  ExpectBoth(run, {{"v", {0.5f, 1, 1.5f, 60}}, {"r", {741, 852, 963}}});
  GlslRunResult vk = RunVulkan(run);
  EXPECT_EQ(vk.notes, (std::vector<std::string>{"uniform unset not set: read as zero"}));
}

// A --uniform of the wrong size is a usage error, as on Mesa; one naming nothing declared too.
TEST(GlslVulkanTest, UniformUsageErrors) {
  GlslRun run("uniform vec3 dir;\nvoid main() { gl_Position = vec4(dir, 1.0); }\n", "");
  run.Uniform("dir=1,2");
  const GlslRunResult vk = RunVulkan(run);
  EXPECT_EQ(vk.usage_error, "--uniform dir: dir is a vec3 and takes 3 value(s), not 2");
  EXPECT_TRUE(vk.vectors.empty());
  GlslRun other("uniform vec3 dir;\nvoid main() { gl_Position = vec4(dir, 1.0); }\n", "");
  other.Uniform("nothing=1");
  EXPECT_EQ(RunVulkan(other).usage_error,
            "--uniform nothing: the shaders have no uniform 'nothing'; active uniforms: dir");
}

// A fragment shader alone: its inputs as given, gl_FragCoord at the vector's pixel (GL's
// lower-left origin: vector 65 is pixel (1, 1)) with the given depth, discard, gl_FragData
// and gl_FragDepth.
TEST(GlslVulkanTest, FragmentInputsFragCoordDiscardAndOutputs) {
  GlslRun run("",
              "varying vec2 uv;\n"
              "void main() {\n"
              "  if (gl_Color.r > 0.5) discard;\n"
              "  gl_FragData[0] = gl_FragCoord;\n"
              "  gl_FragData[1] = vec4(uv, gl_TexCoord[1].xy);\n"
              "  gl_FragDepth = gl_Color.g;\n"
              "}\n");
  run.Vectors(66);
  run.Set("gl_Color=1,0,0,1", 0);
  run.Set("gl_Color=0,0.25,0,1", 65);
  run.Set("uv=3,4", 65);
  run.Set("gl_TexCoord[1]=5,6,0,1", 65);
  run.Set("gl_FragCoord.z=0.75", 65);
  ExpectBoth(run,
             {{"gl_FragData[0]", {1.5f, 1.5f, 0.75f, 1}},
              {"gl_FragData[1]", {3, 4, 5, 6}},
              {"gl_FragDepth", {0.25f}}},
             65);
  const GlslRunResult vk = RunVulkan(run);
  EXPECT_TRUE(vk.vectors[0].discarded);
  EXPECT_TRUE(vk.vectors[0].outputs.empty());
  EXPECT_TRUE(vk.vectors[1].discarded);  // gl_Color's fill is (1, 1, 1, 1)
  EXPECT_FALSE(vk.vectors[65].discarded);
}

// A pair: the vertex shader's outputs (unclamped) and the fragment's, fed through the
// varyings with GL's vertex colour clamping (gl_FrontColor 2 reaches gl_Color as 1).
TEST(GlslVulkanTest, PairClampsColoursAndPassesVaryings) {
  GlslRun run(
      "varying vec3 v;\n"
      "void main() { gl_Position = ftransform(); gl_FrontColor = vec4(2.0, 0.5, -1.0, 1.0);"
      " gl_TexCoord[0] = vec4(7.0); v = gl_Normal * 3.0; }\n",
      "varying vec3 v;\n"
      "void main() { gl_FragColor = gl_Color + vec4(v, gl_TexCoord[0].x); }\n");
  run.Set("gl_Normal=1,2,3");
  ExpectBoth(
      run,
      {{"gl_FrontColor", {2, 0.5f, -1, 1}}, {"v", {3, 6, 9}}, {"gl_FragColor", {4, 6.5f, 9, 8}}});
}

// Samplers on texture units (nearest filtering of the gradient pattern: texel (x, y, z)
// holds its centre ((x + .5) / W, (y + .5) / H, (z + .5) / D, 1)): a 2D texture, a cube map
// (+X face, layer 0 of 6: s = t = 0.75 for the direction (1, -.5, -.5)), and shadow
// comparisons (LEQUAL against the depth gradient) expanded by GL_DEPTH_TEXTURE_MODE
// LUMINANCE: (r, r, r, 1).
TEST(GlslVulkanTest, SamplersWithTextures) {
  GlslRun run("",
              "uniform sampler2D tex;\n"
              "uniform samplerCube cube;\n"
              "uniform sampler2DShadow depth;\n"
              "void main() {\n"
              "  gl_FragData[0] = texture2D(tex, vec2(0.125, 0.375));\n"
              "  gl_FragData[1] = textureCube(cube, vec3(1.0, -0.5, -0.5));\n"
              "  gl_FragData[2] = shadow2D(depth, vec3(0.625, 0.5, 0.5));\n"
              "  gl_FragData[3] = shadow2D(depth, vec3(0.125, 0.5, 0.5));\n"
              "}\n");
  run.Texture("1=2d:gradient:4x4:nearest");
  run.Texture("2=cube:gradient:2x2:nearest");
  run.Texture("3=2d:depth-gradient-compare:4x4:nearest");
  run.Uniform("tex=1");
  run.Uniform("cube=2");
  run.Uniform("depth=3");
  ExpectBoth(run, {{"gl_FragData[0]", {0.125f, 0.375f, 0.5f, 1}},
                   {"gl_FragData[1]", {0.75f, 0.75f, 0.5f / 6.0f, 1}},
                   {"gl_FragData[2]", {1, 1, 1, 1}},
                   {"gl_FragData[3]", {0, 0, 0, 1}}});
}

// What cannot be lowered exactly is refused with its reason, never run.
TEST(GlslVulkanTest, Refusals) {
  const std::pair<const char*, const char*> cases[] = {
      {"#version 120\nuniform float k = 2.0;\nvoid main() { gl_FragColor = vec4(k); }\n",
       "not applicable: a uniform initializer (GLSL 1.20 4.3.5)"},
      {"void main() { gl_FragColor = vec4(noise1(1.0)); }\n",
       "not applicable: noise1 (Mesa's noise functions return 0)"},
      {"#version 120\nvoid main() { gl_FragColor = vec4(gl_PointCoord, 0.0, 1.0); }\n",
       "not applicable: gl_PointCoord"},
      {"#extension GL_ARB_texture_rectangle : enable\nuniform sampler2DRect r;\n"
       "void main() { gl_FragColor = texture2DRect(r, vec2(0.0)); }\n",
       "not applicable: sampler2DRect (rectangle textures)"},
  };
  for (const auto& [text, reason] : cases) {
    GlslRun run("", text);
    GlslRunResult result;
    std::string not_applicable;
    std::string error;
    EXPECT_FALSE(RunGlslVulkan(run.shaders(), run.inputs(), &result, &not_applicable, &error));
    EXPECT_EQ(not_applicable, reason);
    EXPECT_EQ(error, "");
  }
}

// The worker carries the result, and a refusal, out of its process.
TEST(GlslVulkanTest, Worker) {
  GlslRun run("void main() { gl_Position = gl_Vertex * 2.0; }\n", "");
  run.Set("gl_Vertex=1,2,3,4");
  GlslRunResult result;
  std::string not_applicable;
  std::string error;
  ASSERT_EQ(RunGlslVulkanInWorker(WorkerLimits{}, run.shaders(), run.inputs(), &result,
                                  &not_applicable, &error),
            WorkerStatus::Ok)
      << error;
  EXPECT_EQ(Output(result, "gl_Position"), (V{2, 4, 6, 8}));
  EXPECT_TRUE(result.description.starts_with("llvmpipe")) << result.description;
  GlslRun refused("", "void main() { gl_FragColor = vec4(noise1(1.0)); }\n");
  EXPECT_EQ(RunGlslVulkanInWorker(WorkerLimits{}, refused.shaders(), refused.inputs(), &result,
                                  &not_applicable, &error),
            WorkerStatus::JobFailed);
  EXPECT_EQ(not_applicable, "not applicable: noise1 (Mesa's noise functions return 0)");
}

}  // namespace
}  // namespace arbiter::runtime
