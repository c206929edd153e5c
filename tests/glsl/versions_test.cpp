// GLSL 1.20 beside 1.10, compile versus link, extensions and the preprocessor options: each
// rule with a shader that must pass and one that must fail, with the code and position.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "arbiter/compiler/limits.h"
#include "arbiter/glsl/check.h"
#include "arbiter/glsl/link.h"

namespace arbiter::glsl {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

// "line:col code" of every diagnostic of the given severity.
std::vector<std::string> Keys(const compiler::DiagnosticSink& sink, compiler::Severity severity) {
  std::vector<std::string> keys;
  for (const compiler::Diagnostic& d : sink.diagnostics()) {
    if (d.severity != severity) continue;
    compiler::LineCol lc =
        d.file != nullptr ? d.file->Locate(d.range.begin) : compiler::LineCol{0, 0};
    keys.push_back(std::to_string(lc.line) + ":" + std::to_string(lc.column) + " " +
                   std::string(d.info->code));
  }
  return keys;
}

std::vector<std::string> Check(Stage stage, const std::string& text, CheckOptions options = {},
                               compiler::Severity severity = compiler::Severity::Error) {
  compiler::SourceFile source("test", text);
  compiler::DiagnosticSink sink(0);
  CheckShader(stage, {&source}, options, &sink);
  return Keys(sink, severity);
}

std::vector<std::string> Warnings(Stage stage, const std::string& text) {
  return Check(stage, text, {}, compiler::Severity::Warning);
}

CheckOptions Linked() {
  CheckOptions options;
  options.link = true;
  return options;
}

// 1.20's changes (1.2 "Changes from revision 60 of version 1.10"), each accepted under
// #version 120 and rejected under 1.10.
TEST(Version120, ChangesFrom110) {
  struct Case {
    const char* name;
    const char* declarations;
    const char* statements;
    const char* error_110;  // the first error of the shader under #version 110
  };
  const Case cases[] = {
      {"implicit int to float", "", "float x = 1; gl_Position = vec4(x);",
       "3:23 glsl-type-mismatch"},
      {"f suffix", "", "gl_Position = vec4(3.5f);", "3:37 glsl-version"},
      {"array constructor and length()", "float a[] = float[](1.0, 2.0);",
       "gl_Position = vec4(float(a.length()));", "2:1 glsl-constructor"},
      {"non-square matrix and transpose", "uniform mat2x3 m;",
       "mat3x2 t = transpose(m); gl_Position = vec4(t[0], t[1]);", "2:1 glsl-syntax-error"},
      {"outerProduct", "",
       "mat3 o = outerProduct(vec3(1.0), vec3(2.0)); gl_Position = vec4(o[0], 1.0);",
       "3:24 glsl-no-matching-function"},
      {"uniform initializer", "uniform float u = 2.0;", "gl_Position = vec4(u);",
       "2:1 glsl-qualifier"},
      {"built-in call in a const initializer", "const float c = sin(1.0);",
       "gl_Position = vec4(c);", "2:17 glsl-const-initializer-call"},
      {"whole array assignment", "", "float a[2]; float b[2]; a = b; gl_Position = vec4(a[0]);",
       "3:41 glsl-array-operand"},
  };
  for (const Case& c : cases) {
    std::string shader = std::string(c.declarations) + "\nvoid main() { " + c.statements + " }\n";
    EXPECT_THAT(Check(Stage::Vertex, "#version 120\n" + shader), IsEmpty()) << c.name;
    std::vector<std::string> errors = Check(Stage::Vertex, "#version 110\n" + shader);
    ASSERT_FALSE(errors.empty()) << c.name;
    EXPECT_EQ(errors.front(), c.error_110) << c.name;
  }
}

TEST(Version120, NewBuiltinsAndQualifiers) {
  EXPECT_THAT(Check(Stage::Fragment,
                    "#version 120\ncentroid varying vec4 c;\ninvariant gl_FragColor;\n"
                    "void main() { gl_FragColor = c + vec4(gl_PointCoord, 0.0, 1.0); }\n"),
              IsEmpty());
  EXPECT_THAT(
      Check(Stage::Fragment, "void main() { gl_FragColor = vec4(gl_PointCoord, 0.0, 1.0); }\n"),
      ::testing::Contains("1:35 glsl-undeclared-identifier"));
  // Varyings may be non-square matrices in 1.20 (4.3.6), not in 1.10.
  EXPECT_THAT(Check(Stage::Vertex,
                    "#version 120\nvarying mat2x3 v;\n"
                    "void main() { v = mat2x3(1.0); gl_Position = vec4(1.0); }\n"),
              IsEmpty());
}

// 1.20 4.1.8: "Embedded structures are not supported" (1.10 allows them).
TEST(Version120, EmbeddedStructure) {
  const std::string shader =
      "struct T { struct S { float f; } s; };\nvoid main() { gl_Position = vec4(1.0); }\n";
  EXPECT_THAT(Check(Stage::Vertex, shader), IsEmpty());
  EXPECT_THAT(Check(Stage::Vertex, "#version 120\n" + shader),
              ElementsAre("2:1 glsl-compile-error"));
}

// The ?: third operand is an assignment_expression in the 1.20 grammar, a
// conditional_expression in 1.10's.
TEST(Version120, ConditionalThirdOperand) {
  const std::string body =
      "void main() { float a = 0.0; float b; true ? a : b = 1.0; gl_Position = vec4(a); }\n";
  EXPECT_THAT(Check(Stage::Vertex, body), ElementsAre("1:52 glsl-conditional-assignment"));
  EXPECT_THAT(Check(Stage::Vertex, "#version 120\n" + body), IsEmpty());
}

// glCompileShader accepts a shader object without main() or with prototypes another object
// defines; a program (--link) needs both.
TEST(CompileVersusLink, ShaderObjects) {
  const std::string prototype =
      "vec4 shade(vec4 c);\nvoid main() { gl_FragColor = shade(gl_Color); }\n";
  EXPECT_THAT(Check(Stage::Fragment, prototype), IsEmpty());
  EXPECT_THAT(Check(Stage::Fragment, prototype, Linked()),
              ElementsAre("1:6 glsl-link-missing-function"));
  const std::string library = "vec4 shade(vec4 c) { return c * 0.5; }\n";
  EXPECT_THAT(Check(Stage::Fragment, library), IsEmpty());
  EXPECT_THAT(Check(Stage::Fragment, library, Linked()), ElementsAre("1:1 glsl-link-missing-main"));
  // Recursion is a compile error (drivers find it when compiling; glslang when linking).
  EXPECT_THAT(
      Check(Stage::Fragment,
            "float f(float x) { return f(x); }\nvoid main() { gl_FragColor = vec4(f(1.0)); }\n"),
      ElementsAre("1:7 glsl-link-recursion"));
  // A vertex shader object that never writes gl_Position: a warning when it has main(),
  // nothing when it has not, an error for a program.
  const std::string no_position = "void main() { vec4 c = gl_Color; }\n";
  EXPECT_THAT(Warnings(Stage::Vertex, no_position), ElementsAre("1:6 glsl-position-unwritten"));
  EXPECT_THAT(Warnings(Stage::Vertex, "vec4 helper() { return gl_Color; }\n"), IsEmpty());
  EXPECT_THAT(Check(Stage::Vertex, no_position, Linked()),
              ElementsAre("1:6 glsl-position-unwritten"));
}

TEST(CompileVersusLink, SeveralObjectsOfAStage) {
  compiler::SourceFile main_object(
      "main.frag", "vec4 shade(vec4 c);\nvoid main() { gl_FragColor = shade(gl_Color); }\n");
  compiler::SourceFile library("shade.frag", "vec4 shade(vec4 c) { return c * 0.5; }\n");
  compiler::SourceFile vertex("pass.vert", "void main() { gl_Position = ftransform(); }\n");
  {
    compiler::DiagnosticSink sink(0);
    EXPECT_TRUE(LinkShaders({{Stage::Fragment, {&main_object}},
                             {Stage::Fragment, {&library}},
                             {Stage::Vertex, {&vertex}}},
                            {}, &sink));
    EXPECT_THAT(Keys(sink, compiler::Severity::Error), IsEmpty());
  }
  {
    compiler::DiagnosticSink sink(0);
    EXPECT_FALSE(
        LinkShaders({{Stage::Fragment, {&main_object}}, {Stage::Vertex, {&vertex}}}, {}, &sink));
    EXPECT_THAT(Keys(sink, compiler::Severity::Error),
                ElementsAre("1:6 glsl-link-missing-function"));
  }
  {
    compiler::DiagnosticSink sink(0);
    EXPECT_FALSE(
        LinkShaders({{Stage::Fragment, {&library}}, {Stage::Fragment, {&library}}}, {}, &sink));
    EXPECT_THAT(Keys(sink, compiler::Severity::Error),
                ElementsAre("1:1 glsl-link-error", "1:1 glsl-link-missing-main"));
  }
}

// ARB_texture_rectangle: implicitly enabled where the target supports it (Mesa's profile,
// the default), a reserved word where it does not (spec-min).
TEST(Extensions, TextureRectangleImplicit) {
  const std::string shader =
      "uniform sampler2DRect s;\nvoid main() { gl_FragColor = texture2DRect(s, vec2(1.0)); }\n";
  EXPECT_THAT(Check(Stage::Fragment, shader), IsEmpty());
  EXPECT_THAT(Check(Stage::Fragment, "#version 120\n" + shader), IsEmpty());
  CheckOptions spec_min;
  spec_min.profile = compiler::BuiltinProfile("spec-min");
  EXPECT_THAT(Check(Stage::Fragment, shader, spec_min), ElementsAre("1:9 glsl-reserved-word"));
}

TEST(Extensions, Directives) {
  const std::string main = "void main() { gl_FragColor = vec4(1.0); }\n";
  // Known to arbiter and Mesa, unknown to glslang: no diagnostic.
  EXPECT_THAT(Check(Stage::Fragment, "#extension GL_ARB_draw_buffers : require\n" + main),
              IsEmpty());
  // 3.3: require of an unsupported extension is an error, enable/warn/disable a warning.
  EXPECT_THAT(Check(Stage::Fragment, "#extension GL_NV_nothing : require\n" + main),
              ElementsAre("1:12 glsl-extension-unsupported"));
  EXPECT_THAT(Check(Stage::Fragment, "#extension GL_NV_nothing : enable\n" + main), IsEmpty());
  EXPECT_THAT(Warnings(Stage::Fragment, "#extension GL_NV_nothing : warn\n" + main),
              ElementsAre("1:12 glsl-extension-unsupported"));
  CheckOptions spec_min;
  spec_min.profile = compiler::BuiltinProfile("spec-min");
  EXPECT_THAT(Check(Stage::Fragment, "#extension GL_ARB_draw_buffers : require\n" + main, spec_min),
              ElementsAre("1:12 glsl-extension-unsupported"));
  // The Lod functions of a fragment shader need GL_ARB_shader_texture_lod.
  const std::string lod =
      "uniform sampler2D s;\nvoid main() { gl_FragColor = texture2DLod(s, vec2(0.0), 1.0); }\n";
  EXPECT_THAT(Check(Stage::Fragment, lod), ElementsAre("2:30 glsl-compile-error"));
  EXPECT_THAT(Check(Stage::Fragment, "#extension GL_ARB_shader_texture_lod : require\n" + lod),
              IsEmpty());
}

TEST(Preprocessor, DefinesAndPreamble) {
  const std::string shader = "void main() { gl_FragColor = vec4(SCALE); }\n";
  EXPECT_THAT(Check(Stage::Fragment, shader), ElementsAre("1:35 glsl-undeclared-identifier"));
  CheckOptions defined;
  defined.preprocessor.defines = {"SCALE=0.5"};
  EXPECT_THAT(Check(Stage::Fragment, shader, defined), IsEmpty());
  defined.preprocessor.defines = {"SCALE=0.5", "-SCALE"};
  EXPECT_THAT(Check(Stage::Fragment, shader, defined),
              ElementsAre("1:35 glsl-undeclared-identifier"));
  // -D NAME defines it as 1, as C compilers do.
  CheckOptions flag;
  flag.preprocessor.defines = {"FAST"};
  EXPECT_THAT(Check(Stage::Fragment,
                    "#if FAST == 1\nvoid main() { gl_FragColor = vec4(1.0); }\n#endif\n", flag),
              IsEmpty());
  // The preamble comes after #version, as an application's prepended text.
  compiler::SourceFile preamble("prelude.glsl", "#define SCALE 0.25\nuniform float bias;\n");
  CheckOptions with_preamble;
  with_preamble.preprocessor.preamble = &preamble;
  EXPECT_THAT(
      Check(Stage::Fragment, "#version 120\nvoid main() { gl_FragColor = vec4(SCALE + bias); }\n",
            with_preamble),
      IsEmpty());
}

TEST(FileNames, Stages) {
  EXPECT_EQ(StageFromPath("a.vsh"), Stage::Vertex);
  EXPECT_EQ(StageFromPath("a.fsh"), Stage::Fragment);
  EXPECT_EQ(StageFromPath("dir/a.vert.glsl"), Stage::Vertex);
  EXPECT_EQ(StageFromPath("a.frag.glsl"), Stage::Fragment);
  EXPECT_EQ(StageFromPath("a.glsl"), std::nullopt);
  EXPECT_TRUE(IsGlslPath("a.glsl"));
  EXPECT_FALSE(IsGlslPath("a.vp"));
}

}  // namespace
}  // namespace arbiter::glsl
