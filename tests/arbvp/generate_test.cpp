// The input generator of `arbiter verify` (generate.h): determinism, batch shapes, edge
// coverage, parameters, textures, the GL state's ranges and conditioning, and the description
// of the inputs a program reads.
#include "arbiter/arbvp/generate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/exec_io.h"

namespace arbiter::arbvp {
namespace {

std::unique_ptr<Program> Parse(const std::string& text) {
  compiler::SourceFile source("test", text);
  compiler::DiagnosticSink sink(0);
  CheckResult result = CheckProgram(source, CheckOptions{}, &sink);
  std::string log;
  for (const compiler::Diagnostic& d : sink.diagnostics()) log += d.message + "\n";
  EXPECT_TRUE(result.ok) << log;
  return std::move(result.program);
}

// Reads many attributes, env and local parameters and state.
constexpr char kVertex[] =
    "!!ARBvp1.0\n"
    "PARAM mvp[4] = { state.matrix.mvp };\n"
    "TEMP t;\n"
    "DP4 result.position.x, mvp[0], vertex.position;\n"
    "MOV t, vertex.normal;\n"
    "ADD t, t, vertex.color;\n"
    "ADD t, t, vertex.color.secondary;\n"
    "ADD t, t, vertex.fogcoord;\n"
    "ADD t, t, vertex.texcoord[3];\n"
    "ADD t, t, vertex.attrib[6];\n"
    "ADD t, t, vertex.attrib[7];\n"
    "ADD t, t, program.env[4];\n"
    "MUL t, t, program.local[0];\n"
    "ADD result.color, t, state.light[2].position;\n"
    "END\n";

constexpr char kRelative[] =
    "!!ARBvp1.0\n"
    "PARAM arr[5] = { program.env[3..7] };\n"
    "PARAM two[3] = { program.local[10..12] };\n"
    "ADDRESS a;\n"
    "TEMP t;\n"
    "ARL a.x, vertex.attrib[1].x;\n"
    "MOV result.position, arr[a.x + 1];\n"
    "MOV t, two[1];\n"
    "ADD result.color, t, program.local[20];\n"
    "END\n";

constexpr char kTextures[] =
    "!!ARBfp1.0\n"
    "OPTION ARB_fragment_program_shadow;\n"
    "TEMP r;\n"
    "TEX r, fragment.texcoord[0], texture[0], 1D;\n"
    "TEX r, fragment.texcoord[1], texture[1], 2D;\n"
    "TEX r, fragment.texcoord[2], texture[2], 3D;\n"
    "TEX r, fragment.texcoord[3], texture[3], CUBE;\n"
    "TEX r, fragment.texcoord[4], texture[4], RECT;\n"
    "TEX r, fragment.texcoord[5], texture[5], SHADOW1D;\n"
    "TEX r, fragment.texcoord[6], texture[6], SHADOW2D;\n"
    "TXP r, fragment.texcoord[7], texture[7], SHADOWRECT;\n"
    "ADD result.color, r, fragment.position;\n"
    "END\n";

constexpr char kFragment[] =
    "!!ARBfp1.0\n"
    "TEMP r;\n"
    "ADD r, fragment.color, fragment.color.secondary;\n"
    "ADD r, r, fragment.texcoord[2];\n"
    "ADD r, r, fragment.fogcoord;\n"
    "ADD result.color, r, fragment.position;\n"
    "END\n";

bool SameVec(const Vec4& a, const Vec4& b) {
  for (size_t i = 0; i < 4; ++i) {
    if (!SameFloat(a[i], b[i])) return false;
  }
  return true;
}

bool SameMatrix(const glm::mat4& a, const glm::mat4& b) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!SameFloat(a[c][r], b[c][r])) return false;
    }
  }
  return true;
}

bool SameTexture(const Texture& a, const Texture& b) {
  if (a.dim != b.dim || a.width != b.width || a.height != b.height || a.depth != b.depth ||
      a.filter != b.filter || a.wrap != b.wrap || a.depth_texture != b.depth_texture ||
      a.compare != b.compare || a.compare_func != b.compare_func || a.depth_mode != b.depth_mode ||
      a.texels.size() != b.texels.size()) {
    return false;
  }
  for (size_t i = 0; i < a.texels.size(); ++i) {
    if (!SameFloat(a.texels[i], b.texels[i])) return false;
  }
  return true;
}

bool SameParams(const std::map<int, Vec4>& a, const std::map<int, Vec4>& b) {
  if (a.size() != b.size()) return false;
  for (const auto& [index, value] : a) {
    auto it = b.find(index);
    if (it == b.end() || !SameVec(value, it->second)) return false;
  }
  return true;
}

// Every field of the inputs, floats by bits with every NaN equal to every NaN.
bool SameInputs(const ExecInputs& a, const ExecInputs& b) {
  const GlState& s = a.state;
  const GlState& t = b.state;
  if (!SameMatrix(s.modelview, t.modelview) || !SameMatrix(s.projection, t.projection)) {
    return false;
  }
  for (size_t i = 0; i < s.texture.size(); ++i) {
    if (!SameMatrix(s.texture[i], t.texture[i])) return false;
  }
  for (size_t i = 0; i < s.light.size(); ++i) {
    const LightState& l = s.light[i];
    const LightState& m = t.light[i];
    if (!SameVec(l.ambient, m.ambient) || !SameVec(l.diffuse, m.diffuse) ||
        !SameVec(l.specular, m.specular) || !SameVec(l.position, m.position) ||
        !SameFloat(l.spot_cutoff, m.spot_cutoff) || !SameFloat(l.spot_exponent, m.spot_exponent) ||
        l.spot_direction != m.spot_direction ||
        !SameFloat(l.quadratic_attenuation, m.quadratic_attenuation)) {
      return false;
    }
  }
  for (size_t i = 0; i < s.material.size(); ++i) {
    if (!SameVec(s.material[i].diffuse, t.material[i].diffuse) ||
        !SameFloat(s.material[i].shininess, t.material[i].shininess)) {
      return false;
    }
  }
  if (!SameVec(s.fog_color, t.fog_color) || !SameFloat(s.fog_start, t.fog_start) ||
      !SameFloat(s.fog_end, t.fog_end) || !SameFloat(s.depth_near, t.depth_near) ||
      !SameFloat(s.depth_far, t.depth_far) || !SameFloat(s.point_size, t.point_size) ||
      !SameVec(s.texgen[3].eye[1], t.texgen[3].eye[1]) ||
      !SameVec(s.clip_plane[2], t.clip_plane[2]) ||
      !SameVec(s.texenv_color[5], t.texenv_color[5])) {
    return false;
  }
  if (!SameParams(a.vertex_params.env, b.vertex_params.env) ||
      !SameParams(a.vertex_params.local, b.vertex_params.local) ||
      !SameParams(a.fragment_params.env, b.fragment_params.env) ||
      !SameParams(a.fragment_params.local, b.fragment_params.local)) {
    return false;
  }
  if (a.textures.size() != b.textures.size()) return false;
  for (const auto& [unit, texture] : a.textures) {
    auto it = b.textures.find(unit);
    if (it == b.textures.end() || !SameTexture(texture, it->second)) return false;
  }
  if (a.vectors.size() != b.vectors.size()) return false;
  for (size_t i = 0; i < a.vectors.size(); ++i) {
    const VertexInput& v = a.vectors[i].vertex;
    const VertexInput& w = b.vectors[i].vertex;
    const FragmentInput& f = a.vectors[i].fragment;
    const FragmentInput& g = b.vectors[i].fragment;
    if (!SameVec(v.position, w.position) || !SameVec(v.normal, w.normal) ||
        !SameVec(v.color, w.color) || !SameVec(v.secondary_color, w.secondary_color) ||
        !SameVec(v.fogcoord, w.fogcoord) || !SameVec(f.color, g.color) ||
        !SameVec(f.secondary_color, g.secondary_color) || !SameFloat(f.fogcoord, g.fogcoord) ||
        !SameFloat(f.depth, g.depth)) {
      return false;
    }
    for (size_t k = 0; k < v.texcoord.size(); ++k) {
      if (!SameVec(v.texcoord[k], w.texcoord[k]) || !SameVec(f.texcoord[k], g.texcoord[k])) {
        return false;
      }
    }
    for (size_t k = 0; k < v.generic.size(); ++k) {
      if (!SameVec(v.generic[k], w.generic[k])) return false;
    }
  }
  return true;
}

bool SameBatches(const std::vector<InputBatch>& a, const std::vector<InputBatch>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].name != b[i].name || !SameInputs(a[i].inputs, b[i].inputs)) return false;
  }
  return true;
}

TEST(Generate, SameSeedGivesIdenticalBatches) {
  auto vp = Parse(kVertex);
  auto fp = Parse(kTextures);
  GenerateOptions options;
  options.random_vectors = 100;
  options.seed = 42;
  EXPECT_TRUE(SameBatches(GenerateInputs(vp.get(), nullptr, options),
                          GenerateInputs(vp.get(), nullptr, options)));
  EXPECT_TRUE(SameBatches(GenerateInputs(nullptr, fp.get(), options),
                          GenerateInputs(nullptr, fp.get(), options)));
  EXPECT_TRUE(SameBatches(GenerateInputs(vp.get(), fp.get(), options),
                          GenerateInputs(vp.get(), fp.get(), options)));
}

TEST(Generate, AnotherSeedGivesOtherValues) {
  auto vp = Parse(kVertex);
  GenerateOptions a;
  GenerateOptions b;
  b.seed = 2;
  std::vector<InputBatch> x = GenerateInputs(vp.get(), nullptr, a);
  std::vector<InputBatch> y = GenerateInputs(vp.get(), nullptr, b);
  ASSERT_EQ(x.size(), y.size());
  EXPECT_FALSE(SameBatches(x, y));
  // The edge vectors are the same cycle; the state and the random vectors differ.
  EXPECT_FALSE(SameMatrix(x[0].inputs.state.modelview, y[0].inputs.state.modelview));
  EXPECT_FALSE(SameVec(x[1].inputs.vectors[0].vertex.color, y[1].inputs.vectors[0].vertex.color));
}

// Values drawn with the default seed, pinned: a change of standard library, compiler or
// optimisation must not change them (no std distributions, no libm transcendentals, one
// draw per statement).
TEST(Generate, PinnedValuesAreTheSameOnEveryMachine) {
  auto vp = Parse(kVertex);
  std::vector<InputBatch> batches = GenerateInputs(vp.get(), nullptr, GenerateOptions{});
  ASSERT_EQ(batches.size(), 2u);
  const Vec4 generic = batches[1].inputs.vectors[0].vertex.generic[6];
  EXPECT_TRUE(SameVec(generic, Vec4{0x1.57f288p+1f, 0x1.b26c7p-1f, -0.0f, 0x1.f451ep-2f}));
  const Vec4 local = batches[1].inputs.vertex_params.local.at(0);
  EXPECT_TRUE(SameVec(local, Vec4{3.5f, 0x1.b4bbaap+9f, -0x1.6b5b8p+1f, 3e38f}));
  const GlState& s = batches[0].inputs.state;
  EXPECT_TRUE(SameFloat(s.modelview[0][0], -0x1.4134ep+0f));
  EXPECT_TRUE(SameFloat(s.modelview[3][2], 0x1.8e834p-4f));
  EXPECT_TRUE(SameFloat(s.projection[0][0], 0x1.70fd5ep+1f));
  EXPECT_TRUE(SameFloat(s.light[3].spot_cutoff, 0x1.51cefap+6f));
}

TEST(Generate, BatchCountsAndSizes) {
  auto vp = Parse(kVertex);
  struct Case {
    int random;
    std::vector<size_t> sizes;
  };
  const size_t edge = EdgeValues().size();
  for (const Case& c : {Case{0, {edge}}, Case{1, {edge, 1}}, Case{64, {edge, 64}},
                        Case{65, {edge, 64, 1}}, Case{200, {edge, 64, 64, 64, 8}}}) {
    GenerateOptions options;
    options.random_vectors = c.random;
    std::vector<InputBatch> batches = GenerateInputs(vp.get(), nullptr, options);
    ASSERT_EQ(batches.size(), c.sizes.size()) << c.random;
    for (size_t i = 0; i < batches.size(); ++i) {
      EXPECT_EQ(batches[i].inputs.vectors.size(), c.sizes[i]) << c.random << " batch " << i;
      EXPECT_LE(batches[i].inputs.vectors.size(), static_cast<size_t>(kFramebufferWidth));
      EXPECT_EQ(batches[i].name, i == 0 ? "edge" : "random " + std::to_string(i));
    }
  }
}

TEST(Generate, EdgeListIsDocumented) {
  const std::vector<float>& edge = EdgeValues();
  ASSERT_GE(edge.size(), 30u);
  EXPECT_TRUE(SameFloat(edge[0], 0.0f));
  EXPECT_TRUE(std::signbit(edge[1]) && edge[1] == 0.0f);
  EXPECT_TRUE(std::any_of(edge.begin(), edge.end(), [](float v) { return std::isnan(v); }));
  EXPECT_TRUE(std::any_of(edge.begin(), edge.end(), [](float v) { return std::isinf(v); }));
  EXPECT_TRUE(std::any_of(edge.begin(), edge.end(),
                          [](float v) { return v != 0.0f && std::fpclassify(v) == FP_SUBNORMAL; }));
}

// Whether `values` holds `v` (NaN matches NaN, -0 only -0).
bool Contains(const std::vector<float>& values, float v) {
  return std::any_of(values.begin(), values.end(), [v](float x) { return SameFloat(x, v); });
}

TEST(Generate, EdgeBatchCyclesThroughEveryEdgeValue) {
  auto vp = Parse(kVertex);
  std::vector<InputBatch> batches = GenerateInputs(vp.get(), nullptr, GenerateOptions{});
  const std::vector<InputVector>& vectors = batches[0].inputs.vectors;
  // Per component of attrib[6], texcoord[3] and the normal's xyz.
  for (size_t c = 0; c < 4; ++c) {
    std::vector<float> generic;
    std::vector<float> texcoord;
    std::vector<float> normal;
    for (const InputVector& v : vectors) {
      generic.push_back(v.vertex.generic[6][c]);
      texcoord.push_back(v.vertex.texcoord[3][c]);
      normal.push_back(v.vertex.normal[c]);
    }
    for (float e : EdgeValues()) {
      EXPECT_TRUE(Contains(generic, e)) << "attrib[6]." << c << " misses " << e;
      EXPECT_TRUE(Contains(texcoord, e)) << "texcoord[3]." << c << " misses " << e;
      if (c < 3) {
        EXPECT_TRUE(Contains(normal, e)) << "normal." << c << " misses " << e;
      }
    }
  }
  // Components do not move in lock step: x and y of one attribute pair up differently.
  size_t same = 0;
  for (const InputVector& v : vectors) {
    if (SameFloat(v.vertex.generic[6][0], v.vertex.generic[7][0])) ++same;
  }
  EXPECT_LT(same, vectors.size());
}

TEST(Generate, SecondaryColorAlphaAndNormalWStayOne) {
  auto vp = Parse(kVertex);
  GenerateOptions options;
  options.random_vectors = 200;
  for (const InputBatch& batch : GenerateInputs(vp.get(), nullptr, options)) {
    for (const InputVector& v : batch.inputs.vectors) {
      EXPECT_EQ(v.vertex.secondary_color[3], 1.0f);
      EXPECT_EQ(v.vertex.normal[3], 1.0f);
      EXPECT_EQ(v.vertex.fogcoord[1], 0.0f);
      EXPECT_EQ(v.vertex.weight, (Vec4{1.0f, 0.0f, 0.0f, 0.0f}));
    }
  }
}

TEST(Generate, RandomVectorsFollowTheMixture) {
  auto vp = Parse(kVertex);
  GenerateOptions options;
  options.random_vectors = 64 * 20;
  size_t total = 0;
  size_t in_range = 0;
  size_t halves = 0;
  for (const InputBatch& batch : GenerateInputs(vp.get(), nullptr, options)) {
    if (batch.name == "edge") continue;
    for (const InputVector& v : batch.inputs.vectors) {
      for (float x : v.vertex.generic[6]) {
        ++total;
        if (x >= -4.0f && x <= 4.0f) ++in_range;
        if (x >= -4.0f && x <= 4.0f && x * 2.0f == std::floor(x * 2.0f)) ++halves;
      }
    }
  }
  // ~55% uniform + ~20% halves + part of the log-scale and edge draws.
  EXPECT_GT(in_range, total * 3 / 4);
  EXPECT_LT(in_range, total);
  EXPECT_GT(halves, total * 15 / 100);
  EXPECT_LT(halves, total * 35 / 100);
}

TEST(Generate, EveryReadParameterAndRelativeArrayElementIsSet) {
  auto vp = Parse(kRelative);
  GenerateOptions options;
  options.random_vectors = 10;
  for (const InputBatch& batch : GenerateInputs(vp.get(), nullptr, options)) {
    const ProgramParameters& p = batch.inputs.vertex_params;
    for (int i = 3; i <= 7; ++i) EXPECT_EQ(p.env.count(i), 1u) << batch.name << " env " << i;
    for (int i : {11, 20}) EXPECT_EQ(p.local.count(i), 1u) << batch.name << " local " << i;
    EXPECT_TRUE(batch.inputs.fragment_params.env.empty());
    EXPECT_TRUE(batch.inputs.fragment_params.local.empty());
  }
  // The edge batch's parameters are edge values.
  std::vector<InputBatch> batches = GenerateInputs(vp.get(), nullptr, options);
  for (const auto& [index, value] : batches[0].inputs.vertex_params.env) {
    for (float x : value) EXPECT_TRUE(Contains(EdgeValues(), x)) << index;
  }
}

TEST(Generate, FragmentParametersGoToTheFragmentTarget) {
  auto fp = Parse(
      "!!ARBfp1.0\n"
      "ADD result.color, program.env[2], program.local[5];\n"
      "END\n");
  for (const InputBatch& batch : GenerateInputs(nullptr, fp.get(), GenerateOptions{})) {
    EXPECT_EQ(batch.inputs.fragment_params.env.count(2), 1u);
    EXPECT_EQ(batch.inputs.fragment_params.local.count(5), 1u);
    EXPECT_TRUE(batch.inputs.vertex_params.env.empty());
  }
}

TEST(Generate, TexturesMatchTheSampledTargets) {
  auto fp = Parse(kTextures);
  GenerateOptions options;
  options.random_vectors = 64 * 8;
  const TexDim dims[] = {TexDim::Tex1D, TexDim::Tex2D, TexDim::Tex3D, TexDim::Cube,
                         TexDim::Rect,  TexDim::Tex1D, TexDim::Tex2D, TexDim::Rect};
  for (const InputBatch& batch : GenerateInputs(nullptr, fp.get(), options)) {
    ASSERT_EQ(batch.inputs.textures.size(), 8u);
    for (const auto& [unit, t] : batch.inputs.textures) {
      SCOPED_TRACE(batch.name + " unit " + std::to_string(unit));
      ASSERT_GE(unit, 0);
      ASSERT_LT(unit, 8);
      EXPECT_EQ(t.dim, dims[unit]);
      bool shadow = unit >= 5;
      EXPECT_EQ(t.depth_texture, shadow);
      EXPECT_EQ(t.compare, shadow);
      EXPECT_NE(t.depth_mode, DepthMode::Alpha);
      if (t.dim == TexDim::Rect) {
        EXPECT_EQ(t.wrap, TexWrap::ClampToEdge);
        EXPECT_GE(t.width, 3);
        EXPECT_LE(t.width, 8);
        EXPECT_GE(t.height, 3);
        EXPECT_LE(t.height, 8);
      } else {
        EXPECT_TRUE(t.width == 4 || t.width == 8);
      }
      if (t.dim == TexDim::Tex1D) {
        EXPECT_EQ(t.height, 1);
      }
      if (t.dim == TexDim::Cube) {
        EXPECT_EQ(t.width, t.height);
        EXPECT_EQ(t.depth, 6);
      }
      if (t.dim == TexDim::Tex3D) {
        EXPECT_TRUE(t.depth == 4 || t.depth == 8);
      }
      if (t.dim != TexDim::Tex3D && t.dim != TexDim::Cube) {
        EXPECT_EQ(t.depth, 1);
      }
      ASSERT_EQ(t.texels.size(), static_cast<size_t>(t.width * t.height * t.depth * 4));
      for (float x : t.texels) {
        EXPECT_GE(x, 0.0f);
        EXPECT_LE(x, 1.0f);
      }
    }
  }
}

TEST(Generate, NonShadowProgramsNeverGetDepthTextures) {
  auto fp = Parse(
      "!!ARBfp1.0\n"
      "TEX result.color, fragment.texcoord[0], texture[2], 2D;\n"
      "END\n");
  GenerateOptions options;
  options.random_vectors = 640;
  for (const InputBatch& batch : GenerateInputs(nullptr, fp.get(), options)) {
    ASSERT_EQ(batch.inputs.textures.count(2), 1u);
    EXPECT_FALSE(batch.inputs.textures.at(2).depth_texture);
    EXPECT_FALSE(batch.inputs.textures.at(2).compare);
  }
}

// The largest singular value of m, by power iteration on m^T m (in double).
double Norm2(const glm::dmat4& m) {
  glm::dmat4 a = glm::transpose(m) * m;
  glm::dvec4 v(1.0, 0.7, 0.4, 0.2);
  double lambda = 0.0;
  for (int i = 0; i < 500; ++i) {
    glm::dvec4 w = a * v;
    lambda = std::sqrt(glm::dot(w, w));
    if (lambda == 0.0) return 0.0;
    v = w / lambda;
  }
  return std::sqrt(lambda);
}

double Condition(const glm::mat4& m) {
  glm::dmat4 d(m);
  if (glm::determinant(d) == 0.0) return std::numeric_limits<double>::infinity();
  return Norm2(d) * Norm2(glm::inverse(d));
}

TEST(Generate, StateIsWellConditionedAndWithinRanges) {
  auto vp = Parse(kVertex);
  GenerateOptions options;
  options.random_vectors = 64 * 30;
  for (const InputBatch& batch : GenerateInputs(vp.get(), nullptr, options)) {
    SCOPED_TRACE(batch.name);
    const GlState& s = batch.inputs.state;
    EXPECT_LT(Condition(s.modelview), 100.0);
    EXPECT_LT(Condition(s.projection), 100.0);
    EXPECT_LT(Condition(s.projection * s.modelview), 1000.0);
    for (const glm::mat4& m : s.texture) EXPECT_LT(Condition(m), 100.0);
    for (const glm::mat4& m : s.program) EXPECT_EQ(m, glm::mat4(1.0f));
    // Perspective only (generate_state.cpp: Mesa's stale mvp inverse after an orthographic one).
    EXPECT_EQ(s.projection[2][3], -1.0f);
    EXPECT_EQ(s.projection[3][3], 0.0f);
    for (const LightState& l : s.light) {
      EXPECT_GE(l.spot_cutoff, 0.0f);
      EXPECT_LE(l.spot_cutoff, 90.0f);
      EXPECT_GE(l.spot_exponent, 0.0f);
      EXPECT_LE(l.spot_exponent, 128.0f);
      EXPECT_TRUE(l.position[3] == 0.0f || l.position[3] == 1.0f);
      EXPECT_GE(l.constant_attenuation, 0.5f);
      for (size_t i = 0; i < 4; ++i) {
        EXPECT_GE(l.diffuse[i], 0.0f);
        EXPECT_LE(l.diffuse[i], 1.0f);
      }
    }
    for (const MaterialState& m : s.material) {
      EXPECT_GE(m.shininess, 0.0f);
      EXPECT_LE(m.shininess, 128.0f);
    }
    EXPECT_GE(s.depth_near, 0.0f);
    EXPECT_LE(s.depth_near, 0.4f);
    EXPECT_GE(s.depth_far, 0.6f);
    EXPECT_LE(s.depth_far, 1.0f);
    EXPECT_GE(s.fog_end - s.fog_start, 0.5f);
    EXPECT_LE(s.point_size_min, s.point_size_max);
  }
}

TEST(Generate, FragmentDepthStaysWithinTheDepthRange) {
  auto fp = Parse(kFragment);
  GenerateOptions options;
  options.random_vectors = 300;
  std::vector<InputBatch> batches = GenerateInputs(nullptr, fp.get(), options);
  for (const InputBatch& batch : batches) {
    const GlState& s = batch.inputs.state;
    for (const InputVector& v : batch.inputs.vectors) {
      EXPECT_GE(v.fragment.depth, s.depth_near) << batch.name;
      EXPECT_LE(v.fragment.depth, s.depth_far) << batch.name;
    }
  }
  // The edge batch takes both ends of the range.
  const ExecInputs& edge = batches[0].inputs;
  EXPECT_EQ(edge.vectors[0].fragment.depth, edge.state.depth_near);
  EXPECT_EQ(edge.vectors[1].fragment.depth, edge.state.depth_far);
  // The fragment attributes read cycle through the edge values.
  std::vector<float> secondary_alpha;
  for (const InputVector& v : edge.vectors)
    secondary_alpha.push_back(v.fragment.secondary_color[3]);
  for (float e : EdgeValues()) EXPECT_TRUE(Contains(secondary_alpha, e)) << e;
}

TEST(Generate, PairsGenerateVertexInputsOnly) {
  auto vp = Parse(kVertex);
  auto fp = Parse(kTextures);
  for (const InputBatch& batch : GenerateInputs(vp.get(), fp.get(), GenerateOptions{})) {
    EXPECT_EQ(batch.inputs.textures.size(), 8u);
    for (const InputVector& v : batch.inputs.vectors) {
      EXPECT_EQ(v.fragment.color, (Vec4{1.0f, 1.0f, 1.0f, 1.0f}));
      EXPECT_EQ(v.fragment.depth, 0.5f);
    }
  }
}

TEST(DescribeReadInputs, ListsExactlyTheBindingsRead) {
  auto vp = Parse(
      "!!ARBvp1.0\n"
      "PARAM unused = program.local[7];\n"
      "ADD result.position, vertex.attrib[1], program.local[2];\n"
      "END\n");
  ExecInputs inputs;
  inputs.vectors.resize(2);
  inputs.vectors[1].vertex.generic[1] = {1.0f, -0.0f, std::numeric_limits<float>::infinity(),
                                         std::numeric_limits<float>::quiet_NaN()};
  inputs.vertex_params.local[2] = {0.5f, 2.0f, -3.0f, 1e10f};
  std::vector<std::string> lines = DescribeReadInputs(vp.get(), nullptr, inputs, 1);
  EXPECT_EQ(lines, (std::vector<std::string>{"program.local[2] = (0.5, 2, -3, 10000000000)",
                                             "vertex.attrib[1] = (1, -0, inf, nan)"}));
}

TEST(DescribeReadInputs, ListsStateRelativeArraysAndTextures) {
  auto vp = Parse(kRelative);
  ExecInputs inputs;
  inputs.vectors.resize(1);
  std::vector<std::string> lines = DescribeReadInputs(vp.get(), nullptr, inputs, 0);
  EXPECT_EQ(lines, (std::vector<std::string>{
                       "program.env[3] = (0, 0, 0, 0)", "program.env[4] = (0, 0, 0, 0)",
                       "program.env[5] = (0, 0, 0, 0)", "program.env[6] = (0, 0, 0, 0)",
                       "program.env[7] = (0, 0, 0, 0)", "program.local[11] = (0, 0, 0, 0)",
                       "program.local[20] = (0, 0, 0, 0)", "vertex.attrib[1] = (0, 0, 0, 1)"}));

  auto mvp = Parse(
      "!!ARBvp1.0\n"
      "PARAM m[4] = { state.matrix.mvp };\n"
      "DP4 result.position.x, m[0], vertex.position;\n"
      "END\n");
  lines = DescribeReadInputs(mvp.get(), nullptr, inputs, 0);
  EXPECT_EQ(lines, (std::vector<std::string>{"state.matrix.mvp.row[0] = (1, 0, 0, 0)",
                                             "vertex.position = (0, 0, 0, 1)"}));

  auto fp = Parse(
      "!!ARBfp1.0\n"
      "TEX result.color, fragment.texcoord[1], texture[0], 2D;\n"
      "END\n");
  Texture t;
  t.width = 4;
  t.height = 4;
  t.texels.assign(64, 0.5f);
  t.filter = TexFilter::Linear;
  inputs.textures[0] = t;
  lines = DescribeReadInputs(nullptr, fp.get(), inputs, 0);
  EXPECT_EQ(lines, (std::vector<std::string>{"fragment.texcoord[1] = (0, 0, 0, 1)",
                                             "texture[0] = 2D 4x4 linear repeat"}));
}

TEST(DescribeReadInputs, PairsPrefixParametersAndSkipFragmentAttributes) {
  auto vp = Parse(
      "!!ARBvp1.0\n"
      "MOV result.position, vertex.position;\n"
      "MOV result.color, program.local[0];\n"
      "END\n");
  auto fp = Parse(
      "!!ARBfp1.0\n"
      "ADD result.color, fragment.color, program.local[0];\n"
      "END\n");
  ExecInputs inputs;
  inputs.vectors.resize(1);
  inputs.fragment_params.local[0] = {1.0f, 2.0f, 3.0f, 4.0f};
  std::vector<std::string> lines = DescribeReadInputs(vp.get(), fp.get(), inputs, 0);
  EXPECT_EQ(lines, (std::vector<std::string>{"fragment.program.local[0] = (1, 2, 3, 4)",
                                             "vertex.position = (0, 0, 0, 1)",
                                             "vertex.program.local[0] = (0, 0, 0, 0)"}));
}

TEST(DescribeReadInputs, DescribesGeneratedShadowTextures) {
  auto fp = Parse(kTextures);
  std::vector<InputBatch> batches = GenerateInputs(nullptr, fp.get(), GenerateOptions{});
  std::vector<std::string> lines = DescribeReadInputs(nullptr, fp.get(), batches[0].inputs, 3);
  size_t textures = 0;
  for (const std::string& line : lines) {
    if (line.rfind("texture[", 0) != 0) continue;
    ++textures;
    bool shadow = line.rfind("texture[5]", 0) == 0 || line.rfind("texture[6]", 0) == 0 ||
                  line.rfind("texture[7]", 0) == 0;
    EXPECT_EQ(line.find(" depth compare ") != std::string::npos, shadow) << line;
  }
  EXPECT_EQ(textures, 8u);
  EXPECT_TRUE(std::is_sorted(lines.begin(), lines.end()));
  EXPECT_TRUE(std::find(lines.begin(), lines.end(),
                        "fragment.position = (3.5, 0.5, " +
                            FormatFloat(batches[0].inputs.vectors[3].fragment.depth) + ", 1)") !=
              lines.end());
}

}  // namespace
}  // namespace arbiter::arbvp
