// Program rewriting for readback: see program_rewrite.h.
#include "exec/program_rewrite.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>
#include <set>
#include <tuple>

#include "arbiter/arbvp/print.h"

namespace arbiter::runtime::exec {
namespace {

using arbvp::Binding;
using arbvp::BindingKind;
using arbvp::Instruction;
using arbvp::OptionId;
using arbvp::Program;
using arbvp::ResultReg;
using arbvp::Variable;
using arbvp::VarKind;
using arbvp::VertexAttrib;

// The identity of a result register: colours by face and secondary, texture coordinates and
// draw buffers by index ("result.color" and "result.color[0]" are one register).
using RegisterKey = std::tuple<int, int, int, int>;
RegisterKey KeyOf(const Binding& b) {
  bool color = b.result == ResultReg::Color;
  bool indexed = b.result == ResultReg::TexCoord || b.result == ResultReg::FragColor;
  return {static_cast<int>(b.result), color ? static_cast<int>(b.face) : 0,
          color && b.secondary ? 1 : 0, indexed ? b.index : 0};
}

Binding ResultBinding(ResultReg reg, int index, bool indexed) {
  Binding b;
  b.kind = BindingKind::Result;
  b.result = reg;
  b.index = index;
  b.indexed = indexed;
  return b;
}

Binding AttribBinding(VertexAttrib attrib, int index) {
  Binding b;
  b.kind = BindingKind::VertexAttrib;
  b.vertex_attrib = attrib;
  b.index = index;
  b.indexed = true;
  return b;
}

Binding ConstantBinding(float x, float y, float z, float w) {
  Binding b;
  b.kind = BindingKind::Constant;
  b.value = {x, y, z, w};
  return b;
}

Binding EnvBinding(int index) {
  Binding b;
  b.kind = BindingKind::ProgramEnv;
  b.index = index;
  b.indexed = true;
  return b;
}

// The highest program.env index below `limit` that the program binds nowhere.
int UnusedEnv(const Program& program, int limit) {
  std::set<int> used;
  for (const Variable& var : program.vars) {
    for (const Binding& b : var.bindings) {
      if (b.kind == BindingKind::ProgramEnv) used.insert(b.index);
    }
  }
  for (int index = limit - 1; index >= 0; --index) {
    if (used.count(index) == 0) return index;
  }
  return -1;
}

Binding MvpRow(int row) {
  Binding b;
  b.kind = BindingKind::State;
  b.state = arbvp::StateItem::MatrixRow;
  b.matrix = arbvp::MatrixName::Mvp;
  b.row = static_cast<uint8_t>(row);
  return b;
}

// A copy of a program with helpers to add variables (under names no user variable takes)
// and instructions.
class Editor {
 public:
  explicit Editor(const Program& program) : program_(program) {
    for (const Variable& var : program_.vars) names_.insert(var.name);
  }

  Program& program() { return program_; }

  int AddVar(VarKind kind, const std::string& base, std::vector<Binding> bindings = {}) {
    Variable var;
    var.name = base;
    while (names_.count(var.name) != 0) var.name += "_";
    names_.insert(var.name);
    var.kind = kind;
    var.bindings = std::move(bindings);
    program_.vars.push_back(std::move(var));
    return static_cast<int>(program_.vars.size() - 1);
  }
  int Constant(const std::string& base, float x, float y, float z, float w) {
    return AddVar(VarKind::Param, base, {ConstantBinding(x, y, z, w)});
  }
  int Result(const std::string& base, const Binding& binding) {
    return AddVar(VarKind::Output, base, {binding});
  }

  static Instruction Op(arbvp::Opcode op, int dst, uint8_t mask, std::vector<int> srcs) {
    Instruction inst;
    inst.op = op;
    inst.dst.var = dst;
    inst.dst.mask = mask;
    inst.src_count = static_cast<uint8_t>(srcs.size());
    for (size_t i = 0; i < srcs.size(); ++i) inst.src[i].var = srcs[i];
    return inst;
  }
  void Append(arbvp::Opcode op, int dst, uint8_t mask, std::vector<int> srcs) {
    program_.instructions.push_back(Op(op, dst, mask, std::move(srcs)));
  }
  void Prepend(arbvp::Opcode op, int dst, uint8_t mask, std::vector<int> srcs) {
    program_.instructions.insert(program_.instructions.begin(), Op(op, dst, mask, std::move(srcs)));
  }

  void RemoveOption(OptionId id) {
    auto& options = program_.options;
    options.erase(std::remove_if(options.begin(), options.end(),
                                 [id](const arbvp::Option& o) { return o.id == id; }),
                  options.end());
  }
  void AddOption(OptionId id) {
    if (!program_.HasOption(id)) program_.options.push_back({id, {}});
  }

  // Sends every write of a result register that `select` picks to a fresh temporary (zeroed
  // first, so unwritten components read 0); returns the temporary of each register.
  std::map<RegisterKey, int> RedirectWrites(const std::function<bool(const Binding&)>& select) {
    std::map<int, int> var_temp;
    std::map<RegisterKey, int> key_temp;
    const size_t count = program_.vars.size();
    for (size_t v = 0; v < count; ++v) {
      const Variable& var = program_.vars[v];
      if (var.kind != VarKind::Output || !select(var.bindings.at(0))) continue;
      if (var.relative_array) {
        // result.texcoord[A0.x + n] of NV_vertex_program3, which Mesa's ARB engine never
        // runs (verify compares the NV programs through their translation): each element
        // gets its temporary, so that the passes are planned, and the writes stay.
        for (const Binding& b : var.bindings) {
          if (!key_temp.count(KeyOf(b))) {
            key_temp.emplace(KeyOf(b),
                             AddVar(VarKind::Temp, fmt::format("arbiter_out{}_{}", v, b.index)));
          }
        }
        continue;
      }
      RegisterKey key = KeyOf(var.bindings.at(0));
      auto it = key_temp.find(key);
      if (it == key_temp.end()) {
        it = key_temp.emplace(key, AddVar(VarKind::Temp, fmt::format("arbiter_out{}", v))).first;
      }
      var_temp[static_cast<int>(v)] = it->second;
    }
    for (Instruction& inst : program_.instructions) {
      if (arbvp::GetOpcodeInfo(inst.op).signature == arbvp::OpSignature::Kil) continue;
      auto it = var_temp.find(inst.dst.var);
      if (it != var_temp.end()) inst.dst.var = it->second;
    }
    if (!key_temp.empty()) {
      int zero = Constant("arbiter_zero", 0.0f, 0.0f, 0.0f, 0.0f);
      for (const auto& [key, temp] : key_temp) Prepend(arbvp::Opcode::MOV, temp, 0xF, {zero});
    }
    return key_temp;
  }

 private:
  Program program_;
  std::set<std::string> names_;
};

// Every result register the program's instructions write, with the components written.
std::vector<OutputSlot> WrittenOutputs(const Program& program) {
  std::map<RegisterKey, OutputSlot> slots;
  for (const Instruction& inst : program.instructions) {
    // KIL and the NV flow instructions (and PUSHA) write no register.
    if (inst.op == arbvp::Opcode::KIL || inst.dst.var < 0) continue;
    const Variable& var = program.vars.at(static_cast<size_t>(inst.dst.var));
    if (var.kind != VarKind::Output) continue;
    // result.texcoord[A0.x + n] may write any element of its array.
    for (const arbvp::Binding& b : var.bindings) {
      OutputSlot& slot = slots[KeyOf(b)];
      if (slot.written == 0) slot.binding = b;
      slot.written |= inst.dst.mask;
    }
  }
  std::vector<OutputSlot> out;
  for (auto& [key, slot] : slots) out.push_back(slot);
  return out;
}

void SortOutputs(std::vector<OutputSlot>* outputs) {
  std::stable_sort(outputs->begin(), outputs->end(), [](const OutputSlot& a, const OutputSlot& b) {
    return arbvp::ResultRegOrder(a.binding, b.binding);
  });
}

// A generic attribute the program reads neither directly nor through an alias: 7 and 6
// first (no conventional attribute aliases them).
int SpareGeneric(const Program& vp, RunPlan* plan) {
  std::set<int> taken;
  for (const Variable& var : vp.vars) {
    if (var.kind != VarKind::Attrib) continue;
    for (const Binding& b : var.bindings) {  // every element of a relatively addressed array
      taken.insert(arbvp::GenericAttribSlot(b));
      if (b.vertex_attrib == VertexAttrib::Generic) {
        if (b.index == 0) plan->reads_generic0 = true;
        plan->generics.insert(b.index);
      }
    }
  }
  for (int n : {7, 6, 15, 14, 13, 12, 11, 10, 9, 8, 5, 4, 3, 2, 1}) {
    if (taken.count(n) == 0) return n;
  }
  return -1;
}

// The vertex program rewritten for readback of its own outputs (mode Vertex) or for feeding
// a fragment program (mode Pair): position from the spare attribute, point size 1.
struct VertexRewrite {
  Editor editor;
  std::map<RegisterKey, int> temps;
  bool invariant = false;
};

VertexRewrite RewriteVertex(const Program& vp, RunMode mode, const RunPlan& plan) {
  VertexRewrite r{Editor(vp), {}, vp.HasOption(OptionId::PositionInvariant)};
  Editor& e = r.editor;
  e.RemoveOption(OptionId::PositionInvariant);
  if (mode == RunMode::Vertex) {
    r.temps = e.RedirectWrites([](const Binding&) { return true; });
  } else {
    r.temps = e.RedirectWrites([](const Binding& b) {
      return b.result == ResultReg::Position || b.result == ResultReg::PointSize;
    });
  }
  if (r.invariant && mode == RunMode::Vertex) {
    // The fixed-function transform of ARB_position_invariant: the mvp rows dotted with the
    // position (Mesa's own insertion does the same).
    int position = e.AddVar(VarKind::Attrib, "arbiter_vertex",
                            {plan.reads_generic0 ? AttribBinding(VertexAttrib::Generic, 0)
                                                 : AttribBinding(VertexAttrib::Position, 0)});
    int temp = e.AddVar(VarKind::Temp, "arbiter_ftransform");
    for (int row = 0; row < 4; ++row) {
      int mvp = e.AddVar(VarKind::Param, fmt::format("arbiter_mvp{}", row), {MvpRow(row)});
      e.Append(arbvp::Opcode::DP4, temp, static_cast<uint8_t>(1 << row), {mvp, position});
    }
    r.temps[KeyOf(ResultBinding(ResultReg::Position, 0, false))] = temp;
  }
  int attrib = plan.position_attrib >= 0
                   ? e.AddVar(VarKind::Attrib, "arbiter_pixel",
                              {AttribBinding(VertexAttrib::Generic, plan.position_attrib)})
                   : e.AddVar(VarKind::Param, "arbiter_pixel", {EnvBinding(plan.position_env)});
  int position = e.Result("arbiter_position", ResultBinding(ResultReg::Position, 0, false));
  e.Append(arbvp::Opcode::MOV, position, 0xF, {attrib});
  int one = e.Constant("arbiter_one", 1.0f, 1.0f, 1.0f, 1.0f);
  int size = e.Result("arbiter_pointsize", ResultBinding(ResultReg::PointSize, 0, false));
  e.Append(arbvp::Opcode::MOV, size, 0x1, {one});
  return r;
}

// The fragment program that copies fragment.texcoord[k] to draw buffer k.
std::string PassThroughFragment(int count) {
  std::string text = "!!ARBfp1.0\nOPTION ARB_draw_buffers;\n";
  for (int k = 0; k < count; ++k) {
    text += fmt::format("MOV result.color[{0}], fragment.texcoord[{0}];\n", k);
  }
  return text + "END\n";
}

// The vertex program that feeds a fragment program alone. Every input travels in a generic
// attribute (kFragmentInputAttribs), so all four components reach the fragment program: the
// conventional secondary colour and fog coordinate have fewer.
std::string PassThroughVertex() {
  std::string text = fmt::format(
      "!!ARBvp1.0\n"
      "PARAM one = {{1, 1, 1, 1}};\n"
      "MOV result.position, vertex.attrib[{}];\n"
      "MOV result.color, vertex.attrib[{}];\n"
      "MOV result.color.secondary, vertex.attrib[{}];\n"
      "MOV result.fogcoord, vertex.attrib[{}];\n"
      "MOV result.pointsize.x, one;\n",
      kFragmentInputAttribs.position, kFragmentInputAttribs.color,
      kFragmentInputAttribs.secondary_color, kFragmentInputAttribs.fogcoord);
  for (int k = 0; k < arbvp::kMaxTextureCoords; ++k) {
    text += fmt::format("MOV result.texcoord[{}], vertex.attrib[{}];\n", k,
                        kFragmentInputAttribs.texcoord0 + k);
  }
  return text + "END\n";
}

bool IsFogOption(OptionId id) {
  return id == OptionId::FogLinear || id == OptionId::FogExp || id == OptionId::FogExp2;
}

// The fragment program's passes. A fog option applies to result.color only (Mesa appends the
// blend to writes of the unindexed result.color), so draw buffer 0 gets a pass of its own
// that writes result.color with the option kept; every other pass drops the option, writes
// up to max - 1 outputs to result.color[k] and the alive flag to the last attachment.
void PlanFragmentPasses(const Program& fp, int max_attachments, const std::string& vertex_text,
                        RunPlan* plan) {
  Editor base(fp);
  std::map<RegisterKey, int> temps = base.RedirectWrites([](const Binding&) { return true; });
  bool fog = std::any_of(fp.options.begin(), fp.options.end(),
                         [](const arbvp::Option& o) { return IsFogOption(o.id); });
  std::vector<int> rest;
  for (size_t s = 0; s < plan->outputs.size(); ++s) {
    const Binding& b = plan->outputs[s].binding;
    int temp = temps.at(KeyOf(b));
    if (fog && b.result == ResultReg::FragColor && b.index == 0) {
      Editor e = base;
      int color = e.Result("arbiter_color", ResultBinding(ResultReg::FragColor, 0, false));
      e.Append(arbvp::Opcode::MOV, color, 0xF, {temp});
      plan->passes.push_back({vertex_text, PrintProgram(e.program()), {static_cast<int>(s)}});
      continue;
    }
    rest.push_back(static_cast<int>(s));
  }
  for (OptionId id : {OptionId::FogLinear, OptionId::FogExp, OptionId::FogExp2}) {
    base.RemoveOption(id);
  }
  base.AddOption(OptionId::DrawBuffers);
  const size_t per_pass = static_cast<size_t>(max_attachments - 1);
  size_t next = 0;
  do {
    Editor e = base;
    Pass pass;
    pass.vertex_text = vertex_text;
    for (; next < rest.size() && pass.attachments.size() < per_pass; ++next) {
      int k = static_cast<int>(pass.attachments.size());
      int color =
          e.Result(fmt::format("arbiter_color{}", k), ResultBinding(ResultReg::FragColor, k, true));
      e.Append(arbvp::Opcode::MOV, color, 0xF,
               {temps.at(KeyOf(plan->outputs[rest[next]].binding))});
      pass.attachments.push_back(rest[next]);
    }
    int k = static_cast<int>(pass.attachments.size());
    int one = e.Constant("arbiter_alive_value", 1.0f, 1.0f, 1.0f, 1.0f);
    int alive = e.Result("arbiter_alive", ResultBinding(ResultReg::FragColor, k, true));
    e.Append(arbvp::Opcode::MOV, alive, 0xF, {one});
    pass.attachments.push_back(kAliveFlag);
    pass.fragment_text = PrintProgram(e.program());
    plan->passes.push_back(std::move(pass));
  } while (next < rest.size());
}

}  // namespace

bool PlanRun(const ArbPrograms& programs, const ContextLimits& limits, RunPlan* plan,
             std::string* error) {
  *plan = RunPlan{};
  const int max_attachments = std::min(limits.max_draw_buffers, 8);
  if (max_attachments < 2) {
    *error = "the context has fewer than two draw buffers";
    return false;
  }
  const Program* vp = programs.vertex;
  const Program* fp = programs.fragment;
  if (vp == nullptr && fp == nullptr) {
    *error = "no program to run";
    return false;
  }
  if ((vp != nullptr && vp->kind != arbvp::ProgramKind::Vertex) ||
      (fp != nullptr && fp->kind != arbvp::ProgramKind::Fragment)) {
    *error = "the vertex slot needs an ARBvp1.0 program and the fragment slot an ARBfp1.0 one";
    return false;
  }
  plan->mode = fp == nullptr ? RunMode::Vertex : vp == nullptr ? RunMode::Fragment : RunMode::Pair;
  if (vp != nullptr) {
    plan->position_attrib = SpareGeneric(*vp, plan);
    if (plan->position_attrib < 0) plan->position_env = UnusedEnv(*vp, limits.max_vertex_env);
    if (plan->position_attrib < 0 && plan->position_env < 0) {
      *error =
          "the vertex program binds every generic attribute and every program.env "
          "parameter: none is left for the point's position";
      return false;
    }
  }
  if (plan->mode == RunMode::Vertex) {
    VertexRewrite r = RewriteVertex(*vp, RunMode::Vertex, *plan);
    plan->outputs = WrittenOutputs(*vp);
    if (r.invariant) {
      plan->outputs.push_back({ResultBinding(ResultReg::Position, 0, false), 0xF});
    }
    SortOutputs(&plan->outputs);
    // Vertex outputs travel as texture coordinates, eight per pass.
    const size_t per_pass =
        static_cast<size_t>(std::min(max_attachments, arbvp::kMaxTextureCoords));
    for (size_t first = 0; first < plan->outputs.size(); first += per_pass) {
      Editor e = r.editor;
      Pass pass;
      for (size_t s = first; s < plan->outputs.size() && s < first + per_pass; ++s) {
        int k = static_cast<int>(s - first);
        int out = e.Result(fmt::format("arbiter_texcoord{}", k),
                           ResultBinding(ResultReg::TexCoord, k, true));
        e.Append(arbvp::Opcode::MOV, out, 0xF, {r.temps.at(KeyOf(plan->outputs[s].binding))});
        pass.attachments.push_back(static_cast<int>(s));
      }
      pass.vertex_text = PrintProgram(e.program());
      pass.fragment_text = PassThroughFragment(static_cast<int>(pass.attachments.size()));
      plan->passes.push_back(std::move(pass));
    }
    return true;
  }
  plan->outputs = WrittenOutputs(*fp);
  SortOutputs(&plan->outputs);
  std::string vertex_text =
      plan->mode == RunMode::Fragment
          ? PassThroughVertex()
          : PrintProgram(RewriteVertex(*vp, RunMode::Pair, *plan).editor.program());
  PlanFragmentPasses(*fp, max_attachments, vertex_text, plan);
  return true;
}

}  // namespace arbiter::runtime::exec
