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

namespace arbiter::arbvp {

using compiler::Range;

enum class ProgramKind : uint8_t { Vertex, Fragment };

// ---------------------------------------------------------------------------------------
// Opcodes (one row each in opcodes.def).

enum class Opcode : uint8_t {
#define ARBVP_OPCODE(name, stages, signature, klass, spec) name,
#include "arbiter/arbvp/opcodes.def"
#undef ARBVP_OPCODE
};

enum class OpStages : uint8_t { Vp = 1, Fp = 2, VpFp = 3 };
enum class OpSignature : uint8_t { Vector, Scalar, BinSc, Binary, Ternary, Swz, Arl, Sample, Kil };
enum class OpClass : uint8_t { Alu, Tex };

struct OpcodeInfo {
  Opcode op;
  std::string_view name;
  OpStages stages;
  OpSignature signature;
  OpClass klass;
  std::string_view spec;
};

const OpcodeInfo& GetOpcodeInfo(Opcode op);
// All opcodes in table order.
const std::vector<OpcodeInfo>& AllOpcodes();
// Looks an opcode up by its name without `_SAT`; returns false if unknown.
bool LookupOpcode(std::string_view name, Opcode* op);
bool OpcodeInStage(Opcode op, ProgramKind kind);
// Number of source operands the signature takes (the texture unit is not one).
int SourceCount(OpSignature signature);

// ---------------------------------------------------------------------------------------
// Options (one row each in options.def).

enum class OptionId : uint8_t {
#define ARBVP_OPTION(name, spelling, stages, group, same_as, spec) name,
#include "arbiter/arbvp/options.def"
#undef ARBVP_OPTION
};

struct OptionInfo {
  OptionId id;
  std::string_view spelling;  // "ARB_position_invariant"
  OpStages stages;
  std::string_view group;  // options of one non-empty group exclude each other ("fog")
  OptionId same_as;        // the option whose meaning it has (ATI_draw_buffers: DrawBuffers)
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

enum class FragmentAttrib : uint8_t { Color, SecondaryColor, TexCoord, FogCoord, Position };

enum class ResultReg : uint8_t {
  // vertex programs
  Position,
  Color,  // with face and secondary flags
  FogCoord,
  PointSize,
  TexCoord,
  // fragment programs
  FragColor,  // index = draw buffer (0 for result.color)
  FragDepth,
};

enum class Face : uint8_t { Front, Back };

enum class StateItem : uint8_t {
  MaterialAmbient,
  MaterialDiffuse,
  MaterialSpecular,
  MaterialEmission,
  MaterialShininess,
  LightAmbient,
  LightDiffuse,
  LightSpecular,
  LightPosition,
  LightAttenuation,
  LightSpotDirection,
  LightHalf,
  LightModelAmbient,
  LightModelSceneColor,
  LightProdAmbient,
  LightProdDiffuse,
  LightProdSpecular,
  TexGenEye,     // coord = s t r q
  TexGenObject,  // coord = s t r q
  FogColor,
  FogParams,
  ClipPlane,
  PointSize,
  PointAttenuation,
  TexEnvColor,
  DepthRange,
  MatrixRow,  // matrix, modifier, row
};

enum class MatrixName : uint8_t { Modelview, Projection, Mvp, Texture, Palette, Program };
enum class MatrixModifier : uint8_t { None, Inverse, Transpose, InvTrans };

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

// The generic vertex attribute a vertex attribute binding occupies: its own index for
// vertex.attrib[n], the one a conventional attribute aliases in ARBvp table X.2.1
// (position 0, weight 1, normal 2, colour 3, secondary colour 4, fog 5, texcoord[n] 8+n),
// or -1 (weights beyond the first, matrix indices).
int GenericAttribSlot(const Binding& binding);

// ---------------------------------------------------------------------------------------
// Variables.

enum class VarKind : uint8_t { Attrib, Param, Temp, Address, Output };

struct Variable {
  std::string name;  // empty for a binding used directly in an instruction
  VarKind kind = VarKind::Temp;
  Range decl;  // the declared name, or the implicit binding's text
  bool is_array = false;
  std::vector<Binding> bindings;  // Attrib/Output: one; Param: one per element; else none
};

// ---------------------------------------------------------------------------------------
// Instructions.

// One source component selector: a component or, in SWZ, the constants 0 and 1.
enum class Swz : uint8_t { X, Y, Z, W, Zero, One };

struct SrcOperand {
  int var = -1;  // index into Program::vars
  bool negate = false;
  std::array<Swz, 4> swizzle{Swz::X, Swz::Y, Swz::Z, Swz::W};
  std::array<bool, 4> component_negate{false, false, false, false};  // SWZ only
  // Array access: element `index`, or (relative) A0.x + `index`.
  bool indexed = false;
  bool relative = false;
  int address_var = -1;
  int index = 0;
  Range range;
};

struct DstOperand {
  int var = -1;
  uint8_t mask = 0xF;  // bit 0 = x ... bit 3 = w
  Range range;
};

enum class TexTarget : uint8_t { Tex1D, Tex2D, Tex3D, Cube, Rect, Shadow1D, Shadow2D, ShadowRect };
std::string_view TexTargetName(TexTarget target);

struct Instruction {
  Opcode op = Opcode::MOV;
  bool saturate = false;
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

struct Program {
  ProgramKind kind = ProgramKind::Vertex;
  std::vector<Option> options;
  std::vector<Variable> vars;
  std::vector<Instruction> instructions;
  Range header;
  Range end;

  // Whether an option with `id`'s meaning is given (ATI_draw_buffers counts as ARB_draw_buffers).
  bool HasOption(OptionId id) const;
};

}  // namespace arbiter::arbvp
