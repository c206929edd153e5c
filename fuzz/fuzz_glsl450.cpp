// Fuzz target: the modern back ends (arbiter::targets, docs/targets.md) on any bytes, as a
// GLSL 4.50 Vulkan vertex shader and as a fragment shader: every module glslang makes must pass
// spirv-val (but for known glslang defects) and convert to MSL, and to HLSL that ValidateHlsl
// accepts unless it uses what shader model 5.0 cannot express; every message must say which
// tool gave it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/targets/targets.h"
#include "fuzz_input.h"

namespace {

using arbiter::targets::Message;

bool HasErrorFrom(const std::vector<Message>& messages, std::string_view tool) {
  for (const Message& m : messages) {
    if (m.severity == Message::Severity::Error && m.tool == tool) return true;
  }
  return false;
}

// spirv-val's rules that glslang 12 is known to break (docs/targets.md): CompileGlslToSpirv
// reports these modules as invalid, which is what it should do; any other rule is a new bug.
constexpr std::string_view kKnownGlslangDefects[] = {
    // A shader that reads gl_FragDepth without writing it: no DepthReplacing execution mode.
    "[VUID-FragDepth-FragDepth-04216]",
};

// What HLSL shader model 5.0 cannot express (docs/targets.md): SpirvToHlsl refuses these
// modules with SPIRV-Cross's message; any other refusal is a bug.
constexpr std::string_view kHlslLimits[] = {
    // Built-ins shader model 5.0 lacks (gl_PointSize: Direct3D 11 has no point size).
    "Unsupported builtin in HLSL: ",
    // A std430 layout (push constants) with array strides below 16 bytes.
    "cannot be expressed with either HLSL packing layout or packoffset",
};

// Every error `tool` gave says one of `known`.
template <size_t N>
bool OnlyKnown(const std::vector<Message>& messages, std::string_view tool,
               const std::string_view (&known)[N]) {
  for (const Message& m : messages) {
    if (m.severity != Message::Severity::Error || m.tool != tool) continue;
    bool found = false;
    for (std::string_view text : known) found = found || m.text.find(text) != std::string::npos;
    if (!found) return false;
  }
  return true;
}

void CheckMessages(const std::vector<Message>& messages) {
  for (const Message& m : messages) {
    if (m.tool.empty() || m.line < 0) __builtin_trap();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace arbiter::targets;
  if (size > arbiter::fuzz::kMaxInputBytes) return -1;
  std::string_view text(reinterpret_cast<const char*>(data), size);
  for (Stage stage : {Stage::Vertex, Stage::Fragment}) {
    std::vector<uint32_t> spirv;
    std::vector<Message> messages;
    bool compiled = CompileGlslToSpirv(text, stage, &spirv, &messages);
    CheckMessages(messages);
    // glslang accepted the text but its module fails spirv-val: a glslang bug.
    if (!compiled && HasErrorFrom(messages, "spirv-val") &&
        !OnlyKnown(messages, "spirv-val", kKnownGlslangDefects)) {
      __builtin_trap();
    }
    if (compiled != !(HasErrorFrom(messages, "glslang") || HasErrorFrom(messages, "spirv-val"))) {
      __builtin_trap();
    }
    if (!compiled) {
      if (!spirv.empty()) __builtin_trap();
      continue;
    }
    std::string hlsl;
    std::string msl;
    messages.clear();
    if (!SpirvToMsl(spirv, &msl, &messages) || msl.empty()) __builtin_trap();
    if (!SpirvToHlsl(spirv, &hlsl, &messages)) {
      if (!OnlyKnown(messages, "spirv-cross", kHlslLimits)) __builtin_trap();
    } else if (hlsl.empty() || !ValidateHlsl(hlsl, stage, &messages)) {
      // ValidateHlsl refusing SPIRV-Cross's HLSL: a gap in glslang's HLSL front end (or in
      // SPIRV-Cross), which the validator would report on a correct translation.
      __builtin_trap();
    }
    CheckMessages(messages);
  }
  return 0;
}
