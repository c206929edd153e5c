// The mesa-glsl engine (ArbExecutor::RunTranslated) against the mesa-arb engine (Run) on the
// same programs and inputs, on the backend and driver that ARBITER_TEST_BACKEND and
// ARBITER_TEST_DRIVER name (one ctest entry per combination, as runtime_exec_test). Both
// must agree on every written component the interpreter does not tag undefined: exactly, or
// within 2^-11 relative where the programs use approximated operations. A mutation of the
// translator must make them disagree: that is what a differential verifier relies on.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/emit_mutation.h"
#include "arbiter/arbvp/interpret.h"
#include "arbiter/runtime/exec.h"
#include "test_executor.h"

namespace arbiter::runtime {
namespace {

using arbvp::Vec4;

ArbExecutor* Executor(std::string* error) { return testing::SharedExecutor(error); }

const arbvp::OutputRegister* Find(const arbvp::VectorResult& result, const std::string& name) {
  for (const arbvp::OutputRegister& out : result.outputs) {
    if (out.name == name) return &out;
  }
  return nullptr;
}

constexpr float kApprox = 1.0f / 2048.0f;  // 2^-11, the specs' bound for EX2, LG2, RSQ...

bool Agree(float a, float b, float tolerance) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  if (tolerance == 0.0f) return a == b;
  const float scale = std::max({std::fabs(a), std::fabs(b), 1.0f / (1 << 20)});
  return std::fabs(a - b) <= tolerance * scale;
}

// What a comparison found: the components compared, and the first disagreement.
struct Comparison {
  int compared = 0;
  std::string difference;
};

class ExecGlslTest : public ::testing::Test {
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

  // Runs vp and/or fp (empty: none) on both engines and compares them, skipping what the
  // interpreter tags undefined.
  Comparison Compare(const std::string& vp, const std::string& fp, const arbvp::ExecInputs& in,
                     float tolerance, arbvp::Mutation mutation = arbvp::Mutation::None) {
    std::unique_ptr<arbvp::Program> v = vp.empty() ? nullptr : Parse(vp);
    std::unique_ptr<arbvp::Program> f = fp.empty() ? nullptr : Parse(fp);
    Comparison c;
    if (::testing::Test::HasFailure()) return c;
    std::vector<arbvp::VectorResult> arb;
    std::vector<arbvp::VectorResult> glsl;
    std::string error;
    EXPECT_TRUE(executor_->Run({v.get(), f.get()}, in, &arb, &error)) << error;
    const arbvp::EmitOptions emit = arbvp::WithMutation(arbvp::EmitOptions{}, mutation);
    EXPECT_TRUE(executor_->RunTranslated({v.get(), f.get()}, emit, in, &glsl, &error)) << error;
    const std::vector<arbvp::VectorResult> ref = v != nullptr && f != nullptr
                                                     ? arbvp::InterpretPair(*v, *f, in)
                                                     : arbvp::Interpret(v != nullptr ? *v : *f, in);
    EXPECT_EQ(arb.size(), in.vectors.size());
    EXPECT_EQ(glsl.size(), in.vectors.size());
    if (arb.size() != glsl.size() || ref.size() != arb.size()) return c;
    for (size_t i = 0; i < arb.size() && c.difference.empty(); ++i) {
      if (!ref[i].kill_undefined.empty()) continue;
      if (arb[i].killed != glsl[i].killed) {
        c.difference = "vector " + std::to_string(i) + ": killed differs";
        break;
      }
      for (const arbvp::OutputRegister& a : arb[i].outputs) {
        const arbvp::OutputRegister* g = Find(glsl[i], a.name);
        const arbvp::OutputRegister* r = Find(ref[i], a.name);
        if (g == nullptr) {
          c.difference = "vector " + std::to_string(i) + ": no " + a.name + " from mesa-glsl";
          break;
        }
        for (size_t k = 0; k < 4; ++k) {
          if (((a.written & g->written) & (1u << k)) == 0) continue;
          if (r != nullptr && !r->undefined[k].empty()) continue;
          ++c.compared;
          if (!Agree(a.value[k], g->value[k], tolerance)) {
            std::ostringstream s;
            s << "vector " << i << ": " << a.name << "[" << k << "] mesa-arb " << a.value[k]
              << " mesa-glsl " << g->value[k];
            c.difference = s.str();
            break;
          }
        }
        if (!c.difference.empty()) break;
      }
    }
    return c;
  }

  void ExpectAgree(const std::string& vp, const std::string& fp, const arbvp::ExecInputs& in,
                   float tolerance = 0.0f) {
    Comparison c = Compare(vp, fp, in, tolerance);
    EXPECT_EQ(c.difference, "") << executor_->description();
    EXPECT_GT(c.compared, 0);
  }

  // Vectors with varied, non-default inputs.
  static arbvp::ExecInputs Inputs(size_t count) {
    arbvp::ExecInputs in;
    in.vectors.resize(count);
    for (size_t i = 0; i < count; ++i) {
      const float f = static_cast<float>(i);
      arbvp::InputVector& v = in.vectors[i];
      v.vertex.position = {f - 3.0f, 0.5f * f, 2.0f - f, 1.0f + 0.25f * f};
      v.vertex.normal = {0.25f * f, 1.0f, -0.5f, 1.0f};
      v.vertex.color = {0.1f * f, 1.5f, -0.25f, 0.75f};
      v.vertex.fogcoord = {3.0f + f, 0.0f, 0.0f, 1.0f};
      for (size_t k = 0; k < arbvp::kMaxTextureCoords; ++k) {
        v.vertex.texcoord[k] = {f + static_cast<float>(k), -f, 0.5f, 2.0f};
        v.fragment.texcoord[k] = {0.125f + 0.25f * static_cast<float>((i + k) % 4),
                                  0.375f + 0.25f * static_cast<float>(i % 2),
                                  static_cast<float>(k) - f, 1.0f + 0.5f * f};
      }
      for (size_t n = 1; n < arbvp::kMaxGenericAttribs; ++n) {
        v.vertex.generic[n] = {f * static_cast<float>(n), 1.0f, -2.0f, 0.5f};
      }
      v.fragment.color = {0.25f * f, 2.0f, -1.0f, 0.5f};
      v.fragment.secondary_color = {0.5f, 0.25f * f, 0.125f, 1.0f};
      v.fragment.fogcoord = 0.5f * f;
      v.fragment.depth = 0.125f * static_cast<float>(i % 8);
    }
    return in;
  }

  ArbExecutor* executor_ = nullptr;
};

TEST_F(ExecGlslTest, MoreThanEightVertexOutputs) {
  ExpectAgree(
      "!!ARBvp1.0\n"
      "PARAM k = {1, 2, 3, 4};\n"
      "ADD result.position, vertex.position, k;\n"
      "ADD result.color.front.primary, vertex.position, 2;\n"
      "MUL result.color.front.secondary, vertex.color, 3;\n"
      "ADD result.color.back.primary, vertex.normal, 4;\n"
      "ADD result.color.back.secondary.xz, vertex.position, 5;\n"
      "ADD result.fogcoord.x, vertex.fogcoord, 6;\n"
      "ADD result.pointsize.x, vertex.position.y, 7;\n"
      "MOV result.texcoord[0], vertex.texcoord[0];\n"
      "MOV result.texcoord[1], vertex.texcoord[1];\n"
      "MUL result.texcoord[2], vertex.texcoord[2], k;\n"
      "MOV result.texcoord[3].yw, vertex.attrib[6];\n"
      "MAD result.texcoord[4], vertex.texcoord[4], k, vertex.attrib[6];\n"
      "MOV result.texcoord[5], -vertex.texcoord[5].wzyx;\n"
      "SUB result.texcoord[6], vertex.texcoord[6], k;\n"
      "MOV result.texcoord[7], vertex.texcoord[7];\n"
      "END\n",
      "", Inputs(70));
}

TEST_F(ExecGlslTest, StateBindingsProgramMatricesAndLights) {
  arbvp::ExecInputs in = Inputs(5);
  in.state.modelview = glm::translate(glm::mat4(2.0f), glm::vec3(5.0f, 6.0f, 7.0f));
  in.state.projection = glm::scale(glm::mat4(1.0f), glm::vec3(0.5f, 0.25f, 2.0f));
  in.state.program[1] = glm::rotate(glm::mat4(1.0f), 0.5f, glm::vec3(0.0f, 0.0f, 1.0f));
  in.state.program[1][3] = glm::vec4(1.0f, 2.0f, 3.0f, 1.0f);
  in.state.program[0] = glm::scale(glm::mat4(1.0f), glm::vec3(2.0f, 4.0f, 8.0f));
  in.state.light[1].position = {1.0f, 2.0f, 3.0f, 1.0f};
  in.state.light[1].diffuse = {0.5f, 2.0f, -1.0f, 1.0f};
  in.state.light[0].ambient = {0.25f, 0.5f, 0.75f, 1.0f};
  in.state.light[1].spot_direction = {0.0f, 1.0f, 0.0f};
  in.state.light[1].spot_cutoff = 60.0f;
  in.state.material[0].diffuse = {0.1f, 0.2f, 0.3f, 0.4f};
  in.state.material[0].ambient = {0.5f, 0.5f, 0.25f, 1.0f};
  in.state.clip_plane[1] = {0.0f, 1.0f, 0.0f, -4.0f};
  in.state.fog_density = 2.0f;
  ExpectAgree(
      "!!ARBvp1.0\n"
      "PARAM mvp[4] = {state.matrix.mvp};\n"
      "PARAM p1[4] = {state.matrix.program[1]};\n"
      "PARAM p0i[4] = {state.matrix.program[0].inverse};\n"
      "PARAM mvt[4] = {state.matrix.modelview.transpose};\n"
      "DP4 result.position.x, mvp[0], vertex.position;\n"
      "DP4 result.position.y, mvp[1], vertex.position;\n"
      "DP4 result.position.z, mvp[2], vertex.position;\n"
      "DP4 result.position.w, mvp[3], vertex.position;\n"
      "DP4 result.texcoord[0].x, p1[0], vertex.position;\n"
      "DP4 result.texcoord[0].y, p1[1], vertex.position;\n"
      "DP4 result.texcoord[0].z, p1[2], vertex.position;\n"
      "DP4 result.texcoord[0].w, p1[3], vertex.position;\n"
      "MOV result.texcoord[1], p0i[0];\n"
      "MOV result.texcoord[2], p0i[2];\n"
      "MOV result.texcoord[3], mvt[3];\n"
      "MOV result.texcoord[4], state.light[1].position;\n"
      "MUL result.texcoord[5], state.light[1].diffuse, state.light[0].ambient;\n"
      "MOV result.texcoord[6], state.lightprod[0].ambient;\n"
      "MOV result.texcoord[7], state.light[1].spot.direction;\n"
      "MOV result.color, state.material.diffuse;\n"
      "MOV result.color.secondary, state.clip[1].plane;\n"
      "MOV result.color.back, state.fog.params;\n"
      "END\n",
      "", in, kApprox);
}

TEST_F(ExecGlslTest, EnvLocalAndRelativeAddressing) {
  arbvp::ExecInputs in = Inputs(8);
  for (int n = 0; n < 6; ++n) {
    const float f = static_cast<float>(n);
    in.vertex_params.env[n] = {f, f + 0.5f, -f, 10.0f * f};
    in.vertex_params.local[n] = {2.0f * f, 1.0f, f * f, -3.0f};
  }
  for (size_t i = 0; i < in.vectors.size(); ++i) {
    in.vectors[i].vertex.generic[1] = {static_cast<float>(i) - 1.5f, 0.0f, 0.0f, 1.0f};
  }
  ExpectAgree(
      "!!ARBvp1.0\n"
      "ADDRESS a;\n"
      "PARAM arr[6] = {program.env[0..3], program.local[4..5]};\n"
      "ARL a.x, vertex.attrib[1].x;\n"
      "MOV result.position, vertex.position;\n"
      "MOV result.texcoord[0], arr[a.x + 1];\n"
      "MOV result.texcoord[1], arr[a.x];\n"
      "ADD result.texcoord[2], program.local[1], program.env[5];\n"
      "MOV result.texcoord[3], arr[5];\n"
      "END\n",
      "", in);
}

arbvp::Texture Checker() {
  arbvp::Texture t;
  t.dim = arbvp::TexDim::Tex2D;
  t.width = 4;
  t.height = 2;
  for (int i = 0; i < t.width * t.height; ++i) {
    const float f = static_cast<float>(i);
    t.texels.insert(t.texels.end(), {f, 0.5f * f, -f, 1.0f + f});
  }
  return t;
}

TEST_F(ExecGlslTest, FragmentKillDepthAndTextures) {
  arbvp::ExecInputs in = Inputs(20);
  in.textures[0] = Checker();
  in.textures[3] = Checker();
  in.fragment_params.env[2] = {0.5f, -1.0f, 2.0f, 0.0f};
  in.fragment_params.local[0] = {4.0f, 3.0f, 2.0f, 1.0f};
  for (size_t i = 0; i < in.vectors.size(); i += 3) in.vectors[i].fragment.color[1] = -1.0f;
  ExpectAgree("",
              "!!ARBfp1.0\n"
              "OPTION ARB_draw_buffers;\n"
              "TEMP t, u;\n"
              "KIL fragment.color.y;\n"
              "TEX t, fragment.texcoord[0], texture[0], 2D;\n"
              "TXP u, fragment.texcoord[1], texture[3], 2D;\n"
              "MAD result.color[0], t, program.env[2], program.local[0];\n"
              "ADD result.color[1], u, fragment.color;\n"
              "MOV result.color[2], fragment.position;\n"
              "MOV result.color[3], fragment.texcoord[2];\n"
              "MOV result.color[3].w, fragment.fogcoord.x;\n"
              "MUL result.color[4], fragment.color.secondary, t;\n"
              "ADD result.color[5], t, u;\n"
              "SUB result.color[6], t, u;\n"
              "MOV result.color[7], fragment.texcoord[3];\n"
              "ADD result.depth.z, fragment.position.z, 0.125;\n"
              "END\n",
              in);
}

TEST_F(ExecGlslTest, PairClampsVertexColours) {
  arbvp::ExecInputs in = Inputs(9);
  in.textures[1] = Checker();
  in.state.program[2] = glm::scale(glm::mat4(1.0f), glm::vec3(0.25f, 0.5f, 1.0f));
  ExpectAgree(
      "!!ARBvp1.0\n"
      "PARAM m[4] = {state.matrix.program[2]};\n"
      "MOV result.position, vertex.position;\n"
      "MOV result.color, vertex.color;\n"
      "MUL result.color.secondary, vertex.color, -2;\n"
      "DP4 result.texcoord[0].x, m[0], vertex.texcoord[0];\n"
      "DP4 result.texcoord[0].y, m[1], vertex.texcoord[0];\n"
      "MOV result.texcoord[0].zw, vertex.texcoord[0];\n"
      "MOV result.texcoord[2], vertex.attrib[7];\n"
      "MOV result.fogcoord.x, vertex.fogcoord.x;\n"
      "END\n",
      "!!ARBfp1.0\n"
      "TEMP t;\n"
      "TEX t, fragment.texcoord[0], texture[1], 2D;\n"
      "MAD t, t, fragment.texcoord[2], fragment.color;\n"
      "ADD t.w, t.w, fragment.fogcoord.x;\n"
      "ADD result.color, t, fragment.color.secondary;\n"
      "END\n",
      in);
}

TEST_F(ExecGlslTest, ApproximatedOperations) {
  arbvp::ExecInputs in = Inputs(6);
  ExpectAgree(
      "!!ARBvp1.0\n"
      "TEMP t;\n"
      "MOV result.position, vertex.position;\n"
      "ADD t, vertex.texcoord[0], 1.5;\n"
      "EX2 result.texcoord[0].x, t.x;\n"
      "LG2 result.texcoord[0].y, t.x;\n"
      "POW result.texcoord[0].z, t.x, t.w;\n"
      "RCP result.texcoord[0].w, t.x;\n"
      "RSQ result.texcoord[1].x, -t.x;\n"
      "LIT result.texcoord[2], vertex.attrib[3];\n"
      "EXP result.texcoord[3], t.x;\n"
      "LOG result.texcoord[4], t.x;\n"
      "END\n",
      "", in, kApprox);
  ExpectAgree("",
              "!!ARBfp1.0\n"
              "OPTION ARB_draw_buffers;\n"
              "TEMP t;\n"
              "ADD t, fragment.texcoord[2], 0.25;\n"
              "SIN result.color[0].x, t.x;\n"
              "COS result.color[0].y, t.x;\n"
              "SCS result.color[1].xy, t.x;\n"
              "EX2 result.color[2], t.x;\n"
              "END\n",
              in, kApprox);
}

TEST_F(ExecGlslTest, FogOptionOnResultColor) {
  arbvp::ExecInputs in = Inputs(6);
  in.state.fog_color = {0.25f, 0.5f, 0.75f, 1.0f};
  in.state.fog_start = 0.5f;
  in.state.fog_end = 3.0f;
  ExpectAgree("",
              "!!ARBfp1.0\n"
              "OPTION ARB_fog_linear;\n"
              "MUL result.color, fragment.color, 0.5;\n"
              "END\n",
              in, kApprox);
}

// The verifier's premise: a translator bug shows up as a disagreement with mesa-arb.
TEST_F(ExecGlslTest, MutationChangesTheResult) {
  arbvp::ExecInputs in = Inputs(3);
  const std::string vp =
      "!!ARBvp1.0\n"
      "PARAM k = {-4, 0, 0, 0};\n"
      "MOV result.position, vertex.position;\n"
      "RSQ result.texcoord[0].x, k.x;\n"
      "END\n";
  Comparison same = Compare(vp, "", in, kApprox);
  EXPECT_EQ(same.difference, "");
  Comparison mutated = Compare(vp, "", in, kApprox, arbvp::Mutation::RsqNoAbs);
  EXPECT_NE(mutated.difference, "");

  in.state.program[3] = glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 2.0f, 3.0f));
  const std::string rows =
      "!!ARBvp1.0\n"
      "PARAM m[4] = {state.matrix.program[3]};\n"
      "MOV result.position, vertex.position;\n"
      "MOV result.texcoord[0], m[0];\n"
      "END\n";
  EXPECT_EQ(Compare(rows, "", in, 0.0f).difference, "");
  EXPECT_NE(Compare(rows, "", in, 0.0f, arbvp::Mutation::MatrixRowsColumns).difference, "");
}

TEST_F(ExecGlslTest, TranslationOfEveryMutationRuns) {
  // Each mutation still gives GLSL that Mesa compiles and runs (a mutation that failed to
  // compile would look like an engine error, not a caught bug).
  arbvp::ExecInputs in = Inputs(2);
  std::unique_ptr<arbvp::Program> f = Parse(
      "!!ARBfp1.0\nOPTION ARB_draw_buffers;\nTEMP t;\n"
      "LRP t, fragment.color, fragment.texcoord[0], fragment.texcoord[1];\n"
      "LIT result.color[0], t;\nRSQ result.color[1], t.x;\nKIL t;\n"
      "SWZ result.color[2], t, -x, 0, 1, w;\nEND\n");
  for (arbvp::Mutation m : arbvp::AllMutations()) {
    const arbvp::EmitOptions emit = arbvp::WithMutation(arbvp::EmitOptions{}, m);
    std::vector<arbvp::VectorResult> results;
    std::string error;
    EXPECT_TRUE(executor_->RunTranslated({nullptr, f.get()}, emit, in, &results, &error))
        << arbvp::MutationName(m) << ": " << error;
  }
}

}  // namespace
}  // namespace arbiter::runtime
