// Every valid corpus program translates to GLSL that glslang accepts, byte-identically on
// every run; every test-only mutation changes the translation of some corpus program.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "arbiter/arbvp/emit_mutation.h"
#include "emit_fixture.h"

namespace arbiter::arbvp::testing {
namespace {

namespace fs = std::filesystem;

std::string CorpusPath(const std::string& name) {
  return (fs::path(ARBITER_SOURCE_DIR) / "corpus" / "arb" / name).string();
}

class EmitCorpusTest : public ::testing::TestWithParam<std::string> {};

TEST_P(EmitCorpusTest, TranslatesToAcceptedGlsl) {
  Checked c = CheckText(GetParam(), ReadFile(CorpusPath(GetParam())));
  ASSERT_TRUE(c.program) << c.errors;
  Translation first = EmitGlsl(*c.program, EmitOptions{}, c.source.get());
  Translation second = EmitGlsl(*c.program, EmitOptions{}, c.source.get());
  EXPECT_EQ(first.glsl, second.glsl) << "translation is not deterministic";
  EXPECT_EQ(BindingMapToJson(first.bindings), BindingMapToJson(second.bindings));
  EXPECT_EQ(GlslErrors(c.program->kind, first.glsl), "") << first.glsl;

  // Without the source, comments are rebuilt from the IR; without comments, none at all.
  Translation rebuilt = EmitGlsl(*c.program, EmitOptions{}, nullptr);
  EXPECT_EQ(GlslErrors(c.program->kind, rebuilt.glsl), "") << rebuilt.glsl;
  EmitOptions bare;
  bare.comments = false;
  Translation plain = EmitGlsl(*c.program, bare, c.source.get());
  EXPECT_EQ(plain.glsl.find("// MOV"), std::string::npos);
}

std::string TestName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name;
  for (char ch : info.param) name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, EmitCorpusTest, ::testing::ValuesIn(ValidCorpusFiles()), TestName);

// The NV option programs (corpus/arb/valid-nv), as "valid-nv/name".
std::vector<std::string> NvCorpusFiles() {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(fs::path(CorpusPath("valid-nv")))) {
    std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".vp" || ext == ".fp")) {
      files.push_back("valid-nv/" + entry.path().filename().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Each mutation must change the emitted text of at least one corpus program, the NV ones
// included (else the differential verifier could never catch it), and the mutated text must
// still compile.
TEST(EmitMutations, EachChangesSomeCorpusTranslation) {
  struct Item {
    Checked checked;
    std::string glsl;
  };
  std::vector<Item> items;
  std::vector<std::string> names = ValidCorpusFiles();
  for (const std::string& name : NvCorpusFiles()) names.push_back(name);
  for (const std::string& name : names) {
    Item item{CheckText(name, ReadFile(CorpusPath(name))), ""};
    ASSERT_TRUE(item.checked.program) << name;
    item.glsl = EmitGlsl(*item.checked.program, EmitOptions{}, item.checked.source.get()).glsl;
    items.push_back(std::move(item));
  }
  std::vector<Mutation> all = AllMutations();
  EXPECT_GE(all.size(), 20u);
  for (Mutation m : all) {
    const EmitOptions options = WithMutation(EmitOptions{}, m);
    int changed = 0;
    for (const Item& item : items) {
      Translation t = EmitGlsl(*item.checked.program, options, item.checked.source.get());
      if (t.glsl == item.glsl) continue;
      if (changed++ == 0) {
        EXPECT_EQ(GlslErrors(item.checked.program->kind, t.glsl), "")
            << MutationName(m) << " in " << item.checked.source->path() << ":\n"
            << t.glsl;
      }
      EXPECT_EQ(t.bindings.mutation, MutationName(m));
    }
    EXPECT_GT(changed, 0) << "mutation " << MutationName(m) << " changes no corpus translation";
  }
}

TEST(EmitMutations, NamesRoundTrip) {
  for (Mutation m : AllMutations()) {
    Mutation back = Mutation::None;
    ASSERT_TRUE(LookupMutation(MutationName(m), &back)) << MutationName(m);
    EXPECT_EQ(back, m);
    EXPECT_NE(MutationName(m), "none");
  }
  Mutation none = Mutation::RsqNoAbs;
  EXPECT_TRUE(LookupMutation("none", &none));
  EXPECT_EQ(none, Mutation::None);
  EXPECT_FALSE(LookupMutation("no-such-mutation", &none));
}

}  // namespace
}  // namespace arbiter::arbvp::testing
