// ReflectShader: attributes, uniforms, samplers, varyings, built-in state and resources of
// GLSL 1.10 shaders, read from the AST, with their declarations' positions.
#include "arbiter/glsl/reflect.h"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace arbiter::glsl {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

struct Reflected {
  std::unique_ptr<compiler::SourceFile> source;  // the reflection points into it
  Reflection reflection;
  std::vector<std::string> errors;  // "line:col code"
};

Reflected Reflect(Stage stage, const std::string& text) {
  Reflected out;
  out.source = std::make_unique<compiler::SourceFile>("test", text);
  compiler::DiagnosticSink sink(0);
  out.reflection = ReflectShader(stage, {out.source.get()}, &sink);
  for (const compiler::Diagnostic& d : sink.diagnostics()) {
    if (d.severity != compiler::Severity::Error) continue;
    compiler::LineCol lc = out.source->Locate(d.range.begin);
    out.errors.push_back(fmt::format("{}:{} {}", lc.line, lc.column, d.info->code));
  }
  return out;
}

// "type name[size] flags @line:col" of each variable; flags r (read), w (written).
std::vector<std::string> Vars(const std::vector<ReflectedVariable>& list) {
  std::vector<std::string> out;
  for (const ReflectedVariable& v : list) {
    std::string s = v.type + " " + v.name;
    if (v.array_size > 0) s += fmt::format("[{}]", v.array_size);
    s += fmt::format(" {}{}{}", v.read ? "r" : "", v.written ? "w" : "",
                     v.read || v.written ? "" : "-");
    if (v.file != nullptr) {
      compiler::LineCol lc = v.file->Locate(v.range.begin);
      s += fmt::format(" @{}:{}", lc.line, lc.column);
    }
    out.push_back(s);
  }
  return out;
}

std::vector<std::string> Names(const std::vector<BuiltinUse>& list) {
  std::vector<std::string> out;
  out.reserve(list.size());
  for (const BuiltinUse& b : list) out.push_back(b.name);
  return out;
}

TEST(Reflect, Attributes) {
  Reflected r = Reflect(Stage::Vertex,
                        "attribute vec4 pos;\n"
                        "attribute mat3 basis;  // 3 locations\n"
                        "attribute float unused_one, weight;\n"
                        "void main() { gl_Position = pos * weight + vec4(basis[0], 1.0); }\n");
  ASSERT_TRUE(r.reflection.ok);
  EXPECT_THAT(Vars(r.reflection.attributes),
              ElementsAre("vec4 pos r @1:16", "mat3 basis r @2:16", "float unused_one - @3:17",
                          "float weight r @3:29"));
  // pos 1, basis 3, weight 1; the unused attribute takes no location.
  EXPECT_EQ(r.reflection.resources.vertex_attribs, 5);
  EXPECT_THAT(Names(r.reflection.builtins_written), ElementsAre("gl_Position"));
}

TEST(Reflect, UniformsWithTypesAndArraySizes) {
  Reflected r = Reflect(Stage::Vertex,
                        "uniform mat4 mvp;\n"
                        "uniform vec3 lights[4];\n"
                        "uniform bool flag;\n"
                        "uniform ivec2 unused_pair;\n"
                        "struct Light { vec4 color; float k[2]; };\n"
                        "uniform Light lt;\n"
                        "void main() {\n"
                        "  gl_Position = mvp * vec4(lights[1], flag ? lt.k[0] : 1.0);\n"
                        "}\n");
  ASSERT_TRUE(r.reflection.ok);
  EXPECT_THAT(Vars(r.reflection.uniforms),
              ElementsAre("mat4 mvp r @1:14", "vec3 lights[4] r @2:14", "bool flag r @3:14",
                          "ivec2 unused_pair - @4:15",
                          "struct Light { vec4 color; float k[2]; } lt r @6:15"));
  EXPECT_EQ(r.reflection.uniforms[1].components, 12);
  EXPECT_EQ(r.reflection.uniforms[4].components, 6);
  // 16 + 12 + 1 + 6: the unused uniform does not count.
  EXPECT_EQ(r.reflection.resources.uniform_components, 35);
  EXPECT_THAT(r.reflection.samplers, IsEmpty());
}

TEST(Reflect, SamplersAndTheirLookups) {
  Reflected r = Reflect(Stage::Fragment,
                        "uniform sampler2D tex;\n"
                        "uniform samplerCube env;\n"
                        "uniform sampler2DShadow depth;\n"
                        "uniform sampler1D maps[2];\n"
                        "uniform sampler3D unused_volume;\n"
                        "void main() {\n"
                        "  vec4 c = texture2D(tex, vec2(0.5)) + texture2DProj(tex, vec3(1.0));\n"
                        "  c += textureCube(env, vec3(1.0)) + shadow2DProj(depth, vec4(1.0));\n"
                        "  c += texture1D(maps[1], 0.5, 1.0);\n"
                        "  gl_FragColor = c;\n"
                        "}\n");
  ASSERT_TRUE(r.reflection.ok);
  EXPECT_THAT(Vars(r.reflection.samplers),
              ElementsAre("sampler2D tex r @1:19", "samplerCube env r @2:21",
                          "sampler2DShadow depth r @3:25", "sampler1D maps[2] r @4:19",
                          "sampler3D unused_volume - @5:19"));
  EXPECT_THAT(r.reflection.samplers[0].lookups, ElementsAre("texture2D", "texture2DProj"));
  EXPECT_THAT(r.reflection.samplers[1].lookups, ElementsAre("textureCube"));
  EXPECT_THAT(r.reflection.samplers[2].lookups, ElementsAre("shadow2DProj"));
  EXPECT_THAT(r.reflection.samplers[3].lookups, ElementsAre("texture1D"));
  EXPECT_THAT(r.reflection.samplers[4].lookups, IsEmpty());
  EXPECT_EQ(r.reflection.resources.samplers, 5);  // tex, env, depth, maps[0..1]
  EXPECT_THAT(r.reflection.uniforms, IsEmpty());
  EXPECT_EQ(r.reflection.resources.uniform_components, 0);
}

// An unsized array takes the size its uses imply (GLSL 1.10 4.1.9).
TEST(Reflect, ImplicitlySizedArrays) {
  Reflected r = Reflect(Stage::Vertex,
                        "varying float f[];\n"
                        "void main() { f[2] = 1.0; gl_Position = ftransform(); }\n");
  ASSERT_TRUE(r.reflection.ok);
  EXPECT_THAT(Vars(r.reflection.varyings), ElementsAre("float f[3] w @1:15"));
  EXPECT_EQ(r.reflection.resources.varying_floats, 3);
}

TEST(Reflect, VertexVaryingsWrittenThroughAssignmentsAndOutParameters) {
  Reflected r = Reflect(Stage::Vertex,
                        "varying vec2 uv;\n"
                        "varying float fog[2];\n"
                        "varying vec3 normal;\n"
                        "varying vec4 never;\n"
                        "void set(out vec3 n) { n = vec3(1.0); }\n"
                        "void bump(inout float f) { f += 1.0; }\n"
                        "void main() {\n"
                        "  uv.x = 1.0;\n"
                        "  set(normal);\n"
                        "  bump(fog[1]);\n"
                        "  gl_Position = vec4(uv, 0.0, 1.0);\n"
                        "}\n");
  ASSERT_TRUE(r.reflection.ok);
  EXPECT_THAT(Vars(r.reflection.varyings),
              ElementsAre("vec2 uv rw @1:14", "float fog[2] rw @2:15", "vec3 normal w @3:14",
                          "vec4 never - @4:14"));
  EXPECT_EQ(r.reflection.resources.varying_floats, 2 + 2 + 3);
}

TEST(Reflect, FragmentVaryingsRead) {
  Reflected r = Reflect(Stage::Fragment,
                        "varying vec2 uv;\n"
                        "varying vec3 unread;\n"
                        "void main() { gl_FragColor = vec4(uv, 0.0, 1.0) + gl_Color; }\n");
  ASSERT_TRUE(r.reflection.ok);
  EXPECT_THAT(Vars(r.reflection.varyings), ElementsAre("vec2 uv r @1:14", "vec3 unread - @2:14"));
  EXPECT_EQ(r.reflection.resources.varying_floats, 2 + 4);  // gl_Color counts
  EXPECT_EQ(r.reflection.resources.vertex_attribs, 0);
}

TEST(Reflect, BuiltinStateReadAndWritten) {
  Reflected r = Reflect(Stage::Vertex,
                        "void main() {\n"
                        "  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n"
                        "  vec4 c = gl_LightSource[0].diffuse * gl_FrontMaterial.diffuse;\n"
                        "  gl_FrontColor = c + gl_LightSource[1].ambient.xxxx;\n"
                        "  gl_TexCoord[1] = gl_TextureMatrix[0] * gl_MultiTexCoord0;\n"
                        "  gl_FogFragCoord = gl_Fog.density;\n"
                        "}\n");
  ASSERT_TRUE(r.reflection.ok);
  EXPECT_THAT(Names(r.reflection.builtins_read),
              ElementsAre("gl_Fog.density", "gl_FrontMaterial.diffuse", "gl_LightSource[0].diffuse",
                          "gl_LightSource[1].ambient", "gl_ModelViewProjectionMatrix",
                          "gl_MultiTexCoord0", "gl_TextureMatrix[0]", "gl_Vertex"));
  EXPECT_THAT(Names(r.reflection.builtins_written),
              ElementsAre("gl_FogFragCoord", "gl_FrontColor", "gl_Position", "gl_TexCoord[1]"));
  // 1 + 4 + 4 + 4 + 16 + 16 uniform state values; gl_Vertex and gl_MultiTexCoord0 attributes.
  EXPECT_EQ(r.reflection.resources.uniform_components, 45);
  EXPECT_EQ(r.reflection.resources.vertex_attribs, 2);
  // gl_FrontColor, gl_TexCoord[1], gl_FogFragCoord; gl_Position is no varying.
  EXPECT_EQ(r.reflection.resources.varying_floats, 9);
  // The first access: gl_LightSource[0].diffuse on line 3, at the variable's name.
  const BuiltinUse& light = r.reflection.builtins_read[2];
  ASSERT_NE(light.file, nullptr);
  compiler::LineCol lc = light.file->Locate(light.range.begin);
  EXPECT_EQ(lc.line, 3u);
  EXPECT_EQ(lc.column, 12u);
  EXPECT_EQ(light.kind, BuiltinKind::State);
  EXPECT_EQ(r.reflection.builtins_read[5].kind, BuiltinKind::Attribute);
}

TEST(Reflect, VariableIndexCountsTheWholeArrayAtTheSpecSize) {
  Reflected r = Reflect(Stage::Vertex,
                        "uniform int n;\n"
                        "void main() { gl_Position = gl_LightSource[n].position; }\n");
  ASSERT_TRUE(r.reflection.ok);
  EXPECT_THAT(Names(r.reflection.builtins_read), ElementsAre("gl_LightSource"));
  // MAX_LIGHTS is 8 in GL 2.0; a light holds 29 values.
  EXPECT_EQ(r.reflection.resources.uniform_components, 1 + 8 * 29);
}

TEST(Reflect, FtransformReadsTheMatrixAndTheVertex) {
  Reflected r = Reflect(Stage::Vertex, "void main() { gl_Position = ftransform(); }\n");
  ASSERT_TRUE(r.reflection.ok);
  EXPECT_THAT(Names(r.reflection.builtins_read),
              ElementsAre("gl_ModelViewProjectionMatrix", "gl_Vertex"));
  EXPECT_EQ(r.reflection.resources.uniform_components, 16);
}

TEST(Reflect, FragmentOutputs) {
  Reflected r = Reflect(Stage::Fragment,
                        "void main() {\n"
                        "  gl_FragData[1] = gl_FragCoord;\n"
                        "  gl_FragDepth = gl_FrontFacing ? 0.0 : 1.0;\n"
                        "}\n");
  ASSERT_TRUE(r.reflection.ok);
  EXPECT_THAT(Names(r.reflection.builtins_read), ElementsAre("gl_FragCoord", "gl_FrontFacing"));
  EXPECT_THAT(Names(r.reflection.builtins_written), ElementsAre("gl_FragData[1]", "gl_FragDepth"));
  EXPECT_EQ(r.reflection.resources.varying_floats, 0);
}

// Uses are static (GLSL 1.10 7.2: "whether or not run-time flow of control will cause that
// statement to be executed"): an uncalled function counts; a local of the same name is not
// the global.
TEST(Reflect, UsesAreStaticUsesOfTheGlobal) {
  Reflected r = Reflect(Stage::Vertex,
                        "uniform vec4 a;\n"
                        "uniform vec4 b;\n"
                        "uniform vec4 c;\n"
                        "vec4 never_called() { return a; }\n"
                        "vec4 called() { return c; }\n"
                        "void main() { vec4 b = vec4(1.0); gl_Position = b + called(); }\n");
  ASSERT_TRUE(r.reflection.ok);
  EXPECT_THAT(Vars(r.reflection.uniforms),
              ElementsAre("vec4 a r @1:14", "vec4 b - @2:14", "vec4 c r @3:14"));
}

// Declarations are found where they are, not in comments or preprocessor lines.
TEST(Reflect, DeclarationPositionsSkipCommentsAndDirectives) {
  Reflected r = Reflect(Stage::Fragment,
                        "// uniform vec4 tint; (old)\n"
                        "#define TINT uniform vec4 tint\n"
                        "/* uniform vec4 tint;\n"
                        "   still a comment */ uniform\n"
                        "  vec4 tint;\n"
                        "void main() { gl_FragColor = tint; }\n");
  ASSERT_TRUE(r.reflection.ok);
  EXPECT_THAT(Vars(r.reflection.uniforms), ElementsAre("vec4 tint r @5:8"));
}

TEST(Reflect, SeveralStringsKeepTheirFiles) {
  compiler::SourceFile first("first.glsl", "uniform vec4 tint;\n");
  compiler::SourceFile second("second.glsl",
                              "varying vec2 uv;\nvoid main() { gl_FragColor = tint * uv.x; }\n");
  compiler::DiagnosticSink sink(0);
  Reflection r = ReflectShader(Stage::Fragment, {&first, &second}, &sink);
  ASSERT_TRUE(r.ok);
  ASSERT_EQ(r.uniforms.size(), 1u);
  EXPECT_EQ(r.uniforms[0].file, &first);
  ASSERT_EQ(r.varyings.size(), 1u);
  EXPECT_EQ(r.varyings[0].file, &second);
  EXPECT_EQ(second.Locate(r.varyings[0].range.begin).column, 14u);
}

TEST(Reflect, ShaderWithErrorsHasNoReflection) {
  Reflected r = Reflect(Stage::Fragment, "uniform vec4 t;\nvoid main() { gl_FragColor = x; }\n");
  EXPECT_FALSE(r.reflection.ok);
  EXPECT_THAT(r.errors, ::testing::Contains("2:30 glsl-undeclared-identifier"));
  EXPECT_THAT(r.reflection.uniforms, IsEmpty());
}

TEST(Reflect, StageNames) {
  EXPECT_EQ(StageName(Stage::Vertex), "vertex");
  EXPECT_EQ(StageName(Stage::Fragment), "fragment");
}

}  // namespace
}  // namespace arbiter::glsl
