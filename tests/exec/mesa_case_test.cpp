// Runs every execution case of cases.h on Mesa (the backend and driver named by
// ARBITER_TEST_BACKEND and ARBITER_TEST_DRIVER; ctest runs each combination in its own
// process, as OSMesa picks its driver once per process). The expectations are the specs'
// values: where Mesa deviates, the case and component must be listed in
// mesa-deviations.txt with the reason, and every listed deviation must still happen (unless
// it is marked "sometimes": Mesa state that earlier draws change).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "../runtime/test_executor.h"
#include "arbiter/arbvp/check.h"
#include "arbiter/runtime/exec.h"
#include "case_compare.h"
#include "cases.h"

namespace arbiter::exec_cases {
namespace {

using arbvp::OutputRegister;
using arbvp::VectorResult;

// One context for the whole run, as `verify` uses it: many programs one after another.
runtime::ArbExecutor* Executor() {
  std::string error;
  runtime::ArbExecutor* executor = runtime::testing::SharedExecutor(&error);
  EXPECT_NE(executor, nullptr) << error;
  return executor;
}

// "case-name result.color.y" keys, per driver (or "*"), from mesa-deviations.txt.
struct Deviations {
  std::map<std::string, std::string> reasons;  // key -> reason
  std::set<std::string> sometimes;             // keys that do not happen on every run
};

const Deviations& KnownDeviations() {
  static const Deviations d = [] {
    Deviations out;
    std::ifstream in(ARBITER_TEST_DIR "/mesa-deviations.txt");
    std::string line;
    const std::string driver = runtime::testing::TestDriver();
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream fields(line);
      std::string who, name, component, flag;
      fields >> who >> name >> component >> flag;
      std::string reason;
      std::getline(fields, reason);
      if (who != driver && who != "*") continue;
      const std::string key = name + " " + component;
      out.reasons[key] = reason;
      if (flag == "sometimes") out.sometimes.insert(key);
    }
    return out;
  }();
  return d;
}

struct Loaded {
  std::unique_ptr<compiler::SourceFile> source;
  arbvp::CheckResult result;
};

Loaded Load(const std::string& text) {
  Loaded l;
  l.source = std::make_unique<compiler::SourceFile>("case", text);
  compiler::DiagnosticSink sink(0);
  l.result = arbvp::CheckProgram(*l.source, {}, &sink);
  return l;
}

// The components of the case on which Mesa's results differ from the spec, as
// "result.color.y" (vector 0) or "result.color.y@2" keys; "killed@v" for a kill mismatch.
std::set<std::string> Mismatches(const ExecCase& c, const std::vector<VectorResult>& results,
                                 std::string* details) {
  std::set<std::string> out;
  auto suffix = [](size_t v) { return v == 0 ? std::string() : "@" + std::to_string(v); };
  for (size_t v = 0; v < results.size(); ++v) {
    bool want_killed = std::find(c.killed.begin(), c.killed.end(), v) != c.killed.end();
    if (results[v].killed != want_killed) {
      out.insert("killed" + suffix(v));
      *details += "vector " + std::to_string(v) + (want_killed ? " survived\n" : " was killed\n");
    }
  }
  for (const Expect& e : c.expects) {
    if (e.vector >= results.size()) {
      out.insert("missing-vector");
      continue;
    }
    const VectorResult& r = results[e.vector];
    if (r.killed) continue;  // reported above if unexpected
    const OutputRegister* found = nullptr;
    for (const OutputRegister& o : r.outputs) {
      if (o.name == e.reg) found = &o;
    }
    if (e.absent || !found) {
      if (e.absent != !found) out.insert(e.reg + suffix(e.vector));
      continue;
    }
    for (size_t i = 0; i < 4; ++i) {
      if (!(e.mask & (1u << i)) || (e.undefined & (1u << i))) continue;
      if (!(found->written & (1u << i)) ||
          !Matches(found->value[i], e.value[i], e.tolerance, e.bound)) {
        std::string key = e.reg + "." + "xyzw"[i] + suffix(e.vector);
        out.insert(key);
        *details += key + ": mesa " + std::to_string(found->value[i]) + ", spec " +
                    std::to_string(e.value[i]) + "\n";
      }
    }
  }
  return out;
}

class MesaCaseTest : public testing::TestWithParam<ExecCase> {};

TEST_P(MesaCaseTest, MatchesSpecOrAKnownDeviation) {
  const ExecCase& c = GetParam();
  runtime::ArbExecutor* executor = Executor();
  ASSERT_NE(executor, nullptr);
  arbvp::ExecInputs inputs;
  inputs.vectors.resize(1);
  c.setup(inputs);
  Loaded vp;
  Loaded fp;
  runtime::ArbPrograms programs;
  if (!c.vertex_text.empty()) {
    vp = Load(c.vertex_text);
    ASSERT_TRUE(vp.result.ok);
    programs.vertex = vp.result.program.get();
  }
  if (!c.fragment_text.empty()) {
    fp = Load(c.fragment_text);
    ASSERT_TRUE(fp.result.ok);
    programs.fragment = fp.result.program.get();
  }
  // Mesa has none of the NV program options: their cases are the reference interpreter's.
  if ((programs.vertex && programs.vertex->Nv()) ||
      (programs.fragment && programs.fragment->Nv())) {
    GTEST_SKIP() << "an NV program option";
  }
  std::vector<VectorResult> results;
  std::string error;
  ASSERT_TRUE(executor->Run(programs, inputs, &results, &error)) << error;
  ASSERT_EQ(results.size(), inputs.vectors.size());

  std::string details;
  std::set<std::string> mismatches = Mismatches(c, results, &details);
  const auto& known = KnownDeviations().reasons;
  for (const std::string& m : mismatches) {
    EXPECT_TRUE(known.count(c.name + " " + m))
        << c.name << " " << m << " differs from the spec (" << c.spec << ")\n"
        << details << (results.empty() ? "" : Describe(results[0]));
  }
  for (const auto& [key, reason] : known) {
    if (key.rfind(c.name + " ", 0) != 0 || KnownDeviations().sometimes.count(key)) continue;
    EXPECT_TRUE(mismatches.count(key.substr(c.name.size() + 1)))
        << "listed deviation no longer happens, remove it from mesa-deviations.txt: " << key;
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, MesaCaseTest, testing::ValuesIn(AllExecCases()),
                         [](const testing::TestParamInfo<ExecCase>& param) {
                           return param.param.name;
                         });

}  // namespace
}  // namespace arbiter::exec_cases
