// Runs every case of glsl_cases.h on every GLSL engine: "softpipe" and "llvmpipe" (RunGlsl,
// on the backend of ARBITER_TEST_BACKEND), and "vulkan" (RunGlslVulkan, glslang and lavapipe)
// where this tree has it and it runs. OSMesa picks its driver once per process, so ctest runs
// each engine in a process of its own (--gtest_filter=*/<engine>_*). The expectations are the
// specs' values: where an engine deviates, the case and component must be listed in
// glsl-deviations.txt with the spec section and the reason, and every listed deviation must
// still happen. The Vulkan engine refusing a case (not_applicable) fails it unless the case
// names that refusal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>

#include "glsl_cases.h"
#include "glsl_run.h"
#if __has_include("arbiter/runtime/glsl_vulkan.h")
#include "arbiter/runtime/glsl_vulkan.h"
#define ARBITER_TEST_GLSL_VULKAN 1
#endif

namespace arbiter::glsl_cases {
namespace {

using runtime::GlslOutput;
using runtime::GlslRunResult;
using runtime::testing::GlslRun;

// The comparison of glsl_cases.h.
bool Matches(float got, float want, Tolerance tolerance, float bound) {
  if (std::isnan(want)) return std::isnan(got);
  if (std::isnan(got)) return false;
  if (std::isinf(want) || std::isinf(got)) return got == want;
  switch (tolerance) {
    case Tolerance::Exact:
      return got == want;
    case Tolerance::Relative:
      return std::fabs(got - want) <= bound * std::fabs(want);
    case Tolerance::Absolute:
      return std::fabs(got - want) <= bound;
  }
  return false;
}

// "ENGINE CASE KEY # reason" lines of glsl-deviations.txt that apply to `engine` (ENGINE is
// the engine, "mesa" for softpipe and llvmpipe, or "*"), as "CASE KEY" -> reason.
std::map<std::string, std::string> KnownDeviations(const std::string& engine) {
  std::map<std::string, std::string> out;
  std::ifstream in(ARBITER_TEST_DIR "/glsl-deviations.txt");
  std::string line;
  const bool mesa = engine == "softpipe" || engine == "llvmpipe";
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string who, name, key;
    fields >> who >> name >> key;
    if (who != engine && who != "*" && !(who == "mesa" && mesa)) continue;
    std::string reason;
    std::getline(fields, reason);
    out[name + " " + key] = reason;
  }
  return out;
}

std::string Suffix(size_t vector) { return vector == 0 ? "" : "@" + std::to_string(vector); }

// The component's name in a key: x y z w for up to 4 numbers, else its index (matrices).
std::string Component(size_t i, size_t size) {
  return size <= 4 ? std::string(1, "xyzw"[i]) : std::to_string(i);
}

std::string Values(const std::vector<float>& v) {
  std::ostringstream out;
  out.precision(9);
  for (size_t i = 0; i < v.size(); ++i) out << (i ? ", " : "") << v[i];
  return "(" + out.str() + ")";
}

// The keys on which the result differs from the case: "v.y", "gl_FragColor.x@2" (vector 2),
// "m.5" (a matrix's component 5), "m.size", "k.missing", "discarded@1", "vectors".
std::set<std::string> Mismatches(const GlslCase& c, const GlslRunResult& result,
                                 std::string* details) {
  std::set<std::string> out;
  if (result.vectors.size() != c.vectors) {
    out.insert("vectors");
    *details += "the engine returned " + std::to_string(result.vectors.size()) + " vectors\n";
    return out;
  }
  for (size_t v = 0; v < c.vectors; ++v) {
    const bool want = std::find(c.discarded.begin(), c.discarded.end(), v) != c.discarded.end();
    if (result.vectors[v].discarded != want) {
      out.insert("discarded" + Suffix(v));
      *details += "vector " + std::to_string(v) + (want ? " survived\n" : " was discarded\n");
    }
  }
  for (const GlslExpect& e : c.expects) {
    const runtime::GlslVectorResult& r = result.vectors[e.vector];
    const GlslOutput* found = nullptr;
    for (const GlslOutput& o : r.outputs) {
      if (o.name == e.name) found = &o;
    }
    if (found == nullptr) {
      out.insert(e.name + ".missing" + Suffix(e.vector));
      *details += e.name + Suffix(e.vector) + ": not among the outputs\n";
      continue;
    }
    if (found->value.size() != e.value.size()) {
      out.insert(e.name + ".size" + Suffix(e.vector));
      *details += e.name + Suffix(e.vector) + ": " + Values(found->value) + ", spec " +
                  Values(e.value) + "\n";
      continue;
    }
    bool differs = false;
    for (size_t i = 0; i < e.value.size(); ++i) {
      if (!Matches(found->value[i], e.value[i], e.tolerance, e.bound)) {
        out.insert(e.name + "." + Component(i, e.value.size()) + Suffix(e.vector));
        differs = true;
      }
    }
    if (differs) {
      *details += e.name + Suffix(e.vector) + ": engine " + Values(found->value) + ", spec " +
                  Values(e.value) + "\n";
    }
  }
  return out;
}

// OSMesa (and EGL's Mesa) run the driver of the process's first context: a second driver in
// the same process is skipped (ctest runs each in its own process).
bool LockDriver(const std::string& driver, std::string* why) {
  static std::string locked;
  if (locked.empty()) locked = driver;
  if (locked == driver) return true;
  *why = "this process runs " + locked + ": Mesa picks its driver once per process (run with " +
         "--gtest_filter=*/" + driver + "_*)";
  return false;
}

#ifdef ARBITER_TEST_GLSL_VULKAN
// Whether RunGlslVulkan runs at all (a vertex shader that copies gl_Vertex); `why` when not.
bool VulkanRuns(std::string* why) {
  static const std::string failure = [] {
    GlslRun probe("void main() { gl_Position = gl_Vertex; }\n", "");
    GlslRunResult result;
    std::string not_applicable;
    std::string error;
    if (runtime::RunGlslVulkan(probe.shaders(), probe.inputs(), &result, &not_applicable, &error)) {
      return std::string();
    }
    return "the Vulkan engine does not run: " + (error.empty() ? not_applicable : error);
  }();
  *why = failure;
  return failure.empty();
}
#endif

using Param = std::tuple<std::string, GlslCase>;

class GlslCaseTest : public ::testing::TestWithParam<Param> {};

TEST_P(GlslCaseTest, MatchesSpecOrAKnownDeviation) {
  const std::string& engine = std::get<0>(GetParam());
  const GlslCase& c = std::get<1>(GetParam());
  std::string why;
#ifdef ARBITER_TEST_GLSL_VULKAN
  if (engine == "vulkan" && !VulkanRuns(&why)) GTEST_SKIP() << why;
#else
  if (engine == "vulkan") {
    GTEST_SKIP() << "this tree has no Vulkan GLSL engine (arbiter/runtime/glsl_vulkan.h)";
  }
#endif
  if (engine != "vulkan" && !LockDriver(engine, &why)) GTEST_SKIP() << why;

  GlslRun run(c.vertex, c.fragment);
  ASSERT_EQ(run.check_errors(), 0u) << "arbiter's checker rejects the case's shaders";
  run.Vectors(c.vectors);
  for (size_t v = 0; v < c.sets.size(); ++v) {
    for (const std::string& s : c.sets[v]) run.Set(s, v);
  }
  for (const std::string& u : c.uniforms) run.Uniform(u);
  for (const std::string& s : c.state) run.State(s);
  for (const std::string& t : c.textures) run.Texture(t);
  if (c.make_textures) c.make_textures(run.inputs().textures);
  ASSERT_FALSE(HasFatalFailure());

  GlslRunResult result;
  std::string error;
  std::string not_applicable;
  bool ok = false;
  if (engine == "vulkan") {
#ifdef ARBITER_TEST_GLSL_VULKAN
    ok = runtime::RunGlslVulkan(run.shaders(), run.inputs(), &result, &not_applicable, &error);
#endif
  } else {
    runtime::ExecOptions options = runtime::testing::EnvOptions();
    options.driver = engine;
    ok = runtime::RunGlsl(options, run.shaders(), run.inputs(), &result, &error);
  }

  std::set<std::string> mismatches;
  std::string details;
  if (!c.vulkan_refusal.empty() && engine == "vulkan") {
    EXPECT_NE(not_applicable.find(c.vulkan_refusal), std::string::npos)
        << c.name << ": the Vulkan engine should refuse it (" << c.vulkan_refusal << ") but "
        << (ok ? "ran it" : "said: " + not_applicable + error);
    return;
  }
  if (!ok && !not_applicable.empty()) {
    mismatches.insert("refused");
    details += "refused: " + not_applicable + "\n";
  } else if (!ok) {
    mismatches.insert("error");
    details += "error: " + error + "\n";
  } else if (!result.usage_error.empty()) {
    mismatches.insert("error");
    details += "usage error: " + result.usage_error + "\n";
  } else {
    mismatches = Mismatches(c, result, &details);
  }

  const std::map<std::string, std::string> known = KnownDeviations(engine);
  for (const std::string& m : mismatches) {
    EXPECT_TRUE(known.count(c.name + " " + m))
        << c.name << " " << m << " on " << engine << " differs from the spec (" << c.spec << ")\n"
        << details;
  }
  for (const auto& [key, reason] : known) {
    if (key.rfind(c.name + " ", 0) != 0) continue;
    EXPECT_TRUE(mismatches.count(key.substr(c.name.size() + 1)))
        << "listed deviation no longer happens on " << engine
        << ", remove it from glsl-deviations.txt: " << key;
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, GlslCaseTest,
                         ::testing::Combine(::testing::Values("softpipe", "llvmpipe", "vulkan"),
                                            ::testing::ValuesIn(AllGlslCases())),
                         [](const ::testing::TestParamInfo<Param>& param) {
                           return std::get<0>(param.param) + "_" + std::get<1>(param.param).name;
                         });

}  // namespace
}  // namespace arbiter::glsl_cases
