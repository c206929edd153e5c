// The GLSL 1.10 emitter: translates a checked ARB vertex or fragment program into a GLSL 1.10
// shader with the exact ARB semantics, and describes in a BindingMap every uniform, attribute
// and sampler the host must feed.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/arbvp/ir.h"
#include "arbiter/compiler/source.h"

namespace arbiter::arbvp {

// Test-only: the translator mutations (arbiter/arbvp/emit_mutation.h).
enum class Mutation : uint8_t;

// The GLSL dialect of the output (emit_targets.def; docs/guide/translate.md "Targets").
enum class EmitTarget : uint8_t {
#define ARBVP_EMIT_TARGET(name, ...) name,
#include "arbiter/arbvp/emit_targets.def"
#undef ARBVP_EMIT_TARGET
};
// The --target spelling ("glsl330"); LookupEmitTarget reads it back.
std::string_view EmitTargetName(EmitTarget target);
bool LookupEmitTarget(std::string_view name, EmitTarget* target);
// The dialect as refusals name it ("GLSL ES 1.00").
std::string_view EmitTargetTitle(EmitTarget target);

// Where GL state comes from: GLSL 1.10 built-ins (gl_ModelViewMatrix, gl_Vertex, gl_TexCoord),
// or named uniforms, attributes with locations and named varyings (forced for the targets
// without built-in state).
enum class StateSource : uint8_t { Builtins, Uniforms };

struct EmitOptions {
  EmitTarget target = EmitTarget::Glsl110;
  StateSource state = StateSource::Builtins;
  // Precede each statement with the ARB instruction it translates, as a `//` comment (the
  // instruction's source text when a SourceFile is given).
  bool comments = true;

 private:
  // Test-only: an injected translator bug, which only emit_mutation.h's WithMutation sets.
  Mutation mutation_{};  // Mutation::None
  friend EmitOptions WithMutation(EmitOptions options, Mutation mutation);
  friend Mutation MutationOf(const EmitOptions& options);
};

// Whether the translation reads state from uniforms (options.state, or forced by the target).
bool UsesStateUniforms(const EmitOptions& options);

// ---------------------------------------------------------------------------------------
// The binding map: what the host must feed to the translated shader(s).

// A user `attribute vec4` standing for a vertex attribute without a GLSL 1.10 built-in.
struct AttributeBinding {
  std::string name;     // GLSL name ("arb_attrib3")
  int location = -1;    // glBindAttribLocation index; -1: any (no ARB alias)
  std::string binding;  // ARB spelling ("vertex.attrib[3]")
};

// A `uniform vec4 NAME[size]` array holding program.env or program.local of one target.
struct ParameterArray {
  std::string name;  // "arb_vp_env"
  ProgramKind target = ProgramKind::Vertex;
  bool local = false;  // program.local (else program.env)
  int size = 0;        // element i = program.{env,local}[i]
  int offset = -1;     // in a uniform block: the std140 byte offset (array stride 16)
};

// A sampler uniform for one texture unit.
struct SamplerBinding {
  std::string name;  // "arb_texture0"
  int unit = 0;
  TexTarget target = TexTarget::Tex2D;
  std::string type;  // GLSL sampler type ("sampler2D")
  int binding = -1;  // Vulkan: the descriptor binding in set 0 (-1: none)
};

// Whether the host uploads the texture of `s` as a 2D texture: a 1D or rectangle target that
// the dialect emulates with a 2D sampler (1D: N x 1; rectangle: W x H without levels;
// docs/guide/translate.md, "Emulated samplers").
inline bool UploadsAs2D(const SamplerBinding& s) {
  const bool one_d = s.target == TexTarget::Tex1D || s.target == TexTarget::Shadow1D;
  const bool rect = s.target == TexTarget::Rect || s.target == TexTarget::ShadowRect;
  return (one_d || rect) && s.type.rfind("sampler2D", 0) == 0 &&
         s.type.find("Rect") == std::string::npos;
}

// A uniform standing for GL state that GLSL 1.10 has no built-in for (program matrices,
// modelview[n>0], palette matrices, clip planes beyond gl_MaxClipPlanes' minimum...).
struct StateUniform {
  std::string name;     // "arb_matrix_program0"
  std::string type;     // "mat4" (column-major, as glUniformMatrix4fv without transpose) or "vec4"
  std::string binding;  // ARB spelling of the state ("state.matrix.program[0].inverse")
  int offset = -1;      // in a uniform block: the std140 byte offset (-1: a plain uniform)
  std::string block = "";  // the UniformBlock holding it ("" for a plain uniform)
};

// Vulkan: the std140 uniform block (set 0) holding a stage's parameters and state.
struct UniformBlock {
  std::string name;  // "ArbVertexUniforms"
  ProgramKind stage = ProgramKind::Vertex;
  int set = 0;
  int binding = 0;
  int size = 0;  // bytes
};

// How an ARB register maps onto GLSL (read registers and written results).
struct RegisterMapping {
  std::string binding;  // ARB spelling ("result.fogcoord", "fragment.texcoord[1]")
  std::string glsl;     // GLSL expression ("gl_FogFragCoord", "gl_TexCoord[1]")
  ProgramKind stage = ProgramKind::Vertex;
  int location = -1;  // Vulkan: the varying's location (-1: matched by name)
};

struct BindingMap {
  std::string target = "glsl110";  // EmitTargetName
  bool state_uniforms = false;     // state as uniforms (else GLSL 1.10 built-ins)
  std::vector<UniformBlock> blocks;
  std::vector<AttributeBinding> attributes;
  std::vector<ParameterArray> parameters;
  std::vector<SamplerBinding> samplers;
  std::vector<StateUniform> state;
  std::vector<RegisterMapping> inputs;   // attributes the program reads
  std::vector<RegisterMapping> outputs;  // results the program writes
  // Choices for cases the specs leave undefined, so that a verifier knows what to expect.
  bool relative_out_of_range_reads_zero = true;  // a[A0.x + k] outside the array: vec4(0.0)
  float xpd_w = 1.0f;                            // XPD writes w = 1.0 when w is in the mask
  float scs_z = 0.0f;                            // SCS writes (cos, sin, 0.0, 1.0)
  float scs_w = 1.0f;
  bool temporaries_start_zero = true;  // TEMPs are vec4(0.0) before their first write
  std::string mutation = "none";       // the injected test mutation, if any
};

// The binding map as JSON text (stable key order, 2-space indent, final newline).
std::string BindingMapToJson(const BindingMap& map);

// ---------------------------------------------------------------------------------------
// Translation.

// The first instruction GLSL 1.10 cannot express exactly, which the translation refuses:
// the NV pack and unpack instructions (PK2H ... UP4UB) form or read the bits of a float,
// and GLSL 1.10 has no bit casts. `what` is empty when the program translates.
struct Untranslatable {
  std::string what;  // "PK2H needs the bits of a float (floatBitsToUint, GLSL 3.30)"
  Range range;       // the instruction
};
Untranslatable FindUntranslatable(const Program& program);
// The same for options.target, whose dialect may lack more (1D and RECT textures in ES, ...):
// `what` then names the construct and the target.
Untranslatable FindUntranslatable(const Program& program, const EmitOptions& options);

struct Translation {
  std::string glsl;  // a vertex shader for a vertex program, a fragment shader otherwise
  BindingMap bindings;
};

struct PairTranslation {
  std::string vertex;    // GLSL vertex shader
  std::string fragment;  // GLSL fragment shader
  BindingMap bindings;   // merged: both stages' uniforms, attributes and samplers
};

// Translates one checked program (CheckResult::ok). `source` (optional) is the program's
// text, quoted in the comments; the output is byte-identical for identical input.
Translation EmitGlsl(const Program& program, const EmitOptions& options,
                     const compiler::SourceFile* source);

// Translates a vertex and a fragment program for one GLSL program object: the varyings
// match (gl_TexCoord is declared with the same size in both shaders) and the binding map is
// merged (program.env/local keep one array per target).
PairTranslation EmitGlslPair(const Program& vertex, const Program& fragment,
                             const EmitOptions& options, const compiler::SourceFile* vertex_source,
                             const compiler::SourceFile* fragment_source);

}  // namespace arbiter::arbvp
