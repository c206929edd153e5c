// The reference interpreter: operand loading (ARBvp 2.14.4.1-2.14.4.2, ARBfp 3.11.4.1),
// destination update with masks and _SAT (2.14.4.3, 3.11.4.3), the program options that
// change execution (ARB_position_invariant, ARB_fog_*), and the vertex -> fragment hand-off
// of a pair. The operations themselves are in ops.cpp, texture sampling in sample.cpp.
#include "arbiter/arbvp/interpret.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <map>
#include <tuple>

#include "arbiter/arbvp/deviations.h"
#include "arbiter/glstate/values.h"
#include "exec/machine.h"
#include "exec/nv_flow.h"
#include "exec/ops.h"
#include "exec/ops_nv.h"
#include "exec/precision.h"
#include "exec/state_internal.h"
#include "exec/tolerance.h"

namespace arbiter::arbvp {
namespace {

using exec::From;
using exec::kDefined;
using exec::kUnwritten;
using exec::Reasons;
using exec::Reg;
using exec::Val;
using D1 = std::array<double, 1>;
using D2 = std::array<double, 2>;

constexpr char kComponents[] = "xyzw";

std::string Where(const compiler::SourceFile* source, Range range) {
  if (!source) return {};
  compiler::LineCol lc = source->Locate(range.begin);
  return fmt::format(" at {}:{}", lc.line, lc.column);
}

// Result registers that are the same GL output, whatever variable or spelling bound them
// ("result.color" and "result.color[0]" are draw buffer 0).
using OutKey = std::tuple<ResultReg, Face, bool, int32_t>;
OutKey KeyOf(const Binding& b) {
  bool color = b.result == ResultReg::Color;
  return {b.result, color ? b.face : Face::Front, color && b.secondary, b.index};
}

struct Output {
  Binding binding;
  Reg value{};
  uint8_t written = 0;
};
using Outputs = std::map<OutKey, Output>;

const Output* FindOutput(const Outputs& outputs, ResultReg reg, int32_t index = 0,
                         bool secondary = false) {
  auto it = outputs.find(OutKey{reg, Face::Front, secondary, index});
  return it == outputs.end() ? nullptr : &it->second;
}

// The fragment attributes of one run: given (a fragment program alone) or produced by the
// vertex program of a pair.
struct FragmentSource {
  Reg color{};
  Reg secondary{};
  std::array<Reg, kMaxTextureCoords> texcoord{};
  Val fogcoord;
  Reg position{};
};

FragmentSource FromFragmentInput(const FragmentInput& in, size_t vector_index, size_t count,
                                 FragCoordConvention convention) {
  FragmentSource f;
  f.color = exec::DefinedReg(in.color);
  f.secondary = exec::DefinedReg(in.secondary_color);
  for (size_t i = 0; i < f.texcoord.size(); ++i) f.texcoord[i] = exec::DefinedReg(in.texcoord[i]);
  f.fogcoord = exec::InputVal(in.fogcoord);
  const auto [x, y] = FragmentCoordXY(vector_index, count, convention);
  f.position = exec::DefinedReg({x, y, in.depth, 1.0f});
  // The window z goes through the depth range transform and a depth format.
  f.position[2].err = static_cast<float>(exec::kDepthPrecision);
  return f;
}

Vec4 Element(const std::array<Vec4, kMaxTextureCoords>& a, int32_t index) {
  if (index < 0 || index >= kMaxTextureCoords) return {0.0f, 0.0f, 0.0f, 1.0f};
  return a[static_cast<size_t>(index)];
}

// Table X.2 of ARBvp: the components each vertex attribute binding reads.
Reg VertexAttribValue(const Binding& b, const VertexInput& in) {
  switch (b.vertex_attrib) {
    case VertexAttrib::Position:
      return exec::DefinedReg(in.position);
    case VertexAttrib::Weight:
      // Only weights 0-3 are modelled; the others read as unsupported weights (0,0,0,1).
      return exec::DefinedReg(b.index == 0 ? in.weight : Vec4{0.0f, 0.0f, 0.0f, 1.0f});
    case VertexAttrib::Normal:
      return exec::DefinedReg({in.normal[0], in.normal[1], in.normal[2], 1.0f});
    case VertexAttrib::Color:
      return exec::DefinedReg(in.color);
    case VertexAttrib::SecondaryColor:
      // GL 2.0 2.7: the secondary colour has only three-value commands; its A is always 1.
      return exec::DefinedReg(
          {in.secondary_color[0], in.secondary_color[1], in.secondary_color[2], 1.0f});
    case VertexAttrib::FogCoord:
      return exec::DefinedReg({in.fogcoord[0], 0.0f, 0.0f, 1.0f});
    case VertexAttrib::TexCoord:
      return exec::DefinedReg(Element(in.texcoord, b.index));
    case VertexAttrib::MatrixIndex:
      return exec::DefinedReg(b.index == 0 ? in.matrix_index : Vec4{0.0f, 0.0f, 0.0f, 1.0f});
    case VertexAttrib::Generic:
      // "vertex.attrib[0]" and "vertex.position" are equivalent.
      if (b.index == 0) return exec::DefinedReg(in.position);
      if (b.index < 0 || b.index >= kMaxGenericAttribs) {
        return exec::DefinedReg({0.0f, 0.0f, 0.0f, 1.0f});
      }
      return exec::DefinedReg(in.generic[static_cast<size_t>(b.index)]);
  }
  return exec::DefinedReg({0.0f, 0.0f, 0.0f, 1.0f});
}

// Table X.1 of ARBfp.
Reg FragmentAttribValue(const Binding& b, const FragmentSource& f) {
  switch (b.fragment_attrib) {
    case FragmentAttrib::Color:
      return f.color;
    case FragmentAttrib::SecondaryColor:
      return f.secondary;
    case FragmentAttrib::TexCoord:
      if (b.index < 0 || b.index >= kMaxTextureCoords) {
        return exec::DefinedReg({0.0f, 0.0f, 0.0f, 1.0f});
      }
      return f.texcoord[static_cast<size_t>(b.index)];
    case FragmentAttrib::FogCoord:
      return {f.fogcoord, Val{0.0f}, Val{0.0f}, Val{1.0f}};
    case FragmentAttrib::Position:
      return f.position;
    case FragmentAttrib::Facing: {  // NV_fragment_program2: +1 for the front-facing points drawn
      Reg facing = exec::DefinedReg({1.0f, 0.0f, 0.0f, 1.0f});
      facing[0].dev |= kDevPointFacingSoftpipe;
      return facing;
    }
  }
  return exec::DefinedReg({0.0f, 0.0f, 0.0f, 1.0f});
}

// State the driver derives (products, inverses, half vectors, cosines) carries its float32
// computation: kApprox of the largest element of the vector (of the whole matrix for a row).
float DerivedStateError(const GlState& state, const Binding& b) {
  bool derived = false;
  switch (b.state) {
    case StateItem::MatrixRow:
      derived = b.matrix == MatrixName::Mvp || b.modifier == MatrixModifier::Inverse ||
                b.modifier == MatrixModifier::InvTrans;
      break;
    case StateItem::LightSpotDirection:
    case StateItem::LightHalf:
    case StateItem::LightModelSceneColor:
    case StateItem::LightProdAmbient:
    case StateItem::LightProdDiffuse:
    case StateItem::LightProdSpecular:
    case StateItem::FogParams:
      derived = true;
      break;
    default:
      break;
  }
  if (!derived) return 0.0f;
  double largest = 0.0;
  Binding row = b;
  for (uint8_t r = 0; r < (b.state == StateItem::MatrixRow ? 4 : 1); ++r) {
    if (b.state == StateItem::MatrixRow) row.row = r;
    for (float v : ReadStateBinding(state, row)) {
      largest = std::max(largest, std::fabs(static_cast<double>(v)));
    }
  }
  return exec::RoundUp(exec::kApprox * largest);
}

double Clamp01(const D1& x) { return x[0] < 0.0 ? 0.0 : (x[0] > 1.0 ? 1.0 : x[0]); }

// One execution of one program on one input.
class Run {
 public:
  Run(const Program& program, const ExecInputs& inputs, const compiler::SourceFile* source,
      Reasons* reasons)
      : program_(program),
        inputs_(inputs),
        source_(source),
        reasons_(reasons),
        nv_(program, reasons) {}

  // Executes with the attribute values `attrib` (per variable, one per binding: an attribute
  // array read with relative addressing has several; only Attrib ones used).
  // An ARB program runs its instructions in order; one with an NV option follows its flow
  // instructions from the label "main" (nv_flow.h).
  void Execute(const std::vector<std::vector<Reg>>& attrib) {
    attrib_ = &attrib;
    Setup();
    const bool nv = program_.Nv();
    const int end = static_cast<int>(program_.instructions.size());
    int pc = nv ? nv_.Entry() : 0;
    while (pc >= 0 && pc < end) {
      const Instruction& inst = program_.instructions[static_cast<size_t>(pc)];
      const std::string where = Where(source_, inst.range);
      if (nv && !nv_.Count(where)) break;
      if (!Step(inst, where, &pc)) break;
    }
    FoldTaint();
  }

  Outputs& outputs() { return outputs_; }
  bool killed() const { return killed_; }
  // The reason whether the fragment was killed is undefined, or kDefined.
  int kill_why() const { return killed_defined_ ? kDefined : kill_why_; }
  bool kill_unstable() const { return kill_unstable_; }
  uint32_t kill_dev() const { return kill_dev_; }

 private:
  const ProgramParameters& Params() const {
    return program_.kind == ProgramKind::Vertex ? inputs_.vertex_params : inputs_.fragment_params;
  }

  exec::OpContext Context(const Instruction& inst, const std::string& where) {
    exec::OpContext ctx;
    ctx.inst = &inst;
    ctx.kind = program_.kind;
    ctx.reasons = reasons_;
    ctx.where = where;
    ctx.textures = &inputs_.textures;
    ctx.shadow_option = program_.HasOption(OptionId::FragmentProgramShadow);
    ctx.killed = killed_;
    ctx.killed_defined = killed_defined_;
    ctx.kill_why = kill_why_;
    ctx.kill_unstable = kill_unstable_;
    ctx.kill_dev = kill_dev_;
    for (size_t s = 0; s < inst.src_count; ++s) ctx.src[s] = Load(inst.src[s], where);
    return ctx;
  }

  // Executes the instruction at *pc and moves *pc on; false when the program terminates.
  bool Step(const Instruction& inst, const std::string& where, int* pc) {
    exec::OpContext ctx = Context(inst, where);
    const OpClass klass = GetOpcodeInfo(inst.op).klass;
    if (klass == OpClass::Flow) return nv_.Step(inst, ctx.src[0], pc, where);
    ++*pc;
    switch (inst.op) {
      case Opcode::PUSHA:
        return nv_.Push(ctx.src[0], where);
      case Opcode::POPA: {
        Reg popped{};
        if (!nv_.Pop(&popped, where)) return false;
        Store(inst, popped, where);
        return true;
      }
      case Opcode::KIL:
        Kill(inst, ctx);
        return true;
      default:
        break;
    }
    const bool nv_arl = inst.op == Opcode::ARL && program_.Nv();
    Reg result = nv_arl ? exec::OpArlNv(ctx) : exec::Execute(inst.op, ctx);
    const Precision precision = OperationPrecision(inst);
    if (precision == Precision::H || precision == Precision::X) {
      result = exec::AtPrecision(inst.op, ctx, precision, result);
    }
    Store(inst, result, where);
    return true;
  }

  // KIL with an operand (ops.cpp) or, under the NV options, a condition code test. A KIL
  // reached through a flow decision on an undefined or unstable condition decides nothing
  // for sure.
  void Kill(const Instruction& inst, exec::OpContext& ctx) {
    const bool was_defined = killed_defined_;
    if (inst.cond.present) {
      const exec::CcOutcome o = exec::TestCcAny(inst.cond, nv_.cc(inst.cond.reg));
      killed_ = killed_ || o.pass;
      if (o.pass && o.certain()) killed_defined_ = true;
      if (!o.certain() && kill_why_ == kDefined) kill_why_ = o.why;
      kill_unstable_ = kill_unstable_ || o.unstable;
      kill_dev_ |= o.dev;
    } else {
      exec::Execute(inst.op, ctx);
      killed_ = ctx.killed;
      killed_defined_ = ctx.killed_defined;
      kill_why_ = ctx.kill_why;
      kill_unstable_ = ctx.kill_unstable;
      kill_dev_ = ctx.kill_dev;
    }
    const exec::Taint& t = nv_.taint();
    if (t.why != kDefined || t.unstable) {
      killed_defined_ = was_defined;
      if (kill_why_ == kDefined) kill_why_ = t.why;
      kill_unstable_ = kill_unstable_ || t.unstable;
    }
  }

  // The precision an ALU instruction is carried out at: its suffix, else "at least as much
  // precision as the destination variable" (NV_fragment_program_option 3.11.4.X): H for a
  // SHORT one. The instructions without precision suffixes (packing, texture) run at fp32.
  Precision OperationPrecision(const Instruction& inst) const {
    if (program_.kind != ProgramKind::Fragment || !program_.Nv()) return Precision::R;
    const OpcodeInfo& info = GetOpcodeInfo(inst.op);
    if (info.klass != OpClass::Alu || info.fp2_mods.find('H') == std::string_view::npos) {
      return Precision::R;
    }
    if (inst.precision != Precision::Default) return inst.precision;
    return DstSize(inst) == VarSize::Short ? Precision::H : Precision::R;
  }

  VarSize DstSize(const Instruction& inst) const {
    if (inst.dst.var < 0) return VarSize::Default;
    return program_.vars[static_cast<size_t>(inst.dst.var)].size;
  }

  // What the run's flow depends on reaches every result (and whether a KIL discards).
  void FoldTaint() {
    const exec::Taint& t = nv_.taint();
    if (t.why == kDefined && !t.unstable && t.dev == 0) return;
    for (auto& [key, out] : outputs_) {
      for (Val& v : out.value) {
        if (v.why == kDefined) v.why = t.why;
        if (t.unstable) v.err = exec::kUnstable;
        v.dev |= t.dev;
      }
    }
    const bool has_kil = std::any_of(program_.instructions.begin(), program_.instructions.end(),
                                     [](const Instruction& i) { return i.op == Opcode::KIL; });
    if (has_kil) {
      if (!killed_defined_ && kill_why_ == kDefined) kill_why_ = t.why;
      kill_unstable_ = kill_unstable_ || t.unstable;
      kill_dev_ |= t.dev;
    }
  }

  void Setup() {
    size_t n = program_.vars.size();
    params_.assign(n, {});
    temps_.assign(n, Reg{Val{0.0f, kUnwritten}, Val{0.0f, kUnwritten}, Val{0.0f, kUnwritten},
                         Val{0.0f, kUnwritten}});
    address_.assign(n, Reg{Val{0.0f, kUnwritten}, Val{0.0f, kUnwritten}, Val{0.0f, kUnwritten},
                           Val{0.0f, kUnwritten}});
    for (size_t v = 0; v < n; ++v) {
      const Variable& var = program_.vars[v];
      if (var.kind == VarKind::Param) {
        for (const Binding& b : var.bindings) params_[v].push_back(ParamReg(b));
      } else if (var.kind == VarKind::Output) {
        // A relatively addressed result array may write any of its elements.
        for (const Binding& b : var.bindings) {
          OutKey key = KeyOf(b);
          if (!outputs_.count(key)) outputs_[key].binding = b;
        }
      }
    }
  }

  Reg ParamReg(const Binding& b) {
    switch (b.kind) {
      case BindingKind::Constant:
        return exec::DefinedReg(b.value);
      case BindingKind::ProgramEnv:
        return exec::DefinedReg(glstate::ParameterValue(Params().env, b.index));
      case BindingKind::ProgramLocal:
        return exec::DefinedReg(glstate::ParameterValue(Params().local, b.index));
      case BindingKind::State: {
        Vec4 v = ReadStateBinding(inputs_.state, b);
        std::string why = StateBindingUndefined(inputs_.state, b);
        Reg r =
            why.empty()
                ? exec::DefinedReg(v)
                : exec::UndefinedReg(
                      v, reasons_->Add(fmt::format("{}: {}", BindingName(b, program_.kind), why)));
        float err = DerivedStateError(inputs_.state, b);
        for (Val& c : r) c.err = std::max(c.err, err);
        return r;
      }
      case BindingKind::VertexAttrib:
      case BindingKind::FragmentAttrib:
      case BindingKind::Result:
        break;
    }
    return exec::DefinedReg({0.0f, 0.0f, 0.0f, 0.0f});
  }

  std::string VarName(const Variable& var) const {
    if (!var.name.empty()) return var.name;
    if (!var.bindings.empty()) return BindingName(var.bindings[0], program_.kind);
    return "?";
  }

  // The register an operand names, before swizzle and negation.
  Reg Fetch(const SrcOperand& src, const std::string& where) {
    const Variable& var = program_.vars[static_cast<size_t>(src.var)];
    size_t v = static_cast<size_t>(src.var);
    switch (var.kind) {
      case VarKind::Attrib:
        return FetchParam(src, var, (*attrib_)[v], where);
      case VarKind::Temp:
        return temps_[v];
      case VarKind::Param:
        return FetchParam(src, var, params_[v], where);
      case VarKind::Address:  // ARA, PUSHA (NV_vertex_program2, 3)
        return address_[v];
      case VarKind::Output:
        break;
    }
    return exec::DefinedReg({0.0f, 0.0f, 0.0f, 0.0f});
  }

  // The address component a relative operand uses. NV address registers are vectors (A0.y);
  // NV_fragment_program2's A0.x is the loop index of the innermost LOOP block.
  Val AddressComponent(const SrcOperand& src, const std::string& where) {
    const Variable& addr_var = program_.vars[static_cast<size_t>(src.address_var)];
    const char component = kComponents[src.address_component & 3u];
    if (program_.kind == ProgramKind::Fragment) {
      Val index;
      if (nv_.LoopIndex(&index)) return index;
      return Val{0.0f, reasons_->Add(fmt::format("'{}.{}' read outside a LOOP block{}",
                                                 addr_var.name, component, where))};
    }
    Val addr = address_[static_cast<size_t>(src.address_var)][src.address_component & 3u];
    if (addr.why == kUnwritten) {
      addr.why = reasons_->Add(
          program_.Nv() ? fmt::format("address register '{}.{}' read before it is written{}",
                                      addr_var.name, component, where)
                        : fmt::format("address register '{}' read before ARL wrote it{}",
                                      addr_var.name, where));
    }
    return addr;
  }

  // ARBvp 2.14.4.2: index = addrReg + offset; outside the array the result is undefined and
  // reads (0,0,0,0), as Mesa does.
  Reg FetchParam(const SrcOperand& src, const Variable& var, const std::vector<Reg>& elements,
                 const std::string& where) {
    if (!src.relative) {
      size_t index = src.indexed ? static_cast<size_t>(src.index) : 0;
      return index < elements.size() ? elements[index] : exec::DefinedReg({0, 0, 0, 0});
    }
    const Variable& addr_var = program_.vars[static_cast<size_t>(src.address_var)];
    const Val addr = AddressComponent(src, where);
    std::string offset = src.index == 0 ? "" : fmt::format("{:+d}", src.index);
    bool finite = std::isfinite(addr.v) && std::fabs(addr.v) < 1.0e9f;
    int64_t index = finite ? static_cast<int64_t>(addr.v) + src.index : -1;
    if (!finite || index < 0 || index >= static_cast<int64_t>(elements.size())) {
      if (addr.why != kDefined) return exec::UndefinedReg({0, 0, 0, 0}, addr.why);
      if (addr.err > 0.0f) {
        Reg r = exec::DefinedReg({0, 0, 0, 0});
        for (Val& c : r) c.err = exec::kUnstable;
        return r;
      }
      return exec::UndefinedReg(
          {0.0f, 0.0f, 0.0f, 0.0f},
          reasons_->Add(fmt::format("relative address {}.{}{} = {} outside '{}[0..{}]'{}",
                                    addr_var.name, kComponents[src.address_component & 3u], offset,
                                    index, VarName(var), elements.size() - 1, where)));
    }
    Reg r = elements[static_cast<size_t>(index)];
    for (Val& c : r) {
      if (addr.why != kDefined) c.why = addr.why;
      if (addr.err > 0.0f) c.err = exec::kUnstable;  // another element may be selected
      c.dev |= addr.dev;
    }
    return r;
  }

  // "result.texcoord": the spelling of a relatively addressed array, without its index.
  std::string ArrayName(const Variable& var) const {
    const std::string name = BindingName(var.bindings.at(0), program_.kind);
    return name.substr(0, name.find('['));
  }

  // The element of result.texcoord[A0.x + n] (NV_vertex_program3) a write goes to. Outside
  // the array the spec leaves the write's effects undefined ("may overwrite other programs
  // results"): the write is dropped and its reason recorded on the results.
  bool RelativeElement(const DstOperand& dst, const Variable& var, const std::string& where,
                       size_t* element) {
    SrcOperand as_src;
    as_src.relative = true;
    as_src.address_var = dst.address_var;
    as_src.address_component = dst.address_component;
    const Val addr = AddressComponent(as_src, where);
    const bool finite = std::isfinite(addr.v) && std::fabs(addr.v) < 1.0e9f;
    const int64_t index = finite ? static_cast<int64_t>(addr.v) + dst.index : -1;
    if (addr.why == kDefined && addr.err == 0.0f && index >= 0 &&
        index < static_cast<int64_t>(var.bindings.size())) {
      *element = static_cast<size_t>(index);
      return true;
    }
    // An undefined or unstable address, or one outside the array: every result may change.
    const int why = addr.why != kDefined
                        ? addr.why
                        : reasons_->Add(fmt::format(
                              "a write to {}[{}] outside the array, or at an unstable address{}",
                              ArrayName(var), index, where));
    for (auto& [key, out] : outputs_) {
      for (Val& c : out.value) c.why = c.why == kDefined ? why : c.why;
    }
    if (index >= 0 && index < static_cast<int64_t>(var.bindings.size())) {
      *element = static_cast<size_t>(index);
      return true;
    }
    return false;
  }

  // VectorLoad with swizzle (or extended swizzle) and negation.
  Reg Load(const SrcOperand& src, const std::string& where) {
    Reg base = Fetch(src, where);
    const Variable& var = program_.vars[static_cast<size_t>(src.var)];
    Reg r;
    for (size_t i = 0; i < 4; ++i) {
      Swz sel = src.swizzle[i];
      Val v;
      if (sel == Swz::Zero) {
        v = Val{0.0f};
      } else if (sel == Swz::One) {
        v = Val{1.0f};
      } else {
        size_t c = static_cast<size_t>(sel);
        v = base[c];
        if (v.why == kUnwritten) {
          v.why = reasons_->Add(
              fmt::format("{} '{}.{}' read before it is written{}",
                          var.kind == VarKind::Address ? "address register" : "temporary",
                          VarName(var), kComponents[c], where));
        }
      }
      if (src.abs) v.v = std::fabs(v.v);  // NV: the absolute value, then the negation
      if (src.negate != src.component_negate[i]) v.v = -v.v;
      r[i] = v;
    }
    return r;
  }

  // 3.11.4.3 (NV_fragment_program 3.11.4.4): "if (result.x < 0) result.x = 0; else if
  // (result.x > 1) result.x = 1;" for _SAT, [-1, 1] for _SSAT (NV_fragment_program2).
  static void Saturate(Reg* result, double lo, double hi) {
    for (Val& v : *result) {
      const Val in = v;
      if (v.v < static_cast<float>(lo)) {
        v.v = static_cast<float>(lo);
      } else if (v.v > static_cast<float>(hi)) {
        v.v = static_cast<float>(hi);
      }
      v.err = exec::CornerBound<1>(
          v.v, {in}, [&](const D1& x) { return x[0] < lo ? lo : (x[0] > hi ? hi : x[0]); }, 0.0);
      if (std::isnan(in.v)) v.dev |= kDevNanClamp;
    }
  }

  // A write that a conditional write mask on an undefined or unstable condition code may
  // or may not have made: the new value, undefined with the test, or within reach of the old.
  Val UncertainWrite(Val v, const Val& old, const exec::CcOutcome& t, const std::string& where) {
    if (v.why == kDefined) v.why = t.why;
    v.dev |= t.dev;
    if (!t.unstable) return v;
    if (old.why != kDefined && v.why == kDefined) {
      v.why = old.why != kUnwritten
                  ? old.why
                  : reasons_->Add(
                        "a conditional write on an unstable condition code may not "
                        "happen, leaving the component unwritten" +
                        where);
    }
    const double apart = std::fabs(exec::Wide(v.v) - exec::Wide(old.v)) + exec::Wide(old.err);
    v.err = std::isnan(apart) ? exec::kUnstable : std::max(v.err, exec::RoundUp(apart));
    v.dev |= old.dev;
    return v;
  }

  // The destination update: saturation, the conversion to a SHORT variable's fp16, the write
  // mask and the NV conditional write mask, then the condition code update from each written
  // component (NV_vertex_program2_option 2.14.4.3, NV_fragment_program_option 3.11.4.3).
  void Store(const Instruction& inst, Reg result, const std::string& where) {
    if (inst.saturate) Saturate(&result, 0.0, 1.0);
    if (inst.signed_saturate) Saturate(&result, -1.0, 1.0);
    const Variable& var = program_.vars[static_cast<size_t>(inst.dst.var)];
    if (var.size == VarSize::Short) {
      for (Val& v : result) v = exec::ConvertVal(v, Precision::H);
    }
    Reg* dest = nullptr;
    uint8_t* written = nullptr;
    if (var.kind == VarKind::Output) {
      size_t element = 0;
      if (inst.dst.relative && !RelativeElement(inst.dst, var, where, &element)) return;
      Output& out = outputs_[KeyOf(var.bindings[element])];
      dest = &out.value;
      written = &out.written;
    } else if (var.kind == VarKind::Address) {
      dest = &address_[static_cast<size_t>(inst.dst.var)];
    } else {
      dest = &temps_[static_cast<size_t>(inst.dst.var)];
    }
    for (size_t i = 0; i < 4; ++i) {
      if (!(inst.dst.mask & (1u << i))) continue;
      const exec::CcOutcome t = exec::TestCcComponent(inst.dst.cc, nv_.cc(inst.dst.cc.reg), i);
      if (t.certain() && !t.pass) continue;
      const bool sure = t.certain();
      (*dest)[i] = sure ? result[i] : UncertainWrite(result[i], (*dest)[i], t, where);
      if (written) *written = static_cast<uint8_t>(*written | (1u << i));
      if (inst.cc_update < 0) continue;
      exec::CcVal cc = exec::GenerateCc(result[i]);
      if (!sure) {
        if (cc.why == kDefined) cc.why = t.why;
        cc.unstable = cc.unstable || t.unstable;
        cc.dev |= t.dev;
      }
      nv_.cc(inst.cc_update)[i] = cc;
    }
  }

  const Program& program_;
  const ExecInputs& inputs_;
  const compiler::SourceFile* source_;
  Reasons* reasons_;
  const std::vector<std::vector<Reg>>* attrib_ = nullptr;
  std::vector<std::vector<Reg>> params_;
  std::vector<Reg> temps_;
  std::vector<Reg> address_;
  Outputs outputs_;
  bool killed_ = false;
  bool killed_defined_ = false;
  int kill_why_ = kDefined;
  bool kill_unstable_ = false;
  uint32_t kill_dev_ = 0;
  exec::NvMachine nv_;
};

std::vector<std::vector<Reg>> VertexAttribs(const Program& program, const VertexInput& in) {
  std::vector<std::vector<Reg>> attribs(program.vars.size());
  for (size_t v = 0; v < program.vars.size(); ++v) {
    const Variable& var = program.vars[v];
    if (var.kind != VarKind::Attrib) continue;
    for (const Binding& b : var.bindings) attribs[v].push_back(VertexAttribValue(b, in));
  }
  return attribs;
}

std::vector<std::vector<Reg>> FragmentAttribs(const Program& program,
                                              const FragmentSource& source) {
  std::vector<std::vector<Reg>> attribs(program.vars.size());
  for (size_t v = 0; v < program.vars.size(); ++v) {
    const Variable& var = program.vars[v];
    if (var.kind != VarKind::Attrib) continue;
    for (const Binding& b : var.bindings) attribs[v].push_back(FragmentAttribValue(b, source));
  }
  return attribs;
}

// ARB_position_invariant: clip coordinates as GL 2.0 section 2.11 computes them, eye =
// M * v then clip = P * eye, in float.
void AddInvariantPosition(const ExecInputs& inputs, const VertexInput& in, Outputs* outputs) {
  glm::vec4 object(in.position[0], in.position[1], in.position[2], in.position[3]);
  glm::vec4 eye = inputs.state.modelview * object;
  glm::vec4 clip = inputs.state.projection * eye;
  Binding b;
  b.kind = BindingKind::Result;
  b.result = ResultReg::Position;
  Output& out = (*outputs)[KeyOf(b)];
  out.binding = b;
  out.value = exec::DefinedReg({clip.x, clip.y, clip.z, clip.w});
  // Any order of the two transforms' products and sums (GL may use the product matrix).
  glm::mat4 amv = inputs.state.modelview;
  glm::mat4 ap = inputs.state.projection;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      amv[i][j] = std::fabs(amv[i][j]);
      ap[i][j] = std::fabs(ap[i][j]);
    }
  }
  glm::vec4 magnitude = ap * (amv * glm::abs(object));
  glm::vec4 flushed(0.0f);  // denormal inputs a driver may flush
  for (int i = 0; i < 4; ++i) flushed[i] = exec::InputVal(object[i]).err;
  glm::vec4 carried = ap * (amv * flushed);
  for (int i = 0; i < 4; ++i) {
    Val& v = out.value[static_cast<size_t>(i)];
    double e = 8.0 * exec::kRounding * static_cast<double>(magnitude[i]) +
               static_cast<double>(carried[i]) + static_cast<double>(v.err);
    v.err = exec::RoundUp(e);
  }
  out.written = 0xF;
}

// ARBfp 3.11.4.5.1: fog (GL 2.0 section 3.10) applied to the program's final clamped colour:
// C = f * clamp(Cr) + (1 - f) * Cf for r, g, b with f clamped to [0, 1] and Cf the fog
// colour (clamped when specified, so here); alpha is clamped and not blended. (Without a
// fog option no output is clamped: the engines read unclamped colour buffers.)
void ApplyFog(const Program& program, const GlState& state, Val c, Reasons* reasons,
              Outputs* outputs) {
  double start = exec::Wide(state.fog_start);
  double end = exec::Wide(state.fog_end);
  double density = exec::Wide(state.fog_density);
  float f = 0.0f;
  float f_err = 0.0f;
  int why = c.why;
  if (program.HasOption(OptionId::FogLinear)) {
    f = (state.fog_end - c.v) / (state.fog_end - state.fog_start);
    if (state.fog_end == state.fog_start && why == kDefined) {
      why = reasons->Add("ARB_fog_linear with fog start == fog end");
    }
    f_err = exec::CornerBound<1>(
        f, {c}, [&](const D1& x) { return (end - x[0]) / (end - start); }, exec::Wide(std::fabs(f)),
        0.0);
  } else if (program.HasOption(OptionId::FogExp)) {
    f = std::exp(-(state.fog_density * c.v));
    f_err = exec::CornerBound<1>(
        f, {c}, [&](const D1& x) { return std::exp(-(density * x[0])); }, 0.0, exec::kApprox);
  } else if (program.HasOption(OptionId::FogExp2)) {
    float dc = state.fog_density * c.v;
    f = std::exp(-(dc * dc));
    f_err = exec::CornerBound<1>(
        f, {c}, [&](const D1& x) { return std::exp(-(density * x[0] * density * x[0])); }, 0.0,
        exec::kApprox);
  } else {
    return;
  }
  Val factor{std::clamp(f, 0.0f, 1.0f), why, 0.0f, c.dev};
  factor.err = exec::CornerBound<1>(factor.v, {Val{f, why, f_err, 0}}, Clamp01, 0.0);
  // Mesa leaves a program with ARB_draw_buffers unfogged (deviations.h).
  if (program.HasOption(OptionId::DrawBuffers)) factor.dev |= kDevFogWithDrawBuffers;
  if (std::isnan(f)) factor.dev |= kDevNanClamp;
  for (auto& [key, out] : *outputs) {
    if (out.binding.result != ResultReg::FragColor) continue;
    if (out.written & 0x8) {
      // "The final clamped color": alpha is clamped too, and not blended.
      Val alpha = out.value[3];
      out.value[3].v = std::clamp(alpha.v, 0.0f, 1.0f);
      out.value[3].err = exec::CornerBound<1>(out.value[3].v, {alpha}, Clamp01, 0.0);
      if (std::isnan(alpha.v)) out.value[3].dev |= kDevNanClamp;
      out.value[3].dev |= factor.dev & kDevFogWithDrawBuffers;
    }
    for (size_t i = 0; i < 3; ++i) {
      if (!(out.written & (1u << i))) continue;
      Val colour = out.value[i];
      float cr = std::clamp(colour.v, 0.0f, 1.0f);
      double cf = exec::Wide(std::clamp(state.fog_color[i], 0.0f, 1.0f));
      float v = factor.v * cr + (1.0f - factor.v) * static_cast<float>(cf);
      // Drivers blend as cf + f * (cr - cf): the rounding of both forms.
      double f64 = exec::Wide(factor.v);
      double c64 = exec::Wide(cr);
      double magnitude = f64 * c64 + (1.0 - f64) * cf + cf + f64 * std::fabs(c64 - cf);
      float err = exec::CornerBound<2>(
          v, {factor, colour},
          [&](const D2& x) { return x[0] * Clamp01({x[1]}) + (1.0 - x[0]) * cf; }, magnitude, 0.0,
          0.0, /*reformulated=*/true);
      out.value[i] = From(v, {colour, factor}, err);
      if (std::isnan(colour.v)) out.value[i].dev |= kDevNanClamp;
    }
  }
}

VectorResult Collect(const Program& program, const Outputs& outputs, const Reasons& reasons,
                     bool killed, int kill_why, bool kill_unstable, uint32_t kill_dev) {
  VectorResult result;
  result.killed = killed;
  result.kill_unstable = kill_unstable;
  result.kill_deviations = kill_dev;
  if (kill_why != kDefined) {
    result.kill_undefined = "whether KIL discards the fragment depends on " + reasons.Get(kill_why);
  }
  if (killed) return result;
  for (const auto& [key, out] : outputs) {
    if (out.written == 0) continue;
    OutputRegister reg;
    reg.binding = out.binding;
    reg.name = BindingName(out.binding, program.kind);
    reg.written = out.written;
    for (size_t i = 0; i < 4; ++i) {
      if (!(out.written & (1u << i))) continue;
      reg.value[i] = out.value[i].v;
      int why = out.value[i].why;
      if (why == kDefined && kill_why != kDefined) why = kill_why;
      if (why >= 0) reg.undefined[i] = reasons.Get(why);
      // NV_vertex_program2's binding table: result.clip[n] is (d,*,*,*), one distance.
      if (i > 0 && out.binding.kind == BindingKind::Result &&
          out.binding.result == ResultReg::ClipDistance) {
        reg.undefined[i] = "result.clip[n] holds only x, the distance (NV_vertex_program2)";
      }
      reg.tolerance[i] = kill_unstable ? exec::kUnstable : out.value[i].err;
      reg.deviations[i] = out.value[i].dev | kill_dev;
    }
    result.outputs.push_back(std::move(reg));
  }
  std::stable_sort(result.outputs.begin(), result.outputs.end(),
                   [](const OutputRegister& a, const OutputRegister& b) {
                     return ResultRegOrder(a.binding, b.binding);
                   });
  return result;
}

// Runs one program on one vector; `fragment` supplies fragment attributes (unused by a
// vertex program).
VectorResult RunOne(const Program& program, const ExecInputs& inputs, const InputVector& in,
                    const FragmentSource& fragment, const compiler::SourceFile* source,
                    Reasons* reasons) {
  Run run(program, inputs, source, reasons);
  bool vp = program.kind == ProgramKind::Vertex;
  run.Execute(vp ? VertexAttribs(program, in.vertex) : FragmentAttribs(program, fragment));
  if (vp && program.HasOption(OptionId::PositionInvariant)) {
    AddInvariantPosition(inputs, in.vertex, &run.outputs());
  }
  if (!vp) ApplyFog(program, inputs.state, fragment.fogcoord, reasons, &run.outputs());
  return Collect(program, run.outputs(), *reasons, run.killed(), run.kill_why(),
                 run.kill_unstable(), run.kill_dev());
}

// A vertex output as a fragment input; components the vertex program did not write are
// undefined (ARBvp 2.14.3.4).
Reg Varying(const Outputs& outputs, ResultReg reg, int32_t index, bool secondary, const char* name,
            Reasons* reasons) {
  const Output* out = FindOutput(outputs, reg, index, secondary);
  Reg r = exec::DefinedReg({0.0f, 0.0f, 0.0f, 0.0f});
  for (size_t i = 0; i < 4; ++i) {
    if (out && (out->written & (1u << i))) {
      r[i] = out->value[i];
    } else {
      r[i].why = reasons->Add(fmt::format("{}.{} not written by the vertex program",
                                          fmt::format(fmt::runtime(name), index), kComponents[i]));
    }
  }
  return r;
}

// GL 2.0 section 2.14.6 (ARBvp 2.14.4.4 "color clamping"): vertex colours are clamped to
// [0, 1] before rasterization.
Reg ClampColor(Reg r) {
  for (Val& v : r) {
    Val in = v;
    v.v = std::clamp(v.v, 0.0f, 1.0f);
    v.err = exec::CornerBound<1>(v.v, {in}, Clamp01, 0.0);
    if (std::isnan(in.v)) v.dev |= kDevNanClamp;
  }
  return r;
}

}  // namespace

std::vector<VectorResult> Interpret(const Program& program, const ExecInputs& inputs,
                                    const compiler::SourceFile* source) {
  std::vector<VectorResult> results;
  results.reserve(inputs.vectors.size());
  for (size_t i = 0; i < inputs.vectors.size(); ++i) {
    const InputVector& in = inputs.vectors[i];
    Reasons reasons;
    FragmentSource fragment =
        FromFragmentInput(in.fragment, i, inputs.vectors.size(), FragCoordConventionOf(program));
    results.push_back(RunOne(program, inputs, in, fragment, source, &reasons));
  }
  return results;
}

std::vector<VectorResult> InterpretPair(const Program& vertex, const Program& fragment,
                                        const ExecInputs& inputs,
                                        const compiler::SourceFile* vertex_source,
                                        const compiler::SourceFile* fragment_source) {
  std::vector<VectorResult> results;
  results.reserve(inputs.vectors.size());
  for (size_t i = 0; i < inputs.vectors.size(); ++i) {
    const InputVector& in = inputs.vectors[i];
    Reasons reasons;
    Run vrun(vertex, inputs, vertex_source, &reasons);
    vrun.Execute(VertexAttribs(vertex, in.vertex));
    const Outputs& vout = vrun.outputs();
    // position: the vector's pixel
    FragmentSource f =
        FromFragmentInput(in.fragment, i, inputs.vectors.size(), FragCoordConventionOf(fragment));
    f.color = ClampColor(
        Varying(vout, ResultReg::Color, 0, false, "result.color.front.primary", &reasons));
    f.secondary = ClampColor(
        Varying(vout, ResultReg::Color, 0, true, "result.color.front.secondary", &reasons));
    for (size_t t = 0; t < f.texcoord.size(); ++t) {
      f.texcoord[t] = Varying(vout, ResultReg::TexCoord, static_cast<int32_t>(t), false,
                              "result.texcoord[{}]", &reasons);
    }
    f.fogcoord = Varying(vout, ResultReg::FogCoord, 0, false, "result.fogcoord", &reasons)[0];
    results.push_back(RunOne(fragment, inputs, in, f, fragment_source, &reasons));
  }
  return results;
}

}  // namespace arbiter::arbvp
