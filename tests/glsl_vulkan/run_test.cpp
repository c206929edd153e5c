// GLSL shaders run on the Vulkan engine (RunGlslVulkan: lowered to 4.50, lavapipe) and on Mesa
// GL (RunGlsl, softpipe), each checked against values from the GLSL and GL specs' formulas,
// and the two results compared output by output.
#include "arbiter/runtime/glsl_vulkan.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../glsl_exec/glsl_run.h"

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

}  // namespace
}  // namespace arbiter::runtime
