// GLSL names for ARB variables: sanitised, never reserved, never a built-in, unique.
#include <set>
#include <string>
#include <string_view>

#include "emit/emit_context.h"

namespace arbiter::arbvp::emit {
namespace {

// GLSL 1.10 keywords (3.6), reserved words, and the built-in functions and types a local
// variable must not hide (8.x), plus main.
constexpr std::string_view kReserved[] = {
    "attribute", "const", "uniform", "varying", "break", "continue", "do", "for", "while", "if",
    "else", "in", "out", "inout", "float", "int", "void", "bool", "true", "false", "discard",
    "return", "mat2", "mat3", "mat4", "vec2", "vec3", "vec4", "ivec2", "ivec3", "ivec4", "bvec2",
    "bvec3", "bvec4", "sampler1D", "sampler2D", "sampler3D", "samplerCube", "sampler1DShadow",
    "sampler2DShadow", "struct", "asm", "class", "union", "enum", "typedef", "template", "this",
    "packed", "goto", "switch", "default", "inline", "noinline", "volatile", "public", "static",
    "extern", "external", "interface", "long", "short", "double", "half", "fixed", "unsigned",
    "input", "output", "hvec2", "hvec3", "hvec4", "dvec2", "dvec3", "dvec4", "fvec2", "fvec3",
    "fvec4", "sampler2DRect", "sampler3DRect", "sampler2DRectShadow", "sizeof", "cast", "namespace",
    "using", "lowp", "mediump", "highp", "precision", "invariant", "centroid", "flat", "smooth",
    "noperspective", "uint", "main",
    // built-in functions
    "radians", "degrees", "sin", "cos", "tan", "asin", "acos", "atan", "pow", "exp", "log", "exp2",
    "log2", "sqrt", "inversesqrt", "abs", "sign", "floor", "ceil", "fract", "mod", "min", "max",
    "clamp", "mix", "step", "smoothstep", "length", "distance", "dot", "cross", "normalize",
    "ftransform", "faceforward", "reflect", "refract", "matrixCompMult", "lessThan",
    "lessThanEqual", "greaterThan", "greaterThanEqual", "equal", "notEqual", "any", "all", "not",
    "texture1D", "texture1DProj", "texture1DLod", "texture1DProjLod", "texture2D", "texture2DProj",
    "texture2DLod", "texture2DProjLod", "texture3D", "texture3DProj", "texture3DLod",
    "texture3DProjLod", "textureCube", "textureCubeLod", "shadow1D", "shadow2D", "shadow1DProj",
    "shadow2DProj", "shadow1DLod", "shadow2DLod", "shadow1DProjLod", "shadow2DProjLod",
    "texture2DRect", "texture2DRectProj", "shadow2DRect", "shadow2DRectProj", "dFdx", "dFdy",
    "fwidth", "noise1", "noise2", "noise3", "noise4", "transpose", "inverse", "trunc", "round",
    "texture"};

bool IsReserved(const std::string& name) {
  for (std::string_view r : kReserved) {
    if (name == r) return true;
  }
  return false;
}

}  // namespace

// ARB identifiers are [A-Za-z_$][A-Za-z0-9_$]*. GLSL has no '$', reserves "gl_" prefixes and
// "__" anywhere, and our own generated names all start with "arb_".
std::string SanitizeName(const std::string& arb_name) {
  std::string out;
  for (char c : arb_name) {
    char g = c == '$' ? '_' : c;
    if (g == '_' && !out.empty() && out.back() == '_') continue;  // no "__"
    out += g;
  }
  // assign(1, c) and insert(0, s): GCC 12 at -O3 takes `out = "v"` and `"u_" + out` for an
  // overlapping copy (a false -Wrestrict in std::string).
  if (out.empty() || out == "_") out.assign(1, 'v');
  if (out.rfind("gl_", 0) == 0 || out.rfind("arb_", 0) == 0 || IsReserved(out)) {
    out.insert(0, "u_");
  }
  if (out.size() > 1 && out.back() == '_' && out[out.size() - 2] == '_') out.pop_back();
  return out;
}

void AssignNames(Context& ctx) {
  const Program& p = ctx.program;
  ctx.var_names.assign(p.vars.size(), "");
  ctx.relative.assign(p.vars.size(), false);
  for (const Instruction& inst : p.instructions) {
    for (int i = 0; i < inst.src_count; ++i) {
      const SrcOperand& s = inst.src[static_cast<size_t>(i)];
      if (s.relative && s.var >= 0) ctx.relative[static_cast<size_t>(s.var)] = true;
    }
  }
  std::set<std::string> taken;
  for (size_t i = 0; i < p.vars.size(); ++i) {
    const Variable& v = p.vars[i];
    bool named = v.kind == VarKind::Temp || v.kind == VarKind::Address ||
                 ((v.kind == VarKind::Param || v.kind == VarKind::Attrib) && ctx.relative[i]);
    if (!named) continue;
    std::string base = SanitizeName(!v.name.empty()             ? v.name
                                    : v.kind == VarKind::Attrib ? "attrib"
                                                                : "param");
    if (ctx.target.id != EmitTarget::Glsl110 && IsReservedLater(base)) base.insert(0, "u_");
    std::string name = base;
    for (int n = 2; taken.count(name); ++n) name = base + "_" + std::to_string(n);
    taken.insert(name);
    ctx.var_names[i] = name;
  }
}

}  // namespace arbiter::arbvp::emit
