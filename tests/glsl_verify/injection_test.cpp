// The injection test of the GLSL verify (issue 23): wrong values put into one engine's
// results, one output component per vector, and discards flipped, each reported as a
// disagreement at its vector and component, and nothing else reported.
#include <gtest/gtest.h>

#include <cmath>
#include <compare>
#include <cstdio>
#include <fstream>
#include <memory>
#include <ostream>
#include <set>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/runtime/glsl_verify.h"

namespace arbiter::runtime {
namespace {

struct Shader {
  std::unique_ptr<compiler::SourceFile> file;
  glsl::Reflection reflection;
};

std::unique_ptr<Shader> Load(glsl::Stage stage, const std::string& path, const std::string& text) {
  auto s = std::make_unique<Shader>();
  s->file = std::make_unique<compiler::SourceFile>(path, text);
  compiler::DiagnosticSink sink(0);
  s->reflection = glsl::ReflectShader(stage, {s->file.get()}, &sink);
  EXPECT_TRUE(s->reflection.ok) << text;
  return s;
}

// Shaders whose outputs every engine computes alike on every input: no operation with
// undefined results, no discontinuity, no imprecise built-in.
const char* kVertex =
    "uniform mat2 m2;\n"
    "uniform vec3 offset;\n"
    "attribute vec3 tangent;\n"
    "varying vec3 n;\n"
    "varying mat2 rot;\n"
    "void main() {\n"
    "  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n"
    "  gl_FrontColor = gl_Color * gl_FrontMaterial.diffuse;\n"
    "  gl_TexCoord[1] = gl_TextureMatrix[1] * gl_MultiTexCoord1;\n"
    "  gl_PointSize = gl_Point.size * 2.0;\n"
    "  n = gl_NormalMatrix * gl_Normal + tangent * offset;\n"
    "  rot = m2 * 0.5;\n"
    "}\n";
const char* kFragment =
    "uniform vec4 tint;\n"
    "varying vec2 uv;\n"
    "void main() {\n"
    "  if (uv.x > 50.0) discard;\n"
    "  gl_FragData[0] = gl_Color * tint;\n"
    "  gl_FragData[1] = vec4(uv * 2.0, gl_TexCoord[0].xy);\n"
    "  gl_FragDepth = gl_FragCoord.z * 0.5;\n"
    "}\n";

struct Site {
  size_t vector;
  std::string label;  // "" for a discard flipped
  auto operator<=>(const Site&) const = default;
};
void PrintTo(const Site& s, std::ostream* out) { *out << s.vector << " " << s.label; }

std::string Label(const GlslOutput& o, size_t c) {
  if (o.value.size() == 1) return o.name;
  if (o.type.rfind("mat", 0) == 0) {
    const size_t rows = static_cast<size_t>(o.type.back() - '0');
    return o.name + "[" + std::to_string(c / rows) + "]." + "xyzw"[c % rows];
  }
  return o.name + "." + "xyzw"[c];
}

// Verifies `subject` on softpipe and `engine` with one wrong value per vector of the edge
// batch in `engine`'s results (and, with `discards`, every fifth vector's discard flipped
// instead), and checks that exactly those sites are reported. The tamper runs in verify's
// worker process: it writes the sites it made to a file the test reads afterwards.
void ExpectEachCaught(const GlslVerifySubject& subject, const std::string& engine, bool discards) {
  // One file per test: ctest runs the tests of this binary in parallel processes.
  const std::string log = ::testing::TempDir() + "glsl_verify_injected_" +
                          ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".txt";
  std::remove(log.c_str());
  GlslVerifyOptions options;
  options.engines = {kGlslEngineSoftpipe, engine};
  options.generate.random_vectors = 8;
  options.tamper = [&](const std::string& e, size_t batch, std::vector<GlslVectorResult>* r) {
    if (e != engine || batch != 0) return;
    std::ofstream out(log);
    for (size_t v = 0; v < r->size(); ++v) {
      GlslVectorResult& result = (*r)[v];
      if (discards && v % 5 == 0) {
        result.discarded = !result.discarded;
        if (result.discarded) result.outputs.clear();
        out << v << "|\n";
        continue;
      }
      size_t total = 0;
      for (const GlslOutput& o : result.outputs) total += o.value.size();
      if (total == 0) continue;
      size_t k = (v * 7) % total;
      for (GlslOutput& o : result.outputs) {
        if (k >= o.value.size()) {
          k -= o.value.size();
          continue;
        }
        float& x = o.value[k];
        x = std::isfinite(x) ? x + 1.0f + 2.0f * std::fabs(x) : 1.0f;
        out << v << "|" << Label(o, k) << "\n";
        break;
      }
    }
  };
  const std::vector<Verdict> verdicts = VerifyGlsl({subject}, options);
  ASSERT_EQ(verdicts.size(), 1u);
  const Verdict& v = verdicts[0];
  EXPECT_EQ(v.error, "");
  EXPECT_TRUE(v.not_applicable.empty());
  EXPECT_EQ(v.undefined.size(), 0u);
  EXPECT_EQ(v.unstable, 0u);
  std::set<Site> injected;
  std::ifstream in(log);
  for (std::string line; std::getline(in, line);) {
    const size_t bar = line.find('|');
    injected.insert({std::stoul(line.substr(0, bar)), line.substr(bar + 1)});
  }
  ASSERT_GE(injected.size(), 20u);
  std::set<Site> reported;
  for (const Disagreement& d : v.disagreements) {
    EXPECT_EQ(d.batch, "edge");
    EXPECT_EQ(d.engines, std::vector<std::string>{engine});
    EXPECT_FALSE(d.inputs.empty());
    if (d.label.empty()) {
      EXPECT_EQ(d.what.rfind("discarded by ", 0), 0u) << d.what;
    }
    reported.insert({d.vector, d.label});
  }
  EXPECT_EQ(reported.size(), v.disagreements.size()) << "one report per site";
  EXPECT_EQ(reported, injected);
}

TEST(GlslVerifyInjection, VertexOutputsOnLlvmpipe) {
  auto s = Load(glsl::Stage::Vertex, "inject.vert", kVertex);
  ExpectEachCaught({"inject.vert", s->file.get(), nullptr, &s->reflection, nullptr},
                   kGlslEngineLlvmpipe, false);
}

TEST(GlslVerifyInjection, FragmentOutputsAndDiscardsOnLlvmpipe) {
  auto s = Load(glsl::Stage::Fragment, "inject.frag", kFragment);
  ExpectEachCaught({"inject.frag", nullptr, s->file.get(), nullptr, &s->reflection},
                   kGlslEngineLlvmpipe, true);
}

TEST(GlslVerifyInjection, PairOnLlvmpipe) {
  auto v = Load(glsl::Stage::Vertex, "inject.vert", kVertex);
  auto f = Load(glsl::Stage::Fragment, "pair.frag",
                "varying vec3 n;\nvoid main() { gl_FragColor = vec4(n, 1.0) * gl_Color; }\n");
  ExpectEachCaught({"pair", v->file.get(), f->file.get(), &v->reflection, &f->reflection},
                   kGlslEngineLlvmpipe, false);
}

// The same on the Vulkan engine (glslang to SPIR-V on lavapipe).
TEST(GlslVerifyInjection, VertexOutputsOnVulkan) {
  auto s = Load(glsl::Stage::Vertex, "inject.vert", kVertex);
  ExpectEachCaught({"inject.vert", s->file.get(), nullptr, &s->reflection, nullptr},
                   kGlslEngineVulkan, false);
}

TEST(GlslVerifyInjection, FragmentOutputsAndDiscardsOnVulkan) {
  auto s = Load(glsl::Stage::Fragment, "inject.frag", kFragment);
  ExpectEachCaught({"inject.frag", nullptr, s->file.get(), nullptr, &s->reflection},
                   kGlslEngineVulkan, true);
}

}  // namespace
}  // namespace arbiter::runtime
