// The GLSL dialects (emit_targets.def) and the state-as-uniforms translation: what the
// emitter's files ask of the target (emit_target.cpp, state_uniforms.cpp).
#pragma once

#include <string>
#include <string_view>

#include "arbiter/arbvp/emit.h"

namespace arbiter::arbvp::emit {

// One row of emit_targets.def.
struct DialectRow {
  EmitTarget id;
  std::string_view spelling;
  std::string_view version;
  std::string_view title;
  bool es;
  bool uniforms;
  std::string_view attribute;
  std::string_view vertex_out;
  std::string_view fragment_in;
  bool modern;
  bool outputs;
  bool locations;
  bool block;
  bool tex1d;
  bool rect;
  bool tex3d;
  bool shadow;
  bool shadow1d;
  std::string_view fragment_lod;  // "core", "ext" (GL_ARB_shader_texture_lod) or "" (none)
  bool draw_buffers;
  bool loops;
  bool coord_conventions;
  bool frag_position;
  std::string_view clip_planes;  // "distance", "enabled", "discard" or ""
  bool frag_coord_highp;
};

const DialectRow& GetDialectRow(EmitTarget target);

}  // namespace arbiter::arbvp::emit

namespace arbiter::arbvp::emit {

struct Context;
struct Expr;
struct DestTarget;

// sampler_emulation.cpp: the sampler type of `target` in the dialect, its own or the 2D one
// that emulates it (1D textures in GLSL ES, rectangle textures in ES 3.00 and Vulkan); and
// `text` with the lookups of emulated samplers rewritten as the 2D lookups standing for them.
std::string DialectSamplerType(const DialectRow& row, TexTarget target);
std::string EmulateSamplers(const DialectRow& row, const std::string& text);

// emit_target.cpp: the dialect's text from the GLSL 1.10 the emitter wrote (lookups,
// ES 1.00's gl_FragDepthEXT and extensions, ES precision statements).
std::string FinishForTarget(const Context& ctx, std::string text);

// state_uniforms.cpp: state as uniforms (EmitOptions::state, forced by the targets without
// GL 2.0 built-in state). Each returns false where the GLSL 1.10 translation stays.
// A state binding (not a matrix row) as one vec4 uniform named after its ARB spelling.
Expr ReadStateUniform(Context& ctx, const Binding& b);
// A vertex attribute as a vec4 input with a location (the ARB aliasing of generic attributes).
Expr VertexInput(Context& ctx, const Binding& b);
// A fragment attribute as a named varying (fragment.position and .facing stay built-ins).
bool FragmentInput(Context& ctx, const Binding& b, Expr* out);
// A vertex result as a named varying (result.clip[n] and fragment results stay as they are).
bool ResultOutput(Context& ctx, const Binding& b, DestTarget* out);
// The fog state the OPTION ARB_fog_* blend reads: "coord", "density", "start", "end", "color".
std::string FogField(Context& ctx, std::string_view field);
// The name of a uniform standing for the state spelled `spelling` ("state.light[0].diffuse"
// -> "arb_state_light0_diffuse").
std::string StateUniformName(std::string_view spelling);
// The statements ending main(): the vertex colours clamped to [0, 1] as GL clamps them.
std::string UniformsEpilogue(const Context& ctx);
// gl_Position of OPTION ARB_position_invariant: state.matrix.mvp times vertex.position, and
// the user clip planes as the dialect's clip_planes says.
std::string InvariantPosition(Context& ctx);
// The varyings that carry the clip distances to a GLSL ES fragment shader (planes 0-3, 4-5),
// and the discard that stands for the clipping there (Context::clip_discard).
inline constexpr const char* kClipVaryings[] = {"arb_user_clip0", "arb_user_clip1"};
std::string ClipDiscard(Context& ctx);
// The declarations of a shader reading state from uniforms: attributes with locations,
// varyings, uniforms (in a std140 block for Vulkan), samplers, fragment outputs.
std::string UniformsDeclarations(Context& ctx);
// Vulkan varying locations (by name, so that a pair's interfaces match).
int VaryingLocation(std::string_view name);
// Whether a later dialect (GLSL 1.20 to 4.50, ES 1.00 and 3.00) reserves `name` or declares
// it as a type or a function the translation calls (a variable of that name would hide it).
bool IsReservedLater(std::string_view name);

}  // namespace arbiter::arbvp::emit

namespace arbiter::arbvp::emit {
// Vulkan: the descriptor binding of a texture unit's sampler (-1 elsewhere) and of the
// stage's uniform block.
int SamplerBindingOf(const Context& ctx, int unit);
int BlockBindingOf(const Context& ctx);
}  // namespace arbiter::arbvp::emit
