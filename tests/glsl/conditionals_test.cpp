// The conditional-group tracker (glsl/src/conditionals.h): the reach of every line, and the
// undefined identifiers of the #if and #elif a preprocessor surely evaluates.
#include "conditionals.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

namespace arbiter::glsl {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

// One letter per line of the texts (one source string each, in order): A(ctive), S(kipped),
// U(nknown), read at the line's first character that is not blank (a directive's '#').
std::string Reaches(std::vector<std::string_view> texts, std::string_view preamble = "") {
  const ShaderReach reach(preamble, texts);
  std::string out;
  for (size_t index = 0; index < texts.size(); ++index) {
    const std::string_view text = texts[index];
    for (size_t start = 0; start < text.size();) {
      size_t end = std::min(text.find('\n', start), text.size());
      size_t first = std::min(text.find_first_not_of(" \t", start), end);
      out += "ASU"[static_cast<int>(reach.At(index, static_cast<uint32_t>(first)))];
      start = end + 1;
    }
  }
  return out;
}

TEST(ScanConditionals, NestedIfElifElse) {
  EXPECT_EQ(Reaches({"#if 1\n"
                     "a\n"
                     "#if 0\n"
                     "b\n"
                     "#elif 2 > 1\n"
                     "c\n"
                     "#else\n"
                     "d\n"
                     "#endif\n"
                     "#elif 1\n"
                     "e\n"
                     "#else\n"
                     "f\n"
                     "#endif\n"
                     "g\n"}),
            "AAASAAASAASASAA");
}

// C++ 16.1: in a skipped group, conditionals are only counted; their own lines are skipped.
TEST(ScanConditionals, GroupsInsideASkippedGroupAreSkipped) {
  EXPECT_EQ(
      Reaches({"#if 0\n#if 1\nx\n#else\ny\n#endif\n#define X 1\n#endif\n#ifdef X\nz\n#endif\n"}),
      "ASSSSSSAASA");
}

// The preamble (-D, -U, --preamble) is read before the first line.
TEST(ScanConditionals, IfdefOfPreambleMacros) {
  const std::string_view preamble = "#define FAST 1\n#define SLOW 1\n#undef SLOW\n";
  EXPECT_EQ(Reaches({"#ifdef FAST\n"
                     "a\n"
                     "#endif\n"
                     "#ifdef SLOW\n"
                     "b\n"
                     "#endif\n"
                     "#ifndef SLOW\n"
                     "c\n"
                     "#endif\n"
                     "#if defined(FAST) && FAST == 1\n"
                     "d\n"
                     "#endif\n"},
                    preamble),
            "AAAASAAAAAAA");
}

// A function-like macro, a GL_ name and __LINE__ have values arbiter does not know; a group
// known false inside an unknown one is still skipped; after a branch perhaps taken, the next
// ones are unknown.
TEST(ScanConditionals, UnknownConditions) {
  EXPECT_EQ(Reaches({"#define F(x) x\n"
                     "#if F(1)\n"
                     "a\n"
                     "#if 0\n"
                     "b\n"
                     "#endif\n"
                     "#elif 1\n"
                     "c\n"
                     "#elif 0\n"
                     "d\n"
                     "#else\n"
                     "e\n"
                     "#endif\n"
                     "#ifdef GL_SOME_EXTENSION\n"
                     "f\n"
                     "#endif\n"
                     "#if __LINE__ > 5\n"
                     "g\n"
                     "#endif\n"}),
            "AAUUSUAUASAUAAUAAUA");
}

// A macro (un)defined in an unknown group, or by an #include, has an unknown value.
TEST(ScanConditionals, MacrosOfUnknownGroupsAndIncludes) {
  EXPECT_EQ(Reaches({"#define M 1\n"
                     "#ifdef GL_X\n"
                     "#define N 1\n"
                     "#undef M\n"
                     "#endif\n"
                     "#if N\n"
                     "a\n"
                     "#endif\n"
                     "#ifdef M\n"
                     "b\n"
                     "#endif\n"
                     "#ifdef LATER\n"
                     "c\n"
                     "#endif\n"
                     "#include \"later.glsl\"\n"
                     "#ifdef LATER\n"
                     "d\n"
                     "#endif\n"}),
            "AAUUAAUAAUAASAAAUA");
}

// The source strings are one text: a group goes on into the next string.
TEST(ScanConditionals, GroupsSpanSourceStrings) {
  EXPECT_EQ(Reaches({"#define ON 1\n#if !ON\n", "a\n#else\nb\n#endif\nc\n"}), "AASAAAA");
}

// The undefined identifiers of the #if and #elif a preprocessor surely evaluates, placed at the
// macro's name when they come from its body.
TEST(ScanConditionals, UndefinedIdentifiers) {
  const std::string text =
      "#define B A + C\n#define A 1\n#define F(x) x\n#if UNDEFINED\n#elif B\n#endif\n"
      "#if F(1)\n#elif NOPE\n#endif\n#if 0\n#if NOPE\n#endif\n#endif\n";
  GroupTracker tracker("");
  std::vector<std::string> found;
  for (const Directive& d : Directives(text)) {
    for (const Token& t : tracker.Follow(d).undefined) {
      found.push_back(std::string(t.text) + "@" + std::to_string(t.offset));
    }
  }
  EXPECT_THAT(found, ElementsAre("UNDEFINED@47", "C@63"));
  EXPECT_THAT(GroupTracker("#define X 1\n").Follow(Directives("#if X\n")[0]).undefined, IsEmpty());
}

}  // namespace
}  // namespace arbiter::glsl
