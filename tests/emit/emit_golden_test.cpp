// Golden translations of representative programs: tests/emit/golden/NAME.vert / NAME.frag
// and NAME.bindings.json. ARBITER_UPDATE_GOLDEN=1 rewrites them; review the diff.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "emit_fixture.h"

namespace arbiter::arbvp::testing {
namespace {

namespace fs = std::filesystem;

struct Golden {
  const char* name;
  const char* vertex;    // path under the source tree, or nullptr
  const char* fragment;  // path under the source tree, or nullptr
};

// Inputs: corpus programs, and tests/emit/golden/inputs/ for what the corpus lacks.
const Golden kGoldens[] = {
    {"lighting", "corpus/arb/valid/directional-light-two-sided.vp", nullptr},
    {"fog-linear", nullptr, "corpus/arb/valid/option-fog-linear.fp"},
    {"shadow", nullptr, "corpus/arb/valid/shadow-and-color-units.fp"},
    {"relative-addressing", "corpus/arb/valid/arl-relative-addressing.vp", nullptr},
    {"swz-lit-exp-log", "tests/emit/golden/inputs/swz-lit-exp-log.vp", nullptr},
    {"position-invariant", "corpus/arb/valid/position-invariant-lighting.vp", nullptr},
    {"draw-buffers", nullptr, "tests/emit/golden/inputs/draw-buffers-fog.fp"},
    {"fragment-ops", nullptr, "tests/emit/golden/inputs/fragment-ops.fp"},
    {"pair", "tests/emit/golden/inputs/pair.vp", "tests/emit/golden/inputs/pair.fp"},
    {"nv-vertex", "tests/emit/golden/inputs/nv-vertex.vp", nullptr},
    {"nv-fragment", nullptr, "tests/emit/golden/inputs/nv-fragment.fp"},
    {"nv-flow", nullptr, "tests/emit/golden/inputs/nv-flow.fp"},
};

void PrintTo(const Golden& g, std::ostream* os) { *os << g.name; }

fs::path GoldenDir() { return fs::path(ARBITER_TEST_DIR) / "golden"; }

void Compare(const std::string& file, const std::string& actual) {
  fs::path path = GoldenDir() / file;
  if (std::getenv("ARBITER_UPDATE_GOLDEN")) {
    std::ofstream(path, std::ios::binary) << actual;
    return;
  }
  ASSERT_TRUE(fs::exists(path)) << path << " is missing: rerun with ARBITER_UPDATE_GOLDEN=1";
  EXPECT_EQ(ReadFile(path.string()), actual)
      << file << " differs: rerun with ARBITER_UPDATE_GOLDEN=1 and review the diff";
}

Checked Load(const char* path) {
  std::string full = (fs::path(ARBITER_SOURCE_DIR) / path).string();
  return CheckText(fs::path(path).filename().string(), ReadFile(full));
}

class EmitGoldenTest : public ::testing::TestWithParam<Golden> {};

TEST_P(EmitGoldenTest, MatchesGoldenFiles) {
  const Golden& g = GetParam();
  if (g.vertex && g.fragment) {
    Checked vp = Load(g.vertex);
    Checked fp = Load(g.fragment);
    ASSERT_TRUE(vp.program) << vp.errors;
    ASSERT_TRUE(fp.program) << fp.errors;
    PairTranslation pair =
        EmitGlslPair(*vp.program, *fp.program, EmitOptions{}, vp.source.get(), fp.source.get());
    EXPECT_EQ(GlslErrors(ProgramKind::Vertex, pair.vertex), "");
    EXPECT_EQ(GlslErrors(ProgramKind::Fragment, pair.fragment), "");
    Compare(std::string(g.name) + ".vert", pair.vertex);
    Compare(std::string(g.name) + ".frag", pair.fragment);
    Compare(std::string(g.name) + ".bindings.json", BindingMapToJson(pair.bindings));
    return;
  }
  Checked c = Load(g.vertex ? g.vertex : g.fragment);
  ASSERT_TRUE(c.program) << c.errors;
  Translation t = EmitGlsl(*c.program, EmitOptions{}, c.source.get());
  EXPECT_EQ(GlslErrors(c.program->kind, t.glsl), "");
  Compare(std::string(g.name) + (g.vertex ? ".vert" : ".frag"), t.glsl);
  Compare(std::string(g.name) + ".bindings.json", BindingMapToJson(t.bindings));
}

std::string GoldenName(const ::testing::TestParamInfo<Golden>& param) {
  std::string name;
  for (const char* p = param.param.name; *p; ++p) name += *p == '-' ? '_' : *p;
  return name;
}

INSTANTIATE_TEST_SUITE_P(Golden, EmitGoldenTest, ::testing::ValuesIn(kGoldens), GoldenName);

}  // namespace
}  // namespace arbiter::arbvp::testing
