// Runs every execution case of cases.h on the reference interpreter, plus interpreter-only
// checks (reasons without a source, the result order, KIL on undefined values).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <set>
#include <sstream>

#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/interpret.h"
#include "case_compare.h"
#include "cases.h"

namespace arbiter::exec_cases {
namespace {

using arbvp::OutputRegister;
using arbvp::VectorResult;

struct Loaded {
  std::unique_ptr<compiler::SourceFile> source;
  arbvp::CheckResult result;
  std::string errors;
};

Loaded Load(const std::string& text) {
  Loaded l;
  l.source = std::make_unique<compiler::SourceFile>("case", text);
  compiler::DiagnosticSink sink(0);
  l.result = arbvp::CheckProgram(*l.source, {}, &sink);
  for (const compiler::Diagnostic& d : sink.diagnostics()) l.errors += d.message + "\n";
  return l;
}

std::vector<VectorResult> RunCase(const ExecCase& c, bool with_source = true) {
  arbvp::ExecInputs inputs;
  inputs.vectors.resize(1);
  c.setup(inputs);
  Loaded vp;
  Loaded fp;
  if (!c.vertex_text.empty()) {
    vp = Load(c.vertex_text);
    EXPECT_TRUE(vp.result.ok) << vp.errors;
    if (!vp.result.ok) return {};
  }
  if (!c.fragment_text.empty()) {
    fp = Load(c.fragment_text);
    EXPECT_TRUE(fp.result.ok) << fp.errors;
    if (!fp.result.ok) return {};
  }
  if (vp.result.program && fp.result.program) {
    return arbvp::InterpretPair(*vp.result.program, *fp.result.program, inputs,
                                with_source ? vp.source.get() : nullptr,
                                with_source ? fp.source.get() : nullptr);
  }
  const Loaded& one = vp.result.program ? vp : fp;
  return arbvp::Interpret(*one.result.program, inputs, with_source ? one.source.get() : nullptr);
}

class RefCaseTest : public testing::TestWithParam<ExecCase> {};

TEST_P(RefCaseTest, MatchesSpec) {
  const ExecCase& c = GetParam();
  std::vector<VectorResult> results = RunCase(c);
  ASSERT_FALSE(results.empty());
  for (size_t v = 0; v < results.size(); ++v) {
    bool want_killed = std::find(c.killed.begin(), c.killed.end(), v) != c.killed.end();
    EXPECT_EQ(results[v].killed, want_killed) << "vector " << v << "\n" << Describe(results[v]);
    EXPECT_EQ(results[v].kill_undefined, "") << "vector " << v;
  }
  for (const Expect& e : c.expects) {
    ASSERT_LT(e.vector, results.size());
    const VectorResult& r = results[e.vector];
    const OutputRegister* found = nullptr;
    for (const OutputRegister& o : r.outputs) {
      if (o.name == e.reg) found = &o;
    }
    std::string context =
        "vector " + std::to_string(e.vector) + " " + e.reg + " (" + c.spec + ")\n" + Describe(r);
    if (e.absent) {
      EXPECT_EQ(found, nullptr) << context;
      continue;
    }
    ASSERT_NE(found, nullptr) << context;
    if (e.written >= 0) {
      EXPECT_EQ(found->written, e.written) << context;
    }
    for (size_t i = 0; i < 4; ++i) {
      std::string comp = context + " component " + "xyzw"[i];
      if (e.undefined & (1u << i)) {
        EXPECT_TRUE(found->written & (1u << i)) << comp;
        EXPECT_NE(found->undefined[i].find(e.reason), std::string::npos)
            << comp << ": want a tag containing '" << e.reason << "', got '" << found->undefined[i]
            << "'";
        continue;
      }
      if (!(e.mask & (1u << i))) continue;
      EXPECT_TRUE(found->written & (1u << i)) << comp;
      EXPECT_EQ(found->undefined[i], "") << comp;
      EXPECT_TRUE(Matches(found->value[i], e.value[i], e.tolerance, e.bound))
          << comp << ": got " << found->value[i] << ", want " << e.value[i];
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, RefCaseTest, testing::ValuesIn(AllExecCases()),
                         [](const testing::TestParamInfo<ExecCase>& param) {
                           return param.param.name;
                         });

TEST(RefCases, NamesAreUnique) {
  std::set<std::string> names;
  for (const ExecCase& c : AllExecCases()) EXPECT_TRUE(names.insert(c.name).second) << c.name;
}

// The tolerance model must reject a wrong value, or the table could not catch a bug.
TEST(RefCases, ComparisonRejectsWrongValues) {
  EXPECT_FALSE(Matches(0.0f, -0.0f, Tolerance::Exact, 0));
  EXPECT_FALSE(Matches(1.0f, std::nextafter(1.0f, 2.0f), Tolerance::Exact, 0));
  EXPECT_TRUE(Matches(NAN, NAN, Tolerance::Exact, 0));
  EXPECT_FALSE(Matches(NAN, 1.0f, Tolerance::Relative, kApprox));
  EXPECT_FALSE(Matches(INFINITY, 3.4e38f, Tolerance::Relative, kApprox));
  EXPECT_TRUE(Matches(8.003f, 8.0f, Tolerance::Relative, kApprox));
  EXPECT_FALSE(Matches(8.01f, 8.0f, Tolerance::Relative, kApprox));
}

const ExecCase& Find(const std::string& name) {
  for (const ExecCase& c : AllExecCases()) {
    if (c.name == name) return c;
  }
  static ExecCase none;
  ADD_FAILURE() << "no case " << name;
  return none;
}

TEST(RefInterpreter, ReasonsWithoutSourceHaveNoLocation) {
  std::vector<VectorResult> r = RunCase(Find("xpd"), /*with_source=*/false);
  ASSERT_EQ(r.size(), 1u);
  ASSERT_EQ(r[0].outputs.size(), 1u);
  EXPECT_EQ(r[0].outputs[0].undefined[3], "XPD w");
}

TEST(RefInterpreter, OutputsInResultOrder) {
  ExecCase c;
  c.vertex_text =
      "!!ARBvp1.0\nMOV result.texcoord[3], 1;\nMOV result.texcoord[1], 1;\n"
      "MOV result.fogcoord.x, 1;\nMOV result.color.back, 1;\nMOV result.position, 1;\n"
      "MOV result.color, 1;\nMOV result.pointsize.x, 1;\nMOV result.color.secondary, 1;\nEND\n";
  c.setup = [](arbvp::ExecInputs&) {};
  std::vector<VectorResult> r = RunCase(c);
  ASSERT_EQ(r.size(), 1u);
  std::vector<std::string> names;
  for (const OutputRegister& o : r[0].outputs) names.push_back(o.name);
  EXPECT_EQ(names,
            (std::vector<std::string>{"result.position", "result.color.front.primary",
                                      "result.color.front.secondary", "result.color.back.primary",
                                      "result.fogcoord", "result.pointsize", "result.texcoord[1]",
                                      "result.texcoord[3]"}));
}

TEST(RefInterpreter, KilOnUndefinedValueIsReported) {
  ExecCase c;
  c.fragment_text = "!!ARBfp1.0\nTEMP t;\nKIL t;\nMOV result.color, 1;\nEND\n";
  c.setup = [](arbvp::ExecInputs&) {};
  std::vector<VectorResult> r = RunCase(c);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_NE(r[0].kill_undefined.find("temporary 't.x' read before it is written at 3:1"),
            std::string::npos)
      << r[0].kill_undefined;
  ASSERT_FALSE(r[0].killed);
  ASSERT_EQ(r[0].outputs.size(), 1u);
  EXPECT_NE(r[0].outputs[0].undefined[0], "");
}

TEST(RefInterpreter, DefinedKillWinsOverUndefined) {
  ExecCase c;
  c.fragment_text = "!!ARBfp1.0\nTEMP t;\nMOV t.x, -1;\nKIL t;\nMOV result.color, 1;\nEND\n";
  c.setup = [](arbvp::ExecInputs&) {};
  std::vector<VectorResult> r = RunCase(c);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_TRUE(r[0].killed);
  EXPECT_EQ(r[0].kill_undefined, "");
  EXPECT_TRUE(r[0].outputs.empty());
}

TEST(RefState, InitialState) {
  arbvp::GlState s;
  arbvp::Binding b;
  b.kind = arbvp::BindingKind::State;
  b.state = arbvp::StateItem::MatrixRow;
  b.matrix = arbvp::MatrixName::Program;
  b.index = 7;
  b.row = 2;
  EXPECT_EQ(arbvp::ReadStateBinding(s, b), (arbvp::Vec4{0, 0, 1, 0}));
  b.state = arbvp::StateItem::FogParams;
  // GL 2.0 initial fog: density 1, start 0, end 1 -> 1 / (1 - 0) = 1.
  EXPECT_EQ(arbvp::ReadStateBinding(s, b), (arbvp::Vec4{1, 0, 1, 1}));
  b.state = arbvp::StateItem::LightPosition;
  b.index = 5;
  EXPECT_EQ(arbvp::ReadStateBinding(s, b), (arbvp::Vec4{0, 0, 1, 0}));
}

}  // namespace
}  // namespace arbiter::exec_cases
