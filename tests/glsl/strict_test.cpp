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

// 1.10 4.3: initializers of unqualified and const globals "must have constant type"; 1.20
// drops the sentence and every driver accepts them in 1.10: a warning of its own code, 1.10
// only.
TEST(Strict, GlobalInitializersAreConstant) {
  const auto kWarning = compiler::Severity::Warning;
  EXPECT_THAT(Check(Stage::Vertex,
                    std::string("const float k = 2.0;\nfloat g = k * 3.0;\n") + kMain, kWarning),
              IsEmpty());
  EXPECT_THAT(
      Check(Stage::Vertex, std::string("uniform float u;\nfloat g = u;\n") + kMain, kWarning),
      ElementsAre("2:11 glsl-global-initializer"));
  EXPECT_THAT(
      Check(Stage::Vertex, std::string("attribute vec4 a;\nvec4 g = a * 2.0;\n") + kMain, kWarning),
      ElementsAre("2:10 glsl-global-initializer"));
  EXPECT_THAT(Check(Stage::Vertex, std::string("uniform float u;\nfloat g = u;\n") + kMain),
              IsEmpty());
  EXPECT_THAT(
      Check(Stage::Vertex, std::string("#version 120\nuniform float u;\nfloat g = u;\n") + kMain,
            kWarning),
      IsEmpty());
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

// 4.3.2 and 5.9: a comma of constant expressions is one (1.20 4.3.3 too). glslang 12 folds no
// comma; arbiter judges the operands of each const initializer glslang leaves unfolded.
TEST(Strict, ConstInitializersWithComma) {
  EXPECT_THAT(Check(Stage::Fragment,
                    "void main() {\n  const mat2 m = mat2(1.0);\n  const vec2 c = m[0, 1];\n"
                    "  const float f = (c.x, 2.0) * c.y;\n  gl_FragColor = vec4(c, f, 1.0);\n}\n"),
              IsEmpty());
  EXPECT_THAT(Check(Stage::Vertex,
                    "float f(const in float p) {\n  const float a = (1.0, 2.0), b = (a, p);\n"
                    "  return b;\n}\n" +
                        std::string(kMain)),
              ElementsAre("2:39 glsl-const-initializer-operand"));
  // The left operand too, though only the right one gives the value (Mesa accepts this).
  EXPECT_THAT(Check(Stage::Fragment,
                    "uniform float u;\nvoid main() {\n  const float f = (u, 1.0);\n"
                    "  gl_FragColor = vec4(f);\n}\n"),
              ElementsAre("3:20 glsl-const-initializer-operand"));
  EXPECT_THAT(Check(Stage::Vertex,
                    "void main() {\n  float x = 1.0;\n  const float c = x;\n"
                    "  gl_Position = vec4(c);\n}\n"),
              ElementsAre("3:19 glsl-const-initializer-operand"));
  // 1.10: the call is reported once, from the text (ConstInitializersCallNoFunctions).
  const std::string call =
      "float g() { return 1.0; }\nvoid main() {\n  const float a = (1.0, g());\n"
      "  const float c = (a, 2.0);\n  gl_Position = vec4(c);\n}\n";
  EXPECT_THAT(Check(Stage::Vertex, call), ElementsAre("3:25 glsl-const-initializer-call"));
  EXPECT_THAT(Check(Stage::Vertex, "#version 120\n" + call),
              ElementsAre("4:25 glsl-const-initializer-call"));
  // 1.20 4.3.3: no noise function nor ftransform, which glslang does not fold either.
  EXPECT_THAT(Check(Stage::Vertex,
                    "#version 120\nvoid main() {\n  const float n = noise1(0.5);\n"
                    "  const vec4 p = (1.0, ftransform());\n  gl_Position = p * n;\n}\n"),
              ElementsAre("3:19 glsl-const-initializer-call", "4:24 glsl-const-initializer-call"));
  EXPECT_THAT(Check(Stage::Fragment,
                    "#version 120\nvoid main() {\n  const vec4 v = (vec4(1.0), vec4(2.0));\n"
                    "  gl_FragColor = v * v[0, 1];\n}\n"),
              IsEmpty());
}

// 4.2: in 1.10 "Functions names are always identifiable as function names based on context,
// and they have their own name space"; glslang reads a call as the constant of that name.
// 1.20 4.2 shares one name space.
TEST(Strict, FunctionsHaveTheirOwnNameSpace) {
  const std::string shader =
      "float foo() { return 0.5; }\nconst float foo = 1.0;\n"
      "void main() { gl_Position = vec4(foo - foo()); }\n";
  EXPECT_THAT(Check(Stage::Vertex, shader), IsEmpty());
  EXPECT_THAT(Check(Stage::Vertex, "#version 120\n" + shader),
              ::testing::Contains("3:13 glsl-redefinition"));
  // A local const, a one-letter name ('_' taken), a call in a macro.
  EXPECT_THAT(Check(Stage::Vertex,
                    "float f(float x) { return x; }\n#define TWICE f(2.0)\nvoid main() {\n"
                    "  const float f = 1.0, _ = 0.0;\n  gl_Position = vec4(f(f) + TWICE);\n}\n"),
              IsEmpty());
  // A wrong call keeps its error, with the user's name.
  compiler::SourceFile source("test",
                              "float foo(float x) { return x; }\nconst float foo = 1.0;\n"
                              "void main() {\n  gl_Position = vec4(foo(foo, 2.0));\n}\n");
  compiler::DiagnosticSink sink(0);
  CheckShader(Stage::Vertex, {&source}, {}, &sink);
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  EXPECT_EQ(std::string(sink.diagnostics()[0].info->code), "glsl-no-matching-function");
  EXPECT_EQ(source.Locate(sink.diagnostics()[0].range.begin).column, 22u);
  EXPECT_THAT(sink.diagnostics()[0].message, ::testing::HasSubstr("'foo'"));
}

// 7.1: not writing gl_Position allows a diagnostic (a warning for a shader), and fails a
// program link.
TEST(Strict, PositionUnwritten) {
  const char* shader = "void main() { vec4 c = gl_Color; }\n";
  EXPECT_THAT(Check(Stage::Vertex, shader), IsEmpty());
  EXPECT_THAT(Check(Stage::Vertex, shader, compiler::Severity::Warning),
              ElementsAre("1:6 glsl-position-unwritten"));
  CheckOptions program;
  program.link = true;
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

// 3.6 reserves neither 'case' nor 'filter' (glslang 12 does); diagnostics keep the user's
// spelling of the renamed words.
TEST(Strict, WordsGlslangReservesAreIdentifiers) {
  EXPECT_THAT(Check(Stage::Vertex,
                    "float case = 1.0;\nfloat filter = case;\nvoid main() { "
                    "gl_Position = vec4(filter, active, 0.0, 1.0); }\n"),
              ElementsAre("3:42 glsl-undeclared-identifier"));
  EXPECT_THAT(Check(Stage::Vertex,
                    "uniform float common;\nfloat partition = common;\n" + std::string(kMain),
                    compiler::Severity::Warning),
              ElementsAre("2:19 glsl-global-initializer"));
}

// 4.2: "A function body has a scope nested inside the function's definition."
TEST(Strict, FunctionBodyNestsTheParameterScope) {
  EXPECT_THAT(Check(Stage::Vertex, "float f(float x) {\n  vec2 x = vec2(2.0);\n  return x.y;\n}\n" +
                                       std::string(kMain)),
              IsEmpty());
  // The body's x is a vec2: returning it from a float function is still an error.
  EXPECT_THAT(Check(Stage::Vertex, "float f(float x) {\n  vec2 x = vec2(2.0);\n  return x;\n}\n" +
                                       std::string(kMain)),
              ElementsAre("3:3 glsl-type-mismatch"));
  // A duplicate parameter stays an error (glslang's message has no column: the first 'x').
  EXPECT_THAT(
      Check(Stage::Vertex, "float f(float x, float x) { return x; }\n" + std::string(kMain)),
      ElementsAre("1:15 glsl-redefinition"));
}

// 4.1.8: embedded structure definitions, their names scoped as the outer structure's.
TEST(Strict, EmbeddedStructDefinitions) {
  EXPECT_THAT(
      Check(Stage::Vertex, "struct O { struct I { float x; } i; };\nI j;\n" + std::string(kMain)),
      IsEmpty());
  EXPECT_THAT(
      Check(Stage::Vertex, "struct I { float y; };\nstruct O { struct I { float x; } i; };\n" +
                               std::string(kMain)),
      ElementsAre("2:19 glsl-redefinition"));
}

// 5.5, 5.6: a constant index past a vector or matrix is undefined behaviour: a warning.
TEST(Strict, ConstantIndexPastVectorWarns) {
  const char* shader =
      "uniform vec2 v;\nuniform mat3 m;\nvoid main() {\n  gl_Position = "
      "vec4(v[2] + m[3][0]);\n}\n";
  EXPECT_THAT(Check(Stage::Vertex, shader), IsEmpty());
  // glslang's messages have no column: both at the first '[' of the line.
  EXPECT_THAT(Check(Stage::Vertex, shader, compiler::Severity::Warning),
              ElementsAre("4:23 glsl-index-out-of-range", "4:23 glsl-index-out-of-range"));
}

// 1.10 sets no limit on a name's length; glslang refuses past 1 024 characters.
TEST(Strict, NamesHaveNoLengthLimit) {
  const std::string name(2000, 'a');
  EXPECT_THAT(Check(Stage::Fragment, "#if 0\n" + std::string(16384, 'b') +
                                         "\n#endif\nvoid main() {\n  float " + name +
                                         " = 1.0;\n  gl_FragColor = vec4(" + name + ");\n}\n"),
              IsEmpty());
  EXPECT_THAT(Check(Stage::Fragment, "void main() {\n  gl_FragColor = vec4(" + name + ");\n}\n"),
              ElementsAre("2:23 glsl-undeclared-identifier"));
}

// 3.3: #error's message is the shader's own; words in it ("array", "version") do not pick the
// code.
TEST(Strict, ErrorDirectiveHasItsOwnCode) {
  EXPECT_THAT(Check(Stage::Fragment, "void main() {}\n#error wrong array version\n"),
              ElementsAre("2:1 glsl-error-directive"));
}

// 5.9: unary '+' takes numbers only; glslang drops the operator, arbiter finds its operand.
TEST(Strict, UnaryPlusTakesNumbers) {
  EXPECT_THAT(Check(Stage::Vertex,
                    "struct S { float x; };\nuniform S s;\nuniform vec4 a[2];\n"
                    "float f(float x) { return +x; }\nvoid main() {\n"
                    "  float x = +a[0].x + +s.x + +f(1.0) + 1e+5;\n"
                    "  gl_Position = vec4(+x, x+ +x, x++ + +x, - +x);\n}\n"),
              IsEmpty());
  EXPECT_THAT(Check(Stage::Vertex,
                    "void f(void) {}\nstruct S { float x; };\nuniform S s;\nuniform bool b;\n"
                    "void main() {\n  +f();\n  bool c = +b;\n  S t = +s;\n"
                    "  gl_Position = vec4(0.0);\n}\n"),
              ElementsAre("6:3 glsl-unary-plus-operand", "7:12 glsl-unary-plus-operand",
                          "8:9 glsl-unary-plus-operand"));
  EXPECT_THAT(Check(Stage::Vertex,
                    "#version 120\nuniform vec4 a[2];\nuniform vec4 b[2];\n"
                    "void main() { gl_Position = vec4(+a == b); }\n"),
              ElementsAre("4:34 glsl-unary-plus-operand"));
}

// 5.7-5.9: whole arrays are no operands of '=', '==', '!=' or '?:'; structures with array
// fields are.
TEST(Strict, WholeArraysAreNoOperands) {
  EXPECT_THAT(Check(Stage::Fragment,
                    "struct S { float a[2]; };\nuniform S u;\nvoid main() {\n  S s = u;\n  bool "
                    "e = s == u;\n  gl_FragColor = vec4(s.a[0]);\n}\n"),
              IsEmpty());
  EXPECT_THAT(
      Check(Stage::Fragment,
            "uniform bool p;\nvoid main() {\n  float a[2];\n  float b[2];\n  a = b;\n  "
            "bool e = a != b;\n  gl_FragColor = vec4((p ? a : b)[0]);\n}\n"),
      ElementsAre("5:5 glsl-array-operand", "6:14 glsl-array-operand", "7:26 glsl-array-operand"));
}

// Chapter 9: the third operand of ?: is a conditional_expression.
TEST(Strict, AssignmentInThirdOperandOfConditional) {
  EXPECT_THAT(Check(Stage::Vertex,
                    "uniform bool p;\nvoid main() {\n  float x;\n  p ? x = 1.0 : "
                    "(x = 2.0);\n  gl_Position = vec4(x);\n}\n"),
              IsEmpty());
  EXPECT_THAT(Check(Stage::Vertex,
                    "uniform bool p;\nvoid main() {\n  float x;\n  p ? x = 1.0 : "
                    "x = 2.0;\n  gl_Position = vec4(x);\n}\n"),
              ElementsAre("4:19 glsl-conditional-assignment"));
}

// 7.6: gl_TexCoord has at most gl_MaxTextureCoords elements.
TEST(Strict, TexCoordIndexBelowMax) {
  EXPECT_THAT(Check(Stage::Vertex,
                    "void main() {\n  gl_TexCoord[gl_MaxTextureCoords - 1] = "
                    "vec4(0.0);\n  gl_Position = vec4(0.0);\n}\n"),
              IsEmpty());
  EXPECT_THAT(Check(Stage::Vertex,
                    "void main() {\n  gl_TexCoord[gl_MaxTextureCoords] = "
                    "vec4(0.0);\n  gl_Position = vec4(0.0);\n}\n"),
              ElementsAre("2:14 glsl-texcoord-index"));
}

// 7.2: assigning both gl_FragColor and gl_FragData is an error, reading one of them is not.
TEST(Strict, FragColorAndFragDataAssigned) {
  EXPECT_THAT(
      Check(Stage::Fragment, "void main() {\n  gl_FragData[0] = vec4(0.5) + gl_FragColor;\n}\n"),
      IsEmpty());
  EXPECT_THAT(Check(Stage::Fragment,
                    "void set(out vec4 c) { c = vec4(1.0); }\nvoid main() {\n  "
                    "set(gl_FragColor);\n  gl_FragData[0] = vec4(0.5);\n}\n"),
              ElementsAre("4:3 glsl-link-fragcolor-fragdata"));
}

// 3.3: #if and #elif operands are integer literals and 'defined' (after macro expansion).
TEST(Strict, ConditionalOperandsAreMacrosOrLiterals) {
  EXPECT_THAT(Check(Stage::Vertex,
                    "#define A 1\n#if A && defined(A) || defined B\n#elif 0x10 "
                    "> 010\n#endif\n#ifdef NOPE\n#if NOPE2\n#endif\n#endif\n/*\n#if "
                    "Q\n*/\n" +
                        std::string(kMain)),
              IsEmpty());
  EXPECT_THAT(Check(Stage::Vertex,
                    "#define B A + C\n#define A 1\n#if UNDEFINED\n#elif B\n#endif\n#if 1\n#elif "
                    "SKIPPED\n#endif\n" +
                        std::string(kMain)),
              ElementsAre("3:5 glsl-if-undefined-identifier", "4:7 glsl-if-undefined-identifier"));
}

// 3.3: "There are no number sign based operators"; the conditionals "operate as is standard
// for C++ preprocessors", which do not process a skipped group's #define: its '#' is no
// operator (piglit's stringification-in-unreachable-branch.frag). Where arbiter cannot tell
// the group's value, nothing is reported.
TEST(Strict, StringificationOnlyInCompiledText) {
  EXPECT_THAT(Check(Stage::Vertex,
                    "#ifdef NOT_DEFINED\n#define S(a) vec4(#a)\n#endif\n" + std::string(kMain)),
              IsEmpty());
  EXPECT_THAT(Check(Stage::Vertex,
                    "#ifndef NOT_DEFINED\n#define S(a) vec4(#a)\n#endif\n" + std::string(kMain)),
              ElementsAre("2:19 glsl-preprocessor"));
  EXPECT_THAT(Check(Stage::Vertex, "#ifdef GL_NOT_AN_EXTENSION\n#define S(a) vec4(#a)\n#endif\n" +
                                       std::string(kMain)),
              IsEmpty());
}

// 3.1 has no backslash, so 1.10 and 1.20 have no line continuation (an error, glslang's), but
// in a group the preprocessor skips every driver accepts one: a warning of its own code, at
// the backslash (piglit's if-statement-in-macro-in-false-ifdef.vert). Where arbiter cannot
// tell the group's value, the error stands.
TEST(Strict, LineContinuationWarnsOnlyInSkippedGroups) {
  const auto kWarning = compiler::Severity::Warning;
  const std::string skipped =
      "#ifdef NOT_DEFINED\n#define A(x) \\\n  if (x)\n#endif\n" + std::string(kMain);
  EXPECT_THAT(Check(Stage::Vertex, skipped, kWarning),
              ElementsAre("2:14 glsl-skipped-line-continuation"));
  EXPECT_THAT(Check(Stage::Vertex, skipped), IsEmpty());
  EXPECT_THAT(Check(Stage::Vertex, "#define A(x) \\\n  (x)\n" + std::string(kMain)),
              ElementsAre("1:14 glsl-version"));
  EXPECT_THAT(
      Check(Stage::Vertex, "#if 1\nfloat f = 1.0 \\\r\n  + 2.0;\n#endif\n" + std::string(kMain)),
      ElementsAre("2:15 glsl-version"));
  EXPECT_THAT(Check(Stage::Vertex, "#ifdef GL_NOT_AN_EXTENSION\n#define A(x) \\\n  (x)\n#endif\n" +
                                       std::string(kMain)),
              ElementsAre("2:14 glsl-version"));
}

// 4.1.9, 4.3.3: an array size is an integral constant expression, read operand by operand:
// integer literals and const int variables, through operators and constructors, no calls.
TEST(Strict, ArraySizesAreIntegralConstantExpressions) {
  const char* kFrag = "void main() { gl_FragColor = vec4(0.0); }\n";
  EXPECT_THAT(Check(Stage::Fragment,
                    "#define N 3\n#define M N\nconst int n = 2;\nstruct S { float f[int(n)]; };\n"
                    "float a[int(3)], b[2 + 1], c[n * 2], d[1 > 0 ? 2 : 3], e[ivec2(n, 3).y];\n"
                    "float g[gl_MaxLights], h[int(M)], k[0x2], l[__LINE__];\n"
                    "void f(float p[int(2)]) { const float n = 1.0; { const int n = 2; "
                    "float q[int(n)]; } }\n" +
                        std::string(kFrag)),
              IsEmpty());
  EXPECT_THAT(
      Check(Stage::Fragment,
            "const float f = 2.0;\nconst bool b = true;\nconst ivec2 v = ivec2(2, 3);\n"
            "float a[int(2.0)], a2[int(2e0)];\nfloat c[int(f)];\nfloat d[true ? 2 : 3];\n"
            "float e[int(b)];\nfloat g[int(abs(-2.0))];\nfloat h[v.y];\n"
            "struct S { float m[int(.5e1)]; } s[int(true) + 1];\n"
            "void p(float x[int(f)]);\n" +
                std::string(kFrag)),
      ElementsAre("4:13 glsl-array-size-not-integral", "4:27 glsl-array-size-not-integral",
                  "5:13 glsl-array-size-not-integral", "6:9 glsl-array-size-not-integral",
                  "7:13 glsl-array-size-not-integral", "8:13 glsl-array-size-not-integral",
                  "9:9 glsl-array-size-not-integral", "10:24 glsl-array-size-not-integral",
                  "10:40 glsl-array-size-not-integral", "11:20 glsl-array-size-not-integral"));
  // Locals, and a const float shadowed by a const int.
  EXPECT_THAT(Check(Stage::Fragment,
                    "const int n = 2;\nvoid main() {\n  const float n = 2.0;\n  float a[int(n)];\n"
                    "  gl_FragColor = vec4(0.0);\n}\n"),
              ElementsAre("4:15 glsl-array-size-not-integral"));
  // An object-like macro is expanded and reported at its name; a function-like macro and an
  // undecidable #if (a function-like macro, a GL_ name) leave the size unjudged; a group known
  // to be false is skipped; #if expressions are evaluated (__VERSION__ is 110).
  EXPECT_THAT(
      Check(Stage::Fragment,
            "#define TWO 2.0\n#define F(x) x\nfloat a[int(TWO)];\nfloat b[int(F(2.0))];\n"
            "#if __VERSION__ >= 110\nfloat c[int(2.0)];\n#endif\n#if 0\nfloat d[int(2.0)];\n"
            "#else\nfloat d[2];\n#endif\n#ifdef GL_ES\nconst int k = 2;\n#else\nconst float "
            "k = 2.0;\n#endif\nfloat e[int(k)];\n#if !defined(TWO)\nfloat g[int(2.0)];\n"
            "#elif defined TWO\nfloat g[int(1.0)];\n#endif\n#if F(1)\nfloat h[int(2.0)];\n"
            "#endif\n#if GL_NOT_AN_EXTENSION > 1\nfloat i[int(2.0)];\n#endif\n" +
                std::string(kFrag)),
      ElementsAre("3:13 glsl-array-size-not-integral", "6:13 glsl-array-size-not-integral",
                  "22:13 glsl-array-size-not-integral"));
}

// glslang's own diagnostics keep their line and get the column of the token they quote.
TEST(Diagnostics, ColumnFromQuotedToken) {
  EXPECT_THAT(Check(Stage::Vertex, "void main() {\n  gl_Position = vec4(foo);\n}\n"),
              ElementsAre("2:22 glsl-undeclared-identifier"));
  EXPECT_THAT(Check(Stage::Vertex, "void main() {\n  gl_Position = vec4(1.0f);\n}\n"),
              ElementsAre("2:25 glsl-version"));
}

// 3.3: "Any number less than 110 will cause an error to be generated. Any number greater
// than the latest version of the language a compiler supports will also cause an error".
// arbiter checks 1.10 and 1.20: a number below 110 is an error at the number and the rest is
// checked as 1.10 (`float x = 1;` is an error in 1.10, with no implicit conversion, not in
// 1.20); a later version gets one diagnostic and nothing else.
TEST(Diagnostics, VersionOtherThan110Or120) {
  const std::string body = "void main() { float x = 1; gl_Position = vec4(x); }\n";
  EXPECT_THAT(Check(Stage::Vertex, "#version 110\n" + body),
              ElementsAre("2:23 glsl-type-mismatch"));
  EXPECT_THAT(Check(Stage::Vertex, "#version 120\n" + body), IsEmpty());
  EXPECT_THAT(
      Check(Stage::Vertex, "/* a\n comment */ // and another\n  #  version   460 core\n" + body),
      ElementsAre("3:16 glsl-version"));
  EXPECT_THAT(Check(Stage::Vertex, "#version 130\nin vec4 p;\nvoid main() { gl_Position = p; }\n"),
              ElementsAre("1:10 glsl-version"));
  EXPECT_THAT(Check(Stage::Vertex, "#version 109\r\n" + std::string(kMain)),
              ElementsAre("1:10 glsl-version"));
  // 100 is OpenGL ES for glslang; 0110 is octal 72 for a preprocessor.
  EXPECT_THAT(Check(Stage::Vertex, "#version 100\n" + std::string(kMain)),
              ElementsAre("1:10 glsl-version"));
  EXPECT_THAT(Check(Stage::Vertex, "#version 0110\n" + std::string(kMain)),
              ElementsAre("1:10 glsl-version"));
  // Not the shader's first token: glslang says so at the directive, and checks as 1.10.
  EXPECT_THAT(Check(Stage::Vertex, "float f;\n#version 999\n" + body),
              ElementsAre("2:10 glsl-version", "2:1 glsl-version", "3:23 glsl-type-mismatch"));
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
