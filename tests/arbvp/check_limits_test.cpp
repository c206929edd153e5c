// Tests of resource limits and Stats, including texture indirections and option reserves.
#include <string>

#include "check_fixture.h"

namespace arbiter::arbvp {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

const compiler::LimitProfile* SpecMin() { return compiler::BuiltinProfile("spec-min"); }

// spec-min with some keys changed.
compiler::LimitProfile SpecMinWith(std::initializer_list<std::pair<const char*, int64_t>> keys) {
  compiler::LimitProfile p = *compiler::BuiltinProfile("spec-min");
  p.name = "custom";
  for (const auto& [key, value] : keys) p.values[key] = value;
  return p;
}

std::string Repeat(const std::string& line, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += line;
  return out;
}

// "TEMP t0;\nTEMP t1;\n..." : one declaration per line.
std::string Temps(int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += "TEMP t" + std::to_string(i) + ";\n";
  return out;
}

// ---- instructions -------------------------------------------------------------------------

// MAX_PROGRAM_INSTRUCTIONS_ARB is at least 128 for vertex programs (ARBvp 2.14.3.7).
TEST(CheckLimits, VertexInstructions) {
  const std::string inst = "MOV result.position, vertex.position;\n";
  Checked ok = CheckVp(Repeat(inst, 128), SpecMin());
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  EXPECT_EQ(ok.result.stats.instructions, 128);
  Checked over = CheckVp(Repeat(inst, 129), SpecMin());
  EXPECT_THAT(over.ErrorKeys(), ElementsAre("130:1 arb-limit-instructions"));
  EXPECT_THAT(over.Errors()[0].message,
              HasSubstr("MAX_PROGRAM_INSTRUCTIONS_ARB is 128 in profile 'spec-min'"));
  // The default (Mesa's limits): past the minimum is no warning.
  Checked mesa = CheckVp(Repeat(inst, 131));
  EXPECT_THAT(mesa.diags, IsEmpty()) << mesa.Dump();
  EXPECT_EQ(mesa.result.stats.instructions, 131);
}

// "a vertex program will fail to load if the number of instructions it contains exceeds the
// implementation-dependent limit minus four." (ARBvp 2.14.4.5.1)
TEST(CheckLimits, PositionInvariantTakesFourInstructions) {
  const std::string option = "OPTION ARB_position_invariant;\n";
  const std::string inst = "MOV result.color, vertex.color;\n";
  Checked ok = CheckVp(option + Repeat(inst, 124), SpecMin());
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  Checked over = CheckVp(option + Repeat(inst, 125), SpecMin());
  EXPECT_THAT(over.ErrorKeys(), ElementsAre("127:1 arb-limit-instructions"));
  EXPECT_THAT(over.Errors()[0].message, HasSubstr("4 reserved by the program's options"));
}

// MAX_PROGRAM_ALU_INSTRUCTIONS_ARB >= 48, MAX_PROGRAM_TEX_INSTRUCTIONS_ARB >= 24 (3.11.3.6).
TEST(CheckLimits, FragmentAluInstructions) {
  const std::string inst = "MOV result.color, fragment.color;\n";
  Checked ok = CheckFp(Repeat(inst, 48), SpecMin());
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  Checked over = CheckFp(Repeat(inst, 49), SpecMin());
  EXPECT_THAT(over.ErrorKeys(), ElementsAre("50:1 arb-limit-alu-instructions"));
  EXPECT_EQ(over.result.stats.alu_instructions, 49);
}

// KIL is a texture instruction (<TexInstruction> ::= <SAMPLE_instruction> | <KIL_instruction>).
TEST(CheckLimits, FragmentTexInstructionsCountKil) {
  const std::string tex = "TEX result.color, fragment.texcoord[0], texture[0], 2D;\n";
  Checked ok = CheckFp(Repeat(tex, 23) + "KIL fragment.texcoord;\n", SpecMin());
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  EXPECT_EQ(ok.result.stats.tex_instructions, 24);
  Checked over = CheckFp(Repeat(tex, 24) + "KIL fragment.texcoord;\n", SpecMin());
  EXPECT_THAT(over.ErrorKeys(), ElementsAre("26:1 arb-limit-tex-instructions"));
}

// The total limit is separate from the ALU and TEX limits.
TEST(CheckLimits, FragmentTotalInstructions) {
  const compiler::LimitProfile profile = SpecMinWith({{"arbfp.max_instructions", 10}});
  const std::string pair =
      "MOV result.color, fragment.color;\nTEX result.color, fragment.texcoord, texture, 2D;\n";
  Checked ok = CheckFp(Repeat(pair, 5), &profile);
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  Checked over = CheckFp(Repeat(pair, 5) + "KIL fragment.color;\n", &profile);
  EXPECT_THAT(over.ErrorKeys(), ElementsAre("12:1 arb-limit-instructions"));
}

TEST(CheckLimits, StatsCountInstructionClasses) {
  Checked c =
      CheckFp("TEMP t;\nTEX t, fragment.texcoord, texture, 2D;\nKIL t;\nMUL result.color, t, t;\n");
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
  EXPECT_EQ(c.result.stats.instructions, 3);
  EXPECT_EQ(c.result.stats.alu_instructions, 1);
  EXPECT_EQ(c.result.stats.tex_instructions, 2);
  EXPECT_EQ(c.result.stats.temporaries, 1);
  EXPECT_EQ(c.result.stats.outputs, 1);
}

// ---- fog options (ARBfp 3.11.4.5.1) -----------------------------------------------------------

struct FogCase {
  const char* option;
  int reserved;  // instructions and ALU instructions the option takes
};

class CheckFogLimits : public testing::TestWithParam<FogCase> {};

TEST_P(CheckFogLimits, ReduceInstructionAndAluLimits) {
  const FogCase& p = GetParam();
  const std::string option = std::string("OPTION ") + p.option + ";\n";
  const std::string alu = "MOV result.color, fragment.color;\n";
  // ALU: 48 minus the reserve.
  Checked ok = CheckFp(option + Repeat(alu, 48 - p.reserved), SpecMin());
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  Checked over = CheckFp(option + Repeat(alu, 49 - p.reserved), SpecMin());
  EXPECT_THAT(over.ErrorKeys(),
              ElementsAre(std::to_string(51 - p.reserved) + ":1 arb-limit-alu-instructions"));
  ASSERT_FALSE(over.Errors().empty());
  EXPECT_THAT(over.Errors()[0].message,
              HasSubstr(std::to_string(p.reserved) + " reserved by the program's options"));
  // Total: 72 minus the reserve, with the ALU limit out of the way.
  const compiler::LimitProfile profile = SpecMinWith({{"arbfp.max_alu_instructions", 1000}});
  Checked total_ok = CheckFp(option + Repeat(alu, 72 - p.reserved), &profile);
  EXPECT_THAT(total_ok.diags, IsEmpty()) << total_ok.Dump();
  Checked total_over = CheckFp(option + Repeat(alu, 73 - p.reserved), &profile);
  EXPECT_THAT(total_over.ErrorKeys(),
              ElementsAre(std::to_string(75 - p.reserved) + ":1 arb-limit-instructions"));
}

// "... if the number of temporaries it contains exceeds the implementation-dependent limit
// minus 1, if the number of attributes it contains exceeds the implementation-dependent limit
// minus 1" (parameters minus 2: param_count_test.cpp).
TEST_P(CheckFogLimits, ReduceTemporaryAndAttributeLimits) {
  const std::string option = std::string("OPTION ") + GetParam().option + ";\n";
  Checked temps_ok = CheckFp(option + Temps(15), SpecMin());
  EXPECT_THAT(temps_ok.diags, IsEmpty()) << temps_ok.Dump();
  Checked temps_over = CheckFp(option + Temps(16), SpecMin());
  EXPECT_THAT(temps_over.ErrorKeys(), ElementsAre("18:6 arb-limit-temporaries"));

  const char* attribs[] = {"fragment.color",       "fragment.color.secondary",
                           "fragment.fogcoord",    "fragment.position",
                           "fragment.texcoord[0]", "fragment.texcoord[1]",
                           "fragment.texcoord[2]", "fragment.texcoord[3]",
                           "fragment.texcoord[4]", "fragment.texcoord[5]"};
  std::string decls;
  for (int i = 0; i < 10; ++i) {
    decls += "ATTRIB a" + std::to_string(i) + " = " + attribs[i] + ";\n";
  }
  const compiler::LimitProfile profile = SpecMinWith({{"arbfp.max_texture_coords", 8}});
  Checked without_fog = CheckFp(decls, &profile);
  EXPECT_THAT(without_fog.diags, IsEmpty()) << without_fog.Dump();
  Checked attribs_over = CheckFp(option + decls, &profile);
  EXPECT_THAT(attribs_over.ErrorKeys(), ElementsAre("12:8 arb-limit-attributes"));
}

std::string PrintFog(const testing::TestParamInfo<FogCase>& param_info) {
  return param_info.param.option;
}

INSTANTIATE_TEST_SUITE_P(Options, CheckFogLimits,
                         testing::Values(FogCase{"ARB_fog_linear", 2}, FogCase{"ARB_fog_exp", 3},
                                         FogCase{"ARB_fog_exp2", 4}),
                         PrintFog);

// ---- temporaries, address registers, attributes --------------------------------------------

// MAX_PROGRAM_TEMPORARIES_ARB >= 12 (vertex), 16 (fragment); aliases do not count.
TEST(CheckLimits, Temporaries) {
  const std::string position = "MOV result.position, vertex.position;\n";
  Checked vp_ok = CheckVp(Temps(12) + "ALIAS u = t0;\n" + position, SpecMin());
  EXPECT_THAT(vp_ok.diags, IsEmpty()) << vp_ok.Dump();
  EXPECT_EQ(vp_ok.result.stats.temporaries, 12);
  Checked vp_over = CheckVp(Temps(13) + position, SpecMin());
  EXPECT_THAT(vp_over.ErrorKeys(), ElementsAre("14:6 arb-limit-temporaries"));
  EXPECT_THAT(vp_over.Errors()[0].message, HasSubstr("temporary 't12' (number 13)"));
  Checked mesa = CheckVp(Temps(15) + position);
  EXPECT_THAT(mesa.diags, IsEmpty()) << mesa.Dump();
  Checked fp_ok = CheckFp(Temps(16), SpecMin());
  EXPECT_THAT(fp_ok.diags, IsEmpty()) << fp_ok.Dump();
  Checked fp_over = CheckFp(Temps(17), SpecMin());
  EXPECT_THAT(fp_over.ErrorKeys(), ElementsAre("18:6 arb-limit-temporaries"));
}

// MAX_PROGRAM_ADDRESS_REGISTERS_ARB is 1 in both built-in profiles.
TEST(CheckLimits, AddressRegisters) {
  Checked one = CheckVp("ADDRESS a;\nALIAS b = a;\nMOV result.position, vertex.position;\n");
  EXPECT_THAT(one.diags, IsEmpty()) << one.Dump();
  EXPECT_EQ(one.result.stats.address_registers, 1);
  Checked two = CheckVp("ADDRESS a, b;\nMOV result.position, vertex.position;\n");
  EXPECT_THAT(two.ErrorKeys(), ElementsAre("2:12 arb-limit-address-registers"));
  EXPECT_THAT(two.Errors()[0].message, HasSubstr("in profile 'mesa'"));
}

// "Each distinct vertex attribute bound explicitly or implicitly in the program counts
// against this limit; vertex attributes bound multiple times count only once."
TEST(CheckLimits, DistinctAttributesCount) {
  const compiler::LimitProfile profile = SpecMinWith({{"arbvp.max_attribs", 4}});
  const std::string decls =
      "ATTRIB a = vertex.color;\nATTRIB b = vertex.color.primary;\n"
      "ATTRIB c = vertex.texcoord;\nATTRIB d = vertex.texcoord[0];\n"
      "ATTRIB e = vertex.normal;\nATTRIB f = vertex.fogcoord;\n";
  const std::string uses = "MOV result.position, a;\nMOV result.color, vertex.color;\n";
  Checked ok = CheckVp(decls + uses, &profile);
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  EXPECT_EQ(ok.result.stats.attributes, 4);
  Checked over = CheckVp(decls + "ATTRIB g = vertex.attrib[6];\n" + uses, &profile);
  EXPECT_THAT(over.ErrorKeys(), ElementsAre("8:8 arb-limit-attributes"));
  EXPECT_THAT(over.Errors()[0].message, HasSubstr("'vertex.attrib[6]'"));
}

// ---- parameters -------------------------------------------------------------------------------

// MAX_PROGRAM_PARAMETERS_ARB >= 96 for vertex programs.
TEST(CheckLimits, VertexParameters) {
  auto constants = [](int n) {
    std::string list;
    for (int i = 0; i < n; ++i) list += (i ? ", " : "") + std::to_string(i);
    return "PARAM c[] = { " + list + " };\nMOV result.position, c[0];\n";
  };
  Checked ok = CheckVp(constants(96), SpecMin());
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  EXPECT_EQ(ok.result.stats.parameters, 96);
  Checked over = CheckVp(constants(97), SpecMin());
  EXPECT_THAT(over.ErrorKeys(), ElementsAre("2:7 arb-limit-parameters"));
}

// "Two constant vectors are considered identical if the four component values are
// numerically equivalent"; a state vector counts once however it is spelt.
TEST(CheckLimits, EquivalentParametersCountOnce) {
  Checked c = CheckVp(
      "PARAM ones[] = { 1, 1.0, 1e0, {1, 1, 1, 1}, {1.0, +1, 1, 10e-1} };\n"
      "PARAM zero[] = { {0}, {0, 0, 0, 1}, {-0, 0.0, 0, 1} };\n"
      "PARAM m[] = { state.material.ambient, state.material.front.ambient };\n"
      "PARAM g[] = { state.texgen.eye.s, state.texgen[0].eye.s };\n"
      "PARAM e = program.env[3];\n"
      "MOV result.position, program.env[3];\n"
      "ADD result.color, ones[0], zero[2];\n"
      "ADD result.texcoord, m[1], g[0];\n"
      "MOV result.fogcoord, e;\n");
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
  EXPECT_EQ(c.result.stats.parameters, 5);
}

// ---- texture indirections (ARBfp 3.11.6, issue 24) ------------------------------------------

struct IndirectionCase {
  const char* name;
  const char* text;
  int indirections;
};

class CheckIndirections : public testing::TestWithParam<IndirectionCase> {};

TEST_P(CheckIndirections, CountedAsIssue24) {
  // Under mesa: texture[2] and texture[3] are past the spec minimum of two image units.
  Checked c = Check(GetParam().text, compiler::BuiltinProfile("mesa"));
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
  EXPECT_EQ(c.result.stats.tex_indirections, GetParam().indirections);
}

std::string PrintIndirection(const testing::TestParamInfo<IndirectionCase>& param_info) {
  return param_info.param.name;
}

INSTANTIATE_TEST_SUITE_P(
    Issue24, CheckIndirections,
    testing::Values(
        // The three example programs of ARB_fragment_program issue 24, verbatim.
        IndirectionCase{"NoTexture",
                        "!!ARBfp1.0\n"
                        "# No texture instructions, but always 1 indirection\n"
                        "MOV result.color, fragment.color;\n"
                        "END\n",
                        1},
        IndirectionCase{"SimpleDependent",
                        "!!ARBfp1.0\n"
                        "# A simple dependent texture instruction, 2 indirections\n"
                        "TEMP myColor;\n"
                        "MUL myColor, fragment.texcoord[0], fragment.texcoord[1];\n"
                        "TEX result.color, myColor, texture[0], 2D;\n"
                        "END\n",
                        2},
        IndirectionCase{"ComplexDependent",
                        "!!ARBfp1.0\n"
                        "# A more complex example with 3 indirections\n"
                        "TEMP myColor1, myColor2;\n"
                        "TEX myColor1, fragment.texcoord[0], texture[0], 2D;\n"
                        "MUL myColor1, myColor1, myColor1;\n"
                        "TEX myColor2, fragment.texcoord[1], texture[1], 2D;\n"
                        "# so far we still only have 1 indirection\n"
                        "TEX myColor2, myColor1, texture[2], 2D;      # This is #2\n"
                        "TEX result.color, myColor2, texture[3], 2D;  # And #3\n"
                        "END\n",
                        3},
        // Condition 2: the result is a temporary an ALU instruction of the node used.
        IndirectionCase{"ResultUsedByAlu",
                        "!!ARBfp1.0\nTEMP t;\nMOV t, fragment.color;\n"
                        "TEX t, fragment.texcoord, texture, 2D;\nMOV result.color, t;\nEND\n",
                        2},
        // KIL reads its coordinate like a sample, but writes nothing.
        IndirectionCase{"KilOfWrittenTemp",
                        "!!ARBfp1.0\nTEMP t;\nMOV t, fragment.color;\nKIL t;\n"
                        "MOV result.color, t;\nEND\n",
                        2},
        // Masks and swizzles are not taken into account.
        IndirectionCase{"MasksIgnored",
                        "!!ARBfp1.0\nTEMP t;\nMOV t.x, fragment.color;\n"
                        "TEX t.y, t.xxxx, texture, 2D;\nMOV result.color.xy, t;\nEND\n",
                        2}),
    PrintIndirection);

// MAX_PROGRAM_TEX_INDIRECTIONS_ARB >= 4: the error points at the instruction that starts the
// first indirection past the limit.
TEST(CheckLimits, TextureIndirections) {
  const std::string first = "TEMP t;\nTEX t, fragment.texcoord[0], texture[0], 2D;\n";
  const std::string dependent = "TEX t, t, texture[0], 2D;\n";
  Checked ok = CheckFp(first + Repeat(dependent, 3) + "MOV result.color, t;\n", SpecMin());
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  EXPECT_EQ(ok.result.stats.tex_indirections, 4);
  const std::string five = first + Repeat(dependent, 4) + "MOV result.color, t;\n";
  Checked over = CheckFp(five, SpecMin());
  EXPECT_THAT(over.ErrorKeys(), ElementsAre("7:1 arb-limit-tex-indirections"));
  EXPECT_THAT(over.Errors()[0].message, HasSubstr("texture indirection 5"));
  Checked mesa = CheckFp(five);
  EXPECT_THAT(mesa.diags, IsEmpty()) << mesa.Dump();
  EXPECT_EQ(mesa.result.stats.tex_indirections, 5);
}

// ---- the GPU profiles ------------------------------------------------------------------------

// Three texture coordinate sets and five texture indirections: past the specification's
// minimums (2 sets, 4 indirections), within Mesa's and NV40's limits, one indirection too many
// for i915 and R300 (4: i915_screen.c PIPE_SHADER_CAP_MAX_TEX_INDIRECTIONS, r300_screen.c
// is_r500 ? 511 : 4).
const char* const kThreeSetsFiveIndirections =
    "!!ARBfp1.0\n"
    "TEMP t, u;\n"
    "TEX t, fragment.texcoord[0], texture[0], 2D;\n"
    "TEX t, t, texture[0], 2D;\n"
    "TEX t, t, texture[1], 2D;\n"
    "TEX t, t, texture[1], 2D;\n"
    "ADD u, t, fragment.texcoord[2];\n"
    "TEX t, u, texture[2], 2D;\n"  // line 8: indirection 5, image unit 2
    "MUL result.color, t, fragment.texcoord[1];\n"
    "END\n";

TEST(CheckLimits, DefaultWarnsNothingPastTheMinimums) {
  Checked mesa = Check(kThreeSetsFiveIndirections);
  EXPECT_THAT(mesa.diags, IsEmpty()) << mesa.Dump();
  EXPECT_EQ(mesa.result.stats.tex_indirections, 5);
  // spec-min is the opt-in: each resource past the minimum is the error of its limit (3
  // texture coordinate sets, 3 image units, 5 indirections).
  Checked spec = Check(kThreeSetsFiveIndirections, SpecMin());
  EXPECT_THAT(spec.ErrorKeys(),
              ElementsAre("7:29 arb-binding-index-range", "8:19 arb-binding-index-range",
                          "8:1 arb-limit-tex-indirections"));
  EXPECT_THAT(spec.WarningKeys(), IsEmpty());
}

TEST(CheckLimits, I915AndR300TakeFourIndirections) {
  for (const char* name : {"i915", "r300"}) {
    SCOPED_TRACE(name);
    Checked gpu = Check(kThreeSetsFiveIndirections, compiler::BuiltinProfile(name));
    EXPECT_THAT(gpu.ErrorKeys(), ElementsAre("8:1 arb-limit-tex-indirections"));
    EXPECT_THAT(gpu.WarningKeys(), IsEmpty());
    EXPECT_THAT(gpu.Errors()[0].message,
                HasSubstr("texture indirection 5 exceeds the limit: "
                          "MAX_PROGRAM_TEX_INDIRECTIONS_ARB is 4 in profile '" +
                          std::string(name) + "'"));
  }
}

TEST(CheckLimits, Nv40AndR500TakeFiveIndirections) {
  for (const char* name : {"nv40", "nv30", "r500"}) {
    Checked gpu = Check(kThreeSetsFiveIndirections, compiler::BuiltinProfile(name));
    EXPECT_THAT(gpu.diags, IsEmpty()) << name << "\n" << gpu.Dump();
  }
}

// The GPUs' other fragment limits: i915 has 8 texture image units and 16 temporaries
// (i915_screen.c PIPE_SHADER_CAP_MAX_TEXTURE_SAMPLERS, _MAX_TEMPS), R300 16 and 32; NV30 8
// fragment inputs (nv30_screen.c PIPE_SHADER_CAP_MAX_INPUTS).
TEST(CheckLimits, GpuImageUnitsTemporariesAndInputs) {
  const std::string unit8 = "TEX result.color, fragment.texcoord[0], texture[8], 2D;\n";
  EXPECT_THAT(CheckFp(unit8, compiler::BuiltinProfile("i915")).ErrorKeys(),
              ElementsAre("2:49 arb-binding-index-range"));
  EXPECT_THAT(CheckFp(unit8, compiler::BuiltinProfile("r300")).diags, IsEmpty());
  EXPECT_THAT(CheckFp(Temps(17), compiler::BuiltinProfile("i915")).ErrorKeys(),
              ElementsAre("18:6 arb-limit-temporaries"));
  EXPECT_THAT(CheckFp(Temps(17), compiler::BuiltinProfile("r300")).diags, IsEmpty());
  std::string nine_inputs = "MOV result.color, fragment.color;\n";
  for (int i = 0; i < 8; ++i) {
    nine_inputs += "MOV result.depth, fragment.texcoord[" + std::to_string(i) + "];\n";
  }
  EXPECT_THAT(CheckFp(nine_inputs, compiler::BuiltinProfile("nv30")).ErrorKeys(),
              ElementsAre("10:19 arb-limit-attributes"));
  EXPECT_THAT(CheckFp(nine_inputs, compiler::BuiltinProfile("i915")).diags, IsEmpty());
}

// ---- checker bugs: these assert the specification and fail until the checker is fixed -----

// "A vertex program will fail to load if any GL state vector is bound multiple times in a
// single array accessed using relative addressing or bound once in two or more arrays
// accessed using relative addressing." (ARBvp 2.14.3.2, end). No diagnostic code exists for
// this rule yet, so these check only that the program is rejected.
// ARBvp 2.14.3.2: a state vector may be bound only once across relatively addressed arrays.
TEST(CheckLimits, StateVectorTwiceInRelativeArray) {
  const std::string use = "ADDRESS r;\nARL r.x, vertex.position.x;\nMOV result.position, a[r.x];\n";
  Checked absolute =
      CheckVp("PARAM a[2] = { state.fog.color, state.fog.color };\nMOV result.position, a[1];\n");
  EXPECT_TRUE(absolute.result.ok) << absolute.Dump();
  Checked relative = CheckVp("PARAM a[2] = { state.fog.color, state.fog.color };\n" + use);
  EXPECT_THAT(relative.ErrorKeys(), ElementsAre("2:33 arb-param-relative-state"))
      << relative.Dump();
}

TEST(CheckLimits, StateVectorInTwoRelativeArrays) {
  Checked c = CheckVp(
      "PARAM a[2] = { state.fog.color, program.env[0] };\n"
      "PARAM b[2] = { program.env[1], state.fog.color };\n"
      "ADDRESS r;\nARL r.x, vertex.position.x;\n"
      "ADD result.position, a[r.x], b[r.x];\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:32 arb-param-relative-state")) << c.Dump();
}

}  // namespace
}  // namespace arbiter::arbvp
