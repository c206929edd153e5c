// Tests of the opcode table (opcodes.def) against both grammars: stages, operands, _SAT.
#include <string>
#include <vector>

#include "check_fixture.h"

namespace arbiter::arbvp {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

// Declarations before the instruction: a temporary, and in vertex programs an address
// register. The instruction is on program line 4 (vertex) or 3 (fragment).
std::string Prefix(ProgramKind kind) {
  return kind == ProgramKind::Vertex ? "TEMP t;\nADDRESS a;\n" : "TEMP t;\n";
}
int InstructionLine(ProgramKind kind) { return kind == ProgramKind::Vertex ? 4 : 3; }

// A correct operand list for `signature`, reading attribute `s`.
std::string Operands(OpSignature signature, const std::string& s) {
  switch (signature) {
    case OpSignature::Vector:
      return " t, " + s + ";";
    case OpSignature::Scalar:
      return " t, " + s + ".x;";
    case OpSignature::BinSc:
      return " t, " + s + ".x, -" + s + ".y;";
    case OpSignature::Binary:
      return " t, " + s + ", " + s + ".wzyx;";
    case OpSignature::Ternary:
      return " t, " + s + ", -" + s + ", " + s + ".x;";
    case OpSignature::Swz:
      return " t, " + s + ", x, -y, 0, 1;";
    case OpSignature::Arl:
      return " a.x, " + s + ".x;";
    case OpSignature::Sample:
      return " t, " + s + ", texture[0], 2D;";
    case OpSignature::Kil:
      return " " + s + ";";
    case OpSignature::VecSca:
      return " t, " + s + ", " + s + ".x;";
    case OpSignature::Ara:
      return " a.xy, a;";
    case OpSignature::Arr:
      return " a.x, " + s + ";";
    case OpSignature::PushA:
      return " a;";
    case OpSignature::PopA:
      return " a;";
    case OpSignature::TexD:
      return " t, " + s + ", " + s + ", " + s + ", texture[0], 2D;";
    case OpSignature::Branch:
      return " there;";
    case OpSignature::FlowCc:
    case OpSignature::EndFlow:
      return ";";
    case OpSignature::If:
      return " GT.x;";
    case OpSignature::Loop:
      return " " + s + ";";
  }
  return ";";
}

std::string Attribute(ProgramKind kind) {
  return kind == ProgramKind::Vertex ? "vertex.position" : "fragment.color";
}

Checked CheckInstruction(ProgramKind kind, const std::string& opcode, OpSignature signature) {
  std::string body = Prefix(kind) + opcode + Operands(signature, Attribute(kind)) + "\n";
  return kind == ProgramKind::Vertex ? CheckVp(body) : CheckFp(body);
}

std::string Key(ProgramKind kind, const char* code) {
  return std::to_string(InstructionLine(kind)) + ":1 " + code;
}

// Accepted with its operand form where the table says it exists, arb-syntax-opcode-stage
// elsewhere; parsed into the opcode and counted in its class.
void ExpectStages(const OpcodeInfo& info) {
  for (ProgramKind kind : {ProgramKind::Vertex, ProgramKind::Fragment}) {
    SCOPED_TRACE(kind == ProgramKind::Vertex ? "vertex" : "fragment");
    Checked c = CheckInstruction(kind, std::string(info.name), info.signature);
    if (!OpcodeInStage(info.op, kind)) {
      EXPECT_THAT(c.ErrorKeys(), ElementsAre(Key(kind, "arb-syntax-opcode-stage"))) << c.Dump();
      ASSERT_FALSE(c.Errors().empty());
      EXPECT_THAT(c.Errors()[0].message, HasSubstr("'" + std::string(info.name) + "' is a"));
      continue;
    }
    EXPECT_THAT(c.ErrorKeys(), IsEmpty()) << c.Dump();
    ASSERT_NE(c.result.program, nullptr);
    ASSERT_EQ(c.result.program->instructions.size(), 1u);
    const Instruction& inst = c.result.program->instructions[0];
    EXPECT_EQ(inst.op, info.op);
    EXPECT_FALSE(inst.saturate);
    EXPECT_EQ(inst.src_count, SourceCount(info.signature));
    EXPECT_EQ(c.result.stats.alu_instructions, info.klass == OpClass::Alu ? 1 : 0);
    EXPECT_EQ(c.result.stats.tex_instructions, info.klass == OpClass::Tex ? 1 : 0);
  }
}

// ARBfp 3.11.2 lists "<op>_SAT" for every instruction but KIL; ARBvp has no _SAT.
void ExpectSaturateSuffix(const OpcodeInfo& info) {
  std::string sat = std::string(info.name) + "_SAT";
  if (OpcodeInStage(info.op, ProgramKind::Fragment)) {
    Checked c = CheckInstruction(ProgramKind::Fragment, sat, info.signature);
    if (info.op == Opcode::KIL) {
      EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:1 arb-syntax-unknown-instruction")) << c.Dump();
    } else {
      EXPECT_THAT(c.ErrorKeys(), IsEmpty()) << c.Dump();
      ASSERT_NE(c.result.program, nullptr);
      ASSERT_EQ(c.result.program->instructions.size(), 1u);
      EXPECT_TRUE(c.result.program->instructions[0].saturate);
      EXPECT_EQ(c.result.program->instructions[0].op, info.op);
    }
  }
  if (OpcodeInStage(info.op, ProgramKind::Vertex)) {
    Checked c = CheckInstruction(ProgramKind::Vertex, sat, info.signature);
    EXPECT_THAT(c.ErrorKeys(), ElementsAre("4:1 arb-syntax-saturate-vp")) << c.Dump();
    ASSERT_FALSE(c.Errors().empty());
    EXPECT_THAT(c.Errors()[0].message, HasSubstr("only in fragment programs"));
  }
}

// Scalar signatures take <scalarSrcReg>: a vector operand is refused.
void ExpectScalarOperand(const OpcodeInfo& info) {
  if (info.signature != OpSignature::Scalar && info.signature != OpSignature::BinSc &&
      info.signature != OpSignature::Arl) {
    return;
  }
  ProgramKind kind =
      OpcodeInStage(info.op, ProgramKind::Vertex) ? ProgramKind::Vertex : ProgramKind::Fragment;
  std::string dst = info.signature == OpSignature::Arl ? " a.x, " : " t, ";
  std::string body = Prefix(kind) + std::string(info.name) + dst + Attribute(kind) + ".xyzw" +
                     (info.signature == OpSignature::BinSc ? ", " + Attribute(kind) + ".x" : "") +
                     ";\n";
  Checked c = kind == ProgramKind::Vertex ? CheckVp(body) : CheckFp(body);
  // The swizzle follows "<NAME> t, <attribute>.".
  size_t column = info.name.size() + dst.size() + Attribute(kind).size() + 2;
  EXPECT_THAT(c.ErrorKeys(), ElementsAre(std::to_string(InstructionLine(kind)) + ":" +
                                         std::to_string(column) + " arb-operand-scalar"))
      << body << c.Dump();
}

class CheckOpcodeRow : public testing::TestWithParam<OpcodeInfo> {};

TEST_P(CheckOpcodeRow, StagesSaturateAndOperands) {
  {
    SCOPED_TRACE("stages");
    ExpectStages(GetParam());
  }
  {
    SCOPED_TRACE("_SAT");
    ExpectSaturateSuffix(GetParam());
  }
  {
    SCOPED_TRACE("scalar operand");
    ExpectScalarOperand(GetParam());
  }
}

std::string PrintOpcode(const testing::TestParamInfo<OpcodeInfo>& param_info) {
  return std::string(param_info.param.name);
}

// The opcodes of the ARB extensions themselves (the NV-only ones are nv_opcode_test's).
std::vector<OpcodeInfo> ArbOpcodes() {
  std::vector<OpcodeInfo> out;
  for (const OpcodeInfo& info : AllOpcodes()) {
    if (info.vp == OpLevel::Arb || info.fp == OpLevel::Arb) out.push_back(info);
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(OpcodesDef, CheckOpcodeRow, testing::ValuesIn(ArbOpcodes()), PrintOpcode);

// "There are twenty-seven vertex program instructions" (ARBvp 2.14.4, Table X.5) and
// "There are 33 fragment program instructions" (ARBfp 3.11.4, Table X.5).
TEST(OpcodeTable, InstructionCountsMatchTheSpecs) {
  int vp = 0;
  int fp = 0;
  for (const OpcodeInfo& info : AllOpcodes()) {
    vp += OpcodeInStage(info.op, ProgramKind::Vertex) ? 1 : 0;
    fp += OpcodeInStage(info.op, ProgramKind::Fragment) ? 1 : 0;
  }
  EXPECT_EQ(vp, 27);
  EXPECT_EQ(fp, 33);
}

// The NV options' instruction counts: "There are forty-two vertex program instructions"
// (NV_vertex_program2_option), "forty-eight" (NV_vertex_program3), "fifty-two fragment
// program instructions" (NV_fragment_program_option) and "sixty-seven" (NV_fragment_program2).
TEST(OpcodeTable, NvInstructionCountsMatchTheSpecs) {
  int counts[2][3] = {};
  for (const OpcodeInfo& info : AllOpcodes()) {
    for (int level = 0; level < 3; ++level) {
      for (int kind = 0; kind < 2; ++kind) {
        OpLevel l = kind == 0 ? info.vp : info.fp;
        if (l != OpLevel::No && static_cast<int>(l) - 1 <= level) ++counts[kind][level];
      }
    }
  }
  EXPECT_EQ(counts[0][1], 42);
  EXPECT_EQ(counts[0][2], 48);
  EXPECT_EQ(counts[1][1], 52);
  EXPECT_EQ(counts[1][2], 67);
}

// <TexInstruction> ::= <SAMPLE_instruction> | <KIL_instruction> (and the NV options' TXD,
// TXL); flow control is its own class; everything else is ALU.
TEST(OpcodeTable, TexClassIsSampleAndKil) {
  for (const OpcodeInfo& info : AllOpcodes()) {
    SCOPED_TRACE(info.name);
    bool tex = info.signature == OpSignature::Sample || info.signature == OpSignature::TexD ||
               info.op == Opcode::KIL;
    bool flow = info.signature == OpSignature::Branch || info.signature == OpSignature::FlowCc ||
                info.signature == OpSignature::If || info.signature == OpSignature::Loop ||
                info.signature == OpSignature::EndFlow;
    EXPECT_EQ(info.klass, tex ? OpClass::Tex : flow ? OpClass::Flow : OpClass::Alu);
  }
}

TEST(OpcodeTable, LookupByName) {
  Opcode op;
  ASSERT_TRUE(LookupOpcode("DPH", &op));
  EXPECT_EQ(op, Opcode::DPH);
  EXPECT_EQ(GetOpcodeInfo(op).name, "DPH");
  EXPECT_FALSE(LookupOpcode("MOV_SAT", &op));  // the suffix is not part of the name
  EXPECT_FALSE(LookupOpcode("mov", &op));
  ASSERT_TRUE(LookupOpcode("ENDLOOP", &op));
  EXPECT_EQ(op, Opcode::ENDLOOP);
  EXPECT_FALSE(LookupOpcode("MOVC", &op));
}

}  // namespace
}  // namespace arbiter::arbvp
