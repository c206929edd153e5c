// GLSL readback adaptation: see glsl_adapt.h. The emitter's text is edited at the level of
// identifiers only (never by matching statements), so a change in how it phrases a statement
// cannot break the readback: what is relied on is `void main()`, the GLSL names of the
// output built-ins, and the `varying vec4 gl_TexCoord[N];` redeclaration.
#include "exec_glsl/glsl_adapt.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>

namespace arbiter::runtime::exec {
namespace {

bool IsIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool IsIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

}  // namespace

std::string RenameIdentifiers(const std::string& text, const Renames& renames) {
  std::string out;
  out.reserve(text.size() + 256);
  size_t i = 0;
  while (i < text.size()) {
    if (!IsIdentStart(text[i]) || (i > 0 && IsIdentChar(text[i - 1]))) {
      out += text[i++];
      continue;
    }
    size_t end = i;
    while (end < text.size() && IsIdentChar(text[end])) ++end;
    const std::string word = text.substr(i, end - i);
    auto it = renames.find(word);
    out += it != renames.end() ? it->second : word;
    i = end;
  }
  return out;
}

std::string DropLines(const std::string& text, const std::string& needle) {
  std::string out;
  size_t begin = 0;
  while (begin < text.size()) {
    size_t end = text.find('\n', begin);
    end = end == std::string::npos ? text.size() : end + 1;
    std::string_view line(text.data() + begin, end - begin);
    if (line.find(needle) == std::string_view::npos) out += line;
    begin = end;
  }
  return out;
}

std::string InsertGlobals(const std::string& text, const std::string& globals) {
  size_t insert = 0;
  size_t begin = 0;
  while (begin < text.size()) {
    size_t end = text.find('\n', begin);
    end = end == std::string::npos ? text.size() : end + 1;
    std::string_view line(text.data() + begin, end - begin);
    if (line.rfind('#', 0) == 0 || line.rfind("precision ", 0) == 0) {
      insert = end;
    } else if (line.rfind("//", 0) != 0 && line != "\n") {
      break;
    }
    begin = end;
  }
  return text.substr(0, insert) + globals + text.substr(insert);
}

bool AdaptMain(const std::string& text, const Renames& renames, const std::string& globals,
               std::string* out, std::string* error) {
  if (text.find("void main()") == std::string::npos) {
    *error = "the GLSL translation has no 'void main()' to adapt for readback";
    return false;
  }
  Renames all = renames;
  all["main"] = "arbiter_main";
  *out = InsertGlobals(RenameIdentifiers(text, all), globals);
  return true;
}

namespace {

using arbvp::Binding;
using arbvp::ResultReg;

// The global that holds a result register after the renames below, as a vec4. GLSL has
// only x of the fog coordinate and point size, and only z of the depth: the rest reads 0.
std::string OutputExpr(const Binding& b) {
  switch (b.result) {
    case ResultReg::Position:
      return "arbiter_position";
    case ResultReg::Color:
      return fmt::format("arbiter_{}_{}", b.face == arbvp::Face::Back ? "back" : "front",
                         b.secondary ? "secondary" : "color");
    case ResultReg::FogCoord:
      return "vec4(arbiter_fogcoord, 0.0, 0.0, 0.0)";
    case ResultReg::PointSize:
      return "vec4(arbiter_pointsize, 0.0, 0.0, 0.0)";
    case ResultReg::TexCoord:
      return fmt::format("arbiter_texcoord[{}]", b.index);
    case ResultReg::ClipDistance:  // NV_vertex_program2: Mesa runs no NV program
      return fmt::format("vec4(arb_clip_distance{}, 0.0, 0.0, 0.0)", b.index);
    case ResultReg::FragColor:
      return fmt::format("arbiter_fragdata[{}]", b.index);
    case ResultReg::FragDepth:
      return "vec4(0.0, 0.0, arbiter_fragdepth, 0.0)";
  }
  return "vec4(0.0)";
}

const Renames kVertexOutputs = {
    {"gl_Position", "arbiter_position"},
    {"gl_PointSize", "arbiter_pointsize"},
    {"gl_FrontColor", "arbiter_front_color"},
    {"gl_BackColor", "arbiter_back_color"},
    {"gl_FrontSecondaryColor", "arbiter_front_secondary"},
    {"gl_BackSecondaryColor", "arbiter_back_secondary"},
    {"gl_FogFragCoord", "arbiter_fogcoord"},
    {"gl_TexCoord", "arbiter_texcoord"},
};

constexpr const char* kVertexGlobals =
    "vec4 arbiter_position;\nfloat arbiter_pointsize;\nvec4 arbiter_front_color;\n"
    "vec4 arbiter_back_color;\nvec4 arbiter_front_secondary;\nvec4 arbiter_back_secondary;\n"
    "float arbiter_fogcoord;\nvec4 arbiter_texcoord[8];\n";

// The point's clip position: an attribute, or a uniform set per point when the vertex
// program reads all sixteen generic attributes.
std::string PixelDeclaration(const RunPlan& plan) {
  return plan.position_attrib >= 0 ? "attribute vec4 arbiter_pixel;\n"
                                   : "uniform vec4 arbiter_pixel;\n";
}

// GLSL 1.10 globals have no initial value; ARB results start at 0 in the ARB engine's
// rewrite, so unwritten components read the same in both.
constexpr const char* kVertexInit =
    "  arbiter_position = vec4(0.0);\n  arbiter_pointsize = 0.0;\n"
    "  arbiter_front_color = vec4(0.0);\n  arbiter_back_color = vec4(0.0);\n"
    "  arbiter_front_secondary = vec4(0.0);\n  arbiter_back_secondary = vec4(0.0);\n"
    "  arbiter_fogcoord = 0.0;\n"
    "  for (int i = 0; i < 8; ++i) arbiter_texcoord[i] = vec4(0.0);\n";

constexpr const char* kFragmentGlobals = "vec4 arbiter_fragdata[8];\nfloat arbiter_fragdepth;\n";
constexpr const char* kFragmentInit =
    "  for (int i = 0; i < 8; ++i) arbiter_fragdata[i] = vec4(0.0);\n"
    "  arbiter_fragdepth = 0.0;\n";

// A vertex shader alone: every output through the varyings arbiter_out<k>, eight a pass.
bool PlanVertex(const RunPlan& plan, const CheckedTranslation& t, int max_attachments,
                std::vector<GlslPass>* passes, std::string* error) {
  // The translation's own redeclaration would make the renamed array a varying.
  const std::string base = DropLines(t.vertex, "varying vec4 gl_TexCoord[");
  const size_t per_pass = static_cast<size_t>(std::min(max_attachments, 8));
  for (size_t first = 0; first < plan.outputs.size(); first += per_pass) {
    GlslPass pass;
    std::string varyings;
    std::string copies;
    std::string reads;
    for (size_t s = first; s < plan.outputs.size() && s < first + per_pass; ++s) {
      const size_t k = s - first;
      varyings += fmt::format("varying vec4 arbiter_out{};\n", k);
      copies += fmt::format("  arbiter_out{} = {};\n", k, OutputExpr(plan.outputs[s].binding));
      reads += fmt::format("  gl_FragData[{0}] = arbiter_out{0};\n", k);
      pass.attachments.push_back(static_cast<int>(s));
    }
    if (!AdaptMain(base, kVertexOutputs, kVertexGlobals + PixelDeclaration(plan) + varyings,
                   &pass.vertex, error)) {
      return false;
    }
    pass.vertex += fmt::format(
        "\nvoid main() {{\n{}  arbiter_main();\n  gl_Position = arbiter_pixel;\n"
        "  gl_PointSize = 1.0;\n{}}}\n",
        kVertexInit, copies);
    pass.fragment = "#version 110\n" + varyings + "\nvoid main() {\n" + reads + "}\n";
    passes->push_back(std::move(pass));
  }
  return true;
}

// The size of the fragment shader's gl_TexCoord redeclaration (8 without one).
int TexCoordSize(const std::string& fragment) {
  const std::string needle = "varying vec4 gl_TexCoord[";
  size_t at = fragment.find(needle);
  if (at == std::string::npos) return 8;
  return std::clamp(std::atoi(fragment.c_str() + at + needle.size()), 1, 8);
}

// The vertex shader that feeds a fragment shader alone from generic attributes, like
// program_rewrite.cpp's PassThroughVertex: every component reaches the fragment stage.
std::string PassThroughVertex(int texcoords) {
  std::string text = "#version 110\n";
  for (const GeneratedAttribute& a : FragmentInputAttributes()) {
    text += fmt::format("attribute vec4 {};\n", a.name);
  }
  text += fmt::format(
      "varying vec4 gl_TexCoord[{}];\n\nvoid main() {{\n"
      "  gl_Position = arbiter_in_position;\n  gl_FrontColor = arbiter_in_color;\n"
      "  gl_FrontSecondaryColor = arbiter_in_secondary;\n"
      "  gl_FogFragCoord = arbiter_in_fogcoord.x;\n  gl_PointSize = 1.0;\n",
      texcoords);
  for (int k = 0; k < texcoords; ++k) {
    text += fmt::format("  gl_TexCoord[{0}] = arbiter_in_texcoord{0};\n", k);
  }
  return text + "}\n";
}

// The fragment shader's passes: up to max - 1 outputs and the alive flag each.
bool PlanFragment(const RunPlan& plan, const CheckedTranslation& t, int max_attachments,
                  std::vector<GlslPass>* passes, std::string* error) {
  std::string vertex;
  if (plan.mode == RunMode::Fragment) {
    vertex = PassThroughVertex(TexCoordSize(t.fragment));
  } else {
    const Renames renames = {{"gl_Position", "arbiter_position"},
                             {"gl_PointSize", "arbiter_pointsize"}};
    const std::string globals =
        "vec4 arbiter_position;\nfloat arbiter_pointsize;\n" + PixelDeclaration(plan);
    if (!AdaptMain(t.vertex, renames, globals, &vertex, error)) return false;
    vertex +=
        "\nvoid main() {\n  arbiter_position = vec4(0.0);\n  arbiter_pointsize = 0.0;\n"
        "  arbiter_main();\n  gl_Position = arbiter_pixel;\n  gl_PointSize = 1.0;\n}\n";
  }
  std::string fragment;
  const Renames renames = {{"gl_FragColor", "arbiter_fragdata[0]"},
                           {"gl_FragData", "arbiter_fragdata"},
                           {"gl_FragDepth", "arbiter_fragdepth"}};
  if (!AdaptMain(t.fragment, renames, kFragmentGlobals, &fragment, error)) return false;
  const size_t per_pass = static_cast<size_t>(max_attachments - 1);
  size_t next = 0;
  do {
    GlslPass pass;
    pass.vertex = vertex;
    std::string copies;
    for (; next < plan.outputs.size() && pass.attachments.size() < per_pass; ++next) {
      copies += fmt::format("  gl_FragData[{}] = {};\n", pass.attachments.size(),
                            OutputExpr(plan.outputs[next].binding));
      pass.attachments.push_back(static_cast<int>(next));
    }
    // A discard in arbiter_main() ends the invocation: the flag stays (0,0,0,0).
    copies += fmt::format("  gl_FragData[{}] = vec4(1.0);\n", pass.attachments.size());
    pass.attachments.push_back(kAliveFlag);
    pass.fragment = fragment + fmt::format("\nvoid main() {{\n{}  arbiter_main();\n{}}}\n",
                                           kFragmentInit, copies);
    passes->push_back(std::move(pass));
  } while (next < plan.outputs.size());
  return true;
}

}  // namespace

std::vector<GeneratedAttribute> FragmentInputAttributes() {
  const FragmentInputAttribs& a = kFragmentInputAttribs;
  std::vector<GeneratedAttribute> out = {{"arbiter_in_position", a.position},
                                         {"arbiter_in_color", a.color},
                                         {"arbiter_in_secondary", a.secondary_color},
                                         {"arbiter_in_fogcoord", a.fogcoord}};
  static const char* const kTexcoords[] = {"arbiter_in_texcoord0", "arbiter_in_texcoord1",
                                           "arbiter_in_texcoord2", "arbiter_in_texcoord3",
                                           "arbiter_in_texcoord4", "arbiter_in_texcoord5",
                                           "arbiter_in_texcoord6", "arbiter_in_texcoord7"};
  for (int k = 0; k < arbvp::kMaxTextureCoords; ++k) {
    out.push_back({kTexcoords[k], a.texcoord0 + k});
  }
  return out;
}

bool PlanGlslPasses(const RunPlan& plan, const CheckedTranslation& translation, int max_attachments,
                    std::vector<GlslPass>* passes, std::string* error) {
  passes->clear();
  if (plan.mode == RunMode::Vertex) {
    return PlanVertex(plan, translation, max_attachments, passes, error);
  }
  return PlanFragment(plan, translation, max_attachments, passes, error);
}

}  // namespace arbiter::runtime::exec
