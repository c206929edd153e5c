// The undefined-behaviour probe on Mesa (softpipe): the instrumented shaders compile, return
// what the originals return, and report for each vector the hazard kinds its operands made
// undefined and the first such site; two sentinels show what a path never wrote.
#include <gtest/gtest.h>

#include <map>
#include <memory>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/runtime/glsl_exec.h"
#include "arbiter/runtime/glsl_verify.h"
#include "glsl_verify/internal.h"

namespace arbiter::runtime {
namespace {

using glsl::HazardKind;
using glsl_verify::Probe;
using glsl_verify::ProbeFinding;

struct Shader {
  std::unique_ptr<compiler::SourceFile> file;
  glsl::Reflection reflection;
};

Shader Load(glsl::Stage stage, const std::string& path, const std::string& text) {
  Shader s;
  s.file = std::make_unique<compiler::SourceFile>(path, text);
  compiler::DiagnosticSink sink(0);
  s.reflection = glsl::ReflectShader(stage, {s.file.get()}, &sink);
  EXPECT_TRUE(s.reflection.ok) << text;
  return s;
}

unsigned Bit(HazardKind kind) { return 1u << static_cast<unsigned>(kind); }

// Runs the probe of one shader over `vectors` (values by input name) with the sentinel.
std::vector<GlslVectorResult> RunProbe(
    glsl::Stage stage, const Probe& probe,
    const std::vector<std::map<std::string, std::vector<float>>>& vectors, float sentinel,
    const std::vector<std::pair<std::string, std::vector<float>>>& uniforms = {}) {
  const bool vertex = stage == glsl::Stage::Vertex;
  Shader s = Load(stage, "probe.glsl", vertex ? probe.vertex : probe.fragment);
  GlslShaders shaders;
  (vertex ? shaders.vertex : shaders.fragment) = s.file->text();
  (vertex ? shaders.vertex_reflection : shaders.fragment_reflection) = &s.reflection;
  GlslExecInputs in;
  in.slots = GlslInputSlots(vertex ? &s.reflection : nullptr, vertex ? nullptr : &s.reflection);
  for (const auto& given : vectors) {
    std::map<std::string, std::vector<float>> v;
    for (const GlslInputSlot& slot : in.slots) v[slot.name] = slot.fill;
    for (const auto& [name, values] : given) v[name] = values;
    in.vectors.push_back(v);
  }
  in.uniforms = uniforms;
  in.uniforms.emplace_back(glsl_verify::kSentinelUniform, std::vector<float>{sentinel});
  for (const auto& [name, values] : in.uniforms) in.declared_uniforms.push_back(name);
  ExecOptions exec;
  exec.driver = "softpipe";
  GlslRunResult result;
  std::string error;
  EXPECT_EQ(RunGlslInWorker(exec, {}, shaders, in, &result, &error), WorkerStatus::Ok) << error;
  EXPECT_EQ(result.usage_error, "");
  return result.vectors;
}

const GlslOutput* Output(const GlslVectorResult& r, const std::string& name) {
  for (const GlslOutput& o : r.outputs) {
    if (o.name == name) return &o;
  }
  return nullptr;
}

TEST(GlslProbe, FragmentHazardsPerVector) {
  Shader f = Load(glsl::Stage::Fragment, "a.frag",
                  "varying vec4 k;\n"
                  "void main() {\n"
                  "  gl_FragColor = vec4(pow(k.x, k.y), k.z / k.w, sqrt(k.z), 1.0);\n"
                  "}\n");
  GlslVerifySubject subject{"a.frag", nullptr, f.file.get(), nullptr, &f.reflection};
  const Probe probe = glsl_verify::MakeProbe(subject);
  ASSERT_TRUE(probe.ok) << probe.why;
  ASSERT_EQ(probe.sites.size(), 3u);  // pow, '/', sqrt in source order
  EXPECT_EQ(probe.sites[0].kind, HazardKind::Pow);
  EXPECT_EQ(probe.sites[1].kind, HazardKind::Division);
  EXPECT_EQ(probe.sites[2].kind, HazardKind::Sqrt);
  EXPECT_EQ(probe.renamed.at("gl_FragColor"), "gl_FragData[0]");
  const std::vector<GlslVectorResult> r = RunProbe(glsl::Stage::Fragment, probe,
                                                   {{{"k", {2, 3, 1, 4}}},      // none
                                                    {{"k", {-2, 0.5f, 1, 1}}},  // pow
                                                    {{"k", {0, -1, 1, 0}}},     // pow, '/'
                                                    {{"k", {1, 1, -4, 2}}}},    // sqrt
                                                   0.25f);
  ASSERT_EQ(r.size(), 4u);
  const unsigned want[] = {0, Bit(HazardKind::Pow),
                           Bit(HazardKind::Pow) | Bit(HazardKind::Division), Bit(HazardKind::Sqrt)};
  const int first[] = {-1, 0, 0, 2};
  for (size_t v = 0; v < 4; ++v) {
    const ProbeFinding found = glsl_verify::ReadProbe(r[v]);
    EXPECT_TRUE(found.known) << v;
    EXPECT_EQ(found.kinds, want[v]) << v;
    EXPECT_EQ(found.site, first[v]) << v;
  }
  // The instrumented shader computes what the original does: 2^3, 1/4, sqrt(1).
  const GlslOutput* color = Output(r[0], "gl_FragData[0]");
  ASSERT_NE(color, nullptr);
  EXPECT_EQ(color->value, (std::vector<float>{8.0f, 0.25f, 1.0f, 1.0f}));
  EXPECT_EQ(glsl_verify::DescribeFinding(glsl_verify::ReadProbe(r[2]), probe),
            "division by zero (GLSL 1.10 section 4.1.4); pow(x, y) with x < 0, or x = 0 and y <= "
            "0 (GLSL 1.10 section 8.2), first at a.frag:3:23");
}

TEST(GlslProbe, VertexIndexNormalizeAndClamp) {
  Shader v = Load(glsl::Stage::Vertex, "b.vert",
                  "uniform float w[3];\n"
                  "attribute vec4 a;\n"
                  "void main() {\n"
                  "  vec3 n = normalize(a.xyz);\n"
                  "  gl_Position = vec4(n, w[int(a.w)] + clamp(a.x, a.y, 1.0));\n"
                  "}\n");
  GlslVerifySubject subject{"b.vert", v.file.get(), nullptr, &v.reflection, nullptr};
  const Probe probe = glsl_verify::MakeProbe(subject);
  ASSERT_TRUE(probe.ok) << probe.why;
  const std::vector<GlslVectorResult> r = RunProbe(glsl::Stage::Vertex, probe,
                                                   {{{"a", {1, 0, 0, 2}}},
                                                    {{"a", {0, 0, 0, 1}}},
                                                    {{"a", {1, 0, 0, 3}}},
                                                    {{"a", {0.5f, 2, 0, 0}}}},
                                                   0.25f, {{"w", {1, 2, 3}}});
  ASSERT_EQ(r.size(), 4u);
  const unsigned want[] = {0, Bit(HazardKind::Normalize), Bit(HazardKind::Index),
                           Bit(HazardKind::Clamp)};
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(glsl_verify::ReadProbe(r[i]).kinds, want[i]) << i;
  // normalize((1, 0, 0)) and w[2] + clamp(1, 0, 1).
  const GlslOutput* position = Output(r[0], "gl_Position");
  ASSERT_NE(position, nullptr);
  EXPECT_EQ(position->value, (std::vector<float>{1.0f, 0.0f, 0.0f, 4.0f}));
}

TEST(GlslProbe, LookupCoordinates) {
  Shader f = Load(glsl::Stage::Fragment, "d.frag",
                  "uniform sampler2D s;\n"
                  "uniform samplerCube c;\n"
                  "varying vec4 k;\n"
                  "void main() {\n"
                  "  gl_FragColor = texture2DProj(s, k.xyz) + textureCube(c, k.xyw);\n"
                  "}\n");
  GlslVerifySubject subject{"d.frag", nullptr, f.file.get(), nullptr, &f.reflection};
  const Probe probe = glsl_verify::MakeProbe(subject);
  ASSERT_TRUE(probe.ok) << probe.why;
  const std::vector<GlslVectorResult> r = RunProbe(glsl::Stage::Fragment, probe,
                                                   {{{"k", {0.5f, 0.25f, 2, 1}}},  // none
                                                    {{"k", {0.5f, 0.25f, 0, 1}}},  // q = 0
                                                    {{"k", {1, -1, 2, 0.5f}}},  // |x| = |y| largest
                                                    {{"k", {0.5f, 1, 2, 1}}}},  // |y| = |w|
                                                   0.25f, {{"s", {0}}, {"c", {1}}});
  ASSERT_EQ(r.size(), 4u);
  const unsigned want[] = {0, Bit(HazardKind::Projection), Bit(HazardKind::CubeFace),
                           Bit(HazardKind::CubeFace)};
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(glsl_verify::ReadProbe(r[i]).kinds, want[i]) << i;
}

TEST(GlslProbe, StateMatricesReadThroughTheNudge) {
  Shader v = Load(glsl::Stage::Vertex, "n.vert",
                  "void main() {\n"
                  "  vec3 n = gl_NormalMatrix * gl_Normal;\n"
                  "  gl_Position = gl_ModelViewMatrix[1] + gl_TextureMatrix[1] * gl_Vertex +\n"
                  "                vec4(n, 0.0);\n"
                  "}\n");
  GlslVerifySubject subject{"n.vert", v.file.get(), nullptr, &v.reflection, nullptr};
  const Probe probe = glsl_verify::MakeProbe(subject);
  ASSERT_TRUE(probe.ok) << probe.why;
  for (const char* wrapped : {"matrixCompMult(gl_NormalMatrix, arb_probe_nudge3)",
                              "matrixCompMult(gl_ModelViewMatrix, arb_probe_nudge4)[1]",
                              "matrixCompMult(gl_TextureMatrix[1], arb_probe_nudge4)"}) {
    EXPECT_NE(probe.vertex.find(wrapped), std::string::npos) << wrapped << "\n" << probe.vertex;
  }
  // With the nudge all ones the probe computes what the shader does.
  const std::vector<GlslVectorResult> r =
      RunProbe(glsl::Stage::Vertex, probe, {{{"gl_Vertex", {1, 2, 3, 1}}}}, 0.25f,
               {{glsl_verify::kNudge4Uniform, std::vector<float>(16, 1.0f)},
                {glsl_verify::kNudge3Uniform, std::vector<float>(9, 1.0f)}});
  ASSERT_EQ(r.size(), 1u);
  // Identity matrices: column 1 of the modelview (0, 1, 0, 0) + the vertex + the normal
  // (0, 0, 1).
  EXPECT_EQ(Output(r[0], "gl_Position")->value, (std::vector<float>{1, 3, 4, 1}));
}

TEST(GlslProbe, SentinelsShowWhatAPathNeverWrote) {
  Shader v = Load(glsl::Stage::Vertex, "c.vert",
                  "varying float t;\n"
                  "attribute float c;\n"
                  "float g;\n"
                  "struct S { float k; vec2 p; };\n"
                  "S gs;\n"
                  "void main() {\n"
                  "  float x;\n"
                  "  S ls;\n"
                  "  if (c > 0.0) { t = 1.0; x = 2.0; g = 3.0; gs.k = 4.0; ls.p = vec2(5.0); }\n"
                  "  gl_Position = vec4(x, g, gs.k, ls.p.y);\n"
                  "}\n");
  GlslVerifySubject subject{"c.vert", v.file.get(), nullptr, &v.reflection, nullptr};
  const Probe probe = glsl_verify::MakeProbe(subject);
  ASSERT_TRUE(probe.ok) << probe.why;
  const std::vector<std::map<std::string, std::vector<float>>> vectors = {{{"c", {1}}},
                                                                          {{"c", {-1}}}};
  const std::vector<GlslVectorResult> first =
      RunProbe(glsl::Stage::Vertex, probe, vectors, 0.3125f);
  const std::vector<GlslVectorResult> second =
      RunProbe(glsl::Stage::Vertex, probe, vectors, 0.6875f);
  ASSERT_EQ(first.size(), 2u);
  ASSERT_EQ(second.size(), 2u);
  // Written on the first vector's path: the same in both runs.
  EXPECT_EQ(Output(first[0], "t")->value, Output(second[0], "t")->value);
  EXPECT_EQ(Output(first[0], "gl_Position")->value, Output(second[0], "gl_Position")->value);
  EXPECT_EQ(Output(first[0], "gl_Position")->value, (std::vector<float>{2, 3, 4, 5}));
  // Not on the second's: t, the local x, the global g and the structures' members take each
  // run's sentinel.
  EXPECT_EQ(Output(first[1], "t")->value, std::vector<float>{0.3125f});
  EXPECT_EQ(Output(second[1], "t")->value, std::vector<float>{0.6875f});
  EXPECT_EQ(Output(first[1], "gl_Position")->value,
            (std::vector<float>{0.3125f, 0.3125f, 0.3125f, 0.3125f}));
  EXPECT_EQ(Output(second[1], "gl_Position")->value,
            (std::vector<float>{0.6875f, 0.6875f, 0.6875f, 0.6875f}));
}

}  // namespace
}  // namespace arbiter::runtime
