// The GLSL 1.10 strictness layer: for each rule where glslang 12 follows a later version,
// a shader that must pass and one that must fail, with the code and position.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "arbiter/glsl/check.h"

namespace arbiter::glsl {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

// "line:col code" of every diagnostic of the given severity.
std::vector<std::string> Check(Stage stage, const std::string& text,
                               compiler::Severity severity = compiler::Severity::Error,
                               CheckOptions options = {}) {
  compiler::SourceFile source("test", text);
  compiler::DiagnosticSink sink(0);
  CheckShader(stage, {&source}, options, &sink);
  std::vector<std::string> keys;
  for (const compiler::Diagnostic& d : sink.diagnostics()) {
    if (d.severity != severity) continue;
    compiler::LineCol lc = source.Locate(d.range.begin);
    keys.push_back(std::to_string(lc.line) + ":" + std::to_string(lc.column) + " " +
                   std::string(d.info->code));
  }
  return keys;
}

const char* kMain = "void main() { gl_Position = vec4(1.0); }\n";

// 4.3.6: "The varying qualifier can be used only with the data types float, vec2, vec3,
// vec4, mat2, mat3, and mat4, or arrays of these."
TEST(Strict, VaryingTypes) {
  EXPECT_THAT(Check(Stage::Vertex, std::string("varying vec3 n;\nvarying mat4 m;\nvarying float "
                                               "f[2];\n") +
                                       kMain),
              IsEmpty());
  EXPECT_THAT(Check(Stage::Vertex, std::string("varying int i;\n") + kMain),
              ElementsAre("1:13 glsl-varying-type"));
  EXPECT_THAT(Check(Stage::Fragment,
                    "varying bvec2 b;\nvoid main() { gl_FragColor = vec4(b.x ? 1.0 : 0.0); }\n"),
              ElementsAre("1:1 glsl-varying-type"));  // glslang's own message, no token
}

// 4.3: initializers of unqualified and const globals "must have constant type".
TEST(Strict, GlobalInitializersAreConstant) {
  EXPECT_THAT(
      Check(Stage::Vertex, std::string("const float k = 2.0;\nfloat g = k * 3.0;\n") + kMain),
      IsEmpty());
  EXPECT_THAT(Check(Stage::Vertex, std::string("uniform float u;\nfloat g = u;\n") + kMain),
              ElementsAre("2:11 glsl-global-initializer"));
  EXPECT_THAT(Check(Stage::Vertex, std::string("attribute vec4 a;\nvec4 g = a * 2.0;\n") + kMain),
              ElementsAre("2:10 glsl-global-initializer"));
}

// 4.3.2: "Constructors may be used in such expressions, but function calls may not."
TEST(Strict, ConstInitializersCallNoFunctions) {
  EXPECT_THAT(Check(Stage::Vertex,
                    std::string("const vec2 v = vec2(1.0, 2.0);\nconst float a = 1.0, b = a + "
                                "v.y;\nfloat f(const in float x) { return x; }\n") +
                        kMain),
              IsEmpty());
  EXPECT_THAT(Check(Stage::Vertex, std::string("const float c = sin(1.0);\n") + kMain),
              ElementsAre("1:17 glsl-const-initializer-call"));
  EXPECT_THAT(
      Check(Stage::Vertex, std::string("void main() {\n  const float a = 1.0, b = abs(a);\n  "
                                       "gl_Position = vec4(b);\n}\n")),
      ElementsAre("2:28 glsl-const-initializer-call"));
}

// 7.1: not writing gl_Position allows a diagnostic (a warning for a shader), and fails a
// program link.
TEST(Strict, PositionUnwritten) {
  const char* shader = "void main() { vec4 c = gl_Color; }\n";
  EXPECT_THAT(Check(Stage::Vertex, shader), IsEmpty());
  EXPECT_THAT(Check(Stage::Vertex, shader, compiler::Severity::Warning),
              ElementsAre("1:6 glsl-position-unwritten"));
  CheckOptions program;
  program.link_as_program = true;
  EXPECT_THAT(Check(Stage::Vertex, shader, compiler::Severity::Error, program),
              ElementsAre("1:6 glsl-position-unwritten"));
  // The warning points at main's definition, not at a word that contains "main".
  EXPECT_THAT(Check(Stage::Vertex, "float domain;\nvoid main() { vec4 c = gl_Color; }\n",
                    compiler::Severity::Warning),
              ElementsAre("2:6 glsl-position-unwritten"));
  EXPECT_THAT(Check(Stage::Vertex,
                    "void set(out vec4 p) { p = vec4(1.0); }\nvoid main() { "
                    "set(gl_Position); }\n",
                    compiler::Severity::Warning),
              IsEmpty());
}

// glslang's own diagnostics keep their line and get the column of the token they quote.
TEST(Diagnostics, ColumnFromQuotedToken) {
  EXPECT_THAT(Check(Stage::Vertex, "void main() {\n  gl_Position = vec4(foo);\n}\n"),
              ElementsAre("2:22 glsl-undeclared-identifier"));
  EXPECT_THAT(Check(Stage::Vertex, "void main() {\n  gl_Position = vec4(1.0f);\n}\n"),
              ElementsAre("2:25 glsl-version"));
}

TEST(Diagnostics, SeveralStringsKeepTheirNames) {
  compiler::SourceFile a("a.glsl", "uniform vec4 tint;\n");
  compiler::SourceFile b("b.glsl", "void main() {\n  gl_FragColor = tint * nope;\n}\n");
  compiler::DiagnosticSink sink(0);
  CheckShader(Stage::Fragment, {&a, &b}, {}, &sink);
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  const compiler::Diagnostic& d = sink.diagnostics()[0];
  EXPECT_EQ(d.file, &b);
  compiler::LineCol lc = b.Locate(d.range.begin);
  EXPECT_EQ(lc.line, 2u);
  EXPECT_EQ(lc.column, 25u);
}

}  // namespace
}  // namespace arbiter::glsl
