// runtime::CompareWithReference: an engine's results against the interpreter's under the
// tolerance model (docs/verify.md), on results built by hand (no GL context).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "arbiter/arbvp/deviations.h"
#include "arbiter/runtime/verify.h"

namespace arbiter::runtime {
namespace {

using arbvp::OutputRegister;
using arbvp::Vec4;
using arbvp::VectorResult;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kFltMax = std::numeric_limits<float>::max();

OutputRegister Reg(const std::string& name, Vec4 value, uint8_t written = 0xF) {
  OutputRegister r;
  r.binding.kind = arbvp::BindingKind::Result;
  r.name = name;
  r.value = value;
  r.written = written;
  return r;
}

// One vector with one register.
std::vector<VectorResult> One(const OutputRegister& reg) {
  VectorResult v;
  v.outputs.push_back(reg);
  return {v};
}

// Compares `engine` with `ref` as mesa-arb on softpipe-like bits `applicable`.
Verdict Compare(const std::vector<VectorResult>& ref, const std::vector<VectorResult>& engine,
                uint32_t applicable = 0, const std::string& name = kEngineMesaArb) {
  Verdict verdict;
  CompareWithReference(ref, engine, name, applicable, "edge", &verdict);
  return verdict;
}

// A reference and an engine differing only in x of result.color.
struct XCase {
  float ref;
  float got;
  float tolerance;
};
Verdict CompareX(const XCase& c, uint32_t ref_deviations = 0, uint32_t applicable = 0) {
  OutputRegister ref = Reg("result.color", {c.ref, 1, 2, 3});
  ref.tolerance[0] = c.tolerance;
  ref.deviations[0] = ref_deviations;
  OutputRegister got = Reg("result.color", {c.got, 1, 2, 3});
  return Compare(One(ref), One(got), applicable);
}

TEST(VerifyCompare, EqualValuesAgree) {
  Verdict v = CompareX({0.5f, 0.5f, 0.0f});
  EXPECT_TRUE(v.disagreements.empty());
  EXPECT_EQ(v.compared, 4u);
  EXPECT_TRUE(v.deviations.empty());
}

TEST(VerifyCompare, DifferenceWithinToleranceAgrees) {
  EXPECT_TRUE(CompareX({1.0f, 1.001f, 0.002f}).disagreements.empty());
  EXPECT_TRUE(CompareX({1.0f, 0.999f, 0.002f}).disagreements.empty());
  // Exactly at the bound.
  EXPECT_TRUE(CompareX({1.0f, 1.5f, 0.5f}).disagreements.empty());
}

TEST(VerifyCompare, DifferenceBeyondToleranceDisagreesWithBothValues) {
  Verdict v = CompareX({1.0f, 1.25f, 0.125f});
  EXPECT_EQ(v.compared, 4u);
  ASSERT_EQ(v.disagreements.size(), 1u);
  const Disagreement& d = v.disagreements[0];
  EXPECT_EQ(d.batch, "edge");
  EXPECT_EQ(d.vector, 0u);
  EXPECT_EQ(d.reg, "result.color");
  EXPECT_EQ(d.component, 0);
  EXPECT_EQ(d.what, "");
  EXPECT_EQ(d.tolerance, 0.125f);
  EXPECT_EQ(d.engines, (std::vector<std::string>{kEngineMesaArb}));
  ASSERT_EQ(d.values.count(kEngineRef), 1u);
  ASSERT_EQ(d.values.count(kEngineMesaArb), 1u);
  EXPECT_EQ(d.values.at(kEngineRef), 1.0f);
  EXPECT_EQ(d.values.at(kEngineMesaArb), 1.25f);
  // An exact component and the next float.
  EXPECT_EQ(CompareX({1.0f, std::nextafter(1.0f, 2.0f), 0.0f}).disagreements.size(), 1u);
}

TEST(VerifyCompare, SignedZerosAgree) {
  EXPECT_TRUE(CompareX({0.0f, -0.0f, 0.0f}).disagreements.empty());
  EXPECT_TRUE(CompareX({-0.0f, 0.0f, 0.0f}).disagreements.empty());
}

TEST(VerifyCompare, NanAgreesWithNanOnly) {
  EXPECT_TRUE(CompareX({kNan, kNan, 0.0f}).disagreements.empty());
  EXPECT_EQ(CompareX({kNan, 1.0f, 0.0f}).disagreements.size(), 1u);
  EXPECT_EQ(CompareX({1.0f, kNan, 0.5f}).disagreements.size(), 1u);
  // A tolerance does not make a number match NaN.
  EXPECT_EQ(CompareX({kNan, 0.0f, 1e30f}).disagreements.size(), 1u);
}

TEST(VerifyCompare, InfinityAgreesWithTheSameInfinityOnly) {
  EXPECT_TRUE(CompareX({kInf, kInf, 0.0f}).disagreements.empty());
  EXPECT_TRUE(CompareX({-kInf, -kInf, 0.0f}).disagreements.empty());
  EXPECT_EQ(CompareX({kInf, -kInf, 0.0f}).disagreements.size(), 1u);
  EXPECT_EQ(CompareX({kInf, kFltMax, 0.0f}).disagreements.size(), 1u);
  EXPECT_EQ(CompareX({kFltMax, kInf, 0.0f}).disagreements.size(), 1u);
  // Not even within a large finite tolerance.
  EXPECT_EQ(CompareX({kFltMax, kInf, 1e38f}).disagreements.size(), 1u);
}

TEST(VerifyCompare, UndefinedAndUnstableComponentsAreNotCompared) {
  OutputRegister ref = Reg("result.color", {1, 2, 3, 4});
  ref.undefined[1] = "XPD w";
  ref.tolerance[2] = kInf;
  OutputRegister got = Reg("result.color", {1, 99, 99, 4});
  Verdict v = Compare(One(ref), One(got));
  EXPECT_TRUE(v.disagreements.empty());
  EXPECT_EQ(v.compared, 2u);
  EXPECT_TRUE(v.deviations.empty());
}

TEST(VerifyCompare, ApplicableDeviationSkipsAndCountsTheComponentByName) {
  Verdict v = CompareX({kNan, 5.0f, 0.0f}, arbvp::kDevNanClamp, arbvp::kDevNanClamp);
  EXPECT_TRUE(v.disagreements.empty());
  EXPECT_EQ(v.compared, 3u);
  ASSERT_EQ(v.deviations.count("nan-clamp"), 1u);
  EXPECT_EQ(v.deviations.at("nan-clamp"), 1u);
  // The name of each known deviation.
  for (const arbvp::DeviationInfo& d : arbvp::KnownDeviations()) {
    Verdict one = CompareX({1.0f, 2.0f, 0.0f}, d.bit, d.bit);
    EXPECT_TRUE(one.disagreements.empty()) << d.name;
    EXPECT_EQ(one.deviations.count(std::string(d.name)), 1u) << d.name;
  }
}

TEST(VerifyCompare, InapplicableDeviationIsStillCompared) {
  // The component depends on llvmpipe's deviation; this engine runs on softpipe.
  uint32_t softpipe = arbvp::ApplicableDeviations(kEngineMesaArb, "softpipe");
  ASSERT_FALSE(softpipe & arbvp::kDevNonFiniteLlvmpipe);
  Verdict v = CompareX({kInf, 5.0f, 0.0f}, arbvp::kDevNonFiniteLlvmpipe, softpipe);
  EXPECT_EQ(v.compared, 4u);
  EXPECT_EQ(v.disagreements.size(), 1u);
  EXPECT_TRUE(v.deviations.empty());
  // An equal value with an inapplicable deviation agrees and is counted as compared.
  Verdict same = CompareX({kInf, kInf, 0.0f}, arbvp::kDevNonFiniteLlvmpipe, softpipe);
  EXPECT_TRUE(same.disagreements.empty());
  EXPECT_EQ(same.compared, 4u);
}

TEST(VerifyCompare, ComponentsTheEngineDoesNotReportAreSkipped) {
  // mesa-glsl reports only x of result.fogcoord.
  OutputRegister ref = Reg("result.fogcoord", {1, 2, 3, 4});
  OutputRegister got = Reg("result.fogcoord", {1, 0, 0, 0}, 0x1);
  Verdict v = Compare(One(ref), One(got), 0, kEngineMesaGlsl);
  EXPECT_TRUE(v.disagreements.empty());
  EXPECT_EQ(v.compared, 1u);
  // Components ref did not write are not compared either.
  OutputRegister narrow = Reg("result.color", {1, 0, 0, 0}, 0x1);
  OutputRegister wide = Reg("result.color", {1, 5, 6, 7});
  Verdict w = Compare(One(narrow), One(wide));
  EXPECT_TRUE(w.disagreements.empty());
  EXPECT_EQ(w.compared, 1u);
}

TEST(VerifyCompare, MissingRegisterIsADisagreement) {
  OutputRegister ref = Reg("result.texcoord[1]", {1, 2, 3, 4});
  VectorResult engine;
  engine.outputs.push_back(Reg("result.color", {1, 2, 3, 4}));
  Verdict v = Compare(One(ref), {engine}, 0, kEngineMesaGlsl);
  ASSERT_EQ(v.disagreements.size(), 1u);
  const Disagreement& d = v.disagreements[0];
  EXPECT_EQ(d.reg, "result.texcoord[1]");
  EXPECT_EQ(d.component, -1);
  EXPECT_EQ(d.what, "not written by mesa-glsl");
  EXPECT_EQ(d.engines, (std::vector<std::string>{kEngineMesaGlsl}));
  EXPECT_EQ(v.compared, 0u);
}

VectorResult Killed(bool killed) {
  VectorResult v;
  v.killed = killed;
  if (!killed) v.outputs.push_back(Reg("result.color", {1, 2, 3, 4}));
  return v;
}

TEST(VerifyCompare, KillMismatchIsADisagreement) {
  Verdict by_ref = Compare({Killed(true)}, {Killed(false)});
  ASSERT_EQ(by_ref.disagreements.size(), 1u);
  EXPECT_EQ(by_ref.disagreements[0].reg, "");
  EXPECT_EQ(by_ref.disagreements[0].component, -1);
  EXPECT_EQ(by_ref.disagreements[0].what, "killed by ref, not by mesa-arb");
  Verdict by_engine = Compare({Killed(false)}, {Killed(true)});
  ASSERT_EQ(by_engine.disagreements.size(), 1u);
  EXPECT_EQ(by_engine.disagreements[0].what, "killed by mesa-arb, not by ref");
  // Both killed: nothing to compare, nothing wrong.
  Verdict both = Compare({Killed(true)}, {Killed(true)});
  EXPECT_TRUE(both.disagreements.empty());
  EXPECT_EQ(both.compared, 0u);
}

TEST(VerifyCompare, KillMismatchIsSkippedWhenUnstableUndefinedOrADeviation) {
  VectorResult unstable = Killed(true);
  unstable.kill_unstable = true;
  EXPECT_TRUE(Compare({unstable}, {Killed(false)}).disagreements.empty());

  VectorResult undefined = Killed(true);
  undefined.kill_undefined = "whether KIL discards the fragment depends on XPD w";
  EXPECT_TRUE(Compare({undefined}, {Killed(false)}).disagreements.empty());

  VectorResult deviation = Killed(false);
  deviation.kill_deviations = arbvp::kDevNanClamp;
  Verdict skipped = Compare({deviation}, {Killed(true)}, arbvp::kDevNanClamp);
  EXPECT_TRUE(skipped.disagreements.empty());
  EXPECT_EQ(skipped.deviations.count("nan-clamp"), 1u);
  // An inapplicable kill deviation is still a disagreement.
  Verdict compared = Compare({deviation}, {Killed(true)}, arbvp::kDevLrpInfinite);
  EXPECT_EQ(compared.disagreements.size(), 1u);
  EXPECT_TRUE(compared.deviations.empty());
}

TEST(VerifyCompare, EnginesDisagreeingAtTheSamePlaceMerge) {
  OutputRegister ref = Reg("result.color", {1, 2, 3, 4});
  std::vector<VectorResult> refs = One(ref);
  Verdict v;
  CompareWithReference(refs, One(Reg("result.color", {1, 2, 5, 4})), kEngineMesaArb, 0, "edge", &v);
  CompareWithReference(refs, One(Reg("result.color", {1, 2, 6, 4})), kEngineMesaGlsl, 0, "edge",
                       &v);
  ASSERT_EQ(v.disagreements.size(), 1u);
  const Disagreement& d = v.disagreements[0];
  EXPECT_EQ(d.component, 2);
  EXPECT_EQ(d.engines, (std::vector<std::string>{kEngineMesaArb, kEngineMesaGlsl}));
  EXPECT_EQ(d.values.at(kEngineRef), 3.0f);
  EXPECT_EQ(d.values.at(kEngineMesaArb), 5.0f);
  EXPECT_EQ(d.values.at(kEngineMesaGlsl), 6.0f);
  EXPECT_EQ(v.compared, 8u);  // per Mesa engine
  // Another batch or another component is another disagreement.
  CompareWithReference(refs, One(Reg("result.color", {1, 2, 5, 4})), kEngineMesaArb, 0, "random 1",
                       &v);
  CompareWithReference(refs, One(Reg("result.color", {1, 7, 3, 4})), kEngineMesaGlsl, 0, "edge",
                       &v);
  EXPECT_EQ(v.disagreements.size(), 3u);
}

TEST(VerifyCompare, ComparedCountsEveryComparedComponentOfEveryVector) {
  VectorResult a;
  a.outputs.push_back(Reg("result.position", {1, 2, 3, 4}));
  a.outputs.push_back(Reg("result.color", {1, 2, 0, 0}, 0x3));
  VectorResult b = a;
  b.outputs[0].undefined[3] = "temporary 't.w' read before it is written";
  Verdict v = Compare({a, b}, {a, b});
  EXPECT_TRUE(v.disagreements.empty());
  EXPECT_EQ(v.compared, 6u + 5u);
  // Disagreements are recorded with their vector.
  std::vector<VectorResult> engine{a, b};
  engine[1].outputs[1].value[1] = 9.0f;
  Verdict w = Compare({a, b}, engine);
  ASSERT_EQ(w.disagreements.size(), 1u);
  EXPECT_EQ(w.disagreements[0].vector, 1u);
  EXPECT_EQ(w.disagreements[0].component, 1);
}

}  // namespace
}  // namespace arbiter::runtime
