// Reflection of a checked ARB program for `arbiter info` and host engines.
#include "arbiter/arbvp/reflect.h"

#include <algorithm>
#include <set>

namespace arbiter::arbvp {

Reflection Reflect(const Program& program, const Stats& stats) {
  Reflection r;
  r.kind = program.kind == ProgramKind::Vertex ? "vertex" : "fragment";
  r.stats = stats;
  for (const Option& option : program.options) {
    r.options.emplace_back(GetOptionInfo(option.id).spelling);
  }
  std::set<int> env;
  std::set<int> local;
  std::set<std::string> state;
  for (const Variable& var : program.vars) {
    if (var.kind != VarKind::Attrib && var.kind != VarKind::Param) continue;
    ReflectedVariable rv;
    rv.name = var.name;
    for (const Binding& b : var.bindings) {
      rv.bindings.push_back(BindingName(b, program.kind));
      if (b.kind == BindingKind::ProgramEnv) env.insert(b.index);
      if (b.kind == BindingKind::ProgramLocal) local.insert(b.index);
      if (b.kind == BindingKind::State) state.insert(BindingName(b, program.kind));
    }
    // Each use of an inline binding (`MOV R0, vertex.position;`) is a variable of its own in
    // the IR; a reader wants the binding once.
    std::vector<ReflectedVariable>& list =
        var.kind == VarKind::Attrib ? r.attributes : r.parameters;
    const bool repeated =
        rv.name.empty() && std::any_of(list.begin(), list.end(), [&](const auto& v) {
          return v.name.empty() && v.bindings == rv.bindings;
        });
    if (!repeated) list.push_back(std::move(rv));
  }
  r.env_indices.assign(env.begin(), env.end());
  r.local_indices.assign(local.begin(), local.end());
  r.state.assign(state.begin(), state.end());

  std::set<std::string> written;
  std::set<std::pair<int, std::string>> textures;
  for (const Instruction& inst : program.instructions) {
    if (GetOpcodeInfo(inst.op).signature == OpSignature::Sample) {
      textures.emplace(inst.tex_unit, std::string(TexTargetName(inst.target)));
    }
    if (inst.dst.var < 0 || inst.op == Opcode::KIL) continue;
    const Variable& dst = program.vars[static_cast<size_t>(inst.dst.var)];
    if (dst.kind != VarKind::Output) continue;
    for (const Binding& b : dst.bindings) written.insert(BindingName(b, program.kind));
  }
  r.outputs_written.assign(written.begin(), written.end());
  for (const auto& [unit, target] : textures) r.textures.push_back({unit, target});
  return r;
}

}  // namespace arbiter::arbvp
