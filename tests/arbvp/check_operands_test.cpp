// Tests of instruction operands: masks, swizzles, indexing, register access, data-flow warnings.
#include <string>
#include <vector>

#include "check_fixture.h"

namespace arbiter::arbvp {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

// Component index of a mask or swizzle letter (xyzw or rgba).
int ComponentIndex(char c) {
  switch (c) {
    case 'x':
    case 'r':
      return 0;
    case 'y':
    case 'g':
      return 1;
    case 'z':
    case 'b':
      return 2;
    default:
      return 3;
  }
}

bool IsRgba(const std::string& s) { return s.find_first_of("rgba") != std::string::npos; }

// ---- write masks (ARBvp 2.14.2 and ARBfp 3.11.2 <optionalMask>) --------------------------

// Each mask of <xyzwMask> and its twin of <rgbaMask> (ARBfp 3.11.2).
struct MaskCase {
  const char* xyzw;
  const char* rgba;
};

class CheckWriteMask : public testing::TestWithParam<MaskCase> {};

// Both spellings are accepted in fragment programs with the same components; vertex programs
// take only the xyzw spelling (ARBvp 2.14.2 <optionalMask>).
TEST_P(CheckWriteMask, AcceptedInItsStages) {
  for (std::string mask : {GetParam().xyzw, GetParam().rgba}) {
    SCOPED_TRACE(mask);
    uint8_t bits = 0;
    for (char ch : mask) bits = static_cast<uint8_t>(bits | (1u << ComponentIndex(ch)));

    Checked fp = CheckFp("TEMP t;\nMOV t." + mask + ", fragment.color;\n");
    EXPECT_THAT(fp.diags, IsEmpty()) << fp.Dump();
    ASSERT_NE(fp.result.program, nullptr);
    ASSERT_EQ(fp.result.program->instructions.size(), 1u);
    EXPECT_EQ(fp.result.program->instructions[0].dst.mask, bits);

    Checked vp =
        CheckVp("TEMP t;\nMOV t." + mask + ", vertex.position;\nMOV result.position, t;\n");
    if (IsRgba(mask)) {
      EXPECT_THAT(vp.ErrorKeys(), ElementsAre("3:7 arb-operand-rgba-vp")) << vp.Dump();
      ASSERT_FALSE(vp.Errors().empty());
      EXPECT_THAT(vp.Errors()[0].message, HasSubstr("only fragment programs accept"));
    } else {
      EXPECT_THAT(vp.ErrorKeys(), IsEmpty()) << vp.Dump();
      ASSERT_NE(vp.result.program, nullptr);
      EXPECT_EQ(vp.result.program->instructions[0].dst.mask, bits);
    }
  }
}

std::string PrintMask(const testing::TestParamInfo<MaskCase>& param_info) {
  return param_info.param.xyzw;
}

INSTANTIATE_TEST_SUITE_P(
    Masks, CheckWriteMask,
    testing::Values(MaskCase{"x", "r"}, MaskCase{"y", "g"}, MaskCase{"xy", "rg"},
                    MaskCase{"z", "b"}, MaskCase{"xz", "rb"}, MaskCase{"yz", "gb"},
                    MaskCase{"xyz", "rgb"}, MaskCase{"w", "a"}, MaskCase{"xw", "ra"},
                    MaskCase{"yw", "ga"}, MaskCase{"xyw", "rga"}, MaskCase{"zw", "ba"},
                    MaskCase{"xzw", "rba"}, MaskCase{"yzw", "gba"}, MaskCase{"xyzw", "rgba"}),
    PrintMask);

// "The grammar requires that the destination register mask components must be listed in
// "xyzw" order." (ARBvp 2.14.4.3)
TEST(CheckOperands, MalformedMasksAreRejected) {
  struct Case {
    const char* mask;
    const char* code;
  };
  for (const Case& k : {Case{"yx", "arb-operand-mask"}, Case{"xx", "arb-operand-mask"},
                        Case{"xyzwx", "arb-operand-mask"}, Case{"q", "arb-operand-mask"},
                        Case{"ar", "arb-operand-mask"}, Case{"xg", "arb-operand-swizzle-mix"},
                        Case{"rgbw", "arb-operand-swizzle-mix"}}) {
    SCOPED_TRACE(k.mask);
    Checked c = CheckFp(std::string("MOV result.color.") + k.mask + ", fragment.color;\n");
    EXPECT_THAT(c.ErrorKeys(), ElementsAre(std::string("2:18 ") + k.code)) << c.Dump();
  }
}

// ---- swizzles (<swizzleSuffix>, <optionalSuffix>) --------------------------------------------

struct SwizzleCase {
  const char* swizzle;
  const char* vp_code;  // nullptr: accepted
  const char* fp_code;
};

class CheckSwizzle : public testing::TestWithParam<SwizzleCase> {};

TEST_P(CheckSwizzle, InBothStages) {
  const SwizzleCase& p = GetParam();
  std::string swz = p.swizzle;
  // The swizzle starts at column 38 in the vertex and 37 in the fragment program.
  Checked vp = CheckVp("MOV result.position, vertex.position." + swz + ";\n");
  Checked fp = CheckFp("MOV result.color, fragment.texcoord." + swz + ";\n");
  if (p.vp_code) {
    EXPECT_THAT(vp.ErrorKeys(), ElementsAre(std::string("2:38 ") + p.vp_code)) << vp.Dump();
  } else {
    EXPECT_THAT(vp.diags, IsEmpty()) << vp.Dump();
  }
  if (p.fp_code) {
    EXPECT_THAT(fp.ErrorKeys(), ElementsAre(std::string("2:37 ") + p.fp_code)) << fp.Dump();
    return;
  }
  EXPECT_THAT(fp.diags, IsEmpty()) << fp.Dump();
  // A one-component swizzle replicates: ".y" is ".yyyy" (ARBvp 2.14.4.1).
  ASSERT_NE(fp.result.program, nullptr);
  const SrcOperand& src = fp.result.program->instructions[0].src[0];
  for (size_t i = 0; i < 4; ++i) {
    char ch = swz.size() == 1 ? swz[0] : swz[i];
    EXPECT_EQ(src.swizzle[i], static_cast<Swz>(ComponentIndex(ch))) << i;
  }
}

std::string PrintSwizzle(const testing::TestParamInfo<SwizzleCase>& param_info) {
  return std::string(param_info.param.swizzle) + "_" + std::to_string(param_info.index);
}

INSTANTIATE_TEST_SUITE_P(
    Forms, CheckSwizzle,
    testing::Values(SwizzleCase{"x", nullptr, nullptr}, SwizzleCase{"w", nullptr, nullptr},
                    SwizzleCase{"xyzw", nullptr, nullptr}, SwizzleCase{"wzyx", nullptr, nullptr},
                    SwizzleCase{"yzzx", nullptr, nullptr}, SwizzleCase{"xxxx", nullptr, nullptr},
                    SwizzleCase{"g", "arb-operand-rgba-vp", nullptr},
                    SwizzleCase{"abgr", "arb-operand-rgba-vp", nullptr},
                    SwizzleCase{"xy", "arb-operand-swizzle", "arb-operand-swizzle"},
                    SwizzleCase{"xyz", "arb-operand-swizzle", "arb-operand-swizzle"},
                    SwizzleCase{"xyzwx", "arb-operand-swizzle", "arb-operand-swizzle"},
                    SwizzleCase{"xyzq", "arb-operand-swizzle", "arb-operand-swizzle"},
                    SwizzleCase{"xyba", "arb-operand-swizzle-mix", "arb-operand-swizzle-mix"}),
    PrintSwizzle);

// <scalarSrcReg> ::= <optionalSign> <srcReg> <scalarSuffix>: exactly one component.
TEST(CheckOperands, ScalarOperandNeedsOneComponent) {
  Checked ok = CheckFp("TEMP t;\nRCP t, -fragment.color.a;\nPOW result.color, t.x, t.y;\n");
  EXPECT_THAT(ok.ErrorKeys(), IsEmpty()) << ok.Dump();
  Checked none = CheckFp("TEMP t;\nRCP t, fragment.color;\n");
  EXPECT_THAT(none.ErrorKeys(), ElementsAre("3:8 arb-operand-scalar"));
  EXPECT_THAT(none.Errors()[0].message, HasSubstr("'RCP' takes a scalar operand"));
  Checked four = CheckFp("TEMP t;\nRCP t, fragment.color.xyzw;\n");
  EXPECT_THAT(four.ErrorKeys(), ElementsAre("3:23 arb-operand-scalar"));
  Checked second = CheckVp("TEMP t;\nPOW t, vertex.position.x, vertex.position;\n");
  EXPECT_THAT(second.ErrorKeys(), ElementsAre("3:27 arb-operand-scalar"));
  Checked rgba = CheckVp("TEMP t;\nEX2 t, vertex.position.r;\n");
  EXPECT_THAT(rgba.ErrorKeys(), ElementsAre("3:24 arb-operand-rgba-vp"));
}

// ---- SWZ (<extendedSwizzle>) ---------------------------------------------------------------

TEST(CheckOperands, ExtendedSwizzleSelectsComponentsConstantsAndSigns) {
  Checked c = CheckFp("TEMP t;\nSWZ t, fragment.color, -a, g, 0, +1;\nMOV result.color, t;\n");
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
  ASSERT_NE(c.result.program, nullptr);
  const SrcOperand& src = c.result.program->instructions[0].src[0];
  EXPECT_EQ(src.swizzle, (std::array<Swz, 4>{Swz::W, Swz::Y, Swz::Zero, Swz::One}));
  EXPECT_EQ(src.component_negate, (std::array<bool, 4>{true, false, false, false}));
  Checked vp = CheckVp("SWZ result.position, vertex.position, x, -y, 1, -0;\n");
  EXPECT_THAT(vp.diags, IsEmpty()) << vp.Dump();
}

TEST(CheckOperands, MalformedExtendedSwizzlesAreRejected) {
  struct Case {
    const char* operands;  // after "SWZ t, " (column 8 of line 3)
    const char* key;
  };
  for (const Case& k : {
           Case{"vertex.position, x, y, z;", "3:32 arb-operand-extended-swizzle"},
           Case{"vertex.position, x, y, z, w, x;", "3:35 arb-operand-extended-swizzle"},
           Case{"vertex.position.x, x, y, z, w;", "3:23 arb-operand-extended-swizzle"},
           Case{"-vertex.position, x, y, z, w;", "3:8 arb-operand-extended-swizzle"},
           Case{"vertex.position, 2, y, z, w;", "3:25 arb-operand-extended-swizzle"},
           Case{"vertex.position, xy, z, w, 0;", "3:25 arb-operand-extended-swizzle"},
           Case{"vertex.position, r, g, b, a;", "3:25 arb-operand-rgba-vp"},
       }) {
    SCOPED_TRACE(k.operands);
    Checked c = CheckVp(std::string("TEMP t;\nSWZ t, ") + k.operands + "\n");
    EXPECT_THAT(c.ErrorKeys(), ElementsAre(k.key)) << c.Dump();
  }
  // <extendedSwizzle> ::= <xyzwExtendedSwizzle> | <rgbaExtendedSwizzle> (ARBfp 3.11.2)
  Checked mix = CheckFp("TEMP t;\nSWZ t, fragment.color, r, y, 0, 1;\n");
  EXPECT_THAT(mix.ErrorKeys(), ElementsAre("3:27 arb-operand-swizzle-mix"));
}

// ---- address registers and relative addressing (vertex programs) ---------------------------

// <maskedAddrReg> ::= <addrReg> <addrWriteMask>; <addrWriteMask> ::= "." "x"
TEST(CheckOperands, ArlWritesOnlyTheXComponent) {
  Checked ok =
      CheckVp("ADDRESS a;\nARL a.x, -vertex.position.w;\nMOV result.position, vertex.position;\n");
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  struct Case {
    const char* inst;
    const char* key;
  };
  for (const Case& k : {
           Case{"ARL a, vertex.position.x;", "3:6 arb-operand-address-component"},
           Case{"ARL a.y, vertex.position.x;", "3:7 arb-operand-address-component"},
           Case{"ARL a.xy, vertex.position.x;", "3:7 arb-operand-address-component"},
           Case{"ARL a.x, vertex.position;", "3:10 arb-operand-scalar"},
       }) {
    SCOPED_TRACE(k.inst);
    Checked c = CheckVp(std::string("ADDRESS a;\n") + k.inst + "\n");
    EXPECT_THAT(c.ErrorKeys(), ElementsAre(k.key)) << c.Dump();
  }
}

std::string RelativeBody(const std::string& index) {
  return "ADDRESS a;\nPARAM c[4] = { program.env[0..3] };\nARL a.x, vertex.position.x;\n"
         "MOV result.position, c[" +
         index + "];\n";
}

struct OffsetCase {
  const char* index;
  int offset;
  bool ok;
};

class CheckRelativeOffset : public testing::TestWithParam<OffsetCase> {};

// <addrRegPosOffset> ::= <integer> from 0 to 63; <addrRegNegOffset> ::= from 0 to 64
TEST_P(CheckRelativeOffset, RangeIsMinus64To63) {
  const OffsetCase& p = GetParam();
  Checked c = CheckVp(RelativeBody(p.index));
  if (!p.ok) {
    EXPECT_THAT(c.ErrorKeys(), ElementsAre("5:28 arb-operand-offset-range")) << c.Dump();
    ASSERT_FALSE(c.Errors().empty());
    EXPECT_THAT(c.Errors()[0].message, HasSubstr("offsets go from -64 to +63"));
    return;
  }
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
  ASSERT_NE(c.result.program, nullptr);
  const SrcOperand& src = c.result.program->instructions[1].src[0];
  EXPECT_TRUE(src.relative);
  EXPECT_EQ(src.index, p.offset);
}

std::string PrintOffset(const testing::TestParamInfo<OffsetCase>& param_info) {
  return "index_" + std::to_string(param_info.index);
}

INSTANTIATE_TEST_SUITE_P(Offsets, CheckRelativeOffset,
                         testing::Values(OffsetCase{"a.x", 0, true}, OffsetCase{"a.x+0", 0, true},
                                         OffsetCase{"a.x+63", 63, true},
                                         OffsetCase{"a.x-64", -64, true},
                                         OffsetCase{"a.x - 1", -1, true},
                                         OffsetCase{"a.x+64", 0, false},
                                         OffsetCase{"a.x-65", 0, false}),
                         PrintOffset);

// <progParamArrayRel> ::= <addrReg> <addrComponent> <addrRegRelOffset>; <addrComponent> ::= ".x"
TEST(CheckOperands, RelativeIndexNeedsXComponent) {
  Checked bare = CheckVp(RelativeBody("a"));
  EXPECT_THAT(bare.ErrorKeys(), ElementsAre("5:25 arb-operand-address-component"));
  Checked y = CheckVp(RelativeBody("a.y"));
  EXPECT_THAT(y.ErrorKeys(), ElementsAre("5:26 arb-operand-address-component"));
}

// Fragment programs index arrays with <progParamArrayAbs> only (ARBfp 3.11.2).
TEST(CheckOperands, RelativeAddressingInFragmentProgramIsRejected) {
  Checked c = CheckFp("PARAM c[2] = { 1, 2 };\nMOV result.color, c[a.x];\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:21 arb-operand-relative-fp"));
}

// "If any vertex program instruction accesses a program parameter array using absolute
// addressing with an out-of-range index ... the vertex program will fail to load."
TEST(CheckOperands, AbsoluteIndexMustBeInsideTheArray) {
  Checked ok = CheckFp("PARAM c[2] = { 1, 2 };\nMOV result.color, c[1];\n");
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  Checked c = CheckFp("PARAM c[2] = { 1, 2 };\nMOV result.color, c[2];\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:21 arb-operand-index-range"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("out of bounds for array 'c' of 2 elements"));
}

TEST(CheckOperands, OnlyParamArraysAreIndexed) {
  Checked temp = CheckFp("TEMP t;\nMOV t, fragment.color;\nMOV result.color, t[0];\n");
  EXPECT_THAT(temp.ErrorKeys(), ElementsAre("4:20 arb-operand-not-array"));
  Checked single = CheckFp("PARAM p = 1;\nMOV result.color, p[0];\n");
  EXPECT_THAT(single.ErrorKeys(), ElementsAre("3:20 arb-operand-not-array"));
  Checked dst = CheckFp("TEMP t;\nMOV t[0], fragment.color;\n");
  EXPECT_THAT(dst.ErrorKeys(), ElementsAre("3:6 arb-operand-not-array"));
  Checked unindexed = CheckFp("PARAM c[2] = { 1, 2 };\nMOV result.color, c;\n");
  EXPECT_THAT(unindexed.ErrorKeys(), ElementsAre("3:19 arb-operand-array-unindexed"));
}

// ---- register access: attributes and parameters are read-only, results write-only ---------

TEST(CheckOperands, AttributesAndParametersAreReadOnly) {
  struct Case {
    const char* body;
    const char* key;
  };
  for (const Case& k : {
           Case{"ATTRIB p = fragment.color;\nMOV p, fragment.color;\n",
                "3:5 arb-operand-dst-readonly"},
           Case{"PARAM c = 1;\nMOV c, fragment.color;\n", "3:5 arb-operand-dst-readonly"},
           Case{"MOV fragment.color, fragment.color;\n", "2:5 arb-operand-dst-readonly"},
           Case{"MOV state.fog.color, fragment.color;\n", "2:5 arb-operand-dst-readonly"},
           Case{"MOV program.env[0], fragment.color;\n", "2:5 arb-operand-dst-readonly"},
       }) {
    SCOPED_TRACE(k.body);
    Checked c = CheckFp(k.body);
    EXPECT_THAT(c.ErrorKeys(), ElementsAre(k.key)) << c.Dump();
  }
}

TEST(CheckOperands, ResultsAreWriteOnly) {
  Checked direct = CheckFp("MOV result.color, result.color;\n");
  EXPECT_THAT(direct.ErrorKeys(), ElementsAre("2:19 arb-operand-src-writeonly"));
  EXPECT_THAT(direct.Errors()[0].message, HasSubstr("write-only"));
  Checked output =
      CheckFp("OUTPUT o = result.color;\nMOV o, fragment.color;\nMOV result.depth, o;\n");
  EXPECT_THAT(output.ErrorKeys(), ElementsAre("4:19 arb-operand-src-writeonly"));
}

// Operand signs: one per operand; an inline scalar constant has none of its own.
TEST(CheckOperands, InlineConstantsTakeTheOperandSignOnly) {
  Checked ok = CheckFp("MOV result.color, -2;\nMOV result.depth, -{1, -2, 3, 4};\n");
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  ASSERT_NE(ok.result.program, nullptr);
  const SrcOperand& src = ok.result.program->instructions[0].src[0];
  EXPECT_TRUE(src.negate);
  EXPECT_FLOAT_EQ(ok.result.program->vars[static_cast<size_t>(src.var)].bindings[0].value[0], 2.0f);
  Checked c = CheckFp("MOV result.color, --2;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:20 arb-operand-signed-constant"));
}

// ---- ARB_position_invariant (ARBvp 2.14.4.5.1) ----------------------------------------------

TEST(CheckOperands, PositionInvariantProgramMayNotWritePosition) {
  Checked ok = CheckVp("OPTION ARB_position_invariant;\nMOV result.color, vertex.color;\n");
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  Checked write =
      CheckVp("OPTION ARB_position_invariant;\nMOV result.position, vertex.position;\n");
  EXPECT_THAT(write.ErrorKeys(), ElementsAre("3:5 arb-operand-position-invariant"));
  EXPECT_THAT(write.Errors()[0].message, HasSubstr("cannot write result.position"));
  Checked bind = CheckVp("OPTION ARB_position_invariant;\nOUTPUT p = result.position;\n");
  EXPECT_THAT(bind.ErrorKeys(), ElementsAre("3:12 arb-operand-position-invariant"));
}

// ---- data-flow warnings -----------------------------------------------------------------------

// SCS leaves z and w undefined (ARBfp 3.11.5.23); XPD leaves w undefined (3.11.5.29).
TEST(CheckOperands, UndefinedResultComponentsWarn) {
  Checked ok = CheckFp(
      "TEMP s, x;\nSCS s.xy, fragment.color.x;\nXPD x.xyz, fragment.color, fragment.texcoord;\n"
      "ADD result.color.xy, s, x;\n");
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  Checked scs = CheckFp("TEMP s;\nSCS s, fragment.color.x;\nMOV result.color.xy, s;\n");
  EXPECT_THAT(scs.ErrorKeys(), IsEmpty());
  EXPECT_THAT(scs.WarningKeys(), ElementsAre("3:5 arb-undefined-result"));
  EXPECT_THAT(scs.Warnings()[0].message, HasSubstr("z and w"));
  Checked xpd = CheckVp("XPD result.position, vertex.position, vertex.normal;\n");
  EXPECT_THAT(xpd.WarningKeys(), ElementsAre("2:5 arb-undefined-result"));
}

// Temporaries "are undefined at the beginning of each ... program invocation" (2.14.3.3).
TEST(CheckOperands, TemporaryReadBeforeWriteWarns) {
  Checked c = CheckFp("TEMP t;\nMOV t.x, fragment.color;\nMOV result.color, t.xxyy;\n");
  EXPECT_THAT(c.ErrorKeys(), IsEmpty());
  EXPECT_THAT(c.WarningKeys(), ElementsAre("4:19 arb-temp-uninitialized"));
  EXPECT_THAT(c.Warnings()[0].message, HasSubstr("'t' is read ('.y')"));
  Checked ok = CheckFp("TEMP t;\nMOV t.x, fragment.color;\nMOV result.color, t.x;\n");
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
}

// After an error the program is partial: no data-flow warnings echo it.
TEST(CheckOperands, NoDataFlowWarningsAfterAnError) {
  Checked c = CheckFp("TEMP t;\nMOV result.color, t;\nMOV result.depth, nope;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("4:19 arb-decl-undeclared"));
  EXPECT_THAT(c.WarningKeys(), IsEmpty());
}

TEST(CheckOperands, VertexProgramWithoutPositionWarns) {
  Checked c = CheckVp("MOV result.color, vertex.color;\n");
  EXPECT_THAT(c.ErrorKeys(), IsEmpty());
  EXPECT_THAT(c.WarningKeys(), ElementsAre("3:1 arb-position-unwritten"));
  EXPECT_TRUE(c.result.ok);
}

// ---- checker bugs: these assert the specification and fail until the checker is fixed -----

// <SWZ_instruction> ::= "SWZ" <maskedDstReg> "," <srcReg> "," <extendedSwizzle>, and <srcReg>
// includes <progParamReg> ::= ... | <paramSingleItemUse>, which includes <paramConstUse>
// (ARBvp 2.14.2, ARBfp 3.11.2): an inline constant is a valid SWZ source.
TEST(CheckOperands, SwzTakesInlineConstantSource) {
  Checked vector = CheckFp("SWZ result.color, {0.5, 0.25, 0, 1}, x, y, -1, w;\n");
  EXPECT_THAT(vector.diags, IsEmpty()) << vector.Dump();
  Checked scalar = CheckVp("SWZ result.position, 2.5, x, 0, 0, 1;\n");
  EXPECT_THAT(scalar.diags, IsEmpty()) << scalar.Dump();
}

// A suffix of component letters after "fragment.color" or "vertex.color" is a swizzle
// (<swizzleSuffix>/<optionalSuffix>), not a misspelt <optColorType>: "xyzwx" and "xyzq" are
// malformed swizzles (arb-operand-swizzle, as after any other register), not unknown colour
// types (arb-binding-unknown).
TEST(CheckOperands, MalformedSwizzleOnColourIsASwizzleError) {
  Checked five = CheckFp("MOV result.color, fragment.color.xyzwx;\n");
  EXPECT_THAT(five.ErrorKeys(), ElementsAre("2:34 arb-operand-swizzle")) << five.Dump();
  Checked q = CheckVp("MOV result.position, vertex.color.xyzq;\n");
  EXPECT_THAT(q.ErrorKeys(), ElementsAre("2:35 arb-operand-swizzle")) << q.Dump();
}

}  // namespace
}  // namespace arbiter::arbvp
