// Target readback adaptation: see target_adapt.h. Like glsl_adapt.cpp, the translation is
// edited at the level of identifiers and whole lines only. What is relied on: `void main()`,
// the names the binding map gives each result and input, the declaration of a fragment
// output as `out vec4 NAME;` on its own line (after `layout(location = N) ` in Vulkan, where
// each varying is declared the same way), and the comment that marks the epilogue's
// vertex-colour clamp (dropped for a vertex program alone, whose results the other engines
// report unclamped).
#include "exec_glsl/target_adapt.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <functional>
#include <set>
#include <string_view>

namespace arbiter::runtime::exec {
namespace {

using arbvp::Binding;
using arbvp::ResultReg;

constexpr const char* kClampMarker = "// GL clamps the vertex colours";
// The user clip planes of OPTION ARB_position_invariant (GLSL 3.30): not a result register,
// and a run must draw every point. Measured on Mesa 22.3: with them written, softpipe and
// llvmpipe drew none of a run's points on the core context, even with every plane 0 and no
// GL_CLIP_DISTANCEn enabled (not understood; run --translate clips by them as expected).
constexpr const char* kClipDistance = "gl_ClipDistance[";

// The first identifier of a GLSL expression from the binding map ("arb_fogcoord" of
// "vec4(arb_fogcoord, 0.0, 0.0, 1.0)"), skipping the constructor.
std::string FirstName(const std::string& glsl) {
  size_t i = 0;
  if (glsl.rfind("vec4(", 0) == 0) i = 5;
  size_t end = i;
  while (end < glsl.size() &&
         (std::isalnum(static_cast<unsigned char>(glsl[end])) || glsl[end] == '_')) {
    ++end;
  }
  return glsl.substr(i, end - i);
}

// The map's GLSL expression of result `b` of a `kind` program.
bool ResultGlsl(const arbvp::BindingMap& map, const Binding& b, arbvp::ProgramKind kind,
                std::string* glsl, std::string* error) {
  const std::string name = arbvp::BindingName(b, kind);
  for (const arbvp::RegisterMapping& m : map.outputs) {
    if (m.binding == name && m.stage == kind) {
      *glsl = m.glsl;
      return true;
    }
  }
  *error = fmt::format("the binding map lists no output for {}", name);
  return false;
}

// The attachment value of a result held in `expr` (after the renames): GLSL has one
// component of the fog coordinate and point size (x) and of the depth (z).
std::string AsVec4(const Binding& b, const std::string& expr) {
  switch (b.result) {
    case ResultReg::FogCoord:
    case ResultReg::PointSize:
    case ResultReg::ClipDistance:
      return fmt::format("vec4({}, 0.0, 0.0, 0.0)", expr);
    case ResultReg::FragDepth:
      return fmt::format("vec4(0.0, 0.0, {}, 0.0)", expr);
    default:
      return expr;
  }
}

// Points are point sprites on core and ES contexts: Mesa rasterises a quad of four equal
// vertices, and interpolating across it turns an infinite varying into NaN (inf - inf).
// Every varying of a run is therefore `flat` where the dialect has it (not ES 1.00).
std::string VertexIn(const TargetDialect& d) { return d.legacy_io ? "attribute" : "in"; }
std::string VertexOut(const TargetDialect& d) { return d.legacy_io ? "varying" : "flat out"; }
// The layout qualifier of a stage input or output at `location`, where the dialect needs one.
std::string Location(const TargetDialect& d, int location) {
  return d.locations ? fmt::format("layout(location = {}) ", location) : "";
}

// The length of the `layout(...) ` that opens `line`, if any.
size_t LayoutPrefix(const std::string& line) {
  if (line.rfind("layout(", 0) != 0) return 0;
  const size_t close = line.find(") ");
  return close == std::string::npos ? 0 : close + 2;
}

// `text` with each line (its '\n' included) replaced by what `edit` makes of it.
std::string EditLines(const std::string& text,
                      const std::function<std::string(const std::string&)>& edit) {
  std::string out;
  size_t begin = 0;
  while (begin < text.size()) {
    size_t end = text.find('\n', begin);
    end = end == std::string::npos ? text.size() : end + 1;
    out += edit(text.substr(begin, end - begin));
    begin = end;
  }
  return out;
}

// The translation's declaration of varying `name` (`in vec4 NAME;`, `out float NAME;`, after
// a layout qualifier in Vulkan) made flat, where the dialect has it.
std::string MakeFlat(const std::string& text, const TargetDialect& d, const char* keyword,
                     const std::string& name) {
  if (d.legacy_io) return text;
  return EditLines(text, [&](const std::string& line) {
    const size_t layout = LayoutPrefix(line);
    for (const char* type : {" vec4 ", " float "}) {
      const std::string declaration = keyword + std::string(type) + name + ";";
      if (line.compare(layout, declaration.size(), declaration) == 0) {
        return line.substr(0, layout) + "flat " + line.substr(layout);
      }
    }
    return line;
  });
}

// The location the translation declares for its stage input `name` (`layout(location = N)
// in vec4 NAME;`), or -1.
int DeclaredLocation(const std::string& text, const std::string& name) {
  int location = -1;
  (void)EditLines(text, [&](const std::string& line) {
    constexpr std::string_view kLayout = "layout(location = ";
    const size_t layout = LayoutPrefix(line);
    for (const char* type : {"in vec4 ", "in float "}) {
      const std::string declaration = type + name + ";";
      if (line.rfind(kLayout, 0) == 0 &&
          line.compare(layout, declaration.size(), declaration) == 0) {
        location = std::atoi(line.c_str() + kLayout.size());
      }
    }
    return std::string();
  });
  return location;
}

// Vulkan, a vertex shader alone: the translation's outputs (`layout(location = N) out vec4
// NAME;`) become globals, leaving the locations to the readback carriers.
std::string DemoteOutputs(const std::string& text, const TargetDialect& d) {
  if (!d.locations) return text;
  return EditLines(text, [](const std::string& line) {
    const size_t layout = LayoutPrefix(line);
    return layout != 0 && line.compare(layout, 4, "out ") == 0 ? line.substr(layout + 4) : line;
  });
}

// The fragment shader's inputs: the binding map's, and the fog coordinate that a fog option
// reads without the program naming it (the map lists only what the program reads; as of
// this writing the emitter's fog epilogue reads `arb_fogcoord` unlisted).
std::vector<arbvp::RegisterMapping> FragmentInputs(const CheckedTranslation& t) {
  std::vector<arbvp::RegisterMapping> inputs;
  bool fog = false;
  for (const arbvp::RegisterMapping& m : t.bindings.inputs) {
    // fragment.position and fragment.facing read gl_FragCoord and gl_FrontFacing (in an
    // expression where the dialect differs), never a varying.
    if (m.stage != arbvp::ProgramKind::Fragment || m.glsl.rfind("gl_", 0) == 0 ||
        m.binding == "fragment.position" || m.binding == "fragment.facing") {
      continue;
    }
    inputs.push_back(m);
    fog = fog || m.binding == "fragment.fogcoord";
  }
  if (!fog && t.fragment.find(" float arb_fogcoord;") != std::string::npos) {
    inputs.push_back(
        {"fragment.fogcoord", "vec4(arb_fogcoord, 0.0, 0.0, 1.0)", arbvp::ProgramKind::Fragment});
  }
  return inputs;
}

// The names of the fragment shader's varyings.
std::set<std::string> FragmentVaryings(const CheckedTranslation& t) {
  std::set<std::string> names;
  for (const arbvp::RegisterMapping& m : FragmentInputs(t)) names.insert(FirstName(m.glsl));
  return names;
}

// The fragment shader's colour outputs 0..count-1, and the statement that writes one.
std::string AttachmentDeclarations(const TargetDialect& d, size_t count) {
  if (d.legacy_io) return "";
  std::string out;
  for (size_t k = 0; k < count; ++k) {
    out += fmt::format("layout(location = {0}) out vec4 arbiter_att{0};\n", k);
  }
  return out;
}
std::string Attachment(const TargetDialect& d, size_t k) {
  return d.legacy_io ? fmt::format("gl_FragData[{}]", k) : fmt::format("arbiter_att{}", k);
}

// The header of a generated (or adapted) fragment shader: ES 1.00 needs EXT_draw_buffers
// for more than one attachment.
constexpr const char* kDrawBuffers = "#extension GL_EXT_draw_buffers : require\n";
std::string FragmentHeader(const TargetDialect& d) {
  if (!d.legacy_io) return d.header;
  std::string header = d.header;
  header.insert(header.find('\n') + 1, kDrawBuffers);
  return header;
}

// A vec4 sent from the vertex to the fragment stage (the carrier varying `name`). ES 1.00 has
// no flat varyings, and interpolating across a point sprite's quad turns an infinity into
// NaN: there the value travels as its finite part and a class per component (0 finite,
// 1 +inf, 2 -inf, 3 NaN; both constant over the quad, so interpolated exactly), and the
// fragment shader rebuilds it from the uniform arbiter_special = (+inf, -inf, NaN, 0).
constexpr const char* kEncode =
    "float arbiter_class(float v) {\n"
    "  return v != v ? 3.0 : (v > 3.4028235e38 ? 1.0 : (v < -3.4028235e38 ? 2.0 : 0.0));\n"
    "}\n"
    "vec4 arbiter_class(vec4 v) {\n"
    "  return vec4(arbiter_class(v.x), arbiter_class(v.y), arbiter_class(v.z), "
    "arbiter_class(v.w));\n"
    "}\n"
    "vec4 arbiter_finite(vec4 v, vec4 c) {\n"
    "  return vec4(c.x == 0.0 ? v.x : 0.0, c.y == 0.0 ? v.y : 0.0, c.z == 0.0 ? v.z : 0.0,\n"
    "              c.w == 0.0 ? v.w : 0.0);\n"
    "}\n";
constexpr const char* kDecode =
    "float arbiter_decode(float v, float c) {\n"
    "  return c == 0.0 ? v\n"
    "                  : (c == 1.0 ? arbiter_special.x\n"
    "                              : (c == 2.0 ? arbiter_special.y : arbiter_special.z));\n"
    "}\n"
    "vec4 arbiter_decode(vec4 v, vec4 c) {\n"
    "  return vec4(arbiter_decode(v.x, c.x), arbiter_decode(v.y, c.y), arbiter_decode(v.z, c.z),\n"
    "              arbiter_decode(v.w, c.w));\n"
    "}\n";
constexpr const char* kSpecialUniform = "uniform vec4 arbiter_special;\n";

std::string SendDeclaration(const TargetDialect& d, const std::string& name, int location) {
  if (!d.legacy_io) return fmt::format("{}flat out vec4 {};\n", Location(d, location), name);
  return fmt::format("varying vec4 {0};\nvarying vec4 {0}_class;\n", name);
}
std::string ReceiveDeclaration(const TargetDialect& d, const std::string& name, int location) {
  if (!d.legacy_io) return fmt::format("{}flat in vec4 {};\n", Location(d, location), name);
  return fmt::format("varying vec4 {0};\nvarying vec4 {0}_class;\n", name);
}
// Statements of the vertex shader's main that send `value` (a vec4 expression).
std::string Send(const TargetDialect& d, const std::string& name, const std::string& value) {
  if (!d.legacy_io) return fmt::format("  {} = {};\n", name, value);
  return fmt::format("  {0}_class = arbiter_class({1});\n  {0} = arbiter_finite({1}, {0}_class);\n",
                     name, value);
}
// The fragment shader's vec4 expression of the value received.
std::string Receive(const TargetDialect& d, const std::string& name) {
  if (!d.legacy_io) return name;
  return fmt::format("arbiter_decode({0}, {0}_class)", name);
}
// The functions Send and Receive need, before the generated main of each stage.
std::string SendFunctions(const TargetDialect& d) { return d.legacy_io ? kEncode : ""; }
std::string ReceiveFunctions(const TargetDialect& d) { return d.legacy_io ? kDecode : ""; }
std::string ReceiveGlobals(const TargetDialect& d) { return d.legacy_io ? kSpecialUniform : ""; }

std::string PixelDeclaration(const RunPlan& plan, const TargetDialect& d) {
  return plan.position_attrib >= 0
             ? Location(d, plan.position_attrib) + VertexIn(d) + " vec4 arbiter_pixel;\n"
             : "uniform vec4 arbiter_pixel;\n";
}

const Renames kPositionRenames = {{"gl_Position", "arbiter_position"},
                                  {"gl_PointSize", "arbiter_pointsize"}};
constexpr const char* kPositionGlobals = "vec4 arbiter_position;\nfloat arbiter_pointsize;\n";
// Vulkan clips a point by every gl_ClipDistance the vertex shader writes (GL only by the
// enabled ones, none here): the translation's clip distances become a global array.
Renames PositionRenames(const TargetDialect& d) {
  Renames renames = kPositionRenames;
  if (d.locations) renames["gl_ClipDistance"] = "arbiter_clipdistance";
  return renames;
}
std::string PositionGlobals(const TargetDialect& d) {
  return std::string(kPositionGlobals) + (d.locations ? "float arbiter_clipdistance[8];\n" : "");
}
constexpr const char* kPositionInit =
    "  arbiter_position = vec4(0.0);\n  arbiter_pointsize = 0.0;\n";
constexpr const char* kPositionSet = "  gl_Position = arbiter_pixel;\n  gl_PointSize = 1.0;\n";

// A vertex shader alone: every result through the varyings arbiter_out<k>, up to
// max_attachments a pass, to a generated fragment shader.
bool PlanVertex(const RunPlan& plan, const CheckedTranslation& t, const TargetDialect& d,
                int max_attachments, std::vector<GlslPass>* passes, std::string* error) {
  const std::string base =
      DemoteOutputs(DropLines(DropLines(t.vertex, kClampMarker), kClipDistance), d);
  const size_t per_pass = static_cast<size_t>(std::clamp(max_attachments, 1, 8));
  for (size_t first = 0; first < plan.outputs.size(); first += per_pass) {
    GlslPass pass;
    std::string outs;
    std::string ins;
    std::string copies;
    std::string reads;
    for (size_t s = first; s < plan.outputs.size() && s < first + per_pass; ++s) {
      const size_t k = s - first;
      const Binding& b = plan.outputs[s].binding;
      std::string glsl;
      if (!ResultGlsl(t.bindings, b, arbvp::ProgramKind::Vertex, &glsl, error)) return false;
      const std::string carrier = fmt::format("arbiter_out{}", k);
      outs += SendDeclaration(d, carrier, static_cast<int>(k));
      ins += ReceiveDeclaration(d, carrier, static_cast<int>(k));
      copies += Send(d, carrier, AsVec4(b, RenameIdentifiers(glsl, PositionRenames(d))));
      reads += fmt::format("  {} = {};\n", Attachment(d, k), Receive(d, carrier));
      pass.attachments.push_back(static_cast<int>(s));
    }
    if (!AdaptMain(base, PositionRenames(d), PositionGlobals(d) + PixelDeclaration(plan, d) + outs,
                   &pass.vertex, error)) {
      return false;
    }
    pass.vertex += SendFunctions(d) + fmt::format("\nvoid main() {{\n{}  arbiter_main();\n{}{}}}\n",
                                                  kPositionInit, kPositionSet, copies);
    pass.fragment = FragmentHeader(d) + ReceiveGlobals(d) + ins +
                    AttachmentDeclarations(d, pass.attachments.size()) + ReceiveFunctions(d) +
                    "\nvoid main() {\n" + reads + "}\n";
    passes->push_back(std::move(pass));
  }
  return true;
}

// The generated attribute that feeds fragment input `binding` (fragment programs alone).
bool FragmentInputSource(const std::string& binding, std::string* attribute) {
  if (binding == "fragment.color" || binding == "fragment.color.primary") {
    *attribute = "arbiter_in_color";
  } else if (binding == "fragment.color.secondary") {
    *attribute = "arbiter_in_secondary";
  } else if (binding == "fragment.fogcoord") {
    *attribute = "arbiter_in_fogcoord";
  } else if (binding == "fragment.texcoord") {
    *attribute = "arbiter_in_texcoord0";
  } else if (binding.rfind("fragment.texcoord[", 0) == 0) {
    const int k = std::atoi(binding.c_str() + 18);
    if (k < 0 || k >= arbvp::kMaxTextureCoords) return false;
    *attribute = fmt::format("arbiter_in_texcoord{}", k);
  } else {
    return false;
  }
  return true;
}

// The vertex shader that feeds a fragment shader alone: each varying the binding map lists
// as a fragment input, from its generated attribute (FragmentInputAttributes).
bool PassThroughVertex(const CheckedTranslation& t, const TargetDialect& d, std::string* out,
                       std::string* error) {
  std::string text = d.header;
  for (const GeneratedAttribute& a : FragmentInputAttributes()) {
    text += fmt::format("{}{} vec4 {};\n", Location(d, a.location), VertexIn(d), a.name);
  }
  std::string copies;
  std::set<std::string> declared;
  for (const arbvp::RegisterMapping& m : FragmentInputs(t)) {
    const std::string name = FirstName(m.glsl);
    std::string attribute;
    if (name.empty() || !FragmentInputSource(m.binding, &attribute)) {
      *error = fmt::format("no generated input feeds fragment input {} ({})", m.binding, m.glsl);
      return false;
    }
    if (!declared.insert(name).second) continue;
    // A varying the map wraps in a constructor is a float (the fog coordinate).
    const bool scalar = m.glsl != name;
    if (d.legacy_io) {
      text += SendDeclaration(d, "arbiter_v_" + name, -1);
      copies += Send(d, "arbiter_v_" + name, attribute);
      continue;
    }
    const int location = DeclaredLocation(t.fragment, name);
    if (d.locations && location < 0) {
      *error = fmt::format("the translation declares no location for fragment input {}", name);
      return false;
    }
    text += fmt::format("{}{} {} {};\n", Location(d, location), VertexOut(d),
                        scalar ? "float" : "vec4", name);
    copies += fmt::format("  {} = {}{};\n", name, attribute, scalar ? ".x" : "");
  }
  *out = text + SendFunctions(d) +
         "\nvoid main() {\n  gl_Position = arbiter_in_position;\n  gl_PointSize = 1.0;\n" + copies +
         "}\n";
  return true;
}

// The fragment shader's passes: up to max - 1 results and the alive flag each.
bool PlanFragment(const RunPlan& plan, const CheckedTranslation& t, const TargetDialect& d,
                  int max_attachments, std::vector<GlslPass>* passes, std::string* error) {
  std::string vertex;
  const std::set<std::string> varyings = FragmentVaryings(t);
  // ES 1.00: each varying of the translation becomes a global of both stages, sent and
  // received through a carrier (Send, Receive).
  std::string sent_globals;
  std::string sends;
  std::string received_globals = ReceiveGlobals(d);
  std::string receives;
  std::string fragment = t.fragment;
  std::string base = DropLines(t.vertex, kClipDistance);
  for (const arbvp::RegisterMapping& m : FragmentInputs(t)) {
    const std::string name = FirstName(m.glsl);
    if (!d.legacy_io || received_globals.find(" " + name + ";") != std::string::npos) continue;
    const bool scalar = m.glsl != name;
    const std::string carrier = "arbiter_v_" + name;
    for (const char* type : {"vec4", "float"}) {
      fragment = DropLines(fragment, fmt::format("varying {} {};", type, name));
      base = DropLines(base, fmt::format("varying {} {};", type, name));
    }
    const std::string declaration = fmt::format("{} {};\n", scalar ? "float" : "vec4", name);
    received_globals += declaration + ReceiveDeclaration(d, carrier, -1);
    receives += fmt::format("  {} = {}{};\n", name, Receive(d, carrier), scalar ? ".x" : "");
    sent_globals += declaration + SendDeclaration(d, carrier, -1);
    sends += Send(d, carrier, scalar ? fmt::format("vec4({}, 0.0, 0.0, 0.0)", name) : name);
  }
  if (plan.mode == RunMode::Fragment) {
    if (!PassThroughVertex(t, d, &vertex, error)) return false;
  } else {
    for (const std::string& name : varyings) base = MakeFlat(base, d, "out", name);
    if (!AdaptMain(base, PositionRenames(d),
                   PositionGlobals(d) + PixelDeclaration(plan, d) + sent_globals, &vertex, error)) {
      return false;
    }
    vertex += SendFunctions(d) + fmt::format("\nvoid main() {{\n{}  arbiter_main();\n{}{}}}\n",
                                             kPositionInit, kPositionSet, sends);
  }
  // Every fragment output the map names becomes a global.
  for (const std::string& name : varyings) fragment = MakeFlat(fragment, d, "in", name);
  Renames renames = {{"gl_FragColor", "arbiter_fragdata[0]"},
                     {"gl_FragData", "arbiter_fragdata"},
                     {"gl_FragDepth", "arbiter_fragdepth"},
                     // ES 1.00 with EXT_frag_depth (the binding map says gl_FragDepth).
                     {"gl_FragDepthEXT", "arbiter_fragdepth"}};
  std::string globals = received_globals + "vec4 arbiter_fragdata[8];\nfloat arbiter_fragdepth;\n";
  std::string init = receives +
                     "  for (int i = 0; i < 8; ++i) arbiter_fragdata[i] = vec4(0.0);\n"
                     "  arbiter_fragdepth = 0.0;\n";
  for (const arbvp::RegisterMapping& m : t.bindings.outputs) {
    if (m.stage != arbvp::ProgramKind::Fragment || m.glsl.rfind("gl_", 0) == 0) continue;
    const std::string name = FirstName(m.glsl);
    if (renames.count(name) != 0) continue;
    fragment = DropLines(fragment, fmt::format("out vec4 {};", name));
    renames[name] = "arbiter_" + name;
    globals += fmt::format("vec4 arbiter_{};\n", name);
    init += fmt::format("  arbiter_{} = vec4(0.0);\n", name);
  }
  std::string adapted;
  if (!AdaptMain(fragment, renames, globals, &adapted, error)) return false;
  // After #version: the translation's own #extension lines and precision block follow.
  if (d.legacy_io) adapted.insert(adapted.find('\n') + 1, kDrawBuffers);
  const size_t per_pass = static_cast<size_t>(std::max(max_attachments - 1, 1));
  size_t next = 0;
  do {
    GlslPass pass;
    pass.vertex = vertex;
    std::string copies;
    for (; next < plan.outputs.size() && pass.attachments.size() < per_pass; ++next) {
      const Binding& b = plan.outputs[next].binding;
      std::string glsl;
      if (!ResultGlsl(t.bindings, b, arbvp::ProgramKind::Fragment, &glsl, error)) return false;
      copies += fmt::format("  {} = {};\n", Attachment(d, pass.attachments.size()),
                            AsVec4(b, RenameIdentifiers(glsl, renames)));
      pass.attachments.push_back(static_cast<int>(next));
    }
    // A discard in arbiter_main() ends the invocation: the flag stays (0,0,0,0).
    copies += fmt::format("  {} = vec4(1.0);\n", Attachment(d, pass.attachments.size()));
    pass.attachments.push_back(kAliveFlag);
    pass.fragment = adapted + AttachmentDeclarations(d, pass.attachments.size()) +
                    ReceiveFunctions(d) +
                    fmt::format("\nvoid main() {{\n{}  arbiter_main();\n{}}}\n", init, copies);
    passes->push_back(std::move(pass));
  } while (next < plan.outputs.size());
  return true;
}

// The model's value of the vertex attribute the binding map spells `spelling`.
bool AttributeValue(const arbvp::VertexInput& in, const std::string& spelling, arbvp::Vec4* out) {
  auto index = [&](const char* prefix, int* n) {
    const size_t length = std::char_traits<char>::length(prefix);
    if (spelling.compare(0, length, prefix) != 0) return false;
    *n = std::atoi(spelling.c_str() + length);
    return true;
  };
  int n = 0;
  if (spelling == "vertex.position" || spelling == "vertex.attrib[0]") {
    *out = in.position;
  } else if (index("vertex.attrib[", &n) && n > 0 && n < arbvp::kMaxGenericAttribs) {
    *out = in.generic[static_cast<size_t>(n)];
  } else if (spelling == "vertex.normal") {
    *out = in.normal;
  } else if (spelling == "vertex.color" || spelling == "vertex.color.primary") {
    *out = in.color;
  } else if (spelling == "vertex.color.secondary") {
    *out = in.secondary_color;
  } else if (spelling == "vertex.fogcoord") {
    *out = in.fogcoord;
  } else if (spelling == "vertex.texcoord") {
    *out = in.texcoord[0];
  } else if (index("vertex.texcoord[", &n) && n >= 0 && n < arbvp::kMaxTextureCoords) {
    *out = in.texcoord[static_cast<size_t>(n)];
  } else if (spelling == "vertex.weight" || spelling == "vertex.weight[0]") {
    *out = in.weight;
  } else if (spelling == "vertex.matrixindex" || spelling == "vertex.matrixindex[0]") {
    *out = in.matrix_index;
  } else {
    return false;
  }
  return true;
}

}  // namespace

bool PointAttributes(const RunPlan& plan, const arbvp::BindingMap& map, const arbvp::InputVector& v,
                     const arbvp::Vec4& clip,
                     const std::function<void(int, const arbvp::Vec4&)>& put, std::string* error) {
  if (plan.mode == RunMode::Fragment) {
    const FragmentInputAttribs& a = kFragmentInputAttribs;
    put(a.position, clip);
    put(a.color, v.fragment.color);
    put(a.secondary_color, v.fragment.secondary_color);
    put(a.fogcoord, {v.fragment.fogcoord, 0.0f, 0.0f, 1.0f});
    for (int k = 0; k < arbvp::kMaxTextureCoords; ++k) {
      put(a.texcoord0 + k, v.fragment.texcoord[static_cast<size_t>(k)]);
    }
    return true;
  }
  for (const arbvp::AttributeBinding& a : map.attributes) {
    arbvp::Vec4 value{};
    if (a.location < 0 || a.location >= arbvp::kMaxGenericAttribs ||
        !AttributeValue(v.vertex, a.binding, &value)) {
      *error = fmt::format("no input of the model feeds the attribute {} ({}, location {})", a.name,
                           a.binding, a.location);
      return false;
    }
    put(a.location, value);
  }
  if (plan.position_attrib >= 0) put(plan.position_attrib, clip);
  return true;
}

TargetDialect DialectOf(arbvp::EmitTarget target) {
  TargetDialect d;
  d.target = target;
  switch (target) {
    case arbvp::EmitTarget::Es300:
      d.header = "#version 300 es\nprecision highp float;\nprecision highp int;\n";
      break;
    case arbvp::EmitTarget::Es100:
      d.legacy_io = true;
      d.header = "#version 100\nprecision highp float;\nprecision highp int;\n";
      break;
    case arbvp::EmitTarget::Vk450:
      d.locations = true;
      d.header = "#version 450\n";
      break;
    default:
      d.header = "#version 330 core\n";
      break;
  }
  return d;
}

bool PlanTargetPasses(const RunPlan& plan, const CheckedTranslation& translation,
                      const TargetDialect& dialect, int max_attachments,
                      std::vector<GlslPass>* passes, std::string* error) {
  passes->clear();
  if (plan.mode == RunMode::Vertex) {
    return PlanVertex(plan, translation, dialect, max_attachments, passes, error);
  }
  return PlanFragment(plan, translation, dialect, max_attachments, passes, error);
}

bool TranslateForTarget(const ArbPrograms& programs, const arbvp::EmitOptions& emit,
                        arbvp::EmitTarget target, const compiler::SourceFile* vertex_source,
                        const compiler::SourceFile* fragment_source,
                        CheckedTranslation* translation, std::string* not_applicable,
                        std::string* error) {
  arbvp::EmitOptions options = emit;
  options.target = target;
  options.state = arbvp::StateSource::Uniforms;
  *translation =
      EmitTranslation(programs.vertex, programs.fragment, options, vertex_source, fragment_source);
  if (translation->refused) {
    *not_applicable = translation->error;
    return false;
  }
  if (!translation->error.empty()) {
    *error = translation->error;
    return false;
  }
  return true;
}

}  // namespace arbiter::runtime::exec
