// ARB_fragment_coord_conventions' redeclarations of gl_FragCoord in GLSL 1.10 and 1.20
// (frag_coord.h): what the extension allows passes, what it forbids is an error of code
// glsl-fragcoord-redeclaration at the token that decides it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "arbiter/compiler/limits.h"
#include "arbiter/glsl/check.h"

namespace arbiter::glsl {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

struct Checked {
  std::vector<std::string> places;    // "line:col code" of each diagnostic, "note line:col"
  std::vector<std::string> messages;  // of each diagnostic
};

Checked CheckStrings(Stage stage, const std::vector<std::string>& texts,
                     const CheckOptions& options = {}) {
  std::vector<compiler::SourceFile> files;
  files.reserve(texts.size());
  for (const std::string& text : texts) files.emplace_back("test", text);
  std::vector<const compiler::SourceFile*> sources;
  sources.reserve(files.size());
  for (const compiler::SourceFile& file : files) sources.push_back(&file);
  compiler::DiagnosticSink sink(0);
  CheckShader(stage, sources, options, &sink);
  Checked out;
  for (const compiler::Diagnostic& d : sink.diagnostics()) {
    auto at = [&](const compiler::SourceFile* file, compiler::Range r) {
      size_t string = 0;
      while (string < sources.size() && sources[string] != file) ++string;
      compiler::LineCol lc = file->Locate(r.begin);
      std::string place = std::to_string(lc.line) + ":" + std::to_string(lc.column);
      return string == 0 ? place : std::to_string(string) + "/" + place;
    };
    out.places.push_back(at(d.file, d.range) + " " + std::string(d.info->code));
    for (const compiler::Note& n : d.notes) out.places.push_back("note " + at(n.file, n.range));
    out.messages.push_back(d.message);
  }
  return out;
}

Checked Check(Stage stage, const std::string& text, const CheckOptions& options = {}) {
  return CheckStrings(stage, {text}, options);
}

constexpr const char* kRequire =
    "#version 110\n#extension GL_ARB_fragment_coord_conventions : require\n";
constexpr const char* kMain = "void main() { gl_FragColor = gl_FragCoord; }\n";

std::string Fragment(const std::string& declarations) {
  return std::string(kRequire) + declarations + kMain;
}

TEST(FragCoord, TheExtensionsRedeclarationsPass) {
  for (const char* declaration : {
           "in vec4 gl_FragCoord;\n",
           "layout(origin_upper_left) in vec4 gl_FragCoord;\n",
           "layout(pixel_center_integer) in vec4 gl_FragCoord;\n",
           "layout(origin_upper_left, pixel_center_integer) in vec4 gl_FragCoord;\n",
           "layout(pixel_center_integer, origin_upper_left) in vec4 gl_FragCoord;\n",
           // 4.3.x: "these identifiers are not case-sensitive"
           "layout(Origin_Upper_Left, PIXEL_CENTER_INTEGER) in vec4 gl_FragCoord;\n",
           "layout ( origin_upper_left ) /* a comment */ in\n  vec4 gl_FragCoord ;\n",
           // the name through a macro
           "#define POSITION gl_FragCoord\nlayout(origin_upper_left) in vec4 POSITION;\n",
       }) {
    EXPECT_THAT(Check(Stage::Fragment, Fragment(declaration)).places, IsEmpty()) << declaration;
  }
  // The same qualifiers again.
  const std::string upper_left = "layout(origin_upper_left) in vec4 gl_FragCoord;\n";
  EXPECT_THAT(Check(Stage::Fragment, Fragment(upper_left + upper_left)).places, IsEmpty());
  EXPECT_THAT(Check(Stage::Fragment,
                    "#version 120\n#extension GL_ARB_fragment_coord_conventions : enable\n"
                    "layout(origin_upper_left) in vec4 gl_FragCoord;\n" +
                        std::string(kMain))
                  .places,
              IsEmpty());
  // What arbiter translate emits for OPTION ARB_fragment_coord_origin_upper_left.
  EXPECT_THAT(Check(Stage::Fragment,
                    "#version 110\n#extension GL_ARB_fragment_coord_conventions : require\n"
                    "// ARB fragment program translated to GLSL 1.10 by arbiter.\n"
                    "layout(origin_upper_left) in vec4 gl_FragCoord;\n"
                    "void main()\n{\n  gl_FragColor = gl_FragCoord;\n}\n")
                  .places,
              IsEmpty());
}

// Only text the preprocessor compiles counts (conditionals.h).
TEST(FragCoord, ConditionalGroups) {
  EXPECT_THAT(Check(Stage::Fragment,
                    "#ifdef GL_ARB_fragment_coord_conventions\n"
                    "#extension GL_ARB_fragment_coord_conventions : enable\n"
                    "layout(origin_upper_left) in vec4 gl_FragCoord;\n#endif\n" +
                        std::string(kMain))
                  .places,
              IsEmpty());
  EXPECT_THAT(
      Check(Stage::Fragment, Fragment("#if 0\nlayout(origin_lower_left) in vec3 gl_FragCoord;\n"
                                      "#endif\n"))
          .places,
      IsEmpty());
  // A use in a skipped group is none.
  EXPECT_THAT(Check(Stage::Fragment, Fragment("#if 0\nvec4 a = gl_FragCoord;\n#endif\n"
                                              "in vec4 gl_FragCoord;\n"))
                  .places,
              IsEmpty());
  // The extension enabled in a skipped group is not.
  EXPECT_THAT(Check(Stage::Fragment,
                    "#if 0\n#extension GL_ARB_fragment_coord_conventions : enable\n#endif\n"
                    "layout(origin_upper_left) in vec4 gl_FragCoord;\n" +
                        std::string(kMain))
                  .places,
              ElementsAre("4:1 glsl-fragcoord-redeclaration"));
  // Where arbiter cannot tell, a valid redeclaration is hidden and nothing is reported.
  EXPECT_THAT(Check(Stage::Fragment, Fragment("#if defined(GL_VENDOR_THING)\n"
                                              "layout(origin_upper_left) in vec4 gl_FragCoord;\n"
                                              "#endif\n"))
                  .places,
              IsEmpty());
}

TEST(FragCoord, NeedsTheExtension) {
  Checked c = Check(Stage::Fragment,
                    "layout(origin_upper_left) in vec4 gl_FragCoord;\n" + std::string(kMain));
  EXPECT_THAT(c.places, ElementsAre("1:1 glsl-fragcoord-redeclaration"));
  EXPECT_THAT(c.messages[0],
              HasSubstr("needs '#extension GL_ARB_fragment_coord_conventions : enable'"));
  EXPECT_THAT(
      Check(Stage::Fragment, Fragment("#extension GL_ARB_fragment_coord_conventions : disable\n"
                                      "layout(pixel_center_integer) in vec4 gl_FragCoord;\n"))
          .places,
      ElementsAre("4:1 glsl-fragcoord-redeclaration"));
  // A target without the extension: the #extension and the layout are reported.
  CheckOptions spec_min;
  spec_min.profile = compiler::BuiltinProfile("spec-min");
  c = Check(Stage::Fragment, Fragment("layout(origin_upper_left) in vec4 gl_FragCoord;\n"),
            spec_min);
  EXPECT_THAT(c.places,
              ElementsAre("2:12 glsl-extension-unsupported", "3:1 glsl-fragcoord-redeclaration"));
  EXPECT_THAT(c.messages[1], HasSubstr("which the target profile does not have"));
}

// "The built-in gl_FragCoord is only predeclared in fragment shaders, so redeclaring it in
// any other shader language will be illegal"; "Vertex shaders do not have any input layout
// qualifiers".
TEST(FragCoord, OnlyInFragmentShaders) {
  const std::string vertex_main = "void main() { gl_Position = vec4(0.0); }\n";
  EXPECT_THAT(
      Check(Stage::Vertex, std::string(kRequire) + "in vec4 gl_FragCoord;\n" + vertex_main).places,
      ElementsAre("3:9 glsl-fragcoord-redeclaration"));
  EXPECT_THAT(
      Check(Stage::Vertex, std::string(kRequire) +
                               "layout(origin_upper_left) in vec4 gl_FragCoord;\n" + vertex_main)
          .places,
      ElementsAre("3:35 glsl-fragcoord-redeclaration"));
  // On a vertex input: the layout is reported, and glslang reports 1.10's global 'in'.
  Checked c = Check(Stage::Vertex, std::string(kRequire) +
                                       "layout(origin_upper_left) in vec4 v;\n"
                                       "void main() { gl_Position = v; }\n");
  ASSERT_FALSE(c.places.empty());
  EXPECT_EQ(c.places[0], "3:1 glsl-fragcoord-redeclaration");
  EXPECT_THAT(c.messages[0], HasSubstr("a vertex shader has no input layout qualifiers"));
}

// "Fragment shaders can have an input layout only for redeclaring the built-in variable
// gl_FragCoord", at global scope.
TEST(FragCoord, OnlyOnGlFragCoord) {
  EXPECT_THAT(Check(Stage::Fragment,
                    Fragment("layout(origin_upper_left, pixel_center_integer)uniform vec4 a;\n"))
                  .places,
              ElementsAre("3:48 glsl-fragcoord-redeclaration"));
  EXPECT_THAT(
      Check(Stage::Fragment, Fragment("layout(origin_upper_left) in vec2 gl_PointCoord;\n")).places,
      ElementsAre("3:35 glsl-fragcoord-redeclaration"));
  EXPECT_THAT(
      Check(Stage::Fragment, Fragment("layout(origin_upper_left) varying vec4 gl_FragCoord;\n"))
          .places,
      ElementsAre("3:27 glsl-fragcoord-redeclaration"));
  Checked c = Check(Stage::Fragment, Fragment("layout(pixel_center_integer) in vec4 a;\n"));
  ASSERT_FALSE(c.places.empty());
  EXPECT_EQ(c.places[0], "3:38 glsl-fragcoord-redeclaration");
  EXPECT_THAT(Check(Stage::Fragment,
                    std::string(kRequire) +
                        "void main() {\n  layout(origin_upper_left) in vec4 gl_FragCoord;\n"
                        "  gl_FragColor = gl_FragCoord;\n}\n")
                  .places,
              ElementsAre("4:3 glsl-fragcoord-redeclaration"));
}

TEST(FragCoord, TheRedeclarationsShape) {
  EXPECT_THAT(Check(Stage::Fragment, Fragment("in vec3 gl_FragCoord;\n")).places,
              ElementsAre("3:4 glsl-fragcoord-redeclaration"));
  EXPECT_THAT(
      Check(Stage::Fragment, Fragment("layout(origin_lower_left) in vec4 gl_FragCoord;\n")).places,
      ElementsAre("3:8 glsl-fragcoord-redeclaration"));
  EXPECT_THAT(
      Check(Stage::Fragment, Fragment("layout(origin_upper_left = 1) in vec4 gl_FragCoord;\n"))
          .places,
      ElementsAre("3:26 glsl-fragcoord-redeclaration"));
  EXPECT_THAT(Check(Stage::Fragment, Fragment("layout() in vec4 gl_FragCoord;\n")).places,
              ElementsAre("3:8 glsl-fragcoord-redeclaration"));
  EXPECT_THAT(
      Check(Stage::Fragment, Fragment("layout(origin_upper_left pixel_center_integer) in vec4 "
                                      "gl_FragCoord;\n"))
          .places,
      ElementsAre("3:26 glsl-fragcoord-redeclaration"));
  // Other declarators are glslang's to judge too.
  Checked c = Check(Stage::Fragment, Fragment("in vec4 gl_FragCoord[2];\n"));
  ASSERT_FALSE(c.places.empty());
  EXPECT_EQ(c.places[0], "3:21 glsl-fragcoord-redeclaration");
}

// "Within any shader, the first redeclarations of gl_FragCoord must appear before any use of
// gl_FragCoord."
TEST(FragCoord, RedeclaredBeforeAnyUse) {
  EXPECT_THAT(Check(Stage::Fragment,
                    Fragment("vec2 f() { return gl_FragCoord.xy; }\nin vec4 gl_FragCoord;\n"))
                  .places,
              ElementsAre("4:9 glsl-fragcoord-redeclaration", "note 3:19"));
  EXPECT_THAT(
      Check(Stage::Fragment, Fragment("#define POS gl_FragCoord.xy\nvec2 f() { return POS; }\n"
                                      "in vec4 gl_FragCoord;\n"))
          .places,
      ElementsAre("5:9 glsl-fragcoord-redeclaration", "note 4:19"));
  // A macro that is not used is no use.
  EXPECT_THAT(
      Check(Stage::Fragment, Fragment("#define POS gl_FragCoord.xy\nin vec4 gl_FragCoord;\n"))
          .places,
      IsEmpty());
  // Only the first redeclaration.
  EXPECT_THAT(Check(Stage::Fragment, Fragment("in vec4 gl_FragCoord;\n"
                                              "vec2 f() { return gl_FragCoord.xy; }\n"
                                              "in vec4 gl_FragCoord;\n"))
                  .places,
              IsEmpty());
  // Across the strings of a shader.
  EXPECT_THAT(CheckStrings(Stage::Fragment,
                           {std::string(kRequire) + "vec4 f() { return gl_FragCoord; }\n",
                            "in vec4 gl_FragCoord;\nvoid main() { gl_FragColor = f(); }\n"})
                  .places,
              ElementsAre("1/1:9 glsl-fragcoord-redeclaration", "note 3:19"));
}

// "All redeclarations of gl_FragCoord in all fragment shaders in a single program must have
// the same set of qualifiers."
TEST(FragCoord, TheSameQualifiersEachTime) {
  EXPECT_THAT(
      Check(Stage::Fragment, Fragment("layout(origin_upper_left) in vec4 gl_FragCoord;\n"
                                      "layout(pixel_center_integer) in vec4 gl_FragCoord;\n"))
          .places,
      ElementsAre("4:1 glsl-fragcoord-redeclaration", "note 3:1"));
  EXPECT_THAT(Check(Stage::Fragment, Fragment("in vec4 gl_FragCoord;\n"
                                              "layout(origin_upper_left) in vec4 gl_FragCoord;\n"))
                  .places,
              ElementsAre("4:1 glsl-fragcoord-redeclaration", "note 3:1"));
  EXPECT_THAT(Check(Stage::Fragment,
                    Fragment("layout(pixel_center_integer, origin_upper_left) in vec4 "
                             "gl_FragCoord;\nlayout(ORIGIN_UPPER_LEFT, pixel_center_integer) "
                             "in vec4 gl_FragCoord;\n"))
                  .places,
              IsEmpty());
}

// 3.3: "warn: Behave as specified for enable, except also emit warnings on any detectable use
// of that extension".
TEST(FragCoord, WarnBehavior) {
  Checked c = Check(Stage::Fragment,
                    "#extension GL_ARB_fragment_coord_conventions : warn\n"
                    "layout(origin_upper_left) in vec4 gl_FragCoord;\n" +
                        std::string(kMain));
  EXPECT_THAT(c.places, ElementsAre("2:1 glsl-compile-warning"));
  EXPECT_THAT(c.messages[0], HasSubstr("GL_ARB_fragment_coord_conventions is used"));
}

// Without the extension, 'layout' is an identifier and a global 'in' glslang's to judge.
TEST(FragCoord, OtherTextIsLeftToGlslang) {
  EXPECT_THAT(Check(Stage::Fragment,
                    "float layout(float x) { return x; }\n"
                    "void main() { gl_FragColor = vec4(layout(1.0)); }\n")
                  .places,
              IsEmpty());
  Checked c = Check(Stage::Fragment, "in vec4 gl_FragCoord;\n" + std::string(kMain));
  ASSERT_FALSE(c.places.empty());
  EXPECT_THAT(c.places[0], ::testing::Not(HasSubstr("glsl-fragcoord-redeclaration")));
}

}  // namespace
}  // namespace arbiter::glsl
