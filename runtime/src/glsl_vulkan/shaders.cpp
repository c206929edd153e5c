// The generated mains of the Vulkan engine: see shaders.h.
#include "glsl_vulkan/shaders.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "arbiter/glsl/lower_vulkan.h"
#include "glsl_exec/types.h"

namespace arbiter::runtime::glsl_vulkan {
namespace {

using glsl_exec::LookUpType;
using glsl_exec::TypeInfo;

constexpr std::string_view kSwizzle = "xyzw";

int Columns(const std::string& type) { return std::max(LookUpType(type).columns, 1); }

// The value of `type` read from the vec4s of arb_in from arb_b + `first`.
std::string ReadInput(const std::string& type, int first) {
  const TypeInfo info = LookUpType(type);
  const int columns = std::max(info.columns, 1);
  const int rows = std::max(info.components / columns, 1);
  auto column = [&](int c) {
    const std::string at = fmt::format("arb_in[arb_b + {}]", first + c);
    return rows == 4 ? at : fmt::format("{}.{}", at, kSwizzle.substr(0, static_cast<size_t>(rows)));
  };
  if (columns == 1) return column(0);
  std::string args;
  for (int c = 0; c < columns; ++c) args += (c > 0 ? ", " : "") + column(c);
  return fmt::format("{}({})", type, args);
}

// Stores of every number of `access` (of `type`) from arb_out[arb_o + *next] on.
void Store(const std::string& access, const std::string& type, int* next, std::string* out) {
  const TypeInfo info = LookUpType(type);
  const int columns = std::max(info.columns, 1);
  const int rows = std::max(info.components / columns, 1);
  for (int c = 0; c < columns; ++c) {
    for (int r = 0; r < rows; ++r) {
      std::string part = access;
      if (columns > 1) part += fmt::format("[{}]", c);
      if (rows > 1) part += fmt::format(".{}", kSwizzle[static_cast<size_t>(r)]);
      *out += fmt::format("  arb_out[arb_o + {}] = {};\n", (*next)++, part);
    }
  }
}

constexpr std::string_view kBuffers =
    "layout(std430, set = 0, binding = 30) readonly buffer arb_inputs { vec4 arb_in[]; };\n"
    "layout(std430, set = 0, binding = 31) buffer arb_outputs { float arb_out[]; };\n";

// The varyings a pair passes (flat: one point per vector): the built-ins the fragment stage
// reads (colours clamped, as GL's vertex colour clamping does) and the user varyings.
struct Varying {
  std::string type;
  int array_size;    // 0: none
  std::string from;  // the vertex stage's expression
  std::string to;    // the fragment stage's global
};

std::vector<Varying> PairVaryings(const glsl::Reflection& fragment) {
  std::vector<Varying> out = {
      {"vec4", 0, "clamp(arb_gl_FrontColor, 0.0, 1.0)", "arb_gl_Color"},
      {"vec4", 0, "clamp(arb_gl_FrontSecondaryColor, 0.0, 1.0)", "arb_gl_SecondaryColor"},
      {"vec4", 8, "arb_gl_TexCoord", "arb_gl_TexCoord"},
      {"float", 0, "arb_gl_FogFragCoord", "arb_gl_FogFragCoord"},
  };
  for (const glsl::ReflectedVariable& v : fragment.varyings) {
    const std::string name = glsl::LoweredIdentifier(v.name);
    out.push_back({v.type, v.array_size, name, name});
  }
  return out;
}

std::string VaryingDeclarations(const std::vector<Varying>& varyings, const char* direction) {
  std::string out = fmt::format("layout(location = 0) flat {} int arb_index;\n", direction);
  int location = 1;
  for (size_t i = 0; i < varyings.size(); ++i) {
    const Varying& v = varyings[i];
    out += fmt::format("layout(location = {}) flat {} {} arb_v{}{};\n", location, direction, v.type,
                       i, v.array_size > 0 ? fmt::format("[{}]", v.array_size) : "");
    location += Columns(v.type) * std::max(v.array_size, 1);
  }
  return out;
}

// Each run of identifier characters that starts with a letter or '_' goes through `f`.
template <typename F>
std::string MapNames(std::string_view access, F f) {
  std::string out;
  size_t i = 0;
  while (i < access.size()) {
    const char c = access[i];
    const bool start = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
    if (!start) {
      out += c;
      ++i;
      continue;
    }
    size_t end = i;
    while (end < access.size() &&
           (std::isalnum(static_cast<unsigned char>(access[end])) != 0 || access[end] == '_')) {
      ++end;
    }
    out += f(access.substr(i, end - i));
    i = end;
  }
  return out;
}

}  // namespace

std::string LowerAccess(std::string_view access) {
  return MapNames(access, [](std::string_view name) { return glsl::LoweredIdentifier(name); });
}

std::string UserAccess(std::string_view lowered) {
  return MapNames(lowered, [](std::string_view name) {
    if (name.starts_with("arb_u_")) return std::string(name.substr(6));
    if (name.starts_with("arb_gl_")) return std::string(name.substr(4));
    return std::string(name);
  });
}

IoPlan PlanIo(const GlslShaders& shaders, const GlslExecInputs& inputs) {
  IoPlan plan;
  for (const GlslInputSlot& slot : inputs.slots) {
    if (slot.name == "gl_FragCoord.z") continue;
    // gl_SecondaryColor takes three numbers (glSecondaryColor3f) into a vec4 of alpha 1.
    plan.inputs.push_back(
        {slot.name, slot.name == "gl_SecondaryColor" ? "vec4" : slot.type, plan.input_stride});
    plan.input_stride += Columns(slot.type);
  }
  if (shaders.vertex_reflection != nullptr && !shaders.vertex.empty()) {
    plan.vertex_outputs = glsl_exec::VertexOutputs(*shaders.vertex_reflection);
    for (const glsl_exec::VertexOutput& o : plan.vertex_outputs) plan.vertex_stride += o.components;
  }
  if (shaders.fragment_reflection != nullptr && !shaders.fragment.empty()) {
    plan.fragment_outputs = glsl_exec::OutputsOf(*shaders.fragment_reflection);
    const glsl_exec::FragmentOutputs& f = plan.fragment_outputs;
    plan.fragment_stride =
        1 + (f.color ? 4 : 0) + 4 * static_cast<int>(f.data.size()) + (f.depth ? 1 : 0);
  }
  return plan;
}

Generated GenerateMains(const GlslShaders& shaders, const std::string& lowered_vertex,
                        const std::string& lowered_fragment, const IoPlan& plan, size_t count,
                        int height) {
  Generated out;
  const bool pair = !lowered_vertex.empty() && !lowered_fragment.empty();
  std::vector<Varying> varyings;
  if (pair) varyings = PairVaryings(*shaders.fragment_reflection);
  // The inputs: read by the vertex stage; a fragment shader alone gets them through flat
  // varyings from the generated vertex shader (reading them in the fragment stage would leave
  // the helper invocations of a quad without them: derivatives need the same values there).
  std::string feed;
  for (const IoPlan::Input& in : plan.inputs) {
    feed += fmt::format("  {} = {};\n", LowerAccess(in.name), ReadInput(in.type, in.first));
  }
  if (lowered_vertex.empty()) {
    for (const IoPlan::Input& in : plan.inputs) {
      varyings.push_back({in.type, 0, ReadInput(in.type, in.first), LowerAccess(in.name)});
    }
  }
  if (!lowered_vertex.empty()) {
    std::string body = fmt::format("  int arb_b = gl_VertexIndex * {};\n", plan.input_stride);
    body += feed;
    body += "  arb_main();\n";
    body += fmt::format("  int arb_o = gl_VertexIndex * {};\n", plan.vertex_stride);
    int next = 0;
    for (const glsl_exec::VertexOutput& o : plan.vertex_outputs) {
      Store(LowerAccess(o.name), o.type, &next, &body);
    }
    body += "  gl_Position = arb_in[arb_b];\n  gl_PointSize = 1.0;\n";
    std::string declarations(kBuffers);
    if (pair) {
      declarations += VaryingDeclarations(varyings, "out");
      body += "  arb_index = gl_VertexIndex;\n";
      for (size_t i = 0; i < varyings.size(); ++i) {
        body += fmt::format("  arb_v{} = {};\n", i, varyings[i].from);
      }
    }
    out.vertex = fmt::format("{}{}void main() {{\n{}}}\n", lowered_vertex, declarations, body);
  } else {
    std::string body = fmt::format(
        "  int arb_b = gl_VertexIndex * {};\n  gl_Position = arb_in[arb_b];\n"
        "  gl_PointSize = 1.0;\n  arb_index = gl_VertexIndex;\n",
        plan.input_stride);
    for (size_t i = 0; i < varyings.size(); ++i) {
      body += fmt::format("  arb_v{} = {};\n", i, varyings[i].from);
    }
    out.vertex = fmt::format("#version 450\n{}{}void main() {{\n{}}}\n", kBuffers,
                             VaryingDeclarations(varyings, "out"), body);
  }
  if (lowered_fragment.empty()) return out;
  std::string declarations(kBuffers);
  std::string body = fmt::format(
      "  arb_gl_FragCoord = vec4(gl_FragCoord.x, {:.1f} - gl_FragCoord.y, gl_FragCoord.z, "
      "gl_FragCoord.w);\n",
      static_cast<double>(height));
  declarations += VaryingDeclarations(varyings, "in");
  for (size_t i = 0; i < varyings.size(); ++i) {
    body += fmt::format("  {} = arb_v{};\n", varyings[i].to, i);
  }
  body += "  arb_main();\n";
  body += fmt::format("  int arb_o = {} + arb_index * {};\n", plan.vertex_stride * count,
                      plan.fragment_stride);
  body += "  arb_out[arb_o] = 1.0;\n";
  int next = 1;
  const glsl_exec::FragmentOutputs& f = plan.fragment_outputs;
  if (f.color) Store("arb_gl_FragColor", "vec4", &next, &body);
  for (int n : f.data) Store(fmt::format("arb_gl_FragData[{}]", n), "vec4", &next, &body);
  // GL 2.0 3.11.2: the depth a fragment shader writes is clamped to [0, 1] (softpipe keeps
  // it unclamped in its DEPTH32F buffer, a deviation tests/glsl_exec/glsl-deviations.txt lists).
  if (f.depth) Store("clamp(arb_gl_FragDepth, 0.0, 1.0)", "float", &next, &body);
  out.fragment = fmt::format("{}{}void main() {{\n{}}}\n", lowered_fragment, declarations, body);
  return out;
}

}  // namespace arbiter::runtime::glsl_vulkan
