// Whole translations: the shader text (header, declarations, helpers, main) and the binding
// map, for one program or for a vertex + fragment pair.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "arbiter/arbvp/emit.h"
#include "emit/emit_context.h"

namespace arbiter::arbvp {
namespace emit {
namespace {

std::string Indent(const std::string& lines) {
  std::string out;
  size_t start = 0;
  while (start < lines.size()) {
    size_t end = lines.find('\n', start);
    if (end == std::string::npos) end = lines.size();
    std::string line = lines.substr(start, end - start);
    out += (line.empty() ? "" : "  ") + line + "\n";
    start = end + 1;
  }
  return out;
}

// The fog blend of OPTION ARB_fog_*: ARBfp 3.11.4.5.1 applies GL fog (GL 2.0 section 3.10)
// to the program's final colour clamped to [0, 1]: C = mix(Cf, clamp(Cr), f) for r, g, b,
// alpha clamped, f clamped to [0, 1], c = fragment.fogcoord.x and Cf the fog colour
// (clamped, as GL clamps it when it is specified). With ARB_draw_buffers every
// result.color[n] is fogged, as the reference interpreter does.
std::string FogEpilogue(Context& ctx) {
  const std::string c = FogField(ctx, "coord");
  const std::string start = FogField(ctx, "start");
  const std::string end = FogField(ctx, "end");
  const std::string density = FogField(ctx, "density");
  const std::string fog_color = FogField(ctx, "color");
  std::string out;
  if (ctx.program.HasOption(OptionId::FogLinear)) {
    out += fmt::format("// OPTION ARB_fog_linear: f = (end - c) / (end - start), c = {}\n", c);
    out += ctx.Mutated(Mutation::FogLinearStartEnd)
               ? fmt::format("float arb_fog = clamp(({0} - {1}) / ({0} - {2}), 0.0, 1.0);\n", start,
                             c, end)
               : fmt::format("float arb_fog = clamp(({0} - {1}) / ({0} - {2}), 0.0, 1.0);\n", end,
                             c, start);
  } else if (ctx.program.HasOption(OptionId::FogExp) && !ctx.Mutated(Mutation::FogExpAsExp2)) {
    out += fmt::format("// OPTION ARB_fog_exp: f = exp(-density * c), c = {}\n", c);
    out += fmt::format("float arb_fog = clamp(exp(-({} * {})), 0.0, 1.0);\n", density, c);
  } else {
    out += fmt::format("// OPTION {}: f = exp(-(density * c)^2), c = {}\n",
                       ctx.program.HasOption(OptionId::FogExp) ? "ARB_fog_exp" : "ARB_fog_exp2", c);
    out += fmt::format("float arb_fog_dc = {} * {};\n", density, c);
    out += "float arb_fog = clamp(exp(-(arb_fog_dc * arb_fog_dc)), 0.0, 1.0);\n";
  }
  for (int n : ctx.fog_colors) {
    std::string color = FogColorName(ctx, n);
    std::string rgb = ctx.Mutated(Mutation::FogColorUnclamped)
                          ? color + ".rgb"
                          : fmt::format("clamp({}.rgb, 0.0, 1.0)", color);
    out += fmt::format(
        "{} = vec4(mix(clamp({}.rgb, 0.0, 1.0), {}, arb_fog), clamp({}.a, 0.0, 1.0));\n",
        FragColorName(ctx, n), fog_color, rgb, color);
  }
  return out;
}

std::string_view PrecisionNote(const Program& p) {
  if (p.HasOption(OptionId::PrecisionFastest)) return "ARB_precision_hint_fastest";
  if (p.HasOption(OptionId::PrecisionNicest)) return "ARB_precision_hint_nicest";
  return "";
}

// The options of ARB_fragment_coord_conventions are gl_FragCoord's layout qualifiers of the
// same names (the extension's GLSL section).
std::string FragCoordLayout(const Program& p) {
  std::vector<std::string_view> ids;
  if (p.HasOption(OptionId::OriginUpperLeft)) ids.push_back("origin_upper_left");
  if (p.HasOption(OptionId::PixelCenterInteger)) ids.push_back("pixel_center_integer");
  if (ids.empty()) return "";
  return fmt::format("layout({}) in vec4 gl_FragCoord;\n", fmt::join(ids, ", "));
}

std::string EmitShader(Context& ctx) {
  const Program& p = ctx.program;
  AssignNames(ctx);
  ctx.fog_redirect = p.kind == ProgramKind::Fragment &&
                     (p.HasOption(OptionId::FogLinear) || p.HasOption(OptionId::FogExp) ||
                      p.HasOption(OptionId::FogExp2));

  // The body first: it records what the declarations must provide.
  std::string body = EmitBody(ctx);
  // Appended piece by piece: GCC 12 at -O3 reads `s += "\n" + t` as an overlapping copy (a
  // false -Wrestrict in std::string).
  if (ctx.fog_redirect) {
    if (!body.empty()) body += '\n';
    body += FogEpilogue(ctx);
  }
  if (ctx.uniforms && !ctx.vertex_colors.empty()) {
    if (!body.empty()) body += '\n';
    body += UniformsEpilogue(ctx);
  }

  std::string locals;
  if (ctx.clip_discard) locals += ClipDiscard(ctx);
  std::string globals;
  std::string readers;
  for (size_t i = 0; i < p.vars.size(); ++i) {
    const Variable& v = p.vars[i];
    const std::string& name = ctx.var_names[i];
    if (v.kind == VarKind::Temp) locals += fmt::format("vec4 {} = vec4(0.0);\n", name);
    if (v.kind == VarKind::Address) {
      // NV_vertex_program2 address registers are ivec4 (2.14.3.5).
      locals +=
          p.Nv() ? fmt::format("ivec4 {} = ivec4(0);\n", name) : fmt::format("int {} = 0;\n", name);
    }
  }
  for (const auto& [name, declaration] : ctx.nv_locals) locals += declaration + "\n";
  for (int n : ctx.clip_distances) {
    locals += fmt::format("arb_clip_distance{} = 0.0;  // result.clip[{}] starts at 0\n", n, n);
  }
  for (int n : ctx.fog_colors) {
    locals +=
        fmt::format("vec4 {} = vec4(0.0);  // result.color{}, before fog\n", FogColorName(ctx, n),
                    p.HasOption(OptionId::DrawBuffers) ? fmt::format("[{}]", n) : "");
  }
  for (size_t i = 0; i < p.vars.size(); ++i) {
    // A relatively addressed array is copied at the start: its elements are constant.
    const Variable& v = p.vars[i];
    if (!ctx.relative[i] || (v.kind != VarKind::Param && v.kind != VarKind::Attrib)) continue;
    const std::string& name = ctx.var_names[i];
    globals += fmt::format("vec4 {}[{}];  // {} {}, read with relative addressing\n", name,
                           v.bindings.size(), v.kind == VarKind::Param ? "PARAM" : "ATTRIB",
                           v.name.empty() ? BindingName(v.bindings.at(0), p.kind) : v.name);
    for (size_t e = 0; e < v.bindings.size(); ++e) {
      locals += fmt::format("{}[{}] = {};\n", name, e, ReadBinding(ctx, v.bindings[e]).text);
    }
    readers += '\n';
    readers += RelativeReaderText(ctx, static_cast<int>(i));
  }
  if (p.HasOption(OptionId::PositionInvariant) && ctx.uniforms) {
    // No ftransform() and no gl_ClipVertex without the built-in state.
    locals += InvariantPosition(ctx);
    ctx.outputs["result.position"] =
        RegisterMapping{"result.position", "gl_Position", ProgramKind::Vertex};
  } else if (p.HasOption(OptionId::PositionInvariant)) {
    locals += "gl_Position = ftransform();  // OPTION ARB_position_invariant\n";
    // Clipping against user planes happens in eye space as without a program; GLSL 1.10
    // leaves it undefined unless gl_ClipVertex is written (7.1).
    locals += "gl_ClipVertex = gl_ModelViewMatrix * gl_Vertex;\n";
    ctx.outputs["result.position"] =
        RegisterMapping{"result.position", "gl_Position", ProgramKind::Vertex};
  } else if (ctx.IsVertex() && !ctx.outputs.count("result.position")) {
    // A GLSL vertex shader must write gl_Position (GLSL 1.10 section 7.1).
    locals +=
        "gl_Position = vec4(0.0, 0.0, 0.0, 1.0);  // result.position is never written: "
        "undefined in ARB\n";
  }

  std::string out = std::string(ctx.target.version) + "\n";
  if (ctx.needs_rect && !ctx.target.modern) {
    out += "#extension GL_ARB_texture_rectangle : require\n";
  }
  if (ctx.needs_texture_lod && ctx.target.fragment_lod == "ext") {
    out += "#extension GL_ARB_shader_texture_lod : require\n";
  }
  // Where the dialect has no layout qualifiers, FragPosition emulates them.
  const std::string frag_coord = ctx.target.coord_conventions ? FragCoordLayout(p) : "";
  if (!frag_coord.empty()) out += "#extension GL_ARB_fragment_coord_conventions : require\n";
  out += fmt::format("// ARB {} program translated to {} by arbiter{}.\n",
                     ctx.IsVertex() ? "vertex" : "fragment", ctx.target.title,
                     ctx.uniforms && !ctx.target.uniforms ? " (state as uniforms)" : "");
  if (std::string_view hint = PrecisionNote(p); !hint.empty()) {
    out += fmt::format("// OPTION {}: a hint, nothing to translate.\n", hint);
  }
  if (p.HasOption(OptionId::FragmentProgramShadow)) {
    out += "// OPTION ARB_fragment_program_shadow: shadow samplers.\n";
  }

  std::string decls = frag_coord;
  if (ctx.uniforms) {
    decls += UniformsDeclarations(ctx);
  } else if (ctx.texcoord_declared > 0) {
    decls += fmt::format("varying vec4 gl_TexCoord[{}];\n", ctx.texcoord_declared);
  }
  std::vector<AttributeBinding> attribs;
  for (const auto& [name, a] : ctx.attribs) {
    if (!ctx.uniforms) attribs.push_back(a);
  }
  std::stable_sort(attribs.begin(), attribs.end(), [](const auto& a, const auto& b) {
    return (a.location < 0 ? 99 : a.location) < (b.location < 0 ? 99 : b.location);
  });
  for (const AttributeBinding& a : attribs) {
    decls += fmt::format("attribute vec4 {};  // {}{}\n", a.name, a.binding,
                         a.location >= 0 ? fmt::format(", location {}", a.location) : "");
  }
  for (bool local : {false, true}) {
    int size = local ? ctx.local_size : ctx.env_size;
    if (size == 0 || ctx.uniforms) continue;
    decls += fmt::format("uniform vec4 {}[{}];  // program.{}[{}]\n", EnvName(ctx, local), size,
                         local ? "local" : "env", size == 1 ? "0" : fmt::format("0..{}", size - 1));
  }
  for (const auto& [name, s] : ctx.state) {
    if (ctx.uniforms) break;
    decls += fmt::format("uniform {} {};  // {}\n", s.type, name, s.binding);
  }
  for (const auto& [unit, target] : ctx.samplers) {
    if (ctx.uniforms) break;
    decls += fmt::format("uniform {} {};  // texture[{}], {}\n", SamplerType(target),
                         SamplerName(unit), unit, TexTargetName(target));
  }
  for (int n : ctx.clip_distances) {
    if (ctx.uniforms) break;
    decls += fmt::format(
        "varying float arb_clip_distance{};  // result.clip[{}]: GLSL 1.10 has no clip distances\n",
        n, n);
  }
  decls += globals;
  if (!decls.empty()) {
    out += '\n';
    out += decls;
  }
  for (Helper h : ctx.helpers) {
    out += '\n';
    out += HelperText(ctx, h);
  }
  out += readers;
  out += "\nvoid main() {\n";
  out += Indent(locals);
  if (!locals.empty() && !body.empty()) out += "\n";
  out += Indent(body);
  out += "}\n";
  return FinishForTarget(ctx, std::move(out));
}

BindingMap MakeBindingMap(const Context& ctx) {
  BindingMap map;
  for (const auto& [name, a] : ctx.attribs) map.attributes.push_back(a);
  std::stable_sort(map.attributes.begin(), map.attributes.end(), [](const auto& a, const auto& b) {
    return (a.location < 0 ? 99 : a.location) < (b.location < 0 ? 99 : b.location);
  });
  if (ctx.env_size > 0) {
    map.parameters.push_back({EnvName(ctx, false), ctx.program.kind, false, ctx.env_size});
  }
  if (ctx.local_size > 0) {
    map.parameters.push_back({EnvName(ctx, true), ctx.program.kind, true, ctx.local_size});
  }
  for (const auto& [unit, target] : ctx.samplers) {
    map.samplers.push_back({SamplerName(unit), unit, target, DialectSamplerType(ctx.target, target),
                            SamplerBindingOf(ctx, unit)});
  }
  for (const auto& [name, s] : ctx.state) map.state.push_back(s);
  for (const auto& [name, r] : ctx.inputs) map.inputs.push_back(r);
  for (const auto& [name, r] : ctx.outputs) map.outputs.push_back(r);
  map.target = std::string(ctx.target.spelling);
  map.state_uniforms = ctx.uniforms;
  if (!ctx.block_offsets.empty()) {
    map.blocks.push_back({ctx.IsVertex() ? "ArbVertexUniforms" : "ArbFragmentUniforms",
                          ctx.program.kind, 0, BlockBindingOf(ctx), ctx.block_size});
    for (ParameterArray& a : map.parameters) a.offset = ctx.block_offsets.at(a.name);
    for (StateUniform& s : map.state) {
      s.offset = ctx.block_offsets.at(s.name);
      s.block = map.blocks.back().name;
    }
  }
  if (ctx.target.block) {
    for (auto* list : {&map.inputs, &map.outputs}) {
      for (RegisterMapping& r : *list) {
        const std::string name = r.glsl.substr(0, r.glsl.find_first_of(".["));
        if (ctx.varyings.count(name) || name.rfind("arb_clip_distance", 0) == 0) {
          r.location = VaryingLocation(name);
        }
      }
    }
  }
  map.mutation = std::string(MutationName(ctx.mutation));
  return map;
}

}  // namespace
}  // namespace emit

Translation EmitGlsl(const Program& program, const EmitOptions& options,
                     const compiler::SourceFile* source) {
  emit::Context ctx(program, options, source);
  Translation t;
  t.glsl = emit::EmitShader(ctx);
  t.bindings = emit::MakeBindingMap(ctx);
  return t;
}

PairTranslation EmitGlslPair(const Program& vertex, const Program& fragment,
                             const EmitOptions& options, const compiler::SourceFile* vertex_source,
                             const compiler::SourceFile* fragment_source) {
  // A first pass finds how many gl_TexCoord elements each side uses; both shaders then
  // declare the array with the same size, so the linked varyings match.
  int texcoords = 0;
  std::map<std::string, std::string> fragment_inputs;
  {
    emit::Context v(vertex, options, vertex_source);
    emit::Context f(fragment, options, fragment_source);
    (void)emit::EmitShader(v);
    (void)emit::EmitShader(f);
    texcoords = std::max(v.texcoord_size, f.texcoord_size);
    fragment_inputs = f.varyings;
  }
  emit::Context v(vertex, options, vertex_source);
  emit::Context f(fragment, options, fragment_source);
  f.clip_discard = vertex.HasOption(OptionId::PositionInvariant) && f.uniforms &&
                   f.target.clip_planes == "discard";
  if (f.clip_discard) {  // the first pass did not see the fragment shader's clip varyings
    fragment_inputs[emit::kClipVaryings[0]] = "vec4";
    fragment_inputs[emit::kClipVaryings[1]] = "vec2";
  }
  v.texcoord_declared = texcoords;
  f.texcoord_declared = texcoords;
  // State as uniforms: the vertex shader declares the fragment shader's inputs too (a used
  // fragment input without a vertex output does not link in GLSL 1.30 and ES).
  if (v.uniforms) v.pair_varyings = fragment_inputs;
  PairTranslation pair;
  pair.vertex = emit::EmitShader(v);
  pair.fragment = emit::EmitShader(f);
  BindingMap vm = emit::MakeBindingMap(v);
  BindingMap fm = emit::MakeBindingMap(f);
  pair.bindings = vm;
  BindingMap& m = pair.bindings;
  m.attributes.insert(m.attributes.end(), fm.attributes.begin(), fm.attributes.end());
  m.parameters.insert(m.parameters.end(), fm.parameters.begin(), fm.parameters.end());
  m.samplers.insert(m.samplers.end(), fm.samplers.begin(), fm.samplers.end());
  m.blocks.insert(m.blocks.end(), fm.blocks.begin(), fm.blocks.end());
  for (const StateUniform& s : fm.state) {
    bool seen = std::any_of(m.state.begin(), m.state.end(), [&](const StateUniform& x) {
      return x.name == s.name && x.block == s.block;
    });
    if (!seen) m.state.push_back(s);
  }
  m.inputs.insert(m.inputs.end(), fm.inputs.begin(), fm.inputs.end());
  m.outputs.insert(m.outputs.end(), fm.outputs.begin(), fm.outputs.end());
  return pair;
}

}  // namespace arbiter::arbvp
