// The modern back ends (docs/targets.md): GLSL 4.50 shaped like arbiter's Vulkan translations
// (corpus/glsl450) through SPIR-V to HLSL and MSL, every validator, and the messages of each
// failure.
#include "arbiter/targets/targets.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace arbiter::targets {

// gtest prints a message as FormatMessage writes it.
void PrintTo(const Message& message, std::ostream* out) { *out << FormatMessage(message); }

namespace {

using ::testing::AllOf;
using ::testing::Each;
using ::testing::ElementsAre;
using ::testing::Field;
using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::Not;
using Severity = Message::Severity;

constexpr uint32_t kSpirvMagic = 0x07230203;

std::string ReadCorpus(const std::string& name) {
  std::ifstream in(std::string(ARBITER_SOURCE_DIR) + "/corpus/glsl450/" + name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A message that matches severity, tool, line and text exactly.
auto IsMessage(Severity severity, const std::string& tool, int line, const std::string& text) {
  return AllOf(Field(&Message::severity, severity), Field(&Message::tool, tool),
               Field(&Message::line, line), Field(&Message::text, text));
}

std::vector<uint32_t> Compile(const std::string& file, Stage stage) {
  std::vector<uint32_t> spirv;
  std::vector<Message> messages;
  EXPECT_TRUE(CompileGlslToSpirv(ReadCorpus(file), stage, &spirv, &messages));
  EXPECT_THAT(messages, IsEmpty());
  return spirv;
}

// The messages of a GLSL 4.50 text that does not compile; the module stays empty.
std::vector<Message> CompileErrors(const std::string& glsl, Stage stage) {
  std::vector<uint32_t> spirv;
  std::vector<Message> messages;
  EXPECT_FALSE(CompileGlslToSpirv(glsl, stage, &spirv, &messages));
  EXPECT_THAT(spirv, IsEmpty());
  return messages;
}

// The messages of spirv-val on the module of `file` after `corrupt`.
template <typename Corrupt>
std::vector<Message> CorruptModuleErrors(const std::string& file, Stage stage, Corrupt corrupt) {
  std::vector<uint32_t> spirv = Compile(file, stage);
  corrupt(spirv);
  std::vector<Message> messages;
  EXPECT_FALSE(ValidateSpirv(spirv, &messages));
  return messages;
}

// --- GLSL 4.50 -> SPIR-V ---------------------------------------------------------------------

TEST(SpirvTest, CompilesTheVertexShader) {
  std::vector<uint32_t> spirv = Compile("arb_vertex.vert", Stage::Vertex);
  ASSERT_GE(spirv.size(), 5u);
  EXPECT_EQ(spirv[0], kSpirvMagic);
  EXPECT_EQ(spirv[1], 0x00010000u);  // SPIR-V 1.0, for Vulkan 1.0
  std::vector<Message> messages;
  EXPECT_TRUE(ValidateSpirv(spirv, &messages));
  EXPECT_THAT(messages, IsEmpty());
}

TEST(SpirvTest, CompilesTheFragmentShader) {
  std::vector<uint32_t> spirv = Compile("arb_fragment.frag", Stage::Fragment);
  ASSERT_GE(spirv.size(), 5u);
  EXPECT_EQ(spirv[0], kSpirvMagic);
  std::vector<Message> messages;
  EXPECT_TRUE(ValidateSpirv(spirv, &messages));
  EXPECT_THAT(messages, IsEmpty());
}

TEST(SpirvTest, BadGlslGivesItsLine) {
  std::vector<Message> messages = CompileErrors(
      "#version 450\nlayout(location = 0) in vec4 p;\nvoid main() {\n  gl_Position = q;\n}\n",
      Stage::Vertex);
  ASSERT_FALSE(messages.empty());
  EXPECT_THAT(messages[0], IsMessage(Severity::Error, "glslang", 4, "'q' : undeclared identifier"));
  EXPECT_THAT(messages, Each(Field(&Message::line, 4)));
  EXPECT_EQ(FormatMessage(messages[0]), "glslang: line 4: error: 'q' : undeclared identifier");
}

TEST(SpirvTest, VulkanRulesApply) {
  EXPECT_THAT(
      CompileErrors("#version 450\nuniform vec4 u;\nlayout(location = 0) out vec4 o;\n"
                    "void main() { o = u; }\n",
                    Stage::Fragment),
      ElementsAre(IsMessage(
          Severity::Error, "glslang", 2,
          "'non-opaque uniforms outside a block' : not allowed when using GLSL for Vulkan")));
  EXPECT_THAT(
      CompileErrors("#version 450\nin vec4 p;\nvoid main() { gl_Position = p; }\n", Stage::Vertex),
      ElementsAre(IsMessage(Severity::Error, "glslang", 2,
                            "'location' : SPIR-V requires location for user input/output")));
}

TEST(SpirvTest, TheStageMatters) {
  // texture() with a bias (TXB) exists in fragment shaders only.
  std::vector<Message> messages = CompileErrors(ReadCorpus("arb_fragment.frag"), Stage::Vertex);
  ASSERT_FALSE(messages.empty());
  EXPECT_THAT(messages[0], IsMessage(Severity::Error, "glslang", 29,
                                     "'texture' : no matching overloaded function found"));
  EXPECT_THAT(CompileErrors("#version 450\nvoid main() {\n  discard;\n}\n", Stage::Vertex),
              ElementsAre(IsMessage(Severity::Error, "glslang", 3,
                                    "'discard' : not supported in this stage: vertex")));
}

TEST(SpirvTest, OnlyVersion450) {
  EXPECT_THAT(
      CompileErrors(
          "#version 460\nlayout(location = 0) in vec4 p;\nvoid main() { gl_Position = p; }\n",
          Stage::Vertex),
      ElementsAre(IsMessage(Severity::Error, "glslang", 0,
                            "the shader is not #version 450 (its #version is 460)")));
}

TEST(SpirvTest, MissingMainIsALinkError) {
  EXPECT_THAT(
      CompileErrors("#version 450\nlayout(location = 0) out vec4 o;\nvoid f() { o = vec4(1.0); }\n",
                    Stage::Fragment),
      ElementsAre(IsMessage(Severity::Error, "glslang", 0,
                            "Linking fragment stage: Missing entry point: Each stage requires one "
                            "entry point")));
}

// glslang 12 accepts a shader that reads gl_FragDepth without writing it but leaves out the
// DepthReplacing execution mode that Vulkan requires: spirv-val catches the invalid module
// (found by fuzz_glsl450; fuzz/regressions/glsl450).
TEST(SpirvTest, GlslangsInvalidModulesAreCaught) {
  std::vector<Message> messages = CompileErrors(
      "#version 450\nlayout(location = 0) out vec4 o;\nvoid main() { o = vec4(gl_FragDepth); }\n",
      Stage::Fragment);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].tool, "spirv-val");
  EXPECT_THAT(messages[0].text,
              HasSubstr("[VUID-FragDepth-FragDepth-04216] Vulkan spec requires DepthReplacing "
                        "execution mode to be declared when using BuiltIn FragDepth."));
}

// --- spirv-val -------------------------------------------------------------------------------

TEST(ValidateSpirvTest, RejectsABadMagicNumber) {
  EXPECT_THAT(CorruptModuleErrors("arb_vertex.vert", Stage::Vertex,
                                  [](std::vector<uint32_t>& spirv) { spirv[0] = 0x12345678; }),
              ElementsAre(IsMessage(Severity::Error, "spirv-val", 0,
                                    "instruction 0: Invalid SPIR-V magic number.")));
}

TEST(ValidateSpirvTest, RejectsATruncatedModule) {
  std::vector<Message> messages =
      CorruptModuleErrors("arb_vertex.vert", Stage::Vertex,
                          [](std::vector<uint32_t>& spirv) { spirv.resize(spirv.size() - 3); });
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_THAT(messages[0].text, HasSubstr("End of input reached while decoding"));
}

// The header's ID bound (word 3) below the IDs the module uses.
void LowerIdBound(std::vector<uint32_t>& spirv) { spirv[3] = 2; }

TEST(ValidateSpirvTest, RejectsAnIdOutsideTheBound) {
  std::vector<Message> messages =
      CorruptModuleErrors("arb_fragment.frag", Stage::Fragment, LowerIdBound);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_THAT(messages[0].text, HasSubstr("must be less than the ID bound '2'"));
}

TEST(ValidateSpirvTest, RejectsAnEmptyModule) {
  std::vector<Message> messages;
  EXPECT_FALSE(ValidateSpirv({}, &messages));
  EXPECT_THAT(messages,
              ElementsAre(IsMessage(Severity::Error, "spirv-val", 0, "the module is empty")));
}

TEST(ValidateSpirvTest, CorruptModulesNeverReachSpirvCross) {
  std::vector<uint32_t> spirv = Compile("arb_fragment.frag", Stage::Fragment);
  LowerIdBound(spirv);
  std::string out = "untouched";
  std::vector<Message> messages;
  EXPECT_FALSE(SpirvToHlsl(spirv, &out, &messages));
  EXPECT_FALSE(SpirvToMsl(spirv, &out, &messages));
  EXPECT_EQ(out, "untouched");
  ASSERT_EQ(messages.size(), 2u);
  EXPECT_THAT(messages, Each(Field(&Message::tool, "spirv-val")));
  EXPECT_EQ(FormatMessage(messages[0]).rfind("spirv-val: error: instruction ", 0), 0u);
}

// --- SPIR-V -> HLSL (shader model 5.0) ---------------------------------------------------------

TEST(HlslTest, VertexShader) {
  std::string hlsl;
  std::vector<Message> messages;
  ASSERT_TRUE(SpirvToHlsl(Compile("arb_vertex.vert", Stage::Vertex), &hlsl, &messages));
  EXPECT_THAT(messages, IsEmpty());
  for (const char* line : {
           "cbuffer ArbVertexState : register(b0)",
           "    row_major float4x4 state_mvp : packoffset(c0);",
           "    float4 state_env[4] : packoffset(c10);",
           "cbuffer ArbVertexLocal : register(b13)",  // push constants
           "    float4 vertex_position : TEXCOORD0;",
           "    float4 vertex_normal : TEXCOORD2;",
           "    float4 vertex_color : TEXCOORD3;",
           "    float4 vertex_texcoord0 : TEXCOORD8;",
           "    float4 result_color : TEXCOORD0;",
           "    float4 result_texcoord0 : TEXCOORD1;",
           "    float4 gl_Position : SV_Position;",
           "SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)",
       }) {
    EXPECT_THAT(hlsl, HasSubstr(std::string(line) + "\n"));
  }
  EXPECT_TRUE(ValidateHlsl(hlsl, Stage::Vertex, &messages));
  EXPECT_THAT(messages, IsEmpty());
}

TEST(HlslTest, FragmentShader) {
  std::string hlsl;
  std::vector<Message> messages;
  ASSERT_TRUE(SpirvToHlsl(Compile("arb_fragment.frag", Stage::Fragment), &hlsl, &messages));
  EXPECT_THAT(messages, IsEmpty());
  for (const char* line : {
           "cbuffer ArbFragmentState : register(b0)",
           "Texture2D<float4> texture0 : register(t1);",
           "SamplerState _texture0_sampler : register(s1);",
           "TextureCube<float4> texture1 : register(t2);",
           "SamplerState _texture1_sampler : register(s2);",
           "Texture2D<float4> texture2 : register(t3);",
           "SamplerComparisonState _texture2_sampler : register(s3);",
           "Texture3D<float4> texture3 : register(t4);",
           "SamplerState _texture3_sampler : register(s4);",
           "    float4 fragment_color : TEXCOORD0;",
           "    float4 fragment_texcoord0 : TEXCOORD1;",  // the vertex shader's result_texcoord0
           "    float4 gl_FragCoord : SV_Position;",
           "    float4 result_color : SV_Target0;",
           "    float gl_FragDepth : SV_Depth;",
           "        discard;",
       }) {
    EXPECT_THAT(hlsl, HasSubstr(std::string(line) + "\n"));
  }
  EXPECT_THAT(hlsl, HasSubstr("texture2.SampleCmp(_texture2_sampler, "));
  EXPECT_THAT(hlsl, HasSubstr("texture3.SampleBias(_texture3_sampler, "));
  EXPECT_TRUE(ValidateHlsl(hlsl, Stage::Fragment, &messages));
  EXPECT_THAT(messages, IsEmpty());
}

TEST(HlslTest, PointSizeIsRefused) {
  std::vector<uint32_t> spirv;
  std::vector<Message> messages;
  ASSERT_TRUE(
      CompileGlslToSpirv("#version 450\nlayout(location = 0) in vec4 p;\n"
                         "void main() { gl_Position = p; gl_PointSize = p.x; }\n",
                         Stage::Vertex, &spirv, &messages));
  std::string hlsl;
  EXPECT_FALSE(SpirvToHlsl(spirv, &hlsl, &messages));
  EXPECT_THAT(messages, ElementsAre(IsMessage(
                            Severity::Error, "spirv-cross", 0,
                            "Unsupported builtin in HLSL: 1 (PointSize: Direct3D 11 has none)")));
  messages.clear();
  std::string msl;
  EXPECT_TRUE(SpirvToMsl(spirv, &msl, &messages));
  EXPECT_THAT(msl, HasSubstr("float gl_PointSize [[point_size]];"));
}

// Push constants have the std430 layout: an array of vec2 has a stride of 8 bytes, which no
// HLSL constant buffer has (found by fuzz_glsl450). MSL takes it.
TEST(HlslTest, Std430ArraysAreRefused) {
  std::vector<uint32_t> spirv;
  std::vector<Message> messages;
  ASSERT_TRUE(CompileGlslToSpirv(
      "#version 450\nlayout(push_constant) uniform Local { vec2 local[2]; } local;\n"
      "layout(location = 0) in vec4 p;\n"
      "void main() { gl_Position = p + local.local[1].xyxy; }\n",
      Stage::Vertex, &spirv, &messages));
  std::string hlsl;
  EXPECT_FALSE(SpirvToHlsl(spirv, &hlsl, &messages));
  EXPECT_THAT(messages,
              ElementsAre(IsMessage(Severity::Error, "spirv-cross", 0,
                                    "cbuffer ID 24 (name: Local), member index 0 (name: local) "
                                    "cannot be expressed with either HLSL packing layout or "
                                    "packoffset.")));
  messages.clear();
  std::string msl;
  EXPECT_TRUE(SpirvToMsl(spirv, &msl, &messages));
  EXPECT_THAT(msl, HasSubstr("float2 local[2];"));
}

TEST(ValidateHlslTest, BadHlslGivesItsLine) {
  std::vector<Message> messages;
  EXPECT_FALSE(ValidateHlsl("float4 main(float4 p : POSITION) : SV_Position {\n  return p +\n}\n",
                            Stage::Vertex, &messages));
  ASSERT_FALSE(messages.empty());
  EXPECT_THAT(messages[0], IsMessage(Severity::Error, "glslang", 3, "'expression' : Expected"));
}

TEST(ValidateHlslTest, TheEntryPointIsMain) {
  std::vector<Message> messages;
  EXPECT_FALSE(ValidateHlsl("float4 f(float4 p : POSITION) : SV_Position { return p; }\n",
                            Stage::Vertex, &messages));
  EXPECT_THAT(messages.back(), IsMessage(Severity::Error, "glslang", 0, "no entry point main"));
  messages.clear();
  EXPECT_FALSE(ValidateHlsl("", Stage::Fragment, &messages));
  EXPECT_THAT(messages.back(), IsMessage(Severity::Error, "glslang", 0, "no entry point main"));
}

// --- SPIR-V -> MSL 2.0 (macOS) -------------------------------------------------------------------

TEST(MslTest, VertexShader) {
  std::string msl;
  std::vector<Message> messages;
  ASSERT_TRUE(SpirvToMsl(Compile("arb_vertex.vert", Stage::Vertex), &msl, &messages));
  EXPECT_THAT(messages, IsEmpty());
  for (const char* line : {
           "#include <metal_stdlib>",
           "    float4 vertex_position [[attribute(0)]];",
           "    float4 vertex_normal [[attribute(2)]];",
           "    float4 vertex_texcoord0 [[attribute(8)]];",
           "    float4 result_color [[user(locn0)]];",
           "    float4 result_texcoord0 [[user(locn1)]];",
           "    float4 gl_Position [[position]];",
       }) {
    EXPECT_THAT(msl, HasSubstr(std::string(line) + "\n"));
  }
  // The uniform block at its binding, the push constants at buffer 30.
  EXPECT_THAT(msl, HasSubstr("vertex main0_out main0(main0_in in [[stage_in]], constant "
                             "ArbVertexState& state [[buffer(0)]], constant ArbVertexLocal& "
                             "local [[buffer(30)]])\n"));
}

TEST(MslTest, FragmentShader) {
  std::string msl;
  std::vector<Message> messages;
  ASSERT_TRUE(SpirvToMsl(Compile("arb_fragment.frag", Stage::Fragment), &msl, &messages));
  EXPECT_THAT(messages, IsEmpty());
  for (const char* line : {
           "    float4 fragment_color [[user(locn0)]];",
           "    float4 fragment_texcoord0 [[user(locn1)]];",
           "    float4 result_color [[color(0)]];",
           "    float gl_FragDepth [[depth(any)]];",
           "        discard_fragment();",
       }) {
    EXPECT_THAT(msl, HasSubstr(std::string(line) + "\n"));
  }
  for (const char* parameter : {
           "constant ArbFragmentState& state [[buffer(0)]]",
           "texture2d<float> texture0 [[texture(1)]]",
           "texturecube<float> texture1 [[texture(2)]]",
           "depth2d<float> texture2 [[texture(3)]]",
           "texture3d<float> texture3 [[texture(4)]]",
           "sampler texture0Smplr [[sampler(1)]]",
           "sampler texture2Smplr [[sampler(3)]]",
           "float4 gl_FragCoord [[position]]",
       }) {
    EXPECT_THAT(msl, HasSubstr(parameter));
  }
  EXPECT_THAT(msl, HasSubstr("texture2.sample_compare(texture2Smplr, "));
}

// --- the whole pipeline on every shader of corpus/glsl450 ---------------------------------------

class CorpusTest : public ::testing::TestWithParam<std::string> {};

TEST_P(CorpusTest, EveryTargetWithoutAMessage) {
  Stage stage = GetParam().ends_with(".vert") ? Stage::Vertex : Stage::Fragment;
  std::string glsl = ReadCorpus(GetParam());
  std::vector<Message> messages;
  EXPECT_TRUE(ValidateGlsl(glsl, stage, GlslDialect::Vulkan450, &messages));
  std::vector<uint32_t> spirv;
  ASSERT_TRUE(CompileGlslToSpirv(glsl, stage, &spirv, &messages));
  EXPECT_TRUE(ValidateSpirv(spirv, &messages));
  std::string hlsl;
  ASSERT_TRUE(SpirvToHlsl(spirv, &hlsl, &messages));
  EXPECT_TRUE(ValidateHlsl(hlsl, stage, &messages));
  std::string msl;
  EXPECT_TRUE(SpirvToMsl(spirv, &msl, &messages));
  EXPECT_THAT(messages, IsEmpty());
}

// The files, listed by hand: a new one is a new test case, named here.
INSTANTIATE_TEST_SUITE_P(Glsl450, CorpusTest,
                         ::testing::Values("arb_vertex.vert", "arb_fragment.frag",
                                           "arb_vertex_indexed.vert", "arb_fragment_outputs.frag"),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           std::string name = param.param;
                           for (char& c : name) {
                             if (c == '.') c = '_';
                           }
                           return name;
                         });

TEST(CorpusTest, ArraysClipDistancesAndFacing) {
  std::string hlsl;
  std::string msl;
  std::vector<Message> messages;
  std::vector<uint32_t> vertex = Compile("arb_vertex_indexed.vert", Stage::Vertex);
  ASSERT_TRUE(SpirvToHlsl(vertex, &hlsl, &messages));
  ASSERT_TRUE(SpirvToMsl(vertex, &msl, &messages));
  // An array of varyings takes consecutive locations: one HLSL semantic, MSL one per element.
  EXPECT_THAT(hlsl, HasSubstr("    float4 result_texcoord[2] : TEXCOORD3;\n"));
  EXPECT_THAT(hlsl, HasSubstr("    float gl_ClipDistance0 : SV_ClipDistance0;\n"));
  EXPECT_THAT(msl, HasSubstr("    float4 result_texcoord_0 [[user(locn3)]];\n"
                             "    float4 result_texcoord_1 [[user(locn4)]];\n"));
  EXPECT_THAT(msl, HasSubstr("    float gl_ClipDistance [[clip_distance]] [1];\n"));
  std::vector<uint32_t> fragment = Compile("arb_fragment_outputs.frag", Stage::Fragment);
  ASSERT_TRUE(SpirvToHlsl(fragment, &hlsl, &messages));
  ASSERT_TRUE(SpirvToMsl(fragment, &msl, &messages));
  EXPECT_THAT(hlsl, HasSubstr("Texture1D<float4> texture0 : register(t1);\n"));
  EXPECT_THAT(hlsl, HasSubstr("    bool gl_FrontFacing : SV_IsFrontFace;\n"));
  EXPECT_THAT(hlsl, HasSubstr("    float4 result_color1 : SV_Target1;\n"));
  EXPECT_THAT(msl, HasSubstr("    float4 result_color1 [[color(1)]];\n"));
  EXPECT_THAT(msl, HasSubstr("bool gl_FrontFacing [[front_facing]]"));
  EXPECT_THAT(messages, IsEmpty());
}

// --- GLSL of every dialect -------------------------------------------------------------------

struct DialectCase {
  const char* name;
  GlslDialect dialect;
  Stage stage;
  const char* text;
};

class GlslDialectTest : public ::testing::TestWithParam<DialectCase> {};

TEST_P(GlslDialectTest, Accepted) {
  std::vector<Message> messages;
  EXPECT_TRUE(ValidateGlsl(GetParam().text, GetParam().stage, GetParam().dialect, &messages));
  EXPECT_THAT(messages, IsEmpty());
}

INSTANTIATE_TEST_SUITE_P(
    Dialects, GlslDialectTest,
    ::testing::Values(
        DialectCase{"glsl110", GlslDialect::Glsl110, Stage::Vertex,
                    "void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }\n"},
        DialectCase{
            "glsl120", GlslDialect::Glsl120, Stage::Fragment,
            "#version 120\nvoid main() { gl_FragColor = vec4(gl_PointCoord, 0.0, 1.0); }\n"},
        DialectCase{"glsl330", GlslDialect::Glsl330Core, Stage::Vertex,
                    "#version 330 core\nlayout(location = 0) in vec4 p;\nuniform mat4 mvp;\n"
                    "void main() { gl_Position = mvp * p; }\n"},
        DialectCase{"es100", GlslDialect::Es100, Stage::Fragment,
                    "#version 100\nprecision mediump float;\nvarying vec4 c;\n"
                    "void main() { gl_FragColor = c; }\n"},
        DialectCase{"es300", GlslDialect::Es300, Stage::Fragment,
                    "#version 300 es\nprecision mediump float;\nin vec4 c;\nout vec4 o;\n"
                    "void main() { o = c; }\n"},
        DialectCase{"vulkan450", GlslDialect::Vulkan450, Stage::Fragment,
                    "#version 450\nlayout(set = 0, binding = 1) uniform sampler2D t;\n"
                    "layout(location = 0) in vec2 uv;\nlayout(location = 0) out vec4 o;\n"
                    "void main() { o = texture(t, uv); }\n"}),
    [](const ::testing::TestParamInfo<DialectCase>& param) { return param.param.name; });

TEST(ValidateGlslTest, TheVersionMustBeTheDialects) {
  std::vector<Message> messages;
  EXPECT_FALSE(ValidateGlsl("void main() { gl_Position = gl_Vertex; }\n", Stage::Vertex,
                            GlslDialect::Glsl120, &messages));
  EXPECT_THAT(messages, ElementsAre(IsMessage(Severity::Error, "glslang", 0,
                                              "the shader is not #version 120 (its #version is "
                                              "110)")));
  messages.clear();
  EXPECT_FALSE(ValidateGlsl("#version 300 es\nin vec4 p;\nvoid main() { gl_Position = p; }\n",
                            Stage::Vertex, GlslDialect::Glsl330Core, &messages));
  EXPECT_THAT(messages, ElementsAre(IsMessage(Severity::Error, "glslang", 0,
                                              "the shader is not #version 330 core (its "
                                              "#version is 300 es)")));
  messages.clear();
  EXPECT_FALSE(ValidateGlsl(ReadCorpus("arb_vertex.vert"), Stage::Vertex, GlslDialect::Glsl330Core,
                            &messages));
  EXPECT_THAT(messages, Not(IsEmpty()));
}

TEST(ValidateGlslTest, CoreProfileHasNoBuiltInState) {
  std::vector<Message> messages;
  EXPECT_FALSE(
      ValidateGlsl("#version 330 core\nin vec4 p;\nvoid main() {\n  gl_Position = "
                   "gl_ModelViewProjectionMatrix * "
                   "p;\n}\n",
                   Stage::Vertex, GlslDialect::Glsl330Core, &messages));
  EXPECT_THAT(messages, ElementsAre(IsMessage(Severity::Error, "glslang", 4,
                                              "'gl_ModelViewProjectionMatrix' : undeclared "
                                              "identifier")));
}

TEST(ValidateGlslTest, Es100FragmentShadersNeedAFloatPrecision) {
  std::vector<Message> messages;
  EXPECT_FALSE(ValidateGlsl("#version 100\nvarying vec4 c;\nvoid main() { gl_FragColor = c; }\n",
                            Stage::Fragment, GlslDialect::Es100, &messages));
  EXPECT_THAT(messages, ElementsAre(IsMessage(Severity::Error, "glslang", 2,
                                              "'float' : type requires declaration of default "
                                              "precision qualifier")));
}

}  // namespace
}  // namespace arbiter::targets
