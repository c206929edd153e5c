// The interpreter's tolerance model (arbvp/src/exec/tolerance.h, docs/verify.md): every
// expectation is derived from the model's documented formulas, not read off the code.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>

#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/deviations.h"
#include "arbiter/arbvp/interpret.h"

namespace arbiter::arbvp {
namespace {

// The model's constants (tolerance.h).
constexpr double kRounding = 0x1p-23;  // one ulp of the terms' magnitude
constexpr double kApprox = 0x1p-16;    // RCP, RSQ, EX2, POW relative; LG2, SIN, COS absolute
constexpr double kRough = 0x1p-11;     // EXP.z, LOG.z, LIT.z
constexpr double kTexel = 0x1p-8;      // of a texel, for a lookup
constexpr double kCoordPrecision = 0x1p-16;
constexpr float kFltMin = std::numeric_limits<float>::min();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNan = std::numeric_limits<float>::quiet_NaN();

double Wide(float x) { return static_cast<double>(x); }
// One unit in the last place of a float of magnitude |x|.
double Ulp(float x) {
  float a = std::fabs(x);
  return Wide(std::nextafter(a, kInf)) - Wide(a);
}

using Setup = std::function<void(ExecInputs&)>;

// Runs one program on one input vector prepared by `setup`.
VectorResult RunProgram(const std::string& text, const Setup& setup = {}) {
  compiler::SourceFile source("tolerance", text);
  compiler::DiagnosticSink sink(0);
  CheckResult checked = CheckProgram(source, {}, &sink);
  std::string errors;
  for (const compiler::Diagnostic& d : sink.diagnostics()) errors += d.message + "\n";
  EXPECT_TRUE(checked.ok) << text << errors;
  if (!checked.ok || !checked.program) return {};
  ExecInputs inputs;
  inputs.vectors.resize(1);
  if (setup) setup(inputs);
  std::vector<VectorResult> results = Interpret(*checked.program, inputs, &source);
  EXPECT_EQ(results.size(), 1u);
  return results.empty() ? VectorResult{} : results[0];
}

// The only output register a program wrote.
OutputRegister Only(const VectorResult& r, const std::string& text) {
  EXPECT_EQ(r.outputs.size(), 1u) << text;
  return r.outputs.empty() ? OutputRegister{} : r.outputs[0];
}

// A vertex program: `body` reads `v` (vertex.attrib[1] = `in`) and writes `o`
// (result.texcoord[0]), with a temporary `t`.
OutputRegister Vp(const std::string& body, Vec4 in = {0.0f, 0.0f, 0.0f, 1.0f}) {
  std::string text =
      "!!ARBvp1.0\nTEMP t;\nATTRIB v = vertex.attrib[1];\nOUTPUT o = result.texcoord[0];\n" + body +
      "END\n";
  return Only(
      RunProgram(text, [&](ExecInputs& inputs) { inputs.vectors[0].vertex.generic[1] = in; }),
      text);
}

// A fragment program: `v` is fragment.texcoord[1] = `in`, `o` is result.color.
std::string FpText(const std::string& body, const std::string& options = "") {
  return "!!ARBfp1.0\n" + options +
         "TEMP t;\nATTRIB v = fragment.texcoord[1];\nOUTPUT o = result.color;\n" + body + "END\n";
}

VectorResult FpRun(const std::string& body, Vec4 in = {0.0f, 0.0f, 0.0f, 1.0f},
                   const Setup& setup = {}, const std::string& options = "") {
  return RunProgram(FpText(body, options), [&](ExecInputs& inputs) {
    inputs.vectors[0].fragment.texcoord[1] = in;
    if (setup) setup(inputs);
  });
}

OutputRegister Fp(const std::string& body, Vec4 in = {0.0f, 0.0f, 0.0f, 1.0f},
                  const Setup& setup = {}) {
  return Only(FpRun(body, in, setup), FpText(body));
}

// t.x = 3 * RCP(3): 1 in float, with RCP's approximation allowance as its bound.
constexpr char kOneInexact[] = "RCP t.x, {3}.x;\nMUL t.x, t.x, 3;\n";
// t.x = 3 * RCP(3) - 1: 0 in float, within its bound of 0.
constexpr char kZeroInexact[] = "RCP t.x, {3}.x;\nMUL t.x, t.x, 3;\nSUB t.x, t.x, 1;\n";
// t.x = 3 * RCP(3) - 0.999999: about 1e-6, positive, within its bound of 0.
constexpr char kTinyInexact[] = "RCP t.x, {3}.x;\nMUL t.x, t.x, 3;\nADD t.x, t.x, -0.999999;\n";

// ---- exact operations ------------------------------------------------------------------

TEST(ToleranceExact, ExactOperationsOnExactInputsHaveToleranceZero) {
  struct Case {
    const char* body;
    float value;
  };
  const Case cases[] = {
      {"MOV o, 7;\n", 7.0f},    {"FLR o, 2.5;\n", 2.0f},  {"FRC o, 2.5;\n", 0.5f},
      {"MAX o, 1, 2;\n", 2.0f}, {"MIN o, 1, 2;\n", 1.0f}, {"SGE o, 1, 2;\n", 0.0f},
      {"SGE o, 2, 1;\n", 1.0f}, {"SLT o, 1, 2;\n", 1.0f}, {"ABS o, -4;\n", 4.0f},
  };
  for (const Case& c : cases) {
    OutputRegister o = Vp(c.body);
    for (size_t i = 0; i < 4; ++i) {
      EXPECT_EQ(o.value[i], c.value) << c.body;
      EXPECT_EQ(o.tolerance[i], 0.0f) << c.body << " component " << i;
    }
  }
  OutputRegister mov = Vp("MOV o, v;\n", {1.0f, -2.0f, 0.5f, 3.0f});
  EXPECT_EQ(mov.tolerance, (std::array<float, 4>{0, 0, 0, 0}));
  // CMP is a fragment instruction: the selected exact operand.
  OutputRegister cmp = Fp("CMP o, {-1, 1, 0, -0.5}, 2, 3;\n");
  EXPECT_EQ(cmp.value, (Vec4{2, 3, 3, 2}));
  EXPECT_EQ(cmp.tolerance, (std::array<float, 4>{0, 0, 0, 0}));
}

// Sums and products may be reassociated with their neighbours by the compiler (no `precise`
// in ARB or GLSL 1.10): exact ones keep kRounding of their terms' magnitude.
TEST(ToleranceRounding, ExactArithmeticKeepsTheReassociationAllowance) {
  struct Case {
    const char* body;
    float value;
    double terms;
  };
  const Case cases[] = {
      {"ADD o, 1, 2;\n", 3.0f, 1 + 2 + 3},
      {"SUB o, 1, 3;\n", -2.0f, 1 + 3 + 2},
      {"MUL o, 2, 3;\n", 6.0f, 6},
      {"MAD o, 2, 3, 4;\n", 10.0f, 6 + 4 + 10},
  };
  for (const Case& c : cases) {
    OutputRegister o = Vp(c.body);
    EXPECT_EQ(o.value[0], c.value) << c.body;
    EXPECT_EQ(Wide(o.tolerance[0]), kRounding * c.terms) << c.body;
  }
}

TEST(ToleranceRounding, InexactAddGetsAboutOneUlpOfTheResult) {
  OutputRegister o = Vp("ADD o, 1, 1e-8;\n");
  EXPECT_EQ(o.value[0], 1.0f);
  // The rounded-away 1e-8 plus kRounding of the result's magnitude.
  EXPECT_GE(Wide(o.tolerance[0]), kRounding * 1.0 + 0.99e-8);
  // ... of the terms' magnitude (1 + 1e-8 + 1): a reassociated sum.
  EXPECT_LE(Wide(o.tolerance[0]), 3.0 * Ulp(1.0f));
}

TEST(ToleranceRounding, InexactMultiplyIsBoundedByItsRoundingAndAUlp) {
  OutputRegister o = Vp("MUL o, 0.1, 0.1;\n");
  double exact = Wide(0.1f) * Wide(0.1f);
  double err = std::fabs(exact - Wide(o.value[0]));
  EXPECT_GT(err, 0.0);
  EXPECT_GE(Wide(o.tolerance[0]), err + kRounding * std::fabs(Wide(o.value[0])));
  EXPECT_LE(Wide(o.tolerance[0]), 2.0 * Ulp(o.value[0]));
}

// ---- approximations ----------------------------------------------------------------------

TEST(ToleranceApprox, ReciprocalGetsTheRelativeAllowance) {
  OutputRegister o = Vp("RCP o, {3}.x;\n");
  EXPECT_EQ(o.value[0], 1.0f / 3.0f);
  double third = 1.0 / 3.0;
  EXPECT_GE(Wide(o.tolerance[0]), kApprox * third);
  EXPECT_LT(Wide(o.tolerance[0]) / third, 2e-5);
}

TEST(ToleranceApprox, ReciprocalSquareRootGetsTheRelativeAllowance) {
  OutputRegister o = Vp("RSQ o, {4}.x;\n");  // 0.5 exactly: no rounding
  EXPECT_EQ(o.value[0], 0.5f);
  EXPECT_EQ(Wide(o.tolerance[0]), kApprox * 0.5);
}

TEST(ToleranceApprox, Exp2AndPowGetTheRelativeAllowance) {
  OutputRegister ex2 = Vp("EX2 o, {3}.x;\n");  // 8 exactly
  EXPECT_EQ(ex2.value[0], 8.0f);
  EXPECT_EQ(Wide(ex2.tolerance[0]), kApprox * 8.0);
  OutputRegister half = Vp("EX2 o, {0.5}.x;\n");
  double v = std::sqrt(2.0);
  EXPECT_GE(Wide(half.tolerance[0]), kApprox * v);
  EXPECT_LE(Wide(half.tolerance[0]), kApprox * v + 3.0 * Ulp(half.value[0]));
  OutputRegister pow = Vp("POW o, {2}.x, {3}.x;\n");
  EXPECT_EQ(pow.value[0], 8.0f);
  EXPECT_EQ(Wide(pow.tolerance[0]), kApprox * 8.0);
}

TEST(ToleranceApprox, Log2GetsTheAbsoluteAllowance) {
  // tolerance.h: "kApprox relative (RCP, RSQ, EX2, POW) or absolute (LG2, SIN, COS)";
  // docs/verify.md: "2^-16 absolute for LG2, SIN and COS". LG2 8 = 3 exactly.
  OutputRegister one = Vp("LG2 o, {1}.x;\n");
  EXPECT_EQ(one.value[0], 0.0f);
  EXPECT_EQ(Wide(one.tolerance[0]), kApprox);
  OutputRegister o = Vp("LG2 o, {8}.x;\n");
  EXPECT_EQ(o.value[0], 3.0f);
  EXPECT_EQ(Wide(o.tolerance[0]), kApprox);
}

TEST(ToleranceApprox, SineAndCosineGetTheAbsoluteAllowanceAndTheRangeReduction) {
  OutputRegister sin0 = Fp("SIN o, {0}.x;\n");
  EXPECT_EQ(sin0.value[0], 0.0f);
  EXPECT_EQ(Wide(sin0.tolerance[0]), kApprox);
  OutputRegister cos0 = Fp("COS o, {0}.x;\n");
  EXPECT_EQ(cos0.value[0], 1.0f);
  EXPECT_EQ(Wide(cos0.tolerance[0]), kApprox);
  // |x| * 2^-22 more for the reduction of the angle, and the result's rounding.
  OutputRegister sin1000 = Fp("SIN o, {1000}.x;\n");
  double reduction = 1000.0 * 0x1p-22;
  EXPECT_GE(Wide(sin1000.tolerance[0]), kApprox + reduction);
  EXPECT_LE(Wide(sin1000.tolerance[0]), kApprox + reduction + 3.0 * Ulp(sin1000.value[0]));
  // SCS (within [-PI, PI]) has the same bounds on x and y.
  OutputRegister scs = Fp("SCS o.xy, {0}.x;\n");
  EXPECT_EQ(Wide(scs.tolerance[0]), kApprox);
  EXPECT_EQ(Wide(scs.tolerance[1]), kApprox);
}

TEST(ToleranceApprox, ExpLogAndLitZUseTheRoughAllowance) {
  OutputRegister exp = Vp("EXP o, {3}.x;\n");
  EXPECT_EQ(exp.value, (Vec4{8, 0, 8, 1}));
  EXPECT_EQ(exp.tolerance[0], 0.0f);  // 2^floor(3): exact
  EXPECT_EQ(exp.tolerance[1], 0.0f);
  EXPECT_EQ(Wide(exp.tolerance[2]), kRough * 8.0);
  EXPECT_EQ(exp.tolerance[3], 0.0f);
  OutputRegister log = Vp("LOG o, {8}.x;\n");
  EXPECT_EQ(log.value, (Vec4{3, 1, 3, 1}));
  EXPECT_EQ(log.tolerance[0], 0.0f);
  EXPECT_EQ(log.tolerance[1], 0.0f);
  EXPECT_GE(Wide(log.tolerance[2]), kRough);
  EXPECT_LE(Wide(log.tolerance[2]), kRough * 3.0);
  OutputRegister lit = Vp("LIT o, {1, 2, 0, 3};\n");
  EXPECT_EQ(lit.value, (Vec4{1, 1, 8, 1}));
  EXPECT_EQ(lit.tolerance[1], 0.0f);
  EXPECT_EQ(Wide(lit.tolerance[2]), kRough * 8.0);
}

// ---- reformulated operations -------------------------------------------------------------

TEST(ToleranceRounding, DotProductsOfExactIntegersKeepTheReformulationAllowance) {
  // 1*4 + 2*5 + 3*6 = 32: exact, but another order or a fused multiply-add rounds.
  OutputRegister dp3 = Vp("DP3 o, {1, 2, 3, 0}, {4, 5, 6, 0};\n");
  EXPECT_EQ(dp3.value[0], 32.0f);
  EXPECT_GT(dp3.tolerance[0], 0.0f);
  // At most one rounding of the terms' magnitude (4 + 10 + 18) per addition.
  EXPECT_LE(Wide(dp3.tolerance[0]), 3.0 * kRounding * 32.0);
  OutputRegister dp4 = Vp("DP4 o, {1, 2, 3, 4}, {4, 5, 6, 7};\n");
  EXPECT_EQ(dp4.value[0], 60.0f);
  EXPECT_GT(dp4.tolerance[0], 0.0f);
  EXPECT_LE(Wide(dp4.tolerance[0]), 4.0 * kRounding * 60.0);
  // One product alone (DST.y) is not reformulated.
  OutputRegister dst = Vp("DST o, {1, 2, 3, 4}, {5, 6, 7, 8};\n");
  EXPECT_EQ(dst.value, (Vec4{1, 12, 3, 8}));
  EXPECT_EQ(dst.tolerance, (std::array<float, 4>{0, 0, 0, 0}));
}

TEST(ToleranceRounding, LrpOfExactValuesKeepsTheMixAllowance) {
  // 0.5 * 2 + 0.5 * 4 = 3 exactly; drivers compute 4 + 0.5 * (2 - 4).
  OutputRegister o = Fp("LRP o, 0.5, 2, 4;\n");
  EXPECT_EQ(o.value[0], 3.0f);
  EXPECT_GT(o.tolerance[0], 0.0f);
  // The terms of both forms: 1 + 2 (spec's), 4 + 1 (mix's), and the result.
  EXPECT_LE(Wide(o.tolerance[0]), kRounding * (1.0 + 2.0 + 4.0 + 1.0 + 3.0));
}

// ---- unstable values ----------------------------------------------------------------------

// tolerance.h: the steps (SGE, SLT, FLR, CMP, the floors of EXP.x and LOG.x) are monotone:
// within its bound of the threshold the corners give both outcomes, and the tolerance is
// their distance (plus a rounding allowance), so either outcome agrees and nothing beyond.
TEST(ToleranceSteps, ComparisonWithinItsBoundOfTheThresholdAcceptsBothOutcomes) {
  std::string base = kOneInexact;
  EXPECT_FLOAT_EQ(Vp(base + "SGE o, t.x, 1;\n").tolerance[0], 1.0f);
  EXPECT_FLOAT_EQ(Vp(base + "SLT o, t.x, 1;\n").tolerance[0], 1.0f);
}

TEST(ToleranceSteps, FloorWithinItsBoundOfAnIntegerAcceptsBothIntegers) {
  EXPECT_FLOAT_EQ(Vp(std::string(kOneInexact) + "FLR o, t.x;\n").tolerance[0], 1.0f);
}

// EXP.x = 2^floor(x) and LOG.x = floor(log2|x|) are floors too.
TEST(ToleranceSteps, ExponentFloorsWithinTheirBoundAcceptBothSteps) {
  OutputRegister exp = Vp(std::string(kOneInexact) + "EXP o, t.x;\n");
  EXPECT_FLOAT_EQ(exp.value[0], 2.0f);
  EXPECT_FLOAT_EQ(exp.tolerance[0], 1.0f);  // 2^0 or 2^1
  OutputRegister log = Vp(std::string(kOneInexact) + "LOG o, t.x;\n");
  EXPECT_FLOAT_EQ(log.value[0], 0.0f);
  EXPECT_FLOAT_EQ(log.tolerance[0], 1.0f);  // -1 or 0
}

TEST(ToleranceSteps, CmpWithinItsBoundOfZeroAcceptsBothOperands) {
  EXPECT_FLOAT_EQ(Fp(std::string(kZeroInexact) + "CMP o, t.x, 2, 3;\n").tolerance[0], 1.0f);
}

TEST(ToleranceUnstable, FractionAcrossAnIntegerIsAnyValueInZeroToOne) {
  // docs/verify.md item 1: "FRC within one integer step carries the bound; across an
  // integer it is 1".
  OutputRegister o = Vp(std::string(kOneInexact) + "FRC o, t.x;\n");
  EXPECT_EQ(o.tolerance[0], 1.0f);
}

TEST(ToleranceUnstable, ComparisonsFloorAndCmpFarFromTheThresholdAreStable) {
  std::string third = "RCP t.x, {3}.x;\n";  // 1/3 with a bound of about 5e-6
  EXPECT_EQ(Vp(third + "SGE o, t.x, 0.5;\n").tolerance[0], 0.0f);
  EXPECT_EQ(Vp(third + "SLT o, t.x, 0.5;\n").tolerance[0], 0.0f);
  EXPECT_EQ(Vp(third + "FLR o, t.x;\n").tolerance[0], 0.0f);
  OutputRegister frc = Vp(third + "FRC o, t.x;\n");
  EXPECT_GT(frc.tolerance[0], 0.0f);
  EXPECT_LT(frc.tolerance[0], 1e-4f);
  std::string negative = third + "SUB t.x, t.x, 1;\n";
  OutputRegister cmp = Fp(negative + "CMP o, t.x, 2, 3;\n");
  EXPECT_EQ(cmp.value[0], 2.0f);
  EXPECT_EQ(cmp.tolerance[0], 0.0f);
}

TEST(ToleranceUnstable, RelativeAddressWithinItsBoundOfAnIntegerIsUnstable) {
  std::string decl = "ADDRESS a0;\nPARAM arr[] = { {1, 2, 3, 4}, {5, 6, 7, 8} };\n";
  OutputRegister near = Vp(decl + kOneInexact + "ARL a0.x, t.x;\nMOV o, arr[a0.x];\n");
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(near.tolerance[i], kInf) << i;
  OutputRegister far = Vp(decl + "RCP t.x, {0.75}.x;\nARL a0.x, t.x;\nMOV o, arr[a0.x];\n");
  EXPECT_EQ(far.value, (Vec4{5, 6, 7, 8}));
  EXPECT_EQ(far.tolerance, (std::array<float, 4>{0, 0, 0, 0}));
}

TEST(ToleranceUnstable, PolesOfAnInexactValueAreUnstable) {
  std::string tiny = kTinyInexact;
  // t.x is positive (about 1e-6): only its box reaches the pole or the edge of the domain.
  OutputRegister t = Vp(tiny + "MOV o, t;\n");
  EXPECT_GT(t.value[0], 0.0f);
  EXPECT_GE(t.tolerance[0], t.value[0]);
  for (const char* op : {"RCP", "RSQ", "LG2"}) {
    OutputRegister o = Vp(tiny + op + " o, t.x;\n");
    EXPECT_TRUE(std::isfinite(o.value[0])) << op;
    EXPECT_TRUE(o.undefined[0].empty()) << op;
    EXPECT_EQ(o.tolerance[0], kInf) << op;
  }
  // The same operations of an inexact value far from 0 are comparable.
  for (const char* op : {"RCP", "RSQ", "LG2"}) {
    OutputRegister o = Vp(std::string(kOneInexact) + op + " o, t.x;\n");
    EXPECT_LT(o.tolerance[0], 1e-4f) << op;
  }
}

TEST(ToleranceUnstable, InexactValuesNearFloatOverflowAreUnstable) {
  // 1e38 > 2^125, rounded (1e30 is below half an ulp of 1e38): a reassociating compiler
  // may overflow.
  OutputRegister above = Vp("ADD o, 1e38, 1e30;\n");
  EXPECT_EQ(above.value[0], 1e38f);
  EXPECT_EQ(above.tolerance[0], kInf);
  // Below 2^125 the same rounding is a finite bound.
  OutputRegister below = Vp("ADD o, 1e37, 1e29;\n");
  EXPECT_EQ(below.value[0], 1e37f);
  EXPECT_LT(below.tolerance[0], kInf);
  EXPECT_GE(Wide(below.tolerance[0]), kRounding * 1e37);
  // Exact arithmetic there too: a compiler may reassociate it with its neighbours.
  EXPECT_EQ(Vp("MUL o, 1e38, 1;\n").tolerance[0], kInf);
  // A move is no arithmetic: it stays comparable.
  EXPECT_EQ(Vp("MOV o, 1e38;\n").tolerance[0], 0.0f);
}

TEST(ToleranceUnstable, OverflowOfFiniteTermsIsUnstable) {
  // 3e38 * 2 overflows to inf; a compiler that reassociates (3e38 * 2) * 0.25 as
  // 3e38 * (2 * 0.25) gives 1.5e38 (measured on Mesa, both engines): not comparable.
  OutputRegister product = Vp("MUL o, v.x, 2;\n", {3e38f, 0.0f, 0.0f, 1.0f});
  EXPECT_EQ(product.value[0], kInf);
  EXPECT_EQ(product.tolerance[0], kInf);
  OutputRegister dot = Vp("DP3 o, v, v;\n", {3e38f, 0.0f, 0.0f, 1.0f});
  EXPECT_EQ(dot.value[0], kInf);
  EXPECT_EQ(dot.tolerance[0], kInf);
  // An infinite operand gives an infinity in any order: exact.
  OutputRegister infinite = Vp("MUL o, v.x, 2;\n", {kInf, 0.0f, 0.0f, 1.0f});
  EXPECT_EQ(infinite.value[0], kInf);
  EXPECT_EQ(infinite.tolerance[0], 0.0f);
}

// ---- denormals ---------------------------------------------------------------------------

TEST(ToleranceDenormal, DenormalInputMayBeFlushed) {
  OutputRegister o = Vp("MOV o, v;\n", {1e-40f, -1e-40f, 1.0f, 0.0f});
  EXPECT_EQ(o.tolerance[0], kFltMin);
  EXPECT_EQ(o.tolerance[1], kFltMin);
  EXPECT_EQ(o.tolerance[2], 0.0f);
  EXPECT_EQ(o.tolerance[3], 0.0f);
}

TEST(ToleranceDenormal, DenormalResultMayBeFlushed) {
  OutputRegister o = Vp("MUL o, 1e-20, 1e-20;\n");
  EXPECT_LT(std::fabs(o.value[0]), kFltMin);
  EXPECT_GE(o.tolerance[0], kFltMin);
}

// ---- texture lookups ---------------------------------------------------------------------

// A 4x4 (or 4x1) RGBA texture whose texel (i, j) is (i / 4, j / 16, 1/2, 1 - i / 8).
Texture Ramp(TexDim dim, int height, TexFilter filter, TexWrap wrap) {
  Texture t;
  t.dim = dim;
  t.width = 4;
  t.height = height;
  t.filter = filter;
  t.wrap = wrap;
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < 4; ++i) {
      t.texels.insert(t.texels.end(),
                      {0.25f * static_cast<float>(i), 0.0625f * static_cast<float>(j), 0.5f,
                       1.0f - 0.125f * static_cast<float>(i)});
    }
  }
  return t;
}

Setup WithTexture(Texture t) {
  return [t](ExecInputs& inputs) { inputs.textures[0] = t; };
}

TEST(ToleranceTexture, CoordinateWhosePrecisionExceedsATexelIsUnstable) {
  Texture t = Ramp(TexDim::Tex2D, 4, TexFilter::Nearest, TexWrap::Repeat);
  // |s| * 2^-16 > 1/4 (a texel of 4): the lookup may land in any texel.
  float s = 20000.3f;
  ASSERT_GT(Wide(s) * kCoordPrecision, 0.25);
  OutputRegister far = Fp("TEX o, v, texture[0], 2D;\n", {s, 0.375f, 0, 1}, WithTexture(t));
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(far.tolerance[i], kInf) << i;
  // Inside a texel, far from its edges: the texel, exactly.
  OutputRegister inside = Fp("TEX o, v, texture[0], 2D;\n", {0.3f, 0.375f, 0, 1}, WithTexture(t));
  EXPECT_EQ(inside.value, (Vec4{0.25f, 0.0625f, 0.5f, 0.875f}));
  EXPECT_EQ(inside.tolerance, (std::array<float, 4>{0, 0, 0, 0}));
}

TEST(ToleranceTexture, NearestLookupOnATexelBoundaryToleratesEitherTexel) {
  Texture t = Ramp(TexDim::Tex2D, 4, TexFilter::Nearest, TexWrap::ClampToEdge);
  // s = 0.5: u = 2, the edge between texels 1 and 2 (GL picks 2); t = 0.375: row 1's centre.
  ASSERT_LT(kTexel * 0.25 + 0.5 * kCoordPrecision, 0.125);
  OutputRegister o = Fp("TEX o, v, texture[0], 2D;\n", {0.5f, 0.375f, 0, 1}, WithTexture(t));
  EXPECT_EQ(o.value, (Vec4{0.5f, 0.0625f, 0.5f, 0.75f}));
  // The difference of texels (1, 1) and (2, 1).
  EXPECT_EQ(o.tolerance, (std::array<float, 4>{0.25f, 0.0f, 0.0f, 0.125f}));
}

TEST(ToleranceTexture, RepeatedCoordinateWithinRoundingOfAnIntegerIsUnstable) {
  Texture t = Ramp(TexDim::Tex2D, 4, TexFilter::Nearest, TexWrap::Repeat);
  // 1 + 2^-20: within the lookup's box of 1, where drivers' fractions round to 0 or 1.
  float s = 1.0f + 0x1p-20f;
  ASSERT_LT(Wide(s) - 1.0, kTexel * 0.25);
  OutputRegister near = Fp("TEX o, v, texture[0], 2D;\n", {s, 0.375f, 0, 1}, WithTexture(t));
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(near.tolerance[i], kInf) << i;
  // Inside the period, the same distance from a texel edge is an ordinary edge: the
  // neighbouring texels' difference.
  OutputRegister edge =
      Fp("TEX o, v, texture[0], 2D;\n", {0.5f + 0x1p-20f, 0.375f, 0, 1}, WithTexture(t));
  EXPECT_EQ(edge.tolerance, (std::array<float, 4>{0.25f, 0.0f, 0.0f, 0.125f}));
}

TEST(ToleranceTexture, LinearLookupOfAConstantTextureIsExact) {
  for (int height : {1, 4}) {
    Texture t;
    t.dim = height == 1 ? TexDim::Tex1D : TexDim::Tex2D;
    t.width = 4;
    t.height = height;
    t.filter = TexFilter::Linear;
    t.wrap = TexWrap::Repeat;
    for (int k = 0; k < 4 * height; ++k)
      t.texels.insert(t.texels.end(), {0.5f, 0.25f, 1.0f, 0.125f});
    std::string body = height == 1 ? "TEX o, v, texture[0], 1D;\n" : "TEX o, v, texture[0], 2D;\n";
    OutputRegister o = Fp(body, {0.3f, 0.7f, 0, 1}, WithTexture(t));
    EXPECT_EQ(o.value, (Vec4{0.5f, 0.25f, 1.0f, 0.125f})) << height;
    EXPECT_EQ(o.tolerance, (std::array<float, 4>{0, 0, 0, 0})) << height;
  }
}

// ---- KIL -----------------------------------------------------------------------------------

TEST(ToleranceKill, KillWithinRoundingOfZeroIsUnstable) {
  VectorResult r = FpRun(std::string(kZeroInexact) + "KIL t.x;\nMOV o, 1;\n");
  EXPECT_TRUE(r.kill_unstable);
  EXPECT_FALSE(r.killed);  // 0 is not < 0
  ASSERT_EQ(r.outputs.size(), 1u);
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(r.outputs[0].tolerance[i], kInf) << i;
}

TEST(ToleranceKill, KillFarFromZeroIsStable) {
  VectorResult killed = FpRun("RCP t.x, {3}.x;\nSUB t.x, t.x, 1;\nKIL t.x;\nMOV o, 1;\n");
  EXPECT_TRUE(killed.killed);
  EXPECT_FALSE(killed.kill_unstable);
  VectorResult kept = FpRun("RCP t.x, {3}.x;\nKIL t.x;\nMOV o, 1;\n");
  EXPECT_FALSE(kept.killed);
  EXPECT_FALSE(kept.kill_unstable);
  ASSERT_EQ(kept.outputs.size(), 1u);
  EXPECT_EQ(kept.outputs[0].tolerance, (std::array<float, 4>{0, 0, 0, 0}));
}

// ---- deviations --------------------------------------------------------------------------

TEST(ToleranceDeviation, MaxOfANumberAndNanIsTheNanClamp) {
  // MAX: (tmp0 > tmp1) ? tmp0 : tmp1. 5 > NaN is false: NaN, where Mesa's maxNum gives 5.
  OutputRegister nan_second = Vp("MAX o, v.x, v.y;\n", {5.0f, kNan, 0.0f, 1.0f});
  EXPECT_TRUE(std::isnan(nan_second.value[0]));
  EXPECT_TRUE(nan_second.deviations[0] & kDevNanClamp);
  // NaN > 5 is false: 5, as Mesa.
  OutputRegister nan_first = Vp("MAX o, v.y, v.x;\n", {5.0f, kNan, 0.0f, 1.0f});
  EXPECT_EQ(nan_first.value[0], 5.0f);
  EXPECT_FALSE(nan_first.deviations[0] & kDevNanClamp);
  // MIN: (tmp0 > tmp1) ? tmp1 : tmp0. NaN > 5 is false: NaN; 5 > NaN is false: 5.
  OutputRegister min_nan = Vp("MIN o, v.y, v.x;\n", {5.0f, kNan, 0.0f, 1.0f});
  EXPECT_TRUE(std::isnan(min_nan.value[0]));
  EXPECT_TRUE(min_nan.deviations[0] & kDevNanClamp);
  OutputRegister min_five = Vp("MIN o, v.x, v.y;\n", {5.0f, kNan, 0.0f, 1.0f});
  EXPECT_EQ(min_five.value[0], 5.0f);
  EXPECT_FALSE(min_five.deviations[0] & kDevNanClamp);
}

TEST(ToleranceDeviation, SaturateOfNanIsTheNanClamp) {
  OutputRegister o = Fp("MOV_SAT o, v;\n", {kNan, 0.5f, 2.0f, -1.0f});
  EXPECT_TRUE(std::isnan(o.value[0]));
  EXPECT_TRUE(o.deviations[0] & kDevNanClamp);
  EXPECT_EQ(o.value[1], 0.5f);
  EXPECT_EQ(o.value[2], 1.0f);
  EXPECT_EQ(o.value[3], 0.0f);
  for (size_t i = 1; i < 4; ++i) {
    EXPECT_EQ(o.deviations[i], 0u) << i;
    EXPECT_EQ(o.tolerance[i], 0.0f) << i;
  }
}

TEST(ToleranceDeviation, LrpWithAnInfiniteOperand) {
  OutputRegister inf = Fp("LRP o, 0.5, v.x, 1;\n", {kInf, 0.0f, 0.0f, 1.0f});
  EXPECT_EQ(inf.value[0], kInf);
  EXPECT_TRUE(inf.deviations[0] & kDevLrpInfinite);
  OutputRegister finite = Fp("LRP o, 0.5, v.x, 1;\n", {3.0f, 0.0f, 0.0f, 1.0f});
  EXPECT_EQ(finite.value[0], 2.0f);
  EXPECT_EQ(finite.deviations[0], 0u);
}

TEST(ToleranceDeviation, ComparisonOfNanIsFoldedOnTheGlslPathOnly) {
  // SGE: NaN >= 1 is false (0) by the pseudo-code; Mesa's GLSL compiler may fold it with
  // another comparison of the same operand (a >= max(b, c)) and lose the NaN.
  OutputRegister sge = Fp("SGE o, v, 1;\n", {kNan, 2.0f, 0.0f, 1.0f});
  EXPECT_EQ(sge.value, (Vec4{0, 1, 0, 1}));
  EXPECT_TRUE(sge.deviations[0] & kDevNanCompareFolded);
  for (size_t i = 1; i < 4; ++i) EXPECT_FALSE(sge.deviations[i] & kDevNanCompareFolded) << i;
  OutputRegister slt = Fp("SLT o, 1, v;\n", {kNan, 2.0f, 0.0f, 1.0f});
  EXPECT_EQ(slt.value, (Vec4{0, 1, 0, 0}));
  EXPECT_TRUE(slt.deviations[0] & kDevNanCompareFolded);
  EXPECT_FALSE(slt.deviations[1] & kDevNanCompareFolded);
  EXPECT_TRUE(ApplicableDeviations("mesa-glsl", "softpipe") & kDevNanCompareFolded);
  EXPECT_TRUE(ApplicableDeviations("mesa-glsl", "llvmpipe") & kDevNanCompareFolded);
  EXPECT_FALSE(ApplicableDeviations("mesa-arb", "softpipe") & kDevNanCompareFolded);
}

TEST(ToleranceDeviation, NanMadeOfInfinities) {
  // t = -inf * 3; MAD t * -inf + t: inf + -inf = NaN by IEEE; Mesa factors it as
  // t * (-inf + 1) = inf (`arbiter exec --engine all`, both engines and drivers), so the NaN
  // depends on nan-from-infinities.
  OutputRegister mad = Vp("MUL t, v.x, v.y;\nMAD o, t, v.x, t;\n", {-kInf, 3.0f, 0.0f, 1.0f});
  EXPECT_TRUE(std::isnan(mad.value[0]));
  EXPECT_TRUE(mad.deviations[0] & kDevNanFromInfinities);
  // A NaN operand's NaN is not made of infinities; an infinite result is not a NaN.
  OutputRegister nan = Vp("ADD o, v.x, v.y;\n", {kNan, kInf, 0.0f, 1.0f});
  EXPECT_FALSE(nan.deviations[0] & kDevNanFromInfinities);
  OutputRegister sum = Vp("ADD o, v.x, v.x;\n", {kInf, 0.0f, 0.0f, 1.0f});
  EXPECT_FALSE(sum.deviations[0] & kDevNanFromInfinities);
  EXPECT_TRUE(ApplicableDeviations("mesa-arb", "softpipe") & kDevNanFromInfinities);
  EXPECT_TRUE(ApplicableDeviations("mesa-glsl", "softpipe") & kDevNanFromInfinities);
}

TEST(ToleranceDeviation, LitZeroPowZeroOnZOnly) {
  OutputRegister o = Vp("LIT o, v;\n", {1.0f, 0.0f, 0.0f, 0.0f});
  EXPECT_EQ(o.value, (Vec4{1, 1, 1, 1}));
  EXPECT_TRUE(o.deviations[2] & kDevLitZeroPowZero);
  EXPECT_EQ(o.deviations[0], 0u);
  EXPECT_EQ(o.deviations[1], 0u);
  EXPECT_EQ(o.deviations[3], 0u);
  // x = 0 decides z = 0 whatever the power.
  OutputRegister x0 = Vp("LIT o, v;\n", {0.0f, 0.0f, 0.0f, 0.0f});
  EXPECT_EQ(x0.value[2], 0.0f);
  EXPECT_FALSE(x0.deviations[2] & kDevLitZeroPowZero);
  // y > 0: an ordinary power.
  OutputRegister y = Vp("LIT o, v;\n", {1.0f, 2.0f, 0.0f, 0.0f});
  EXPECT_EQ(y.value[2], 1.0f);
  EXPECT_FALSE(y.deviations[2] & kDevLitZeroPowZero);
}

TEST(ToleranceDeviation, FogWithDrawBuffers) {
  auto fog = [](ExecInputs& inputs) {
    inputs.vectors[0].fragment.fogcoord = 0.25f;
    inputs.state.fog_start = 0.0f;
    inputs.state.fog_end = 1.0f;
  };
  VectorResult with = FpRun("MOV o, v;\n", {0.5f, 0.5f, 0.5f, 0.5f}, fog,
                            "OPTION ARB_fog_linear;\nOPTION ARB_draw_buffers;\n");
  ASSERT_EQ(with.outputs.size(), 1u);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_TRUE(with.outputs[0].deviations[i] & kDevFogWithDrawBuffers) << i;
  }
  VectorResult without =
      FpRun("MOV o, v;\n", {0.5f, 0.5f, 0.5f, 0.5f}, fog, "OPTION ARB_fog_linear;\n");
  ASSERT_EQ(without.outputs.size(), 1u);
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(without.outputs[0].deviations[i], 0u) << i;
  VectorResult unfogged =
      FpRun("MOV o, v;\n", {0.5f, 0.5f, 0.5f, 0.5f}, fog, "OPTION ARB_draw_buffers;\n");
  ASSERT_EQ(unfogged.outputs.size(), 1u);
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(unfogged.outputs[0].deviations[i], 0u) << i;
}

TEST(ToleranceDeviation, ValuesComputedFromNonFiniteInputsAreLlvmpipes) {
  OutputRegister inf = Vp("ADD o, v.x, 1;\n", {kInf, 0.0f, 0.0f, 1.0f});
  EXPECT_EQ(inf.value[0], kInf);
  EXPECT_TRUE(inf.deviations[0] & kDevNonFiniteLlvmpipe);
  // A finite result computed from an infinity depends on it too.
  OutputRegister sge = Vp("SGE o, v.x, 1;\n", {kInf, 0.0f, 0.0f, 1.0f});
  EXPECT_EQ(sge.value[0], 1.0f);
  EXPECT_TRUE(sge.deviations[0] & kDevNonFiniteLlvmpipe);
  OutputRegister nan = Vp("MUL o, v.y, 2;\n", {0.0f, kNan, 0.0f, 1.0f});
  EXPECT_TRUE(nan.deviations[0] & kDevNonFiniteLlvmpipe);
  // A non-finite result of finite operands.
  OutputRegister overflow = Vp("MUL o, 1e30, 1e30;\n");
  EXPECT_EQ(overflow.value[0], kInf);
  EXPECT_TRUE(overflow.deviations[0] & kDevNonFiniteLlvmpipe);
  OutputRegister finite = Vp("ADD o, v.x, 1;\n", {1.0f, 0.0f, 0.0f, 1.0f});
  EXPECT_EQ(finite.deviations[0], 0u);
}

TEST(ToleranceDeviation, ApplicableDeviationsByEngineAndDriver) {
  uint32_t arb_softpipe = ApplicableDeviations("mesa-arb", "softpipe");
  EXPECT_TRUE(arb_softpipe & kDevNanClamp);
  EXPECT_TRUE(arb_softpipe & kDevLrpInfinite);
  EXPECT_TRUE(arb_softpipe & kDevFogWithDrawBuffers);
  EXPECT_TRUE(arb_softpipe & kDevMirrorCentreSoftpipe);
  EXPECT_FALSE(arb_softpipe & kDevLitZeroPowZero);
  EXPECT_FALSE(arb_softpipe & kDevNonFiniteLlvmpipe);
  EXPECT_FALSE(arb_softpipe & kDevCubeEdgeLlvmpipe);

  uint32_t glsl_llvmpipe = ApplicableDeviations("mesa-glsl", "llvmpipe");
  EXPECT_TRUE(glsl_llvmpipe & kDevNanClamp);
  EXPECT_TRUE(glsl_llvmpipe & kDevLrpInfinite);
  EXPECT_TRUE(glsl_llvmpipe & kDevNonFiniteLlvmpipe);
  EXPECT_TRUE(glsl_llvmpipe & kDevCubeEdgeLlvmpipe);
  EXPECT_FALSE(glsl_llvmpipe & kDevLitZeroPowZero);
  EXPECT_FALSE(glsl_llvmpipe & kDevFogWithDrawBuffers);
  EXPECT_FALSE(glsl_llvmpipe & kDevMirrorCentreSoftpipe);

  uint32_t arb_llvmpipe = ApplicableDeviations("mesa-arb", "llvmpipe");
  EXPECT_TRUE(arb_llvmpipe & kDevLitZeroPowZero);
  EXPECT_EQ(ApplicableDeviations("ref", "softpipe"), 0u);
  // Every bit has one entry with a name.
  for (const DeviationInfo& d : KnownDeviations()) EXPECT_FALSE(d.name.empty());
}

// ---- fog, state and position invariance --------------------------------------------------

TEST(ToleranceFog, AlphaIsClampedAndColourBlended) {
  auto fog = [](ExecInputs& inputs) {
    inputs.vectors[0].fragment.fogcoord = 0.25f;  // linear: f = (1 - 0.25) / (1 - 0) = 0.75
    inputs.state.fog_start = 0.0f;
    inputs.state.fog_end = 1.0f;
    inputs.state.fog_color = {0.0f, 1.0f, 0.5f, 0.25f};
  };
  VectorResult r = FpRun("MOV o, v;\n", {0.5f, 2.0f, -1.0f, 1.5f}, fog, "OPTION ARB_fog_linear;\n");
  ASSERT_EQ(r.outputs.size(), 1u);
  const OutputRegister& o = r.outputs[0];
  // f * clamp(C) + (1 - f) * Cf for RGB; alpha clamped, not blended.
  EXPECT_EQ(o.value, (Vec4{0.375f, 1.0f, 0.125f, 1.0f}));
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_GT(o.tolerance[i], 0.0f) << i;  // the blend is reformulated (cf + f * (c - cf))
    EXPECT_LE(o.tolerance[i], 1e-6f) << i;
  }
  EXPECT_EQ(o.tolerance[3], 0.0f);
  // Alpha within [0, 1] passes unchanged.
  VectorResult in_range =
      FpRun("MOV o, v;\n", {0.5f, 0.5f, 0.5f, 0.625f}, fog, "OPTION ARB_fog_linear;\n");
  ASSERT_EQ(in_range.outputs.size(), 1u);
  EXPECT_EQ(in_range.outputs[0].value[3], 0.625f);
  // Without a fog option nothing is clamped.
  OutputRegister plain = Fp("MOV o, v;\n", {0.5f, 2.0f, -1.0f, 1.5f}, fog);
  EXPECT_EQ(plain.value, (Vec4{0.5f, 2.0f, -1.0f, 1.5f}));
}

TEST(ToleranceState, DerivedStateCarriesTheApproximation) {
  // The mvp is a product the driver computes: kApprox of its largest element.
  OutputRegister mvp = Vp("PARAM m = state.matrix.mvp.row[0];\nMOV o, m;\n");
  EXPECT_EQ(mvp.value, (Vec4{1, 0, 0, 0}));
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(Wide(mvp.tolerance[i]), kApprox) << i;
  // The modelview itself is stored, not derived.
  OutputRegister mv = Vp("PARAM m = state.matrix.modelview.row[0];\nMOV o, m;\n");
  EXPECT_EQ(mv.tolerance, (std::array<float, 4>{0, 0, 0, 0}));
}

TEST(TolerancePosition, InvariantPositionAllowsAnyOrderOfTheTransforms) {
  std::string text = "!!ARBvp1.0\nOPTION ARB_position_invariant;\nMOV result.color, 1;\nEND\n";
  VectorResult r = RunProgram(text, [](ExecInputs& inputs) {
    inputs.vectors[0].vertex.position = {1.0f, 2.0f, -4.0f, 1.0f};
  });
  const OutputRegister* pos = nullptr;
  for (const OutputRegister& o : r.outputs) {
    if (o.binding.result == ResultReg::Position) pos = &o;
  }
  ASSERT_NE(pos, nullptr);
  EXPECT_EQ(pos->value, (Vec4{1, 2, -4, 1}));
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_GT(pos->tolerance[i], 0.0f) << i;
    EXPECT_LE(Wide(pos->tolerance[i]), 8.0 * kRounding * std::fabs(Wide(pos->value[i])) * 2.0) << i;
  }
}

}  // namespace
}  // namespace arbiter::arbvp
