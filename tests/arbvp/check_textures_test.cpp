// Tests of texture instructions: targets, one target per unit, SHADOW targets and their option.
#include <string>

#include "check_fixture.h"

namespace arbiter::arbvp {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

TEST(CheckTextures, EveryTargetIsAccepted) {
  const std::pair<const char*, TexTarget> targets[] = {{"1D", TexTarget::Tex1D},
                                                       {"2D", TexTarget::Tex2D},
                                                       {"3D", TexTarget::Tex3D},
                                                       {"CUBE", TexTarget::Cube},
                                                       {"RECT", TexTarget::Rect}};
  for (const auto& [name, target] : targets) {
    SCOPED_TRACE(name);
    Checked c =
        CheckFp(std::string("TEX result.color, fragment.texcoord[0], texture[1], ") + name + ";\n");
    EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
    ASSERT_NE(c.result.program, nullptr);
    EXPECT_EQ(c.result.program->instructions[0].target, target);
    EXPECT_EQ(c.result.program->instructions[0].tex_unit, 1);
  }
}

// <texImageUnit> ::= "texture" <optTexImageUnitNum>: without a number it is unit 0.
TEST(CheckTextures, BareTextureKeywordIsUnitZero) {
  Checked c = CheckFp(
      "TEMP t;\nTXP t, fragment.texcoord, texture, 2D;\n"
      "TXB result.color, fragment.texcoord[1], texture[0], 2D;\n");
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
  ASSERT_NE(c.result.program, nullptr);
  EXPECT_EQ(c.result.program->instructions[0].tex_unit, 0);
}

TEST(CheckTextures, MissingTextureUnitIsRejected) {
  Checked c = CheckFp("TEX result.color, fragment.texcoord[0], 2D;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:41 arb-syntax-expected"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("a texture unit"));
}

TEST(CheckTextures, UnknownTargetIsRejected) {
  Checked c = CheckFp("TEX result.color, fragment.texcoord[0], texture[0], CUB;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:53 arb-texture-target"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("did you mean 'CUBE'?"));
  Checked lower = CheckFp("TEX result.color, fragment.texcoord[0], texture[0], 2d;\n");
  EXPECT_THAT(lower.ErrorKeys(), ElementsAre("2:53 arb-texture-target"));
  Checked four = CheckFp("TEX result.color, fragment.texcoord[0], texture[0], 4D;\n");
  EXPECT_THAT(four.ErrorKeys(), ElementsAre("2:53 arb-texture-target"));
}

// The example of ARBfp 3.11.6: "the following program would fail to load".
TEST(CheckTextures, TwoTargetsOnOneUnitAreRejected) {
  Checked c = Check(
      "!!ARBfp1.0\n"
      "TEX result.color, fragment.texcoord[0], texture[0], 2D;\n"
      "TEX result.depth, fragment.texcoord[1], texture[0], 3D;\n"
      "END\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:53 arb-texture-target-conflict"));
  EXPECT_THAT(c.Errors()[0].message,
              HasSubstr("texture unit 0 is sampled as '3D' here but as '2D' before"));
}

TEST(CheckTextures, BareAndIndexedUnitZeroConflict) {
  Checked c = CheckFp(
      "TEMP t;\nTEX t, fragment.texcoord, texture, 2D;\n"
      "TXP result.color, fragment.texcoord, texture[0], CUBE;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("4:50 arb-texture-target-conflict"));
}

TEST(CheckTextures, OneTargetPerUnitIsAccepted) {
  Checked c = CheckFp(
      "TEMP a, b;\n"
      "TEX a, fragment.texcoord[0], texture[0], 2D;\n"
      "TXB b, fragment.texcoord[1], texture[1], CUBE;\n"
      "TXP a, fragment.texcoord[1], texture[0], 2D;\n"
      "KIL b;\n"
      "ADD result.color, a, b;\n");
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
}

// ARB_fragment_program_shadow: SHADOW1D, SHADOW2D and SHADOWRECT exist only with the option.
TEST(CheckTextures, ShadowTargetsNeedTheOption) {
  for (const char* target : {"SHADOW1D", "SHADOW2D", "SHADOWRECT"}) {
    SCOPED_TRACE(target);
    std::string inst =
        std::string("TEX result.color, fragment.texcoord[0], texture[0], ") + target + ";\n";
    Checked with = CheckFp("OPTION ARB_fragment_program_shadow;\n" + inst);
    EXPECT_THAT(with.diags, IsEmpty()) << with.Dump();
    Checked without = CheckFp(inst);
    EXPECT_THAT(without.ErrorKeys(), ElementsAre("2:53 arb-texture-shadow-option"));
    ASSERT_FALSE(without.Errors().empty());
    EXPECT_THAT(without.Errors()[0].message, HasSubstr("needs OPTION ARB_fragment_program_shadow"));
  }
}

// The second example of ARB_fragment_program_shadow's 3.11.6: a shadow and a non-shadow
// target on one unit are two targets.
TEST(CheckTextures, ShadowAndNonShadowTargetOnOneUnitConflict) {
  Checked c = Check(
      "!!ARBfp1.0\n"
      "OPTION ARB_fragment_program_shadow;\n"
      "TEX result.color.rgb, fragment.texcoord[0], texture[0], 2D;\n"
      "TEX result.color.a,   fragment.texcoord[1], texture[0], SHADOW2D;\n"
      "END\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("4:57 arb-texture-target-conflict"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("'SHADOW2D' here but as '2D' before"));
}

TEST(CheckTextures, ShadowTargetsOfDifferentUnitsAreIndependent) {
  Checked c = CheckFp(
      "OPTION ARB_fragment_program_shadow;\n"
      "TEMP a;\n"
      "TEX a, fragment.texcoord[0], texture[0], SHADOW2D;\n"
      "TEX result.color, fragment.texcoord[0], texture[1], 2D;\n");
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
}

// The unit is checked against MAX_TEXTURE_IMAGE_UNITS_ARB (the selector table in
// check_bindings_test.cpp covers the default); texture[n] is no texcoord set.
TEST(CheckTextures, ImageUnitAndCoordinateSetHaveSeparateLimits) {
  std::string body = "TEX result.color, fragment.texcoord[1], texture[15], 2D;\n";
  Checked mesa = CheckFp(body, compiler::BuiltinProfile("mesa"));
  EXPECT_THAT(mesa.diags, IsEmpty()) << mesa.Dump();
  Checked strict = CheckFp(body, compiler::BuiltinProfile("spec-min"));
  EXPECT_THAT(strict.ErrorKeys(), ElementsAre("2:49 arb-binding-index-range"));
  EXPECT_THAT(strict.Errors()[0].message, HasSubstr("texture image unit 15"));
}

TEST(CheckTextures, TextureInstructionsAreFragmentOnly) {
  Checked c = CheckVp("TEX result.position, vertex.texcoord[0], texture[0], 2D;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:1 arb-syntax-opcode-stage"));
}

}  // namespace
}  // namespace arbiter::arbvp
