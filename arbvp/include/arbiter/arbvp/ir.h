// The IR of an ARB vertex or fragment program: resolved variables and bindings, and
// instructions with explicit swizzles and masks. Shared by the checker, the reference
// interpreter, the GLSL emitter and `arbiter info`.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/compiler/source.h"
#include "arbiter/glstate/state_items.h"

namespace arbiter::arbvp {

using compiler::Range;

enum class ProgramKind : uint8_t { Vertex, Fragment };

// ---------------------------------------------------------------------------------------
// Opcodes (one row each in opcodes.def).

enum class Opcode : uint8_t {
#define ARBVP_OPCODE(name, vp, fp, signature, klass, vp_mods, fp_mods, fp2_mods, reads, spec) name,
#include "arbiter/arbvp/opcodes.def"
#undef ARBVP_OPCODE
};

enum class OpStages : uint8_t { Vp = 1, Fp = 2, VpFp = 3 };
// Where a program kind has an opcode: not at all, in the ARB extension, or with the first
// (Nv: NV_vertex_program2, NV_fragment_program) or second (Nv2: NV_vertex_program3,
// NV_fragment_program2) NV option.
enum class OpLevel : uint8_t { No, Arb, Nv, Nv2 };
enum class OpSignature : uint8_t {
  Vector,
  Scalar,
  BinSc,
  Binary,
  Ternary,
  Swz,
  Arl,
  Sample,
  Kil,
  VecSca,
  Ara,
  Arr,
  PushA,
  PopA,
  TexD,
  Branch,
  FlowCc,
  If,
  Loop,
  EndFlow,
};
enum class OpClass : uint8_t { Alu, Tex, Flow };

struct OpcodeInfo {
  Opcode op;
  std::string_view name;
  OpLevel vp;
  OpLevel fp;
  OpSignature signature;
  OpClass klass;
  std::string_view vp_mods;   // "C", "S" of NV_vertex_program3's table X.5
  std::string_view fp_mods;   // "R", "H", "X", "C", "S" of NV_fragment_program_option's
  std::string_view fp2_mods;  // ... and of NV_fragment_program2's
  std::string_view reads;     // the components each source reads (opcodes.def)
  std::string_view spec;
};

const OpcodeInfo& GetOpcodeInfo(Opcode op);
// All opcodes in table order.
const std::vector<OpcodeInfo>& AllOpcodes();
// Looks an opcode up by its bare name (no suffixes); returns false if unknown.
bool LookupOpcode(std::string_view name, Opcode* op);
// Whether the ARB extension of `kind` has the opcode (no NV option).
bool OpcodeInStage(Opcode op, ProgramKind kind);
OpLevel OpcodeLevel(Opcode op, ProgramKind kind);
// Number of source operands the signature takes (the texture unit is not one).
int SourceCount(OpSignature signature);

// ---------------------------------------------------------------------------------------
// Options (one row each in options.def).

enum class OptionId : uint8_t {
#define ARBVP_OPTION(name, spelling, stages, group, implies, spec) name,
#include "arbiter/arbvp/options.def"
#undef ARBVP_OPTION
};

struct OptionInfo {
  OptionId id;
  std::string_view spelling;  // "ARB_position_invariant"
  OpStages stages;
  std::string_view group;  // options of one non-empty group exclude each other ("fog")
  OptionId implies;        // an option it includes (ATI_draw_buffers: ARB_draw_buffers)
  std::string_view spec;
};
const OptionInfo& GetOptionInfo(OptionId id);
const std::vector<OptionInfo>& AllOptions();
bool LookupOption(std::string_view spelling, OptionId* id);

struct Option {
  OptionId id;
  Range range;  // the option's identifier
};

// ---------------------------------------------------------------------------------------
// Bindings: what a variable (or one element of a PARAM array) is bound to.

enum class BindingKind : uint8_t {
  VertexAttrib,    // vertex.*
  FragmentAttrib,  // fragment.*
  Result,          // result.*
  State,           // state.* (one vector; matrices are expanded to rows)
  ProgramEnv,      // program.env[index]
  ProgramLocal,    // program.local[index]
  Constant,        // an inline or declared constant vector
};

enum class VertexAttrib : uint8_t {
  Position,
  Weight,
  Normal,
  Color,  // primary colour
  SecondaryColor,
  FogCoord,
  TexCoord,
  MatrixIndex,
  Generic,  // vertex.attrib[n]
};

// Facing: fragment.facing of NV_fragment_program2 (+1 front, -1 back).
enum class FragmentAttrib : uint8_t { Color, SecondaryColor, TexCoord, FogCoord, Position, Facing };

enum class ResultReg : uint8_t {
  // vertex programs
  Position,
  Color,  // with face and secondary flags
  FogCoord,
  PointSize,
  TexCoord,
  ClipDistance,  // result.clip[n] of NV_vertex_program2 (index = n)
  // fragment programs
  FragColor,  // index = draw buffer (0 for result.color)
  FragDepth,
};

// The GL state vocabulary (state_items.def) is glstate's, shared with the host library.
using glstate::Face;
using glstate::MatrixModifier;
using glstate::MatrixName;
using glstate::StateItem;

struct Binding {
  BindingKind kind = BindingKind::Constant;
  // VertexAttrib / FragmentAttrib / ResultReg / StateItem, as the kind says.
  VertexAttrib vertex_attrib = VertexAttrib::Position;
  FragmentAttrib fragment_attrib = FragmentAttrib::Color;
  ResultReg result = ResultReg::Position;
  StateItem state = StateItem::MaterialAmbient;
  Face face = Face::Front;
  bool secondary = false;  // result.color(.face).secondary
  // The selector: texture unit, light, clip plane, generic attribute, env/local index,
  // weight/matrix-index base, draw buffer; matrix number for modelview/palette/program/texture.
  int32_t index = 0;
  uint8_t coord = 0;  // texgen coordinate: 0 s, 1 t, 2 r, 3 q
  MatrixName matrix = MatrixName::Modelview;
  MatrixModifier modifier = MatrixModifier::None;
  uint8_t row = 0;
  std::array<float, 4> value{0.0f, 0.0f, 0.0f, 1.0f};  // Constant
  Range range;                                         // the binding's text
  Range selector;        // the index integer ([n]) that range checks point at; else == range
  Range row_sel;         // the row integer of .row[n] (MatrixRow)
  Range item;            // the word naming the item ("weight", "palette"), for feature errors
  bool indexed = false;  // the binding spelled its selector ("texcoord[0]", not "texcoord")
};

// The spelling of a binding as in the specs, e.g. "state.matrix.mvp.inverse.row[2]".
std::string BindingName(const Binding& binding, ProgramKind kind);
// The GL state a state binding reads, in the host library's terms.
glstate::StateRef StateRefOf(const Binding& binding);

// The generic vertex attribute a vertex attribute binding occupies: its own index for
// vertex.attrib[n], the one a conventional attribute aliases in ARBvp table X.2.1
// (position 0, weight 1, normal 2, colour 3, secondary colour 4, fog 5, texcoord[n] 8+n),
// or -1 (weights beyond the first, matrix indices).
int GenericAttribSlot(const Binding& binding);

// ---------------------------------------------------------------------------------------
// Variables.

enum class VarKind : uint8_t { Attrib, Param, Temp, Address, Output };

// The storage size NV_fragment_program gives TEMP and OUTPUT declarations (SHORT: fp16 at
// least, LONG: fp32; Default: the implementation's).
enum class VarSize : uint8_t { Default, Short, Long };

struct Variable {
  std::string name;  // empty for a binding used directly in an instruction
  VarKind kind = VarKind::Temp;
  VarSize size = VarSize::Default;
  Range decl;  // the declared name, or the implicit binding's text
  bool is_array = false;
  std::vector<Binding> bindings;  // Attrib/Output: one; Param: one per element; else none
  // An attribute or result array that a binding addresses relatively (NV_vertex_program3's
  // vertex.attrib[A0.x+n], vertex.texcoord[..] and result.texcoord[..];
  // NV_fragment_program2's fragment.texcoord[A0.x+n]): one binding per element.
  bool relative_array = false;
};

// ---------------------------------------------------------------------------------------
// Instructions.

// One source component selector: a component or, in SWZ, the constants 0 and 1.
enum class Swz : uint8_t { X, Y, Z, W, Zero, One };

// A condition code test of the NV options: <ccMaskRule> <swizzleSuffix>, e.g. "GT.xyzw" or,
// with NV_vertex_program3 / NV_fragment_program2's second register, "NE1.x".
enum class CcRule : uint8_t { EQ, GE, GT, LE, LT, NE, TR, FL };
struct CcTest {
  bool present = false;
  CcRule rule = CcRule::TR;
  uint8_t reg = 0;  // CC0 or CC1
  std::array<Swz, 4> swizzle{Swz::X, Swz::Y, Swz::Z, Swz::W};
  Range range;
};

struct SrcOperand {
  int var = -1;  // index into Program::vars
  bool negate = false;
  bool abs = false;  // |operand| of the NV options: the absolute value, then the negation
  std::array<Swz, 4> swizzle{Swz::X, Swz::Y, Swz::Z, Swz::W};
  std::array<bool, 4> component_negate{false, false, false, false};  // SWZ only
  // Array access: element `index`, or (relative) A0.x + `index`.
  bool indexed = false;
  bool relative = false;
  int address_var = -1;
  uint8_t address_component = 0;  // A0.x (0) ... A0.w (3): NV address registers are vectors
  int index = 0;
  Range range;
};

struct DstOperand {
  int var = -1;
  uint8_t mask = 0xF;  // bit 0 = x ... bit 3 = w
  CcTest cc;           // NV conditional write mask: "R0.xy (GT.x)" writes where the test holds
  // result.texcoord[A0.x + index] (NV_vertex_program3): element A0.x + index of a
  // relative_array output.
  bool relative = false;
  int address_var = -1;
  uint8_t address_component = 0;
  int index = 0;
  Range range;
};

// The arithmetic precision an NV_fragment_program opcode suffix asks for (R fp32, H fp16,
// X fixed point s1.10); Default: the destination's.
enum class Precision : uint8_t { Default, R, H, X };

enum class TexTarget : uint8_t {
#define ARBVP_TEX_TARGET(name, ...) name,
#include "arbiter/arbvp/texture_targets.def"
#undef ARBVP_TEX_TARGET
};
bool TexTargetIsShadow(TexTarget target);
std::string_view TexTargetName(TexTarget target);
// The coordinate components a target reads (x; xy; xyz; the shadow targets add the depth
// reference: SHADOW1D x and z).
uint8_t TexTargetCoordMask(TexTarget target);

struct Instruction {
  Opcode op = Opcode::MOV;
  bool saturate = false;         // _SAT: [0, 1]
  bool signed_saturate = false;  // _SSAT (NV_fragment_program2): [-1, 1]
  Precision precision = Precision::Default;
  int8_t cc_update = -1;  // the condition code register a C / C0 / C1 suffix updates; -1 none
  // Branch, FlowCc, If and the KIL <ccTest> form: the condition (BRA, CAL, RET, BRK: optional).
  CcTest cond;
  // Branch: the label and the index of the instruction it marks (instructions.size() for a
  // label before END). If: its ELSE or ENDIF; ELSE: its ENDIF; LOOP/REP: its ENDLOOP/ENDREP;
  // ENDLOOP/ENDREP: its LOOP/REP; BRK: the ENDLOOP/ENDREP of the loop it leaves. -1 unset.
  std::string label;
  Range label_range;
  int jump = -1;
  DstOperand dst;  // unused by KIL
  std::array<SrcOperand, 3> src{};
  uint8_t src_count = 0;
  int tex_unit = 0;  // Sample
  TexTarget target = TexTarget::Tex2D;
  Range range;  // the whole instruction, opcode to last operand
  Range opcode_range;
  Range unit_range;    // Sample: the texture unit (or the 'texture' keyword)
  Range target_range;  // Sample: the target
};

// A label of the NV options ("loop:"), before instruction `index`.
struct Label {
  std::string name;
  int index = 0;
  Range range;
};

struct Program {
  ProgramKind kind = ProgramKind::Vertex;
  std::vector<Option> options;
  std::vector<Variable> vars;
  std::vector<Instruction> instructions;
  std::vector<Label> labels;
  Range header;
  Range end;

  // Whether option `id` is given or included in one given (ATI_draw_buffers includes
  // ARB_draw_buffers, NV_vertex_program3 NV_vertex_program2).
  bool HasOption(OptionId id) const;
  // The NV option level: 0 none, 1 NV_vertex_program2 / NV_fragment_program, 2
  // NV_vertex_program3 / NV_fragment_program2.
  int NvLevel() const;
  bool Nv() const { return NvLevel() > 0; }
  // Whether this program has `op` (its kind and NV options).
  bool HasOpcode(Opcode op) const;
};

}  // namespace arbiter::arbvp
