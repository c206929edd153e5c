// The vulkan-spirv engine in process (runtime/src/vulkan/): exact results of small programs on
// lavapipe (parameters through the std140 block, a nearest-filtered texture, KIL, a vertex
// program's unclamped results), and the engine's whole life under LeakSanitizer in the asan
// preset (arbiter verify's workers exit without a leak check).
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "arbiter/arbvp/check.h"
#include "exec_glsl/target_run.h"

namespace arbiter::runtime {
namespace {

using arbvp::Vec4;

class VulkanEngineTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // The loader unloads lavapipe at vkDestroyInstance, and with it the globals through which
    // lavapipe still reaches a few hundred bytes of its own: LeakSanitizer then reports them
    // as leaks in an "<unknown module>" that no suppression can name. Pinned, they stay
    // reachable (measured: no report, without any suppression).
    static void* const lavapipe = dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_NODELETE);
    (void)lavapipe;
    std::string error;
    engine_ = CreateTargetEngine(arbvp::EmitTarget::Vk450, "llvmpipe", &error);
    ASSERT_NE(engine_, nullptr) << error;
  }

  std::unique_ptr<arbvp::Program> Parse(const std::string& text) {
    compiler::SourceFile source("test", text);
    compiler::DiagnosticSink sink(0);
    arbvp::CheckResult result = arbvp::CheckProgram(source, arbvp::CheckOptions{}, &sink);
    EXPECT_TRUE(result.ok) << text;
    return std::move(result.program);
  }

  std::vector<arbvp::VectorResult> Run(const arbvp::Program* vertex, const arbvp::Program* fragment,
                                       const arbvp::ExecInputs& inputs) {
    std::vector<arbvp::VectorResult> results;
    std::string not_applicable;
    std::string error;
    EXPECT_TRUE(engine_->Run({vertex, fragment}, arbvp::EmitOptions{}, inputs, &results,
                             &not_applicable, &error))
        << error << not_applicable;
    return results;
  }

  static Vec4 Value(const arbvp::VectorResult& r, const std::string& name) {
    for (const arbvp::OutputRegister& o : r.outputs) {
      if (o.name == name) return o.value;
    }
    ADD_FAILURE() << "no " << name;
    return {};
  }

  std::unique_ptr<TargetEngine> engine_;
};

TEST_F(VulkanEngineTest, DescribesLavapipe) {
  EXPECT_EQ(engine_->description().rfind("llvmpipe", 0), 0u) << engine_->description();
  EXPECT_NE(engine_->description().find(", Vulkan 1."), std::string::npos);
  EXPECT_NE(engine_->description().find("(lavapipe)"), std::string::npos);
}

// program.local[0] and an attribute through the vertex block and buffer; result.color is
// reported unclamped (GL clamps it only on the way to the fragment).
TEST_F(VulkanEngineTest, VertexProgramResults) {
  auto vp = Parse(
      "!!ARBvp1.0\n"
      "PARAM k = program.local[0];\n"
      "MOV result.color, k;\n"
      "ADD result.texcoord[1], vertex.attrib[6], k;\n"
      "MOV result.position, vertex.position;\n"
      "END\n");
  arbvp::ExecInputs in;
  in.vertex_params.local[0] = {0.25f, -2.0f, 3.5f, 1e30f};
  for (int i = 0; i < 70; ++i) {  // two rows of the 64-wide framebuffer
    arbvp::InputVector v;
    v.vertex.generic[6] = {static_cast<float>(i), 0.5f, -0.25f, 2.0f};
    v.vertex.position = {1.0f, 2.0f, 3.0f, static_cast<float>(i)};
    in.vectors.push_back(v);
  }
  const std::vector<arbvp::VectorResult> results = Run(vp.get(), nullptr, in);
  ASSERT_EQ(results.size(), 70u);
  for (size_t i = 0; i < results.size(); ++i) {
    const auto f = static_cast<float>(i);
    EXPECT_EQ(Value(results[i], "result.color.front.primary"), (Vec4{0.25f, -2.0f, 3.5f, 1e30f}))
        << i;
    EXPECT_EQ(Value(results[i], "result.texcoord[1]"), (Vec4{f + 0.25f, -1.5f, 3.25f, 1e30f})) << i;
    EXPECT_EQ(Value(results[i], "result.position"), (Vec4{1.0f, 2.0f, 3.0f, f})) << i;
  }
}

// A 2x2 nearest-filtered texture on unit 0 times program.local[1] (the fragment block); a KIL
// on fragment.color.x < 0.
TEST_F(VulkanEngineTest, FragmentProgramTextureAndKill) {
  auto fp = Parse(
      "!!ARBfp1.0\n"
      "TEMP t;\n"
      "KIL fragment.color.x;\n"
      "TEX t, fragment.texcoord[0], texture[0], 2D;\n"
      "MUL result.color, t, program.local[1];\n"
      "END\n");
  arbvp::ExecInputs in;
  in.fragment_params.local[1] = {2.0f, 4.0f, 0.5f, -1.0f};
  arbvp::Texture t;
  t.width = 2;
  t.height = 2;
  t.texels = {0.1f, 0.2f, 0.3f, 0.4f, 1.0f, 2.0f,  3.0f,   4.0f,
              5.0f, 6.0f, 7.0f, 8.0f, 0.5f, 0.25f, 0.125f, 1.0f};
  in.textures[0] = t;
  const Vec4 coords[] = {{0.25f, 0.25f, 0.0f, 1.0f},
                         {0.75f, 0.25f, 0.0f, 1.0f},
                         {0.25f, 0.75f, 0.0f, 1.0f},
                         {0.75f, 0.75f, 0.0f, 1.0f}};
  for (const Vec4& c : coords) {
    arbvp::InputVector v;
    v.fragment.texcoord[0] = c;
    in.vectors.push_back(v);
  }
  arbvp::InputVector killed;
  killed.fragment.color = {-1.0f, 1.0f, 1.0f, 1.0f};
  in.vectors.push_back(killed);
  const std::vector<arbvp::VectorResult> results = Run(nullptr, fp.get(), in);
  ASSERT_EQ(results.size(), 5u);
  EXPECT_EQ(Value(results[0], "result.color"), (Vec4{0.2f, 0.8f, 0.15f, -0.4f}));
  EXPECT_EQ(Value(results[1], "result.color"), (Vec4{2.0f, 8.0f, 1.5f, -4.0f}));
  EXPECT_EQ(Value(results[2], "result.color"), (Vec4{10.0f, 24.0f, 3.5f, -8.0f}));
  EXPECT_EQ(Value(results[3], "result.color"), (Vec4{1.0f, 1.0f, 0.0625f, -1.0f}));
  for (size_t i = 0; i < 4; ++i) EXPECT_FALSE(results[i].killed) << i;
  EXPECT_TRUE(results[4].killed);
}

}  // namespace
}  // namespace arbiter::runtime
