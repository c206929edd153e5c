// Tests of the program header: empty input, the two header strings, malformed headers, --stage.
#include <string>

#include "check_fixture.h"

namespace arbiter::arbvp {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

// Checks `text` as the CLI does with --stage: the caller expects a program of `kind`.
Checked CheckExpecting(const std::string& text, ProgramKind kind) {
  CheckOptions options;
  options.expected_kind = kind;
  return Check(text, options);
}

TEST(CheckHeader, VertexHeaderGivesVertexProgram) {
  Checked c = Check("!!ARBvp1.0\nMOV result.position, vertex.position;\nEND\n");
  EXPECT_TRUE(c.result.ok) << c.Dump();
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
  ASSERT_NE(c.result.program, nullptr);
  EXPECT_EQ(c.result.program->kind, ProgramKind::Vertex);
}

TEST(CheckHeader, FragmentHeaderGivesFragmentProgram) {
  Checked c = Check("!!ARBfp1.0\nEND\n");
  EXPECT_TRUE(c.result.ok) << c.Dump();
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
  ASSERT_NE(c.result.program, nullptr);
  EXPECT_EQ(c.result.program->kind, ProgramKind::Fragment);
}

// ARBvp 2.14.2: parsing begins with the character immediately after the header, so the
// program may continue on the header's line.
TEST(CheckHeader, ProgramMayContinueOnTheHeaderLine) {
  Checked c = Check("!!ARBfp1.0 MOV result.color, fragment.color; END");
  EXPECT_TRUE(c.result.ok) << c.Dump();
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
}

TEST(CheckHeader, EmptyInputIsRejected) {
  Checked c = Check("");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("1:1 arb-input-empty"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("empty"));
  EXPECT_FALSE(c.result.ok);
  EXPECT_EQ(c.result.program, nullptr);
}

TEST(CheckHeader, WhitespaceOnlyInputIsRejected) {
  Checked c = Check(" \t\r\n\n  ");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("1:1 arb-input-empty"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("only whitespace"));
  EXPECT_EQ(c.result.program, nullptr);
}

// "A vertex program is required to begin with the header string "!!ARBvp1.0", without any
// preceding whitespace." (ARBvp 2.14.2; ARBfp 3.11.2 likewise)
TEST(CheckHeader, LeadingWhitespaceIsRejected) {
  Checked c = Check(" !!ARBvp1.0\nMOV result.position, vertex.position;\nEND\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("1:1 arb-header-missing"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("very first bytes"));
  EXPECT_EQ(c.result.program, nullptr);
}

TEST(CheckHeader, LeadingNewlineIsRejected) {
  Checked c = Check("\n!!ARBfp1.0\nEND\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("1:1 arb-header-missing"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("very first bytes"));
}

TEST(CheckHeader, ByteOrderMarkIsRejected) {
  Checked c = Check("\xEF\xBB\xBF!!ARBfp1.0\nEND\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("1:1 arb-header-missing"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("byte-order mark"));
}

TEST(CheckHeader, OtherArbVersionIsRejected) {
  Checked c = Check("!!ARBvp2.0\nMOV result.position, vertex.position;\nEND\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("1:1 arb-header-missing"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("unsupported program header '!!ARBvp2.0'"));
}

TEST(CheckHeader, NvHeaderIsRejected) {
  Checked c = Check("!!VP1.0\nMOV o[HPOS], v[OPOS];\nEND\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("1:1 arb-header-missing"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("'!!VP1.0' is not an ARB program header"));
}

// Header strings are case-sensitive like every other token.
TEST(CheckHeader, LowerCaseHeaderIsRejected) {
  Checked c = Check("!!arbfp1.0\nEND\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("1:1 arb-header-missing"));
}

TEST(CheckHeader, MissingHeaderIsRejected) {
  Checked c = Check("MOV result.color, fragment.color;\nEND\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("1:1 arb-header-missing"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("missing program header"));
}

TEST(CheckHeader, ExpectedKindMatchingHeaderIsAccepted) {
  Checked vp = CheckExpecting("!!ARBvp1.0\nMOV result.position, vertex.position;\nEND\n",
                              ProgramKind::Vertex);
  EXPECT_TRUE(vp.result.ok) << vp.Dump();
  Checked fp = CheckExpecting("!!ARBfp1.0\nEND\n", ProgramKind::Fragment);
  EXPECT_TRUE(fp.result.ok) << fp.Dump();
}

TEST(CheckHeader, VertexProgramWhereFragmentExpectedIsRejected) {
  Checked c = CheckExpecting("!!ARBvp1.0\nMOV result.position, vertex.position;\nEND\n",
                             ProgramKind::Fragment);
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("1:1 arb-header-stage"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("expected a fragment program ('!!ARBfp1.0')"));
  EXPECT_FALSE(c.result.ok);
}

TEST(CheckHeader, FragmentProgramWhereVertexExpectedIsRejected) {
  Checked c = CheckExpecting("!!ARBfp1.0\nEND\n", ProgramKind::Vertex);
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("1:1 arb-header-stage"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("expected a vertex program ('!!ARBvp1.0')"));
}

TEST(CheckHeader, LooksLikeArbProgram) {
  EXPECT_TRUE(LooksLikeArbProgram("!!ARBvp1.0\nEND\n"));
  EXPECT_TRUE(LooksLikeArbProgram("!!ARBfp1.0"));
  EXPECT_FALSE(LooksLikeArbProgram(" !!ARBfp1.0"));
  EXPECT_FALSE(LooksLikeArbProgram("!!VP1.0"));
  EXPECT_FALSE(LooksLikeArbProgram(""));
}

}  // namespace
}  // namespace arbiter::arbvp
