// The GLSL targets (emit_targets.def) and state as uniforms: golden translations of a few
// programs per target (tests/emit/golden/targets/NAME.TARGET.vert|frag|bindings.json), every
// valid corpus program on every target held to the target's validator (glslang for GLSL and
// HLSL, spirv-val for SPIR-V) or refused with a diagnostic naming the construct and the
// target, and the refusals themselves.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "arbiter/targets/targets.h"
#include "emit_fixture.h"

namespace arbiter::arbvp::testing {
namespace {

namespace fs = std::filesystem;

constexpr EmitTarget kTargets[] = {EmitTarget::Glsl120, EmitTarget::Glsl330, EmitTarget::Es100,
                                   EmitTarget::Es300, EmitTarget::Vk450};

// The validator's dialect of a GLSL target, by its --target spelling.
targets::GlslDialect Dialect(EmitTarget t) {
  return targets::GlslDialectNamed(EmitTargetName(t)).value_or(targets::GlslDialect::Glsl110);
}

targets::Stage StageOf(ProgramKind kind) {
  return kind == ProgramKind::Vertex ? targets::Stage::Vertex : targets::Stage::Fragment;
}

std::string Messages(const std::vector<targets::Message>& messages) {
  std::string out;
  for (const targets::Message& m : messages) out += targets::FormatMessage(m) + "\n";
  return out;
}

// "" when the target's validators accept the shader (Vulkan: the SPIR-V module, its HLSL
// and its MSL too), else what they said.
std::string TargetErrors(EmitTarget target, ProgramKind kind, const std::string& glsl) {
  std::vector<targets::Message> messages;
  if (!targets::ValidateGlsl(glsl, StageOf(kind), Dialect(target), &messages)) {
    return "glsl: " + Messages(messages);
  }
  if (target != EmitTarget::Vk450) return "";
  std::vector<uint32_t> spirv;
  if (!targets::CompileGlslToSpirv(glsl, StageOf(kind), &spirv, &messages)) {
    return "spirv: " + Messages(messages);
  }
  std::string hlsl;
  // Direct3D 11 has no point size: `translate --target hlsl` refuses result.pointsize.
  if (glsl.find("gl_PointSize") != std::string::npos) return "";
  if (!targets::SpirvToHlsl(spirv, &hlsl, &messages)) return "to hlsl: " + Messages(messages);
  if (!targets::ValidateHlsl(hlsl, StageOf(kind), &messages)) return "hlsl: " + Messages(messages);
  std::string msl;
  if (!targets::SpirvToMsl(spirv, &msl, &messages)) return "to msl: " + Messages(messages);
  return "";
}

EmitOptions For(EmitTarget target) {
  EmitOptions o;
  o.target = target;
  return o;
}

Checked Load(const std::string& path) {
  std::string full = (fs::path(ARBITER_SOURCE_DIR) / path).string();
  return CheckText(fs::path(path).filename().string(), ReadFile(full));
}

void Compare(const std::string& file, const std::string& actual) {
  fs::path path = fs::path(ARBITER_TEST_DIR) / "golden" / "targets" / file;
  if (std::getenv("ARBITER_UPDATE_GOLDEN")) {
    std::ofstream(path, std::ios::binary) << actual;
    return;
  }
  ASSERT_TRUE(fs::exists(path)) << path << " is missing: rerun with ARBITER_UPDATE_GOLDEN=1";
  EXPECT_EQ(ReadFile(path.string()), actual)
      << file << " differs: rerun with ARBITER_UPDATE_GOLDEN=1 and review the diff";
}

struct Golden {
  const char* name;
  const char* vertex;
  const char* fragment;
};

const Golden kGoldens[] = {
    {"pair", "tests/emit/golden/inputs/pair.vp", "tests/emit/golden/inputs/pair.fp"},
    {"lighting", "corpus/arb/valid/directional-light-two-sided.vp", nullptr},
    {"fog-linear", nullptr, "corpus/arb/valid/option-fog-linear.fp"},
    {"position-invariant", "corpus/arb/valid/position-invariant-lighting.vp", nullptr},
    {"relative-addressing", "corpus/arb/valid/arl-relative-addressing.vp", nullptr},
};

TEST(EmitTargetsTest, GoldenTranslations) {
  for (const Golden& g : kGoldens) {
    for (EmitTarget target : kTargets) {
      SCOPED_TRACE(std::string(g.name) + " " + std::string(EmitTargetName(target)));
      const std::string base = std::string(g.name) + "." + std::string(EmitTargetName(target));
      if (g.vertex && g.fragment) {
        Checked vp = Load(g.vertex);
        Checked fp = Load(g.fragment);
        ASSERT_TRUE(vp.program && fp.program) << vp.errors << fp.errors;
        PairTranslation pair =
            EmitGlslPair(*vp.program, *fp.program, For(target), vp.source.get(), fp.source.get());
        EXPECT_EQ(TargetErrors(target, ProgramKind::Vertex, pair.vertex), "");
        EXPECT_EQ(TargetErrors(target, ProgramKind::Fragment, pair.fragment), "");
        Compare(base + ".vert", pair.vertex);
        Compare(base + ".frag", pair.fragment);
        Compare(base + ".bindings.json", BindingMapToJson(pair.bindings));
        continue;
      }
      Checked c = Load(g.vertex ? g.vertex : g.fragment);
      ASSERT_TRUE(c.program) << c.errors;
      Translation t = EmitGlsl(*c.program, For(target), c.source.get());
      EXPECT_EQ(TargetErrors(target, c.program->kind, t.glsl), "");
      Compare(base + (g.vertex ? ".vert" : ".frag"), t.glsl);
      Compare(base + ".bindings.json", BindingMapToJson(t.bindings));
    }
  }
}

// What a dialect's gl_FragCoord lacks is emulated exactly (state_uniforms.cpp, FragPosition):
// y counted from the other edge is "framebuffer.height" minus y, integer pixel centres are
// half a pixel lower; where gl_FragCoord matches there is no uniform.
TEST(EmitTargetsTest, FragmentPositionConventions) {
  auto translate = [](EmitTarget target, const std::string& text) {
    Checked c = CheckText("t.fp", text);
    EXPECT_TRUE(c.program) << c.errors;
    Translation t = EmitGlsl(*c.program, For(target), c.source.get());
    EXPECT_EQ(TargetErrors(target, ProgramKind::Fragment, t.glsl), "") << t.glsl;
    return t;
  };
  auto has_height = [](const Translation& t) {
    for (const StateUniform& u : t.bindings.state) {
      if (u.name == "arb_framebuffer_height") return u.binding == "framebuffer.height";
    }
    return false;
  };
  const std::string plain = "!!ARBfp1.0\nMOV result.color, fragment.position;\nEND\n";
  const std::string upper =
      "!!ARBfp1.0\nOPTION ARB_fragment_coord_origin_upper_left;\n"
      "MOV result.color, fragment.position;\nEND\n";
  const std::string both =
      "!!ARBfp1.0\nOPTION ARB_fragment_coord_origin_upper_left;\n"
      "OPTION ARB_fragment_coord_pixel_center_integer;\n"
      "MOV result.color, fragment.position;\nEND\n";
  // Vulkan counts y from the top: ARB's lower-left y is flipped, the upper-left one is not.
  Translation t = translate(EmitTarget::Vk450, plain);
  EXPECT_NE(t.glsl.find("(arb_framebuffer_height.x - gl_FragCoord.y)"), std::string::npos);
  EXPECT_TRUE(has_height(t));
  t = translate(EmitTarget::Vk450, upper);
  EXPECT_EQ(t.glsl.find("arb_framebuffer_height"), std::string::npos);
  EXPECT_NE(t.glsl.find("arb_fragcolor0 = gl_FragCoord;"), std::string::npos) << t.glsl;
  // ES counts y from the bottom: the option's upper-left y is flipped.
  t = translate(EmitTarget::Es300, plain);
  EXPECT_EQ(t.glsl.find("arb_framebuffer_height"), std::string::npos);
  t = translate(EmitTarget::Es300, both);
  EXPECT_NE(t.glsl.find("vec4((gl_FragCoord.x - 0.5), ((arb_framebuffer_height.x - "
                        "gl_FragCoord.y) - 0.5), gl_FragCoord.zw)"),
            std::string::npos)
      << t.glsl;
  EXPECT_TRUE(has_height(t));
  // GLSL 3.30 has the layout qualifiers.
  t = translate(EmitTarget::Glsl330, both);
  EXPECT_NE(t.glsl.find("layout(origin_upper_left, pixel_center_integer) in vec4 gl_FragCoord;"),
            std::string::npos);
  EXPECT_FALSE(has_height(t));
}

// A shadow lookup of the GLSL 1.30 dialects expands its float by the texture's
// GL_DEPTH_TEXTURE_MODE, a uniform spelled "texture[n].depthmode" (glstate::DepthModeSelector).
TEST(EmitTargetsTest, ShadowLookupReadsDepthMode) {
  Checked c = CheckText("t.fp",
                        "!!ARBfp1.0\nOPTION ARB_fragment_program_shadow;\n"
                        "TEX result.color, fragment.texcoord[0], texture[2], SHADOW2D;\nEND\n");
  ASSERT_TRUE(c.program) << c.errors;
  for (EmitTarget target : {EmitTarget::Glsl330, EmitTarget::Es300, EmitTarget::Vk450}) {
    SCOPED_TRACE(std::string(EmitTargetName(target)));
    Translation t = EmitGlsl(*c.program, For(target), c.source.get());
    EXPECT_EQ(TargetErrors(target, ProgramKind::Fragment, t.glsl), "");
    EXPECT_NE(t.glsl.find("arb_shadow(texture(arb_texture2, arb_texcoord0.xyz), "
                          "arb_texture2_depthmode)"),
              std::string::npos)
        << t.glsl;
    bool bound = false;
    for (const StateUniform& u : t.bindings.state) {
      bound = bound || (u.name == "arb_texture2_depthmode" && u.type == "vec4" &&
                        u.binding == "texture[2].depthmode");
    }
    EXPECT_TRUE(bound);
  }
}

// Samplers a dialect lacks are 2D ones (sampler_emulation.cpp): a 1D texture N x 1 read at
// t = 0.5 (0.5 q before a projective division), a rectangle one read at its texel
// coordinates over textureSize; the binding map gives their 2D type, which UploadsAs2D reads.
TEST(EmitTargetsTest, EmulatedSamplers) {
  Checked c = CheckText("t.fp",
                        "!!ARBfp1.0\nOPTION ARB_fragment_program_shadow;\nTEMP a, b, d;\n"
                        "TEX a, fragment.texcoord[0], texture[0], 1D;\n"
                        "TXP b, fragment.texcoord[0], texture[0], 1D;\n"
                        "TXP d, fragment.texcoord[1], texture[1], SHADOW1D;\n"
                        "TEX a, fragment.texcoord[2], texture[2], RECT;\n"
                        "TXP b, fragment.texcoord[2], texture[2], RECT;\n"
                        "TEX d, fragment.texcoord[3], texture[3], SHADOWRECT;\n"
                        "ADD result.color, a, b;\nEND\n");
  ASSERT_TRUE(c.program) << c.errors;
  Translation t = EmitGlsl(*c.program, For(EmitTarget::Es300), c.source.get());
  EXPECT_EQ(TargetErrors(EmitTarget::Es300, ProgramKind::Fragment, t.glsl), "");
  for (const char* expected :
       {"a = texture(arb_texture0, vec2(arb_texcoord0.x, 0.5));",
        "b = textureProj(arb_texture0, vec4((arb_texcoord0).x, 0.5 * (arb_texcoord0).w, 0.0, "
        "(arb_texcoord0).w));",
        "d = arb_shadow(textureProj(arb_texture1, vec4((arb_texcoord1).x, 0.5 * "
        "(arb_texcoord1).w, (arb_texcoord1).z, (arb_texcoord1).w)), arb_texture1_depthmode);",
        "a = texture(arb_texture2, (arb_texcoord2.xy) / vec2(textureSize(arb_texture2, 0)));",
        "b = textureProj(arb_texture2, vec4((arb_texcoord2).xy / "
        "vec2(textureSize(arb_texture2, 0)), (arb_texcoord2).zw));",
        "d = arb_shadow(texture(arb_texture3, vec3((arb_texcoord3.xyz).xy / "
        "vec2(textureSize(arb_texture3, 0)), (arb_texcoord3.xyz).z)), arb_texture3_depthmode);",
        "uniform highp sampler2D arb_texture0;  // texture[0], 1D",
        "uniform highp sampler2DShadow arb_texture3;  // texture[3], SHADOWRECT"}) {
    EXPECT_NE(t.glsl.find(expected), std::string::npos) << expected << "\n" << t.glsl;
  }
  ASSERT_EQ(t.bindings.samplers.size(), 4u);
  for (const SamplerBinding& s : t.bindings.samplers) {
    EXPECT_TRUE(UploadsAs2D(s)) << s.name << " " << s.type;
  }
  // GLSL 3.30 has them all; Vulkan has 1D samplers but no rectangle ones.
  Translation core = EmitGlsl(*c.program, For(EmitTarget::Glsl330), c.source.get());
  for (const SamplerBinding& s : core.bindings.samplers) EXPECT_FALSE(UploadsAs2D(s)) << s.name;
  Translation vk = EmitGlsl(*c.program, For(EmitTarget::Vk450), c.source.get());
  EXPECT_EQ(TargetErrors(EmitTarget::Vk450, ProgramKind::Fragment, vk.glsl), "");
  for (const SamplerBinding& s : vk.bindings.samplers) {
    EXPECT_EQ(UploadsAs2D(s), s.unit >= 2) << s.name;
  }
}

// GLSL 1.10 with --state uniforms: the same uniforms, GLSL 1.10 keywords.
TEST(EmitTargetsTest, Glsl110WithStateUniforms) {
  Checked c = Load("corpus/arb/valid/directional-light-two-sided.vp");
  ASSERT_TRUE(c.program) << c.errors;
  EmitOptions o;
  o.state = StateSource::Uniforms;
  Translation t = EmitGlsl(*c.program, o, c.source.get());
  EXPECT_EQ(GlslErrors(ProgramKind::Vertex, t.glsl), "");
  EXPECT_EQ(t.glsl.find("gl_ModelView"), std::string::npos) << t.glsl;
  EXPECT_EQ(t.glsl.find("gl_Vertex"), std::string::npos) << t.glsl;
  EXPECT_NE(t.glsl.find("attribute vec4 arb_vertex_position;"), std::string::npos) << t.glsl;
  EXPECT_TRUE(t.bindings.state_uniforms);
}

// Every valid corpus program on every target: accepted by the target's validators, or
// refused with a diagnostic that names the target's dialect.
TEST(EmitTargetsTest, CorpusTranslatesToEveryTargetOrIsRefused) {
  std::vector<std::string> files = ValidCorpusFiles();
  for (const fs::directory_entry& e :
       fs::directory_iterator(fs::path(ARBITER_SOURCE_DIR) / "corpus/arb/valid-nv")) {
    files.push_back("valid-nv/" + e.path().filename().string());
  }
  ASSERT_GT(files.size(), 200u);
  int translated = 0;
  int refused = 0;
  for (const std::string& file : files) {
    Checked c = Load("corpus/arb/" + file);
    ASSERT_TRUE(c.program) << file << ": " << c.errors;
    for (EmitTarget target : kTargets) {
      SCOPED_TRACE(file + " " + std::string(EmitTargetName(target)));
      Untranslatable u = FindUntranslatable(*c.program, For(target));
      if (!u.what.empty()) {
        EXPECT_NE(u.what.find(EmitTargetTitle(target)), std::string::npos) << u.what;
        EXPECT_LT(u.range.begin, u.range.end) << u.what;
        ++refused;
        continue;
      }
      Translation t = EmitGlsl(*c.program, For(target), c.source.get());
      EXPECT_EQ(TargetErrors(target, c.program->kind, t.glsl), "") << t.glsl;
      ++translated;
    }
  }
  // Most programs translate everywhere: the refusals are the dialects' gaps.
  EXPECT_GT(translated, 8 * refused);
}

// ARB names that later dialects reserve (or that name their types and the lookups the
// translation calls) are renamed there: the output still compiles.
TEST(EmitTargetsTest, NamesReservedByLaterDialects) {
  const std::string text =
      "!!ARBvp1.0\nTEMP sample, patch, buffer, shared, filter, subroutine, coherent, readonly, "
      "resource, atomic_uint, precise, superp, centroid, layout, flat, smooth, uint, uvec4, "
      "isampler2D, mat2x3, textureLod, case;\n"
      "MOV sample, vertex.position;\nMOV patch, sample;\nMOV buffer, patch;\n"
      "MOV shared, buffer;\nMOV filter, shared;\nMOV subroutine, filter;\n"
      "MOV coherent, subroutine;\nMOV readonly, coherent;\nMOV resource, readonly;\n"
      "MOV atomic_uint, resource;\nMOV precise, atomic_uint;\nMOV superp, precise;\n"
      "MOV centroid, superp;\nMOV layout, centroid;\nMOV flat, layout;\nMOV smooth, flat;\n"
      "MOV uint, smooth;\nMOV uvec4, uint;\nMOV isampler2D, uvec4;\nMOV mat2x3, isampler2D;\n"
      "MOV textureLod, mat2x3;\nMOV case, textureLod;\nMOV result.position, case;\nEND\n";
  for (EmitTarget target : kTargets) {
    SCOPED_TRACE(std::string(EmitTargetName(target)));
    Translation t = TranslateText(text, For(target));
    EXPECT_EQ(TargetErrors(target, ProgramKind::Vertex, t.glsl), "") << t.glsl;
    EXPECT_NE(t.glsl.find("vec4 u_sample = vec4(0.0);"), std::string::npos) << t.glsl;
  }
  // GLSL 1.10 keeps the names it does not reserve (its output is unchanged).
  EXPECT_NE(TranslateText(text).glsl.find("vec4 sample = vec4(0.0);"), std::string::npos);
}

std::string RefusalOf(EmitTarget target, const std::string& text) {
  Checked c = CheckText("t", text);
  EXPECT_TRUE(c.program) << c.errors;
  if (!c.program) return "";
  Untranslatable u = FindUntranslatable(*c.program, For(target));
  if (u.what.empty()) return "";
  compiler::LineCol at = c.source->Locate(u.range.begin);
  return std::to_string(at.line) + ":" + std::to_string(at.column) + ": " + u.what;
}

TEST(EmitTargetsTest, Refusals) {
  const std::string tex1d =
      "!!ARBfp1.0\nTEMP t;\nTEX t, fragment.texcoord[0], texture[0], 1D;\n"
      "MOV result.color, t;\nEND\n";
  // 1D textures are emulated everywhere, rectangle ones where textureSize exists, their
  // shadow forms where 2D shadow samplers do (EmulatedSamplers below).
  for (EmitTarget t : kTargets) EXPECT_EQ(RefusalOf(t, tex1d), "") << EmitTargetName(t);
  const std::string shadow1d =
      "!!ARBfp1.0\nOPTION ARB_fragment_program_shadow;\n"
      "TEX result.color, fragment.texcoord[0], texture[0], SHADOW1D;\nEND\n";
  EXPECT_EQ(RefusalOf(EmitTarget::Es100, shadow1d),
            "3:53: TEX of a SHADOW1D texture: GLSL ES 1.00 has no SHADOW1D samplers");
  EXPECT_EQ(RefusalOf(EmitTarget::Es300, shadow1d), "");
  const std::string rect =
      "!!ARBfp1.0\nTEX result.color, fragment.texcoord[0], texture[1], RECT;\nEND\n";
  // The packing instructions need floatBitsToUint: GLSL 3.30, ES 3.00 and Vulkan have it.
  const std::string pack =
      "!!ARBfp1.0\nOPTION NV_fragment_program;\nTEMP t;\nPK2H t, fragment.color;\n"
      "UP4UB result.color, t.x;\nEND\n";
  EXPECT_EQ(RefusalOf(EmitTarget::Es100, pack),
            "4:1: PK2H needs the bits of a float, which GLSL ES 1.00 cannot form "
            "(floatBitsToUint: GLSL 3.30 and ES 3.00)");
  for (EmitTarget t : {EmitTarget::Glsl330, EmitTarget::Es300, EmitTarget::Vk450}) {
    EXPECT_EQ(RefusalOf(t, pack), "") << EmitTargetName(t);
  }
  EXPECT_EQ(RefusalOf(EmitTarget::Es100, rect),
            "2:53: TEX of a RECT texture: GLSL ES 1.00 has no RECT samplers");
  for (EmitTarget t : {EmitTarget::Glsl330, EmitTarget::Es300, EmitTarget::Vk450}) {
    EXPECT_EQ(RefusalOf(t, rect), "") << EmitTargetName(t);
  }
  // fragment.position and ARB_fragment_coord_conventions are emulated with state as uniforms
  // (FragPosition); GLSL 1.20 with built-in state has no layout qualifiers and no uniform.
  const std::string position = "!!ARBfp1.0\nMOV result.color, fragment.position;\nEND\n";
  EXPECT_EQ(RefusalOf(EmitTarget::Vk450, position), "");
  EXPECT_EQ(RefusalOf(EmitTarget::Es300, position), "");
  const std::string upper =
      "!!ARBfp1.0\nOPTION ARB_fragment_coord_origin_upper_left;\n"
      "MOV result.color, fragment.position;\nEND\n";
  for (EmitTarget t : {EmitTarget::Es300, EmitTarget::Vk450}) {
    EXPECT_EQ(RefusalOf(t, upper), "") << EmitTargetName(t);
  }
  // ES 1.00's gl_FragCoord is mediump: no exact fragment.position there at all.
  EXPECT_EQ(RefusalOf(EmitTarget::Es100, position),
            "2:19: fragment.position: GLSL ES 1.00 has a mediump gl_FragCoord (section 7.2), "
            "not the window position to float precision");
  EXPECT_EQ(RefusalOf(EmitTarget::Glsl120, upper),
            "2:8: OPTION ARB_fragment_coord_origin_upper_left: GLSL 1.20 has no gl_FragCoord "
            "layout qualifiers");
  const std::string color1 =
      "!!ARBfp1.0\nOPTION ARB_draw_buffers;\nMOV result.color[1], fragment.color;\nEND\n";
  EXPECT_EQ(RefusalOf(EmitTarget::Es100, color1),
            "3:5: result.color[n] with n > 0: GLSL ES 1.00 has one colour output");
  EXPECT_EQ(RefusalOf(EmitTarget::Es300, color1), "");
  const std::string rep =
      "!!ARBfp1.0\nOPTION NV_fragment_program2;\nTEMP t;\nMOV t, 0;\nREP {4}.x;\n"
      "ADD t, t, 1;\nENDREP;\nMOV result.color, t;\nEND\n";
  EXPECT_EQ(RefusalOf(EmitTarget::Es100, rep),
            "5:1: REP: GLSL ES 1.00 has only for loops with constant bounds (Appendix A), no "
            "branches");
  EXPECT_EQ(RefusalOf(EmitTarget::Es300, rep), "");
}

}  // namespace
}  // namespace arbiter::arbvp::testing
