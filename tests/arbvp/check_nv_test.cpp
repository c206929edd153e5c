// Tests of the NV program options' grammar: opcode suffixes, condition codes, |abs|, labels
// and flow blocks, address register vectors, SHORT/LONG, result.clip and fragment.facing
// (NV_vertex_program2_option, NV_vertex_program3, NV_fragment_program_option,
// NV_fragment_program2).
#include <string>

#include "check_fixture.h"

namespace arbiter::arbvp {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::UnorderedElementsAre;

const Instruction& Only(const Checked& c) { return c.result.program->instructions.at(0); }

TEST(CheckNv, SuffixesSplitIntoOpcodeAndModifiers) {
  Checked c = CheckFp("OPTION NV_fragment_program2;\nTEMP t;\nADDHC_SSAT t, fragment.color, 1;\n");
  ASSERT_THAT(c.ErrorKeys(), IsEmpty()) << c.Dump();
  const Instruction& inst = c.result.program->instructions.at(0);
  EXPECT_EQ(inst.op, Opcode::ADD);
  EXPECT_EQ(inst.precision, Precision::H);
  EXPECT_EQ(inst.cc_update, 0);
  EXPECT_TRUE(inst.signed_saturate);
  EXPECT_FALSE(inst.saturate);
}

// "DDXC" is DDX with the C suffix: the opcode's own X is not a precision.
TEST(CheckNv, OpcodeEndingInXKeepsIt) {
  Checked c = CheckFp("OPTION NV_fragment_program;\nTEMP t;\nDDXC t, fragment.color;\n");
  ASSERT_THAT(c.ErrorKeys(), IsEmpty()) << c.Dump();
  EXPECT_EQ(Only(c).op, Opcode::DDX);
  EXPECT_EQ(Only(c).precision, Precision::Default);
  EXPECT_EQ(Only(c).cc_update, 0);
}

// Table X.5 of NV_fragment_program_option: DST has no X precision form.
TEST(CheckNv, PrecisionTheTableDoesNotListIsRefused) {
  Checked c = CheckFp("OPTION NV_fragment_program;\nTEMP t;\nDSTX t, fragment.color, 1;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("4:1 arb-syntax-modifier")) << c.Dump();
}

TEST(CheckNv, SuffixesNeedTheOption) {
  Checked c = CheckFp("TEMP t;\nMOVC t, fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:1 arb-syntax-modifier")) << c.Dump();
  ASSERT_FALSE(c.Errors().empty());
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("NV_fragment_program"));
}

TEST(CheckNv, SecondConditionRegisterIsVertexProgram3s) {
  Checked ok = CheckVp(
      "OPTION NV_vertex_program3;\nTEMP t;\nMOVC1 t, vertex.color;\n"
      "MOV result.position (GT1.x), t;\n");
  EXPECT_THAT(ok.ErrorKeys(), IsEmpty()) << ok.Dump();
  Checked bad = CheckVp(
      "OPTION NV_vertex_program2;\nTEMP t;\nMOVC1 t, vertex.color;\n"
      "MOV result.position, t;\n");
  EXPECT_THAT(bad.ErrorKeys(), ElementsAre("4:1 arb-syntax-modifier")) << bad.Dump();
}

TEST(CheckNv, ConditionalWriteMaskAndAbsoluteValue) {
  Checked c = CheckFp(
      "OPTION NV_fragment_program;\nTEMP t;\nMOVC t, -|fragment.color.xxyy|;\n"
      "MOV result.color.xy (LT.zwzw), t;\n");
  ASSERT_THAT(c.ErrorKeys(), IsEmpty()) << c.Dump();
  const auto& insts = c.result.program->instructions;
  EXPECT_TRUE(insts[0].src[0].abs);
  EXPECT_TRUE(insts[0].src[0].negate);
  EXPECT_EQ(insts[0].src[0].swizzle[2], Swz::Y);
  ASSERT_TRUE(insts[1].dst.cc.present);
  EXPECT_EQ(insts[1].dst.cc.rule, CcRule::LT);
  EXPECT_EQ(insts[1].dst.cc.swizzle[0], Swz::Z);
  EXPECT_EQ(insts[1].dst.mask, 0x3);
}

TEST(CheckNv, AbsoluteValueAndConditionMasksNeedTheOption) {
  Checked abs = CheckFp("MOV result.color, |fragment.color|;\n");
  EXPECT_THAT(abs.ErrorKeys(), ElementsAre("2:19 arb-syntax-nv-construct")) << abs.Dump();
  Checked cc = CheckVp("MOV result.position (GT.x), vertex.position;\n");
  EXPECT_THAT(cc.ErrorKeys(), ElementsAre("2:21 arb-syntax-nv-construct")) << cc.Dump();
}

TEST(CheckNv, OpcodesOfAnOptionNeedIt) {
  Checked c = CheckVp("TEMP t;\nSEQ t, vertex.color, 1;\nMOV result.position, t;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:1 arb-option-required")) << c.Dump();
  ASSERT_FALSE(c.Errors().empty());
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("needs OPTION NV_vertex_program2"));
  Checked rep = CheckFp("OPTION NV_fragment_program;\nREP 4;\nENDREP;\n");
  EXPECT_THAT(rep.ErrorKeys(), ElementsAre("3:1 arb-option-required", "4:1 arb-option-required"))
      << rep.Dump();
}

TEST(CheckNv, BranchesResolveTheirLabels) {
  Checked c = CheckVp(
      "OPTION NV_vertex_program2;\nTEMP t;\nMOVC t, vertex.color;\nBRA skip (EQ.x);\n"
      "MOV t, vertex.normal;\nskip:\nMOV result.position, t;\n");
  ASSERT_THAT(c.ErrorKeys(), IsEmpty()) << c.Dump();
  const auto& insts = c.result.program->instructions;
  EXPECT_EQ(insts[1].op, Opcode::BRA);
  EXPECT_EQ(insts[1].jump, 3);
  EXPECT_EQ(insts[1].cond.rule, CcRule::EQ);
}

TEST(CheckNv, UndefinedAndRepeatedLabels) {
  Checked c = CheckVp(
      "OPTION NV_vertex_program2;\nCAL nowhere;\nhere:\nhere:\nMOV result.position, "
      "vertex.position;\n");
  // The renderers put diagnostics in position order; the check reports labels first.
  EXPECT_THAT(c.ErrorKeys(),
              UnorderedElementsAre("3:5 arb-flow-label-undefined", "5:1 arb-flow-label-repeated"))
      << c.Dump();
}

TEST(CheckNv, LabelsNeedTheOption) {
  Checked c = CheckFp("OPTION NV_fragment_program;\nhere:\nMOV result.color, 1;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:1 arb-syntax-nv-construct")) << c.Dump();
}

TEST(CheckNv, BlocksNestAndMatch) {
  Checked c = CheckFp(
      "OPTION NV_fragment_program2;\nTEMP t;\nMOVC t, fragment.color;\nIF GT.x;\n"
      "REP {3};\nBRK (EQ.y);\nENDREP;\nELSE;\nMOV t, 0;\nENDIF;\nMOV result.color, t;\n");
  ASSERT_THAT(c.ErrorKeys(), IsEmpty()) << c.Dump();
  const auto& insts = c.result.program->instructions;
  EXPECT_EQ(insts[1].jump, 5);  // IF -> ELSE
  EXPECT_EQ(insts[2].jump, 4);  // REP -> ENDREP
  EXPECT_EQ(insts[3].jump, 4);  // BRK -> ENDREP
  EXPECT_EQ(insts[4].jump, 2);  // ENDREP -> REP
  EXPECT_EQ(insts[5].jump, 7);  // ELSE -> ENDIF
}

TEST(CheckNv, UnmatchedBlocksAndStrayBreak) {
  Checked c = CheckFp(
      "OPTION NV_fragment_program2;\nBRK;\nENDIF;\nLOOP {1, 0, 1};\n"
      "MOV result.color, 1;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:1 arb-flow-break-outside-loop",
                                         "4:1 arb-flow-unmatched", "5:1 arb-flow-unmatched"))
      << c.Dump();
}

// NV_vertex_program3 2.14.5.43: POPA takes no write mask but .xyzw.
TEST(CheckNv, PopaWritesTheWholeRegister) {
  Checked c = CheckVp(
      "OPTION NV_vertex_program3;\nADDRESS a;\nARL a, vertex.color;\nPUSHA a;\n"
      "POPA a.xy;\nMOV result.position, vertex.position;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("6:6 arb-operand-mask")) << c.Dump();
}

TEST(CheckNv, AddressRegistersAreVectors) {
  Checked c = CheckVp(
      "OPTION NV_vertex_program2;\nADDRESS a;\nPARAM p[4] = {program.local[0..3]};\n"
      "ARL a.xy, vertex.color;\nARA a.xy, a;\nMOV result.position, p[a.y + 1];\n");
  ASSERT_THAT(c.ErrorKeys(), IsEmpty()) << c.Dump();
  const auto& insts = c.result.program->instructions;
  EXPECT_EQ(insts[0].dst.mask, 0x3);
  EXPECT_EQ(insts[2].src[0].address_component, 1);
  EXPECT_EQ(insts[2].src[0].index, 1);
}

TEST(CheckNv, ScalarConstantsNeedNoSuffix) {
  Checked c = CheckFp("OPTION NV_fragment_program;\nCOS result.color, 3.14159;\n");
  EXPECT_THAT(c.ErrorKeys(), IsEmpty()) << c.Dump();
}

TEST(CheckNv, SizedTemporariesAndNewBindings) {
  Checked fp = CheckFp(
      "OPTION NV_fragment_program2;\nSHORT TEMP h;\nLONG TEMP f;\n"
      "MOV h, fragment.facing;\nMOV result.color, h;\n");
  ASSERT_THAT(fp.ErrorKeys(), IsEmpty()) << fp.Dump();
  EXPECT_EQ(fp.result.program->vars.at(0).size, VarSize::Short);
  EXPECT_EQ(fp.result.program->vars.at(1).size, VarSize::Long);
  Checked vp = CheckVp(
      "OPTION NV_vertex_program2;\nMOV result.position, vertex.position;\n"
      "DP4 result.clip[0].x, vertex.position, program.local[0];\n");
  EXPECT_THAT(vp.ErrorKeys(), IsEmpty()) << vp.Dump();
  Checked no = CheckFp("SHORT TEMP h;\nMOV result.color, fragment.color;\n");
  EXPECT_THAT(no.ErrorKeys(), ElementsAre("2:1 arb-syntax-nv-construct")) << no.Dump();
}

TEST(CheckNv, KilTakesAConditionTest) {
  Checked c = CheckFp(
      "OPTION NV_fragment_program;\nTEMP t;\nMOVC t, fragment.color;\n"
      "KIL LT.xyzw;\nMOV result.color, t;\n");
  ASSERT_THAT(c.ErrorKeys(), IsEmpty()) << c.Dump();
  const Instruction& kil = c.result.program->instructions.at(1);
  EXPECT_EQ(kil.src_count, 0);
  EXPECT_TRUE(kil.cond.present);
  EXPECT_EQ(kil.cond.rule, CcRule::LT);
}

}  // namespace
}  // namespace arbiter::arbvp
