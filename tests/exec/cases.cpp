// The execution cases. Every expected value is derived by hand from the spec's pseudo-code
// (the comment says how where it is not obvious); none was copied from an engine's output.
#include "cases.h"

#include <bit>
#include <cmath>
#include <glm/mat4x4.hpp>
#include <utility>

namespace arbiter::exec_cases {
namespace {

using arbvp::ExecInputs;
using arbvp::Texture;

const float kInf = INFINITY;
const float kNaN = NAN;
const float kDenorm = 1.0e-40f;  // a denormal float
const float kHuge = 3.0e38f;
// The reason the interpreter gives a product of 0 and an infinity or NaN.
const char* const kZeroTimesNonFinite = "0 times an infinity or NaN";

std::string Fp(const std::string& body) { return "!!ARBfp1.0\n" + body + "END\n"; }
std::string Vp(const std::string& body) { return "!!ARBvp1.0\n" + body + "END\n"; }

Expect Eq(std::string reg, Vec4 v, uint8_t mask = 0xF) {
  Expect e;
  e.reg = std::move(reg);
  e.value = v;
  e.mask = mask;
  return e;
}
Expect Rel(std::string reg, Vec4 v, float bound = kApprox, uint8_t mask = 0xF) {
  Expect e = Eq(std::move(reg), v, mask);
  e.tolerance = Tolerance::Relative;
  e.bound = bound;
  return e;
}
Expect Abs(std::string reg, Vec4 v, float bound = kApprox, uint8_t mask = 0xF) {
  Expect e = Eq(std::move(reg), v, mask);
  e.tolerance = Tolerance::Absolute;
  e.bound = bound;
  return e;
}
Expect Undef(std::string reg, uint8_t mask, std::string reason) {
  Expect e;
  e.reg = std::move(reg);
  e.mask = 0;
  e.undefined = mask;
  e.reason = std::move(reason);
  return e;
}
Expect Written(std::string reg, Vec4 v, uint8_t mask) {
  Expect e = Eq(std::move(reg), v, mask);
  e.written = mask;
  return e;
}
Expect Absent(std::string reg) {
  Expect e;
  e.reg = std::move(reg);
  e.mask = 0;
  e.absent = true;
  return e;
}
Expect At(size_t vector, Expect e) {
  e.vector = vector;
  return e;
}

using Setup = std::function<void(ExecInputs&)>;

// Fragment (or vertex) program.env[0..] = values.
Setup FpEnv(std::vector<Vec4> values) {
  return [values](ExecInputs& in) {
    for (size_t i = 0; i < values.size(); ++i)
      in.fragment_params.env[static_cast<int>(i)] = values[i];
  };
}
Setup VpEnv(std::vector<Vec4> values) {
  return [values](ExecInputs& in) {
    for (size_t i = 0; i < values.size(); ++i)
      in.vertex_params.env[static_cast<int>(i)] = values[i];
  };
}
// A matrix given by its ROWS (as ARB reads them), stored column-major as GL and glm do.
glm::mat4 Rows(Vec4 r0, Vec4 r1, Vec4 r2, Vec4 r3) {
  glm::mat4 m(1.0f);
  const Vec4* rows[4] = {&r0, &r1, &r2, &r3};
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) m[c][r] = (*rows[r])[static_cast<size_t>(c)];
  }
  return m;
}

// An invertible, non-symmetric matrix whose inverse is exact in binary:
// x' = 2x + 1, y' = 4y + 2, z' = 8z + 3. Inverse rows: (0.5,0,0,-0.5), (0,0.25,0,-0.5),
// (0,0,0.125,-0.375), (0,0,0,1).
glm::mat4 ScaleTranslate() { return Rows({2, 0, 0, 1}, {0, 4, 0, 2}, {0, 0, 8, 3}, {0, 0, 0, 1}); }
// Swaps x and y: P * M has M's rows 0 and 1 swapped, M * P its columns.
glm::mat4 SwapXY() { return Rows({0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}); }

// A 2x2 RGBA texture: (0,0) red, (1,0) green, (0,1) blue, (1,1) white.
Texture Quad2D(arbvp::TexFilter filter, arbvp::TexWrap wrap) {
  Texture t;
  t.dim = arbvp::TexDim::Tex2D;
  t.width = 2;
  t.height = 2;
  t.texels = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 1};
  t.filter = filter;
  t.wrap = wrap;
  return t;
}

// A 1x1 depth texture holding `depth`.
Texture Depth2D(float depth, bool compare, arbvp::CompareFunc func = arbvp::CompareFunc::Lequal,
                arbvp::DepthMode mode = arbvp::DepthMode::Luminance) {
  Texture t;
  t.dim = arbvp::TexDim::Tex2D;
  t.texels = {depth, 0, 0, 1};
  t.depth_texture = true;
  t.compare = compare;
  t.compare_func = func;
  t.depth_mode = mode;
  return t;
}

// Vectors whose fragment.texcoord[0] are `coords`.
Setup TexCoords(std::vector<Vec4> coords) {
  return [coords](ExecInputs& in) {
    in.vectors.resize(coords.size());
    for (size_t i = 0; i < coords.size(); ++i) in.vectors[i].fragment.texcoord[0] = coords[i];
  };
}

Setup WithTexture(int unit, Texture tex, Setup then) {
  return [unit, tex, then](ExecInputs& in) {
    in.textures[unit] = tex;
    then(in);
  };
}

class Table {
 public:
  void Add(std::string name, std::string spec, std::string vp, std::string fp, Setup setup,
           std::vector<Expect> expects, std::vector<size_t> killed = {}) {
    ExecCase c;
    c.name = std::move(name);
    c.spec = std::move(spec);
    c.vertex_text = std::move(vp);
    c.fragment_text = std::move(fp);
    c.setup = setup ? std::move(setup) : [](ExecInputs&) {};
    c.expects = std::move(expects);
    c.killed = std::move(killed);
    cases.push_back(std::move(c));
  }
  // A fragment program alone reading program.env[0..2].
  void Fp1(std::string name, std::string spec, const std::string& body, std::vector<Vec4> env,
           std::vector<Expect> expects) {
    Add(std::move(name), std::move(spec), "",
        Fp("PARAM e0 = program.env[0];\n"
           "PARAM e1 = program.env[1];\n"
           "PARAM e2 = program.env[2];\n" +
           body),
        FpEnv(std::move(env)), std::move(expects));
  }
  // A vertex program alone reading program.env[0..2].
  void Vp1(std::string name, std::string spec, const std::string& body, std::vector<Vec4> env,
           std::vector<Expect> expects) {
    Add(std::move(name), std::move(spec),
        Vp("PARAM e0 = program.env[0];\nPARAM e1 = program.env[1];\n"
           "PARAM e2 = program.env[2];\n" +
           body),
        "", VpEnv(std::move(env)), std::move(expects));
  }
  std::vector<ExecCase> cases;
};

const char kColor[] = "result.color";
const char kTex0[] = "result.texcoord[0]";

void AluCases(Table& t) {
  // Swizzle, negation, masks.
  t.Fp1("mov_swizzle", "ARBfp 3.11.4.1", "MOV result.color, e0.yzwx;\n", {{1, 2, 3, 4}},
        {Eq(kColor, {2, 3, 4, 1})});
  t.Fp1("mov_negate_replicate", "ARBfp 3.11.4.1: '.z' is '.zzzz'", "MOV result.color, -e0.z;\n",
        {{1, 2, 3, 4}}, {Eq(kColor, {-3, -3, -3, -3})});
  t.Fp1("mov_negate_zero", "negation of +0 is -0", "MOV result.color, -e0;\n",
        {{0.0f, -0.0f, kInf, kNaN}}, {Eq(kColor, {-0.0f, 0.0f, -kInf, kNaN})});
  t.Fp1("write_mask_xz", "ARBfp 3.11.4.3", "MOV result.color.xz, e0;\n", {{1, 2, 3, 4}},
        {Written(kColor, {1, 0, 3, 0}, 0x5)});
  t.Fp1("write_mask_rgba_names", "ARBfp 3.11.4.3: .ga is .yw", "MOV result.color.ga, e0.x;\n",
        {{7, 2, 3, 4}}, {Written(kColor, {0, 7, 0, 7}, 0xA)});
  t.Fp1("mask_merges_with_previous", "2.14.4.3: unmasked components keep their value",
        "TEMP t;\nMOV t, e0;\nMOV t.yw, e1;\nMOV result.color, t;\n", {{1, 2, 3, 4}, {5, 6, 7, 8}},
        {Eq(kColor, {1, 6, 3, 8})});

  t.Fp1("abs", "ARBfp 3.11.5.1", "ABS result.color, e0;\n", {{-1.5f, -0.0f, -kInf, kNaN}},
        {Eq(kColor, {1.5f, 0.0f, kInf, kNaN})});
  t.Fp1("abs_negated_operand", "ABS of -x: the operand is negated first",
        "ABS result.color, -e0;\n", {{2, -3, 0, 1}}, {Eq(kColor, {2, 3, 0, 1})});
  // 2 + -2 = +0 (IEEE round-to-nearest); inf + -inf = NaN; 3e38 + 3e38 overflows to inf.
  t.Fp1("add_special", "ARBfp 3.11.5.2", "ADD result.color, e0, e1;\n",
        {{1, 2, kInf, kHuge}, {0.5f, -2, -kInf, kHuge}}, {Eq(kColor, {1.5f, 0.0f, kNaN, kInf})});
  t.Fp1("add_zero_identity", "2.14.5.2 rule 2: x + 0 = x", "ADD result.color, e0, e1;\n",
        {{kDenorm, -kDenorm, 5, -0.0f}, {0, 0, 0, 0}}, {Eq(kColor, {kDenorm, -kDenorm, 5, 0.0f})});
  // -0 - +0 = -0.
  t.Fp1("sub", "ARBfp 3.11.5.27", "SUB result.color, e0, e1;\n", {{-0.0f, 1, 3, 4}, {0, 1, 2, 1}},
        {Eq(kColor, {-0.0f, 0.0f, 1, 3})});
  // -0 * 5 = -0 (rule 2); inf * 0 is undefined (below); a denormal times 1 stays (rule 3).
  t.Fp1("mul_special", "ARBfp 3.11.5.19", "MUL result.color, e0, e1;\n",
        {{2, -0.0f, kInf, kDenorm}, {3, 5, 0, 1}},
        {Eq(kColor, {6, -0.0f, 0, kDenorm}, 0xB), Undef(kColor, 0x4, kZeroTimesNonFinite)});
  // Rule 2, "+/-0.0 * <x> = +/-0.0, at least for all <x> that correspond to representable
  // numbers (IEEE "not a number" and "infinity" encodings may be exceptions)": 0 * NaN,
  // -0 * inf and NaN * 0 may give 0 or NaN, so they are undefined; inf * 2 is inf.
  t.Fp1("mul_zero_non_finite", "ARBfp 3.11.5.19 rule 2; GL 2.0 2.1.1",
        "MUL result.color, e0, e1;\n", {{0, -0.0f, kNaN, kInf}, {kNaN, kInf, 0, 2}},
        {Eq(kColor, {0, 0, 0, kInf}, 0x8), Undef(kColor, 0x7, kZeroTimesNonFinite)});
  // 0 * 5 + -0 = +0 + -0 = +0.
  // The product of MAD is "subject to the same rules" as MUL's: 0 * inf undefined, 2 * inf
  // + 1 = inf, 1 * 0 + 1 = 1.
  t.Fp1("mad_zero_non_finite", "ARBfp 3.11.5.15, 3.11.5.19 rule 2",
        "MAD result.color, e0, e1, e2;\n", {{0, 2, 1, kNaN}, {kInf, kInf, 0, 0}, {1, 1, 1, 1}},
        {Eq(kColor, {0, kInf, 1, 0}, 0x6), Undef(kColor, 0x9, kZeroTimesNonFinite)});
  t.Fp1("mad", "ARBfp 3.11.5.15", "MAD result.color, e0, e1, e2;\n",
        {{2, 3, 4, 0}, {0.5f, 2, -1, 5}, {1, 1, 1, -0.0f}}, {Eq(kColor, {2, 7, -3, 0.0f})});
  // MAX: (a > b) ? a : b -> NaN > 3 is false: 3; -0 > +0 false: +0; 5 > NaN false: NaN.
  t.Fp1("max_nan_zero", "ARBfp 3.11.5.16", "MAX result.color, e0, e1;\n",
        {{1, kNaN, -0.0f, 5}, {2, 3, 0.0f, kNaN}}, {Eq(kColor, {2, 3, 0.0f, kNaN})});
  // MIN: (a > b) ? b : a -> NaN; -0; 5.
  t.Fp1("min_nan_zero", "ARBfp 3.11.5.17", "MIN result.color, e0, e1;\n",
        {{1, kNaN, -0.0f, 5}, {2, 3, 0.0f, kNaN}}, {Eq(kColor, {1, kNaN, -0.0f, 5})});
  t.Fp1("flr", "ARBfp 3.11.5.10", "FLR result.color, e0;\n", {{-1.7f, 2.3f, -0.0f, -kInf}},
        {Eq(kColor, {-2, 2, -0.0f, -kInf})});
  // -1.75 - floor(-1.75) = -1.75 + 2 = 0.25.
  t.Fp1("frc", "ARBfp 3.11.5.11", "FRC result.color, e0;\n", {{-1.75f, 2.25f, 5, -0.25f}},
        {Eq(kColor, {0.25f, 0.25f, 0, 0.75f})});
  t.Fp1("dp3", "ARBfp 3.11.5.5", "DP3 result.color, e0, e1;\n", {{1, 2, 3, 100}, {4, 5, 6, 100}},
        {Eq(kColor, {32, 32, 32, 32})});
  t.Fp1("dp4", "ARBfp 3.11.5.6", "DP4 result.color, e0, e1;\n", {{1, 2, 3, 4}, {5, 6, 7, 8}},
        {Eq(kColor, {70, 70, 70, 70})});
  // A dot product is a sum of products: inf * 0 in one term makes the sum undefined
  // (3.11.5.19 rule 2); inf * 2 + 1 + 1 = inf is defined.
  t.Fp1("dp4_nan_and_inf", "ARBfp 3.11.5.6, 3.11.5.19 rule 2", "DP4 result.color.x, e0, e1;\n",
        {{kInf, 1, 1, 1}, {0, 1, 1, 1}}, {Undef(kColor, 0x1, kZeroTimesNonFinite)});
  t.Fp1("dp3_infinite", "ARBfp 3.11.5.5", "DP3 result.color.x, e0, e1;\n",
        {{kInf, 1, 1, 0}, {2, 1, 1, kNaN}}, {Eq(kColor, {kInf, 0, 0, 0}, 0x1)});
  t.Fp1("dph_zero_non_finite", "ARBfp 3.11.5.7, 3.11.5.19 rule 2", "DPH result.color.x, e0, e1;\n",
        {{1, 0, 1, 5}, {1, kNaN, 1, 1}}, {Undef(kColor, 0x1, kZeroTimesNonFinite)});
  // 1*4 + 2*5 + 3*6 + 7 (tmp0.w ignored).
  t.Fp1("dph", "ARBfp 3.11.5.7", "DPH result.color, e0, e1;\n", {{1, 2, 3, 999}, {4, 5, 6, 7}},
        {Eq(kColor, {39, 39, 39, 39})});
  t.Fp1("dst", "ARBfp 3.11.5.8: (1, a.y*b.y, a.z, b.w)", "DST result.color, e0, e1;\n",
        {{9, 4, 16, 9}, {9, 0.25f, 9, 0.5f}}, {Eq(kColor, {1, 1, 16, 0.5f})});
  t.Fp1("sge", "ARBfp 3.11.5.24: NaN compares false; -0 >= +0", "SGE result.color, e0, e1;\n",
        {{1, 2, kNaN, -0.0f}, {1, 3, 0, 0.0f}}, {Eq(kColor, {1, 0, 0, 1})});
  t.Fp1("slt", "ARBfp 3.11.5.26", "SLT result.color, e0, e1;\n",
        {{1, 2, kNaN, -0.0f}, {1, 3, 0, 0.0f}}, {Eq(kColor, {0, 1, 0, 0})});
  // a < 0 ? b : c, -0 < 0 and NaN < 0 are false.
  t.Fp1("cmp", "ARBfp 3.11.5.3", "CMP result.color, e0, e1, e2;\n",
        {{-1, 0, -0.0f, kNaN}, {10, 20, 30, 40}, {1, 2, 3, 4}}, {Eq(kColor, {10, 2, 3, 4})});
  // a*b + (1-a)*c: 0.25*4 + 0.75*8 = 7; 0*8 + 1*0 = 0; 12; 0.5*2 + 0.5*6 = 4.
  // a*b + (1-a)*c: 0*inf and (1-1)*inf are undefined; 0.5*inf + 0.5*6 = inf; 0*3 + 1*NaN
  // = NaN.
  t.Fp1("lrp_zero_non_finite", "ARBfp 3.11.5.14, 3.11.5.19 rule 2",
        "LRP result.color, e0, e1, e2;\n",
        {{0, 1, 0.5f, 0}, {kInf, 2, kInf, 3}, {4, kInf, 6, kNaN}},
        {Eq(kColor, {0, 0, kInf, kNaN}, 0xC), Undef(kColor, 0x3, kZeroTimesNonFinite)});
  t.Fp1("lrp", "ARBfp 3.11.5.14", "LRP result.color, e0, e1, e2;\n",
        {{0.25f, 0, 1, 0.5f}, {4, 8, 12, 2}, {8, 0, 4, 6}}, {Eq(kColor, {7, 0, 12, 4})});
  // (2*6 - 3*5, 3*4 - 1*6, 1*5 - 2*4) = (-3, 6, -3).
  // DST.y = a.y * b.y = 0 * inf: undefined; x = 1, z = a.z, w = b.w.
  t.Fp1("dst_zero_non_finite", "ARBfp 3.11.5.8, 3.11.5.19 rule 2", "DST result.color, e0, e1;\n",
        {{5, 0, 3, 7}, {6, kInf, 8, 9}},
        {Eq(kColor, {1, 0, 3, 9}, 0xD), Undef(kColor, 0x2, kZeroTimesNonFinite)});
  // XPD of (0,1,0) and (inf,0,0): x = 1*0 - 0*0 = 0; y = 0*inf - 0*0 (undefined);
  // z = 0*0 - 1*inf = -inf.
  t.Fp1("xpd_zero_non_finite", "ARBfp 3.11.5.29, 3.11.5.19 rule 2",
        "XPD result.color.xyz, e0, e1;\n", {{0, 1, 0, 0}, {kInf, 0, 0, 0}},
        {Eq(kColor, {0, 0, -kInf, 0}, 0x5), Undef(kColor, 0x2, kZeroTimesNonFinite)});
  t.Fp1("xpd", "ARBfp 3.11.5.29", "XPD result.color, e0, e1;\n", {{1, 2, 3, 7}, {4, 5, 6, 7}},
        {Eq(kColor, {-3, 6, -3, 0}, 0x7), Undef(kColor, 0x8, "XPD w at 5:1")});
  t.Fp1("swz", "ARBfp 3.11.5.28", "SWZ result.color, e0, -y, 0, 1, -w;\n", {{1, 2, 3, 4}},
        {Eq(kColor, {-2, 0, 1, -4})});
  // "-0" selects 0.0 and negates it: -0.0.
  t.Fp1("swz_negative_constants", "ARBfp 3.11.5.28: negate after selection",
        "SWZ result.color, e0, -0, x, -1, -z;\n", {{1, 2, -3, 4}}, {Eq(kColor, {-0.0f, 1, -1, 3})});
  t.Fp1("swz_rgba_names", "ARBfp 3.11.5.28", "SWZ result.color, e0, a, b, g, r;\n", {{1, 2, 3, 4}},
        {Eq(kColor, {4, 3, 2, 1})});
  // _SAT: "if (x < 0) x = 0; else if (x > 1) x = 1": -0 and NaN pass through.
  t.Fp1("saturate", "ARBfp 3.11.4.3", "MOV_SAT result.color, e0;\n", {{-1, -0.0f, 2, kNaN}},
        {Eq(kColor, {0, -0.0f, 1, kNaN})});
  t.Fp1("saturate_after_op", "_SAT clamps the result, not the operands",
        "ADD_SAT result.color, e0, e1;\n", {{0.75f, -2, 0.5f, 3}, {0.75f, 1.5f, 0.25f, -2.5f}},
        {Eq(kColor, {1, 0, 0.75f, 0.5f})});
  t.Fp1("saturate_mask", "_SAT and a mask", "MUL_SAT result.color.yz, e0, e1;\n",
        {{2, 2, 2, 2}, {1, -1, 0.25f, 1}}, {Written(kColor, {0, 0, 0.5f, 0}, 0x6)});

  // Scalar operations replicate (and respect the mask).
  t.Fp1("rcp_replicate_mask", "ARBfp 3.11.5.21", "RCP result.color.xw, e0.y;\n", {{0, 4, 0, 0}},
        {Written(kColor, {0.25f, 0, 0, 0.25f}, 0x9)});
  t.Fp1("rcp_one_exact", "ApproxReciprocal(+1.0) = +1.0 (rule 1)", "RCP result.color, e0.x;\n",
        {{1, 0, 0, 0}}, {Eq(kColor, {1, 1, 1, 1})});
  t.Fp1("rcp_values", "ARBfp 3.11.5.21",
        "RCP result.color.x, e0.x;\nRCP result.color.y, e0.y;\nRCP result.color.z, e0.z;\n"
        "RCP result.color.w, e0.w;\n",
        {{3, -0.5f, kInf, 0.0f}}, {Rel(kColor, {1.0f / 3.0f, -2, 0, kInf})});
  t.Fp1("rcp_negative_zero", "sign of RCP(-0) is undefined (docs/design/semantics.md)",
        "RCP result.color, e0.x;\n", {{-0.0f, 0, 0, 0}}, {Undef(kColor, 0xF, "RCP of -0")});
  // RSQ uses |x|: RSQ(-4) = 0.5; RSQ(-0) = 1/sqrt(+0) = +inf.
  t.Fp1("rsq_abs", "ARBfp 3.11.5.22",
        "RSQ result.color.x, e0.x;\nRSQ result.color.y, e0.y;\nRSQ result.color.z, e0.z;\n"
        "RSQ result.color.w, e0.w;\n",
        {{-4, 16, -0.0f, kInf}}, {Rel(kColor, {0.5f, 0.25f, kInf, 0})});
  t.Fp1("ex2", "ARBfp 3.11.5.9",
        "EX2 result.color.x, e0.x;\nEX2 result.color.y, e0.y;\nEX2 result.color.z, e0.z;\n"
        "EX2 result.color.w, e0.w;\n",
        {{3, -1, -kInf, 200}}, {Rel(kColor, {8, 0.5f, 0, kInf})});
  t.Fp1("ex2_fraction", "ARBfp 3.11.5.9: 2^0.5", "EX2 result.color, e0.x;\n", {{0.5f, 0, 0, 0}},
        {Rel(kColor, {1.41421356f, 1.41421356f, 1.41421356f, 1.41421356f})});
  t.Fp1("lg2", "ARBfp 3.11.5.12",
        "LG2 result.color.x, e0.x;\nLG2 result.color.y, e0.y;\nLG2 result.color.z, e0.z;\n"
        "LG2 result.color.w, e0.w;\n",
        {{8, 0.5f, kInf, 10}}, {Rel(kColor, {3, -1, kInf, 3.32192809f})});
  t.Fp1(
      "lg2_zero_undefined", "ARBfp 3.11.5.12: zero or negative is undefined",
      "LG2 result.color.x, e0.x;\nLG2 result.color.y, e0.y;\nLG2 result.color.z, e0.z;\n"
      "LG2 result.color.w, e0.w;\n",
      {{0, -0.0f, -1, 2}},
      {Undef(kColor, 0x1, "LG2 of a value <= 0 at 5:1"),
       Undef(kColor, 0x2, "LG2 of a value <= 0 at 6:1"),
       Undef(kColor, 0x4, "LG2 of a value <= 0 at 7:1"), Rel(kColor, {0, 0, 0, 1}, kApprox, 0x8)});
  t.Fp1("pow", "ARBfp 3.11.5.20",
        "POW result.color.x, e0.x, e1.x;\nPOW result.color.y, e0.y, e1.y;\n"
        "POW result.color.z, e0.z, e1.z;\nPOW result.color.w, e0.w, e1.w;\n",
        {{2, 4, 9, 3}, {10, 0.5f, 0.5f, 0}}, {Rel(kColor, {1024, 2, 3, 1})});
  t.Fp1("pow_negative_base", "ARBfp 3.11.5.20: negative base goes through a logarithm",
        "POW result.color, e0.x, e1.x;\n", {{-2, 0, 0, 0}, {2, 0, 0, 0}},
        {Undef(kColor, 0xF, "POW with a negative base")});
  t.Fp1("pow_zero_zero", "POW(0, 0) is undefined (docs/design/semantics.md)",
        "POW result.color, e0.x, e1.x;\n", {{0, 0, 0, 0}, {0, 0, 0, 0}},
        {Undef(kColor, 0xF, "POW with base 0")});
  t.Fp1("pow_zero_base", "ARBfp 3.11.5.20: ApproxPower goes through ApproxLog2(0), undefined",
        "POW result.color, e0.x, e1.x;\n", {{0, 0, 0, 0}, {2, 0, 0, 0}},
        {Undef(kColor, 0xF, "POW with base 0")});
  t.Fp1("sin_cos", "ARBfp 3.11.5.25, 3.11.5.4: any angle",
        "SIN result.color.x, e0.x;\nSIN result.color.y, e0.y;\nCOS result.color.z, e0.x;\n"
        "COS result.color.w, e0.z;\n",
        {{0, 1.57079633f, 3.14159265f, 0}}, {Abs(kColor, {0, 1, 1, -1})});
  // sin(100) = -0.50636564, cos(-100) = 0.86231887: no range reduction by the program.
  t.Fp1("sin_cos_large_angle", "ARBfp 3.11.5.25: the angle need not be in [-PI, PI]",
        "SIN result.color.x, e0.x;\nCOS result.color.y, e0.y;\n", {{100, -100, 0, 0}},
        {Abs(kColor, {-0.50636564f, 0.86231887f, 0, 0}, kApprox, 0x3)});
  // (cos 0.5, sin 0.5) = (0.87758256, 0.47942554).
  t.Fp1("scs", "ARBfp 3.11.5.23", "SCS result.color, e0.x;\n", {{0.5f, 0, 0, 0}},
        {Abs(kColor, {0.87758256f, 0.47942554f, 0, 0}, kApprox, 0x3),
         Undef(kColor, 0xC, "SCS z and w at 5:1")});
  t.Fp1("scs_out_of_range", "ARBfp 3.11.5.23: outside [-PI, PI] the result is undefined",
        "SCS result.color.xy, e0.x;\n", {{4, 0, 0, 0}},
        {Undef(kColor, 0x3, "SCS of an angle outside [-PI, PI]")});

  // LIT: (1, max(x,0), x > 0 ? max(y,0)^clamp(w) : 0, 1).
  t.Fp1("lit", "ARBfp 3.11.5.13", "LIT result.color, e0;\n", {{0.5f, 0.25f, 9, 2}},
        {Eq(kColor, {1, 0.5f, 0, 1}, 0xB), Rel(kColor, {0, 0, 0.0625f, 0}, kApprox, 0x4)});
  t.Fp1("lit_negative_diffuse", "LIT: x <= 0 forces z to 0", "LIT result.color, e0;\n",
        {{-1, 0.5f, 9, 2}}, {Eq(kColor, {1, 0, 0, 1})});
  t.Fp1("lit_zero_pow_zero", "LIT: 0^0 = 1 (RoughApproxPower(0, 0) = 1)", "LIT result.color, e0;\n",
        {{1, 0, 9, 0}}, {Eq(kColor, {1, 1, 1, 1}, 0xB), Rel(kColor, {0, 0, 1, 0}, kApprox, 0x4)});
  t.Fp1("lit_negative_specular", "LIT: y < 0 is clamped to 0, 0^2 = 0", "LIT result.color, e0;\n",
        {{1, -0.5f, 9, 2}}, {Eq(kColor, {1, 1, 0, 1})});
  // w = 200 clamps to 128 - eps: 2^(128 - eps) = 3.4026e38 (finite); a clamp at +-180 (a
  // known translator bug) would give inf.
  t.Fp1("lit_exponent_clamp", "LIT: w clamped to (-128, 128) exclusive",
        "LIT result.color.z, e0;\nLIT result.depth.z, e1;\n", {{1, 2, 0, 200}, {1, 0.5f, 0, -200}},
        {Rel(kColor, {0, 0, 3.40264e38f, 0}, kApprox, 0x4),
         Rel("result.depth", {0, 0, 3.40264e38f, 0}, kApprox, 0x4)});
}

void UndefinedCases(Table& t) {
  t.Add("temp_read_before_written", "ARBfp 3.11.3.3: temporaries start undefined", "",
        Fp("TEMP t;\nMOV result.color, t;\n"), nullptr,
        {Undef(kColor, 0x1, "temporary 't.x' read before it is written at 3:1"),
         Undef(kColor, 0x8, "temporary 't.w' read before it is written at 3:1")});
  t.Add("temp_partly_written", "only the unwritten components are undefined", "",
        Fp("TEMP t;\nMOV t.x, fragment.color;\nMOV result.color, t.xxyy;\n"), nullptr,
        {Eq(kColor, {1, 1, 0, 0}, 0x3), Undef(kColor, 0xC, "temporary 't.y'")});
  // An undefined LG2 result flows through ADD: the tag keeps the origin.
  t.Fp1("undefined_propagates", "undefined inputs give undefined results",
        "TEMP t;\nLG2 t, e0.x;\nADD result.color, t, e1;\n", {{0, 0, 0, 0}, {1, 1, 1, 1}},
        {Undef(kColor, 0xF, "LG2 of a value <= 0 at 6:1")});
  // XPD.w is undefined: DP4 reads it, DP3 does not.
  t.Fp1("undefined_dot_products", "DP3 ignores w",
        "TEMP t;\nXPD t, e0, e1;\nDP4 result.color.x, t, e2;\nDP3 result.color.y, t, e2;\n",
        {{1, 2, 3, 0}, {4, 5, 6, 0}, {1, 1, 1, 1}},
        {Undef(kColor, 0x1, "XPD w at 6:1"), Eq(kColor, {0, 0, 0, 0}, 0x2)});
  // Swizzling w away from an XPD result keeps it defined.
  t.Fp1("undefined_swizzled_away", "only the components read matter",
        "TEMP t;\nXPD t, e0, e1;\nMOV result.color, t.xyzx;\n", {{1, 0, 0, 0}, {0, 1, 0, 0}},
        {Eq(kColor, {0, 0, 1, 0})});
  // CMP depends on the operand it selects only.
  t.Fp1("undefined_cmp_unselected", "CMP selects per component",
        "TEMP t;\nXPD t, e0, e1;\nCMP result.color, e2, t.w, e1;\n",
        {{1, 0, 0, 0}, {0, 1, 0, 0}, {1, -1, 1, -1}},
        {Eq(kColor, {0, 0, 0, 0}, 0x5), Undef(kColor, 0xA, "XPD w")});
  t.Add("unwritten_result_not_reported", "ARBvp 2.14.3.4: unwritten results stay undefined",
        Vp("MOV result.texcoord[1], vertex.position;\n"), "", nullptr,
        {Eq("result.texcoord[1]", {0, 0, 0, 1}), Absent("result.color.front.primary"),
         Absent("result.position")});
  t.Add("unwritten_fragment_color", "ARBfp 3.11.3.4: result.color unwritten is undefined", "",
        Fp("MOV result.depth.z, fragment.color.x;\n"), nullptr,
        {Written("result.depth", {0, 0, 1, 0}, 0x4), Absent(kColor)});
}

void KillCases(Table& t) {
  // Vector 1 has a negative component; vector 2 only NaN, -0 and +inf, which do not kill.
  t.Add("kil", "ARBfp 3.11.6.4", "", Fp("KIL fragment.texcoord[0];\nMOV result.color, 1;\n"),
        TexCoords({{1, 1, 1, 1}, {0, 0, -1, 0}, {kNaN, 0, -0.0f, kInf}}),
        {At(0, Eq(kColor, {1, 1, 1, 1})), At(2, Eq(kColor, {1, 1, 1, 1}))}, {1});
  t.Add("kil_swizzle_negate", "KIL reads its operand with swizzle and sign", "",
        Fp("KIL -fragment.texcoord[0].y;\nMOV result.color, 1;\n"),
        TexCoords({{-5, 1, -5, -5}, {1, -1, 1, 1}}), {At(1, Eq(kColor, {1, 1, 1, 1}))}, {0});
}

void VertexCases(Table& t) {
  t.Add("vertex_attribute_fill",
        "ARBvp table X.2: normal w = 1, fogcoord (f,0,0,1); GL 2.0 2.7: secondary A = 1",
        Vp("MOV result.texcoord[0], vertex.normal;\nMOV result.texcoord[1], vertex.fogcoord;\n"
           "MOV result.texcoord[2], vertex.attrib[7];\nMOV result.texcoord[3], "
           "vertex.texcoord[2];\nMOV result.color, vertex.color;\n"
           "MOV result.color.secondary, vertex.color.secondary;\n"),
        "",
        [](ExecInputs& in) {
          in.vectors[0].vertex.normal = {1, 2, 3, 9};
          in.vectors[0].vertex.fogcoord = {5, 7, 7, 7};
          in.vectors[0].vertex.generic[7] = {0.5f, 1.5f, 2.5f, 3.5f};
          in.vectors[0].vertex.texcoord[2] = {4, 3, 2, 1};
          in.vectors[0].vertex.color = {0.25f, 0.5f, 0.75f, 1};
          in.vectors[0].vertex.secondary_color = {1, 0.5f, 0.25f, 0};
        },
        {Eq("result.texcoord[0]", {1, 2, 3, 1}), Eq("result.texcoord[1]", {5, 0, 0, 1}),
         Eq("result.texcoord[2]", {0.5f, 1.5f, 2.5f, 3.5f}), Eq("result.texcoord[3]", {4, 3, 2, 1}),
         Eq("result.color.front.primary", {0.25f, 0.5f, 0.75f, 1}),
         // GL 2.0 2.7: "Secondary A is always set to 1.0", whatever the model holds.
         Eq("result.color.front.secondary", {1, 0.5f, 0.25f, 1})});
  t.Add("vertex_attrib0_is_position", "ARBvp 2.14.3.1: vertex.attrib[0] = vertex.position",
        Vp("MOV result.position, vertex.attrib[0];\n"), "",
        [](ExecInputs& in) {
          in.vectors[0].vertex.position = {1, 2, 3, 4};
        },
        {Eq("result.position", {1, 2, 3, 4})});
  t.Add("vertex_results_all", "ARBvp table X.4",
        Vp("MOV result.color.back, 1;\nMOV result.color.back.secondary, 0.5;\n"
           "MOV result.pointsize.x, 3;\nMOV result.fogcoord.x, 2;\n"),
        "", nullptr,
        {Eq("result.color.back.primary", {1, 1, 1, 1}),
         Eq("result.color.back.secondary", {0.5f, 0.5f, 0.5f, 0.5f}),
         Written("result.pointsize", {3, 0, 0, 0}, 0x1),
         Written("result.fogcoord", {2, 0, 0, 0}, 0x1)});
  // ARL floors: 1.7 -> 1 (a[1 + 1] = a[2]), -0.5 -> -1 (a[-1 + 2] = a[1]).
  const std::string array =
      "PARAM a[4] = { {1,1,1,1}, {2,2,2,2}, {3,3,3,3}, {4,4,4,4} };\nADDRESS A0;\n";
  t.Vp1("arl_relative", "ARBvp 2.14.5.3, 2.14.4.2",
        array +
            "ARL A0.x, e0.x;\nMOV result.texcoord[0], a[A0.x+1];\n"
            "ARL A0.x, e0.y;\nMOV result.texcoord[1], a[A0.x+2];\n"
            "ARL A0.x, e0.z;\nMOV result.texcoord[2], a[A0.x-3];\n",
        {{1.7f, -0.5f, 3.0f, 0}},
        {Eq("result.texcoord[0]", {3, 3, 3, 3}), Eq("result.texcoord[1]", {2, 2, 2, 2}),
         Eq("result.texcoord[2]", {1, 1, 1, 1})});
  t.Vp1("arl_out_of_range", "ARBvp 2.14.4.2: out of range is undefined (reads 0 as Mesa)",
        array +
            "ARL A0.x, e0.x;\nMOV result.texcoord[0], a[A0.x+1];\n"
            "MOV result.texcoord[1], a[A0.x-4];\n",
        {{3, 0, 0, 0}},
        {Undef("result.texcoord[0]", 0xF, "relative address A0.x+1 = 4 outside 'a[0..3]' at 8:1"),
         Undef("result.texcoord[1]", 0xF, "relative address A0.x-4 = -1 outside 'a[0..3]'")});
  t.Vp1("arl_unwritten_address", "ARBvp 2.14.3.5: address registers start undefined",
        array + "MOV result.texcoord[0], a[A0.x];\n", {},
        {Undef("result.texcoord[0]", 0xF, "address register 'A0' read before ARL wrote it")});
  // EXP 2.5: (2^2, 0.5, ~2^2.5, 1); EXP -1.25: (2^-2, 0.75, ~2^-1.25, 1).
  t.Vp1("exp", "ARBvp 2.14.5.9", "EXP result.texcoord[0], e0.x;\nEXP result.texcoord[1], e0.y;\n",
        {{2.5f, -1.25f, 0, 0}},
        {Eq("result.texcoord[0]", {4, 0.5f, 0, 1}, 0xB),
         Rel("result.texcoord[0]", {0, 0, 5.65685425f, 0}, kApprox, 0x4),
         Eq("result.texcoord[1]", {0.25f, 0.75f, 0, 1}, 0xB),
         Rel("result.texcoord[1]", {0, 0, 0.42044821f, 0}, kApprox, 0x4)});
  // LOG -10: |t| = 10 = 1.25 * 2^3 -> (3, 1.25, ~3.3219, 1); 0.375 = 1.5 * 2^-2.
  t.Vp1("log", "ARBvp 2.14.5.14: uses |x|",
        "LOG result.texcoord[0], e0.x;\nLOG result.texcoord[1], e0.y;\n", {{-10, 0.375f, 0, 0}},
        {Eq("result.texcoord[0]", {3, 1.25f, 0, 1}, 0xB),
         Rel("result.texcoord[0]", {0, 0, 3.32192809f, 0}, kApprox, 0x4),
         Eq("result.texcoord[1]", {-2, 1.5f, 0, 1}, 0xB),
         Rel("result.texcoord[1]", {0, 0, -1.41503750f, 0}, kApprox, 0x4)});
  t.Vp1(
      "log_zero", "ARBvp 2.14.5.14: log2(0) does not exist", "LOG result.texcoord[0], e0.x;\n",
      {{0, 0, 0, 0}},
      {Undef("result.texcoord[0]", 0x7, "LOG of 0"), Eq("result.texcoord[0]", {0, 0, 0, 1}, 0x8)});
  t.Vp1("vp_scalar_ops", "ARBvp 2.14.5: the vertex forms replicate",
        "RCP result.texcoord[0], e0.x;\nRSQ result.texcoord[1], e0.y;\n"
        "EX2 result.texcoord[2], e0.z;\nPOW result.texcoord[3], e0.w, e0.z;\n",
        {{4, -16, 3, 2}},
        {Rel("result.texcoord[0]", {0.25f, 0.25f, 0.25f, 0.25f}),
         Rel("result.texcoord[1]", {0.25f, 0.25f, 0.25f, 0.25f}),
         Rel("result.texcoord[2]", {8, 8, 8, 8}), Rel("result.texcoord[3]", {8, 8, 8, 8})});
  t.Vp1("vp_swz_xpd_dst", "ARBvp 2.14.5.26-27, 2.14.5.7",
        "SWZ result.texcoord[0], e0, w, -x, 1, -0;\nXPD result.texcoord[1].xyz, e0, e1;\n"
        "DST result.texcoord[2], e0, e1;\n",
        {{1, 2, 3, 4}, {4, 5, 6, 7}},
        {Eq("result.texcoord[0]", {4, -1, 1, -0.0f}),
         Written("result.texcoord[1]", {-3, 6, -3, 0}, 0x7),
         Eq("result.texcoord[2]", {1, 10, 3, 7})});
  // M = translate(1,2,3): eye = (2,3,4,1); P rows (2,0,0,0) (0,3,0,0) (0,0,-1,-2)
  // (0,0,-1,0): clip = (4, 9, -6, -4).
  t.Add("position_invariant", "ARBvp 2.14.4.5.1: clip = P * (M * v)",
        Vp("OPTION ARB_position_invariant;\nMOV result.color, vertex.color;\n"), "",
        [](ExecInputs& in) {
          in.state.modelview = Rows({1, 0, 0, 1}, {0, 1, 0, 2}, {0, 0, 1, 3}, {0, 0, 0, 1});
          in.state.projection = Rows({2, 0, 0, 0}, {0, 3, 0, 0}, {0, 0, -1, -2}, {0, 0, -1, 0});
          in.vectors[0].vertex.position = {1, 1, 1, 1};
        },
        {Rel("result.position", {4, 9, -6, -4}, 1.0e-6f),
         Eq("result.color.front.primary", {1, 1, 1, 1})});
}

// A vertex program that copies one state binding to result.texcoord[0].
std::string StateVp(const std::string& binding) {
  return Vp("PARAM p = " + binding + ";\nMOV result.texcoord[0], p;\n");
}
std::string StateFp(const std::string& binding) {
  return Fp("PARAM p = " + binding + ";\nMOV result.color, p;\n");
}

void StateCases(Table& t) {
  auto state = [&t](std::string name, std::string binding, Setup setup, Vec4 want,
                    Tolerance tol = Tolerance::Exact) {
    Expect e = Eq(kTex0, want);
    if (tol != Tolerance::Exact) {
      e.tolerance = tol;
      e.bound = 1.0e-6f;
    }
    t.Add("state_" + std::move(name), "ARBvp 2.14.3.2 tables X.3.2-X.3.8", StateVp(binding), "",
          std::move(setup), {e});
  };
  auto materials = [](ExecInputs& in) {
    in.state.material[0].ambient = {0.5f, 0.5f, 0.25f, 0.375f};
    in.state.material[0].diffuse = {0.5f, 0.5f, 0.5f, 0.75f};
    in.state.material[0].specular = {0.25f, 0.5f, 1, 0.125f};
    in.state.material[0].emission = {0.25f, 0.125f, 0.5f, 0.0625f};
    in.state.material[0].shininess = 12;
    in.state.material[1].ambient = {1, 0.5f, 0.5f, 0.5f};
    in.state.material[1].diffuse = {0.125f, 0.25f, 0.375f, 0.625f};
    in.state.material[1].emission = {0, 0.5f, 0, 1};
    in.state.material[1].shininess = 7;
    in.state.light_model_ambient = {0.5f, 0.25f, 1, 0.125f};
    in.state.light[2].ambient = {0.5f, 1, 0.25f, 0.125f};
    in.state.light[2].diffuse = {0.5f, 1, 0.25f, 0.125f};
    in.state.light[2].specular = {2, 2, 2, 2};
  };
  state("material_ambient", "state.material.ambient", materials, {0.5f, 0.5f, 0.25f, 0.375f});
  state("material_front_specular", "state.material.front.specular", materials,
        {0.25f, 0.5f, 1, 0.125f});
  state("material_back_diffuse", "state.material.back.diffuse", materials,
        {0.125f, 0.25f, 0.375f, 0.625f});
  state("material_emission", "state.material.emission", materials, {0.25f, 0.125f, 0.5f, 0.0625f});
  state("material_shininess", "state.material.shininess", materials, {12, 0, 0, 1});
  state("material_back_shininess", "state.material.back.shininess", materials, {7, 0, 0, 1});
  state("material_default", "state.material.diffuse", nullptr, {0.8f, 0.8f, 0.8f, 1});
  // Light 0 defaults: white diffuse; light 1 defaults: black diffuse (GL 2.0 table 6.x).
  state("light0_default_diffuse", "state.light[0].diffuse", nullptr, {1, 1, 1, 1});
  state("light1_default_diffuse", "state.light[1].diffuse", nullptr, {0, 0, 0, 1});
  state("light_ambient", "state.light[2].ambient", materials, {0.5f, 1, 0.25f, 0.125f});
  state("light_specular", "state.light[2].specular", materials, {2, 2, 2, 2});
  state("light_position", "state.light[3].position",
        [](ExecInputs& in) {
          in.state.light[3].position = {1, -2, 3, 0.5f};
        },
        {1, -2, 3, 0.5f});
  state("light_attenuation", "state.light[1].attenuation",
        [](ExecInputs& in) {
          in.state.light[1].constant_attenuation = 2;
          in.state.light[1].linear_attenuation = 0.5f;
          in.state.light[1].quadratic_attenuation = 0.25f;
          in.state.light[1].spot_exponent = 16;
        },
        {2, 0.5f, 0.25f, 16});
  state("light_spot_direction_default", "state.light[0].spot.direction", nullptr, {0, 0, -1, -1},
        Tolerance::Absolute);  // cos(180 degrees) = -1
  state(
      "light_spot_direction", "state.light[4].spot.direction",
      [](ExecInputs& in) {
        in.state.light[4].spot_direction = {1, 0, 0};
        in.state.light[4].spot_cutoff = 60;
      },
      {1, 0, 0, 0.5f}, Tolerance::Absolute);
  // A light at its initial position (0,0,1,0) (GL 2.0 table 6.11): P = (0,0,1), so
  // h_inf = ||(0,0,1) + (0,0,1)|| = (0,0,1), w = 1. Light 7: no other case moves it.
  state("light_half_default", "state.light[7].half", nullptr, {0, 0, 1, 1});
  // (1,0,0,0): normalize((1,0,0) + (0,0,1)) = (0.7071, 0, 0.7071).
  state(
      "light_half_infinite", "state.light[0].half",
      [](ExecInputs& in) {
        in.state.light[0].position = {1, 0, 0, 0};
      },
      {0.70710678f, 0, 0.70710678f, 1}, Tolerance::Absolute);
  // Local light (0,3,4,2): P = normalize((0,1.5,2)) = (0,0.6,0.8); + (0,0,1) = (0,0.6,1.8),
  // |.| = sqrt(3.6) -> (0, 0.3162278, 0.9486833).
  state(
      "light_half_local", "state.light[0].half",
      [](ExecInputs& in) {
        in.state.light[0].position = {0, 3, 4, 2};
      },
      {0, 0.31622777f, 0.94868330f, 1}, Tolerance::Absolute);
  state("lightmodel_ambient", "state.lightmodel.ambient", materials, {0.5f, 0.25f, 1, 0.125f});
  // a_cs * a_cm + e_cm = (0.25 + 0.25, 0.125 + 0.125, 0.25 + 0.5), w = diffuse alpha 0.75.
  state("lightmodel_scenecolor", "state.lightmodel.scenecolor", materials,
        {0.5f, 0.25f, 0.75f, 0.75f});
  // Back: (0.5*1 + 0, 0.25*0.5 + 0.5, 1*0.5 + 0), w = back diffuse alpha 0.625.
  state("lightmodel_back_scenecolor", "state.lightmodel.back.scenecolor", materials,
        {0.5f, 0.625f, 0.5f, 0.625f});
  // light 2 diffuse * front diffuse = (0.25, 0.5, 0.125), w = material alpha 0.75.
  state("lightprod_diffuse", "state.lightprod[2].diffuse", materials, {0.25f, 0.5f, 0.125f, 0.75f});
  state("lightprod_back_ambient", "state.lightprod[2].back.ambient", materials,
        {0.5f, 0.5f, 0.125f, 0.5f});
  state("lightprod_specular", "state.lightprod[2].front.specular", materials, {0.5f, 1, 2, 0.125f});
  state("texgen_eye", "state.texgen[1].eye.r",
        [](ExecInputs& in) {
          in.state.texgen[1].eye[2] = {1, 2, 3, 4};
        },
        {1, 2, 3, 4});
  state("texgen_object_default", "state.texgen.object.t", nullptr, {0, 1, 0, 0});
  state("texgen_object", "state.texgen[2].object.q",
        [](ExecInputs& in) {
          in.state.texgen[2].object[3] = {-1, 0.5f, 2, 8};
        },
        {-1, 0.5f, 2, 8});
  state("fog_color", "state.fog.color",
        [](ExecInputs& in) {
          in.state.fog_color = {0.25f, 0.5f, 0.75f, 1};
        },
        {0.25f, 0.5f, 0.75f, 1});
  state("fog_params", "state.fog.params",
        [](ExecInputs& in) {
          in.state.fog_density = 0.5f;
          in.state.fog_start = 1;
          in.state.fog_end = 5;
        },
        {0.5f, 1, 5, 0.25f});
  state("clip_plane", "state.clip[2].plane",
        [](ExecInputs& in) {
          in.state.clip_plane[2] = {1, -2, 3, -4};
        },
        {1, -2, 3, -4});
  state("point_size", "state.point.size",
        [](ExecInputs& in) {
          in.state.point_size = 2;
          in.state.point_size_min = 1;
          in.state.point_size_max = 64;
          in.state.point_fade_threshold = 0.5f;
        },
        {2, 1, 64, 0.5f});
  state("point_attenuation", "state.point.attenuation",
        [](ExecInputs& in) {
          in.state.point_attenuation = {0.5f, 0.25f, 2};
        },
        {0.5f, 0.25f, 2, 1});

  // Matrices: rows, not columns.
  auto numbered = [](ExecInputs& in) {
    in.state.modelview = Rows({1, 2, 3, 4}, {5, 6, 7, 8}, {9, 10, 11, 12}, {13, 14, 15, 16});
  };
  state("matrix_row", "state.matrix.modelview.row[1]", numbered, {5, 6, 7, 8});
  state("matrix_row_indexed", "state.matrix.modelview[0].row[3]", numbered, {13, 14, 15, 16});
  state("matrix_transpose", "state.matrix.modelview.transpose.row[1]", numbered, {2, 6, 10, 14});
  auto invertible = [](ExecInputs& in) {
    in.state.modelview = ScaleTranslate();
    in.state.projection = SwapXY();
    in.state.texture[1] = ScaleTranslate();
    in.state.program[2] = ScaleTranslate();
  };
  state("matrix_inverse", "state.matrix.modelview.inverse.row[2]", invertible,
        {0, 0, 0.125f, -0.375f}, Tolerance::Absolute);
  state("matrix_invtrans", "state.matrix.modelview.invtrans.row[3]", invertible,
        {-0.5f, -0.5f, -0.375f, 1}, Tolerance::Absolute);
  state("matrix_projection", "state.matrix.projection.row[0]", invertible, {0, 1, 0, 0});
  // MVP = P * M: P swaps rows 0 and 1 of M (M * P would swap columns: (0, 2, 0, 1)).
  state("matrix_mvp", "state.matrix.mvp.row[0]", invertible, {0, 4, 0, 2});
  state("matrix_mvp_transpose", "state.matrix.mvp.transpose.row[3]", invertible, {2, 1, 3, 1});
  state("matrix_texture", "state.matrix.texture[1].row[2]", invertible, {0, 0, 8, 3});
  state("matrix_texture_default", "state.matrix.texture[3].row[0]", invertible, {1, 0, 0, 0});
  state("matrix_program", "state.matrix.program[2].inverse.row[1]", invertible,
        {0, 0.25f, 0, -0.5f}, Tolerance::Absolute);
  t.Add("state_matrix_array", "ARBvp 2.14.3.2: a matrix binds rows 0..3 to an array",
        Vp("PARAM m[] = { state.matrix.modelview };\nDP4 result.texcoord[0].x, m[0], "
           "vertex.position;\nDP4 result.texcoord[0].y, m[1], vertex.position;\n"
           "MOV result.texcoord[1], m[3];\n"),
        "",
        [](ExecInputs& in) {
          in.state.modelview = ScaleTranslate();
          in.vectors[0].vertex.position = {1, 1, 1, 1};
        },
        // (M * (1,1,1,1)).xy = (2 + 1, 4 + 2).
        {Written(kTex0, {3, 6, 0, 0}, 0x3), Eq("result.texcoord[1]", {0, 0, 0, 1})});
  t.Add("state_singular_inverse", "ARBvp 2.14.3.2: the inverse of a singular matrix is undefined",
        StateVp("state.matrix.modelview.inverse.row[0]"), "",
        [](ExecInputs& in) { in.state.modelview = glm::mat4(0.0f); },
        {Undef(kTex0, 0xF, "singular")});
  // Fragment-only state.
  t.Add("state_texenv_color", "ARBfp table X.2.4", "", StateFp("state.texenv[1].color"),
        [](ExecInputs& in) {
          in.state.texenv_color[1] = {0.25f, 0.5f, 0.75f, 1};
        },
        {Eq(kColor, {0.25f, 0.5f, 0.75f, 1})});
  t.Add("state_depth_range", "ARBfp table X.2.6: (n, f, f - n, 1)", "",
        StateFp("state.depth.range"),
        [](ExecInputs& in) {
          in.state.depth_near = 0.25f;
          in.state.depth_far = 0.75f;
        },
        {Eq(kColor, {0.25f, 0.75f, 0.5f, 1})});
  t.Add("state_fp_matrix", "ARBfp 3.11.3.2: matrices in fragment programs", "",
        StateFp("state.matrix.mvp.row[1]"),
        [](ExecInputs& in) {
          in.state.modelview = ScaleTranslate();
          in.state.projection = SwapXY();
        },
        {Eq(kColor, {2, 0, 0, 1})});
  t.Add("program_env_local", "ARBvp table X.3.1: unset parameters read 0",
        Vp("PARAM e[] = { program.env[3..4] };\nMOV result.texcoord[0], e[1];\n"
           "MOV result.texcoord[1], program.local[2];\nMOV result.texcoord[2], program.env[9];\n"),
        "",
        [](ExecInputs& in) {
          in.vertex_params.env[4] = {1, 2, 3, 4};
          in.vertex_params.local[2] = {5, 6, 7, 8};
          in.fragment_params.env[9] = {9, 9, 9, 9};  // the other target's: not read
        },
        {Eq(kTex0, {1, 2, 3, 4}), Eq("result.texcoord[1]", {5, 6, 7, 8}),
         Eq("result.texcoord[2]", {0, 0, 0, 0})});
  t.Add(
      "constants", "ARBvp 2.14.3.2: {a} = (a,0,0,1), {a,b} = (a,b,0,1), scalar = (a,a,a,a)",
      Vp("PARAM a = {2};\nPARAM b = {2, 3};\nPARAM c = -1.5;\nMOV result.texcoord[0], a;\n"
         "MOV result.texcoord[1], b;\nMOV result.texcoord[2], c;\nMOV result.texcoord[3], 0.5;\n"),
      "", nullptr,
      {Eq(kTex0, {2, 0, 0, 1}), Eq("result.texcoord[1]", {2, 3, 0, 1}),
       Eq("result.texcoord[2]", {-1.5f, -1.5f, -1.5f, -1.5f}),
       Eq("result.texcoord[3]", {0.5f, 0.5f, 0.5f, 0.5f})});
}

const Vec4 kRed{1, 0, 0, 1};
const Vec4 kGreen{0, 1, 0, 1};
const Vec4 kBlue{0, 0, 1, 1};
const Vec4 kWhite{1, 1, 1, 1};
const Vec4 kGrey{0.5f, 0.5f, 0.5f, 1};

void TextureCases(Table& t) {
  using arbvp::TexFilter;
  using arbvp::TexWrap;
  const std::string tex2d = Fp("TEX result.color, fragment.texcoord[0], texture[0], 2D;\n");
  // Nearest: u = s * 2; (1.25, .25) repeats to (.25, .25); (-.25, .25) to (.75, .25).
  t.Add("tex_2d_nearest_repeat", "GL 2.0 3.8.7-3.8.8", "", tex2d,
        WithTexture(0, Quad2D(TexFilter::Nearest, TexWrap::Repeat),
                    TexCoords({{0.25f, 0.25f, 0, 1},
                               {0.75f, 0.25f, 0, 1},
                               {0.25f, 0.75f, 0, 1},
                               {1.25f, 0.25f, 0, 1},
                               {-0.25f, 0.25f, 0, 1},
                               {1, 1, 0, 1}})),
        {At(0, Eq(kColor, kRed)), At(1, Eq(kColor, kGreen)), At(2, Eq(kColor, kBlue)),
         At(3, Eq(kColor, kRed)), At(4, Eq(kColor, kGreen)),
         // repeat: 1 - floor(1) = 0 -> texel (0, 0)
         At(5, Eq(kColor, kRed))});
  // Linear at the centre averages all four; at (0.25, 0.25) alpha = beta = 0 gives red; at
  // (0, 0) REPEAT wraps i0 = -1 to 1 (alpha = 0.5): the average again, CLAMP_TO_EDGE clamps
  // s to 1/4: red.
  t.Add("tex_2d_linear_repeat", "GL 2.0 3.8.8 equation 3.26", "", tex2d,
        WithTexture(0, Quad2D(TexFilter::Linear, TexWrap::Repeat),
                    TexCoords({{0.5f, 0.5f, 0, 1}, {0.25f, 0.25f, 0, 1}, {0, 0, 0, 1}})),
        {At(0, Eq(kColor, kGrey)), At(1, Eq(kColor, kRed)), At(2, Eq(kColor, kGrey))});
  t.Add(
      "tex_2d_linear_clamp", "GL 2.0 3.8.7 CLAMP_TO_EDGE", "", tex2d,
      WithTexture(0, Quad2D(TexFilter::Linear, TexWrap::ClampToEdge),
                  TexCoords({{0, 0, 0, 1}, {-3, 5, 0, 1}, {0.375f, 0.25f, 0, 1}})),
      // (0.375, .25): u = .75, alpha = .25 -> .75 red + .25 green.
      {At(0, Eq(kColor, kRed)), At(1, Eq(kColor, kBlue)), At(2, Eq(kColor, {0.75f, 0.25f, 0, 1}))});
  // mirror(1.25): floor 1 is odd -> 1 - 0.25 = 0.75 -> green; mirror(-0.25): floor -1 odd ->
  // 1 - 0.75 = 0.25 -> red.
  t.Add("tex_2d_mirrored_repeat", "GL 2.0 3.8.7 MIRRORED_REPEAT", "", tex2d,
        WithTexture(0, Quad2D(TexFilter::Nearest, TexWrap::MirroredRepeat),
                    TexCoords({{1.25f, 0.25f, 0, 1}, {-0.25f, 0.25f, 0, 1}})),
        {At(0, Eq(kColor, kGreen)), At(1, Eq(kColor, kRed))});
  Texture tex1d;
  tex1d.dim = arbvp::TexDim::Tex1D;
  tex1d.width = 4;
  tex1d.texels = {0, 0, 0, 1, 0.25f, 0, 0, 1, 0.5f, 0, 0, 1, 0.75f, 0, 0, 1};
  // u = 0.6 * 4 = 2.4 -> texel 2; t is ignored.
  t.Add("tex_1d", "ARBfp 3.11.6: 1D uses s only", "",
        Fp("TEX result.color, fragment.texcoord[0], texture[1], 1D;\n"),
        WithTexture(1, tex1d, TexCoords({{0.6f, 0.9f, 0.9f, 1}})), {Eq(kColor, {0.5f, 0, 0, 1})});
  Texture tex3d;
  tex3d.dim = arbvp::TexDim::Tex3D;
  tex3d.width = 2;
  tex3d.height = 2;
  tex3d.depth = 2;
  for (int i = 0; i < 8; ++i) {
    tex3d.texels.insert(tex3d.texels.end(), {static_cast<float>(i) * 0.125f, 0, 0, 1});
  }
  // (0.75, 0.25, 0.75) -> texel (1, 0, 1) = index 1 + 0*2 + 1*4 = 5.
  t.Add("tex_3d", "GL 2.0 3.8.8", "",
        Fp("TEX result.color, fragment.texcoord[0], texture[2], 3D;\n"),
        WithTexture(2, tex3d, TexCoords({{0.75f, 0.25f, 0.75f, 1}})),
        {Eq(kColor, {0.625f, 0, 0, 1})});
  // Cube: 2x2 faces; face f texel (i, j) = (f, i, j, 1) / 8.
  Texture cube;
  cube.dim = arbvp::TexDim::Cube;
  cube.width = 2;
  cube.height = 2;
  cube.depth = 6;
  cube.wrap = TexWrap::ClampToEdge;
  for (int f = 0; f < 6; ++f) {
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 2; ++i) {
        cube.texels.insert(cube.texels.end(),
                           {static_cast<float>(f) * 0.125f, static_cast<float>(i) * 0.125f,
                            static_cast<float>(j) * 0.125f, 1});
      }
    }
  }
  // Table 3.20. +X (1,-.5,-.5): sc = -rz = .5, tc = -ry = .5 -> s = t = .75 -> texel (1,1).
  // -X (-1,.5,-.5): sc = rz = -.5, tc = -ry = -.5 -> (0,0). +Y (.5,2,-1): sc = rx = .5,
  // tc = rz = -1 -> s = .625, t = .25 -> (1,0). -Y (.5,-2,-1): tc = -rz = 1 -> (1,1).
  // +Z (-.5,.5,3): sc = rx, tc = -ry -> (0,0). -Z (-.5,-.5,-3): sc = -rx = .5, tc = .5 -> (1,1).
  t.Add("tex_cube_faces", "GL 2.0 3.8.6 table 3.20", "",
        Fp("TEX result.color, fragment.texcoord[0], texture[3], CUBE;\n"),
        WithTexture(3, cube,
                    TexCoords({{1, -0.5f, -0.5f, 1},
                               {-1, 0.5f, -0.5f, 1},
                               {0.5f, 2, -1, 1},
                               {0.5f, -2, -1, 1},
                               {-0.5f, 0.5f, 3, 1},
                               {-0.5f, -0.5f, -3, 1},
                               {1, 1, 0, 1}})),
        {At(0, Eq(kColor, {0, 0.125f, 0.125f, 1})), At(1, Eq(kColor, {0.125f, 0, 0, 1})),
         At(2, Eq(kColor, {0.25f, 0.125f, 0, 1})), At(3, Eq(kColor, {0.375f, 0.125f, 0.125f, 1})),
         At(4, Eq(kColor, {0.5f, 0, 0, 1})), At(5, Eq(kColor, {0.625f, 0.125f, 0.125f, 1})),
         At(6, Undef(kColor, 0xF, "major axis"))});
  Texture rect;
  rect.dim = arbvp::TexDim::Rect;
  rect.width = 3;
  rect.height = 2;
  rect.wrap = TexWrap::ClampToEdge;
  for (int i = 0; i < 6; ++i)
    rect.texels.insert(rect.texels.end(), {static_cast<float>(i), 0, 0, 1});
  // RECT coordinates are texels: (2.5, 1.5) -> (2, 1) = 5; (10, -5) clamps to (2, 0) = 2.
  t.Add("tex_rect", "ARB_texture_rectangle: unnormalised coordinates", "",
        Fp("TEX result.color, fragment.texcoord[0], texture[4], RECT;\n"),
        WithTexture(4, rect, TexCoords({{2.5f, 1.5f, 0, 1}, {10, -5, 0, 1}})),
        {At(0, Eq(kColor, {5, 0, 0, 1})), At(1, Eq(kColor, {2, 0, 0, 1}))});
  t.Add(
      "tex_incomplete", "ARBfp 3.11.6: an incomplete texture samples (0,0,0,1)", "",
      Fp("TEX result.color, fragment.texcoord[0], texture[5], 2D;\n"
         "TEX result.color[1], fragment.texcoord[0], texture[0], 3D;\n")
          .insert(11, "OPTION ARB_draw_buffers;\n"),
      WithTexture(0, Quad2D(TexFilter::Nearest, TexWrap::Repeat), TexCoords({{0.2f, 0.2f, 0, 1}})),
      {Eq(kColor, {0, 0, 0, 1}), Eq("result.color[1]", {0, 0, 0, 1})});
  // TXP: (0.5, 1.5, 0, 2) / 2 = (0.25, 0.75) -> blue; q <= 0 is undefined.
  t.Add("txp", "ARBfp 3.11.6.2", "",
        Fp("TXP result.color, fragment.texcoord[0], texture[0], 2D;\n"),
        WithTexture(0, Quad2D(TexFilter::Nearest, TexWrap::Repeat),
                    TexCoords({{0.5f, 1.5f, 0, 2}, {0.5f, 0.5f, 0, 0}, {0.5f, 0.5f, 0, -1}})),
        {At(0, Eq(kColor, kBlue)), At(1, Undef(kColor, 0xF, "TXP with q <= 0 at 2:1")),
         At(2, Undef(kColor, 0xF, "TXP with q <= 0"))});
  t.Add("txb", "ARBfp 3.11.6.3: one level, the bias changes nothing", "",
        Fp("TXB result.color, fragment.texcoord[0], texture[0], 2D;\n"),
        WithTexture(0, Quad2D(TexFilter::Nearest, TexWrap::Repeat),
                    TexCoords({{0.75f, 0.75f, 0, 5}})),
        {Eq(kColor, kWhite)});
  t.Add("tex_swizzled_coordinate", "TEX loads its coordinate with the swizzle", "",
        Fp("TEX result.color, fragment.texcoord[0].yxzw, texture[0], 2D;\n"),
        WithTexture(0, Quad2D(TexFilter::Nearest, TexWrap::Repeat),
                    TexCoords({{0.25f, 0.75f, 0, 1}})),
        {Eq(kColor, kGreen)});
  // Depth textures without comparison: D as luminance, intensity or alpha (table 3.21).
  t.Add("tex_depth_luminance", "GL 2.0 3.8.5, 3.8.14 (compare NONE: r = Dt)", "", tex2d,
        WithTexture(0, Depth2D(0.25f, false), TexCoords({{0.5f, 0.5f, 0, 1}})),
        {Eq(kColor, {0.25f, 0.25f, 0.25f, 1})});
  t.Add(
      "tex_depth_intensity", "DEPTH_TEXTURE_MODE INTENSITY", "", tex2d,
      WithTexture(0, Depth2D(0.25f, false, arbvp::CompareFunc::Lequal, arbvp::DepthMode::Intensity),
                  TexCoords({{0.5f, 0.5f, 0, 1}})),
      {Eq(kColor, {0.25f, 0.25f, 0.25f, 0.25f})});
  t.Add("tex_depth_alpha", "DEPTH_TEXTURE_MODE ALPHA", "", tex2d,
        WithTexture(0, Depth2D(0.25f, false, arbvp::CompareFunc::Lequal, arbvp::DepthMode::Alpha),
                    TexCoords({{0.5f, 0.5f, 0, 1}})),
        {Eq(kColor, {0, 0, 0, 0.25f})});
  // Without the shadow option a 2D sample ignores the compare mode.
  t.Add("tex_depth_compare_ignored", "ARB_fragment_program_shadow: as if compare were NONE", "",
        tex2d, WithTexture(0, Depth2D(0.25f, true), TexCoords({{0.5f, 0.5f, 0.9f, 1}})),
        {Eq(kColor, {0.25f, 0.25f, 0.25f, 1})});
  const std::string shadow2d =
      Fp("OPTION ARB_fragment_program_shadow;\n"
         "TEX result.color, fragment.texcoord[0], texture[0], SHADOW2D;\n");
  // LEQUAL: R <= Dt passes; R = r clamped to [0, 1].
  t.Add("shadow2d_lequal", "GL 2.0 3.8.14 table 3.27", "", shadow2d,
        WithTexture(0, Depth2D(0.5f, true),
                    TexCoords({{0.5f, 0.5f, 0.4f, 1},
                               {0.5f, 0.5f, 0.6f, 1},
                               {0.5f, 0.5f, 0.5f, 1},
                               {0.5f, 0.5f, 1.5f, 1}})),
        {At(0, Eq(kColor, {1, 1, 1, 1})), At(1, Eq(kColor, {0, 0, 0, 1})),
         At(2, Eq(kColor, {1, 1, 1, 1})), At(3, Eq(kColor, {0, 0, 0, 1}))});
  t.Add(
      "shadow2d_greater_intensity", "table 3.27 GREATER, INTENSITY", "", shadow2d,
      WithTexture(0, Depth2D(0.5f, true, arbvp::CompareFunc::Greater, arbvp::DepthMode::Intensity),
                  TexCoords({{0.5f, 0.5f, 0.75f, 1}, {0.5f, 0.5f, 0.5f, 1}})),
      {At(0, Eq(kColor, {1, 1, 1, 1})), At(1, Eq(kColor, {0, 0, 0, 0}))});
  // R = clamp(-1) = 0 < 0.5: GEQUAL fails, LESS passes.
  t.Add("shadow2d_gequal_clamped", "table 3.27 GEQUAL, R clamped to [0, 1]", "", shadow2d,
        WithTexture(0, Depth2D(0.5f, true, arbvp::CompareFunc::Gequal),
                    TexCoords({{0.5f, 0.5f, -1, 1}})),
        {Eq(kColor, {0, 0, 0, 1})});
  Texture depth1d = Depth2D(0.5f, true, arbvp::CompareFunc::Less);
  depth1d.dim = arbvp::TexDim::Tex1D;
  // SHADOW1D compares r = the z component (not y): 0.25 < 0.5 passes.
  t.Add("shadow1d_uses_r", "ARB_fragment_program_shadow: SHADOW1D uses s and r", "",
        Fp("OPTION ARB_fragment_program_shadow;\n"
           "TEX result.color, fragment.texcoord[0], texture[0], SHADOW1D;\n"),
        WithTexture(0, depth1d, TexCoords({{0.5f, 0.9f, 0.25f, 1}})), {Eq(kColor, {1, 1, 1, 1})});
  // TXP projects r too: (0.5, 0.5, 1.2, 2) -> R = 0.6 > 0.5 fails LEQUAL.
  t.Add("shadow2d_txp", "TXP divides r by q before the comparison", "",
        Fp("OPTION ARB_fragment_program_shadow;\n"
           "TXP result.color, fragment.texcoord[0], texture[0], SHADOW2D;\n"),
        WithTexture(0, Depth2D(0.5f, true), TexCoords({{0.5f, 0.5f, 1.2f, 2}})),
        {Eq(kColor, {0, 0, 0, 1})});
  t.Add("shadow_without_compare", "ARB_fragment_program_shadow: undefined when inconsistent", "",
        shadow2d, WithTexture(0, Depth2D(0.5f, false), TexCoords({{0.5f, 0.5f, 0.4f, 1}})),
        {Undef(kColor, 0xF, "compare mode is NONE")});
  t.Add(
      "shadow_of_color_texture", "ARB_fragment_program_shadow: undefined when inconsistent", "",
      shadow2d,
      WithTexture(0, Quad2D(TexFilter::Nearest, TexWrap::Repeat), TexCoords({{0.5f, 0.5f, 0, 1}})),
      {Undef(kColor, 0xF, "not a depth texture")});
  t.Add("non_shadow_target_with_compare", "ARB_fragment_program_shadow: undefined", "",
        Fp("OPTION ARB_fragment_program_shadow;\n"
           "TEX result.color, fragment.texcoord[0], texture[0], 2D;\n"),
        WithTexture(0, Depth2D(0.5f, true), TexCoords({{0.5f, 0.5f, 0.4f, 1}})),
        {Undef(kColor, 0xF, "depth comparison enabled")});
  Texture pcf = Depth2D(0.5f, true);
  pcf.filter = TexFilter::Linear;
  t.Add("shadow_linear_filter", "GL 2.0 3.8.14: linear comparison is implementation-dependent", "",
        shadow2d, WithTexture(0, pcf, TexCoords({{0.5f, 0.5f, 0.4f, 1}})),
        {Undef(kColor, 0xF, "implementation-dependent")});
}

void FogAndOutputCases(Table& t) {
  auto fog_setup = [](float start, float end, float density, float fogcoord, Vec4 color) {
    return [=](ExecInputs& in) {
      in.state.fog_start = start;
      in.state.fog_end = end;
      in.state.fog_density = density;
      in.state.fog_color = {0, 0, 1, 0.5f};
      in.vectors[0].fragment.fogcoord = fogcoord;
      in.vectors[0].fragment.color = color;
    };
  };
  // f = (4 - 1) / 4 = 0.75: rgb = 0.75 * c + 0.25 * (0, 0, 1); alpha unchanged.
  t.Add("fog_linear", "ARBfp 3.11.4.5.1, GL 2.0 3.10 equation 3.32", "",
        Fp("OPTION ARB_fog_linear;\nMOV result.color, fragment.color;\n"),
        fog_setup(0, 4, 1, 1, {1, 0.5f, 0, 0.25f}),
        {Abs(kColor, {0.75f, 0.375f, 0.25f, 0}, kApprox, 0x7), Eq(kColor, {0, 0, 0, 0.25f}, 0x8)});
  // f = exp(-0.5 * 2) = 0.36787944: rgb = f * 1 + (1 - f) * (0, 0, 1).
  t.Add("fog_exp", "GL 2.0 3.10 equation 3.30", "",
        Fp("OPTION ARB_fog_exp;\nMOV result.color, fragment.color;\n"),
        fog_setup(0, 1, 0.5f, 2, {1, 1, 0, 1}),
        {Abs(kColor, {0.36787944f, 0.36787944f, 0.63212056f, 1}, kApprox)});
  // f = exp(-(0.5 * 4)^2) = exp(-4) = 0.01831564.
  t.Add("fog_exp2", "GL 2.0 3.10 equation 3.31", "",
        Fp("OPTION ARB_fog_exp2;\nMOV result.color, fragment.color;\n"),
        fog_setup(0, 1, 0.5f, 4, {1, 1, 1, 1}),
        {Abs(kColor, {0.01831564f, 0.01831564f, 1, 1}, kApprox)});
  // The colour is clamped before the blend (2 -> 1, -1 -> 0), alpha with it (3 -> 1), and
  // f = 2 clamps to 1.
  t.Add("fog_clamps", "ARBfp 3.11.4.5.1: fog applies to the final clamped colour", "",
        Fp("OPTION ARB_fog_linear;\nMOV result.color, fragment.color;\n"),
        fog_setup(0, 4, 1, -4, {2, -1, 0.5f, 3}), {Abs(kColor, {1, 0, 0.5f, 1}, kApprox)});
  t.Add("fog_clamps_alpha", "ARBfp 3.11.4.5.1: the final clamped colour includes alpha", "",
        Fp("OPTION ARB_fog_exp;\nMOV result.color, fragment.color;\n"),
        fog_setup(0, 4, 0, 1, {0.5f, 0.5f, 0.5f, -2}),
        {Abs(kColor, {0.5f, 0.5f, 0.5f, 0}, kApprox)});
  t.Add("draw_buffers", "ARB_draw_buffers: result.color[n]", "",
        Fp("OPTION ARB_draw_buffers;\nMOV result.color[0], fragment.color;\n"
           "MOV result.color[2], fragment.texcoord[1];\n"),
        [](ExecInputs& in) {
          in.vectors[0].fragment.color = {0.25f, 0.5f, 0.75f, 1};
          in.vectors[0].fragment.texcoord[1] = {4, 3, 2, 1};
        },
        {Eq("result.color[0]", {0.25f, 0.5f, 0.75f, 1}), Eq("result.color[2]", {4, 3, 2, 1}),
         Absent("result.color[1]")});
  // Vector 65 is pixel (1, 1).
  t.Add("fragment_position", "ARBfp table X.1: (x + .5, y + .5, z, 1/w)", "",
        Fp("MOV result.color, fragment.position;\n"),
        [](ExecInputs& in) {
          in.vectors.resize(66);
          in.vectors[65].fragment.depth = 0.25f;
        },
        {At(0, Eq(kColor, {0.5f, 0.5f, 0.5f, 1})), At(65, Eq(kColor, {1.5f, 1.5f, 0.25f, 1}))});
  // ARB_fragment_coord_conventions 3.11.4.5.3 on a framebuffer of two rows: the upper-left
  // origin counts rows from the top (y = 2 - window y), an integer centre drops the half.
  auto two_rows = [](ExecInputs& in) {
    in.vectors.resize(66);
    in.vectors[65].fragment.depth = 0.25f;
  };
  t.Add("fragment_position_upper_left", "ARB_fragment_coord_origin_upper_left", "",
        Fp("OPTION ARB_fragment_coord_origin_upper_left;\nMOV result.color, fragment.position;\n"),
        two_rows,
        {At(0, Eq(kColor, {0.5f, 1.5f, 0.5f, 1})), At(65, Eq(kColor, {1.5f, 0.5f, 0.25f, 1}))});
  t.Add("fragment_position_integer", "ARB_fragment_coord_pixel_center_integer", "",
        Fp("OPTION ARB_fragment_coord_pixel_center_integer;\n"
           "MOV result.color, fragment.position;\n"),
        two_rows, {At(0, Eq(kColor, {0, 0, 0.5f, 1})), At(65, Eq(kColor, {1, 1, 0.25f, 1}))});
  t.Add("fragment_position_upper_left_integer", "both fragment coordinate options", "",
        Fp("OPTION ARB_fragment_coord_pixel_center_integer;\n"
           "OPTION ARB_fragment_coord_origin_upper_left;\nMOV result.color, fragment.position;\n"),
        two_rows, {At(0, Eq(kColor, {0, 1, 0.5f, 1})), At(65, Eq(kColor, {1, 0, 0.25f, 1}))});
  t.Add("ati_draw_buffers", "ATI_draw_buffers: result.color[n] as ARB_draw_buffers", "",
        Fp("OPTION ATI_draw_buffers;\nMOV result.color[0], fragment.color;\n"
           "MOV result.color[3], fragment.texcoord[1];\n"),
        [](ExecInputs& in) {
          in.vectors[0].fragment.color = {0.25f, 0.5f, 0.75f, 1};
          in.vectors[0].fragment.texcoord[1] = {4, 3, 2, 1};
        },
        {Eq("result.color[0]", {0.25f, 0.5f, 0.75f, 1}), Eq("result.color[3]", {4, 3, 2, 1}),
         Absent("result.color[1]")});
  t.Add("fragment_fogcoord", "ARBfp table X.1: (f, 0, 0, 1)", "",
        Fp("MOV result.color, fragment.fogcoord;\n"),
        [](ExecInputs& in) { in.vectors[0].fragment.fogcoord = 3; }, {Eq(kColor, {3, 0, 0, 1})});
}

void PairCases(Table& t) {
  t.Add("pair_varyings", "ARBvp 2.14.3.4 -> ARBfp 3.11.3.1",
        Vp("MOV result.position, vertex.position;\nMOV result.color, vertex.color;\n"
           "MOV result.texcoord[1], vertex.texcoord[0];\n"),
        Fp("OPTION ARB_draw_buffers;\nMOV result.color[0], fragment.color;\n"
           "MOV result.color[1], fragment.texcoord[1];\n"),
        [](ExecInputs& in) {
          in.vectors[0].vertex.color = {0.25f, 0.5f, 0.75f, 1};
          in.vectors[0].vertex.texcoord[0] = {-4, 3, 2, 9};
        },
        {Eq("result.color[0]", {0.25f, 0.5f, 0.75f, 1}), Eq("result.color[1]", {-4, 3, 2, 9})});
  // Vertex colours are clamped to [0, 1] (GL 2.0 2.14.6); texture coordinates are not.
  t.Add("pair_color_clamp", "GL 2.0 2.14.6 colour clamping",
        Vp("MOV result.color, program.env[0];\nMOV result.color.secondary, -program.env[0];\n"),
        Fp("ADD result.color, fragment.color, fragment.color.secondary;\n"),
        VpEnv({{2, -1, 0.5f, 1}}), {Eq(kColor, {1, 1, 0.5f, 1})});
  t.Add("pair_unwritten_varying", "ARBvp 2.14.3.4: unwritten results are undefined",
        Vp("MOV result.color, vertex.color;\n"), Fp("MOV result.color, fragment.texcoord[2];\n"),
        nullptr, {Undef(kColor, 0xF, "result.texcoord[2]")});
  t.Add("pair_fog", "ARB_fog_linear with the vertex program's fog coordinate",
        Vp("MOV result.color, 1;\nMOV result.fogcoord.x, 3;\n"),
        Fp("OPTION ARB_fog_linear;\nMOV result.color, fragment.color;\n"),
        [](ExecInputs& in) {
          in.state.fog_start = 0;
          in.state.fog_end = 4;
          in.state.fog_color = {0, 0, 0, 0};
        },
        // f = (4 - 3) / 4 = 0.25.
        {Abs(kColor, {0.25f, 0.25f, 0.25f, 1}, kApprox)});
  // Vector 1's colour x = -1 is clamped to 0 by the vertex stage: KIL does not fire;
  // vector 2's texture coordinate is not clamped: it does.
  t.Add("pair_kil", "KIL on values from the vertex program",
        Vp("MOV result.color, vertex.color;\nMOV result.texcoord[0], vertex.texcoord[0];\n"),
        Fp("SUB result.color, fragment.color, 0.5;\nKIL fragment.color;\n"
           "KIL fragment.texcoord[0];\n"),
        [](ExecInputs& in) {
          in.vectors.resize(3);
          in.vectors[1].vertex.color = {-1, 1, 1, 1};
          in.vectors[2].vertex.texcoord[0] = {0, -1, 0, 0};
        },
        {At(0, Eq(kColor, {0.5f, 0.5f, 0.5f, 0.5f})), At(1, Eq(kColor, {-0.5f, 0.5f, 0.5f, 0.5f}))},
        {2});
}

// ---- The NV program options ---------------------------------------------------------------
// Mesa has none of them: these cases run on the reference interpreter only.

// An NV program: the option, program.env[0..2] as e0..e2, then the body.
std::string NvBody(const std::string& option, const std::string& body) {
  return "OPTION " + option +
         ";\nPARAM e0 = program.env[0];\nPARAM e1 = program.env[1];\n"
         "PARAM e2 = program.env[2];\n" +
         body;
}
void NvFp(Table& t, std::string name, std::string spec, const std::string& body,
          std::vector<Vec4> env, std::vector<Expect> expects, std::vector<size_t> killed = {}) {
  t.Add(std::move(name), std::move(spec), "", Fp(NvBody("NV_fragment_program2", body)),
        FpEnv(std::move(env)), std::move(expects), std::move(killed));
}
void NvVp(Table& t, std::string name, std::string spec, const std::string& body,
          std::vector<Vec4> env, std::vector<Expect> expects) {
  t.Add(std::move(name), std::move(spec), Vp(NvBody("NV_vertex_program3", body)), "",
        VpEnv(std::move(env)), std::move(expects));
}

// A float with the given bits (the packing instructions' results).
float Bits(uint32_t bits) { return std::bit_cast<float>(bits); }

// R1 = (-2, 0, 2, NaN) of the specs' condition code examples: CC = (LT, EQ, GT, UN).
const Vec4 kCcExample{-2, 0, 2, kNaN};

void NvAluCases(Table& t) {
  const std::string spec = "NV_fragment_program_option 3.11.5";
  // NaN compares false, so only SNE is 1 in w.
  const Vec4 a{1, 2, 3, kNaN};
  const Vec4 b{1, 3, 2, kNaN};
  NvFp(t, "nv_seq", spec + ".37", "SEQ result.color, e0, e1;\n", {a, b},
       {Eq(kColor, {1, 0, 0, 0})});
  NvFp(t, "nv_sgt", spec + ".39", "SGT result.color, e0, e1;\n", {a, b},
       {Eq(kColor, {0, 0, 1, 0})});
  NvFp(t, "nv_sle", spec + ".40", "SLE result.color, e0, e1;\n", {a, b},
       {Eq(kColor, {1, 1, 0, 0})});
  NvFp(t, "nv_sne", spec + ".41", "SNE result.color, e0, e1;\n", {a, b},
       {Eq(kColor, {0, 1, 1, 1})});
  NvFp(t, "nv_sfl_str", spec + ".38, .42",
       "TEMP r;\nSFL r.xy, e0, e1;\nSTR r.zw, e0, e1;\nMOV result.color, r;\n", {a, b},
       {Eq(kColor, {0, 0, 1, 1})});
  // NV_vertex_program2's rules give 0 for SEQ of NaN, its issue on NaN says NaN.
  NvVp(t, "nv_vp_seq_nan", "NV_vertex_program2 2.14.3.28 and its NaN issue",
       "SEQ result.texcoord[0], e0, e1;\n", {a, b},
       {Eq(kTex0, {1, 0, 0, 0}, 0x7), Undef(kTex0, 0x8, "SEQ of NaN")});
  NvVp(t, "nv_ssg", "NV_vertex_program2 2.14.3.37", "SSG result.texcoord[0], e0;\n",
       {{2, -0.0f, -kInf, kNaN}}, {Eq(kTex0, {1, 0, -1, kNaN})});
  // RCC: 1/2; +0 and -0 give +-2^64 (rules 4, 5), 2^70 gives 2^-64 (rule 6).
  NvVp(t, "nv_rcc", "NV_vertex_program2 2.14.3.25",
       "RCC result.texcoord[0].x, e0.x;\nRCC result.texcoord[0].y, e0.y;\n"
       "RCC result.texcoord[0].z, e0.z;\nRCC result.texcoord[0].w, e0.w;\n",
       {{2, 0.0f, -0.0f, 0x1p70f}}, {Rel(kTex0, {0.5f, 0x1p64f, -0x1p64f, 0x1p-64f})});
  NvFp(t, "nv_div", "NV_fragment_program2 3.11.5.48", "DIV result.color, e0, e1.y;\n",
       {{1, 2, -3, 0}, {0, 2, 0, 0}}, {Rel(kColor, {0.5f, 1, -1.5f, 0})});
  // DP2 ignores z and w; DP2A adds tmp2.x: 3 + 8 = 11, + 5.
  NvFp(t, "nv_dp2", "NV_fragment_program2 3.11.5.49", "DP2 result.color, e0, e1;\n",
       {{1, 2, 100, 100}, {3, 4, 100, 100}}, {Eq(kColor, {11, 11, 11, 11})});
  NvFp(t, "nv_dp2a", "NV_fragment_program2 3.11.5.50", "DP2A result.color, e0, e1, e2;\n",
       {{1, 2, 100, 100}, {3, 4, 100, 100}, {5, 7, 7, 7}}, {Eq(kColor, {16, 16, 16, 16})});
  // (3, 0, 4) / 5; w undefined.
  NvFp(t, "nv_nrm", "NV_fragment_program2 3.11.5.51", "NRM result.color, e0;\n", {{3, 0, 4, 7}},
       {Rel(kColor, {0.6f, 0, 0.8f, 0}, kApprox, 0x7), Undef(kColor, 0x8, "NRM w")});
  // axis (0, 0, 2), direction (1, 2, 3): tmp.w = 4, tmp.x = 2 * 6 / 4 = 3, so
  // (3 * 0 - 1, 3 * 0 - 2, 3 * 2 - 3).
  NvFp(t, "nv_rfl", spec + ".36", "RFL result.color.xyz, e0, e1;\n", {{0, 0, 2, 9}, {1, 2, 3, 9}},
       {Rel(kColor, {-1, -2, 3, 0}, kApprox, 0x7)});
  // (1 + 3 * 5 + 4 * 6, 2 + 3 * 7 + 4 * 8) in x, z and y, w.
  NvFp(t, "nv_x2d", spec + ".47", "X2D result.color, e0, e1, e2;\n",
       {{1, 2, 0, 0}, {3, 4, 0, 0}, {5, 6, 7, 8}}, {Eq(kColor, {40, 55, 40, 55})});
  // One point per vector: "zero for point-mode polygons" (NV_fragment_program's issues).
  NvFp(t, "nv_ddx_ddy", spec + ".30-31; NV_fragment_program issue on polygon offset",
       "TEMP r;\nDDX r.xy, fragment.texcoord[0];\nDDY r.zw, e0;\nMOV result.color, r;\n",
       {{1, 2, 3, 4}}, {Eq(kColor, {0, 0, 0, 0})});
  NvFp(t, "nv_ddx_infinite", spec + ".30 and NV_fragment_program 3.11.5.3",
       "DDX result.color, e0;\n", {{1, kInf, 0, 0}},
       {Eq(kColor, {0, 0, 0, 0}, 0xD), Undef(kColor, 0x2, "DDX of an infinite or NaN value")});
  // |x| first, then the negation.
  NvFp(t, "nv_abs_operand", "NV_fragment_program_option 3.11.4.1", "MOV result.color, -|e0|;\n",
       {{-1, 2, -0.0f, -kInf}}, {Eq(kColor, {-1, -2, -0.0f, -kInf})});
  NvFp(t, "nv_ssat", "NV_fragment_program2 3.11.4.3: _SSAT clamps to [-1, 1]",
       "MOV_SSAT result.color, e0;\n", {{-2, -0.5f, 0.5f, 3}}, {Eq(kColor, {-1, -0.5f, 0.5f, 1})});
}

void NvPackCases(Table& t) {
  const std::string spec = "NV_fragment_program_option 3.11.5";
  // fp16 1.0 = 0x3C00, -2.0 = 0xC000: 0xC0003C00; UP2H gives them back.
  NvFp(t, "nv_pk2h", spec + ".32", "PK2H result.color, e0;\n", {{1, -2, 0, 0}},
       {Eq(kColor, {Bits(0xC0003C00u), Bits(0xC0003C00u), Bits(0xC0003C00u), Bits(0xC0003C00u)})});
  NvFp(t, "nv_up2h", spec + ".43", "TEMP p;\nPK2H p, e0;\nUP2H result.color, p.x;\n",
       {{1, -2, 0, 0}}, {Eq(kColor, {1, -2, 1, -2})});
  // 65535 * 1 = 0xFFFF, 65535 * 0.25 = 16383.75 -> 0x4000.
  NvFp(t, "nv_pk2us", spec + ".33", "PK2US result.color, e0;\n", {{1, 0.25f, 0, 0}},
       {Eq(kColor, {Bits(0x4000FFFFu), Bits(0x4000FFFFu), Bits(0x4000FFFFu), Bits(0x4000FFFFu)})});
  NvFp(t, "nv_up2us", spec + ".44", "TEMP p;\nPK2US p, e0;\nUP2US result.color, p.x;\n",
       {{1, 0.25f, 0, 0}}, {Rel(kColor, {1, 16384.0f / 65535.0f, 1, 16384.0f / 65535.0f})});
  // 255 * (1, 0, 0.2, 0.6) = (255, 0, 51, 153): 0x993300FF.
  NvFp(t, "nv_pk4ub", spec + ".35", "PK4UB result.color, e0;\n", {{1, 0, 0.2f, 0.6f}},
       {Eq(kColor, {Bits(0x993300FFu), Bits(0x993300FFu), Bits(0x993300FFu), Bits(0x993300FFu)})});
  NvFp(t, "nv_up4ub", spec + ".46", "TEMP p;\nPK4UB p, e0;\nUP4UB result.color, p.x;\n",
       {{1, 0, 0.2f, 0.6f}}, {Rel(kColor, {1, 0, 0.2f, 0.6f})});
  // 127 * (-1, 0, 1, 0.25) + 128 = (1, 128, 255, 159.75 -> 160): 0xA0FF8001.
  NvFp(t, "nv_pk4b", spec + ".34", "PK4B result.color, e0;\n", {{-1, 0, 1, 0.25f}},
       {Eq(kColor, {Bits(0xA0FF8001u), Bits(0xA0FF8001u), Bits(0xA0FF8001u), Bits(0xA0FF8001u)})});
  NvFp(t, "nv_up4b", spec + ".45", "TEMP p;\nPK4B p, e0;\nUP4B result.color, p.x;\n",
       {{-1, 0, 1, 0.25f}}, {Rel(kColor, {-1, 0, 1, 32.0f / 127.0f})});
  NvFp(t, "nv_pk4ub_nan", spec + ".35: round(NaN) is not defined", "PK4UB result.color, e0;\n",
       {{kNaN, 0, 0, 0}}, {Undef(kColor, 0xF, "PK4UB of NaN")});
}

void NvPrecisionCases(Table& t) {
  const std::string spec = "NV_fragment_program 3.11.4.2";
  // fp16(1/3): 1.0101010101b * 2^-2 = 1365/4096 (the next bit is 0).
  NvFp(t, "nv_half_one_third", spec, "MOVH result.color, e0;\n", {{1.0f / 3.0f, 1, -0.0f, kNaN}},
       {Eq(kColor, {1365.0f / 4096.0f, 1, -0.0f, kNaN})});
  // >= 2^16 is INF; 65519 rounds to 65504, the largest fp16.
  NvFp(t, "nv_half_overflow", spec, "MOVH result.color, e0;\n", {{70000, -1e5f, 65519, 65504}},
       {Eq(kColor, {kInf, -kInf, 65504, 65504})});
  // The operands are converted first: 1365/4096 + 1365/4096.
  NvFp(t, "nv_half_operands", spec + ", VectorLoad", "ADDH result.color, e0, e0;\n",
       {{1.0f / 3.0f, 0, 0, 0}}, {Eq(kColor, {1365.0f / 2048.0f, 0, 0, 0})});
  NvFp(t, "nv_short_temp", "NV_fragment_program_option 3.11.3.2: SHORT is fp16",
       "SHORT TEMP h;\nMOV h, e0;\nMOV result.color, h;\n", {{1.0f / 3.0f, 2, 0, 0}},
       {Eq(kColor, {1365.0f / 4096.0f, 2, 0, 0})});
  // fx12: [-2048/1024, +2047/1024] in steps of 1/1024; NaN becomes 0; 0.3 * 1024 = 307.2.
  NvFp(t, "nv_fixed", spec, "MOVX result.color, e0;\n", {{3, -5, 0.3f, kNaN}},
       {Eq(kColor, {2047.0f / 1024.0f, -2, 307.0f / 1024.0f, 0})});
}

void NvConditionCodeCases(Table& t) {
  const std::string spec = "NV_fragment_program_option 3.11.4.3";
  // The specs' example, step by step.
  NvFp(t, "nv_cc_example", spec + " (example)",
       "TEMP r0;\nMOVC r0, e0;\nMOVC r0.xyz, e0.yzwx;\nMOVC r0 (NE), e0.zywx;\n"
       "MOV result.color, r0;\n",
       {kCcExample}, {Eq(kColor, {0, 0, kNaN, -2})});
  // Each rule on CC = (LT, EQ, GT, UN); UN passes NE only (and TR).
  const struct {
    const char* rule;
    Vec4 want;
  } rules[] = {{"EQ", {0, 1, 0, 0}}, {"NE", {1, 0, 1, 1}}, {"LT", {1, 0, 0, 0}},
               {"GE", {0, 1, 1, 0}}, {"LE", {1, 1, 0, 0}}, {"GT", {0, 0, 1, 0}},
               {"TR", {1, 1, 1, 1}}, {"FL", {0, 0, 0, 0}}};
  for (const auto& r : rules) {
    NvFp(t, std::string("nv_cc_rule_") + r.rule, spec + ": TestCC",
         "TEMP c;\nTEMP r;\nMOVC c, e0;\nMOV r, 0;\nMOV r (" + std::string(r.rule) +
             "), 1;\nMOV result.color, r;\n",
         {kCcExample}, {Eq(kColor, r.want)});
  }
  // The test's swizzle: (LT.wzyx) reads (UN, GT, EQ, LT).
  NvFp(t, "nv_cc_swizzle", spec + ": the swizzled condition code",
       "TEMP c;\nTEMP r;\nMOVC c, e0;\nMOV r, 0;\nMOV r (LT.wzyx), 1;\nMOV result.color, r;\n",
       {kCcExample}, {Eq(kColor, {0, 0, 0, 1})});
  // The condition code starts EQ; a masked-off component keeps its code.
  NvFp(t, "nv_cc_initial_eq", "NV_fragment_program_option 3.11.3.X: initialized to EQ",
       "TEMP c;\nTEMP r;\nMOVC c.x, e0;\nMOV r, 0;\nMOV r (EQ), 1;\nMOV result.color, r;\n",
       {kCcExample}, {Eq(kColor, {0, 1, 1, 1})});
  // Codes from the saturated result: -2 clamps to 0 (EQ).
  NvFp(t, "nv_cc_after_sat", spec + ": the written value sets the code",
       "TEMP c;\nTEMP r;\nMOVC_SAT c, e0;\nMOV r, 0;\nMOV r (EQ), 1;\nMOV result.color, r;\n",
       {kCcExample}, {Eq(kColor, {1, 1, 0, 0})});
  // An undefined value's code makes a masked write undefined.
  NvFp(t, "nv_cc_undefined", spec,
       "TEMP u;\nTEMP r;\nMOVC r.x, u.x;\nMOV r, 1;\nMOV r (GT.x), 2;\nMOV result.color, r;\n", {},
       {Undef(kColor, 0xF, "temporary 'u.x' read before it is written")});
  // KIL <ccTest>.
  NvFp(t, "nv_kil_cc", "NV_fragment_program_option 3.11.6.4",
       "TEMP c;\nMOVC c, e0;\nKIL LT.x;\nMOV result.color, 1;\n", {{-1, 0, 0, 0}}, {}, {0});
  NvFp(t, "nv_kil_cc_not_taken", "NV_fragment_program_option 3.11.6.4",
       "TEMP c;\nMOVC c, e0;\nKIL LT.yzww;\nMOV result.color, 1;\n", {{-1, 0, 0, 0}},
       {Eq(kColor, {1, 1, 1, 1})});
  // NV_vertex_program3's second condition code.
  NvVp(t, "nv_cc1", "NV_vertex_program3 2.14.4.3",
       "TEMP c;\nTEMP r;\nMOVC1 c, e0;\nMOV r, 0;\nMOV r (LT1), 1;\nMOV r (GT), 2;\n"
       "MOV result.texcoord[0], r;\n",
       {kCcExample}, {Eq(kTex0, {1, 0, 0, 0})});
}

void NvFlowCases(Table& t) {
  const std::string fp2 = "NV_fragment_program2 3.11.X";
  const std::string if_else =
      "TEMP c;\nTEMP r;\nMOVC c, e0;\nIF GT.x;\nMOV r, e1;\nELSE;\nMOV r, e2;\nENDIF;\n"
      "MOV result.color, r;\n";
  NvFp(t, "nv_if_true", fp2 + ".7", if_else, {{1, 0, 0, 0}, {1, 2, 3, 4}, {5, 6, 7, 8}},
       {Eq(kColor, {1, 2, 3, 4})});
  NvFp(t, "nv_if_else", fp2 + ".3, .7", if_else, {{-1, 0, 0, 0}, {1, 2, 3, 4}, {5, 6, 7, 8}},
       {Eq(kColor, {5, 6, 7, 8})});
  NvFp(t, "nv_if_no_else", fp2 + ".7",
       "TEMP c;\nTEMP r;\nMOV r, 0;\nMOVC c, e0;\nIF GT.x;\nMOV r, e1;\nENDIF;\n"
       "MOV result.color, r;\n",
       {{-1, 0, 0, 0}, {1, 2, 3, 4}}, {Eq(kColor, {0, 0, 0, 0})});
  // REP count floor(2.7) = 2; a count of 0 skips the block.
  const std::string rep =
      "TEMP r;\nMOV r, 0;\nREP e0;\nADD r, r, 1;\nENDREP;\nMOV result.color, r;\n";
  NvFp(t, "nv_rep", fp2 + ".6, .9", rep, {{2.7f, 0, 0, 0}}, {Eq(kColor, {2, 2, 2, 2})});
  NvFp(t, "nv_rep_zero", fp2 + ".9", rep, {{0, 0, 0, 0}}, {Eq(kColor, {0, 0, 0, 0})});
  NvFp(t, "nv_loop", fp2 + ".5, .8",
       "TEMP r;\nMOV r, 0;\nLOOP e0;\nADD r, r, 1;\nENDLOOP;\nMOV result.color, r;\n",
       {{4, 0, 1, 0}}, {Eq(kColor, {4, 4, 4, 4})});
  // BRK when r.x reaches 3 (SGEC sets GT): 3 iterations of 10.
  NvFp(t, "nv_brk", fp2 + ".1",
       "TEMP r;\nTEMP c;\nMOV r, 0;\nREP e0;\nADD r, r, 1;\nSGEC c.x, r.x, 3;\nBRK (GT.x);\n"
       "ENDREP;\nMOV result.color, r;\n",
       {{10, 0, 0, 0}}, {Eq(kColor, {3, 3, 3, 3})});
  // CAL pushes the return; RET with an empty stack ends the program (sub runs once).
  NvFp(t, "nv_cal_ret", fp2 + ".2, .10",
       "TEMP r;\nMOV r, 0;\nCAL sub;\nMOV result.color, r;\nRET;\nsub:\nADD r, r, e0;\nRET;\n",
       {{1, 2, 3, 4}}, {Eq(kColor, {1, 2, 3, 4})});
  // Execution begins after the label "main".
  NvFp(t, "nv_main_label", "NV_fragment_program2 3.11.4.X: the label main",
       "TEMP r;\nsub:\nMOV r, e1;\nRET;\nmain:\nMOV r, e0;\nCAL sub;\nMOV result.color, r;\n",
       {{1, 2, 3, 4}, {5, 6, 7, 8}}, {Eq(kColor, {5, 6, 7, 8})});
  // Unbounded recursion overflows MAX_PROGRAM_CALL_DEPTH_NV: the results are undefined.
  NvFp(t, "nv_call_overflow", fp2 + ".2", "MOV result.color, e0;\nCAL sub;\nsub:\nCAL sub;\n",
       {{1, 2, 3, 4}}, {Undef(kColor, 0xF, "MAX_PROGRAM_CALL_DEPTH_NV")});
  // RET inside an IF block of a subroutine leaves the block; the caller goes on.
  NvFp(t, "nv_ret_in_if", fp2 + ".7, .10",
       "TEMP r;\nTEMP c;\nMOV r, 0;\nCAL sub;\nADD result.color, r, 1;\nRET;\nsub:\n"
       "MOVC c, e0;\nIF GT.x;\nMOV r, e1;\nRET;\nENDIF;\nMOV r, e2;\nRET;\n",
       {{1, 0, 0, 0}, {1, 2, 3, 4}, {5, 6, 7, 8}}, {Eq(kColor, {2, 3, 4, 5})});
  // A branch on an undefined condition code: every result depends on it.
  NvFp(t, "nv_if_undefined", fp2 + ".7",
       "TEMP u;\nTEMP c;\nTEMP r;\nMOVC c, u;\nMOV r, 1;\nIF GT.x;\nMOV r, 2;\nENDIF;\n"
       "MOV result.color, r;\n",
       {}, {Undef(kColor, 0xF, "temporary 'u.x' read before it is written")});
  // Past MAX_PROGRAM_LOOP_COUNT_NV's minimum (255) the implementation decides.
  NvFp(t, "nv_rep_count_limit", fp2 + " (MAX_PROGRAM_LOOP_COUNT_NV)", rep, {{300, 0, 0, 0}},
       {Undef(kColor, 0xF, "MAX_PROGRAM_LOOP_COUNT_NV")});
  // The specs' branch example: the first BRA is taken (x is LT), the second not.
  NvVp(t, "nv_bra", "NV_vertex_program2_option 2.14.4.X (example)",
       "TEMP c;\nTEMP r;\nMOV r, 0;\nMOVC c, e0;\nBRA label1 (LT.xyzw);\nMOV r, e1;\nlabel1:\n"
       "BRA label2 (LT.wyzw);\nMOV r, e2;\nlabel2:\nMOV result.texcoord[0], r;\n",
       {kCcExample, {1, 1, 1, 1}, {2, 2, 2, 2}}, {Eq(kTex0, {2, 2, 2, 2})});
  // NV_vertex_program3 2.14.3.4: result.texcoord[A0.x + n] writes set A0.x + n: -1 + 1 = 0.
  const std::string relative = "ADDRESS A0;\nARL A0.x, e0.x;\nMOV result.texcoord[A0.x + 1], e1;\n";
  NvVp(t, "nv_relative_result", "NV_vertex_program3 2.14.3.4", relative,
       {{-1, 0, 0, 0}, {1, 2, 3, 4}}, {Eq(kTex0, {1, 2, 3, 4})});
  // Set 7 + 1 = 8 does not exist: the write's effects are undefined.
  NvVp(t, "nv_relative_result_outside", "NV_vertex_program3 2.14.3.4",
       "ADDRESS A0;\nARL A0.x, e0.x;\nMOV result.texcoord[0], e1;\n"
       "MOV result.texcoord[A0.x + 1], e1;\n",
       {{7, 0, 0, 0}, {1, 2, 3, 4}}, {Undef(kTex0, 0xF, "outside the array")});
  // An endless loop ends at MAX_PROGRAM_EXEC_INSTRUCTIONS_NV: undefined results.
  NvVp(t, "nv_exec_limit", "NV_vertex_program2_option 2.14.4.X",
       "MOV result.texcoord[0], e0;\ntop:\nBRA top;\n", {{1, 2, 3, 4}},
       {Undef(kTex0, 0xF, "MAX_PROGRAM_EXEC_INSTRUCTIONS_NV")});
}

void NvAddressCases(Table& t) {
  const std::string array =
      "ADDRESS A0;\nPARAM arr[4] = { {0, 0, 0, 0}, {1, 1, 1, 1}, "
      "{2, 2, 2, 2}, {3, 3, 3, 3} };\n";
  // ARL loads a vector: A0 = floor(0.5, 1.7) = (0, 1); arr[A0.y + 1].
  NvVp(t, "nv_arl_vector", "NV_vertex_program2_option 2.14.5.3",
       array + "ARL A0.xy, e0;\nMOV result.texcoord[0], arr[A0.y+1];\n", {{0.5f, 1.7f, 0, 0}},
       {Eq(kTex0, {2, 2, 2, 2})});
  // round(2.5) is the even 2; round(-0.7) is -1: arr[-1 + 2].
  NvVp(t, "nv_arr", "NV_vertex_program2_option 2.14.5.29",
       array +
           "ARR A0.xy, e0;\nMOV result.texcoord[0], arr[A0.x];\n"
           "MOV result.texcoord[1], arr[A0.y+2];\n",
       {{2.5f, -0.7f, 0, 0}}, {Eq(kTex0, {2, 2, 2, 2}), Eq("result.texcoord[1]", {1, 1, 1, 1})});
  // ARR clamps to 511: past the array, undefined.
  NvVp(t, "nv_arr_clamp", "NV_vertex_program2 2.14.3.5",
       array + "ARR A0.x, e0;\nMOV result.texcoord[0], arr[A0.x-63];\n", {{1000, 0, 0, 0}},
       {Undef(kTex0, 0xF, "A0.x-63 = 448 outside")});
  // ARA: (x + z, y + w) of A0 = (1, 2, 1, 0).
  NvVp(t, "nv_ara", "NV_vertex_program2_option 2.14.5.28",
       array +
           "ARL A0, e0;\nARA A0, A0;\nMOV result.texcoord[0], arr[A0.x];\n"
           "MOV result.texcoord[1], arr[A0.w];\n",
       {{1, 2, 1, 0}}, {Eq(kTex0, {2, 2, 2, 2}), Eq("result.texcoord[1]", {2, 2, 2, 2})});
  // ARLC sets the condition code from the integers: A0 = (1, -2, 0, 2) is (GT, LT, EQ, GT).
  NvVp(t, "nv_arl_cc", "NV_vertex_program2_option 2.14.4.3 (integer results)",
       array +
           "TEMP r;\nARLC A0, e0;\nMOV r, 0;\nMOV r (LT), 1;\nMOV r (EQ), 2;\n"
           "MOV result.texcoord[0], r;\n",
       {{1.5f, -1.5f, 0.25f, 2}}, {Eq(kTex0, {0, 1, 2, 0})});
  NvVp(t, "nv_pusha_popa", "NV_vertex_program3 2.14.5.43-44",
       array +
           "ARL A0.x, e0.x;\nPUSHA A0;\nARL A0.x, e0.y;\nPOPA A0;\n"
           "MOV result.texcoord[0], arr[A0.x];\n",
       {{1, 3, 0, 0}}, {Eq(kTex0, {1, 1, 1, 1})});
  NvVp(t, "nv_popa_empty", "NV_vertex_program3 2.14.5.43: POPA on an empty stack",
       array + "MOV result.texcoord[0], e0;\nPOPA A0;\n", {{1, 3, 0, 0}},
       {Undef(kTex0, 0xF, "POPA on an empty call stack")});
}

void NvTextureCases(Table& t) {
  using arbvp::TexFilter;
  using arbvp::TexWrap;
  const Texture quad = Quad2D(TexFilter::Nearest, TexWrap::Repeat);
  // Vertex texture fetch: (0.25, 0.25) is the red texel, (0.75, 0.25) green; TXP divides by
  // q = 2; TXL's LOD and TXB's bias change nothing on one level.
  t.Add(
      "nv_vertex_texture", "NV_vertex_program3 2.14.5.45-48",
      Vp(NvBody("NV_vertex_program3",
                "TEX result.texcoord[0], e0, texture[0], 2D;\n"
                "TXP result.texcoord[1], e1, texture[0], 2D;\n"
                "TXL result.texcoord[2], e2, texture[0], 2D;\n"
                "TXB result.texcoord[3], e2, texture[0], 2D;\n")),
      "",
      WithTexture(0, quad, VpEnv({{0.25f, 0.25f, 0, 0}, {1.5f, 0.5f, 0, 2}, {0.25f, 0.75f, 0, 3}})),
      {Eq(kTex0, kRed), Eq("result.texcoord[1]", kGreen), Eq("result.texcoord[2]", kBlue),
       Eq("result.texcoord[3]", kBlue)});
  t.Add("nv_txd_txl", "NV_fragment_program_option 3.11.6.5, NV_fragment_program2 3.11.6.6", "",
        Fp(NvBody("NV_fragment_program2",
                  "TEMP r;\nTEMP s;\nTXD r, fragment.texcoord[0], e0, e1, texture[0], 2D;\n"
                  "TXL s, e2, texture[0], 2D;\nADD result.color, r, s;\n")),
        WithTexture(0, quad,
                    [](ExecInputs& in) {
                      in.vectors[0].fragment.texcoord[0] = {0.75f, 0.25f, 0, 1};
                      in.fragment_params.env[2] = {0.25f, 0.75f, 0, 5};
                    }),
        {Eq(kColor, {0, 1, 1, 2})});
}

void NvCases(Table& t) {
  NvAluCases(t);
  NvPackCases(t);
  NvPrecisionCases(t);
  NvConditionCodeCases(t);
  NvFlowCases(t);
  NvAddressCases(t);
  NvTextureCases(t);
}

std::vector<ExecCase> Build() {
  Table t;
  AluCases(t);
  UndefinedCases(t);
  KillCases(t);
  VertexCases(t);
  StateCases(t);
  TextureCases(t);
  FogAndOutputCases(t);
  PairCases(t);
  NvCases(t);
  return std::move(t.cases);
}

}  // namespace

const std::vector<ExecCase>& AllExecCases() {
  static const std::vector<ExecCase> cases = Build();
  return cases;
}

}  // namespace arbiter::exec_cases
