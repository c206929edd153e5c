// Internal state of the GLSL emitter and the functions its files share.
#pragma once

#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "arbiter/arbvp/emit.h"
#include "arbiter/arbvp/emit_mutation.h"
#include "arbiter/arbvp/ir.h"
#include "emit/emit_target.h"

namespace arbiter::arbvp::emit {

// A GLSL expression of `width` float components (1: float, 2..4: vecN).
struct Expr {
  Expr() = default;
  Expr(std::string t, int w, bool a) : text(std::move(t)), width(w), atomic(a) {}

  std::string text;
  int width = 4;
  // Safe to follow with a swizzle or to use as an operand without parentheses (a name, a
  // call, an indexing, a constructor, a literal).
  bool atomic = true;
  // For a vec4 built from parts (vec4(gl_Normal, 1.0)): each component's own expression,
  // and the vec3 of the first three when there is one, so that reading .x or .xyz of it
  // stays short (gl_Normal.x, gl_Normal). Empty otherwise.
  std::vector<std::string> parts;
  std::string xyz;
};

// Component positions (0 = x ... 3 = w) an instruction must produce, ascending.
using Comps = std::vector<int>;

// Helper functions emitted before main() when a translation needs them.
// A helper's text may call those before it.
enum class Helper : uint8_t {
  Lit,
  Exp,
  Log,
  Half,
  RoundEven,
  Fp16,
  Fx12,
  Rcc,
  Rfl,
  Ssg,
  Pack,  // the PK* / UP* conversions (GLSL 3.30 bit operations)
};

// The conversion an NV_fragment_program precision suffix applies to operands and results
// (3.11.4.2): none (R, fp32), to fp16 (H), to fixed point s1.10 (X).
enum class Conversion : uint8_t { None, Fp16, Fx12 };

// How the body is laid out (emit_flow.cpp): straight-line statements; IF/LOOP/REP as GLSL
// if and for blocks; or a program-counter machine, one instruction per step.
enum class FlowMode : uint8_t { Straight, Structured, Machine };

// Where an instruction's result goes in GLSL.
struct DestTarget {
  std::string lvalue;
  // -1: a vec4 destination written through the write mask; otherwise a float destination
  // that takes this one component of the ARB result (fogcoord/pointsize: x, depth: z).
  int scalar_component = -1;
};

struct Context {
  Context(const Program& p, const EmitOptions& o, const compiler::SourceFile* s)
      : program(p),
        options(o),
        source(s),
        mutation(MutationOf(o)),
        target(GetDialectRow(o.target)),
        uniforms(UsesStateUniforms(o)) {}

  const Program& program;
  const EmitOptions& options;
  const compiler::SourceFile* source;
  Mutation mutation;
  // The dialect (emit_targets.def) and whether state is read from uniforms (state_uniforms.cpp).
  const DialectRow& target;
  bool uniforms;

  bool Mutated(Mutation m) const { return mutation == m; }
  bool IsVertex() const { return program.kind == ProgramKind::Vertex; }

  // Per variable: its GLSL name (TEMP, ADDRESS, relatively addressed PARAM arrays).
  std::vector<std::string> var_names;
  // Per variable: read with relative addressing (becomes a global array + reader).
  std::vector<bool> relative;

  // What the body used; declarations are emitted from these after the body.
  int env_size = 0;
  int local_size = 0;
  std::map<int, TexTarget> samplers;                // unit -> target
  std::map<std::string, StateUniform> state;        // by GLSL name
  std::map<std::string, AttributeBinding> attribs;  // by GLSL name
  std::set<Helper> helpers;
  std::map<std::string, RegisterMapping> inputs;   // by ARB spelling
  std::map<std::string, RegisterMapping> outputs;  // by ARB spelling
  int texcoord_size = 0;                           // gl_TexCoord elements used (max index + 1)
  int texcoord_declared = 0;  // pair translation: redeclare gl_TexCoord with this size
  // Pair translation to GLSL ES of a position-invariant vertex program: the fragment shader
  // discards on the clipped side of the user clip planes (ClipDiscard).
  bool clip_discard = false;
  bool needs_rect = false;
  // OPTION ARB_fog_*: result.color[n] goes to FogColorName(n), fogged at the end of main.
  bool fog_redirect = false;
  std::set<int> fog_colors;  // the result.color[n] written

  // The NV options.
  // Locals the body needs besides the variables (condition codes, loop state), by name:
  // their declarations, emitted in name order.
  std::map<std::string, std::string> nv_locals;
  Conversion conversion = Conversion::None;  // of the instruction being emitted
  std::set<int> clip_distances;              // result.clip[n] written
  bool needs_texture_lod = false;            // GL_ARB_shader_texture_lod functions used
  FlowMode flow = FlowMode::Straight;
  int pc = 0;  // the index of the instruction being emitted
  // State as uniforms: the varyings a shader declares (vertex outputs, fragment inputs), name
  // -> type; the vertex colour outputs written (clamped at the end of main, as GL clamps
  // result.color); pair translation: the fragment inputs the vertex shader declares too.
  std::map<std::string, std::string> varyings;
  std::set<std::string> vertex_colors;
  std::map<std::string, std::string> pair_varyings;
  // Vulkan: the std140 offsets of the uniform block's members, and its size.
  std::map<std::string, int> block_offsets;
  int block_size = 0;
  std::vector<int> open_loops;  // Structured: the open LOOP blocks' numbers (A0.x: arb_a0_N)
  int loops = 0;                // Structured: LOOP and REP blocks so far
};

// NV implementation limits the translation enforces as the reference interpreter does:
// the minimums of NV_vertex_program2_option and NV_fragment_program2 (tables X.10, X.11).
// GLSL 1.10 guarantees gl_MaxClipPlanes >= 6 only: planes past that become uniforms, and the
// clip distances of OPTION ARB_position_invariant cover six.
inline constexpr int kGlslClipPlanes = 6;
inline constexpr int kMaxExecInstructions = 65536;  // MAX_PROGRAM_EXEC_INSTRUCTIONS_NV
inline constexpr int kMaxCallDepth = 4;             // MAX_PROGRAM_CALL_DEPTH_NV
inline constexpr int kMaxLoopDepth = 4;             // MAX_PROGRAM_LOOP_DEPTH_NV
inline constexpr int kMaxLoopCount = 255;           // MAX_PROGRAM_LOOP_COUNT_NV

// The local that holds result.color[n] before fog.
std::string FogColorName(const Context& ctx, int index);
// The GLSL output of result.color[n].
std::string FragColorName(const Context& ctx, int index);

// names.cpp: GLSL names for the program's variables (fills var_names and relative).
void AssignNames(Context& ctx);
// A valid, non-reserved GLSL identifier for an ARB identifier (not yet made unique).
std::string SanitizeName(const std::string& arb_name);

// glsl_text.cpp: literals and small expression builders.
std::string FormatFloat(float value);
std::string VecType(int width);  // "float", "vec2", ...
std::string Letters(const Comps& comps);
Comps AllComps();
// Selects `comps` of a vec4 expression: e, e.xz, (a + b).y.
Expr Select(const Expr& e4, const Comps& comps);
// Replicates a float expression to `width` components.
Expr Replicate(const Expr& scalar, int width);
// Builds a vector from one expression per component.
Expr Construct(const std::vector<std::string>& components);

// emit_bindings.cpp: reading bound registers and naming written results.
Expr ReadBinding(Context& ctx, const Binding& binding);
DestTarget ResultTarget(Context& ctx, const Binding& binding);
std::string EnvName(const Context& ctx, bool local);
std::string SamplerName(int unit);
std::string SamplerType(TexTarget target);

// emit_operands.cpp: source operands and destination writes.
// Reads `comps` of the instruction-vector positions of `src` (swizzle, |abs|, negation,
// relative addressing, constants folded, the NV precision conversion).
Expr Source(Context& ctx, const SrcOperand& src, const Comps& comps);
// One component of a SWZ operand (0, 1 or a signed component).
std::string SwizzleComponent(Context& ctx, const SrcOperand& src, int comp);
// Writes the instruction's result through its write mask (precision, _SAT, _SSAT, storage
// size, the NV condition codes): `value(comps)` gives the result components listed.
template <typename F>
std::string Assign(Context& ctx, const Instruction& inst, F value);
std::string AssignImpl(Context& ctx, const Instruction& inst,
                       const std::function<Expr(const Comps&)>& value);

// emit_instructions.cpp: one GLSL statement (or a few) per ARB instruction.
std::string EmitInstruction(Context& ctx, const Instruction& inst);

// emit_flow.cpp: the statements of main() for the program's instructions, laid out as its
// flow instructions need (sets ctx.flow).
std::string EmitBody(Context& ctx);

// emit_cc.cpp: the NV condition codes (one vec4 per register holding the last value
// written to each component: its sign is the code, NaN is UN) and the NV destination
// update (conditional write mask, C/C0/C1 update).
std::string CcName(Context& ctx, int reg);
// The test of `cc` on component `comp` of its swizzle ("arb_cc0.y > 0.0"; "true" for TR).
std::string CcComponentTest(Context& ctx, const CcTest& cc, int comp);
// Whether any component of the swizzled test holds (BRA, CAL, RET, BRK, IF, KIL).
std::string CcAnyTest(Context& ctx, const CcTest& cc);
// Whether the instruction writes through the NV destination update (a condition code test
// or update); else AssignImpl's plain assignment does.
bool NeedsCcWrite(const Instruction& inst);
// The writes of `result` (the final result components `comps`, through a vec4 local, an
// ivec4 one when `integer`) under the condition code test, and the condition code update.
// `lvalue(c)` is the destination of component c ("R0.x"; "gl_FragDepth" or "" for a float
// result register).
std::string CcWrite(Context& ctx, const Instruction& inst, const Comps& comps, const Expr& result,
                    const std::function<std::string(int)>& lvalue, bool integer);
// Declares an NV local once.
void DeclareLocal(Context& ctx, const std::string& name, const std::string& declaration);

// emit_precision.cpp: NV_fragment_program precision (3.11.4.2) and storage sizes.
// The conversion of an instruction's operands and result (its suffix, else its destination's
// size); Conversion::None outside NV fragment programs.
Conversion InstructionConversion(const Context& ctx, const Instruction& inst);
// `e` converted (arb_fp16(e), arb_fx12(e)); `e` itself for Conversion::None.
Expr Convert(Context& ctx, const Expr& e, Conversion conversion);
// The storage conversion of a write to `var` (SHORT: fp16) after one at `done`.
Conversion StorageConversion(const Context& ctx, int var, Conversion done);

// The GLSL of an address register component read by relative addressing (A0.x; the loop
// index in NV fragment programs).
std::string AddressComponent(const Context& ctx, const SrcOperand& src);

// emit_helpers.cpp: the text of helper functions and relative-address readers.
std::string HelperText(const Context& ctx, Helper helper);
std::string RelativeReaderName(const Context& ctx, int var);
std::string RelativeReaderText(const Context& ctx, int var);

// emit_comments.cpp: the ARB instruction as a comment.
std::string InstructionComment(const Context& ctx, const Instruction& inst);

template <typename F>
std::string Assign(Context& ctx, const Instruction& inst, F value) {
  return AssignImpl(ctx, inst, std::function<Expr(const Comps&)>(value));
}

}  // namespace arbiter::arbvp::emit
