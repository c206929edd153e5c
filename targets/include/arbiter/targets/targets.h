// The modern back ends (docs/targets.md): GLSL 4.50 (Vulkan) to a SPIR-V module with glslang,
// SPIR-V validation with SPIRV-Tools, SPIR-V to HLSL (shader model 5.0) and MSL (2.0, macOS)
// with SPIRV-Cross, and a validator for every target's output text.
//
// Every function returns true on success and appends what the tool said to `messages` (errors
// on failure; warnings may come with success). Nothing throws and no input crashes: SPIR-V is
// validated before SPIRV-Cross reads it.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace arbiter::targets {

enum class Stage { Vertex, Fragment };

// The GLSL dialects arbiter writes, each a version and profile that ValidateGlsl holds the text
// to (the text's #version must say the same; GLSL 1.10 may omit it).
enum class GlslDialect {
  Glsl110,      // #version 110 (OpenGL 2.0)
  Glsl120,      // #version 120 (OpenGL 2.1)
  Glsl330Core,  // #version 330 core (OpenGL 3.3 core profile)
  Es100,        // #version 100 (OpenGL ES 2.0, WebGL 1)
  Es300,        // #version 300 es (OpenGL ES 3.0, WebGL 2)
  Vulkan450,    // #version 450 with Vulkan semantics (the input of CompileGlslToSpirv)
};

struct Message {
  enum class Severity { Error, Warning };
  Severity severity = Severity::Error;
  // Which tool said it: "glslang", "spirv-val" or "spirv-cross".
  std::string tool;
  // 1-based line in the input text; 0 when the message has no line (link errors, SPIR-V).
  int line = 0;
  // The tool's message without its location prefix.
  std::string text;
};

// "<tool>: line N: error: text" (no line part when `line` is 0).
std::string FormatMessage(const Message& message);

// Compiles GLSL 4.50 with Vulkan semantics (entry point main) to a SPIR-V 1.0 module for
// Vulkan 1.0, then validates it (ValidateSpirv); `spirv` is set only on success.
bool CompileGlslToSpirv(std::string_view glsl, Stage stage, std::vector<uint32_t>* spirv,
                        std::vector<Message>* messages);

// spirv-val's rules for Vulkan 1.0 (SPIRV-Tools' validator, as a library).
bool ValidateSpirv(std::span<const uint32_t> spirv, std::vector<Message>* messages);

// HLSL for shader model 5.0 (fxc, Direct3D 11), entry point main. The module is validated
// first. Names: variables and blocks keep their GLSL names; stage inputs and outputs get the
// semantic TEXCOORD<location> (fragment outputs SV_Target<location>); a uniform block at
// binding B is register(bB), a combined sampler at binding B a texture at register(tB) and a
// sampler `_<name>_sampler` at register(sB); the push constant block is register(b13)
// (kHlslPushConstantRegister, the last of Direct3D 11's 14 constant buffer slots). Block members
// are `<instance>_<member>`. Descriptor sets are ignored (SM 5.0 has no register spaces).
bool SpirvToHlsl(std::span<const uint32_t> spirv, std::string* hlsl,
                 std::vector<Message>* messages);
inline constexpr uint32_t kHlslPushConstantRegister = 13;

// Metal Shading Language 2.0 for macOS, entry point main0 (main is reserved in MSL). The module
// is validated first. At location L, vertex inputs are [[attribute(L)]], varyings
// [[user(locnL)]] and fragment outputs [[color(L)]]; a uniform block at binding B is
// [[buffer(B)]], a combined sampler `<name>` at binding B is [[texture(B)]] and `<name>Smplr`
// [[sampler(B)]];
// the push constant block is [[buffer(30)]] (kMslPushConstantBuffer, the last of Metal's 31
// buffer slots). Descriptor sets are ignored.
bool SpirvToMsl(std::span<const uint32_t> spirv, std::string* msl, std::vector<Message>* messages);
inline constexpr uint32_t kMslPushConstantBuffer = 30;

// The dialect of arbiter translate's --target spelling ("glsl330", "es300", "vk450", ...);
// none for the targets that are not GLSL ("spirv", "hlsl", "msl") or unknown names.
std::optional<GlslDialect> GlslDialectNamed(std::string_view name);

// glslang accepts `glsl` as a shader of `stage` in `dialect` (compiled and linked alone).
bool ValidateGlsl(std::string_view glsl, Stage stage, GlslDialect dialect,
                  std::vector<Message>* messages);

// glslang's HLSL front end accepts `hlsl` as a shader of `stage` with entry point main
// (compiled and linked alone). There is no MSL validator: see docs/targets.md.
bool ValidateHlsl(std::string_view hlsl, Stage stage, std::vector<Message>* messages);

}  // namespace arbiter::targets
