// Internal state of the GLSL emitter and the functions its files share.
#pragma once

#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "arbiter/arbvp/emit.h"
#include "arbiter/arbvp/ir.h"

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
enum class Helper : uint8_t { Lit, Exp, Log, Half };

// Where an instruction's result goes in GLSL.
struct DestTarget {
  std::string lvalue;
  // -1: a vec4 destination written through the write mask; otherwise a float destination
  // that takes this one component of the ARB result (fogcoord/pointsize: x, depth: z).
  int scalar_component = -1;
};

struct Context {
  Context(const Program& p, const EmitOptions& o, const compiler::SourceFile* s)
      : program(p), options(o), source(s), mutation(o.mutation) {}

  const Program& program;
  const EmitOptions& options;
  const compiler::SourceFile* source;
  Mutation mutation;

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
  bool needs_rect = false;
  // OPTION ARB_fog_*: result.color[n] goes to FogColorName(n), fogged at the end of main.
  bool fog_redirect = false;
  std::set<int> fog_colors;  // the result.color[n] written
};

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
// Reads `comps` of the instruction-vector positions of `src` (swizzle, negation, relative
// addressing, constants folded).
Expr Source(Context& ctx, const SrcOperand& src, const Comps& comps);
// One component of a SWZ operand (0, 1 or a signed component).
std::string SwizzleComponent(Context& ctx, const SrcOperand& src, int comp);
// Writes the instruction's result through its write mask (and _SAT): `value(comps)` gives
// the result components listed.
template <typename F>
std::string Assign(Context& ctx, const Instruction& inst, F value);
std::string AssignImpl(Context& ctx, const Instruction& inst,
                       const std::function<Expr(const Comps&)>& value);

// emit_instructions.cpp: one GLSL statement (or a few) per ARB instruction.
std::string EmitInstruction(Context& ctx, const Instruction& inst);

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
