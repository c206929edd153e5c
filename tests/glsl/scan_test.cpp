// The scanner the GLSL rules share (glsl/src/scan.h): the tokens of a #if expression.
#include "scan.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

namespace arbiter::glsl {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

std::vector<std::string> Texts(const std::vector<Token>& tokens) {
  std::vector<std::string> out;
  for (const Token& t : tokens) out.emplace_back(t.text);
  return out;
}

std::vector<std::string> Joined(std::string_view text) {
  return Texts(JoinOperators(Tokenize(text)));
}

TEST(JoinOperators, JoinsTheTwoCharacterOperatorsOfIf) {
  EXPECT_THAT(Joined("a<<b>>c<=d>=e==f!=g&&h||i"),
              ElementsAre("a", "<<", "b", ">>", "c", "<=", "d", ">=", "e", "==", "f", "!=", "g",
                          "&&", "h", "||", "i"));
}

TEST(JoinOperators, LeavesOtherPunctuationSingle) {
  EXPECT_THAT(Joined("!(a)-~b%c^d"),
              ElementsAre("!", "(", "a", ")", "-", "~", "b", "%", "c", "^", "d"));
  EXPECT_THAT(Joined("a += b"), ElementsAre("a", "+", "=", "b"));  // no #if operator
  EXPECT_THAT(Joined(""), IsEmpty());
}

TEST(JoinOperators, JoinsOnlyTouchingCharacters) {
  EXPECT_THAT(Joined("a < < b & & c"), ElementsAre("a", "<", "<", "b", "&", "&", "c"));
}

TEST(JoinOperators, JoinsLeftToRight) {
  EXPECT_THAT(Joined("a<<=b"), ElementsAre("a", "<<", "=", "b"));
  EXPECT_THAT(Joined("a&&&b"), ElementsAre("a", "&&", "&", "b"));
  EXPECT_THAT(Joined("a===b"), ElementsAre("a", "==", "=", "b"));
}

TEST(JoinOperators, KeepsTheOffsetOfTheFirstCharacter) {
  std::vector<Token> tokens = JoinOperators(Tokenize("x  || y"));
  ASSERT_EQ(tokens.size(), 3u);
  EXPECT_EQ(tokens[1].kind, Token::Punct);
  EXPECT_EQ(tokens[1].offset, 3u);
  EXPECT_EQ(tokens[2].offset, 6u);
}

TEST(JoinOperators, ReadsADirectivesWords) {
  const std::string text = "#if A&&(B!=2)\n";
  std::vector<Directive> directives = Directives(text);
  ASSERT_EQ(directives.size(), 1u);
  EXPECT_EQ(directives[0].name, "if");
  EXPECT_THAT(Texts(JoinOperators(directives[0].words)),
              ElementsAre("A", "&&", "(", "B", "!=", "2", ")"));
}

// 3.1: a carriage return alone ends a line, as a line feed does (old Mac files): directives,
// '//' comments and the tokens after them end there.
TEST(Scan, LoneCarriageReturnsEndLines) {
  const std::string text = "#version 120\r// note\r#extension GL_X : enable\rfloat f;\r";
  const std::string blanked = BlankComments(text);
  std::vector<Directive> directives = Directives(blanked);
  ASSERT_EQ(directives.size(), 2u);
  EXPECT_EQ(directives[0].name, "version");
  EXPECT_THAT(Texts(directives[0].words), ElementsAre("120"));
  EXPECT_EQ(directives[1].name, "extension");
  EXPECT_EQ(blanked.substr(directives[1].end, 1), "\r");
  EXPECT_THAT(Texts(Tokenize(text)), ElementsAre("float", "f", ";"));
}

}  // namespace
}  // namespace arbiter::glsl
