// The exact GLSL statements of instructions that translators get wrong (docs/design/semantics.md):
// RSQ takes |x|, LIT's clamps and 0^0, SWZ, CMP, LRP operand order, matrix rows, relative
// addressing, KIL and NaN, masks, scalar replication.
#include <gtest/gtest.h>

#include "arbiter/arbvp/emit_mutation.h"
#include "emit_fixture.h"

namespace arbiter::arbvp::testing {
namespace {

std::vector<std::string> Vp(const std::string& body, const EmitOptions& options = {}) {
  Translation t = TranslateText("!!ARBvp1.0\n" + body + "END\n", options);
  EXPECT_EQ(GlslErrors(ProgramKind::Vertex, t.glsl), "") << t.glsl;
  return Statements(t.glsl);
}

std::vector<std::string> Fp(const std::string& body, const EmitOptions& options = {}) {
  Translation t = TranslateText("!!ARBfp1.0\n" + body + "END\n", options);
  EXPECT_EQ(GlslErrors(ProgramKind::Fragment, t.glsl), "") << t.glsl;
  return Statements(t.glsl);
}

using Lines = std::vector<std::string>;

TEST(EmitStatement, RsqTakesAbsoluteValueAndReplicates) {
  EXPECT_EQ(Vp("TEMP t;\nRSQ t.xz, vertex.position.y;\n"),
            Lines{"t.xz = vec2(inversesqrt(abs(gl_Vertex.y)));"});
  EXPECT_EQ(Vp("TEMP t;\nRSQ t, -vertex.position.w;\n"),
            Lines{"t = vec4(inversesqrt(abs(-gl_Vertex.w)));"});
}

TEST(EmitStatement, LitCallsTheSpecHelper) {
  Translation t = TranslateText("!!ARBvp1.0\nTEMP t;\nLIT t.yz, vertex.normal;\nEND\n");
  EXPECT_EQ(Statements(t.glsl), Lines{"t.yz = arb_lit(vec4(gl_Normal, 1.0)).yz;"});
  EXPECT_NE(t.glsl.find("  float x = s.x < 0.0 ? 0.0 : s.x;\n"
                        "  float y = s.y < 0.0 ? 0.0 : s.y;\n"
                        "  float w = s.w < -127.99999 ? -127.99999 : "
                        "(s.w > 127.99999 ? 127.99999 : s.w);\n"
                        "  float z = x > 0.0 ? (w == 0.0 ? 1.0 : pow(y, w)) : 0.0;\n"
                        "  return vec4(1.0, x, z, 1.0);\n"),
            std::string::npos)
      << t.glsl;
}

// GLSL requires gl_Position; ARB leaves an unwritten result.position undefined.
TEST(EmitStatement, UnwrittenPositionGetsAPlaceholder) {
  Translation t = TranslateText("!!ARBvp1.0\nMOV result.color, vertex.color;\nEND\n");
  EXPECT_EQ(GlslErrors(ProgramKind::Vertex, t.glsl), "") << t.glsl;
  EXPECT_NE(t.glsl.find("  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);  // result.position is never "
                        "written: undefined in ARB\n"),
            std::string::npos)
      << t.glsl;
  Translation written = TranslateText("!!ARBvp1.0\nMOV result.position, vertex.position;\nEND\n");
  EXPECT_EQ(written.glsl.find("never written"), std::string::npos) << written.glsl;
}

TEST(EmitStatement, SwzBuildsSignedComponentsAndConstants) {
  EXPECT_EQ(Vp("TEMP t;\nSWZ t, vertex.position, -x, 0, 1, -w;\n"),
            Lines{"t = vec4(-gl_Vertex.x, 0.0, 1.0, -gl_Vertex.w);"});
  EXPECT_EQ(Vp("TEMP t;\nSWZ t.yw, vertex.color, y, -1, -0, -z;\n"),
            Lines{"t.yw = vec2(-1.0, -gl_Color.z);"});
}

TEST(EmitStatement, CmpSelectsPerComponentWithStrictLess) {
  EXPECT_EQ(Fp("TEMP a, b, c;\nCMP a.xy, -b, c, fragment.color;\n"),
            Lines{"a.xy = vec2(-b.x < 0.0 ? c.x : gl_Color.x, -b.y < 0.0 ? c.y : gl_Color.y);"});
}

TEST(EmitStatement, LrpIsMixWithTheOperandsReversed) {
  EXPECT_EQ(Fp("TEMP a, b, c, d;\nLRP d, a, b, c;\n"), Lines{"d = mix(c, b, a);"});
  EXPECT_EQ(Fp("TEMP a, b, c, d;\nLRP_SAT d.w, a.x, b, c;\n"),
            Lines{"d.w = clamp(mix(c.w, b.w, a.x), 0.0, 1.0);"});
}

TEST(EmitStatement, MatrixRowsAreTransposedColumns) {
  EXPECT_EQ(Vp("PARAM m[4] = { state.matrix.mvp };\n"
               "DP4 result.position.x, m[0], vertex.position;\n"
               "DP4 result.position.w, m[3], vertex.position;\n"),
            (Lines{"gl_Position.x = dot(gl_ModelViewProjectionMatrixTranspose[0], gl_Vertex);",
                   "gl_Position.w = dot(gl_ModelViewProjectionMatrixTranspose[3], gl_Vertex);"}));
  EXPECT_EQ(Vp("PARAM m = state.matrix.modelview.inverse.row[1];\n"
               "PARAM n = state.matrix.texture[1].transpose.row[2];\n"
               "TEMP t;\nADD t, m, n;\n"),
            Lines{"t = gl_ModelViewMatrixInverseTranspose[1] + gl_TextureMatrix[1][2];"});
  // Program matrices live in uniforms: row r of M is (M[0][r], M[1][r], M[2][r], M[3][r]).
  EXPECT_EQ(Vp("PARAM m = state.matrix.program[2].row[1];\nTEMP t;\nMOV t, m;\n"),
            Lines{"t = vec4(arb_matrix_program2[0][1], arb_matrix_program2[1][1], "
                  "arb_matrix_program2[2][1], arb_matrix_program2[3][1]);"});
}

TEST(EmitStatement, RelativeAddressingFloorsAndChecksBounds) {
  Translation t = TranslateText(
      "!!ARBvp1.0\nPARAM c[4] = { program.env[0..3] };\nADDRESS a0;\nTEMP r;\n"
      "ARL a0.x, vertex.position.x;\nMOV r, c[a0.x + 2];\nMOV r.y, c[a0.x - 1].z;\nEND\n");
  EXPECT_EQ(Statements(t.glsl),
            (Lines{"c[0] = arb_vp_env[0];", "c[1] = arb_vp_env[1];", "c[2] = arb_vp_env[2];",
                   "c[3] = arb_vp_env[3];", "a0 = int(floor(gl_Vertex.x));",
                   "r = arb_read_c(a0 + 2);", "r.y = arb_read_c(a0 - 1).z;"}));
  EXPECT_NE(t.glsl.find("vec4 arb_read_c(int arb_i) {\n"
                        "  if (arb_i < 0 || arb_i > 3) return vec4(0.0);\n"
                        "  return c[arb_i];\n"
                        "}\n"),
            std::string::npos)
      << t.glsl;
  EXPECT_TRUE(t.bindings.relative_out_of_range_reads_zero);
}

TEST(EmitStatement, KilTestsEveryComponentAndNaNDoesNotKill) {
  EXPECT_EQ(Fp("TEMP a;\nKIL -a.xyzx;\n"),
            Lines{"if (any(lessThan(-a.xyzx, vec4(0.0)))) discard;"});
  EXPECT_EQ(Fp("KIL { 1, -2, 0, 0.5 };\n"),
            Lines{"if (any(lessThan(vec4(1.0, -2.0, 0.0, 0.5), vec4(0.0)))) discard;"});
}

TEST(EmitStatement, DotProductsDphDstXpd) {
  EXPECT_EQ(Vp("TEMP a, b;\nDPH a.w, b, vertex.position;\n"),
            Lines{"a.w = dot(b.xyz, gl_Vertex.xyz) + gl_Vertex.w;"});
  EXPECT_EQ(Vp("TEMP a, b, c;\nDST a, b, c;\n"), Lines{"a = vec4(1.0, b.y * c.y, b.z, c.w);"});
  EXPECT_EQ(Vp("TEMP a, b, c;\nXPD a.xyz, b, c;\n"), Lines{"a.xyz = cross(b.xyz, c.xyz);"});
  EXPECT_EQ(Vp("TEMP a, b, c;\nXPD a, b, c.yzxw;\n"), Lines{"a = vec4(cross(b.xyz, c.yzx), 1.0);"});
}

TEST(EmitStatement, ResultsAndAttributesWithComponentFill) {
  EXPECT_EQ(Vp("TEMP t;\nMOV t.xw, vertex.normal;\nDP3 t.y, vertex.normal, t;\nMOV t.z, "
               "state.material.shininess.x;\n"),
            (Lines{"t.xw = vec4(gl_Normal, 1.0).xw;", "t.y = dot(gl_Normal, t.xyz);",
                   "t.z = gl_FrontMaterial.shininess;"}));
  EXPECT_EQ(Vp("MOV result.fogcoord, vertex.fogcoord;\n"
               "MOV result.pointsize.y, vertex.normal;\n"
               "MOV result.texcoord[3], vertex.attrib[6];\n"),
            (Lines{"gl_FogFragCoord = gl_FogCoord;", "gl_TexCoord[3] = arb_attrib6;"}));
  EXPECT_EQ(Fp("MOV result.depth, fragment.fogcoord.x;\n"
               "MUL result.color, fragment.position, 2.0;\n"),
            (Lines{"gl_FragDepth = gl_FogFragCoord;", "gl_FragColor = gl_FragCoord * vec4(2.0);"}));
}

TEST(EmitStatement, StateRebuiltWhereArbPacksDifferently) {
  EXPECT_EQ(
      Vp("TEMP t;\nMOV t, state.light[1].attenuation;\nMOV t, state.light[0].spot.direction;\n"
         "MOV t, state.fog.params;\nMOV t, state.point.size;\n"),
      (Lines{"t = vec4(gl_LightSource[1].constantAttenuation, "
             "gl_LightSource[1].linearAttenuation, gl_LightSource[1].quadraticAttenuation, "
             "gl_LightSource[1].spotExponent);",
             "t = vec4(gl_LightSource[0].spotDirection, gl_LightSource[0].spotCosCutoff);",
             "t = vec4(gl_Fog.density, gl_Fog.start, gl_Fog.end, gl_Fog.scale);",
             "t = vec4(gl_Point.size, gl_Point.sizeMin, gl_Point.sizeMax, "
             "gl_Point.fadeThresholdSize);"}));
  EXPECT_EQ(Fp("TEMP t;\nMOV t, state.depth.range;\n"),
            Lines{"t = vec4(gl_DepthRange.near, gl_DepthRange.far, gl_DepthRange.diff, 1.0);"});
}

TEST(EmitStatement, ArlFloorsAndSaturateClamps) {
  EXPECT_EQ(Vp("ADDRESS a;\nARL a.x, -vertex.color.w;\n"), Lines{"a = int(floor(-gl_Color.w));"});
  EXPECT_EQ(Fp("TEMP t;\nADD_SAT t.xw, t, -t.w;\n"),
            Lines{"t.xw = clamp(t.xw + -t.ww, 0.0, 1.0);"});
}

TEST(EmitStatement, MutationsChangeTheirStatement) {
  auto with = [](Mutation m) { return WithMutation(EmitOptions{}, m); };
  EXPECT_EQ(Vp("TEMP t;\nRSQ t, t.x;\n", with(Mutation::RsqNoAbs)),
            Lines{"t = vec4(inversesqrt(t.x));"});
  EXPECT_EQ(Fp("TEMP a, b, c, d;\nLRP d, a, b, c;\n", with(Mutation::LrpOperandOrder)),
            Lines{"d = mix(b, c, a);"});
  EXPECT_EQ(Vp("ADDRESS a;\nARL a.x, vertex.color.w;\n", with(Mutation::ArlTruncate)),
            Lines{"a = int(gl_Color.w);"});
  EXPECT_EQ(Fp("TEMP a;\nKIL a;\n", with(Mutation::KilOnNaN)),
            Lines{"if (!all(greaterThanEqual(a, vec4(0.0)))) discard;"});
  EXPECT_EQ(Vp("TEMP a;\nMOV a.x, vertex.color;\n", with(Mutation::WriteMaskIgnored)),
            Lines{"a = gl_Color;"});
}

TEST(EmitStatement, NvMutationsChangeTheirStatement) {
  auto with = [](Mutation m) { return WithMutation(EmitOptions{}, m); };
  const std::string nv = "OPTION NV_fragment_program2;\nTEMP a, b, c;\n";
  EXPECT_EQ(Fp(nv + "DIV c, a, b.y;\n"), Lines{"c = a / b.y;"});
  EXPECT_EQ(Fp(nv + "DIV c, a, b.y;\n", with(Mutation::DivByVector)), Lines{"c = a / b;"});
  EXPECT_EQ(Fp(nv + "SEQ c, a, b;\n", with(Mutation::SeqSneSwapped)),
            Lines{"c = vec4(notEqual(a, b));"});
  EXPECT_EQ(Fp(nv + "SNE c, a, b;\n", with(Mutation::SeqSneSwapped)),
            Lines{"c = vec4(equal(a, b));"});
  EXPECT_EQ(Fp(nv + "ADD_SSAT c, a, b;\n", with(Mutation::SsatUnitRange)),
            Lines{"c = clamp(a + b, 0.0, 1.0);"});
  const std::string cc = nv + "MOVC c, a;\nMOV c (GT.x), b;\n";
  EXPECT_EQ(Fp(cc), (Lines{"arb_t = a;", "c = arb_t;", "arb_cc0 = arb_t;", "arb_t = b;",
                           "if (arb_cc0.x > 0.0) c = arb_t;"}));
  EXPECT_EQ(Fp(cc, with(Mutation::CcGtAsGe)),
            (Lines{"arb_t = a;", "c = arb_t;", "arb_cc0 = arb_t;", "arb_t = b;",
                   "if (arb_cc0.x >= 0.0) c = arb_t;"}));
  EXPECT_EQ(Fp(cc, with(Mutation::CcUpdateIgnored)),
            (Lines{"arb_t = a;", "c = arb_t;", "arb_t = b;", "if (arb_cc0.x > 0.0) c = arb_t;"}));
  EXPECT_EQ(Fp(cc, with(Mutation::CcWriteMaskIgnored)),
            (Lines{"arb_t = a;", "c = arb_t;", "arb_cc0 = arb_t;", "arb_t = b;", "c = arb_t;"}));
}

}  // namespace
}  // namespace arbiter::arbvp::testing

namespace arbiter::arbvp::testing {
namespace {

TEST(EmitStatement, ConstantsRoundTripWithoutSuffix) {
  EXPECT_EQ(Vp("TEMP t;\nMOV t, { 0.7, 100, 1e20, -0.0 };\nMUL t.y, t, -2.5;\n"),
            (Lines{"t = vec4(0.7, 100.0, 1e+20, -0.0);", "t.y = t.y * -2.5;"}));
}

TEST(EmitStatement, NamesAvoidGlslReservedWordsAndPrefixes) {
  EXPECT_EQ(Vp("TEMP dot, gl_x, a$b, arb_t, a__b;\nMOV dot, gl_x;\nADD a$b, arb_t, a__b;\n"),
            (Lines{"u_dot = u_gl_x;", "a_b = u_arb_t + a_b_2;"}));
}

TEST(EmitPair, SharesTexCoordSizeAndMergesBindings) {
  Checked vp = CheckText("v.vp",
                         "!!ARBvp1.0\nPARAM e = program.env[1];\nMOV result.position, "
                         "vertex.position;\nMOV result.texcoord[1], e;\nEND\n");
  Checked fp = CheckText("f.fp",
                         "!!ARBfp1.0\nPARAM e = program.env[0];\nADD result.color, "
                         "fragment.texcoord[3], e;\nEND\n");
  ASSERT_TRUE(vp.program && fp.program) << vp.errors << fp.errors;
  PairTranslation pair =
      EmitGlslPair(*vp.program, *fp.program, EmitOptions{}, vp.source.get(), fp.source.get());
  EXPECT_NE(pair.vertex.find("varying vec4 gl_TexCoord[4];"), std::string::npos) << pair.vertex;
  EXPECT_NE(pair.fragment.find("varying vec4 gl_TexCoord[4];"), std::string::npos) << pair.fragment;
  ASSERT_EQ(pair.bindings.parameters.size(), 2u);
  EXPECT_EQ(pair.bindings.parameters[0].name, "arb_vp_env");
  EXPECT_EQ(pair.bindings.parameters[0].size, 2);
  EXPECT_EQ(pair.bindings.parameters[1].name, "arb_fp_env");
  EXPECT_EQ(pair.bindings.parameters[1].target, ProgramKind::Fragment);
  EXPECT_EQ(GlslErrors(ProgramKind::Vertex, pair.vertex), "");
  EXPECT_EQ(GlslErrors(ProgramKind::Fragment, pair.fragment), "");
}

}  // namespace
}  // namespace arbiter::arbvp::testing
