// LinkProgram: for each rule of linking a GLSL 1.10 program, a pair that links and a pair that
// does not, with the code and position of the diagnostic (and of its note).
#include "arbiter/glsl/link.h"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "arbiter/compiler/limits.h"

namespace arbiter::glsl {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

std::string Where(const compiler::SourceFile* file, compiler::Range range) {
  if (file == nullptr) return "-";
  compiler::LineCol lc = file->Locate(range.begin);
  return fmt::format("{}:{}:{}", file->path(), lc.line, lc.column);
}

struct Linked {
  LinkResult result;
  // "vs:line:col severity code", then " note vs:line:col" for each note.
  std::vector<std::string> diags;
  std::vector<std::string> messages;
};

Linked Link(const std::string& vs, const std::string& fs,
            const compiler::LimitProfile* profile = nullptr) {
  compiler::SourceFile vertex("vs", vs);
  compiler::SourceFile fragment("fs", fs);
  compiler::DiagnosticSink sink(0);
  LinkOptions options;
  options.profile = profile;
  Linked out{LinkProgram({&vertex}, {&fragment}, options, &sink), {}, {}};
  for (const compiler::Diagnostic& d : sink.diagnostics()) {
    std::string s =
        fmt::format("{} {} {}", Where(d.file, d.range), SeverityName(d.severity), d.info->code);
    for (const compiler::Note& n : d.notes) s += " note " + Where(n.file, n.range);
    out.diags.push_back(s);
    out.messages.push_back(d.message);
  }
  return out;
}

constexpr char kMain[] = "void main() { gl_Position = ftransform(); }\n";

// ---- Varyings (GLSL 1.10 4.3.6) ----

TEST(LinkVaryings, ReadVaryingsDeclaredAndWritten) {
  Linked l = Link(
      "varying vec2 uv;\n"
      "varying vec3 extra;  // superfluous: permitted\n"
      "void main() { uv = vec2(1.0); gl_Position = ftransform(); }\n",
      "varying vec2 uv;\n"
      "varying vec4 never_read;  // not read: the vertex shader need not declare it\n"
      "void main() { gl_FragColor = vec4(uv, 0.0, 1.0); }\n");
  EXPECT_THAT(l.diags, IsEmpty());
  EXPECT_TRUE(l.result.ok);
  EXPECT_TRUE(l.result.vertex.ok);
  EXPECT_TRUE(l.result.fragment.ok);
}

TEST(LinkVaryings, ReadButNotDeclaredByTheVertexShader) {
  Linked l = Link(kMain,
                  "varying vec3 normal;\n"
                  "void main() { gl_FragColor = vec4(normal, 1.0); }\n");
  EXPECT_THAT(l.diags, ElementsAre("fs:1:14 error glsl-link-varying-undeclared"));
  EXPECT_THAT(l.messages[0], ::testing::HasSubstr("declare 'varying vec3 normal'"));
  EXPECT_FALSE(l.result.ok);
}

TEST(LinkVaryings, ReadButNeverWritten) {
  Linked l = Link("varying vec3 normal;\n" + std::string(kMain),
                  "varying vec3 normal;\n"
                  "void main() { gl_FragColor = vec4(normal, 1.0); }\n");
  EXPECT_THAT(l.diags, ElementsAre("fs:1:14 error glsl-link-varying-unwritten note vs:1:14"));
}

TEST(LinkVaryings, WrittenOnlyInAFunctionMainCalls) {
  Linked l = Link(
      "varying vec3 normal;\n"
      "void set(out vec3 n) { n = gl_Normal; }\n"
      "void main() { set(normal); gl_Position = ftransform(); }\n",
      "varying vec3 normal;\n"
      "void main() { gl_FragColor = vec4(normal, 1.0); }\n");
  EXPECT_THAT(l.diags, IsEmpty());
}

// Reads are static: a read in a function main() never calls counts (as Mesa's linker does).
TEST(LinkVaryings, ReadInAnUncalledFunction) {
  Linked l = Link(kMain,
                  "varying vec3 normal;\n"
                  "vec3 unused() { return normal; }\n"
                  "void main() { gl_FragColor = vec4(1.0); }\n");
  EXPECT_THAT(l.diags, ElementsAre("fs:1:14 error glsl-link-varying-undeclared"));
}

TEST(LinkVaryings, TypesMustMatch) {
  Linked l = Link(
      "varying vec3 normal;\n"
      "void main() { normal = vec3(0.0); gl_Position = ftransform(); }\n",
      "varying vec4 normal;\n"
      "void main() { gl_FragColor = normal; }\n");
  EXPECT_THAT(l.diags, ElementsAre("fs:1:14 error glsl-link-varying-type note vs:1:14"));
  EXPECT_THAT(l.messages[0], ::testing::HasSubstr("'vec4' in the fragment shader but 'vec3'"));
}

TEST(LinkVaryings, ArraySizesMustMatch) {
  Linked l = Link(
      "varying float w[2];\n"
      "void main() { w[0] = 1.0; w[1] = 0.0; gl_Position = ftransform(); }\n",
      "varying float w[3];\n"
      "void main() { gl_FragColor = vec4(w[0]); }\n");
  EXPECT_THAT(l.diags, ElementsAre("fs:1:15 error glsl-link-varying-type note vs:1:15"));
  EXPECT_THAT(l.messages[0], ::testing::HasSubstr("'float[3]'"));
}

// "The type of varying variables with the same name declared in both ... must match": read
// or not.
TEST(LinkVaryings, TypesMatchEvenWhenUnread) {
  Linked l = Link("varying vec2 t;\n" + std::string(kMain),
                  "varying vec3 t;\nvoid main() { gl_FragColor = vec4(1.0); }\n");
  EXPECT_THAT(l.diags, ElementsAre("fs:1:14 error glsl-link-varying-type note vs:1:14"));
}

TEST(LinkVaryings, BuiltinVaryingsNeedNoDeclaration) {
  Linked l = Link(
      "void main() {\n"
      "  gl_FrontColor = gl_Color;\n"
      "  gl_TexCoord[0] = gl_MultiTexCoord0;\n"
      "  gl_Position = ftransform();\n"
      "}\n",
      "void main() {\n"
      "  gl_FragColor = gl_Color * gl_TexCoord[0] + gl_SecondaryColor;\n"
      "}\n");
  EXPECT_THAT(l.diags, IsEmpty());
}

// ---- gl_Position (GLSL 1.10 7.1, judged as a program) ----

TEST(LinkPosition, VertexShaderMustWriteGlPosition) {
  Linked l = Link("void main() { gl_FrontColor = gl_Color; }\n",
                  "void main() { gl_FragColor = gl_Color; }\n");
  EXPECT_THAT(l.diags, ElementsAre("vs:1:6 error glsl-position-unwritten"));
  EXPECT_FALSE(l.result.ok);
  EXPECT_THAT(Link(kMain, "void main() { gl_FragColor = gl_Color; }\n").diags, IsEmpty());
}

// ---- Uniforms and samplers (GLSL 1.10 4.3.5, GL 2.0 2.15.3) ----

TEST(LinkUniforms, SameNameSameType) {
  Linked l = Link("uniform vec4 tint;\nuniform float scale;\n" + std::string(kMain),
                  "uniform float scale;\nuniform vec4 tint;\n"
                  "void main() { gl_FragColor = tint * scale; }\n");
  EXPECT_THAT(l.diags, IsEmpty());
}

TEST(LinkUniforms, SameNameDifferentTypes) {
  Linked l = Link("uniform vec4 tint;\n" + std::string(kMain),
                  "\nuniform vec3 tint;\n"
                  "void main() { gl_FragColor = vec4(tint, 1.0); }\n");
  EXPECT_THAT(l.diags, ElementsAre("fs:2:14 error glsl-link-uniform-type note vs:1:14"));
  EXPECT_THAT(l.messages[0], ::testing::HasSubstr("'vec3' in the fragment shader but 'vec4'"));
}

TEST(LinkUniforms, ArraySizesAndUnusedUniformsCount) {
  Linked l = Link("uniform vec4 k[2];\n" + std::string(kMain),
                  "uniform vec4 k[3];\nvoid main() { gl_FragColor = vec4(1.0); }\n");
  EXPECT_THAT(l.diags, ElementsAre("fs:1:14 error glsl-link-uniform-type note vs:1:14"));
}

TEST(LinkUniforms, StructuresCompareTheirMembers) {
  Linked l = Link("struct S { vec4 a; };\nuniform S s;\n" + std::string(kMain),
                  "struct S { vec3 a; };\nuniform S s;\n"
                  "void main() { gl_FragColor = vec4(s.a, 1.0); }\n");
  EXPECT_THAT(l.diags, ElementsAre("fs:2:11 error glsl-link-uniform-type note vs:2:11"));
}

TEST(LinkSamplers, SameSamplerSameTarget) {
  Linked l = Link(
      "uniform sampler2D map;\n"
      "void main() { gl_Position = ftransform() + texture2D(map, vec2(0.0)); }\n",
      "uniform sampler2D map;\n"
      "void main() { gl_FragColor = texture2D(map, vec2(0.5)); }\n",
      compiler::BuiltinProfile("mesa"));
  EXPECT_THAT(l.diags, IsEmpty());
}

TEST(LinkSamplers, OneSamplerTwoTargets) {
  Linked l = Link("uniform sampler2D map;\n" + std::string(kMain),
                  "uniform samplerCube map;\n"
                  "void main() { gl_FragColor = textureCube(map, vec3(0.5)); }\n");
  EXPECT_THAT(l.diags, ElementsAre("fs:1:21 error glsl-link-sampler-type note vs:1:19"));
}

// ---- Resource limits (GL 2.0 2.15.3, 2.15.4, 3.11.1) ----

TEST(LinkLimits, FragmentUniformComponents) {
  // 17 vec4 = 68 components: past the minimum 64, far below Mesa's.
  std::string vs = kMain;
  std::string fs =
      "uniform vec4 a[16];\n"
      "uniform vec4 b;\n"
      "uniform int i;\n"
      "void main() { gl_FragColor = a[i] + b; }\n";
  // The default enforces Mesa's limits: past the minimum is no warning.
  EXPECT_THAT(Link(vs, fs).diags, IsEmpty());
  EXPECT_THAT(Link(vs, fs, compiler::BuiltinProfile("spec-min")).diags,
              ElementsAre("fs:2:14 error glsl-link-limit-uniforms"));
  EXPECT_THAT(Link(vs, fs, compiler::BuiltinProfile("mesa")).diags, IsEmpty());
  // 16 vec4 + the int: exactly 65 is past it too; 16 vec4 alone (64) is not.
  EXPECT_THAT(Link(vs,
                   "uniform vec4 a[16];\nuniform int i;\n"
                   "void main() { gl_FragColor = a[i]; }\n",
                   compiler::BuiltinProfile("spec-min"))
                  .diags,
              ElementsAre("fs:2:13 error glsl-link-limit-uniforms"));
  EXPECT_THAT(Link(vs, "uniform vec4 a[16];\nvoid main() { gl_FragColor = a[3] + a[15]; }\n",
                   compiler::BuiltinProfile("spec-min"))
                  .diags,
              IsEmpty());
}

TEST(LinkLimits, BuiltinUniformStateCounts) {
  // 4 light fields of 4 lights (64) and the material colour (4): 68 fragment components.
  std::string fs =
      "void main() {\n"
      "  vec4 c = gl_FrontMaterial.diffuse;\n"
      "  for (int i = 0; i < 4; ++i) c += gl_LightSource[i].diffuse;\n"
      "  gl_FragColor = c;\n"
      "}\n";
  Linked l = Link(kMain, fs, compiler::BuiltinProfile("spec-min"));
  // gl_LightSource indexed by a variable: the whole array (8 lights x 29 values).
  EXPECT_THAT(l.diags, ElementsAre("fs:3:36 error glsl-link-limit-uniforms"));
  EXPECT_THAT(l.messages[0], ::testing::HasSubstr("take 236 components"));
  EXPECT_THAT(l.messages[0], ::testing::HasSubstr("built-in uniform 'gl_LightSource'"));
}

TEST(LinkLimits, VertexUniformComponents) {
  std::string vs =
      "uniform mat4 m[32];\n"  // 512
      "uniform float one;\n"
      "uniform int i;\n"
      "void main() { gl_Position = m[i] * gl_Vertex * one; }\n";
  std::string fs = "void main() { gl_FragColor = vec4(1.0); }\n";
  EXPECT_THAT(Link(vs, fs).diags, IsEmpty());
  EXPECT_THAT(Link(vs, fs, compiler::BuiltinProfile("spec-min")).diags,
              ElementsAre("vs:2:15 error glsl-link-limit-uniforms"));
}

TEST(LinkLimits, VaryingFloatsCountEachInterpolantOnce) {
  // 7 vec4 + gl_FrontColor (the fragment shader's gl_Color) = 32: at the minimum.
  std::string vs =
      "varying vec4 v[7];\n"
      "void main() {\n"
      "  for (int i = 0; i < 7; ++i) v[i] = gl_Vertex;\n"
      "  gl_FrontColor = gl_Color;\n"
      "  gl_Position = ftransform();\n"
      "}\n";
  std::string fs =
      "varying vec4 v[7];\n"
      "void main() { gl_FragColor = v[2] + gl_Color; }\n";
  EXPECT_THAT(Link(vs, fs, compiler::BuiltinProfile("spec-min")).diags, IsEmpty());
  // One more float written by the vertex shader goes past it: counted in declaration order,
  // then the built-ins, gl_FrontColor (line 5) is the varying that goes past 32.
  std::string more = "varying float f;\n" + vs;
  more.replace(more.find("gl_FrontColor"), 0, "f = 1.0; ");
  EXPECT_THAT(Link(more, fs).diags, IsEmpty());
  EXPECT_THAT(Link(more, fs, compiler::BuiltinProfile("spec-min")).diags,
              ElementsAre("vs:5:12 error glsl-link-limit-varyings"));
}

TEST(LinkLimits, VaryingFloatsPastMesa) {
  // 33 vec4 = 132 > 128 (Mesa): an error without --limits too.
  Linked l = Link(
      "varying vec4 v[33];\n"
      "void main() { for (int i = 0; i < 33; ++i) v[i] = gl_Vertex; gl_Position = "
      "ftransform(); }\n",
      "void main() { gl_FragColor = vec4(1.0); }\n");
  EXPECT_THAT(l.diags, ElementsAre("vs:1:14 error glsl-link-limit-varyings"));
  EXPECT_THAT(l.messages[0], ::testing::HasSubstr("MAX_VARYING_FLOATS = 128 in profile 'mesa'"));
}

TEST(LinkLimits, VertexAttributes) {
  // 4 mat4 take 16 locations; gl_Vertex is the 17th.
  std::string vs =
      "attribute mat4 m0, m1, m2, m3;\n"
      "void main() { gl_Position = m0 * m1 * m2 * m3 * gl_Vertex; }\n";
  std::string fs = "void main() { gl_FragColor = vec4(1.0); }\n";
  EXPECT_THAT(Link(vs, fs).diags, ElementsAre("vs:2:49 error glsl-link-limit-attributes"));
  std::string fits =
      "attribute mat4 m0, m1, m2, m3;\n"
      "void main() { gl_Position = m0 * m1 * m2 * m3 * vec4(1.0); }\n";
  EXPECT_THAT(Link(fits, fs, compiler::BuiltinProfile("spec-min")).diags, IsEmpty());
}

TEST(LinkLimits, VertexTextureUnits) {
  // GL 2.0 requires no vertex texture units at all.
  std::string vs =
      "uniform sampler2D height;\n"
      "void main() { gl_Position = ftransform() + texture2D(height, vec2(0.0)); }\n";
  std::string fs = "void main() { gl_FragColor = vec4(1.0); }\n";
  EXPECT_THAT(Link(vs, fs).diags, IsEmpty());
  EXPECT_THAT(Link(vs, fs, compiler::BuiltinProfile("spec-min")).diags,
              ElementsAre("vs:1:19 error glsl-link-limit-samplers"));
}

TEST(LinkLimits, FragmentAndCombinedTextureUnits) {
  std::string fs =
      "uniform sampler2D a;\n"
      "uniform sampler2D b;\n"
      "uniform sampler2D unused;\n"
      "void main() { gl_FragColor = texture2D(a, vec2(0.0)) + texture2D(b, vec2(0.0)); }\n";
  EXPECT_THAT(Link(kMain, fs, compiler::BuiltinProfile("spec-min")).diags, IsEmpty());
  std::string three = "uniform sampler2D c;\n" + fs;
  three.replace(three.rfind(';'), 0, " + texture2D(c, vec2(1.0))");
  EXPECT_THAT(Link(kMain, three, compiler::BuiltinProfile("spec-min")).diags,
              ElementsAre("fs:3:19 error glsl-link-limit-samplers",
                          "fs:3:19 error glsl-link-limit-samplers"));
  EXPECT_THAT(Link(kMain, three).diags, IsEmpty());
}

TEST(LinkLimits, ProfilesWithoutGlslKeys) {
  std::string fs =
      "uniform sampler2D a, b, c;\n"
      "void main() { gl_FragColor = texture2D(a, vec2(0.0)) + texture2D(b, vec2(0.0)) + "
      "texture2D(c, vec2(0.0)); }\n";
  // A user profile (here: spec-min under another name) takes the spec minimums.
  compiler::LimitProfile custom = *compiler::BuiltinProfile("mesa");
  custom.name = "custom";
  EXPECT_THAT(Link(kMain, fs, &custom).diags,
              ElementsAre("fs:1:25 error glsl-link-limit-samplers",
                          "fs:1:25 error glsl-link-limit-samplers"));
  // A key of the profile wins.
  custom.values["glsl.max_texture_image_units"] = 3;
  custom.values["glsl.max_combined_texture_image_units"] = 3;
  EXPECT_THAT(Link(kMain, fs, &custom).diags, IsEmpty());
}

TEST(LinkLimits, TableHoldsTheSpecMinimums) {
  std::vector<std::string> rows;
  for (const GlslLimit& limit : GlslLimits()) {
    rows.push_back(fmt::format("{} {} {}", limit.key, limit.spec_min, limit.mesa));
  }
  EXPECT_THAT(rows, ElementsAre("glsl.max_vertex_uniform_components 512 16384",
                                "glsl.max_fragment_uniform_components 64 16384",
                                "glsl.max_varying_floats 32 128", "glsl.max_vertex_attribs 16 16",
                                "glsl.max_vertex_texture_image_units 0 32",
                                "glsl.max_texture_image_units 2 32",
                                "glsl.max_combined_texture_image_units 2 128"));
}

// ---- Each stage's own errors ----

TEST(LinkStages, CompileErrorsAreReportedAndStopTheProgramChecks) {
  Linked l = Link(kMain,
                  "varying vec3 n;\n"
                  "void main() { gl_FragColor = vec4(n, undefined_thing); }\n");
  EXPECT_THAT(l.diags, ElementsAre("fs:2:38 error glsl-undeclared-identifier"));
  EXPECT_FALSE(l.result.ok);
  EXPECT_FALSE(l.result.fragment.ok);
}

// A program may have one stage (GL 2.0 2.15.2: a program object with no vertex shader runs the
// fixed-function vertex stage); it still gets its stage's limits. No shader at all is no program.
TEST(LinkStages, OneStageIsAProgram) {
  compiler::SourceFile vertex("vs", kMain);
  {
    compiler::DiagnosticSink sink(0);
    EXPECT_TRUE(LinkProgram({&vertex}, {}, LinkOptions{}, &sink).ok);
  }
  compiler::SourceFile samplers("fs",
                                "uniform sampler2D s[40];\n"
                                "void main() { gl_FragColor = texture2D(s[0], vec2(0.0)); }\n");
  compiler::DiagnosticSink sink(0);
  EXPECT_FALSE(LinkProgram({}, {&samplers}, LinkOptions{}, &sink).ok);
  ASSERT_EQ(sink.error_count(), 1);
  EXPECT_EQ(sink.diagnostics()[0].info->code, "glsl-link-limit-samplers");
  compiler::DiagnosticSink none(0);
  EXPECT_FALSE(LinkProgram({}, {}, LinkOptions{}, &none).ok);
  ASSERT_EQ(none.diagnostics().size(), 1u);
  EXPECT_EQ(none.diagnostics()[0].info->code, "glsl-link-error");
}

TEST(LinkStages, SeveralStringsPerStage) {
  compiler::SourceFile common("common.glsl", "varying vec2 uv;\n");
  compiler::SourceFile vertex("main.vert",
                              "void main() { uv = vec2(0.0); gl_Position = ftransform(); }\n");
  compiler::SourceFile fragment(
      "main.frag", "varying vec3 uv;\nvoid main() { gl_FragColor = vec4(uv, 1.0); }\n");
  compiler::DiagnosticSink sink(0);
  LinkResult result = LinkProgram({&common, &vertex}, {&fragment}, LinkOptions{}, &sink);
  EXPECT_FALSE(result.ok);
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  const compiler::Diagnostic& d = sink.diagnostics()[0];
  EXPECT_EQ(Where(d.file, d.range), "main.frag:1:14");
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(Where(d.notes[0].file, d.notes[0].range), "common.glsl:1:14");
}

}  // namespace
}  // namespace arbiter::glsl
