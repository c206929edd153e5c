// The GLSL of the NV program options' constructs (NV_vertex_program2_option,
// NV_vertex_program3, NV_fragment_program_option, NV_fragment_program2): each construct's
// statements, and that glslang accepts the translation.
#include <gtest/gtest.h>

#include <algorithm>

#include "emit_fixture.h"

namespace arbiter::arbvp::testing {
namespace {

using Lines = std::vector<std::string>;

// The translation of an NV program (`option` and `body` between the header and END), which
// glslang must accept.
Translation Nv(ProgramKind kind, const std::string& option, const std::string& body) {
  const bool vertex = kind == ProgramKind::Vertex;
  Translation t = TranslateText(std::string(vertex ? "!!ARBvp1.0\n" : "!!ARBfp1.0\n") + "OPTION " +
                                option + ";\n" + body + "END\n");
  EXPECT_EQ(GlslErrors(kind, t.glsl), "") << t.glsl;
  return t;
}

Lines Vp2(const std::string& body) {
  return Statements(Nv(ProgramKind::Vertex, "NV_vertex_program2", body).glsl);
}
Lines Fp(const std::string& body) {
  return Statements(Nv(ProgramKind::Fragment, "NV_fragment_program", body).glsl);
}
Lines Fp2(const std::string& body) {
  return Statements(Nv(ProgramKind::Fragment, "NV_fragment_program2", body).glsl);
}

bool Has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Whether the statements of `glsl` contain `run` in a row.
bool HasRun(const std::string& glsl, const Lines& run) {
  Lines all = Statements(glsl);
  return std::search(all.begin(), all.end(), run.begin(), run.end()) != all.end();
}

TEST(EmitNv, SetOnInstructionsCompareComponentwise) {
  EXPECT_EQ(Vp2("TEMP t;\nSEQ t, vertex.position, vertex.color;\nSNE t.xy, t, t.w;\n"
                "SGT t.z, t, 0.5;\nSLE t, t, vertex.color;\nSFL t.xz, t, t;\nSTR t.w, t, t;\n"),
            (Lines{"t = vec4(equal(gl_Vertex, gl_Color));", "t.xy = vec2(notEqual(t.xy, t.ww));",
                   "t.z = float(t.z > 0.5);", "t = vec4(lessThanEqual(t, gl_Color));",
                   "t.xz = vec2(0.0);", "t.w = 1.0;"}));
}

TEST(EmitNv, AbsoluteValueBeforeTheSign) {
  EXPECT_EQ(Vp2("TEMP t;\nMOV t, -|vertex.color.zzxy|;\nADD t.x, |t.y|, -|{-2, 3}|;\n"),
            (Lines{"t = -abs(gl_Color.zzxy);", "t.x = abs(t.y) + -2.0;"}));
}

TEST(EmitNv, SsgRccAndTrigonometry) {
  Translation t = Nv(ProgramKind::Vertex, "NV_vertex_program2",
                     "TEMP t;\nSSG t, vertex.position;\nRCC t.y, vertex.color.x;\n"
                     "SIN t.z, t.x;\nCOS t.w, 2.0;\n");
  EXPECT_EQ(Statements(t.glsl), (Lines{"t = arb_ssg(gl_Vertex);", "t.y = arb_rcc(gl_Color.x);",
                                       "t.z = sin(t.x);", "t.w = cos(2.0);"}));
  EXPECT_TRUE(Has(t.glsl,
                  "float arb_ssg(float x) { return x != x ? x : (x > 0.0 ? 1.0 : (x < "
                  "0.0 ? -1.0 : 0.0)); }"))
      << t.glsl;
  EXPECT_TRUE(
      Has(t.glsl,
          "  if (r > 0.0 || (x > 0.0 && x <= 3.4028235e+38)) return clamp(r, 5.421011e-20, "
          "1.8446744e+19);\n  if (r <= 0.0) return clamp(r, -1.8446744e+19, -5.421011e-20);\n"
          "  return r;\n"))
      << t.glsl;
}

// The three instructions of the specifications' example (2.14.4.3, 3.11.4.3).
TEST(EmitNv, ConditionCodeUpdateAndConditionalWriteMask) {
  EXPECT_EQ(Vp2("TEMP r0, r1;\nMOVC r0, r1;\nMOVC r0.xyz, r1.yzwx;\nMOVC r0 (NE), r1.zywx;\n"),
            (Lines{"arb_t = r1;",          "r0 = arb_t;",
                   "arb_cc0 = arb_t;",     "arb_t.xyz = r1.yzw;",
                   "r0.xyz = arb_t.xyz;",  "arb_cc0.xyz = arb_t.xyz;",
                   "arb_t = r1.zywx;",     "arb_m = notEqual(arb_cc0.xyzw, vec4(0.0));",
                   "if (arb_m.x) {",       "r0.x = arb_t.x;",
                   "arb_cc0.x = arb_t.x;", "if (arb_m.y) {",
                   "r0.y = arb_t.y;",      "arb_cc0.y = arb_t.y;",
                   "if (arb_m.z) {",       "r0.z = arb_t.z;",
                   "arb_cc0.z = arb_t.z;", "if (arb_m.w) {",
                   "r0.w = arb_t.w;",      "arb_cc0.w = arb_t.w;"}));
  // One tested component for all: one test; FL writes nothing.
  EXPECT_EQ(Vp2("TEMP t;\nADD t.xy (GT.x), t, t.w;\nMOV t (FL), t.x;\nMOV t.z (LE.y), t;\n"),
            (Lines{"arb_t.xy = t.xy + t.ww;", "if (arb_cc0.x > 0.0) t.xy = arb_t.xy;",
                   "arb_t.z = t.z;", "if (arb_cc0.y <= 0.0) t.z = arb_t.z;"}));
}

TEST(EmitNv, ConditionCodeOfAFloatResultRegister) {
  // The fog coordinate keeps x, the condition code takes every enabled component.
  EXPECT_EQ(Vp2("MOVC result.fogcoord, vertex.color;\n"),
            (Lines{"arb_t = gl_Color;", "gl_FogFragCoord = arb_t.x;", "arb_cc0 = arb_t;"}));
}

TEST(EmitNv, AddressRegistersAreIntegerVectors) {
  Translation t = Nv(ProgramKind::Vertex, "NV_vertex_program2",
                     "ADDRESS A0;\nPARAM c[4] = { program.env[0..3] };\nTEMP t;\n"
                     "ARL A0.xy, vertex.position;\nARR A0.zw, vertex.color;\n"
                     "ARAC A0.xz (LE.yyyy), A0;\nMOV t, c[A0.y + 1];\n");
  EXPECT_TRUE(Has(t.glsl, "  ivec4 A0 = ivec4(0);\n")) << t.glsl;
  EXPECT_TRUE(
      HasRun(t.glsl, {"A0.xy = ivec2(clamp(floor(gl_Vertex.xy), -512.0, 511.0));",
                      "A0.zw = ivec2(clamp(arb_round_even(gl_Color.zw), -512.0, 511.0));",
                      "arb_ti.xz = ivec2(clamp(vec4(A0.xyxy + A0.zwzw).xz, -512.0, 511.0));",
                      "if (arb_cc0.y <= 0.0) {", "A0.xz = arb_ti.xz;",
                      "arb_cc0.xz = vec2(arb_ti.xz);", "t = arb_read_c(A0.y + 1);"}))
      << t.glsl;
}

TEST(EmitNv, ClipDistancesAreVaryingsStartingAtZero) {
  Translation t =
      Nv(ProgramKind::Vertex, "NV_vertex_program2",
         "MOV result.position, vertex.position;\nMOV result.clip[2].x, vertex.color;\n");
  EXPECT_TRUE(Has(t.glsl, "varying float arb_clip_distance2;")) << t.glsl;
  EXPECT_EQ(Statements(t.glsl),
            (Lines{"arb_clip_distance2 = 0.0;  // result.clip[2] starts at 0",
                   "gl_Position = gl_Vertex;", "arb_clip_distance2 = gl_Color.x;"}));
  ASSERT_EQ(t.bindings.outputs.size(), 2u);
  EXPECT_EQ(t.bindings.outputs[0].binding, "result.clip[2]");
  EXPECT_EQ(t.bindings.outputs[0].glsl, "arb_clip_distance2");
}

// BRA, CAL and RET run on the program-counter machine, bounded by
// MAX_PROGRAM_EXEC_INSTRUCTIONS_NV, with a call stack of MAX_PROGRAM_CALL_DEPTH_NV.
TEST(EmitNv, BranchesAndSubroutinesRunOnTheMachine) {
  Translation t = Nv(ProgramKind::Vertex, "NV_vertex_program2",
                     "TEMP t;\nMOVC t, vertex.position;\nCAL sub (GT.x);\nBRA done;\n"
                     "sub:\nADD t, t, 1;\nRET;\ndone:\nMOV result.position, t;\n");
  const std::string& g = t.glsl;
  EXPECT_TRUE(Has(g, "  int arb_pc = 0;  // the next instruction\n")) << g;
  EXPECT_TRUE(Has(g, "  int arb_stack[4];  // return addresses; -1: a PUSHA entry\n")) << g;
  EXPECT_TRUE(Has(g,
                  "  for (int arb_step = 0; arb_step < 65536; ++arb_step) {  // "
                  "MAX_PROGRAM_EXEC_INSTRUCTIONS_NV\n"
                  "    if (arb_pc >= 6) break;\n"))
      << g;
  EXPECT_TRUE(
      HasRun(g, {"arb_pc = 2;", "if (arb_cc0.x > 0.0) {", "if (arb_sp == 4) {",
                 "arb_pc = 6;  // call stack overflow: the end", "} else {",
                 "if (arb_sp == 0) arb_stack[0] = 2;", "else if (arb_sp == 1) arb_stack[1] = 2;",
                 "else if (arb_sp == 2) arb_stack[2] = 2;", "else arb_stack[3] = 2;",
                 "arb_sp += 1;", "arb_pc = 3;"}))
      << g;
  EXPECT_TRUE(Has(g, "          // BRA done;\n          arb_pc = 5;\n")) << g;
  EXPECT_TRUE(
      HasRun(g, {"arb_pc = 5;", "if (arb_sp == 0) {", "arb_pc = 6;  // empty call stack: the end",
                 "} else {", "arb_sp -= 1;", "arb_pc = arb_stack[arb_sp];"}))
      << g;
}

TEST(EmitNv, ExecutionStartsAtTheLabelMain) {
  EXPECT_EQ(Vp2("TEMP t;\nMOV t, 1;\nmain:\nMOV result.position, t;\n"), Lines{"gl_Position = t;"});
}

TEST(EmitNv, AddressStackOfVertexProgram3) {
  Translation t = Nv(ProgramKind::Vertex, "NV_vertex_program3",
                     "ADDRESS A0;\nARL A0, vertex.color;\nPUSHA A0;\nARL A0.x, 1;\nPOPA A0;\n"
                     "MOV result.position, vertex.position;\n");
  EXPECT_TRUE(HasRun(
      t.glsl, {"if (arb_sp == 4) {", "arb_pc = 5;  // call stack overflow: the end", "} else {",
               "if (arb_sp == 0) arb_stack[0] = -1;", "else if (arb_sp == 1) arb_stack[1] = -1;",
               "else if (arb_sp == 2) arb_stack[2] = -1;", "else arb_stack[3] = -1;",
               "if (arb_sp == 0) arb_saved[0] = A0;", "else if (arb_sp == 1) arb_saved[1] = A0;",
               "else if (arb_sp == 2) arb_saved[2] = A0;", "else arb_saved[3] = A0;",
               "arb_sp += 1;", "arb_pc = 2;"}))
      << t.glsl;
  EXPECT_TRUE(
      HasRun(t.glsl, {"if (arb_sp == 0 || arb_stack[arb_sp - 1] >= 0) {",
                      "arb_pc = 5;  // no address register on the stack: the end", "} else {",
                      "arb_sp -= 1;", "A0 = arb_saved[arb_sp];", "arb_pc = 4;"}))
      << t.glsl;
}

TEST(EmitNv, VertexTexturesSampleAtAnExplicitLevel) {
  EXPECT_EQ(Statements(Nv(ProgramKind::Vertex, "NV_vertex_program3",
                          "TEMP t;\nTEX t, vertex.texcoord[0], texture[1], 2D;\n"
                          "TXB t.x, t, texture[0], CUBE;\nTXL t.y, t, texture[2], 3D;\n"
                          "TXP t.z, t, texture[3], 1D;\nMOV result.position, t;\n")
                           .glsl),
            (Lines{"t = texture2DLod(arb_texture1, gl_MultiTexCoord0.xy, 0.0);",
                   "t.x = textureCubeLod(arb_texture0, t.xyz, t.w).x;",
                   "t.y = texture3DLod(arb_texture2, t.xyz, t.w).y;",
                   "t.z = texture1DProjLod(arb_texture3, t, 0.0).z;", "gl_Position = t;"}));
}

TEST(EmitNv, ConditionCodeRegisterOne) {
  EXPECT_EQ(Statements(Nv(ProgramKind::Vertex, "NV_vertex_program3",
                          "TEMP t;\nMOVC1 t, vertex.color;\nMOV_SAT t.x (LT1.w), t;\n"
                          "MOV result.position, t;\n")
                           .glsl),
            (Lines{"arb_t = gl_Color;", "t = arb_t;", "arb_cc1 = arb_t;",
                   "arb_t.x = clamp(t.x, 0.0, 1.0);", "if (arb_cc1.w < 0.0) t.x = arb_t.x;",
                   "gl_Position = t;"}));
}

// H: operands and result rounded to fp16; X: to s1.10 fixed point; a SHORT destination
// makes H the default and stores fp16.
TEST(EmitNv, PrecisionSuffixesAndShortStorage) {
  Translation t = Nv(ProgramKind::Fragment, "NV_fragment_program",
                     "SHORT TEMP h;\nLONG TEMP r;\nMULH r, fragment.color, fragment.texcoord[0];\n"
                     "ADDX r.xy, r, -|fragment.color|;\nMOV h, fragment.color;\n"
                     "MOVR h.x, r;\nMAD_SAT h.y, r, r, r;\nMOV result.color, h;\n");
  EXPECT_EQ(
      Statements(t.glsl),
      (Lines{"r = arb_fp16(arb_fp16(gl_Color) * arb_fp16(gl_TexCoord[0]));",
             "r.xy = arb_fx12(arb_fx12(r.xy) + arb_fx12(-abs(gl_Color.xy)));",
             "h = arb_fp16(gl_Color);", "h.x = arb_fp16(r.x);",
             "h.y = clamp(arb_fp16(arb_fp16(r.y) * arb_fp16(r.y) + arb_fp16(r.y)), 0.0, 1.0);",
             "gl_FragColor = h;"}));
  EXPECT_TRUE(Has(t.glsl, "  if (d > 0.5 || (d == 0.5 && fract(f * 0.5) != 0.0)) f += 1.0;\n"))
      << t.glsl;
  EXPECT_TRUE(Has(t.glsl, "  return arb_round_even(x * 1024.0) * 0.0009765625;\n")) << t.glsl;
}

TEST(EmitNv, DerivativesReflectionAndTransform) {
  Translation t = Nv(ProgramKind::Fragment, "NV_fragment_program",
                     "TEMP t, r;\nDDX t, fragment.texcoord[0];\nDDY r.xy, fragment.texcoord[0];\n"
                     "RFL t.xyz, r, t;\nX2D r.xz, r, t, fragment.color;\nMOV result.color, r;\n");
  EXPECT_EQ(Statements(t.glsl),
            (Lines{"t = dFdx(gl_TexCoord[0]);", "r.xy = dFdy(gl_TexCoord[0].xy);",
                   "t.xyz = arb_rfl(r.xyz, t.xyz);",
                   "r.xz = vec2(r.x + t.x * gl_Color.x + t.y * gl_Color.y, r.x + t.x * gl_Color.x "
                   "+ t.y * gl_Color.y);",
                   "gl_FragColor = r;"}));
  EXPECT_TRUE(Has(t.glsl, "  float k = 2.0 * dot(a, d) / dot(a, a);\n  return k * a - d;\n"))
      << t.glsl;
}

TEST(EmitNv, TxdSamplesWithTheGivenDerivatives) {
  Translation t =
      Nv(ProgramKind::Fragment, "NV_fragment_program",
         "TEMP t;\nTXD t, fragment.texcoord[0], fragment.texcoord[1], "
         "fragment.texcoord[2], texture[0], 2D;\n"
         "TXD t.x, t, t, t, texture[1], CUBE;\nTXD t.y, t, t, t, texture[2], SHADOW2D;\n"
         "MOV result.color, t;\n");
  EXPECT_TRUE(Has(t.glsl, "#extension GL_ARB_shader_texture_lod : require\n")) << t.glsl;
  EXPECT_EQ(
      Statements(t.glsl),
      (Lines{"t = texture2DGradARB(arb_texture0, gl_TexCoord[0].xy, gl_TexCoord[1].xy, "
             "gl_TexCoord[2].xy);",
             "t.x = textureCubeGradARB(arb_texture1, t.xyz, t.xyz, t.xyz).x;",
             "t.y = shadow2DGradARB(arb_texture2, t.xyz, t.xy, t.xy).y;", "gl_FragColor = t;"}));
}

TEST(EmitNv, KilOnAConditionCode) {
  EXPECT_EQ(
      Fp("TEMP t;\nMOVC t, fragment.color;\nKIL GT.xxyy;\nKIL NE;\nKIL LT.z;\n"),
      (Lines{"arb_t = gl_Color;", "t = arb_t;", "arb_cc0 = arb_t;",
             "if (any(greaterThan(arb_cc0.xy, vec2(0.0)))) discard;",
             "if (any(notEqual(arb_cc0, vec4(0.0)))) discard;", "if (arb_cc0.z < 0.0) discard;"}));
}

// GLSL 1.10 has no bit casts: the pack and unpack instructions are refused with a line
// glslang rejects, naming the instruction.
TEST(EmitNv, PackingIsRefused) {
  for (std::string op : {"PK2H", "PK2US", "PK4B", "PK4UB", "UP2H", "UP2US", "UP4B", "UP4UB"}) {
    const bool unpack = op[0] == 'U';
    Translation t = TranslateText("!!ARBfp1.0\nOPTION NV_fragment_program;\nTEMP t;\n" + op +
                                  " t, fragment.color" + (unpack ? ".x" : "") +
                                  ";\nMOV result.color, t;\nEND\n");
    EXPECT_TRUE(Has(t.glsl, "#error arbiter cannot translate " + op + " to GLSL 1.10")) << t.glsl;
    EXPECT_TRUE(Has(GlslErrors(ProgramKind::Fragment, t.glsl), op));
  }
}

TEST(EmitNv, Program2InstructionsAndSignedSaturation) {
  EXPECT_EQ(Fp2("TEMP t, u;\nNRM u, t;\nDIV u.xy, u, -t.w;\nDP2 u.z, u, t;\n"
                "DP2A u.w, u, t, t.z;\nMOV_SSAT result.color, u;\n"),
            (Lines{"u = vec4(t.xyz * inversesqrt(dot(t.xyz, t.xyz)), 1.0);",
                   "u.xy = u.xy / (-t.w);", "u.z = dot(u.xy, t.xy);",
                   "u.w = dot(u.xy, t.xy) + t.z;", "gl_FragColor = clamp(u, -1.0, 1.0);"}));
}

TEST(EmitNv, TxlSamplesAtTheGivenLevel) {
  Translation t = Nv(ProgramKind::Fragment, "NV_fragment_program2",
                     "TEMP t;\nTXL t, fragment.texcoord[0], texture[0], 2D;\n"
                     "TXL t.y, t, texture[1], RECT;\nMOV result.color, t;\n");
  EXPECT_TRUE(Has(t.glsl, "#extension GL_ARB_shader_texture_lod : require\n")) << t.glsl;
  EXPECT_EQ(Statements(t.glsl),
            (Lines{"t = texture2DLod(arb_texture0, gl_TexCoord[0].xy, gl_TexCoord[0].w);",
                   "t.y = texture2DRectGradARB(arb_texture1, t.xy, vec2(exp2(t.w), 0.0), "
                   "vec2(0.0, exp2(t.w))).y;",
                   "gl_FragColor = t;"}));
}

TEST(EmitNv, FacingIsPlusOrMinusOne) {
  EXPECT_EQ(Fp2("MOV result.color, fragment.facing;\n"),
            Lines{"gl_FragColor = vec4((gl_FrontFacing ? 1.0 : -1.0), 0.0, 0.0, 1.0);"});
}

// Within MAX_PROGRAM_EXEC_INSTRUCTIONS_NV, IF and the loops are GLSL if and for.
TEST(EmitNv, StructuredIfAndLoops) {
  EXPECT_EQ(Fp2("PARAM count = { 3, 1, 2, 0 };\nTEMP t;\nMOVC t, fragment.color;\n"
                "IF GT.x;\nADD t, t, 1;\nELSE;\nADD t, t, 2;\nENDIF;\n"
                "LOOP count;\nREP count.y;\nADDC t, t, -0.25;\nBRK (LE.w);\nENDREP;\n"
                "IF EQ.x;\nBRK;\nENDIF;\nENDLOOP;\nMOV result.color, t;\n"),
            (Lines{"arb_t = gl_Color;",
                   "t = arb_t;",
                   "arb_cc0 = arb_t;",
                   "if (arb_cc0.x > 0.0) {",
                   "t = t + vec4(1.0);",
                   "} else {  // ELSE;",
                   "t = t + vec4(2.0);",
                   "}  // ENDIF;",
                   "arb_loop1 = 3;",
                   "arb_a0_1 = 1;",
                   "arb_incr1 = 2;",
                   "for (; arb_loop1 > 0; --arb_loop1) {",
                   "arb_loop2 = 1;",
                   "for (; arb_loop2 > 0; --arb_loop2) {",
                   "arb_t = t + vec4(-0.25);",
                   "t = arb_t;",
                   "arb_cc0 = arb_t;",
                   "if (arb_cc0.w <= 0.0) break;",
                   "}  // ENDREP;",
                   "if (arb_cc0.x == 0.0) {",
                   "break;",
                   "}  // ENDIF;",
                   "arb_a0_1 += arb_incr1;",
                   "}  // ENDLOOP;",
                   "gl_FragColor = t;"}));
}

// A loop whose count is a program parameter may run 255 times: nested, past the
// instruction limit, so the program runs on the machine.
TEST(EmitNv, LoopsThatCouldPassTheLimitRunOnTheMachine) {
  Translation t = Nv(ProgramKind::Fragment, "NV_fragment_program2",
                     "PARAM n = program.local[0];\nTEMP t;\nREP n;\nREP n;\nADD t, t, 1;\n"
                     "ENDREP;\nENDREP;\nMOV result.color, t;\n");
  EXPECT_TRUE(HasRun(
      t.glsl, {"if (arb_ls == 4) {",
               "arb_pc = 6;  // MAX_PROGRAM_LOOP_DEPTH_NV blocks open: the end", "} else {",
               "arb_entry = ivec3(int(clamp(floor(arb_fp_local[0].x), 0.0, 255.0)), 0, arb_a0);",
               "if (arb_entry.x > 0) {", "if (arb_ls == 0) arb_loops[0] = arb_entry;",
               "else if (arb_ls == 1) arb_loops[1] = arb_entry;",
               "else if (arb_ls == 2) arb_loops[2] = arb_entry;", "else arb_loops[3] = arb_entry;",
               "arb_ls += 1;", "arb_pc = 1;", "} else {", "arb_pc = 5;"}))
      << t.glsl;
  EXPECT_TRUE(HasRun(
      t.glsl,
      {"arb_entry = arb_loops[arb_ls - 1];", "arb_entry.x -= 1;", "if (arb_entry.x > 0) {",
       "if (arb_ls - 1 == 0) arb_loops[0] = arb_entry;",
       "else if (arb_ls - 1 == 1) arb_loops[1] = arb_entry;",
       "else if (arb_ls - 1 == 2) arb_loops[2] = arb_entry;", "else arb_loops[3] = arb_entry;",
       "arb_pc = 2;", "} else {", "arb_ls -= 1;", "arb_pc = 4;"}))
      << t.glsl;
}

TEST(EmitNv, SubroutinesOfFragmentProgram2LeaveTheirLoops) {
  Translation t = Nv(ProgramKind::Fragment, "NV_fragment_program2",
                     "PARAM c = { 2, 0, 1, 0 };\nTEMP t;\nCAL f;\nMOV result.color, t;\nRET;\n"
                     "f:\nLOOP c;\nADD t, t, 1;\nRET;\nENDLOOP;\nRET;\n");
  EXPECT_TRUE(Has(t.glsl, "if (arb_sp == 0) arb_stack_ls[0] = arb_ls;\n")) << t.glsl;
  EXPECT_TRUE(HasRun(
      t.glsl, {"arb_pc = arb_stack[arb_sp];", "if (arb_ls > arb_stack_ls[arb_sp]) {",
               "arb_a0 = arb_loops[arb_stack_ls[arb_sp]].z;", "arb_ls = arb_stack_ls[arb_sp];"}))
      << t.glsl;
}

// Without the source, comments are rebuilt from the IR, NV suffixes and operands included.
TEST(EmitNv, CommentsRebuiltFromTheIr) {
  const std::string text =
      "!!ARBfp1.0\nOPTION NV_fragment_program2;\nPARAM l = {2, 0, 1, 0};\nTEMP t;\n"
      "MOVC t, fragment.color;\nIF GT.x;\nLOOP l;\nADDH_SAT t (NE.xyxy), |t|, -t;\n"
      "BRK (LE.w);\nENDLOOP;\nENDIF;\nKIL LT.z;\nCAL f (GT);\nMOV result.color, t;\nRET;\n"
      "f:\nTXD t, t, t, t, texture[0], 2D;\nRET (EQ.y);\nEND\n";
  Checked c = CheckText("cm.fp", text);
  ASSERT_TRUE(c.program) << c.errors;
  Translation with = EmitGlsl(*c.program, EmitOptions{}, c.source.get());
  Translation without = EmitGlsl(*c.program, EmitOptions{}, nullptr);
  EXPECT_EQ(GlslErrors(ProgramKind::Fragment, without.glsl), "") << without.glsl;
  EXPECT_EQ(Statements(with.glsl), Statements(without.glsl));
  std::vector<std::string> comments;
  for (size_t at = without.glsl.find("// "); at != std::string::npos;
       at = without.glsl.find("// ", at + 1)) {
    comments.push_back(without.glsl.substr(at + 3, without.glsl.find('\n', at) - at - 3));
  }
  for (const char* expected :
       {"MOVC t, fragment.color.primary;", "IF GT.x;", "LOOP l;", "ADDH_SAT t (NE.xyxy), |t|, -t;",
        "BRK (LE.w);", "ENDLOOP;", "KIL LT.z;", "CAL f (GT);", "RET;",
        "TXD t, t, t, t, texture[0], 2D;", "RET (EQ.y);"}) {
    EXPECT_NE(std::find(comments.begin(), comments.end(), expected), comments.end())
        << expected << " in\n"
        << without.glsl;
  }
}

// fragment.texcoord[A0.x + n] inside a LOOP block reads the loop's index, clamped at 0,
// from a copy of the texture coordinates (the IR as the parser would give it: an attribute
// variable binding every element, read with relative addressing).
TEST(EmitNv, LoopIndexAddressesTextureCoordinates) {
  Checked c = CheckText("rel.fp",
                        "!!ARBfp1.0\nOPTION NV_fragment_program2;\nPARAM l = {2, 0, 1, 0};\n"
                        "TEMP t;\nMOV t, 0;\nLOOP l;\nADD t, t, fragment.texcoord[1];\nENDLOOP;\n"
                        "MOV result.color, t;\nEND\n");
  ASSERT_TRUE(c.program) << c.errors;
  Instruction& add = c.program->instructions[2];
  ASSERT_EQ(add.op, Opcode::ADD);
  SrcOperand& src = add.src[1];
  Variable& var = c.program->vars[static_cast<size_t>(src.var)];
  ASSERT_EQ(var.kind, VarKind::Attrib);
  Binding element = var.bindings.at(0);
  var.bindings.clear();
  for (int n = 0; n < 8; ++n) {
    element.index = n;
    var.bindings.push_back(element);
  }
  var.is_array = true;
  src.relative = true;
  src.index = 1;
  Translation t = EmitGlsl(*c.program, EmitOptions{}, nullptr);
  EXPECT_EQ(GlslErrors(ProgramKind::Fragment, t.glsl), "") << t.glsl;
  EXPECT_TRUE(
      HasRun(t.glsl, {"attrib[7] = gl_TexCoord[7];", "t = vec4(0.0);", "arb_loop1 = 2;",
                      "arb_a0_1 = 0;", "arb_incr1 = 1;", "for (; arb_loop1 > 0; --arb_loop1) {",
                      "t = t + arb_read_attrib((arb_a0_1 < 0 ? 0 : arb_a0_1) + 1);",
                      "arb_a0_1 += arb_incr1;", "}  // ENDLOOP;"}))
      << t.glsl;
  EXPECT_TRUE(Has(t.glsl, "  if (arb_i < 0 || arb_i > 7) return vec4(0.0);\n")) << t.glsl;
}

}  // namespace
}  // namespace arbiter::arbvp::testing
