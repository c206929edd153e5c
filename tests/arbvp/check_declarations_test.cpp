// Tests of naming statements (TEMP ADDRESS ATTRIB PARAM OUTPUT ALIAS), names and kinds.
#include <string>
#include <vector>

#include "check_fixture.h"

namespace arbiter::arbvp {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

TEST(CheckDeclarations, EveryNamingStatementIsAccepted) {
  Checked c = CheckVp(
      "ATTRIB pos = vertex.position;\n"
      "PARAM mvp[4] = { state.matrix.mvp };\n"
      "PARAM one = 1.0;\n"
      "TEMP t0, t1;\n"
      "ADDRESS a0;\n"
      "OUTPUT opos = result.position;\n"
      "ALIAS t2 = t1;\n"
      "ARL a0.x, one.x;\n"
      "DP4 t0, mvp[a0.x], pos;\n"
      "MOV t2, t0;\n"
      "MOV opos, t1;\n");
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
  EXPECT_TRUE(c.result.ok);
}

TEST(CheckDeclarations, IdentifiersTakeLettersDigitsUnderscoreAndDollar) {
  Checked c = CheckFp(
      "TEMP $a, _b, c1_$, Z9;\n"
      "MOV $a, fragment.color;\n"
      "MOV _b, $a;\n"
      "MOV c1_$, _b;\n"
      "MOV Z9, c1_$;\n"
      "MOV result.color, Z9;\n");
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
}

TEST(CheckDeclarations, IdentifierMayNotStartWithDigit) {
  Checked c = CheckFp("TEMP 1a;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:6 arb-syntax-expected"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("expected a variable name"));
}

// "A vertex program will fail to load if it declares the same variable name more than
// once" (ARBvp 2.14.3; ARBfp 3.11.3).
TEST(CheckDeclarations, RedeclarationIsRejectedWithNote) {
  Checked c = CheckFp("TEMP a;\nPARAM a = 1;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:7 arb-decl-redeclared"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("redeclaration of 'a'"));
}

TEST(CheckDeclarations, RedeclarationInOneListIsRejected) {
  Checked c = CheckFp("TEMP a, b, a;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:12 arb-decl-redeclared"));
}

TEST(CheckDeclarations, EveryKindOfRedeclarationIsRejected) {
  Checked c = CheckVp(
      "TEMP x;\n"
      "ATTRIB x = vertex.normal;\n"
      "OUTPUT x = result.color;\n"
      "ADDRESS x;\n"
      "ALIAS x = x;\n"
      "MOV result.position, vertex.position;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:8 arb-decl-redeclared", "4:8 arb-decl-redeclared",
                                         "5:9 arb-decl-redeclared", "6:7 arb-decl-redeclared"));
}

// "... or if it refers to a variable name that has not been previously declared".
TEST(CheckDeclarations, UseBeforeDeclarationIsRejected) {
  Checked c = CheckFp("MOV result.color, c;\nPARAM c = 1;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:19 arb-decl-undeclared"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("use of undeclared identifier 'c'"));
}

TEST(CheckDeclarations, UndeclaredNameGetsSuggestion) {
  Checked c = CheckFp("TEMP color0;\nMOV color1, fragment.color;\nMOV result.color, color0;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:5 arb-decl-undeclared"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("did you mean 'color0'?"));
}

TEST(CheckDeclarations, NamesAreCaseSensitive) {
  Checked c = CheckFp("TEMP r0;\nMOV R0, fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:5 arb-decl-undeclared"));
}

// ALIAS (ARBvp 2.14.3.6, ARBfp 3.11.3.5): a new name for an established variable.
TEST(CheckDeclarations, AliasRefersToTheSameVariable) {
  Checked c = CheckFp(
      "TEMP t;\n"
      "ALIAS u = t;\n"
      "ALIAS v = u;\n"
      "MOV v, fragment.color;\n"
      "MOV result.color, t;\n");
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
  ASSERT_NE(c.result.program, nullptr);
  const Program& p = *c.result.program;
  ASSERT_EQ(p.instructions.size(), 2u);
  EXPECT_EQ(p.instructions[0].dst.var, p.instructions[1].src[0].var);
  EXPECT_EQ(c.result.stats.temporaries, 1);  // aliases are not declarations
}

TEST(CheckDeclarations, AliasOfUndeclaredNameIsRejectedOnce) {
  Checked c = CheckFp("ALIAS b = nope;\nMOV result.color, b;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:11 arb-decl-alias-undeclared"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("'nope'"));
}

TEST(CheckDeclarations, AliasNameMustBeNew) {
  Checked c = CheckFp("TEMP a, b;\nALIAS a = b;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:7 arb-decl-redeclared"));
}

// Reserved keywords "may not be used as identifiers" (ARBvp 2.14.2, ARBfp 3.11.2).
TEST(CheckDeclarations, EveryVertexReservedWordIsRejectedAsName) {
  const std::vector<std::string> words = {
      "ABS", "ADD", "ADDRESS", "ALIAS",  "ARL",    "ATTRIB",  "DP3",    "DP4",   "DPH",   "DST",
      "END", "EX2", "EXP",     "FLR",    "FRC",    "LG2",     "LIT",    "LOG",   "MAD",   "MAX",
      "MIN", "MOV", "MUL",     "OPTION", "OUTPUT", "PARAM",   "POW",    "RCP",   "RSQ",   "SGE",
      "SLT", "SUB", "SWZ",     "TEMP",   "XPD",    "program", "result", "state", "vertex"};
  for (const std::string& w : words) {
    SCOPED_TRACE(w);
    Checked c = CheckVp("TEMP " + w + ";\nMOV result.position, vertex.position;\n");
    EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:6 arb-syntax-reserved-name")) << c.Dump();
  }
}

TEST(CheckDeclarations, EveryFragmentReservedWordIsRejectedAsName) {
  const std::vector<std::string> words = {
      "ABS",      "ABS_SAT", "ADD",     "ADD_SAT", "ALIAS",   "ATTRIB",  "CMP",     "CMP_SAT",
      "COS",      "COS_SAT", "DP3",     "DP3_SAT", "DP4",     "DP4_SAT", "DPH",     "DPH_SAT",
      "DST",      "DST_SAT", "END",     "EX2",     "EX2_SAT", "FLR",     "FLR_SAT", "FRC",
      "FRC_SAT",  "KIL",     "LG2",     "LG2_SAT", "LIT",     "LIT_SAT", "LRP",     "LRP_SAT",
      "MAD",      "MAD_SAT", "MAX",     "MAX_SAT", "MIN",     "MIN_SAT", "MOV",     "MOV_SAT",
      "MUL",      "MUL_SAT", "OPTION",  "OUTPUT",  "PARAM",   "POW",     "POW_SAT", "RCP",
      "RCP_SAT",  "RSQ",     "RSQ_SAT", "SIN",     "SIN_SAT", "SCS",     "SCS_SAT", "SGE",
      "SGE_SAT",  "SLT",     "SLT_SAT", "SUB",     "SUB_SAT", "SWZ",     "SWZ_SAT", "TEMP",
      "TEX",      "TEX_SAT", "TXB",     "TXB_SAT", "TXP",     "TXP_SAT", "XPD",     "XPD_SAT",
      "fragment", "program", "result",  "state",   "texture"};
  for (const std::string& w : words) {
    SCOPED_TRACE(w);
    Checked c = CheckFp("TEMP " + w + ";\n");
    EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:6 arb-syntax-reserved-name")) << c.Dump();
  }
}

// Words reserved only in the other program kind (or nowhere) are ordinary names.
TEST(CheckDeclarations, WordsReservedOnlyElsewhereAreNames) {
  for (std::string w : {"texture", "fragment", "KIL", "CMP", "TEX", "MOV_SAT", "SIN"}) {
    SCOPED_TRACE(w);
    Checked c = CheckVp("TEMP " + w + ";\nMOV result.position, vertex.position;\n");
    EXPECT_THAT(c.ErrorKeys(), IsEmpty()) << c.Dump();
  }
  for (std::string w : {"vertex", "ADDRESS", "ARL", "EXP", "LOG", "KIL_SAT", "mov"}) {
    SCOPED_TRACE(w);
    Checked c = CheckFp("TEMP " + w + ";\n");
    EXPECT_THAT(c.ErrorKeys(), IsEmpty()) << c.Dump();
  }
}

// ---- PARAM arrays (ARBvp 2.14.3.2 "Program Parameter Arrays", ARBfp 3.11.3.2) ---------------

TEST(CheckDeclarations, ParamArraySizeIsTheNumberOfBindings) {
  Checked c = CheckFp(
      "PARAM a[2] = { 1, 2 };\n"
      "PARAM b[] = { 1, {2, 3}, -4 };\n"
      "PARAM m[4] = { state.matrix.mvp };\n"
      "PARAM r[5] = { state.matrix.mvp.row[1..2], program.local[0..2] };\n"
      "ADD result.color, a[1], b[2];\n"
      "ADD result.depth, m[3], r[4];\n");
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
  ASSERT_NE(c.result.program, nullptr);
  const auto& vars = c.result.program->vars;
  ASSERT_GE(vars.size(), 4u);
  EXPECT_EQ(vars[0].bindings.size(), 2u);
  EXPECT_EQ(vars[1].bindings.size(), 3u);
  EXPECT_EQ(vars[2].bindings.size(), 4u);
  EXPECT_EQ(vars[3].bindings.size(), 5u);
  EXPECT_TRUE(vars[3].is_array);
}

// "A vertex program that specifies an array size ... that does not match the number of
// parameter bindings in the initialization list will fail to load"; <optArraySize> is an
// integer from 1.
TEST(CheckDeclarations, ParamArraySizeMismatchIsRejected) {
  Checked fewer = CheckFp("PARAM a[3] = { 1, 2 };\n");
  EXPECT_THAT(fewer.ErrorKeys(), ElementsAre("2:9 arb-param-array-size"));
  EXPECT_THAT(fewer.Errors()[0].message,
              HasSubstr("declared with 3 elements but initialised with 2 bindings"));
  Checked matrix = CheckFp("PARAM m[3] = { state.matrix.mvp };\n");
  EXPECT_THAT(matrix.ErrorKeys(), ElementsAre("2:9 arb-param-array-size"));
  Checked zero = CheckFp("PARAM a[0] = { 1 };\n");
  EXPECT_THAT(zero.ErrorKeys(), ElementsAre("2:9 arb-param-array-size"));
  EXPECT_THAT(zero.Errors()[0].message, HasSubstr("at least one element"));
}

TEST(CheckDeclarations, MalformedParamDeclarationsAreRejected) {
  struct Case {
    const char* decl;
    const char* key;
  };
  for (const Case& k : {
           Case{"PARAM c = {1, 2, 3, 4, 5};", "2:24 arb-param-components"},
           Case{"PARAM a[2] = 1;", "2:14 arb-syntax-expected"},
           Case{"PARAM a[] = { };", "2:15 arb-syntax-expected"},
           Case{"PARAM a[2.0] = { 1, 2 };", "2:9 arb-syntax-expected"},
           Case{"PARAM a = { 1, 2 ;", "2:18 arb-syntax-expected"},
       }) {
    SCOPED_TRACE(k.decl);
    Checked c = CheckFp(std::string(k.decl) + "\n");
    EXPECT_THAT(c.ErrorKeys(), ElementsAre(k.key)) << c.Dump();
  }
}

// ---- variables of the wrong kind ----------------------------------------------------------

TEST(CheckDeclarations, AttribBindsOnlyAttributes) {
  Checked state = CheckFp("ATTRIB a = state.fog.color;\n");
  EXPECT_THAT(state.ErrorKeys(), ElementsAre("2:12 arb-decl-wrong-kind"));
  EXPECT_THAT(state.Errors()[0].message, HasSubstr("declared with PARAM"));
  Checked result = CheckFp("ATTRIB a = result.color;\n");
  EXPECT_THAT(result.ErrorKeys(), ElementsAre("2:12 arb-decl-wrong-kind"));
  EXPECT_THAT(result.Errors()[0].message, HasSubstr("declared with OUTPUT"));
}

TEST(CheckDeclarations, OutputBindsOnlyResults) {
  Checked c = CheckFp("OUTPUT o = fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:12 arb-syntax-expected"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("a result binding"));
}

TEST(CheckDeclarations, AddressRegisterIsNotASourceOrDestination) {
  Checked src = CheckVp("ADDRESS a0;\nMOV result.position, a0;\n");
  EXPECT_THAT(src.ErrorKeys(), ElementsAre("3:22 arb-decl-wrong-kind"));
  EXPECT_THAT(src.Errors()[0].message, HasSubstr("can only be used to index a PARAM array"));
  Checked dst = CheckVp("ADDRESS a0;\nMOV a0, vertex.position;\n");
  EXPECT_THAT(dst.ErrorKeys(), ElementsAre("3:5 arb-decl-wrong-kind"));
  EXPECT_THAT(dst.Errors()[0].message, HasSubstr("only be written by ARL"));
}

TEST(CheckDeclarations, ArlWritesOnlyAddressRegisters) {
  Checked c = CheckVp("TEMP t;\nARL t.x, vertex.position.x;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:5 arb-decl-wrong-kind"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("ARL writes an address register"));
}

TEST(CheckDeclarations, RelativeIndexNeedsAddressRegister) {
  Checked c = CheckVp("TEMP t;\nPARAM a[2] = { 1, 2 };\nMOV result.position, a[t.x];\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("4:24 arb-decl-wrong-kind"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("not an address register"));
}

}  // namespace
}  // namespace arbiter::arbvp
