// Samplers a dialect lacks, emulated exactly with 2D ones (docs/guide/translate.md,
// "Emulated samplers"):
// - a 1D texture (GLSL ES) is an N x 1 2D texture read at t = 0.5, the centre of its one row:
//   filtering, levels of detail (the derivatives of t are 0) and every level's width are the
//   1D texture's; a projective lookup passes t as 0.5 q, which the division makes 0.5;
// - a rectangle texture (GLSL ES 3.00, Vulkan) is a 2D texture without levels read at its
//   texel coordinates divided by textureSize, which the sampler multiplies back (derivatives
//   of a level choice too).
// The host uploads such textures as 2D textures: the binding map gives them a 2D sampler type
// beside their ARB target.
#include <fmt/format.h>

#include <string_view>

#include "emit/emit_context.h"
#include "emit/glsl_rewrite.h"

namespace arbiter::arbvp::emit {
namespace {

bool Emulates1D(const DialectRow& row) { return !row.tex1d; }
bool EmulatesRect(const DialectRow& row) { return !row.rect && row.modern; }

// The 2D lookup standing for a GLSL 1.10 1D or rectangle lookup `name` with arguments `a`
// (as the emitter writes them: 1D coordinates a float, shadow ones a vec3 with the reference
// in z, projective ones a vec4), or "" when `name` is none of them.
std::string Emulated(const DialectRow& row, const std::string& name,
                     const std::vector<std::string>& a) {
  auto is = [&](std::string_view base, std::string_view* form) {
    if (name.compare(0, base.size(), base) != 0) return false;
    *form = std::string_view(name).substr(base.size());
    return true;
  };
  auto rest = [&](size_t from) {
    std::string out;
    for (size_t i = from; i < a.size(); ++i) out += ", " + a[i];
    return out;
  };
  std::string_view form;
  if (Emulates1D(row) && (is("texture1D", &form) || is("shadow1D", &form))) {
    const bool shadow = name[0] == 's';
    const std::string f = std::string(shadow ? "shadow2D" : "texture2D") + std::string(form);
    const std::string& c = a[1];
    std::string coord;
    if (form.rfind("Proj", 0) == 0) {
      coord = fmt::format("vec4(({0}).x, 0.5 * ({0}).w, {1}, ({0}).w)", c,
                          shadow ? fmt::format("({}).z", c) : "0.0");
    } else if (shadow) {
      coord = fmt::format("vec3(({0}).x, 0.5, ({0}).z)", c);
    } else {
      coord = fmt::format("vec2({}, 0.5)", c);
    }
    if (form.find("Grad") != std::string_view::npos && a.size() == 4) {
      return fmt::format("{}({}, {}, vec2({}, 0.0), vec2({}, 0.0))", f, a[0], coord, a[2], a[3]);
    }
    return fmt::format("{}({}, {}{})", f, a[0], coord, rest(2));
  }
  if (EmulatesRect(row) && (is("texture2DRect", &form) || is("shadow2DRect", &form))) {
    const bool shadow = name[0] == 's';
    const std::string f = std::string(shadow ? "shadow2D" : "texture2D") + std::string(form);
    const std::string size = fmt::format("vec2(textureSize({}, 0))", a[0]);
    const std::string& c = a[1];
    std::string coord;
    if (form.rfind("Proj", 0) == 0) {
      coord = fmt::format("vec4(({}).xy / {}, ({}).zw)", c, size, c);
    } else if (shadow) {
      coord = fmt::format("vec3(({}).xy / {}, ({}).z)", c, size, c);
    } else {
      coord = fmt::format("({}) / {}", c, size);
    }
    if (form.find("Grad") != std::string_view::npos && a.size() == 4) {
      return fmt::format("{}({}, {}, ({}) / {}, ({}) / {})", f, a[0], coord, a[2], size, a[3],
                         size);
    }
    return fmt::format("{}({}, {}{})", f, a[0], coord, rest(2));
  }
  return "";
}

}  // namespace

std::string DialectSamplerType(const DialectRow& row, TexTarget target) {
  const bool one_d = target == TexTarget::Tex1D || target == TexTarget::Shadow1D;
  const bool rect = target == TexTarget::Rect || target == TexTarget::ShadowRect;
  if ((one_d && Emulates1D(row)) || (rect && EmulatesRect(row))) {
    return TexTargetIsShadow(target) ? "sampler2DShadow" : "sampler2D";
  }
  return SamplerType(target);
}

std::string EmulateSamplers(const DialectRow& row, const std::string& text) {
  if (!Emulates1D(row) && !EmulatesRect(row)) return text;
  return ReplaceIdentifiers(
      text, [&](const std::string& word, const std::string& all, size_t* at) -> std::string {
        std::vector<std::string> args;
        size_t close = 0;
        if (*at >= all.size() || all[*at] != '(' || !CallArguments(all, *at, &args, &close) ||
            args.size() < 2) {
          return word;
        }
        // The arguments may hold lookups themselves (relative addressing does not, but a
        // coordinate may be any expression).
        for (std::string& a : args) a = EmulateSamplers(row, a);
        std::string emulated = Emulated(row, word, args);
        if (emulated.empty()) return word;
        *at = close + 1;
        return emulated;
      });
}

}  // namespace arbiter::arbvp::emit
