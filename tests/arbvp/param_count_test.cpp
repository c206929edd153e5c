// Parameter and attribute accounting exactly as the specs count them (ARBvp 2.14.3.7,
// ARBfp 3.11.3.6), including the spec's own worked example.
#include <gtest/gtest.h>

#include "check_fixture.h"

namespace arbiter::arbvp {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

// ARBvp 2.14.3.7's example: arr1 is relatively addressed, so its four constants count even
// though two are identical; of the rest only {0,1,2,3} and {4,3,2,1} are new.
TEST(ParamCount, SpecExampleWithRelativeAddressing) {
  Checked c = CheckVp(
      "PARAM arr1[4] = { {1,2,3,4}, {1,2,3,4}, {4,4,4,4}, {5,6,7,8} };\n"
      "PARAM arr2[3] = { {1,2,3,4}, {5,6,7,8}, {0,1,2,3} };\n"
      "PARAM x = {4,3,2,1};\nPARAM y = {1,2,3,4};\nPARAM z = 4;\nPARAM r = {4,3,2,1};\n"
      "ADDRESS a;\nTEMP t;\nARL a.x, vertex.position.x;\nMOV t, arr1[a.x];\n"
      "ADD t, t, arr2[1];\nADD t, t, x;\nADD t, t, y;\nADD t, t, z;\n"
      "ADD result.position, t, r;\n");
  ASSERT_TRUE(c.result.ok) << c.Dump();
  EXPECT_EQ(c.result.stats.parameters, 6);
}

TEST(ParamCount, WithoutRelativeAddressingIdenticalConstantsCountOnce) {
  Checked c = CheckVp(
      "PARAM arr1[4] = { {1,2,3,4}, {1,2,3,4}, {4,4,4,4}, {5,6,7,8} };\n"
      "PARAM z = 4;\nMOV result.position, arr1[0];\nMOV result.color, z;\n");
  ASSERT_TRUE(c.result.ok) << c.Dump();
  EXPECT_EQ(c.result.stats.parameters, 3);
}

TEST(ParamCount, StateVectorsCountOnceAndMatricesByRow) {
  Checked c = CheckVp(
      "PARAM m[4] = { state.matrix.mvp };\nPARAM row = state.matrix.mvp.row[1];\n"
      "DP4 result.position.x, m[0], vertex.position;\n"
      "DP4 result.position.y, state.matrix.mvp.row[1], vertex.position;\n"
      "MOV result.color, state.matrix.projection.row[0];\n");
  ASSERT_TRUE(c.result.ok) << c.Dump();
  EXPECT_EQ(c.result.stats.parameters, 5);  // 4 mvp rows + 1 projection row
}

TEST(ParamCount, AttributesBoundTwiceCountOnce) {
  Checked c = CheckVp(
      "ATTRIB p = vertex.position;\nATTRIB t0 = vertex.texcoord;\n"
      "MOV result.position, vertex.position;\nMOV result.color, p;\n"
      "MOV result.texcoord, vertex.texcoord[0];\nMOV result.texcoord[1], t0;\n");
  ASSERT_TRUE(c.result.ok) << c.Dump();
  EXPECT_EQ(c.result.stats.attributes, 2);
}

// Past the spec minimum of 24 fragment-program parameters: no warning by default, one error
// with --limits spec-min, at the first parameter past it, not at every later one.
TEST(ParamCount, PastTheMinimumOnce) {
  std::string list;
  for (int i = 0; i < 30; ++i) list += (i ? ", {" : "{") + std::to_string(i) + "}";
  std::string body = "PARAM p[30] = { " + list + " };\nMOV result.color, p[0];\n";
  Checked c = CheckFp(body);
  ASSERT_TRUE(c.result.ok) << c.Dump();
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
  Checked strict = CheckFp(body, compiler::BuiltinProfile("spec-min"));
  EXPECT_THAT(strict.ErrorKeys(), ElementsAre("2:7 arb-limit-parameters"));
}

// Fog options take two parameters, one temporary and one attribute for themselves
// (ARBfp 3.11.4.5.1).
TEST(ParamCount, FogOptionReservesParameters) {
  std::string body = "PARAM p[23] = { program.local[0..22] };\nMOV result.color, p[0];\n";
  EXPECT_TRUE(CheckFp(body, compiler::BuiltinProfile("spec-min")).result.ok);
  Checked fog = CheckFp("OPTION ARB_fog_exp;\n" + body, compiler::BuiltinProfile("spec-min"));
  EXPECT_THAT(fog.ErrorKeys(), ElementsAre("3:7 arb-limit-parameters")) << fog.Dump();
}

}  // namespace
}  // namespace arbiter::arbvp
