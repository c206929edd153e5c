// The execution model from flags and JSON (exec_io.h), and results to JSON and back.
#include "arbiter/arbvp/exec_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace arbiter::arbvp {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

struct Assigned {
  ExecInputs inputs;
  InputVector vector;
  std::string error;
  bool Set(std::string_view a) { return ApplyAssignment(a, &inputs, &vector, &error); }
};

TEST(ExecAssignment, SetsGenericAttributesAndAliasesAttributeZeroToPosition) {
  Assigned a;
  ASSERT_TRUE(a.Set("vertex.attrib[1]=1,2,3,4")) << a.error;
  EXPECT_EQ(a.vector.vertex.generic[1], (Vec4{1, 2, 3, 4}));
  ASSERT_TRUE(a.Set("vertex.attrib[0]=5,6,7,8")) << a.error;
  EXPECT_EQ(a.vector.vertex.position, (Vec4{5, 6, 7, 8}));
}

TEST(ExecAssignment, FillsMissingComponentsWithZeroZeroZeroOne) {
  Assigned a;
  ASSERT_TRUE(a.Set("vertex.texcoord[2]=5")) << a.error;
  EXPECT_EQ(a.vector.vertex.texcoord[2], (Vec4{5, 0, 0, 1}));
  ASSERT_TRUE(a.Set("fragment.texcoord[1] = 0.5, 0.25")) << a.error;
  EXPECT_EQ(a.vector.fragment.texcoord[1], (Vec4{0.5f, 0.25f, 0, 1}));
}

TEST(ExecAssignment, ReadsSpecialValues) {
  Assigned a;
  ASSERT_TRUE(a.Set("vertex.color=inf,-inf,nan,-0")) << a.error;
  EXPECT_EQ(a.vector.vertex.color[0], kInf);
  EXPECT_EQ(a.vector.vertex.color[1], -kInf);
  EXPECT_TRUE(std::isnan(a.vector.vertex.color[2]));
  EXPECT_TRUE(std::signbit(a.vector.vertex.color[3]));
  ASSERT_TRUE(a.Set("vertex.normal=1e-45,+2")) << a.error;  // a denormal, and a '+'
  EXPECT_EQ(a.vector.vertex.normal[0], std::numeric_limits<float>::denorm_min());
  EXPECT_EQ(a.vector.vertex.normal[1], 2.0f);
}

TEST(ExecAssignment, ProgramParametersGoToBothTargetsUnlessOneIsNamed) {
  Assigned a;
  ASSERT_TRUE(a.Set("program.local[3]=1,2")) << a.error;
  EXPECT_EQ(a.inputs.vertex_params.local.at(3), (Vec4{1, 2, 0, 1}));
  EXPECT_EQ(a.inputs.fragment_params.local.at(3), (Vec4{1, 2, 0, 1}));
  ASSERT_TRUE(a.Set("fragment.program.env[7]=9,9,9,9")) << a.error;
  EXPECT_EQ(a.inputs.fragment_params.env.at(7), (Vec4{9, 9, 9, 9}));
  EXPECT_EQ(a.inputs.vertex_params.env.count(7), 0u);
}

TEST(ExecAssignment, MatricesAreGivenRowMajorAsArbReadsThem) {
  Assigned a;
  ASSERT_TRUE(a.Set("state.matrix.modelview=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16")) << a.error;
  // Row 0 is (1,2,3,4); glm stores m[column][row].
  EXPECT_EQ(a.inputs.state.modelview[0][0], 1.0f);
  EXPECT_EQ(a.inputs.state.modelview[1][0], 2.0f);
  EXPECT_EQ(a.inputs.state.modelview[0][1], 5.0f);
  EXPECT_EQ(a.inputs.state.modelview[3][2], 12.0f);
  ASSERT_TRUE(a.Set("state.matrix.program[2]=0,0,0,1,0,0,1,0,0,1,0,0,1,0,0,0")) << a.error;
  EXPECT_EQ(a.inputs.state.program[2][3][0], 1.0f);
}

TEST(ExecAssignment, SetsStateFieldsByTheirArbNames) {
  Assigned a;
  ASSERT_TRUE(a.Set("state.light[1].attenuation=1,2,3")) << a.error;
  EXPECT_EQ(a.inputs.state.light[1].constant_attenuation, 1.0f);
  EXPECT_EQ(a.inputs.state.light[1].linear_attenuation, 2.0f);
  EXPECT_EQ(a.inputs.state.light[1].quadratic_attenuation, 3.0f);
  ASSERT_TRUE(a.Set("state.depth.range=0.25,0.75")) << a.error;
  EXPECT_EQ(a.inputs.state.depth_near, 0.25f);
  EXPECT_EQ(a.inputs.state.depth_far, 0.75f);
  ASSERT_TRUE(a.Set("state.material.back.shininess=12")) << a.error;
  EXPECT_EQ(a.inputs.state.material[1].shininess, 12.0f);
  ASSERT_TRUE(a.Set("state.texgen[3].eye.q=1,2,3,4")) << a.error;
  EXPECT_EQ(a.inputs.state.texgen[3].eye[3], (Vec4{1, 2, 3, 4}));
  ASSERT_TRUE(a.Set("state.light[0].spot.direction=0,1,0")) << a.error;
  EXPECT_EQ(a.inputs.state.light[0].spot_direction, (std::array<float, 3>{0, 1, 0}));
}

TEST(ExecAssignment, RejectsWhatItCannotSetWithAReason) {
  struct Case {
    const char* text;
    const char* error;
  };
  const Case cases[] = {
      {"vertex.attrib[1]", "is not NAME=VALUES"},
      {"vertex.bogus=1", "'vertex.bogus' names nothing that can be set"},
      {"vertex.attrib[16]=1", "index 16 of 'vertex.attrib[16]' is out of range [0, 16)"},
      {"state.light[8].diffuse=1", "out of range [0, 8)"},
      {"vertex.color=1,2,3,4,5", "takes 1 to 4 numbers, not 5"},
      {"state.matrix.projection=1,2,3", "takes 16 numbers, not 3"},
      {"state.fog.density=1,2", "takes 1 numbers, not 2"},
      {"vertex.color=1,x", "'x' is not a number"},
      {"vertex.attrib[a]=1", "bad index"},
      {"program.env[256]=1", "out of range [0, 256)"},
  };
  for (const Case& c : cases) {
    Assigned a;
    EXPECT_FALSE(a.Set(c.text)) << c.text;
    EXPECT_NE(a.error.find(c.error), std::string::npos) << c.text << ": " << a.error;
  }
}

TEST(ExecTexture, MakesPatternTexturesFromTheFlag) {
  ExecInputs inputs;
  std::string error;
  ASSERT_TRUE(ApplyTextureFlag("1=2d:checker:2x2:linear:clamp", &inputs, &error)) << error;
  const Texture& t = inputs.textures.at(1);
  EXPECT_EQ(t.dim, TexDim::Tex2D);
  EXPECT_EQ(t.filter, TexFilter::Linear);
  EXPECT_EQ(t.wrap, TexWrap::ClampToEdge);
  // (x + y) even: white; odd: opaque black.
  EXPECT_EQ(t.texels, (std::vector<float>{1, 1, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1, 1}));
  ASSERT_TRUE(ApplyTextureFlag("0=cube:gradient:2x2", &inputs, &error)) << error;
  const Texture& cube = inputs.textures.at(0);
  ASSERT_EQ(cube.texels.size(), 2u * 2u * 6u * 4u);
  // Face 5 (-Z), texel (1,0): s centre 0.75, t centre 0.25, b = (5 + 0.5) / 6.
  size_t at = ((5 * 2 + 0) * 2 + 1) * 4;
  EXPECT_EQ(cube.texels[at], 0.75f);
  EXPECT_EQ(cube.texels[at + 1], 0.25f);
  EXPECT_FLOAT_EQ(cube.texels[at + 2], 5.5f / 6.0f);
  ASSERT_TRUE(ApplyTextureFlag("2=rect:depth-gradient-compare:4x1", &inputs, &error)) << error;
  EXPECT_TRUE(inputs.textures.at(2).depth_texture);
  EXPECT_TRUE(inputs.textures.at(2).compare);
  EXPECT_EQ(inputs.textures.at(2).wrap, TexWrap::ClampToEdge);  // RECT allows no other
}

TEST(ExecTexture, RejectsBadFlags) {
  ExecInputs inputs;
  std::string error;
  // Image units past the eight coordinate sets are valid up to 31 (exec.h).
  EXPECT_TRUE(ApplyTextureFlag("8=2d:checker", &inputs, &error)) << error;
  EXPECT_TRUE(ApplyTextureFlag("31=2d:checker", &inputs, &error)) << error;
  EXPECT_FALSE(ApplyTextureFlag("32=2d:checker", &inputs, &error));
  EXPECT_FALSE(ApplyTextureFlag("0=4d:checker", &inputs, &error));
  EXPECT_FALSE(ApplyTextureFlag("0=2d:plaid", &inputs, &error));
  EXPECT_NE(error.find("unknown pattern 'plaid'"), std::string::npos) << error;
  EXPECT_FALSE(ApplyTextureFlag("0=2d:checker:huge", &inputs, &error));
  EXPECT_FALSE(ApplyTextureFlag("0=cube:checker:2x4", &inputs, &error));
  EXPECT_NE(error.find("square"), std::string::npos) << error;
}

TEST(ExecVectorsJson, ReadsSharedSettingsTexturesAndVectors) {
  ExecInputs inputs;
  std::string error;
  ASSERT_TRUE(ParseVectorsJson(R"({
      "set": {"program.local[0]": [1, 2, 3, 4], "vertex.color": [0.5], "state.fog.density": 2},
      "textures": {"3": {"target": "1d", "size": [2], "texels": [0,0,0,1, 1,"inf",0,1],
                         "filter": "linear", "wrap": "mirror"}},
      "vectors": [{"vertex.attrib[1]": [1, "nan"]}, {"vertex.color": [0, 0, 1]}]})",
                               &inputs, &error))
      << error;
  EXPECT_EQ(inputs.vertex_params.local.at(0), (Vec4{1, 2, 3, 4}));
  EXPECT_EQ(inputs.state.fog_density, 2.0f);
  ASSERT_EQ(inputs.vectors.size(), 2u);
  EXPECT_EQ(inputs.vectors[0].vertex.color, (Vec4{0.5f, 0, 0, 1}));  // from "set"
  EXPECT_TRUE(std::isnan(inputs.vectors[0].vertex.generic[1][1]));
  EXPECT_EQ(inputs.vectors[1].vertex.color, (Vec4{0, 0, 1, 1}));  // its own
  const Texture& t = inputs.textures.at(3);
  EXPECT_EQ(t.dim, TexDim::Tex1D);
  EXPECT_EQ(t.texels[5], kInf);
  EXPECT_EQ(t.wrap, TexWrap::MirroredRepeat);
}

TEST(ExecVectorsJson, RejectsMalformedFilesWithAReason) {
  struct Case {
    const char* json;
    const char* error;
  };
  const Case cases[] = {
      {"[1]", "not a JSON object"},
      {"{\"vector\": []}", "unknown key 'vector'"},
      {"{\"vectors\": [{\"vertex.color\": \"red\"}]}", "vectors[0]"},
      {"{\"textures\": {\"0\": {\"target\": \"2d\", \"size\": [2, 2], \"texels\": [1]}}}",
       "needs 16"},
      // Image units are 0 to 31 (Mesa's MAX_TEXTURE_IMAGE_UNITS_ARB), not the 8 coordinate sets.
      {"{\"textures\": {\"32\": {\"pattern\": \"checker\"}}}", "no texture unit in [0, 32)"},
      {"{\"textures\": {\"0\": {}}}", "needs a pattern or texels"},
  };
  for (const Case& c : cases) {
    ExecInputs inputs;
    std::string error;
    EXPECT_FALSE(ParseVectorsJson(c.json, &inputs, &error)) << c.json;
    EXPECT_NE(error.find(c.error), std::string::npos) << c.json << ": " << error;
  }
}

VectorResult OneOutput(Vec4 value, uint8_t written) {
  VectorResult r;
  OutputRegister o;
  o.binding.kind = BindingKind::Result;
  o.binding.result = ResultReg::Color;
  o.binding.face = Face::Back;
  o.binding.secondary = true;
  o.name = "result.color.back.secondary";
  o.value = value;
  o.written = written;
  r.outputs.push_back(o);
  return r;
}

TEST(ExecResultsJson, RoundTripsSpecialValuesAndBindings) {
  std::vector<VectorResult> results{OneOutput({-0.0f, kInf, std::nanf(""), 0.1f}, 0xF)};
  results[0].outputs[0].undefined[2] = "LG2 of a non-positive value at 3:1";
  nlohmann::ordered_json j = ResultsToJson(results, /*with_bindings=*/true);
  EXPECT_EQ(j[0]["outputs"][0]["value"].dump(), "[-0.0,\"inf\",\"nan\",0.1]");
  EXPECT_EQ(j[0]["outputs"][0]["written"], "xyzw");
  std::vector<VectorResult> back;
  std::string error;
  ASSERT_TRUE(ResultsFromJson(nlohmann::json::parse(j.dump()), &back, &error)) << error;
  ASSERT_EQ(back.size(), 1u);
  const OutputRegister& o = back[0].outputs[0];
  EXPECT_TRUE(SameFloat(o.value[0], -0.0f));
  EXPECT_EQ(o.value[1], kInf);
  EXPECT_TRUE(std::isnan(o.value[2]));
  EXPECT_EQ(o.value[3], 0.1f);
  EXPECT_EQ(o.undefined[2], "LG2 of a non-positive value at 3:1");
  EXPECT_EQ(o.binding.result, ResultReg::Color);
  EXPECT_EQ(o.binding.face, Face::Back);
  EXPECT_TRUE(o.binding.secondary);
  EXPECT_FALSE(ResultsFromJson(nlohmann::json::parse("[{\"killed\": 1}]"), &back, &error));
}

TEST(ExecCompare, ComparesDefinedWrittenComponentsExactly) {
  std::vector<VectorResult> a{OneOutput({1, 2, 3, 4}, 0x7)};
  std::vector<VectorResult> b{OneOutput({1, 2.0000002f, 3, 99}, 0x7)};
  std::vector<Difference> d = CompareResults(a, b);
  ASSERT_EQ(d.size(), 1u);  // w is not written; y differs by one ulp
  EXPECT_EQ(d[0].component, 1);
  a[0].outputs[0].undefined[1] = "undefined";
  EXPECT_TRUE(CompareResults(a, b).empty());
  // -0 and +0 differ; NaN equals NaN.
  std::vector<VectorResult> z1{OneOutput({-0.0f, std::nanf(""), 0, 0}, 0x3)};
  std::vector<VectorResult> z2{OneOutput({0.0f, std::nanf(""), 0, 0}, 0x3)};
  ASSERT_EQ(CompareResults(z1, z2).size(), 1u);
  VectorResult killed;
  killed.killed = true;
  std::vector<VectorResult> k{killed};
  ASSERT_EQ(CompareResults(a, k).size(), 1u);
  EXPECT_EQ(CompareResults(a, k)[0].what, "killed by b only");
}

TEST(ExecFormat, PrintsTheShortestRoundTrippingText) {
  EXPECT_EQ(FormatFloat(1.0f), "1");
  EXPECT_EQ(FormatFloat(-0.0f), "-0");
  EXPECT_EQ(FormatFloat(0.1f), "0.1");
  EXPECT_EQ(FormatFloat(-kInf), "-inf");
  EXPECT_EQ(FormatFloat(-std::nanf("")), "nan");
}

}  // namespace
}  // namespace arbiter::arbvp
