// Tests of limit keys, the built-in profiles and loading JSON limit profiles.
#include "arbiter/compiler/limits.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

namespace arbiter::compiler {
namespace {

namespace fs = std::filesystem;

// The built-in names as error messages list them.
constexpr const char* kNames = "'spec-min', 'mesa', 'r300', 'r500', 'i915', 'nv30' or 'nv40'";

TEST(LimitKeysTest, KeysAreUniqueAndWellFormed) {
  const std::vector<LimitKey>& keys = LimitKeys();
  ASSERT_FALSE(keys.empty());
  std::set<std::string_view> seen;
  for (const LimitKey& key : keys) {
    EXPECT_TRUE(seen.insert(key.key).second) << "duplicate key " << key.key;
    const size_t dot = key.key.find('.');
    ASSERT_NE(dot, std::string_view::npos) << key.key;
    const std::string_view stage = key.key.substr(0, dot);
    EXPECT_TRUE(stage == "arbvp" || stage == "arbfp" || stage == "gl") << key.key;
    EXPECT_EQ(key.key.find_first_not_of("abcdefghijklmnopqrstuvwxyz_.", 0), std::string_view::npos)
        << key.key;
    EXPECT_FALSE(key.gl_name.empty()) << key.key;
    EXPECT_FALSE(key.description.empty()) << key.key;
  }
  EXPECT_TRUE(seen.count("arbvp.max_instructions"));
  EXPECT_TRUE(seen.count("arbfp.max_tex_indirections"));
}

TEST(BuiltinProfileTest, NamesAndUnknownName) {
  EXPECT_EQ(BuiltinProfileNames(), (std::vector<std::string_view>{"spec-min", "mesa", "r300",
                                                                  "r500", "i915", "nv30", "nv40"}));
  EXPECT_EQ(BuiltinProfile("nvidia"), nullptr);
  EXPECT_EQ(BuiltinProfile(""), nullptr);
  ASSERT_NE(BuiltinProfile("spec-min"), nullptr);
  EXPECT_EQ(BuiltinProfile("spec-min")->name, "spec-min");
  ASSERT_NE(BuiltinProfile("mesa"), nullptr);
  EXPECT_EQ(BuiltinProfile("mesa")->name, "mesa");
  for (const std::string_view name : BuiltinProfileNames()) {
    ASSERT_NE(BuiltinProfile(name), nullptr) << name;
    EXPECT_EQ(BuiltinProfile(name)->name, name);
    EXPECT_EQ(BuiltinProfile(name)->base, name);
  }
}

TEST(BuiltinProfileTest, EveryProfileDefinesEveryKeyAndNothingElse) {
  for (const std::string_view name : BuiltinProfileNames()) {
    const LimitProfile* profile = BuiltinProfile(name);
    ASSERT_NE(profile, nullptr);
    EXPECT_EQ(profile->values.size(), LimitKeys().size()) << name;
    for (const LimitKey& key : LimitKeys()) {
      EXPECT_EQ(profile->values.count(key.key), 1u) << name << " lacks " << key.key;
      EXPECT_GE(profile->Get(key.key), 0) << name << " " << key.key;
    }
  }
}

TEST(BuiltinProfileTest, SpecMinValues) {
  // The minimum maximums of the ARB_vertex_program and ARB_fragment_program state tables.
  const LimitProfile& spec = *BuiltinProfile("spec-min");
  EXPECT_EQ(spec.Get("arbvp.max_instructions"), 128);
  EXPECT_EQ(spec.Get("arbvp.max_temporaries"), 12);
  EXPECT_EQ(spec.Get("arbvp.max_parameters"), 96);
  EXPECT_EQ(spec.Get("arbvp.max_address_registers"), 1);
  EXPECT_EQ(spec.Get("arbfp.max_instructions"), 72);
  EXPECT_EQ(spec.Get("arbfp.max_alu_instructions"), 48);
  EXPECT_EQ(spec.Get("arbfp.max_tex_instructions"), 24);
  EXPECT_EQ(spec.Get("arbfp.max_tex_indirections"), 4);
  EXPECT_EQ(spec.Get("arbfp.max_temporaries"), 16);
}

TEST(BuiltinProfileTest, MesaMeetsTheSpecMinimums) {
  // An implementation must support at least the minimum maximums.
  const LimitProfile& spec = *BuiltinProfile("spec-min");
  const LimitProfile& mesa = *BuiltinProfile("mesa");
  for (const LimitKey& key : LimitKeys()) {
    EXPECT_GE(mesa.Get(key.key), spec.Get(key.key)) << key.key;
  }
}

// The GPU profiles, spot-checked against the drivers in ../shared/reference/mesa-gpu-limits:
// one row per value, with the line that gives it (or the computation from it).
struct DriverFact {
  const char* profile;
  const char* key;
  int64_t value;
  const char* source;
};

constexpr DriverFact kDriverFacts[] = {
    {"r300", "arbfp.max_instructions", 96, "r300_screen.c:270 is_r500 || is_r400 ? 512 : 96"},
    {"r300", "arbfp.max_alu_instructions", 64, "r300_screen.c:272, radeon_code.h:28"},
    {"r300", "arbfp.max_tex_instructions", 32, "r300_screen.c:274, radeon_code.h:29"},
    {"r300", "arbfp.max_tex_indirections", 4, "r300_screen.c:276 is_r500 ? 511 : 4"},
    {"r300", "arbfp.max_temporaries", 32, "r300_screen.c:296 ... is_r400 ? 64 : 32"},
    {"r300", "arbfp.max_parameters", 32, "r300_screen.c:291 (is_r500 ? 256 : 32) vec4"},
    {"r300", "arbfp.max_attribs", 10, "r300_screen.c:287 2 colors + 8 texcoords"},
    {"r300", "arbfp.max_texture_coords", 8, "min(16 samplers, 8 coordinate units)"},
    {"r300", "arbfp.max_texture_image_units", 16, "r300_screen.c:299 caps.num_tex_units"},
    {"r300", "arbfp.max_draw_buffers", 4, "r300_screen.c:212 PIPE_CAP_MAX_RENDER_TARGETS"},
    {"r300", "arbvp.max_instructions", 256, "r300_screen.c:377, radeon_code.h:250"},
    {"r300", "arbvp.max_temporaries", 32, "r300_screen.c:389, radeon_code.h:254"},
    {"r300", "arbvp.max_parameters", 256, "r300_screen.c:385 256 vec4"},
    {"r500", "arbfp.max_instructions", 512, "r300_screen.c:270 with is_r500"},
    {"r500", "arbfp.max_tex_indirections", 511, "r300_screen.c:276 with is_r500"},
    {"r500", "arbfp.max_temporaries", 128, "r300_screen.c:296 with is_r500"},
    {"r500", "arbfp.max_parameters", 256, "r300_screen.c:291 with is_r500"},
    {"r500", "arbfp.max_env_parameters", 256, "min(256 parameters, 256)"},
    {"r500", "arbvp.max_instructions", 1024, "r300_screen.c:377, radeon_code.h:252"},
    {"r500", "arbvp.max_temporaries", 32, "r300_screen.c:389"},
    {"i915", "arbfp.max_instructions", 96, "i915_screen.c:326 I915_MAX_ALU_INSN + _TEX_INSN"},
    {"i915", "arbfp.max_alu_instructions", 64, "i915_screen.c:328, i915_reg.h:458"},
    {"i915", "arbfp.max_tex_instructions", 32, "i915_screen.c:330, i915_reg.h:457"},
    {"i915", "arbfp.max_tex_indirections", 4, "i915_screen.c:332, i915_reg.h:456"},
    {"i915", "arbfp.max_temporaries", 16, "i915_screen.c:345, i915_reg.h:460"},
    {"i915", "arbfp.max_parameters", 32, "i915_screen.c:340 32 vec4"},
    {"i915", "arbfp.max_attribs", 10, "i915_screen.c:336, i915_reg.h:504-513"},
    {"i915", "arbfp.max_texture_coords", 8, "i915_reg.h:504-511 T_TEX0-T_TEX7"},
    {"i915", "arbfp.max_texture_image_units", 8, "i915_screen.c:361 I915_TEX_UNITS"},
    {"i915", "arbfp.max_draw_buffers", 1, "i915_screen.c:455"},
    {"nv30", "arbvp.max_instructions", 256, "nv30_screen.c:334 NV40 ? 512 : 256"},
    {"nv30", "arbvp.max_temporaries", 13, "nv30_screen.c:348 NV40 ? 32 : 13"},
    {"nv30", "arbvp.max_parameters", 250, "nv30_screen.c:344 (256 - 6) vec4"},
    {"nv30", "arbfp.max_tex_indirections", 4096, "nv30_screen.c:395"},
    {"nv30", "arbfp.max_attribs", 8, "nv30_screen.c:399"},
    {"nv30", "arbfp.max_parameters", 32, "nv30_screen.c:403 NV40 ? 224 : 32"},
    {"nv30", "arbfp.max_draw_buffers", 1, "nv30_screen.c:60 NV40 ? 4 : 1"},
    {"nv40", "arbvp.max_instructions", 512, "nv30_screen.c:334"},
    {"nv40", "arbvp.max_temporaries", 32, "nv30_screen.c:348"},
    {"nv40", "arbvp.max_parameters", 462, "nv30_screen.c:344 (468 - 6) vec4"},
    {"nv40", "arbvp.max_env_parameters", 256, "min(462 parameters, 256)"},
    {"nv40", "arbfp.max_instructions", 4096, "nv30_screen.c:395"},
    {"nv40", "arbfp.max_parameters", 224, "nv30_screen.c:403"},
    {"nv40", "arbfp.max_texture_image_units", 16, "nv30_screen.c:410"},
    {"nv40", "arbfp.max_draw_buffers", 4, "nv30_screen.c:60"},
};

TEST(BuiltinProfileTest, DriverFacts) {
  for (const DriverFact& fact : kDriverFacts) {
    const LimitProfile* profile = BuiltinProfile(fact.profile);
    ASSERT_NE(profile, nullptr) << fact.profile;
    EXPECT_EQ(profile->Get(fact.key), fact.value)
        << fact.profile << " " << fact.key << " (" << fact.source << ")";
  }
}

TEST(BuiltinProfileTest, I915VertexProgramsRunInMesasDrawModule) {
  // i915_screen.c:320: draw_get_shader_param answers for vertex shaders, Mesa's own limits.
  const LimitProfile& i915 = *BuiltinProfile("i915");
  const LimitProfile& mesa = *BuiltinProfile("mesa");
  for (const LimitKey& key : LimitKeys()) {
    if (key.key.starts_with("arbvp.")) {
      EXPECT_EQ(i915.Get(key.key), mesa.Get(key.key)) << key.key;
    }
  }
}

TEST(BuiltinProfileTest, HardwareNeverExceedsMesa) {
  // What a GPU's profile accepts, the default (Mesa's limits) accepts too.
  const LimitProfile& mesa = *BuiltinProfile("mesa");
  for (const std::string_view name : {"r300", "r500", "i915", "nv30", "nv40"}) {
    for (const LimitKey& key : LimitKeys()) {
      EXPECT_LE(BuiltinProfile(name)->Get(key.key), mesa.Get(key.key)) << name << " " << key.key;
    }
  }
}

TEST(BuiltinProfileTest, HardwareMeetsTheSpecMinimumsButNv3xFragmentInputs) {
  // nv30_screen.c:399 reports 8 fragment inputs, fewer than ARB_fragment_program's 10
  // ("should be possible to do 10 with nv4x"); every other value meets the minimum.
  const LimitProfile& spec = *BuiltinProfile("spec-min");
  for (const std::string_view name : {"r300", "r500", "i915", "nv30", "nv40"}) {
    for (const LimitKey& key : LimitKeys()) {
      const bool nv3x_inputs = name.starts_with("nv") && key.key == "arbfp.max_attribs";
      EXPECT_EQ(BuiltinProfile(name)->Get(key.key) >= spec.Get(key.key), !nv3x_inputs)
          << name << " " << key.key;
    }
  }
}

TEST(LimitProfileTest, MissingKey) {
  const LimitProfile& spec = *BuiltinProfile("spec-min");
#ifdef NDEBUG
  EXPECT_EQ(spec.Get("arbvp.max_foo"), 0);
#else
  EXPECT_DEATH((void)spec.Get("arbvp.max_foo"), "unknown limit key");
#endif
}

// A fresh directory for profile files, removed at the end of the test.
class LoadLimitProfileTest : public ::testing::Test {
 protected:
  LoadLimitProfileTest() {
    std::string pattern = (fs::temp_directory_path() / "arbiter-limits-test-XXXXXX").string();
    dir_ = ::mkdtemp(pattern.data());
    file_ = (dir_ / "limits.json").string();
  }
  ~LoadLimitProfileTest() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  // Writes `contents` to `name` in the directory; returns its path.
  std::string Write(const std::string& name, const std::string& contents) {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << contents;
    return path.string();
  }

  // Loads `contents` from file_ and returns the error ("" on success).
  std::string ErrorOf(const std::string& contents) {
    Write("limits.json", contents);
    std::string error;
    const std::optional<LimitProfile> profile = LoadLimitProfile(file_, &error);
    EXPECT_EQ(profile.has_value(), error.empty());
    return error;
  }

  fs::path dir_;
  std::string file_;  // the file ErrorOf writes
};

TEST_F(LoadLimitProfileTest, BuiltinNames) {
  std::string error;
  const std::optional<LimitProfile> mesa = LoadLimitProfile("mesa", &error);
  ASSERT_TRUE(mesa.has_value()) << error;
  EXPECT_EQ(mesa->name, "mesa");
  EXPECT_EQ(mesa->values, BuiltinProfile("mesa")->values);
  const std::optional<LimitProfile> spec = LoadLimitProfile("spec-min", &error);
  ASSERT_TRUE(spec.has_value()) << error;
  EXPECT_EQ(spec->values, BuiltinProfile("spec-min")->values);
}

TEST_F(LoadLimitProfileTest, FileOverridesKeysOfItsBase) {
  const std::string path = Write("gma.json", R"({
    "name": "intel-gma950",
    "base": "mesa",
    "limits": {"arbvp.max_temporaries": 32, "arbfp.max_tex_indirections": 0}
  })");
  std::string error;
  const std::optional<LimitProfile> profile = LoadLimitProfile(path, &error);
  ASSERT_TRUE(profile.has_value()) << error;
  EXPECT_EQ(profile->name, "intel-gma950");
  EXPECT_EQ(profile->Get("arbvp.max_temporaries"), 32);
  EXPECT_EQ(profile->Get("arbfp.max_tex_indirections"), 0);
  // Every other key comes from the base.
  const LimitProfile& mesa = *BuiltinProfile("mesa");
  EXPECT_EQ(profile->values.size(), mesa.values.size());
  EXPECT_EQ(profile->Get("arbvp.max_instructions"), mesa.Get("arbvp.max_instructions"));
}

TEST_F(LoadLimitProfileTest, BaseMayBeAHardwareProfile) {
  const std::string path = Write("gma950.json", R"({
    "name": "gma950-more-temps",
    "base": "i915",
    "limits": {"arbfp.max_temporaries": 32}
  })");
  std::string error;
  const std::optional<LimitProfile> profile = LoadLimitProfile(path, &error);
  ASSERT_TRUE(profile.has_value()) << error;
  EXPECT_EQ(profile->name, "gma950-more-temps");
  EXPECT_EQ(profile->base, "i915");
  EXPECT_EQ(profile->Get("arbfp.max_temporaries"), 32);
  EXPECT_EQ(profile->Get("arbfp.max_tex_indirections"), 4);
  const std::optional<LimitProfile> nv40 = LoadLimitProfile("nv40", &error);
  ASSERT_TRUE(nv40.has_value()) << error;
  EXPECT_EQ(nv40->values, BuiltinProfile("nv40")->values);
}

TEST_F(LoadLimitProfileTest, DefaultBaseIsSpecMinAndDefaultNameIsThePath) {
  const std::string path = Write("small.json", R"({"limits": {"arbfp.max_temporaries": 8}})");
  std::string error;
  const std::optional<LimitProfile> profile = LoadLimitProfile(path, &error);
  ASSERT_TRUE(profile.has_value()) << error;
  EXPECT_EQ(profile->name, path);
  EXPECT_EQ(profile->Get("arbfp.max_temporaries"), 8);
  EXPECT_EQ(profile->Get("arbvp.max_instructions"), 128);
}

TEST_F(LoadLimitProfileTest, LargeValuesAndNoLimitsMember) {
  EXPECT_EQ(ErrorOf(R"({"limits": {"arbvp.max_instructions": 9223372036854775807}})"), "");
  EXPECT_EQ(ErrorOf(R"({"name": "copy", "base": "mesa"})"), "");
  EXPECT_EQ(ErrorOf(R"({})"), "");
}

TEST_F(LoadLimitProfileTest, UnknownKey) {
  EXPECT_EQ(ErrorOf(R"({"limits": {"arbvp.max_foo": 1}})"),
            "unknown limit key 'arbvp.max_foo' in '" + file_ + "'");
}

TEST_F(LoadLimitProfileTest, UnknownKeyNearAKnownOneGetsAHint) {
  EXPECT_EQ(ErrorOf(R"({"limits": {"arbvp.max_temporary": 1}})"),
            "unknown limit key 'arbvp.max_temporary' in '" + file_ +
                "' (did you mean 'arbvp.max_temporaries'?)");
}

TEST_F(LoadLimitProfileTest, ValuesMustBeNonNegativeIntegers) {
  EXPECT_EQ(
      ErrorOf(R"({"limits": {"arbvp.max_temporaries": -1}})"),
      "limit 'arbvp.max_temporaries' in '" + file_ + "' must be a non-negative integer, not -1");
  EXPECT_EQ(
      ErrorOf(R"({"limits": {"arbvp.max_temporaries": 1.5}})"),
      "limit 'arbvp.max_temporaries' in '" + file_ + "' must be a non-negative integer, not 1.5");
  EXPECT_EQ(
      ErrorOf(R"({"limits": {"arbvp.max_temporaries": 12.0}})"),
      "limit 'arbvp.max_temporaries' in '" + file_ + "' must be a non-negative integer, not 12.0");
  EXPECT_EQ(ErrorOf(R"({"limits": {"arbvp.max_temporaries": "12"}})"),
            "limit 'arbvp.max_temporaries' in '" + file_ +
                "' must be a non-negative integer, not \"12\"");
  EXPECT_EQ(
      ErrorOf(R"({"limits": {"arbvp.max_temporaries": true}})"),
      "limit 'arbvp.max_temporaries' in '" + file_ + "' must be a non-negative integer, not true");
  EXPECT_EQ(
      ErrorOf(R"({"limits": {"arbvp.max_temporaries": null}})"),
      "limit 'arbvp.max_temporaries' in '" + file_ + "' must be a non-negative integer, not null");
  EXPECT_EQ(ErrorOf(R"({"limits": {"arbvp.max_temporaries": 9223372036854775808}})"),
            "limit 'arbvp.max_temporaries' in '" + file_ +
                "' must be a non-negative integer, not 9223372036854775808");
}

TEST_F(LoadLimitProfileTest, UnknownBase) {
  EXPECT_EQ(ErrorOf(R"({"base": "nvidia"})"),
            "unknown base profile 'nvidia' in '" + file_ + "' (expected " + kNames + ")");
  EXPECT_EQ(ErrorOf(R"({"base": 3})"),
            "'base' in '" + file_ + "' must be a string (" + kNames + ")");
}

TEST_F(LoadLimitProfileTest, WrongShapes) {
  EXPECT_EQ(ErrorOf(R"([1, 2])"), "limits file '" + file_ + "' must hold a JSON object");
  EXPECT_EQ(ErrorOf(R"({"limit": {}})"),
            "unknown member 'limit' in '" + file_ +
                "' (expected 'name', 'base', 'limits' and 'extensions')");
  EXPECT_EQ(ErrorOf(R"({"limits": [1]})"),
            "'limits' in '" + file_ + "' must be an object of limit keys");
  EXPECT_EQ(ErrorOf(R"({"name": 1})"), "'name' in '" + file_ + "' must be a string");
}

TEST_F(LoadLimitProfileTest, InvalidJson) {
  const std::string error = ErrorOf("{\"limits\": {\"arbvp.max_temporaries\": 1,}}");
  const std::string prefix = "invalid JSON in '" + file_ + "': parse error at line 1, column ";
  EXPECT_EQ(error.substr(0, prefix.size()), prefix) << error;
  EXPECT_EQ(error.find("[json.exception"), std::string::npos) << error;
  EXPECT_EQ(ErrorOf("").substr(0, 16), "invalid JSON in ");
}

TEST_F(LoadLimitProfileTest, MissingFile) {
  const std::string path = (dir_ / "missing.json").string();
  std::string error;
  EXPECT_FALSE(LoadLimitProfile(path, &error).has_value());
  EXPECT_EQ(error, "cannot read limits file '" + path + "': no such file or directory");
}

TEST_F(LoadLimitProfileTest, DirectoryIsNotAFile) {
  std::string error;
  EXPECT_FALSE(LoadLimitProfile(dir_.string(), &error).has_value());
  EXPECT_EQ(error, "cannot read limits file '" + dir_.string() + "': is a directory");
}

TEST_F(LoadLimitProfileTest, UnknownProfileName) {
  std::string error;
  EXPECT_FALSE(LoadLimitProfile("nvidia", &error).has_value());
  EXPECT_EQ(error, "unknown limit profile 'nvidia' (expected " + std::string(kNames) +
                       ", or a JSON file)");
}

}  // namespace
}  // namespace arbiter::compiler
