// ARB bindings as GLSL 1.10: attributes, state (built-ins, rebuilt where ARB packs state
// differently), program parameters, and the results a program writes.
#include <fmt/format.h>

#include "emit/emit_context.h"

namespace arbiter::arbvp::emit {
namespace {

// gl_MultiTexCoord0..7 are the only texture-coordinate attributes GLSL 1.10 names.
constexpr int kGlslMultiTexCoords = 8;

// vec4(xyz, w) with its parts known.
Expr Vec3W(const std::string& xyz, const std::string& w) {
  Expr e{fmt::format("vec4({}, {})", xyz, w), 4, true};
  e.parts = {xyz + ".x", xyz + ".y", xyz + ".z", w};
  e.xyz = xyz;
  return e;
}

// vec4(a, b, c, d) of four float fields.
Expr Fields(const std::string& a, const std::string& b, const std::string& c,
            const std::string& d) {
  Expr e{fmt::format("vec4({}, {}, {}, {})", a, b, c, d), 4, true};
  e.parts = {a, b, c, d};
  return e;
}

Expr UserAttribute(Context& ctx, const Binding& b, const std::string& name, int location) {
  ctx.attribs[name] = AttributeBinding{name, location, BindingName(b, ctx.program.kind)};
  return {name, 4, true};
}

Expr StateUniformVec4(Context& ctx, const Binding& b, const std::string& name) {
  ctx.state[name] = StateUniform{name, "vec4", BindingName(b, ctx.program.kind)};
  return {name, 4, true};
}

std::string Face(const Binding& b, const char* front, const char* back) {
  return b.face == Face::Back ? back : front;
}

// The built-in matrix for a matrix binding, or "" when GLSL 1.10 has none.
std::string BuiltinMatrix(const Binding& b) {
  if (b.matrix == MatrixName::Modelview && b.index != 0) return "";  // vertex blending
  return std::string(glstate::GetStateMatrixInfo(b.matrix).glsl);
}

std::string_view ModifierSuffix(MatrixModifier m) {
  switch (m) {
    case MatrixModifier::None:
      return "";
    case MatrixModifier::Inverse:
      return "Inverse";
    case MatrixModifier::Transpose:
      return "Transpose";
    case MatrixModifier::InvTrans:
      return "InverseTranspose";
  }
  return "";
}

// Row r of an ARB matrix binding. ARB reads ROWS, GLSL indexes COLUMNS: row r of M is
// column r of transpose(M), so for built-ins we index the transposed built-in
// (gl_ModelViewMatrixTranspose[r] is row r of the modelview matrix); for a matrix held in a
// uniform, row r is vec4(M[0][r], M[1][r], M[2][r], M[3][r]).
Expr MatrixRow(Context& ctx, const Binding& b) {
  bool swap = ctx.Mutated(Mutation::MatrixRowsColumns);
  int r = b.row;
  std::string builtin = ctx.uniforms ? "" : BuiltinMatrix(b);
  if (!builtin.empty()) {
    // The built-in whose column r is the wanted row: transpose of (M with modifier).
    MatrixModifier column_of = MatrixModifier::None;
    switch (b.modifier) {
      case MatrixModifier::None:
        column_of = MatrixModifier::Transpose;
        break;
      case MatrixModifier::Inverse:
        column_of = MatrixModifier::InvTrans;
        break;
      case MatrixModifier::Transpose:
        column_of = MatrixModifier::None;
        break;
      case MatrixModifier::InvTrans:
        column_of = MatrixModifier::Inverse;
        break;
    }
    if (swap) column_of = b.modifier;
    std::string m = builtin + std::string(ModifierSuffix(column_of));
    if (b.matrix == MatrixName::Texture) m += fmt::format("[{}]", b.index);
    return {fmt::format("{}[{}]", m, r), 4, true};
  }
  // A uniform holding M (for no modifier and .transpose) or inverse(M) (.inverse and
  // .invtrans), as GL stores matrices (column-major).
  bool inverse = b.modifier == MatrixModifier::Inverse || b.modifier == MatrixModifier::InvTrans;
  bool transposed =
      b.modifier == MatrixModifier::Transpose || b.modifier == MatrixModifier::InvTrans;
  std::string_view kind = glstate::GetStateMatrixInfo(b.matrix).word;
  std::string name = fmt::format("arb_matrix_{}{}{}", kind, b.index, inverse ? "_inverse" : "");
  Binding whole = b;
  whole.modifier = inverse ? MatrixModifier::Inverse : MatrixModifier::None;
  std::string spelled = BindingName(whole, ctx.program.kind);
  spelled = spelled.substr(0, spelled.rfind(".row["));
  ctx.state[name] = StateUniform{name, "mat4", spelled};
  if (transposed != swap) return {fmt::format("{}[{}]", name, r), 4, true};
  return {fmt::format("vec4({0}[0][{1}], {0}[1][{1}], {0}[2][{1}], {0}[3][{1}])", name, r), 4,
          true};
}

// The text of a state item's GLSL pattern (state_items.def) for binding b.
std::string StatePattern(std::string_view pattern, const Binding& b) {
  std::string out;
  for (size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '$' || i + 1 == pattern.size()) {
      out.push_back(pattern[i]);
      continue;
    }
    switch (pattern[++i]) {
      case 'm':
        out += Face(b, "gl_FrontMaterial", "gl_BackMaterial");
        break;
      case 'F':
        out += Face(b, "Front", "Back");
        break;
      case 'l':
        out += fmt::format("gl_LightSource[{}]", b.index);
        break;
      case 'n':
        out += fmt::format("{}", b.index);
        break;
      case 'C':
        out.push_back("STRQ"[b.coord & 3]);
        break;
    }
  }
  return out;
}

// A state binding in GLSL 1.10 built-ins, from its row of state_items.def: one vec4, or its
// parts ("xyz|w", "x|y|z|w") so that reading a component stays short.
Expr ReadState(Context& ctx, const Binding& b) {
  if (b.state == StateItem::MatrixRow) return MatrixRow(ctx, b);
  if (ctx.uniforms) return ReadStateUniform(ctx, b);
  if (b.state == StateItem::ClipPlane && b.index >= kGlslClipPlanes) {
    return StateUniformVec4(ctx, b, fmt::format("arb_clip_plane{}", b.index));
  }
  if (b.state == StateItem::LightHalf) ctx.helpers.insert(Helper::Half);
  const std::string text = StatePattern(glstate::GetStateItemInfo(b.state).glsl, b);
  std::vector<std::string> parts;
  for (size_t begin = 0;;) {
    const size_t bar = text.find('|', begin);
    parts.push_back(text.substr(begin, bar - begin));
    if (bar == std::string::npos) break;
    begin = bar + 1;
  }
  if (parts.size() == 4) return Fields(parts[0], parts[1], parts[2], parts[3]);
  if (parts.size() == 2) return Vec3W(parts[0], parts[1]);
  return {text, 4, true};
}

Expr ReadVertexAttrib(Context& ctx, const Binding& b) {
  if (ctx.uniforms) return VertexInput(ctx, b);
  const int n = b.index;
  auto e = [](std::string text) { return Expr{std::move(text), 4, true}; };
  switch (b.vertex_attrib) {
    case VertexAttrib::Position:
      return e("gl_Vertex");
    case VertexAttrib::Weight:  // ARB_vertex_blend: weight[0] aliases generic attribute 1
      return UserAttribute(ctx, b, fmt::format("arb_weight{}", n), n == 0 ? 1 : -1);
    case VertexAttrib::Normal:  // (x, y, z, 1)
      return Vec3W("gl_Normal", "1.0");
    case VertexAttrib::Color:
      return e("gl_Color");
    case VertexAttrib::SecondaryColor:
      return e("gl_SecondaryColor");
    case VertexAttrib::FogCoord:  // (f, 0, 0, 1)
      return Fields("gl_FogCoord", "0.0", "0.0", "1.0");
    case VertexAttrib::TexCoord:
      if (n >= kGlslMultiTexCoords)
        return UserAttribute(ctx, b, fmt::format("arb_texcoord{}", n), -1);
      return e(fmt::format("gl_MultiTexCoord{}", n));
    case VertexAttrib::MatrixIndex:
      return UserAttribute(ctx, b, fmt::format("arb_matrixindex{}", n), -1);
    case VertexAttrib::Generic:  // attribute 0 is the vertex position (GL 2.0 2.7)
      if (n == 0) return e("gl_Vertex");
      return UserAttribute(ctx, b, fmt::format("arb_attrib{}", n), n);
  }
  return e("vec4(0.0)");
}

Expr ReadFragmentAttrib(Context& ctx, const Binding& b) {
  auto e = [](std::string text) { return Expr{std::move(text), 4, true}; };
  if (Expr input; ctx.uniforms && FragmentInput(ctx, b, &input)) return input;
  switch (b.fragment_attrib) {
    case FragmentAttrib::Color:
      return e("gl_Color");
    case FragmentAttrib::SecondaryColor:
      return e("gl_SecondaryColor");
    case FragmentAttrib::TexCoord:
      ctx.texcoord_size = std::max(ctx.texcoord_size, b.index + 1);
      return e(fmt::format("gl_TexCoord[{}]", b.index));
    case FragmentAttrib::FogCoord:  // (f, 0, 0, 1)
      return Fields("gl_FogFragCoord", "0.0", "0.0", "1.0");
    case FragmentAttrib::Position:  // (x, y, z, 1/w) in both
      return e("gl_FragCoord");
    case FragmentAttrib::Facing:  // (+1 front or -1 back, 0, 0, 1)
      return Fields("(gl_FrontFacing ? 1.0 : -1.0)", "0.0", "0.0", "1.0");
  }
  return e("vec4(0.0)");
}

}  // namespace

std::string EnvName(const Context& ctx, bool local) {
  return fmt::format("arb_{}_{}", ctx.IsVertex() ? "vp" : "fp", local ? "local" : "env");
}

std::string FogColorName(const Context& ctx, int index) {
  if (!ctx.program.HasOption(OptionId::DrawBuffers)) return "arb_color";
  return fmt::format("arb_color{}", index);
}

// Without ARB_draw_buffers result.color is gl_FragColor (broadcast to every draw buffer);
// with it, result.color[n] is gl_FragData[n] (result.color is result.color[0]).
std::string FragColorName(const Context& ctx, int index) {
  if (ctx.target.outputs) return fmt::format("arb_fragcolor{}", index);
  if (!ctx.program.HasOption(OptionId::DrawBuffers)) return "gl_FragColor";
  return fmt::format("gl_FragData[{}]", index);
}

std::string SamplerName(int unit) { return fmt::format("arb_texture{}", unit); }

std::string SamplerType(TexTarget target) {
  static constexpr std::string_view kTypes[] = {
#define ARBVP_TEX_TARGET(name, spelling, coords, shadow, dim, grad, mipmaps, depth, sampler, ...) \
  sampler,
#include "arbiter/arbvp/texture_targets.def"
#undef ARBVP_TEX_TARGET
  };
  return std::string(kTypes[static_cast<size_t>(target)]);
}

Expr ReadBinding(Context& ctx, const Binding& b) {
  Expr out;
  switch (b.kind) {
    case BindingKind::VertexAttrib:
      out = ReadVertexAttrib(ctx, b);
      break;
    case BindingKind::FragmentAttrib:
      out = ReadFragmentAttrib(ctx, b);
      break;
    case BindingKind::State:
      return ReadState(ctx, b);
    case BindingKind::ProgramEnv:
    case BindingKind::ProgramLocal: {
      bool local = b.kind == BindingKind::ProgramLocal;
      int& size = local ? ctx.local_size : ctx.env_size;
      size = std::max(size, b.index + 1);
      return {fmt::format("{}[{}]", EnvName(ctx, local), b.index), 4, true};
    }
    case BindingKind::Constant: {
      std::vector<std::string> parts;
      for (float v : b.value) parts.push_back(FormatFloat(v));
      return Construct(parts);
    }
    case BindingKind::Result:
      return {"vec4(0.0)", 4, true};  // write-only: the checker rejects reads
  }
  std::string name = BindingName(b, ctx.program.kind);
  ctx.inputs[name] = RegisterMapping{name, out.text, ctx.program.kind};
  return out;
}

DestTarget ResultTarget(Context& ctx, const Binding& b) {
  DestTarget t;
  if (ctx.uniforms && ResultOutput(ctx, b, &t)) {
    const std::string name = BindingName(b, ctx.program.kind);
    ctx.outputs[name] = RegisterMapping{name, t.lvalue, ctx.program.kind};
    return t;
  }
  switch (b.result) {
    case ResultReg::Position:
      t.lvalue = "gl_Position";
      break;
    case ResultReg::Color:
      t.lvalue = b.face == Face::Back ? (b.secondary ? "gl_BackSecondaryColor" : "gl_BackColor")
                                      : (b.secondary ? "gl_FrontSecondaryColor" : "gl_FrontColor");
      break;
    case ResultReg::FogCoord:
      t = {"gl_FogFragCoord", 0};
      break;
    case ResultReg::PointSize:
      t = {"gl_PointSize", 0};
      break;
    case ResultReg::TexCoord:
      ctx.texcoord_size = std::max(ctx.texcoord_size, b.index + 1);
      t.lvalue = fmt::format("gl_TexCoord[{}]", b.index);
      break;
    case ResultReg::ClipDistance:
      // GLSL 1.10 has no clip distances (gl_ClipDistance is 1.30's): a varying of our own
      // (docs/guide/translate.md).
      ctx.clip_distances.insert(b.index);
      t = {fmt::format("arb_clip_distance{}", b.index), 0};
      break;
    case ResultReg::FragColor:
      if (ctx.fog_redirect) {
        ctx.fog_colors.insert(b.index);
        t.lvalue = FogColorName(ctx, b.index);
      } else {
        t.lvalue = FragColorName(ctx, b.index);
      }
      break;
    case ResultReg::FragDepth:  // the depth is result.depth.z
      t = {"gl_FragDepth", 2};
      break;
  }
  std::string name = BindingName(b, ctx.program.kind);
  std::string glsl = t.lvalue;
  if (b.result == ResultReg::FragColor) glsl = FragColorName(ctx, b.index);
  ctx.outputs[name] = RegisterMapping{name, glsl, ctx.program.kind};
  return t;
}

}  // namespace arbiter::arbvp::emit
