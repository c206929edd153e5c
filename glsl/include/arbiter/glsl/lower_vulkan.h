// GLSL 1.10 and 1.20 lowered to Vulkan GLSL 4.50, for running a shader on a Vulkan driver
// (runtime/glsl_vulkan.h) as a second engine beside Mesa's GL. The lowering rewrites
// glslang's preprocessed text token by token: every built-in variable of the fixed-function
// interface becomes a plain global or uniform named "arb_gl_<name>", attributes and varyings
// become plain globals (the caller's generated main feeds and reads them), the user's main
// becomes arb_main, the 1.10 lookup functions become 4.50's, and user identifiers that 4.50
// reserves are renamed. What cannot be lowered exactly is refused with a reason.
// docs/exec.md, "GLSL shaders".
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "arbiter/glsl/check.h"

namespace arbiter::glsl {

struct LoweredShader {
  // "#version 450", the built-in declarations, then the shader's declarations and functions
  // with its main named arb_main; no main (the caller appends one that calls arb_main).
  std::string text;
  // "not applicable: <construct>" when the shader cannot be lowered exactly; text is then
  // empty.
  std::string not_applicable;
  // Built-in uniforms the shader reads, by their GLSL names ("gl_LightSource"), each
  // declared as a uniform named LoweredIdentifier(name).
  std::vector<std::string> state;
  // Samplers read by shadow lookups: each has a vec4 uniform "arb_depthmode_<lowered name>"
  // that selects what the lookup returns (glstate::DepthModeSelector of its unit).
  std::vector<std::string> shadow_samplers;
};

// Lowers one shader of `stage`, as arbiter checked it (#version 110 or 120 or none).
LoweredShader LowerForVulkan(Stage stage, std::string_view text);

// The name an identifier of a 1.10/1.20 shader has in lowered text: "arb_gl_<x>" for the
// built-in "gl_<x>", "arb_u_<x>" for a user identifier that 4.50 reserves or names a built-in
// function ("texture", "sample", "filter") or that starts with "arb_"; itself otherwise.
std::string LoweredIdentifier(std::string_view name);

// A lowered pair (or one stage: the other's text empty, each text complete with its main)
// compiled for Vulkan 1.1 / SPIR-V 1.3 by glslang with the relaxed Vulkan rules: the loose
// uniforms of each stage in a std140 block of its own at set 0, binding
// kVertexUniformBinding or kFragmentUniformBinding, samplers at automatically mapped
// bindings of set 0 (the same binding for the same name in both stages).
inline constexpr int kVertexUniformBinding = 28;
inline constexpr int kFragmentUniformBinding = 29;

struct CompiledUniform {
  std::string name;        // the lowered name as glslang reflects it: "m", "l.pos", "w[0]"
  int offset = -1;         // in its stage's block (bytes)
  int array_size = 1;      // elements
  int array_stride = 0;    // bytes between elements
  int matrix_stride = 16;  // bytes between the columns of a matrix
  std::string type;        // the GLSL type ("vec3", "mat3", "sampler2D")
  int binding = -1;        // samplers: the binding in set 0
  bool fragment = false;   // in the fragment stage's block (else the vertex stage's)
};

struct CompiledPair {
  std::vector<uint32_t> vertex;    // SPIR-V (empty when that stage was not given)
  std::vector<uint32_t> fragment;  // idem
  int vertex_block_size = 0;       // bytes of each stage's uniform block (0: none)
  int fragment_block_size = 0;
  std::vector<CompiledUniform> uniforms;  // both blocks' members and the samplers
};

// False with glslang's messages in `error` when the texts do not compile or link.
[[nodiscard]] bool CompileLoweredPair(const std::string& vertex, const std::string& fragment,
                                      CompiledPair* out, std::string* error);

}  // namespace arbiter::glsl
