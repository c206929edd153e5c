// Tests of tokens and statement syntax, and of recovery after a syntax error.
#include <string>

#include "check_fixture.h"

namespace arbiter::arbvp {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

// ---- lexical ----------------------------------------------------------------------------

// "A program is invalid if it contains any undefined tokens or characters." (ARBvp 2.14.2)
TEST(CheckLexical, InvalidCharacterIsRejected) {
  Checked c = CheckFp("MOV result.color, @fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:19 arb-lex-invalid-char"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("invalid character '@'"));
  EXPECT_FALSE(c.result.ok);
}

TEST(CheckLexical, RunOfInvalidCharactersIsReportedOnce) {
  Checked c = CheckFp("MOV result.color, @`%fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:19 arb-lex-invalid-char"));
}

TEST(CheckLexical, NulByteIsRejected) {
  std::string body = "MOV result.color, fragment.color;";
  body.push_back('\0');
  body += "\n";
  Checked c = CheckFp(body);
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:34 arb-lex-invalid-char"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("NUL byte"));
}

TEST(CheckLexical, ControlCharacterIsRejected) {
  Checked c = CheckFp("MOV result.color,\x01 fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:18 arb-lex-invalid-char"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("control character 0x01"));
}

TEST(CheckLexical, NonAsciiOutsideCommentIsAnError) {
  Checked c = CheckFp("MOV result.color, fragment.color; \xC3\xA9\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:35 arb-lex-invalid-char"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("non-ASCII byte 0xC3"));
}

// Program strings are ASCII, but a comment is skipped whole: only a warning, once.
TEST(CheckLexical, NonAsciiInCommentIsOnlyAWarning) {
  Checked c = CheckFp("# caf\xC3\xA9 au lait\nMOV result.color, fragment.color; # na\xC3\xAFve\n");
  EXPECT_THAT(c.ErrorKeys(), IsEmpty()) << c.Dump();
  EXPECT_THAT(c.WarningKeys(), ElementsAre("2:6 arb-lex-non-ascii"));
  EXPECT_THAT(c.Warnings()[0].message, HasSubstr("7-bit ASCII"));
  EXPECT_TRUE(c.result.ok);
}

TEST(CheckLexical, ExponentWithoutDigitsIsRejected) {
  Checked c = CheckFp("PARAM c = 1e;\nMOV result.color, c;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:11 arb-lex-bad-number"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("malformed number '1e'"));
}

TEST(CheckLexical, SignedExponentWithoutDigitsIsRejected) {
  Checked c = CheckFp("PARAM c = {0, 1.5e+};\nMOV result.color, c;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:15 arb-lex-bad-number"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("'1.5e+'"));
}

// <floatConstant>: integer part, fraction, exponent; either the integer or the fraction
// part may be missing, and either the point or the exponent (ARBvp 2.14.2).
TEST(CheckLexical, EveryFloatConstantFormIsAccepted) {
  Checked c = CheckFp(
      "PARAM a[] = { 1, 1.5, .5, 5., 1e5, 1E5, 1.5e-3, .5e+2, 5.e1, -0.25, +3 };\n"
      "MOV result.color, a[10];\n");
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
  ASSERT_NE(c.result.program, nullptr);
  ASSERT_EQ(c.result.program->vars.size(), 2u);
  const std::vector<Binding>& b = c.result.program->vars[0].bindings;
  ASSERT_EQ(b.size(), 11u);
  EXPECT_FLOAT_EQ(b[2].value[0], 0.5f);
  EXPECT_FLOAT_EQ(b[3].value[0], 5.0f);
  EXPECT_FLOAT_EQ(b[6].value[0], 0.0015f);
  EXPECT_FLOAT_EQ(b[7].value[0], 50.0f);
  EXPECT_FLOAT_EQ(b[9].value[0], -0.25f);
}

// Comments end at a newline, a carriage return or the end of the text.
TEST(CheckLexical, CommentsEndAtCarriageReturnAndEndOfText) {
  Checked c = Check("!!ARBfp1.0 # header comment\rMOV result.color, fragment.color;# x\rEND # end");
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
}

TEST(CheckLexical, PositionsCountCrLfAsOneLineEnd) {
  Checked c = Check("!!ARBfp1.0\r\n# comment\r\nMOV result.color, @fragment.color;\r\nEND\r\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:19 arb-lex-invalid-char"));
}

TEST(CheckLexical, PositionsCountLoneCarriageReturnAsLineEnd) {
  Checked c = Check("!!ARBfp1.0\r# comment\rMOV result.color, @fragment.color;\rEND\r");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:19 arb-lex-invalid-char"));
}

TEST(CheckLexical, TabsAndFormFeedsAreWhitespace) {
  Checked c = CheckFp("MOV\tresult.color ,\f fragment.color\t;\n");
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
}

// ---- program structure --------------------------------------------------------------------

TEST(CheckSyntax, MissingEndIsRejected) {
  Checked c = Check("!!ARBfp1.0\nMOV result.color, fragment.color;\n");
  // The end of the text is shown at the end of the last line.
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:34 arb-syntax-missing-end"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("without 'END'"));
}

// <program> ends with "END": a token after it is not part of any program.
TEST(CheckSyntax, TextAfterEndIsRejected) {
  Checked c = Check("!!ARBfp1.0\nEND\nMOV result.color, fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:1 arb-syntax-after-end"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("unexpected 'MOV' after 'END'"));
  EXPECT_FALSE(c.result.ok);
}

TEST(CheckSyntax, CommentAfterEndIsSilent) {
  Checked c = Check("!!ARBfp1.0\nEND\n# trailing comment\n");
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
}

TEST(CheckSyntax, EmptyStatementIsRejected) {
  Checked c = CheckFp(";\nMOV result.color, fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:1 arb-syntax-expected"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("expected an instruction or a declaration"));
}

// A missing ';' is reported just after the previous token; the next statement still parses.
TEST(CheckSyntax, MissingSemicolonPointsAfterPreviousToken) {
  Checked c = CheckFp("TEMP R0\nMOV R0, fragment.color;\nMOV result.color, R0;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:8 arb-syntax-missing-semicolon"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("expected ';' after the"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("found 'MOV'"));
}

TEST(CheckSyntax, MissingSemicolonBeforeEnd) {
  Checked c = CheckFp("MOV result.color, fragment.color\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:33 arb-syntax-missing-semicolon"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("found 'END'"));
}

TEST(CheckSyntax, MissingSemicolonAndEndAtEndOfText) {
  Checked c = Check("!!ARBfp1.0\nMOV result.color, fragment.color");
  EXPECT_THAT(c.ErrorKeys(),
              ElementsAre("2:33 arb-syntax-missing-semicolon", "2:33 arb-syntax-missing-end"));
}

TEST(CheckSyntax, ExtraOperandOnTheSameLineIsAMissingSemicolon) {
  Checked c = CheckFp("MOV result.color, fragment.color fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:33 arb-syntax-missing-semicolon"));
}

TEST(CheckSyntax, MissingCommaIsRejected) {
  Checked c = CheckFp("MOV result.color fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:18 arb-syntax-expected"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("expected ','"));
}

TEST(CheckSyntax, MissingOperandIsRejected) {
  Checked c = CheckFp("ADD result.color, fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:33 arb-syntax-expected"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("found ';'"));
}

TEST(CheckSyntax, KilTakesOneOperand) {
  Checked ok = CheckFp("KIL -fragment.color;\n");
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  Checked c = CheckFp("KIL fragment.color, fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:19 arb-syntax-expected"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("exactly one source operand"));
}

TEST(CheckSyntax, UnknownInstructionIsRejected) {
  Checked c = CheckFp("FOO result.color, fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:1 arb-syntax-unknown-instruction"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("unknown instruction 'FOO'"));
}

// Names are case-sensitive (ARBvp 2.14.2 <identifier>): "mov" is not MOV.
TEST(CheckSyntax, LowerCaseInstructionIsRejectedWithHint) {
  Checked c = CheckFp("mov result.color, fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:1 arb-syntax-unknown-instruction"));
  EXPECT_THAT(c.Errors()[0].message,
              HasSubstr("did you mean 'MOV'? (instructions are upper case)"));
}

TEST(CheckSyntax, VariableInStatementPositionIsRejected) {
  Checked c = CheckFp("TEMP a;\na;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:1 arb-syntax-unknown-instruction"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("found the variable 'a'"));
}

TEST(CheckSyntax, AddressStatementInFragmentProgramIsRejected) {
  Checked c = CheckFp("ADDRESS A0;\nMOV result.color, fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:1 arb-syntax-statement-stage"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("only in vertex programs"));
}

// ---- error recovery (style E6/E7: report every independent error) ---------------------------

TEST(CheckRecovery, TwoIndependentErrorsAreBothReported) {
  Checked c = CheckFp("MOV R9, fragment.color;\nMOV result.color, fragment.colr;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:5 arb-decl-undeclared", "3:28 arb-binding-unknown"));
}

TEST(CheckRecovery, ErrorAfterMissingSemicolonIsReported) {
  Checked c = CheckFp("TEMP R0\nMOV result.color, R1;\n");
  EXPECT_THAT(c.ErrorKeys(),
              ElementsAre("2:8 arb-syntax-missing-semicolon", "3:19 arb-decl-undeclared"));
}

// A statement with a missing ';' on the same line is abandoned up to the next ';'.
TEST(CheckRecovery, SameLineMissingSemicolonSkipsToNextSemicolon) {
  Checked c = CheckFp("TEMP a TEMP b;\nMOV result.color, b;\n");
  EXPECT_THAT(c.ErrorKeys(),
              ElementsAre("2:7 arb-syntax-missing-semicolon", "3:19 arb-decl-undeclared"));
}

// A declaration that failed leaves a poisoned name: its uses are not reported again.
TEST(CheckRecovery, FailedDeclarationDoesNotCascade) {
  Checked c = CheckFp(
      "PARAM p = state.fog.colour;\n"
      "TEMP t;\n"
      "MOV t, p;\n"
      "MOV result.color, q;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:21 arb-binding-unknown", "5:19 arb-decl-undeclared"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("did you mean 'color'?"));
}

TEST(CheckRecovery, ErrorsInEveryStatementAreReported) {
  Checked c = CheckVp(
      "TEMP a, a;\n"
      "PARAM p = state.light[0].colour;\n"
      "MOV result.position, vertex.position.xy;\n"
      "MOV_SAT result.color, vertex.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:9 arb-decl-redeclared", "3:26 arb-binding-unknown",
                                         "4:38 arb-operand-swizzle", "5:1 arb-syntax-saturate-vp"));
}

}  // namespace
}  // namespace arbiter::arbvp
