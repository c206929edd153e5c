// State as uniforms (emit_target.h): every state.* binding a uniform named after its ARB
// spelling (matrices one mat4 each), vertex attributes inputs with locations, results and
// fragment attributes named varyings, fragment colours declared outputs; for Vulkan the
// uniforms in one std140 block per stage (docs/guide/translate.md "State as uniforms").
#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "emit/emit_context.h"
#include "emit/emit_target.h"

namespace arbiter::arbvp::emit {
namespace {

// Vulkan descriptor bindings in set 0: the vertex block, the fragment block, then one combined
// image sampler per texture unit.
constexpr int kVertexBlockBinding = 0;
constexpr int kFragmentBlockBinding = 1;
constexpr int kFirstSamplerBinding = 2;

Expr Input(Context& ctx, const Binding& b, const std::string& name, int location) {
  // vertex.attrib[0] is vertex.position (one input; a program binds only one of them, but a
  // relatively addressed attribute array covers attribute 0 too).
  ctx.attribs.emplace(name, AttributeBinding{name, location, BindingName(b, ctx.program.kind)});
  return {name, 4, true};
}

Expr Varying(Context& ctx, const std::string& name, const std::string& type) {
  ctx.varyings[name] = type;
  if (type == "float") {
    Expr e{fmt::format("vec4({}, 0.0, 0.0, 1.0)", name), 4, true};
    e.parts = {name, "0.0", "0.0", "1.0"};
    return e;
  }
  return {name, 4, true};
}

}  // namespace

std::string StateUniformName(std::string_view spelling) {
  std::string out = "arb_";
  for (char c : spelling) {
    const bool word = std::isalnum(static_cast<unsigned char>(c)) != 0;
    if (word) {
      out.push_back(c);
    } else if (c == '.' && out.back() != '_') {
      out.push_back('_');
    }
  }
  while (out.back() == '_') out.pop_back();
  return out;
}

Expr ReadStateUniform(Context& ctx, const Binding& b) {
  const std::string spelling = BindingName(b, ctx.program.kind);
  const std::string name = StateUniformName(spelling);
  ctx.state[name] = StateUniform{name, "vec4", spelling};
  return {name, 4, true};
}

// ARB_vertex_program's aliasing of conventional and generic attributes (table X.2.2, as
// NV_vertex_program aliases them): a program may not bind both, so one location each.
Expr VertexInput(Context& ctx, const Binding& b) {
  const int n = b.index;
  switch (b.vertex_attrib) {
    case VertexAttrib::Position:
      return Input(ctx, b, "arb_vertex_position", 0);
    case VertexAttrib::Weight:
      return Input(ctx, b, fmt::format("arb_vertex_weight{}", n), n == 0 ? 1 : -1);
    case VertexAttrib::Normal: {  // (x, y, z, 1) whatever the host feeds as w
      Input(ctx, b, "arb_vertex_normal", 2);
      Expr e{"vec4(arb_vertex_normal.xyz, 1.0)", 4, true};
      e.parts = {"arb_vertex_normal.x", "arb_vertex_normal.y", "arb_vertex_normal.z", "1.0"};
      e.xyz = "arb_vertex_normal.xyz";
      return e;
    }
    case VertexAttrib::Color:
      return Input(ctx, b, "arb_vertex_color", 3);
    case VertexAttrib::SecondaryColor:
      return Input(ctx, b, "arb_vertex_color1", 4);
    case VertexAttrib::FogCoord: {  // (f, 0, 0, 1)
      Input(ctx, b, "arb_vertex_fogcoord", 5);
      Expr e{"vec4(arb_vertex_fogcoord.x, 0.0, 0.0, 1.0)", 4, true};
      e.parts = {"arb_vertex_fogcoord.x", "0.0", "0.0", "1.0"};
      return e;
    }
    case VertexAttrib::TexCoord:
      return Input(ctx, b, fmt::format("arb_vertex_texcoord{}", n), 8 + n);
    case VertexAttrib::MatrixIndex:
      return Input(ctx, b, fmt::format("arb_vertex_matrixindex{}", n), -1);
    case VertexAttrib::Generic:
      if (n == 0) return Input(ctx, b, "arb_vertex_position", 0);
      return Input(ctx, b, fmt::format("arb_vertex_attrib{}", n), n);
  }
  return {"vec4(0.0)", 4, true};
}

// fragment.position where the dialect's gl_FragCoord differs from it (emit_targets.def,
// frag_position and coord_conventions): y counted from the other edge is the framebuffer's
// height minus y, and integer pixel centres are half a pixel lower. Both are exact (the
// coordinates are halves of integers). False where gl_FragCoord (with its layout) is it.
bool FragPosition(Context& ctx, Expr* out) {
  const DialectRow& row = ctx.target;
  const bool upper = ctx.program.HasOption(OptionId::OriginUpperLeft);
  const bool integer = ctx.program.HasOption(OptionId::PixelCenterInteger);
  if (row.coord_conventions && row.frag_position) return false;
  const bool flip =
      upper == row.frag_position;  // the origin the program wants is not the dialect's
  if (!flip && !integer) return false;
  std::string x = "gl_FragCoord.x";
  std::string y = "gl_FragCoord.y";
  if (flip) {
    const std::string name = StateUniformName("framebuffer.height");
    ctx.state[name] = StateUniform{name, "vec4", "framebuffer.height"};
    y = fmt::format("({}.x - gl_FragCoord.y)", name);
  }
  if (integer) {
    x = fmt::format("({} - 0.5)", x);
    y = fmt::format("({} - 0.5)", y);
  }
  *out = Expr{fmt::format("vec4({}, {}, gl_FragCoord.zw)", x, y), 4, true};
  out->parts = {x, y, "gl_FragCoord.z", "gl_FragCoord.w"};
  return true;
}

bool FragmentInput(Context& ctx, const Binding& b, Expr* out) {
  switch (b.fragment_attrib) {
    case FragmentAttrib::Color:
      *out = Varying(ctx, "arb_color0", "vec4");
      return true;
    case FragmentAttrib::SecondaryColor:
      *out = Varying(ctx, "arb_color1", "vec4");
      return true;
    case FragmentAttrib::TexCoord:
      *out = Varying(ctx, fmt::format("arb_texcoord{}", b.index), "vec4");
      return true;
    case FragmentAttrib::FogCoord:
      *out = Varying(ctx, "arb_fogcoord", "float");
      return true;
    case FragmentAttrib::Position:
      return FragPosition(ctx, out);
    case FragmentAttrib::Facing:
      return false;
  }
  return false;
}

bool ResultOutput(Context& ctx, const Binding& b, DestTarget* out) {
  std::string name;
  switch (b.result) {
    case ResultReg::Color:
      name = fmt::format("arb_{}color{}", b.face == Face::Back ? "b" : "", b.secondary ? 1 : 0);
      ctx.vertex_colors.insert(name);
      break;
    case ResultReg::FogCoord:
      ctx.varyings["arb_fogcoord"] = "float";
      *out = {"arb_fogcoord", 0};
      return true;
    case ResultReg::TexCoord:
      name = fmt::format("arb_texcoord{}", b.index);
      break;
    default:
      return false;
  }
  ctx.varyings[name] = "vec4";
  *out = {name, -1};
  return true;
}

std::string FogField(Context& ctx, std::string_view field) {
  if (!ctx.uniforms) {
    if (field == "coord") return "gl_FogFragCoord";
    return fmt::format("gl_Fog.{}", field);
  }
  if (field == "coord") {
    ctx.varyings["arb_fogcoord"] = "float";
    return "arb_fogcoord";
  }
  if (field == "color") {
    ctx.state["arb_state_fog_color"] =
        StateUniform{"arb_state_fog_color", "vec4", "state.fog.color"};
    return "arb_state_fog_color";
  }
  // state.fog.params: (density, start, end, 1 / (end - start)).
  ctx.state["arb_state_fog_params"] =
      StateUniform{"arb_state_fog_params", "vec4", "state.fog.params"};
  return fmt::format("arb_state_fog_params.{}", field == "density" ? "x"
                                                : field == "start" ? "y"
                                                                   : "z");
}

std::string UniformsEpilogue(const Context& ctx) {
  std::string out;
  for (const std::string& name : ctx.vertex_colors) {
    out += fmt::format("{0} = clamp({0}, 0.0, 1.0);  // GL clamps the vertex colours\n", name);
  }
  return out;
}

std::string InvariantPosition(Context& ctx) {
  Binding position;
  position.kind = BindingKind::VertexAttrib;
  position.vertex_attrib = VertexAttrib::Position;
  const std::string p = ReadBinding(ctx, position).text;
  // Reading a row declares the matrix's uniform (MatrixRow names it arb_matrix_mvp0).
  Binding row;
  row.kind = BindingKind::State;
  row.state = StateItem::MatrixRow;
  row.matrix = MatrixName::Mvp;
  (void)ReadBinding(ctx, row);
  std::string out =
      fmt::format("gl_Position = arb_matrix_mvp0 * {};  // OPTION ARB_position_invariant\n", p);
  const std::string_view mode = ctx.target.clip_planes;
  if (mode.empty()) return out;
  // User clip planes clip as without a program (ARB_vertex_program 2.11): by the eye-space
  // position. GLSL 1.10 guarantees six planes. Where the dialect has no enable, the enable
  // is a uniform (clip[n].enabled): a disabled plane's distance is 0 (Vulkan) or 1 (the
  // discard of GLSL ES), which never clips.
  row.matrix = MatrixName::Modelview;
  (void)ReadBinding(ctx, row);
  out += fmt::format("vec4 arb_eye_position = arb_matrix_modelview0 * {};\n", p);
  std::vector<std::string> distances;
  for (int n = 0; n < kGlslClipPlanes; ++n) {
    Binding plane;
    plane.kind = BindingKind::State;
    plane.state = StateItem::ClipPlane;
    plane.index = n;
    std::string d = fmt::format("dot({}, arb_eye_position)", ReadStateUniform(ctx, plane).text);
    if (mode != "distance") {
      const std::string enabled = fmt::format("clip[{}].enabled", n);
      const std::string name = StateUniformName(enabled);
      ctx.state[name] = StateUniform{name, "vec4", enabled};
      d = fmt::format("({}.x != 0.0 ? {} : {})", name, d, mode == "enabled" ? "0.0" : "1.0");
    }
    distances.push_back(d);
  }
  if (mode != "discard") {
    for (int n = 0; n < kGlslClipPlanes; ++n) {
      out += fmt::format("gl_ClipDistance[{}] = {};\n", n, distances[static_cast<size_t>(n)]);
    }
    return out;
  }
  ctx.varyings[kClipVaryings[0]] = "vec4";
  ctx.varyings[kClipVaryings[1]] = "vec2";
  out += fmt::format("{} = vec4({}, {}, {}, {});\n", kClipVaryings[0], distances[0], distances[1],
                     distances[2], distances[3]);
  out += fmt::format("{} = vec2({}, {});\n", kClipVaryings[1], distances[4], distances[5]);
  return out;
}

std::string ClipDiscard(Context& ctx) {
  ctx.varyings[kClipVaryings[0]] = "vec4";
  ctx.varyings[kClipVaryings[1]] = "vec2";
  return fmt::format(
      "// The vertex program's user clip planes (OPTION ARB_position_invariant): GLSL ES has\n"
      "// no clip distances, so a fragment on the clipped side is discarded.\n"
      "if (any(lessThan({}, vec4(0.0))) || any(lessThan({}, vec2(0.0)))) discard;\n",
      kClipVaryings[0], kClipVaryings[1]);
}

int VaryingLocation(std::string_view name) {
  // Colours 0-3, the fog coordinate 4, texture coordinates 0-7 at 5-12, clip distances 0-7
  // at 13-20, texture coordinates 8 and up from 21.
  static constexpr std::pair<std::string_view, int> kFixed[] = {{"arb_color0", 0},
                                                                {"arb_color1", 1},
                                                                {"arb_bcolor0", 2},
                                                                {"arb_bcolor1", 3},
                                                                {"arb_fogcoord", 4}};
  for (const auto& [n, l] : kFixed) {
    if (n == name) return l;
  }
  auto suffix = [&](std::string_view prefix) {
    return name.substr(0, prefix.size()) == prefix
               ? std::stoi(std::string(name.substr(prefix.size())))
               : -1;
  };
  if (int n = suffix("arb_texcoord"); n >= 0) return n < 8 ? 5 + n : 21 + (n - 8);
  if (int n = suffix("arb_clip_distance"); n >= 0) return 13 + n;
  return -1;
}

std::string UniformsDeclarations(Context& ctx) {
  const DialectRow& row = ctx.target;
  const bool vertex = ctx.IsVertex();
  std::string out;
  // Attributes: the locations ARB aliasing leaves open go to the others, lowest first.
  std::set<int> used;
  for (const auto& [name, a] : ctx.attribs) {
    if (a.location >= 0) used.insert(a.location);
  }
  for (auto& [name, a] : ctx.attribs) {
    if (a.location >= 0) continue;
    int l = 0;
    while (used.count(l)) ++l;
    a.location = l;
    used.insert(l);
  }
  std::vector<AttributeBinding> attribs;
  for (const auto& [name, a] : ctx.attribs) attribs.push_back(a);
  std::stable_sort(attribs.begin(), attribs.end(),
                   [](const auto& a, const auto& b) { return a.location < b.location; });
  for (const AttributeBinding& a : attribs) {
    out += fmt::format("{}{} vec4 {};  // {}, location {}\n",
                       row.locations ? fmt::format("layout(location = {}) ", a.location) : "",
                       row.attribute, a.name, a.binding, a.location);
  }
  // Varyings (the pair's fragment inputs are declared by the vertex shader too).
  std::map<std::string, std::string> varyings = ctx.varyings;
  for (int n : ctx.clip_distances) varyings[fmt::format("arb_clip_distance{}", n)] = "float";
  if (vertex) {
    for (const auto& [name, type] : ctx.pair_varyings) varyings.emplace(name, type);
  }
  for (const auto& [name, type] : varyings) {
    std::string layout;
    if (row.block) layout = fmt::format("layout(location = {}) ", VaryingLocation(name));
    out +=
        fmt::format("{}{} {} {};\n", layout, vertex ? row.vertex_out : row.fragment_in, type, name);
  }
  // Uniforms. A shadow lookup of these targets reads its texture's GL_DEPTH_TEXTURE_MODE
  // (emit_target.cpp, arb_shadow).
  for (const auto& [unit, target] : ctx.samplers) {
    if (!TexTargetIsShadow(target) || !row.modern) continue;
    const std::string spelling = fmt::format("texture[{}].depthmode", unit);
    const std::string name = StateUniformName(spelling);
    ctx.state[name] = StateUniform{name, "vec4", spelling};
  }
  struct Member {
    std::string declaration;
    std::string name;
    int size;
  };
  std::vector<Member> members;
  for (bool local : {false, true}) {
    int size = local ? ctx.local_size : ctx.env_size;
    if (size == 0) continue;
    members.push_back(
        {fmt::format("vec4 {}[{}];  // program.{}[{}]", EnvName(ctx, local), size,
                     local ? "local" : "env", size == 1 ? "0" : fmt::format("0..{}", size - 1)),
         EnvName(ctx, local), 16 * size});
  }
  for (const auto& [name, s] : ctx.state) {
    members.push_back(
        {fmt::format("{} {};  // {}", s.type, name, s.binding), name, s.type == "mat4" ? 64 : 16});
  }
  if (row.block && !members.empty()) {
    out += fmt::format("layout(std140, set = 0, binding = {}) uniform Arb{}Uniforms {{\n",
                       vertex ? kVertexBlockBinding : kFragmentBlockBinding,
                       vertex ? "Vertex" : "Fragment");
    int offset = 0;
    for (const Member& m : members) {
      out += fmt::format("  {}  offset {}\n", m.declaration, offset);
      ctx.block_offsets[m.name] = offset;
      offset += m.size;
    }
    ctx.block_size = offset;
    out += "};\n";
  } else {
    for (const Member& m : members) out += "uniform " + m.declaration + "\n";
  }
  for (const auto& [unit, target] : ctx.samplers) {
    out += fmt::format(
        "{}uniform {}{} {};  // texture[{}], {}\n",
        row.block ? fmt::format("layout(set = 0, binding = {}) ", kFirstSamplerBinding + unit) : "",
        row.es ? "highp " : "", DialectSamplerType(row, target), SamplerName(unit), unit,
        TexTargetName(target));
  }
  // Fragment colours.
  if (row.outputs && !vertex) {
    std::set<std::string> colors;
    for (const auto& [binding, r] : ctx.outputs) {
      if (r.glsl.rfind("arb_fragcolor", 0) == 0) colors.insert(r.glsl);
    }
    for (const std::string& c : colors) {
      const std::string n = c.substr(std::string_view("arb_fragcolor").size());
      out += fmt::format("layout(location = {}) out vec4 {};  // result.color{}\n", n, c,
                         ctx.program.HasOption(OptionId::DrawBuffers) ? "[" + n + "]" : "");
    }
  }
  return out;
}

int SamplerBindingOf(const Context& ctx, int unit) {
  return ctx.target.block ? kFirstSamplerBinding + unit : -1;
}

int BlockBindingOf(const Context& ctx) {
  return ctx.IsVertex() ? kVertexBlockBinding : kFragmentBlockBinding;
}

}  // namespace arbiter::arbvp::emit
