// Syntax errors: glslang gives a line and the grammar name of the unexpected token; arbiter
// points at the token, and at the end of the previous statement when a ';' is missing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "arbiter/glsl/check.h"

namespace arbiter::glsl {
namespace {

using ::testing::ElementsAre;

// "line:col code" of every diagnostic, and "note line:col" of every note.
std::vector<std::string> Places(const std::string& text) {
  compiler::SourceFile source("test", text);
  compiler::DiagnosticSink sink(0);
  CheckShader(Stage::Fragment, {&source}, {}, &sink);
  std::vector<std::string> out;
  auto at = [&](compiler::Range r) {
    compiler::LineCol lc = source.Locate(r.begin);
    return std::to_string(lc.line) + ":" + std::to_string(lc.column);
  };
  for (const compiler::Diagnostic& d : sink.diagnostics()) {
    out.push_back(at(d.range) + " " + std::string(d.info->code));
    for (const compiler::Note& n : d.notes) out.push_back("note " + at(n.range));
  }
  return out;
}

TEST(SyntaxError, MissingSemicolonPointsAtTheNextTokenAndNotesTheStatementEnd) {
  EXPECT_THAT(Places("void main() {\n  float a = 1.0;\n  float b = 2.0\n  float c = 3.0;\n"
                     "  gl_FragColor = vec4(a, b, c, 1.0);\n}\n"),
              ElementsAre("4:3 glsl-syntax-error", "note 3:16"));
}

TEST(SyntaxError, TheTokenAfterAWholeOperand) {
  // Two float constants on the line: the parser stops at the second, after ')'.
  EXPECT_THAT(Places("void main() {\n  vec4 x = vec4(1.0) 2.0;\n  gl_FragColor = x;\n}\n"),
              ElementsAre("2:22 glsl-syntax-error"));
}

TEST(SyntaxError, PunctuationByItsGrammarName) {
  EXPECT_THAT(Places("void main() {\n  gl_FragColor = vec4(1.0));\n}\n"),
              ElementsAre("2:27 glsl-syntax-error"));
}

}  // namespace
}  // namespace arbiter::glsl
