// The GLSL dialects (emit_targets.def): the table, what each refuses (FindUntranslatable),
// and the final pass that turns the GLSL 1.10 text the other files write into the dialect's
// (lookup function names, the fragment depth of ES 1.00, extensions and precision).
#include "emit/emit_target.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <iterator>

#include "arbiter/arbvp/emit.h"
#include "emit/emit_context.h"
#include "emit/glsl_rewrite.h"

namespace arbiter::arbvp {
namespace emit {
namespace {

constexpr DialectRow kTargetRows[] = {
// DialectRow lists the columns in the table's order.
#define ARBVP_EMIT_TARGET(name, ...) {EmitTarget::name, __VA_ARGS__},
#include "arbiter/arbvp/emit_targets.def"
#undef ARBVP_EMIT_TARGET
};

// The GLSL 1.30 overload for a GLSL 1.10 lookup function ("texture2DProjLod" ->
// "textureProjLod"), and whether it is a shadow lookup; "" for other identifiers.
std::string ModernLookup(std::string_view name, bool* shadow) {
  static constexpr std::string_view kBases[] = {"texture2DRect", "shadow2DRect", "texture1D",
                                                "texture2D",     "texture3D",    "textureCube",
                                                "shadow1D",      "shadow2D"};
  for (std::string_view base : kBases) {
    if (name.substr(0, base.size()) != base) continue;
    std::string_view rest = name.substr(base.size());
    if (rest.size() >= 3 && rest.substr(rest.size() - 3) == "ARB") {
      rest.remove_suffix(3);  // textureGradARB: textureGrad
    }
    static constexpr std::string_view kForms[] = {"", "Proj", "Lod", "ProjLod", "Grad", "ProjGrad"};
    if (std::find(std::begin(kForms), std::end(kForms), rest) == std::end(kForms)) continue;
    *shadow = base.substr(0, 6) == "shadow";
    return "texture" + std::string(rest);
  }
  return "";
}

// The GLSL 1.30 lookups: texture2D(...) -> texture(...); a shadow lookup returns a float
// there and a vec4 in GLSL 1.10, expanded by the texture's GL_DEPTH_TEXTURE_MODE, which these
// targets read from a uniform (glstate::DepthModeSelector; the reference interpreter assumes
// LUMINANCE, GL's default): shadow2D(arb_textureN, ...) ->
// arb_shadow(texture(arb_textureN, ...), arb_textureN_depthmode).
std::string ModernLookups(const std::string& text, bool* used_shadow) {
  return ReplaceIdentifiers(
      text, [&](const std::string& word, const std::string& all, size_t* at) -> std::string {
        bool shadow = false;
        std::string modern = ModernLookup(word, &shadow);
        if (modern.empty() || *at >= all.size() || all[*at] != '(') return word;
        if (!shadow) return modern;
        // Copy the arguments up to the matching parenthesis, rewritten themselves.
        size_t depth = 0;
        size_t end = *at;
        for (; end < all.size(); ++end) {
          if (all[end] == '(') ++depth;
          if (all[end] == ')' && --depth == 0) break;
        }
        std::string args = ModernLookups(all.substr(*at, end + 1 - *at), used_shadow);
        *at = end + 1;
        *used_shadow = true;
        const std::string sampler = args.substr(1, args.find_first_of(", )") - 1);
        return "arb_shadow(" + modern + args + ", " + sampler + "_depthmode)";
      });
}

bool HasIdentifier(const std::string& text, std::string_view name) {
  bool found = false;
  (void)ReplaceIdentifiers(text, [&](const std::string& word, const std::string&, size_t*) {
    if (word == name) found = true;
    return word;
  });
  return found;
}

// Whether `text` calls a GLSL 1.10 lookup at an explicit level (texture2DLod, ...).
bool UsesLodLookup(const std::string& text) {
  bool found = false;
  (void)ReplaceIdentifiers(text, [&](const std::string& word, const std::string&, size_t*) {
    bool shadow = false;
    if (word.find("Lod") != std::string::npos && !ModernLookup(word, &shadow).empty()) {
      found = true;
    }
    return word;
  });
  return found;
}

}  // namespace

const DialectRow& GetDialectRow(EmitTarget target) {
  return kTargetRows[static_cast<size_t>(target)];
}

std::string FinishForTarget(const Context& ctx, std::string text) {
  const DialectRow& row = ctx.target;
  if (row.id == EmitTarget::Glsl110) return text;
  std::string extensions;
  if (row.id == EmitTarget::Glsl120 && ctx.IsVertex() && !ctx.needs_texture_lod &&
      UsesLodLookup(text)) {
    // GLSL 1.20 has the Lod lookups in vertex shaders; glslang asks for the extension that
    // brought them to fragment shaders too. `enable` does not fail without it.
    extensions += "#extension GL_ARB_shader_texture_lod : enable\n";
  }
  text = EmulateSamplers(row, text);
  if (row.modern) {
    bool shadow = false;
    text = ModernLookups(text, &shadow);
    if (shadow) {
      const size_t main = text.find("\nvoid main() {\n");
      text.insert(main + 1,
                  "// A shadow lookup as GLSL 1.10's: r expanded by GL_DEPTH_TEXTURE_MODE, each\n"
                  "// component 0, r or 1 as the mode's selector reads 0, 1 or 2.\n"
                  "float arb_depth_mode(float r, float m) {\n"
                  "  return m == 1.0 ? r : (m == 2.0 ? 1.0 : 0.0);\n"
                  "}\n"
                  "vec4 arb_shadow(float r, vec4 mode) {\n"
                  "  return vec4(arb_depth_mode(r, mode.x), arb_depth_mode(r, mode.y),\n"
                  "              arb_depth_mode(r, mode.z), arb_depth_mode(r, mode.w));\n"
                  "}\n\n");
    }
  }
  if (row.id == EmitTarget::Es100 && !ctx.IsVertex()) {
    if (HasIdentifier(text, "gl_FragDepth")) {
      text = ReplaceIdentifiers(text, [](const std::string& word, const std::string&, size_t*) {
        return word == "gl_FragDepth" ? std::string("gl_FragDepthEXT") : word;
      });
      extensions += "#extension GL_EXT_frag_depth : require\n";
    }
    if (HasIdentifier(text, "dFdx") || HasIdentifier(text, "dFdy") ||
        HasIdentifier(text, "fwidth")) {
      extensions += "#extension GL_OES_standard_derivatives : require\n";
    }
  }
  const size_t first_line = text.find('\n') + 1;
  text.insert(first_line, extensions);
  if (row.es) {
    // Exact ARB arithmetic needs IEEE single precision: highp float and int. ES 1.00 fragment
    // shaders have highp only where GL_FRAGMENT_PRECISION_HIGH is defined; without it the
    // translation does not compile rather than run at a lower precision.
    std::string precision = "precision highp float;\nprecision highp int;\n";
    if (row.id == EmitTarget::Es100 && !ctx.IsVertex()) {
      precision =
          "#ifdef GL_FRAGMENT_PRECISION_HIGH\n" + precision +
          "#else\n#error \"arbiter: exact ARB arithmetic needs highp floats in fragment shaders\"\n"
          "#endif\n";
    }
    // After the header lines (#version, #extension, the leading comments).
    size_t blank = text.find("\n\n");
    if (blank == std::string::npos) blank = text.size() - 1;
    text.insert(blank + 1, "\n" + precision);
  }
  return text;
}

bool IsReservedLater(std::string_view name) {
  static constexpr std::string_view kWords[] = {
      // Keywords and reserved words of GLSL 1.20 to 4.50 and GLSL ES 1.00 and 3.00.
      "active", "atomic_uint", "buffer", "case", "cast", "centroid", "coherent", "common", "filter",
      "flat", "highp", "invariant", "layout", "lowp", "mediump", "namespace", "noperspective",
      "partition", "patch", "precise", "precision", "readonly", "resource", "restrict", "sample",
      "shared", "sizeof", "smooth", "subroutine", "superp", "uint", "using", "writeonly", "input",
      "output", "row_major", "lowp", "dmat2", "dmat3", "dmat4",
      // The GLSL 1.30 lookups the translation calls, and the helpers of later dialects.
      "texture", "textureProj", "textureLod", "textureProjLod", "textureGrad", "textureProjGrad",
      "transpose", "inverse", "round", "trunc", "determinant", "isnan", "isinf"};
  for (std::string_view w : kWords) {
    if (name == w) return true;
  }
  // Types: matNxM, [iu]vecN, dvecN, and every [iu]sampler* and [iu]image*.
  auto starts = [&](std::string_view prefix) { return name.substr(0, prefix.size()) == prefix; };
  for (std::string_view prefix : {"mat2x", "mat3x", "mat4x", "dmat", "uvec", "dvec", "sampler",
                                  "isampler", "usampler", "image", "iimage", "uimage"}) {
    if (starts(prefix)) return true;
  }
  return false;
}

}  // namespace emit

std::string_view EmitTargetName(EmitTarget target) { return emit::GetDialectRow(target).spelling; }

std::string_view EmitTargetTitle(EmitTarget target) { return emit::GetDialectRow(target).title; }

bool LookupEmitTarget(std::string_view name, EmitTarget* target) {
  for (const emit::DialectRow& row : emit::kTargetRows) {
    if (row.spelling != name) continue;
    *target = row.id;
    return true;
  }
  return false;
}

bool UsesStateUniforms(const EmitOptions& options) {
  return options.state == StateSource::Uniforms || emit::GetDialectRow(options.target).uniforms;
}

namespace {

bool IsFragPosition(const Binding& b) {
  return b.kind == BindingKind::FragmentAttrib && b.fragment_attrib == FragmentAttrib::Position;
}

bool IsExtraColor(const Binding& b) {
  return b.kind == BindingKind::Result && b.result == ResultReg::FragColor && b.index > 0;
}

// The first binding of variable `var` that `test` holds for.
template <typename F>
bool AnyBinding(const Program& p, int var, F test) {
  if (var < 0 || static_cast<size_t>(var) >= p.vars.size()) return false;
  const std::vector<Binding>& bindings = p.vars[static_cast<size_t>(var)].bindings;
  return std::any_of(bindings.begin(), bindings.end(), test);
}

// "<construct>: <dialect> has <what it lacks>".
std::string Refusal(const emit::DialectRow& row, std::string_view construct, std::string_view has) {
  return fmt::format("{}: {} has {}", construct, row.title, has);
}

}  // namespace

Untranslatable FindUntranslatable(const Program& program, const EmitOptions& options) {
  Untranslatable base = FindUntranslatable(program);
  const emit::DialectRow& row = emit::GetDialectRow(options.target);
  if (row.id == EmitTarget::Glsl110) return base;
  if (!base.what.empty() && !row.modern) {
    // The bits of a float: floatBitsToUint (GLSL 3.30, ES 3.00, Vulkan).
    const std::string op = base.what.substr(0, base.what.find(' '));
    return {fmt::format("{} needs the bits of a float, which {} cannot form (floatBitsToUint: "
                        "GLSL 3.30 and ES 3.00)",
                        op, row.title),
            base.range};
  }
  // With state as uniforms the conventions are emulated (state_uniforms.cpp, FragPosition).
  const bool uniforms = UsesStateUniforms(options);
  for (const Option& o : program.options) {
    if (!row.coord_conventions && !uniforms &&
        (o.id == OptionId::OriginUpperLeft || o.id == OptionId::PixelCenterInteger)) {
      return {Refusal(row, fmt::format("OPTION {}", GetOptionInfo(o.id).spelling),
                      "no gl_FragCoord layout qualifiers"),
              o.range};
    }
  }
  const bool fragment = program.kind == ProgramKind::Fragment;
  for (const Instruction& inst : program.instructions) {
    const OpcodeInfo& info = GetOpcodeInfo(inst.op);
    const bool sample =
        info.signature == OpSignature::Sample || info.signature == OpSignature::TexD;
    if (sample) {
      bool has = true;
      // 1D textures are 2D ones of height 1 where the dialect lacks them, rectangle ones 2D
      // ones read through textureSize (sampler_emulation.cpp), so the dialect needs 2D
      // shadow samplers for their shadow forms, and textureSize for rectangles.
      switch (inst.target) {
        case TexTarget::Tex3D:
          has = row.tex3d;
          break;
        case TexTarget::Rect:
          has = row.rect || row.modern;
          break;
        case TexTarget::Shadow1D:
          has = row.shadow1d || row.shadow;
          break;
        case TexTarget::Shadow2D:
          has = row.shadow;
          break;
        case TexTarget::ShadowRect:
          has = (row.rect || row.modern) && row.shadow;
          break;
        default:
          break;
      }
      if (!has) {
        return {
            Refusal(row, fmt::format("{} of a {} texture", info.name, TexTargetName(inst.target)),
                    fmt::format("no {} samplers", TexTargetName(inst.target))),
            inst.target_range};
      }
      const bool level = inst.op == Opcode::TXL || inst.op == Opcode::TXD;
      if (fragment && level && row.fragment_lod.empty()) {
        return {Refusal(row, info.name, "no explicit level of detail in fragment shaders"),
                inst.opcode_range};
      }
    }
    if (!row.loops && info.signature != OpSignature::If && info.klass == OpClass::Flow &&
        inst.op != Opcode::ELSE && inst.op != Opcode::ENDIF) {
      return {
          Refusal(row, info.name, "only for loops with constant bounds (Appendix A), no branches"),
          inst.opcode_range};
    }
    if (!row.draw_buffers && AnyBinding(program, inst.dst.var, IsExtraColor)) {
      return {Refusal(row, "result.color[n] with n > 0", "one colour output"), inst.dst.range};
    }
    for (int i = 0; !row.frag_coord_highp && i < inst.src_count; ++i) {
      const SrcOperand& s = inst.src[static_cast<size_t>(i)];
      if (AnyBinding(program, s.var, IsFragPosition)) {
        return {Refusal(row, "fragment.position",
                        "a mediump gl_FragCoord (section 7.2), not the window position to float "
                        "precision"),
                s.range};
      }
    }
  }
  return {};
}

}  // namespace arbiter::arbvp
