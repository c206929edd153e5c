// ArbExecutor on Mesa: small programs whose results follow from the specs by hand, on the
// backend and driver that ARBITER_TEST_BACKEND (osmesa|egl) and ARBITER_TEST_DRIVER
// (softpipe|llvmpipe) name (OSMesa picks its driver once per process: one ctest entry per
// combination). Where a driver deviates from the spec, the test pins the measured value and
// mesa-deviations.md records it.
#include "arbiter/runtime/exec.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "arbiter/arbvp/check.h"
#include "test_executor.h"

namespace arbiter::runtime {
namespace {

using arbvp::Vec4;

ArbExecutor* Executor(std::string* error) { return testing::SharedExecutor(error); }

bool Llvmpipe() { return testing::TestDriver() == "llvmpipe"; }

class ExecTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    executor_ = Executor(&error);
    ASSERT_NE(executor_, nullptr) << error;
  }

  std::unique_ptr<arbvp::Program> Parse(const std::string& text) {
    compiler::SourceFile source("test", text);
    compiler::DiagnosticSink sink(0);
    arbvp::CheckResult result = arbvp::CheckProgram(source, arbvp::CheckOptions{}, &sink);
    std::string log;
    for (const compiler::Diagnostic& d : sink.diagnostics()) log += d.message + "\n";
    EXPECT_TRUE(result.ok) << text << log;
    return std::move(result.program);
  }

  // Runs vp and/or fp text (empty: none) on `inputs`.
  std::vector<arbvp::VectorResult> Run(const std::string& vp, const std::string& fp,
                                       const arbvp::ExecInputs& inputs) {
    std::unique_ptr<arbvp::Program> v = vp.empty() ? nullptr : Parse(vp);
    std::unique_ptr<arbvp::Program> f = fp.empty() ? nullptr : Parse(fp);
    std::vector<arbvp::VectorResult> results;
    std::string error;
    EXPECT_TRUE(executor_->Run({v.get(), f.get()}, inputs, &results, &error))
        << error << " (" << executor_->description() << ")";
    EXPECT_EQ(results.size(), inputs.vectors.size());
    return results;
  }

  // A program alone on both Mesa engines: the ARB program and its translation.
  struct BothEngines {
    std::vector<arbvp::VectorResult> arb;
    std::vector<arbvp::VectorResult> glsl;
  };
  BothEngines RunOnBoth(const std::string& text, const arbvp::ExecInputs& inputs) {
    BothEngines r;
    std::unique_ptr<arbvp::Program> p = Parse(text);
    if (p == nullptr) return r;
    const bool vertex = text.rfind("!!ARBvp", 0) == 0;
    const ArbPrograms programs{vertex ? p.get() : nullptr, vertex ? nullptr : p.get()};
    std::string error;
    EXPECT_TRUE(executor_->Run(programs, inputs, &r.arb, &error)) << error;
    EXPECT_TRUE(executor_->RunTranslated(programs, arbvp::EmitOptions{}, inputs, &r.glsl, &error))
        << error;
    EXPECT_EQ(r.arb.size(), inputs.vectors.size());
    EXPECT_EQ(r.glsl.size(), inputs.vectors.size());
    return r;
  }

  static arbvp::ExecInputs Inputs(size_t count) {
    arbvp::ExecInputs inputs;
    inputs.vectors.resize(count);
    return inputs;
  }

  ArbExecutor* executor_ = nullptr;
};

const arbvp::OutputRegister* Find(const arbvp::VectorResult& result, const std::string& name) {
  for (const arbvp::OutputRegister& out : result.outputs) {
    if (out.name == name) return &out;
  }
  return nullptr;
}

std::string Names(const arbvp::VectorResult& result) {
  std::string names;
  for (const arbvp::OutputRegister& out : result.outputs) names += out.name + " ";
  return names;
}

// Exact comparison of a register's value; NaN matches NaN.
::testing::AssertionResult Value(const arbvp::VectorResult& result, const std::string& name,
                                 Vec4 expected) {
  const arbvp::OutputRegister* out = Find(result, name);
  if (out == nullptr) {
    return ::testing::AssertionFailure() << "no output " << name << " among " << Names(result);
  }
  for (size_t c = 0; c < 4; ++c) {
    const float a = out->value[c];
    const float e = expected[c];
    if (!(a == e || (std::isnan(a) && std::isnan(e)))) {
      return ::testing::AssertionFailure()
             << name << " = (" << out->value[0] << ", " << out->value[1] << ", " << out->value[2]
             << ", " << out->value[3] << "), expected (" << e << " in component " << c << ") ("
             << expected[0] << ", " << expected[1] << ", " << expected[2] << ", " << expected[3]
             << ")";
    }
  }
  return ::testing::AssertionSuccess();
}

::testing::AssertionResult Near(const arbvp::VectorResult& result, const std::string& name,
                                Vec4 expected, float tolerance) {
  const arbvp::OutputRegister* out = Find(result, name);
  if (out == nullptr) {
    return ::testing::AssertionFailure() << "no output " << name << " among " << Names(result);
  }
  for (size_t c = 0; c < 4; ++c) {
    if (!(std::fabs(out->value[c] - expected[c]) <= tolerance)) {
      return ::testing::AssertionFailure()
             << name << " = (" << out->value[0] << ", " << out->value[1] << ", " << out->value[2]
             << ", " << out->value[3] << "), expected (" << expected[0] << ", " << expected[1]
             << ", " << expected[2] << ", " << expected[3] << ") within " << tolerance;
    }
  }
  return ::testing::AssertionSuccess();
}

uint8_t Written(const arbvp::VectorResult& result, const std::string& name) {
  const arbvp::OutputRegister* out = Find(result, name);
  return out != nullptr ? out->written : 0;
}

Vec4 ToVec4(const glm::vec4& v) { return {v.x, v.y, v.z, v.w}; }

// ---------------------------------------------------------------------------------------
// Vertex programs.

TEST_F(ExecTest, VertexMovOfAttributesAndParameters) {
  arbvp::ExecInputs in = Inputs(3);
  for (size_t i = 0; i < 3; ++i) {
    const float f = static_cast<float>(i);
    in.vectors[i].vertex.position = {f, -2.5f, 1e6f, 3.0f};
    in.vectors[i].vertex.color = {0.25f, -1.0f, 7.0f + f, 0.5f};
    in.vectors[i].vertex.texcoord[1] = {-3.4e38f, 1e-3f, f * 100.0f, -0.0f};
  }
  in.vertex_params.env[3] = {1.0f, 2.0f, 3.0f, 4.0f};
  in.vertex_params.local[2] = {-5.0f, 6.0f, -7.0f, 8.0f};
  auto results =
      Run("!!ARBvp1.0\n"
          "MOV result.position, vertex.position;\n"
          "MOV result.color, vertex.color;\n"
          "MOV result.texcoord[1].xyw, vertex.texcoord[1];\n"
          "MOV result.color.secondary, program.env[3];\n"
          "MOV result.texcoord[0].y, program.local[2];\n"
          "END\n",
          "", in);
  ASSERT_EQ(results.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    const float f = static_cast<float>(i);
    const arbvp::VectorResult& r = results[i];
    EXPECT_FALSE(r.killed);
    ASSERT_EQ(r.outputs.size(), 5u) << Names(r);
    // ResultRegOrder: position, colours, texcoords by index.
    EXPECT_EQ(r.outputs[0].name, "result.position");
    EXPECT_EQ(r.outputs[4].name, "result.texcoord[1]");
    EXPECT_TRUE(Value(r, "result.position", {f, -2.5f, 1e6f, 3.0f}));
    EXPECT_TRUE(Value(r, "result.color.front.primary", {0.25f, -1.0f, 7.0f + f, 0.5f}));
    EXPECT_TRUE(Value(r, "result.color.front.secondary", {1.0f, 2.0f, 3.0f, 4.0f}));
    // Unwritten components read 0; -0 crosses the varying as +0 (docs/design/platform.md).
    EXPECT_TRUE(Value(r, "result.texcoord[1]", {-3.4e38f, 1e-3f, 0.0f, 0.0f}));
    EXPECT_TRUE(Value(r, "result.texcoord[0]", {0.0f, 6.0f, 0.0f, 0.0f}));
    EXPECT_EQ(Written(r, "result.texcoord[1]"), 0xB);
    EXPECT_EQ(Written(r, "result.texcoord[0]"), 0x2);
    EXPECT_EQ(Written(r, "result.position"), 0xF);
  }
}

TEST_F(ExecTest, Dp4WithMatrixRows) {
  arbvp::ExecInputs in = Inputs(2);
  glm::mat4 m(1.0f);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) m[c][r] = static_cast<float>(1 + r * 4 + c);  // row r = 4r+1..
  }
  in.state.modelview = m;
  in.state.program[2] = glm::transpose(m);
  in.vectors[0].vertex.position = {1.0f, 0.0f, 0.0f, 0.0f};
  in.vectors[1].vertex.position = {1.0f, -2.0f, 3.0f, 0.5f};
  auto results =
      Run("!!ARBvp1.0\n"
          "PARAM mv[4] = { state.matrix.modelview };\n"
          "PARAM pt[4] = { state.matrix.program[2].transpose };\n"
          "DP4 result.texcoord[0].x, mv[0], vertex.position;\n"
          "DP4 result.texcoord[0].y, mv[1], vertex.position;\n"
          "DP4 result.texcoord[0].z, mv[2], vertex.position;\n"
          "DP4 result.texcoord[0].w, mv[3], vertex.position;\n"
          "MOV result.texcoord[1], mv[1];\n"
          "DP4 result.texcoord[2].x, pt[0], vertex.position;\n"
          "MOV result.texcoord[3], state.matrix.modelview.row[2];\n"
          "END\n",
          "", in);
  ASSERT_EQ(results.size(), 2u);
  // Row 1 of M is (5, 6, 7, 8): ARB reads rows, and DP4 with the rows is M * v.
  EXPECT_TRUE(Value(results[0], "result.texcoord[1]", {5.0f, 6.0f, 7.0f, 8.0f}));
  EXPECT_TRUE(Value(results[0], "result.texcoord[3]", {9.0f, 10.0f, 11.0f, 12.0f}));
  EXPECT_TRUE(Value(results[0], "result.texcoord[0]", {1.0f, 5.0f, 9.0f, 13.0f}));
  const glm::vec4 v(1.0f, -2.0f, 3.0f, 0.5f);
  EXPECT_TRUE(Value(results[1], "result.texcoord[0]", ToVec4(m * v)));
  // transpose(transpose(M)) = M: row 0 again.
  EXPECT_EQ(Find(results[1], "result.texcoord[2]")->value[0], (m * v).x);
}

TEST_F(ExecTest, MoreThanEightVertexOutputsTakeSeveralPasses) {
  arbvp::ExecInputs in = Inputs(2);
  in.vectors[1].vertex.position = {10.0f, 20.0f, 30.0f, 40.0f};
  std::string vp =
      "!!ARBvp1.0\n"
      "PARAM k = {1, 2, 3, 4};\n"
      "ADD result.position, vertex.position, k;\n"
      "ADD result.color.front.primary, vertex.position, 2;\n"
      "ADD result.color.front.secondary, vertex.position, 3;\n"
      "ADD result.color.back.primary, vertex.position, 4;\n"
      "ADD result.color.back.secondary, vertex.position, 5;\n"
      "ADD result.fogcoord.x, vertex.position, 6;\n"
      "ADD result.pointsize.x, vertex.position, 7;\n";
  for (int t = 0; t < 8; ++t) {
    vp += "ADD result.texcoord[" + std::to_string(t) + "], vertex.position, " +
          std::to_string(10 + t) + ";\n";
  }
  auto results = Run(vp + "END\n", "", in);
  ASSERT_EQ(results.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const arbvp::VectorResult& r = results[i];
    const Vec4 p = in.vectors[i].vertex.position;
    auto plus = [&](float k) { return Vec4{p[0] + k, p[1] + k, p[2] + k, p[3] + k}; };
    ASSERT_EQ(r.outputs.size(), 15u) << Names(r);
    EXPECT_TRUE(Value(r, "result.position", {p[0] + 1, p[1] + 2, p[2] + 3, p[3] + 4}));
    EXPECT_TRUE(Value(r, "result.color.front.primary", plus(2)));
    EXPECT_TRUE(Value(r, "result.color.front.secondary", plus(3)));
    EXPECT_TRUE(Value(r, "result.color.back.primary", plus(4)));
    EXPECT_TRUE(Value(r, "result.color.back.secondary", plus(5)));
    EXPECT_TRUE(Value(r, "result.fogcoord", {p[0] + 6, 0, 0, 0}));
    EXPECT_TRUE(Value(r, "result.pointsize", {p[0] + 7, 0, 0, 0}));
    EXPECT_EQ(Written(r, "result.pointsize"), 0x1);
    for (int t = 0; t < 8; ++t) {
      EXPECT_TRUE(
          Value(r, "result.texcoord[" + std::to_string(t) + "]", plus(static_cast<float>(10 + t))));
    }
  }
}

TEST_F(ExecTest, PositionInvariantIsTheFixedFunctionTransform) {
  arbvp::ExecInputs in = Inputs(1);
  in.state.modelview = glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 2.0f, 3.0f));
  in.state.projection = glm::mat4(2.0f);
  in.state.projection[2][3] = -1.0f;
  in.vectors[0].vertex.position = {0.5f, -1.0f, 2.0f, 1.0f};
  in.vectors[0].vertex.color = {0.5f, 0.25f, 0.125f, 1.0f};
  auto results = Run(
      "!!ARBvp1.0\nOPTION ARB_position_invariant;\nMOV result.color, vertex.color;\nEND\n", "", in);
  ASSERT_EQ(results.size(), 1u);
  const glm::vec4 v(0.5f, -1.0f, 2.0f, 1.0f);
  // mvp = P * MV; small integers, so every product is exact.
  EXPECT_TRUE(
      Value(results[0], "result.position", ToVec4(in.state.projection * in.state.modelview * v)));
  EXPECT_EQ(Written(results[0], "result.position"), 0xF);
  EXPECT_TRUE(Value(results[0], "result.color.front.primary", {0.5f, 0.25f, 0.125f, 1.0f}));
}

TEST_F(ExecTest, GenericAttributesAndConventionalOnes) {
  arbvp::ExecInputs in = Inputs(2);
  for (size_t i = 0; i < 2; ++i) {
    const float f = static_cast<float>(i + 1);
    in.vectors[i].vertex.generic[1] = {f, 2 * f, 3 * f, 4 * f};
    in.vectors[i].vertex.generic[6] = {-f, 0.5f, 0.25f, 8.0f};
    in.vectors[i].vertex.generic[7] = {100 * f, 1, 2, 3};
    in.vectors[i].vertex.position = {9.0f, 8.0f, 7.0f, f};  // vertex.attrib[0] (ARBvp 2.7)
    in.vectors[i].vertex.normal = {0.0f, f, -f, 5.0f};
    in.vectors[i].vertex.fogcoord = {3.5f * f, 9.0f, 9.0f, 9.0f};
    in.vectors[i].vertex.secondary_color = {0.5f, f, 2.0f, 1.0f};
  }
  auto results =
      Run("!!ARBvp1.0\n"
          "MOV result.texcoord[0], vertex.attrib[1];\n"
          "MOV result.texcoord[1], vertex.attrib[6];\n"
          "MOV result.texcoord[2], vertex.attrib[7];\n"
          "MOV result.texcoord[3], vertex.attrib[0];\n"
          "MOV result.texcoord[4], vertex.normal;\n"
          "MOV result.texcoord[5], vertex.fogcoord;\n"
          "MOV result.texcoord[6], vertex.color.secondary;\n"
          "END\n",
          "", in);
  ASSERT_EQ(results.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const float f = static_cast<float>(i + 1);
    EXPECT_TRUE(Value(results[i], "result.texcoord[0]", {f, 2 * f, 3 * f, 4 * f}));
    EXPECT_TRUE(Value(results[i], "result.texcoord[1]", {-f, 0.5f, 0.25f, 8.0f}));
    EXPECT_TRUE(Value(results[i], "result.texcoord[2]", {100 * f, 1, 2, 3}));
    EXPECT_TRUE(Value(results[i], "result.texcoord[3]", {9.0f, 8.0f, 7.0f, f}));
    // ARBvp table X.1: normal (x, y, z, 1), fog coordinate (f, 0, 0, 1).
    EXPECT_TRUE(Value(results[i], "result.texcoord[4]", {0.0f, f, -f, 1.0f}));
    EXPECT_TRUE(Value(results[i], "result.texcoord[5]", {3.5f * f, 0.0f, 0.0f, 1.0f}));
    EXPECT_TRUE(Value(results[i], "result.texcoord[6]", {0.5f, f, 2.0f, 1.0f}));
  }
}

// With all sixteen generic attributes read, no attribute is left for the point's position:
// it travels in an unused program.env parameter, one point per glBegin/glEnd.
TEST_F(ExecTest, AllSixteenGenericAttributes) {
  arbvp::ExecInputs in = Inputs(3);
  std::string vp = "!!ARBvp1.0\nTEMP t;\nMOV t, vertex.attrib[0];\n";
  for (int n = 1; n < 16; ++n) vp += "ADD t, t, vertex.attrib[" + std::to_string(n) + "];\n";
  vp +=
      "MOV result.texcoord[0], t;\nMOV result.texcoord[1], vertex.attrib[7];\n"
      "MOV result.color, program.env[95];\nEND\n";
  in.vertex_params.env[95] = {1.0f, 2.0f, 3.0f, 4.0f};
  for (size_t i = 0; i < 3; ++i) {
    for (size_t n = 0; n < 16; ++n) {
      const float f = static_cast<float>(n + 16 * i);
      // Attribute 0 is the position (ARBvp 2.7).
      (n == 0 ? in.vectors[i].vertex.position : in.vectors[i].vertex.generic[n]) = {f, 1.0f, -f,
                                                                                    0.5f};
    }
  }
  auto results = Run(vp, "", in);
  ASSERT_EQ(results.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    const float base = static_cast<float>(16 * i);
    const float sum = 16 * base + 120.0f;  // sum of base + n for n = 0..15
    EXPECT_TRUE(Value(results[i], "result.texcoord[0]", {sum, 16.0f, -sum, 8.0f})) << i;
    EXPECT_TRUE(Value(results[i], "result.texcoord[1]", {base + 7, 1.0f, -base - 7, 0.5f}));
    EXPECT_TRUE(Value(results[i], "result.color.front.primary", {1.0f, 2.0f, 3.0f, 4.0f}));
  }
}

TEST_F(ExecTest, StateBindingsReadTheModelsValues) {
  arbvp::ExecInputs in = Inputs(1);
  // A modelview that would move eye-space items if they were given under it.
  in.state.modelview = glm::translate(glm::mat4(2.0f), glm::vec3(5.0f, 6.0f, 7.0f));
  in.state.light[1].position = {1.0f, 2.0f, 3.0f, 1.0f};
  in.state.light[1].diffuse = {0.5f, 2.0f, -1.0f, 1.0f};
  in.state.clip_plane[2] = {0.0f, 1.0f, 0.0f, -4.0f};
  in.state.texgen[3].eye[1] = {1.0f, 0.0f, 2.0f, 3.0f};
  in.state.fog_color = {0.25f, 0.5f, 0.75f, 1.0f};
  in.state.fog_density = 2.0f;
  in.state.fog_start = 1.0f;
  in.state.fog_end = 5.0f;
  in.state.material[0].diffuse = {0.1f, 0.2f, 0.3f, 0.4f};
  in.state.material[1].shininess = 12.0f;
  in.state.point_size = 4.0f;
  in.state.point_size_min = 3.0f;
  in.state.point_size_max = 6.0f;
  in.state.depth_near = 0.25f;
  in.state.depth_far = 0.75f;
  in.state.texenv_color[2] = {0.5f, 0.25f, 1.0f, 0.0f};
  auto results =
      Run("!!ARBvp1.0\n"
          "MOV result.texcoord[0], state.light[1].position;\n"
          "MOV result.texcoord[1], state.clip[2].plane;\n"
          "MOV result.texcoord[2], state.texgen[3].eye.t;\n"
          "MOV result.texcoord[3], state.fog.params;\n"
          "MOV result.texcoord[4], state.material.diffuse;\n"
          "MOV result.texcoord[5], state.material.back.shininess;\n"
          "MOV result.texcoord[6], state.point.size;\n"
          "MOV result.texcoord[7], state.light[1].diffuse;\n"
          "MOV result.color, state.fog.color;\n"
          "END\n",
          "", in);
  ASSERT_EQ(results.size(), 1u);
  const arbvp::VectorResult& r = results[0];
  EXPECT_TRUE(Value(r, "result.texcoord[0]", {1.0f, 2.0f, 3.0f, 1.0f}));
  EXPECT_TRUE(Value(r, "result.texcoord[1]", {0.0f, 1.0f, 0.0f, -4.0f}));
  EXPECT_TRUE(Value(r, "result.texcoord[2]", {1.0f, 0.0f, 2.0f, 3.0f}));
  EXPECT_TRUE(Value(r, "result.texcoord[3]", {2.0f, 1.0f, 5.0f, 0.25f}));
  EXPECT_TRUE(Value(r, "result.texcoord[4]", {0.1f, 0.2f, 0.3f, 0.4f}));
  EXPECT_TRUE(Value(r, "result.texcoord[5]", {12.0f, 0.0f, 0.0f, 1.0f}));
  // state.point.size = (size, min, max, fade threshold).
  EXPECT_TRUE(Value(r, "result.texcoord[6]", {4.0f, 3.0f, 6.0f, 1.0f}));
  EXPECT_TRUE(Value(r, "result.texcoord[7]", {0.5f, 2.0f, -1.0f, 1.0f}));
  EXPECT_TRUE(Value(r, "result.color.front.primary", {0.25f, 0.5f, 0.75f, 1.0f}));
}

// Every kind of state binding, under a state with no default values and colours outside
// [0, 1], against the model's own reading of it (arbvp::ReadStateBinding).
TEST_F(ExecTest, StateBindingsMatchTheModel) {
  arbvp::ExecInputs in = Inputs(1);
  arbvp::GlState& s = in.state;
  s.modelview = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, -2.0f, 0.5f)), 0.5f,
                            glm::vec3(0.0f, 0.0f, 1.0f));
  s.projection = glm::perspective(1.0f, 1.5f, 0.5f, 20.0f);
  s.texture[1] = glm::scale(glm::mat4(1.0f), glm::vec3(2.0f, 3.0f, 4.0f));
  s.program[3] = glm::translate(glm::mat4(1.0f), glm::vec3(7.0f, 8.0f, 9.0f));
  s.material[0] = {{0.5f, -1.0f, 2.0f, 1.0f},
                   {2.0f, 0.25f, -0.5f, 0.75f},
                   {1.5f, 1.0f, 0.5f, 0.5f},
                   {0.125f, -0.25f, 3.0f, 1.0f},
                   16.0f};
  s.material[1].ambient = {0.3f, 0.6f, 0.9f, 1.0f};
  s.light[2].ambient = {-1.0f, 2.0f, 0.5f, 1.0f};
  s.light[2].diffuse = {3.0f, 0.5f, -2.0f, 1.0f};
  s.light[2].specular = {0.5f, 0.5f, 4.0f, 1.0f};
  s.light[2].position = {1.0f, 2.0f, 3.0f, 0.0f};
  s.light[2].spot_direction = {0.0f, -1.0f, 0.0f};
  s.light[2].spot_exponent = 4.0f;
  s.light[2].spot_cutoff = 60.0f;
  s.light[2].constant_attenuation = 2.0f;
  s.light[2].linear_attenuation = 0.5f;
  s.light[2].quadratic_attenuation = 0.25f;
  s.light_model_ambient = {2.0f, -0.5f, 0.25f, 1.0f};
  s.texgen[1].eye[2] = {0.5f, 1.0f, -1.0f, 2.0f};
  s.texgen[1].object[3] = {1.0f, 2.0f, 3.0f, 4.0f};
  s.fog_color = {2.0f, -1.0f, 0.5f, 3.0f};
  s.fog_density = 0.75f;
  s.fog_start = 2.0f;
  s.fog_end = 6.0f;
  s.clip_plane[5] = {1.0f, -1.0f, 0.5f, 2.0f};
  s.point_size = 3.0f;
  s.point_size_min = 1.0f;
  s.point_size_max = 8.0f;
  s.point_fade_threshold = 2.0f;
  s.point_attenuation = {1.0f, 0.5f, 0.25f};
  s.texenv_color[3] = {2.0f, -1.0f, 0.5f, 3.0f};
  s.depth_near = 0.25f;
  s.depth_far = 0.75f;
  const std::vector<std::string> vertex_bindings = {"state.material.ambient",
                                                    "state.material.diffuse",
                                                    "state.material.specular",
                                                    "state.material.emission",
                                                    "state.material.shininess",
                                                    "state.material.back.ambient",
                                                    "state.light[2].ambient",
                                                    "state.light[2].diffuse",
                                                    "state.light[2].specular",
                                                    "state.light[2].position",
                                                    "state.light[2].attenuation",
                                                    "state.light[2].spot.direction",
                                                    "state.light[2].half",
                                                    "state.lightmodel.ambient",
                                                    "state.lightmodel.scenecolor",
                                                    "state.lightmodel.back.scenecolor",
                                                    "state.lightprod[2].ambient",
                                                    "state.lightprod[2].diffuse",
                                                    "state.lightprod[2].specular",
                                                    "state.lightprod[2].back.ambient",
                                                    "state.texgen[1].eye.r",
                                                    "state.texgen[1].object.q",
                                                    "state.fog.color",
                                                    "state.fog.params",
                                                    "state.clip[5].plane",
                                                    "state.point.size",
                                                    "state.point.attenuation",
                                                    "state.matrix.modelview.row[1]",
                                                    "state.matrix.modelview.inverse.row[0]",
                                                    "state.matrix.modelview.invtrans.row[2]",
                                                    "state.matrix.projection.row[3]",
                                                    "state.matrix.mvp.row[0]",
                                                    "state.matrix.mvp.transpose.row[3]",
                                                    "state.matrix.texture[1].row[1]",
                                                    "state.matrix.program[3].row[0]",
                                                    "state.matrix.program[3].inverse.row[0]"};
  const std::vector<std::string> fragment_bindings = {
      "state.texenv[3].color", "state.fog.color",        "state.fog.params",
      "state.depth.range",     "state.material.diffuse", "state.lightprod[2].diffuse"};
  for (int stage = 0; stage < 2; ++stage) {
    const auto& names = stage == 0 ? vertex_bindings : fragment_bindings;
    for (size_t first = 0; first < names.size(); first += 8) {
      std::string text = stage == 0 ? "!!ARBvp1.0\n" : "!!ARBfp1.0\nOPTION ARB_draw_buffers;\n";
      const size_t count = std::min<size_t>(8, names.size() - first);
      for (size_t k = 0; k < count; ++k) {
        text += "PARAM p" + std::to_string(k) + " = " + names[first + k] + ";\n";
        text += (stage == 0 ? "MOV result.texcoord[" : "MOV result.color[") + std::to_string(k) +
                "], p" + std::to_string(k) + ";\n";
      }
      text += "END\n";
      std::unique_ptr<arbvp::Program> program = Parse(text);
      ASSERT_NE(program, nullptr);
      std::vector<arbvp::VectorResult> results;
      std::string error;
      ArbPrograms programs;
      (stage == 0 ? programs.vertex : programs.fragment) = program.get();
      ASSERT_TRUE(executor_->Run(programs, in, &results, &error)) << error;
      ASSERT_EQ(results.size(), 1u);
      for (size_t k = 0; k < count; ++k) {
        const arbvp::Vec4 expected = arbvp::ReadStateBinding(s, program->vars[2 * k].bindings[0]);
        const std::string out =
            (stage == 0 ? "result.texcoord[" : "result.color[") + std::to_string(k) + "]";
        EXPECT_TRUE(Near(results[0], out, expected, 1e-5f)) << names[first + k];
      }
    }
  }
}

TEST_F(ExecTest, PointsCoverOnePixelWhateverThePointState) {
  arbvp::ExecInputs in = Inputs(130);  // three rows
  in.state.point_size = 9.0f;
  in.state.point_size_min = 5.0f;
  in.state.point_size_max = 20.0f;
  for (size_t i = 0; i < in.vectors.size(); ++i) {
    in.vectors[i].vertex.position = {static_cast<float>(i), 0.0f, 0.0f, 1.0f};
  }
  auto results =
      Run("!!ARBvp1.0\nPARAM big = {12, 0, 0, 0};\nMOV result.texcoord[0], vertex.position;\n"
          "MOV result.pointsize, big;\nEND\n",
          "", in);
  ASSERT_EQ(results.size(), 130u);
  for (size_t i = 0; i < results.size(); ++i) {
    EXPECT_TRUE(Value(results[i], "result.texcoord[0]", {static_cast<float>(i), 0.0f, 0.0f, 1.0f}))
        << i;
    EXPECT_TRUE(Value(results[i], "result.pointsize", {12.0f, 0.0f, 0.0f, 0.0f})) << i;
  }
}

// ---------------------------------------------------------------------------------------
// Fragment programs.

TEST_F(ExecTest, FragmentInputsAndPosition) {
  arbvp::ExecInputs in = Inputs(66);
  in.state.depth_near = 0.25f;
  in.state.depth_far = 0.75f;
  for (size_t i = 0; i < in.vectors.size(); ++i) {
    const float f = static_cast<float>(i);
    in.vectors[i].fragment.color = {f, -1.0f, 0.5f, 2.0f};
    in.vectors[i].fragment.secondary_color = {0.25f, f, 3.0f, -0.5f};
    in.vectors[i].fragment.texcoord[5] = {-f, 1e10f, 0.0f, 7.0f};
    in.vectors[i].fragment.fogcoord = 2.5f + f;
    in.vectors[i].fragment.depth = 0.5f;
  }
  auto results = Run("",
                     "!!ARBfp1.0\nOPTION ARB_draw_buffers;\n"
                     "MOV result.color[0], fragment.color;\n"
                     "MOV result.color[1], fragment.color.secondary;\n"
                     "MOV result.color[2], fragment.texcoord[5];\n"
                     "MOV result.color[3], fragment.fogcoord;\n"
                     "MOV result.color[4], fragment.position;\n"
                     "END\n",
                     in);
  ASSERT_EQ(results.size(), 66u);
  for (size_t i = 0; i < results.size(); ++i) {
    const float f = static_cast<float>(i);
    const arbvp::VectorResult& r = results[i];
    EXPECT_FALSE(r.killed);
    ASSERT_EQ(r.outputs.size(), 5u) << Names(r);
    EXPECT_TRUE(Value(r, "result.color[0]", {f, -1.0f, 0.5f, 2.0f}));
    EXPECT_TRUE(Value(r, "result.color[1]", {0.25f, f, 3.0f, -0.5f}));
    EXPECT_TRUE(Value(r, "result.color[2]", {-f, 1e10f, 0.0f, 7.0f}));
    EXPECT_TRUE(Value(r, "result.color[3]", {2.5f + f, 0.0f, 0.0f, 1.0f}));
    const arbvp::Pixel p = arbvp::FragmentPixel(i);
    EXPECT_TRUE(
        Value(r, "result.color[4]",
              {static_cast<float>(p.x) + 0.5f, static_cast<float>(p.y) + 0.5f, 0.5f, 1.0f}));
  }
}

TEST_F(ExecTest, KillAndDepth) {
  arbvp::ExecInputs in = Inputs(4);
  in.vectors[0].fragment.texcoord[0] = {1.0f, 0.0f, 2.0f, 0.5f};
  in.vectors[1].fragment.texcoord[0] = {1.0f, -0.5f, 2.0f, 0.5f};
  in.vectors[2].fragment.texcoord[0] = {std::numeric_limits<float>::quiet_NaN(), 0, 0, 0};
  in.vectors[3].fragment.texcoord[0] = {0.0f, 0.0f, 0.0f, -1e-30f};
  auto results = Run("",
                     "!!ARBfp1.0\n"
                     "KIL fragment.texcoord[0];\n"
                     "MOV result.color, fragment.texcoord[0];\n"
                     "MOV result.depth.z, fragment.texcoord[0].w;\n"
                     "END\n",
                     in);
  ASSERT_EQ(results.size(), 4u);
  EXPECT_FALSE(results[0].killed);
  EXPECT_TRUE(Value(results[0], "result.color", {1.0f, 0.0f, 2.0f, 0.5f}));
  EXPECT_TRUE(Value(results[0], "result.depth", {0.0f, 0.0f, 0.5f, 0.0f}));
  EXPECT_EQ(Written(results[0], "result.depth"), 0x4);
  EXPECT_EQ(results[0].outputs.back().name, "result.depth");
  EXPECT_TRUE(results[1].killed);
  EXPECT_TRUE(results[1].outputs.empty());
  // NaN < 0 is false: no kill (docs/design/semantics.md).
  EXPECT_FALSE(results[2].killed);
  // -1e-30 is a denormal... no: it is a normal float below zero, so it kills.
  EXPECT_TRUE(results[3].killed);
}

TEST_F(ExecTest, ManyFragmentOutputsTakeSeveralPasses) {
  arbvp::ExecInputs in = Inputs(3);
  for (size_t i = 0; i < 3; ++i) in.vectors[i].fragment.color = {static_cast<float>(i), 1, 2, 3};
  std::string fp = "!!ARBfp1.0\nOPTION ARB_draw_buffers;\n";
  for (int k = 0; k < 8; ++k) {
    fp +=
        "ADD result.color[" + std::to_string(k) + "], fragment.color, " + std::to_string(k) + ";\n";
  }
  fp += "MOV result.depth.z, fragment.color.w;\nEND\n";
  auto results = Run("", fp, in);
  ASSERT_EQ(results.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    const float f = static_cast<float>(i);
    ASSERT_EQ(results[i].outputs.size(), 9u) << Names(results[i]);
    for (int k = 0; k < 8; ++k) {
      const float a = static_cast<float>(k);
      EXPECT_TRUE(Value(results[i], "result.color[" + std::to_string(k) + "]",
                        {f + a, 1 + a, 2 + a, 3 + a}));
    }
    EXPECT_TRUE(Value(results[i], "result.depth", {0.0f, 0.0f, 3.0f, 0.0f}));
  }
}

TEST_F(ExecTest, FogOptionsBlendResultColor) {
  arbvp::ExecInputs in = Inputs(2);
  in.state.fog_color = {0.0f, 0.0f, 1.0f, 0.75f};
  in.state.fog_start = 0.0f;
  in.state.fog_end = 10.0f;
  in.state.fog_density = 0.5f;
  in.vectors[0].fragment.fogcoord = 5.0f;
  in.vectors[1].fragment.fogcoord = 0.0f;
  for (auto& v : in.vectors) v.fragment.color = {1.0f, 0.5f, 0.0f, 0.25f};
  // Linear: f = (end - c) / (end - start), clamped; colour.rgb = f C + (1 - f) fog; alpha kept.
  auto linear = Run("",
                    "!!ARBfp1.0\nOPTION ARB_fog_linear;\nMOV result.color, fragment.color;\n"
                    "MOV result.depth.z, fragment.fogcoord.x;\nEND\n",
                    in);
  ASSERT_EQ(linear.size(), 2u);
  EXPECT_TRUE(Value(linear[0], "result.color", {0.5f, 0.25f, 0.5f, 0.25f}));
  EXPECT_TRUE(Value(linear[1], "result.color", {1.0f, 0.5f, 0.0f, 0.25f}));
  // The fog blend touches result.color only.
  EXPECT_TRUE(Value(linear[0], "result.depth", {0.0f, 0.0f, 5.0f, 0.0f}));
  // Exp: f = e^(-density c) = e^-2.5 at c = 5. Mesa computes the factor with EX2 of a
  // prescaled coordinate: within 2 ulp of the float nearest e^-x.
  auto exp =
      Run("", "!!ARBfp1.0\nOPTION ARB_fog_exp;\nMOV result.color, fragment.color;\nEND\n", in);
  const float f = std::exp(-2.5f);
  EXPECT_TRUE(Near(exp[0], "result.color", {f, 0.5f * f, 1.0f - f, 0.25f}, 1e-6f));
  // Exp2: f = e^(-(density c)^2) = e^-6.25.
  auto exp2 =
      Run("", "!!ARBfp1.0\nOPTION ARB_fog_exp2;\nMOV result.color, fragment.color;\nEND\n", in);
  const float g = std::exp(-6.25f);
  EXPECT_TRUE(Near(exp2[0], "result.color", {g, 0.5f * g, 1.0f - g, 0.25f}, 1e-6f));
}

TEST_F(ExecTest, FogOfAnUnclampedColor) {
  arbvp::ExecInputs in = Inputs(1);
  in.state.fog_color = {0.0f, 0.0f, 1.0f, 0.75f};
  in.state.fog_end = 10.0f;
  in.vectors[0].fragment.fogcoord = 5.0f;
  in.vectors[0].fragment.color = {2.0f, -1.0f, 0.5f, 3.0f};
  auto results =
      Run("", "!!ARBfp1.0\nOPTION ARB_fog_linear;\nMOV result.color, fragment.color;\nEND\n", in);
  ASSERT_EQ(results.size(), 1u);
  // ARBfp 3.11.4.5.1 fogs "the final clamped color": Mesa clamps the colour (alpha too) to
  // [0, 1] before the blend even with colour clamping off (ARB_color_buffer_float), so
  // (1, 0, 0.5, 1) blends with the fog colour at f = 0.5.
  EXPECT_TRUE(Value(results[0], "result.color", {0.5f, 0.0f, 0.75f, 1.0f}));
}

TEST_F(ExecTest, FogWithDrawBuffersAndKill) {
  arbvp::ExecInputs in = Inputs(2);
  in.state.fog_color = {0.0f, 0.0f, 1.0f, 0.75f};
  in.state.fog_end = 10.0f;
  in.vectors[0].fragment.fogcoord = 5.0f;
  in.vectors[1].fragment.fogcoord = 5.0f;
  in.vectors[1].fragment.texcoord[0] = {-1.0f, 0.0f, 0.0f, 0.0f};
  for (auto& v : in.vectors) v.fragment.color = {1.0f, 0.5f, 0.0f, 0.25f};
  auto results = Run("",
                     "!!ARBfp1.0\nOPTION ARB_fog_linear;\nOPTION ARB_draw_buffers;\n"
                     "KIL fragment.texcoord[0];\n"
                     "MOV result.color[0], fragment.color;\n"
                     "MOV result.color[1], fragment.color;\nEND\n",
                     in);
  ASSERT_EQ(results.size(), 2u);
  // Mesa fogs only its FRAG_RESULT_COLOR, and under OPTION ARB_draw_buffers result.color and
  // result.color[0] are both draw buffer 0 (FRAG_RESULT_DATA0): no fog at all
  // (mesa-deviations.md). Draw buffer 1 is never fogged.
  EXPECT_TRUE(Value(results[0], "result.color[0]", {1.0f, 0.5f, 0.0f, 0.25f}));
  EXPECT_TRUE(Value(results[0], "result.color[1]", {1.0f, 0.5f, 0.0f, 0.25f}));
  EXPECT_TRUE(results[1].killed);
}

TEST_F(ExecTest, SpecialValuesAndDepth) {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  arbvp::ExecInputs in = Inputs(3);
  in.state.depth_near = 0.25f;
  in.state.depth_far = 0.75f;
  in.vectors[0].fragment.texcoord[1] = {nan, 0.0f, -0.0f, 1.0f};
  in.vectors[0].fragment.texcoord[2] = {inf, -inf, nan, -0.0f};
  in.vectors[0].fragment.depth = 0.3f;
  in.vectors[1].fragment.texcoord[1] = {-0.0f, 0.0f, 0.0f, 0.0f};
  in.vectors[1].fragment.depth = 0.7f;
  in.vectors[2].fragment.depth = 0.25f;
  auto results = Run("",
                     "!!ARBfp1.0\nOPTION ARB_draw_buffers;\n"
                     "KIL fragment.texcoord[1];\n"
                     "MOV result.color[0], fragment.texcoord[2];\n"
                     "MOV result.color[1], fragment.position;\nEND\n",
                     in);
  ASSERT_EQ(results.size(), 3u);
  // -0 < 0 is false and NaN < 0 is false: none of these kills.
  EXPECT_FALSE(results[0].killed);
  EXPECT_FALSE(results[1].killed);
  // inf and NaN come back exactly; -0 crosses the varying as +0 (docs/design/platform.md).
  EXPECT_TRUE(Value(results[0], "result.color[0]", {inf, -inf, nan, 0.0f}));
  // Window depth through the depth range: exact where the arithmetic is, else within an ulp
  // or two of float.
  EXPECT_TRUE(Near(results[0], "result.color[1]", {0.5f, 0.5f, 0.3f, 1.0f}, 1e-7f));
  EXPECT_TRUE(Near(results[1], "result.color[1]", {1.5f, 0.5f, 0.7f, 1.0f}, 1e-7f));
  EXPECT_TRUE(Value(results[2], "result.color[1]", {2.5f, 0.5f, 0.25f, 1.0f}));
}

TEST_F(ExecTest, Denormals) {
  const float denormal = 1e-40f;
  arbvp::ExecInputs in = Inputs(1);
  in.vectors[0].vertex.texcoord[0] = {denormal, -denormal, 1.0f, 2.0f};
  in.vectors[0].fragment.texcoord[0] = {denormal, -denormal, 1.0f, 2.0f};
  auto vertex = Run("!!ARBvp1.0\nMOV result.texcoord[0], vertex.texcoord[0];\nEND\n", "", in);
  auto fragment = Run("", "!!ARBfp1.0\nMOV result.color, fragment.texcoord[0];\nEND\n", in);
  ASSERT_EQ(vertex.size(), 1u);
  ASSERT_EQ(fragment.size(), 1u);
  // A MOV keeps a denormal in IEEE float32; Mesa flushes it to zero on the way
  // (mesa-deviations.md).
  EXPECT_TRUE(Value(vertex[0], "result.texcoord[0]", {0.0f, 0.0f, 1.0f, 2.0f}));
  EXPECT_TRUE(Value(fragment[0], "result.color", {0.0f, 0.0f, 1.0f, 2.0f}));
}

// The rewritten program reaches Mesa as printed text: constants keep every bit, and an
// overflowing literal (inf) stays inf.
TEST_F(ExecTest, ConstantsSurviveThePrinter) {
  const float inf = std::numeric_limits<float>::infinity();
  auto results =
      Run("!!ARBvp1.0\nPARAM c = {1e39, -1e39, 0.1, 16777215};\n"
          "PARAM d = {3.40282347e38, 1.17549435e-38, -2.5e-7, 0.333333343};\n"
          "MOV result.texcoord[0], c;\nMOV result.texcoord[1], d;\nEND\n",
          "", Inputs(1));
  ASSERT_EQ(results.size(), 1u);
  EXPECT_TRUE(Value(results[0], "result.texcoord[0]", {inf, -inf, 0.1f, 16777215.0f}));
  EXPECT_TRUE(Value(results[0], "result.texcoord[1]",
                    {3.40282347e38f, 1.17549435e-38f, -2.5e-7f, 0.333333343f}));
}

TEST_F(ExecTest, VertexSecondaryColorAlpha) {
  arbvp::ExecInputs in = Inputs(1);
  in.vectors[0].vertex.secondary_color = {0.5f, 0.25f, 2.0f, 0.125f};
  auto results = Run("!!ARBvp1.0\nMOV result.texcoord[0], vertex.color.secondary;\nEND\n", "", in);
  ASSERT_EQ(results.size(), 1u);
  // GL has no way to set the alpha of the current secondary colour (glSecondaryColor3*):
  // Mesa reads 1 whatever the model holds (mesa-deviations.md).
  EXPECT_TRUE(Value(results[0], "result.texcoord[0]", {0.5f, 0.25f, 2.0f, 1.0f}));
}

// ---------------------------------------------------------------------------------------
// Textures.

arbvp::Texture Texture(arbvp::TexDim dim, int w, int h, int d) {
  arbvp::Texture t;
  t.dim = dim;
  t.width = w;
  t.height = h;
  t.depth = d;
  const int layers = dim == arbvp::TexDim::Cube ? 6 : d;
  for (int i = 0; i < w * h * layers; ++i) {
    const float f = static_cast<float>(i);
    t.texels.insert(t.texels.end(), {f, 10.0f + f, -f, 100.0f * f});
  }
  return t;
}

Vec4 Texel(int i) {
  const float f = static_cast<float>(i);
  return {f, 10.0f + f, -f, 100.0f * f};
}

TEST_F(ExecTest, EachTextureTarget) {
  arbvp::ExecInputs in = Inputs(6);
  in.textures[0] = Texture(arbvp::TexDim::Tex1D, 4, 1, 1);
  in.textures[1] = Texture(arbvp::TexDim::Tex2D, 2, 2, 1);
  in.textures[2] = Texture(arbvp::TexDim::Tex3D, 2, 2, 2);
  in.textures[3] = Texture(arbvp::TexDim::Cube, 1, 1, 1);
  in.textures[4] = Texture(arbvp::TexDim::Rect, 3, 2, 1);
  in.textures[4].wrap = arbvp::TexWrap::ClampToEdge;
  in.textures[5] = Texture(arbvp::TexDim::Tex2D, 2, 1, 1);
  in.textures[5].filter = arbvp::TexFilter::Linear;
  in.textures[7] = Texture(arbvp::TexDim::Tex2D, 1, 1, 1);
  const Vec4 cube_dirs[6] = {{1, 0.1f, 0.2f, 0},  {-1, 0.1f, 0.2f, 0}, {0.1f, 1, 0.2f, 0},
                             {0.1f, -1, 0.2f, 0}, {0.1f, 0.2f, 1, 0},  {0.1f, 0.2f, -1, 0}};
  for (size_t i = 0; i < 6; ++i) {
    auto& f = in.vectors[i].fragment;
    f.texcoord[0] = {0.6f, 0, 0, 1};           // 1D: texel 2
    f.texcoord[1] = {0.75f, 0.75f, 0, 1};      // 2D: texel (1, 1) = 3
    f.texcoord[2] = {0.25f, 0.75f, 0.75f, 1};  // 3D: texel (0, 1, 1) = 6
    f.texcoord[3] = cube_dirs[i];              // face i
    f.texcoord[4] = {2.5f, 1.5f, 0, 1};        // RECT: texel (2, 1) = 5
    f.texcoord[5] = {0.5f, 0.5f, 0, 1};        // linear between texels 0 and 1
    f.texcoord[6] = {0.5f, 0.5f, 0.5f, 1};
  }
  auto results = Run("",
                     "!!ARBfp1.0\nOPTION ARB_draw_buffers;\n"
                     "TEX result.color[0], fragment.texcoord[0], texture[0], 1D;\n"
                     "TEX result.color[1], fragment.texcoord[1], texture[1], 2D;\n"
                     "TEX result.color[2], fragment.texcoord[2], texture[2], 3D;\n"
                     "TEX result.color[3], fragment.texcoord[3], texture[3], CUBE;\n"
                     "TEX result.color[4], fragment.texcoord[4], texture[4], RECT;\n"
                     "TEX result.color[5], fragment.texcoord[5], texture[5], 2D;\n"
                     "TEX result.color[6], fragment.texcoord[6], texture[6], 2D;\n"
                     "TEX result.color[7], fragment.texcoord[6], texture[7], 3D;\n"
                     "END\n",
                     in);
  ASSERT_EQ(results.size(), 6u);
  for (size_t i = 0; i < 6; ++i) {
    const arbvp::VectorResult& r = results[i];
    EXPECT_TRUE(Value(r, "result.color[0]", Texel(2)));
    EXPECT_TRUE(Value(r, "result.color[1]", Texel(3)));
    EXPECT_TRUE(Value(r, "result.color[2]", Texel(6)));
    EXPECT_TRUE(Value(r, "result.color[3]", Texel(static_cast<int>(i)))) << "cube face " << i;
    EXPECT_TRUE(Value(r, "result.color[4]", Texel(5)));
    EXPECT_TRUE(Near(r, "result.color[5]", {0.5f, 10.5f, -0.5f, 50.0f}, 1e-4f));
    // No texture on unit 6, and unit 7 holds a 2D texture, not a 3D one: incomplete.
    EXPECT_TRUE(Value(r, "result.color[6]", {0.0f, 0.0f, 0.0f, 1.0f}));
    EXPECT_TRUE(Value(r, "result.color[7]", {0.0f, 0.0f, 0.0f, 1.0f}));
  }
}

// Texture image units are a set of their own, larger than the eight coordinate sets
// (ARBfp 3.11.2 <texImageUnitNum> is below MAX_TEXTURE_IMAGE_UNITS_ARB, 32 on Mesa): Unity's
// shaders sample units 8 to 15. Both Mesa engines bind textures there.
TEST_F(ExecTest, ImageUnitsPastTheCoordinateSets) {
  arbvp::ExecInputs in = Inputs(1);
  in.textures[8] = Texture(arbvp::TexDim::Tex2D, 2, 2, 1);
  in.textures[15] = Texture(arbvp::TexDim::Tex1D, 4, 1, 1);
  in.textures[31] = Texture(arbvp::TexDim::Tex2D, 2, 1, 1);
  in.vectors[0].fragment.texcoord[0] = {0.75f, 0.75f, 0, 1};  // 2D 2x2: texel (1, 1) = 3
  in.vectors[0].fragment.texcoord[1] = {0.6f, 0, 0, 1};       // 1D 4: texel 2
  in.vectors[0].fragment.texcoord[2] = {0.25f, 0.5f, 0, 1};   // 2D 2x1: texel 0
  BothEngines both = RunOnBoth(
      "!!ARBfp1.0\nOPTION ARB_draw_buffers;\n"
      "TEX result.color[0], fragment.texcoord[0], texture[8], 2D;\n"
      "TEX result.color[1], fragment.texcoord[1], texture[15], 1D;\n"
      "TEX result.color[2], fragment.texcoord[2], texture[31], 2D;\n"
      "END\n",
      in);
  for (const auto* engine : {&both.arb, &both.glsl}) {
    ASSERT_EQ(engine->size(), 1u);
    const arbvp::VectorResult& r = engine->front();
    const char* name = engine == &both.arb ? "arb" : "glsl";
    EXPECT_TRUE(Value(r, "result.color[0]", Texel(3))) << name;
    EXPECT_TRUE(Value(r, "result.color[1]", Texel(2))) << name;
    EXPECT_TRUE(Value(r, "result.color[2]", Texel(0))) << name;
  }
}

// state.light[n].half of a light at its initial position (0,0,1,0) (GL 2.0 table 6.11):
// h_inf = ||(0,0,1) + (0,0,1)|| = (0,0,1), w = 1 (ARBvp 2.14.2). The translation derives it
// from gl_LightSource[n].position and gets it on both drivers. Mesa's ARB engine reads
// (0,0,0,0) while the light's position has never changed on the context (mesa-deviations.md),
// which depends on the tests before this one, so its value is not pinned here (the exec case
// state_light_half_default pins it).
TEST_F(ExecTest, LightHalfOfTheInitialPositionThroughTheTranslation) {
  std::unique_ptr<arbvp::Program> program = Parse(
      "!!ARBvp1.0\nMOV result.texcoord[0], state.light[7].half;\n"
      "MOV result.position, vertex.position;\nEND\n");
  ASSERT_NE(program, nullptr);
  std::vector<arbvp::VectorResult> glsl;
  std::string error;
  ASSERT_TRUE(executor_->RunTranslated({program.get(), nullptr}, arbvp::EmitOptions{}, Inputs(1),
                                       &glsl, &error))
      << error;
  ASSERT_EQ(glsl.size(), 1u);
  EXPECT_TRUE(Near(glsl[0], "result.texcoord[0]", {0.0f, 0.0f, 1.0f, 1.0f}, 1e-6f));
}

TEST_F(ExecTest, ShadowComparison) {
  arbvp::ExecInputs in = Inputs(2);
  for (int unit = 0; unit < 3; ++unit) {
    arbvp::Texture t;
    t.texels = {0.5f, 0.0f, 0.0f, 0.0f};
    t.depth_texture = true;
    t.compare = unit != 2;
    t.depth_mode = unit == 1 ? arbvp::DepthMode::Alpha : arbvp::DepthMode::Luminance;
    in.textures[unit] = t;
  }
  in.vectors[0].fragment.texcoord[0] = {0.5f, 0.5f, 0.25f, 1.0f};  // r <= 0.5: passes
  in.vectors[1].fragment.texcoord[0] = {0.5f, 0.5f, 0.75f, 1.0f};  // fails
  auto results = Run("",
                     "!!ARBfp1.0\nOPTION ARB_fragment_program_shadow;\nOPTION ARB_draw_buffers;\n"
                     "TEX result.color[0], fragment.texcoord[0], texture[0], SHADOW2D;\n"
                     "TEX result.color[1], fragment.texcoord[0], texture[1], SHADOW2D;\n"
                     "TEX result.color[2], fragment.texcoord[0], texture[2], 2D;\n"
                     "END\n",
                     in);
  ASSERT_EQ(results.size(), 2u);
  EXPECT_TRUE(Value(results[0], "result.color[0]", {1.0f, 1.0f, 1.0f, 1.0f}));
  EXPECT_TRUE(Value(results[1], "result.color[0]", {0.0f, 0.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(Value(results[0], "result.color[1]", {0.0f, 0.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(Value(results[1], "result.color[1]", {0.0f, 0.0f, 0.0f, 0.0f}));
  // No comparison: the depth as luminance.
  EXPECT_TRUE(Value(results[0], "result.color[2]", {0.5f, 0.5f, 0.5f, 1.0f}));
}

TEST_F(ExecTest, WrapModesAndShadowTargets) {
  arbvp::ExecInputs in = Inputs(1);
  const arbvp::TexWrap wraps[3] = {arbvp::TexWrap::Repeat, arbvp::TexWrap::ClampToEdge,
                                   arbvp::TexWrap::MirroredRepeat};
  for (int unit = 0; unit < 3; ++unit) {
    in.textures[unit] = Texture(arbvp::TexDim::Tex2D, 4, 1, 1);
    in.textures[unit].wrap = wraps[unit];
  }
  arbvp::Texture shadow1d;
  shadow1d.dim = arbvp::TexDim::Tex1D;
  shadow1d.width = 2;
  shadow1d.texels = {0.25f, 0, 0, 0, 0.75f, 0, 0, 0};
  shadow1d.depth_texture = true;
  shadow1d.compare = true;
  shadow1d.compare_func = arbvp::CompareFunc::Greater;
  shadow1d.depth_mode = arbvp::DepthMode::Intensity;
  in.textures[3] = shadow1d;
  arbvp::Texture rect = shadow1d;
  rect.dim = arbvp::TexDim::Rect;
  rect.wrap = arbvp::TexWrap::ClampToEdge;
  rect.compare_func = arbvp::CompareFunc::Lequal;
  rect.depth_mode = arbvp::DepthMode::Luminance;
  in.textures[4] = rect;
  auto& f = in.vectors[0].fragment;
  f.texcoord[0] = {1.3f, 0.5f, 0.0f, 1.0f};   // repeat 0.3: texel 1; clamp: 3; mirror 0.7: 2
  f.texcoord[1] = {0.75f, 0.5f, 0.5f, 1.0f};  // 1D texel 1 (0.75); r = 0.5 > 0.75 fails
  f.texcoord[2] = {0.5f, 0.5f, 0.5f, 1.0f};   // RECT texel 0 (0.25); 0.5 <= 0.25 fails
  f.texcoord[3] = {1.5f, 0.5f, 0.5f, 1.0f};   // RECT texel 1 (0.75); 0.5 <= 0.75 passes
  auto results = Run("",
                     "!!ARBfp1.0\nOPTION ARB_draw_buffers;\nOPTION ARB_fragment_program_shadow;\n"
                     "TEX result.color[0], fragment.texcoord[0], texture[0], 2D;\n"
                     "TEX result.color[1], fragment.texcoord[0], texture[1], 2D;\n"
                     "TEX result.color[2], fragment.texcoord[0], texture[2], 2D;\n"
                     "TEX result.color[3], fragment.texcoord[1], texture[3], SHADOW1D;\n"
                     "TEX result.color[4], fragment.texcoord[2], texture[4], SHADOWRECT;\n"
                     "TEX result.color[5], fragment.texcoord[3], texture[4], SHADOWRECT;\n"
                     "END\n",
                     in);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_TRUE(Value(results[0], "result.color[0]", Texel(1)));
  EXPECT_TRUE(Value(results[0], "result.color[1]", Texel(3)));
  EXPECT_TRUE(Value(results[0], "result.color[2]", Texel(2)));
  // Intensity: the comparison result in all four channels.
  EXPECT_TRUE(Value(results[0], "result.color[3]", {0.0f, 0.0f, 0.0f, 0.0f}));
  EXPECT_TRUE(Value(results[0], "result.color[4]", {0.0f, 0.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(Value(results[0], "result.color[5]", {1.0f, 1.0f, 1.0f, 1.0f}));
}

// ---------------------------------------------------------------------------------------
// Pairs, several runs, errors, driver deviations.

TEST_F(ExecTest, PairFeedsTheFragmentProgram) {
  arbvp::ExecInputs in = Inputs(2);
  for (size_t i = 0; i < 2; ++i) {
    const float f = static_cast<float>(i);
    in.vectors[i].vertex.color = {f, 2.0f, -3.0f, 0.5f};
    in.vectors[i].vertex.generic[6] = {1.0f, 1.0f, f, 4.0f};
    in.vectors[i].fragment.depth = 0.25f;
  }
  in.fragment_params.local[0] = {10.0f, 20.0f, 30.0f, 40.0f};
  auto results =
      Run("!!ARBvp1.0\nOPTION ARB_position_invariant;\n"
          "MUL result.color, vertex.color, 2;\n"
          "MOV result.texcoord[2], vertex.attrib[6];\n"
          "MOV result.fogcoord.x, vertex.attrib[6].z;\nEND\n",
          "!!ARBfp1.0\nOPTION ARB_draw_buffers;\n"
          "ADD result.color[0], fragment.color, fragment.texcoord[2];\n"
          "MOV result.color[1], program.local[0];\n"
          "MOV result.color[2], fragment.fogcoord;\n"
          "MOV result.color[3], fragment.position;\nEND\n",
          in);
  ASSERT_EQ(results.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const float f = static_cast<float>(i);
    const arbvp::VectorResult& r = results[i];
    ASSERT_EQ(r.outputs.size(), 4u) << Names(r);
    // The vertex colour is clamped to [0, 1] on its way to the fragment program (GL 2.0
    // 2.14.6): (2f, 4, -6, 1) becomes (min(2f, 1), 1, 0, 1); texcoord[2] is not clamped.
    EXPECT_TRUE(Value(r, "result.color[0]", {std::min(2 * f, 1.0f) + 1, 2.0f, f, 5.0f}));
    EXPECT_TRUE(Value(r, "result.color[1]", {10.0f, 20.0f, 30.0f, 40.0f}));
    EXPECT_TRUE(Value(r, "result.color[2]", {f, 0.0f, 0.0f, 1.0f}));
    EXPECT_TRUE(Value(r, "result.color[3]", {static_cast<float>(i) + 0.5f, 0.5f, 0.25f, 1.0f}));
  }
}

TEST_F(ExecTest, RunsOneAfterAnotherStartFromTheModel) {
  arbvp::ExecInputs first = Inputs(1);
  first.vertex_params.env[5] = {1.0f, 2.0f, 3.0f, 4.0f};
  first.textures[0] = Texture(arbvp::TexDim::Tex2D, 1, 1, 1);
  const std::string vp = "!!ARBvp1.0\nMOV result.texcoord[0], program.env[5];\nEND\n";
  auto a = Run(vp, "", first);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_TRUE(Value(a[0], "result.texcoord[0]", {1.0f, 2.0f, 3.0f, 4.0f}));
  auto b = Run(vp, "", Inputs(1));
  ASSERT_EQ(b.size(), 1u);
  EXPECT_TRUE(Value(b[0], "result.texcoord[0]", {0.0f, 0.0f, 0.0f, 0.0f}));
  auto c = Run("", "!!ARBfp1.0\nTEX result.color, fragment.texcoord[0], texture[0], 2D;\nEND\n",
               Inputs(1));
  ASSERT_EQ(c.size(), 1u);
  EXPECT_TRUE(Value(c[0], "result.color", {0.0f, 0.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(Run(vp, "", Inputs(0)).empty());
}

// The executor keeps compiled programs between runs (by their text): a program run again
// must still see only the new run's parameters, on both engines.
TEST_F(ExecTest, ARerunProgramSeesOnlyTheNewParameters) {
  const std::string vp =
      "!!ARBvp1.0\nMOV result.texcoord[0], program.local[3];\n"
      "MOV result.texcoord[1], program.env[2];\nEND\n";
  std::unique_ptr<arbvp::Program> program = Parse(vp);
  arbvp::ExecInputs set = Inputs(1);
  set.vertex_params.local[3] = {1.0f, 2.0f, 3.0f, 4.0f};
  set.vertex_params.env[2] = {5.0f, 6.0f, 7.0f, 8.0f};
  const arbvp::ExecInputs none = Inputs(1);
  const arbvp::ExecInputs* given_inputs = &set;
  for (bool translated : {false, true}) {
    SCOPED_TRACE(translated ? "mesa-glsl" : "mesa-arb");
    for (const arbvp::ExecInputs* inputs : {given_inputs, &none, given_inputs}) {
      std::vector<arbvp::VectorResult> results;
      std::string error;
      const bool ok = translated
                          ? executor_->RunTranslated({program.get(), nullptr}, arbvp::EmitOptions{},
                                                     *inputs, &results, &error)
                          : executor_->Run({program.get(), nullptr}, *inputs, &results, &error);
      ASSERT_TRUE(ok) << error;
      ASSERT_EQ(results.size(), 1u);
      const bool given = inputs == given_inputs;
      EXPECT_TRUE(Value(results[0], "result.texcoord[0]",
                        given ? Vec4{1.0f, 2.0f, 3.0f, 4.0f} : Vec4{0.0f, 0.0f, 0.0f, 0.0f}));
      EXPECT_TRUE(Value(results[0], "result.texcoord[1]",
                        given ? Vec4{5.0f, 6.0f, 7.0f, 8.0f} : Vec4{0.0f, 0.0f, 0.0f, 0.0f}));
    }
  }
}

TEST_F(ExecTest, ErrorsAreReported) {
  arbvp::ExecInputs in = Inputs(1);
  in.textures[0] = Texture(arbvp::TexDim::Tex2D, 2, 2, 1);
  in.textures[0].texels.pop_back();
  std::unique_ptr<arbvp::Program> fp =
      Parse("!!ARBfp1.0\nTEX result.color, fragment.texcoord[0], texture[0], 2D;\nEND\n");
  std::vector<arbvp::VectorResult> results;
  std::string error;
  EXPECT_FALSE(executor_->Run({nullptr, fp.get()}, in, &results, &error));
  EXPECT_EQ(error, "texture on unit 0 holds 15 floats; its size needs 16");
  EXPECT_TRUE(results.empty());
  // An invalid GL state value: a spot cutoff outside [0, 90] and 180.
  arbvp::ExecInputs bad = Inputs(1);
  bad.state.light[0].spot_cutoff = 100.0f;
  EXPECT_FALSE(executor_->Run({nullptr, fp.get()}, bad, &results, &error));
  EXPECT_EQ(error, "setting the GL state raised GL_INVALID_VALUE");
  // An IR that Mesa rejects (built by hand: the checker would refuse the text): Mesa's
  // message and the line of the printed program.
  std::unique_ptr<arbvp::Program> bad_unit =
      Parse("!!ARBfp1.0\nTEX result.color, fragment.texcoord[0], texture[0], 2D;\nEND\n");
  ASSERT_NE(bad_unit, nullptr);
  bad_unit->instructions[0].tex_unit = 200;
  EXPECT_FALSE(executor_->Run({nullptr, bad_unit.get()}, Inputs(1), &results, &error));
  EXPECT_EQ(error.rfind("mesa rejected the fragment program: line ", 0), 0u) << error;
  EXPECT_NE(error.find("texture[200], 2D;')"), std::string::npos) << error;
  // The context still works afterwards.
  auto ok = Run("", "!!ARBfp1.0\nMOV result.color, fragment.color;\nEND\n", Inputs(1));
  ASSERT_EQ(ok.size(), 1u);
  EXPECT_TRUE(Value(ok[0], "result.color", {1.0f, 1.0f, 1.0f, 1.0f}));
}

// SGE of a NaN is 0 ("tmp.x = (tmp0.x >= tmp1.x) ? 1.0 : 0.0", ARBfp 3.11.5.24), and a
// product of comparisons (the specs' branch-free "and") keeps it. Mesa's GLSL compiler folds
// (a >= b) * (a >= c) into a >= max(b, c), whose maxNum drops a NaN b: the translation then
// gives the other comparison's result (deviation nan-compare-folded, mesa-deviations.md).
// The ARB engine keeps the spec's value on softpipe; on llvmpipe it folds too (verify covers
// that by llvmpipe-nonfinite: nothing computed from a NaN is compared on llvmpipe).
TEST_F(ExecTest, ProductOfComparisonsWithANan) {
  arbvp::ExecInputs in = Inputs(1);
  in.vectors[0].fragment.color = {std::numeric_limits<float>::quiet_NaN(), -1.0f, 127.5f, -0.5f};
  in.vectors[0].fragment.texcoord[0] = {2.0f, 3.0f, 4.0f, 5.0f};
  BothEngines both = RunOnBoth(
      "!!ARBfp1.0\nTEMP r0, r1;\n"
      "SGE r0, fragment.color, fragment.color.yzxw;\n"
      "SGE r1, fragment.color, fragment.color.zxyw;\n"
      "MUL r0, r0, r1;\n"
      "MUL result.color, r0, fragment.texcoord[0];\nEND\n",
      in);
  ASSERT_EQ(both.arb.size(), 1u);
  ASSERT_EQ(both.glsl.size(), 1u);
  // r0 = (NaN >= -1, -1 >= 127.5, 127.5 >= NaN, 1) = (0, 0, 0, 1); r1 = (NaN >= 127.5,
  // -1 >= NaN, 127.5 >= -1, 1) = (0, 0, 1, 1); their product (0, 0, 0, 1).
  // Measured: z = 127.5 >= max(NaN, -1) = 1, times 4.
  EXPECT_TRUE(Value(both.arb[0], "result.color", {0.0f, 0.0f, Llvmpipe() ? 4.0f : 0.0f, 5.0f}));
  EXPECT_TRUE(Value(both.glsl[0], "result.color", {0.0f, 0.0f, 4.0f, 5.0f}));
  // One comparison alone is not folded: the spec's (0, 0, 0, 1) on both engines and drivers.
  BothEngines one =
      RunOnBoth("!!ARBfp1.0\nSGE result.color, fragment.color, fragment.color.yzxw;\nEND\n", in);
  ASSERT_EQ(one.arb.size(), 1u);
  ASSERT_EQ(one.glsl.size(), 1u);
  EXPECT_TRUE(Value(one.arb[0], "result.color", {0.0f, 0.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(Value(one.glsl[0], "result.color", {0.0f, 0.0f, 0.0f, 1.0f}));
}

// MUL t, v.x, v.y; MAD o, t, v.x, t of v = (-inf, 3): (-inf)(-inf) + (-inf) = inf + -inf =
// NaN by the pseudo-code (ARBvp 2.14.5.15); Mesa factors t * v.x + t as t * (v.x + 1) = inf
// on both engines (deviation nan-from-infinities, mesa-deviations.md).
TEST_F(ExecTest, NanMadeOfInfinitiesIsFactoredAway) {
  arbvp::ExecInputs in = Inputs(1);
  in.vectors[0].vertex.generic[1] = {-std::numeric_limits<float>::infinity(), 3.0f, 0.0f, 1.0f};
  BothEngines both = RunOnBoth(
      "!!ARBvp1.0\nTEMP t;\nMUL t, vertex.attrib[1].x, vertex.attrib[1].y;\n"
      "MAD result.texcoord[0], t, vertex.attrib[1].x, t;\n"
      "MOV result.position, vertex.position;\nEND\n",
      in);
  ASSERT_EQ(both.arb.size(), 1u);
  ASSERT_EQ(both.glsl.size(), 1u);
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_TRUE(Value(both.arb[0], "result.texcoord[0]", {inf, inf, inf, inf}));
  EXPECT_TRUE(Value(both.glsl[0], "result.texcoord[0]", {inf, inf, inf, inf}));
}

TEST_F(ExecTest, LitZeroToTheZero) {
  arbvp::ExecInputs in = Inputs(1);
  in.vectors[0].vertex.texcoord[0] = {1.0f, 0.0f, 0.0f, 0.0f};
  in.vertex_params.env[0] = {1.0f, 0.0f, 0.0f, 0.0f};
  auto results =
      Run("!!ARBvp1.0\nPARAM a = {1, 0, 0, 0};\nLIT result.texcoord[0], a;\n"
          "LIT result.texcoord[1], vertex.texcoord[0];\nLIT result.texcoord[2], program.env[0];\n"
          "END\n",
          "", in);
  ASSERT_EQ(results.size(), 1u);
  // LIT (1, x, x > 0 ? y^w : 0, 1) with x = 1, y = 0, w = 0: 0^0 = 1 (ARBvp 2.14.5.17).
  // llvmpipe computes 0 when the operand is not a compile-time constant
  // (mesa-deviations.md).
  const float z = Llvmpipe() ? 0.0f : 1.0f;
  EXPECT_TRUE(Value(results[0], "result.texcoord[0]", {1.0f, 1.0f, 1.0f, 1.0f}));
  EXPECT_TRUE(Value(results[0], "result.texcoord[1]", {1.0f, 1.0f, z, 1.0f}));
  EXPECT_TRUE(Value(results[0], "result.texcoord[2]", {1.0f, 1.0f, z, 1.0f}));
}

// Every valid corpus program survives the rewrite: Mesa loads every pass and the run reports
// each result register the program writes, with the components its instructions write.
TEST_F(ExecTest, EveryValidCorpusProgramRuns) {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(ARBITER_SOURCE_DIR) / "corpus" / "arb" / "valid";
  int ran = 0;
  for (const auto& entry : fs::directory_iterator(root)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".vp" && ext != ".fp") continue;
    SCOPED_TRACE(entry.path().filename().string());
    std::ifstream file(entry.path(), std::ios::binary);
    std::stringstream text;
    text << file.rdbuf();
    std::unique_ptr<arbvp::Program> program = Parse(text.str());
    ASSERT_NE(program, nullptr);
    // NV options are not Mesa's: such programs run on the interpreter only
    // (docs/design/platform.md).
    if (text.str().find("OPTION NV_") != std::string::npos) continue;
    arbvp::ExecInputs in = Inputs(2);
    in.vectors[1].vertex.position = {1.0f, 2.0f, 3.0f, 1.0f};
    ArbPrograms programs;
    (ext == ".vp" ? programs.vertex : programs.fragment) = program.get();
    std::vector<arbvp::VectorResult> results;
    std::string error;
    ASSERT_TRUE(executor_->Run(programs, in, &results, &error)) << error;
    ASSERT_EQ(results.size(), 2u);
    for (const arbvp::VectorResult& r : results) {
      if (r.killed) continue;
      for (const arbvp::OutputRegister& out : r.outputs) EXPECT_NE(out.written, 0) << out.name;
      if (ext == ".vp") {
        EXPECT_FALSE(r.outputs.empty());
      }
    }
    ++ran;
  }
  EXPECT_GE(ran, 100);
}

}  // namespace
}  // namespace arbiter::runtime
