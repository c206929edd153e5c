// Resource accounting against limit profiles (ARBvp 2.14.3.x and 6.1.12, ARBfp 3.11.3.6).
#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <string>

#include "checks.h"

namespace arbiter::arbvp {
namespace {

std::string_view GlName(std::string_view key) {
  for (const compiler::LimitKey& k : compiler::LimitKeys()) {
    if (k.key == key) return k.gl_name;
  }
  return key;
}

// How much of a limit the fog and position-invariant options take for themselves
// (ARBfp 3.11.4.5.1, ARBvp 2.14.4.5.1).
struct Reserve {
  int instructions = 0;
  int temporaries = 0;
  int attribs = 0;
  int parameters = 0;
};

Reserve OptionReserve(const Program& program) {
  Reserve r;
  if (program.HasOption(OptionId::PositionInvariant)) r.instructions = 4;
  bool fog = false;
  if (program.HasOption(OptionId::FogLinear)) {
    r.instructions = 2;
    fog = true;
  } else if (program.HasOption(OptionId::FogExp)) {
    r.instructions = 3;
    fog = true;
  } else if (program.HasOption(OptionId::FogExp2)) {
    r.instructions = 4;
    fog = true;
  }
  if (fog) {
    r.temporaries = 1;
    r.attribs = 1;
    r.parameters = 2;
  }
  return r;
}

// Texture indirections, counted exactly as ARB_fragment_program issue 24's pseudo-code.
// Returns the count and, for each indirection past the first, the instruction starting it.
int CountIndirections(const Program& program, std::vector<size_t>* starts) {
  int indirections = 1;
  std::set<int> temps_output;
  std::set<int> alu_temps;
  auto is_temp = [&](int var) {
    return var >= 0 && program.vars[static_cast<size_t>(var)].kind == VarKind::Temp;
  };
  for (size_t i = 0; i < program.instructions.size(); ++i) {
    const Instruction& inst = program.instructions[i];
    bool tex = GetOpcodeInfo(inst.op).klass == OpClass::Tex;
    bool kil = inst.op == Opcode::KIL;
    if (tex) {
      int input = inst.src[0].var;
      if ((is_temp(input) && temps_output.count(input)) ||
          (!kil && is_temp(inst.dst.var) && alu_temps.count(inst.dst.var))) {
        ++indirections;
        starts->push_back(i);
        temps_output.clear();
        alu_temps.clear();
      }
    } else {
      for (size_t s = 0; s < inst.src_count; ++s) {
        if (is_temp(inst.src[s].var)) alu_temps.insert(inst.src[s].var);
      }
      if (is_temp(inst.dst.var)) alu_temps.insert(inst.dst.var);
    }
    if (!kil && is_temp(inst.dst.var)) temps_output.insert(inst.dst.var);
  }
  return indirections;
}

std::string CountKey(const Binding& b, ProgramKind kind) {
  if (b.kind == BindingKind::Constant) {
    // Numerically equal constants count once (so -0 equals 0).
    return fmt::format("const {} {} {} {}", b.value[0] + 0.0f, b.value[1] + 0.0f, b.value[2] + 0.0f,
                       b.value[3] + 0.0f);
  }
  return BindingName(b, kind);
}

}  // namespace

std::string CheckContext::StageKey(std::string_view name) const {
  return fmt::format("{}.{}", vp() ? "arbvp" : "arbfp", name);
}

bool CheckLimit(const CheckContext& ctx, std::string_view key, int64_t used, int reserve, Diag diag,
                Range range, std::string_view what) {
  const compiler::LimitProfile* enforced =
      ctx.profile ? ctx.profile : compiler::BuiltinProfile("mesa");
  int64_t limit = enforced->Get(key) - reserve;
  std::string reserve_note =
      reserve > 0 ? fmt::format(" ({} reserved by the program's options)", reserve) : "";
  if (used > limit) {
    ctx.Report(diag, range,
               fmt::format("{} exceeds the limit: {} is {} in profile '{}'{}", what, GlName(key),
                           limit, enforced->name, reserve_note));
    return false;
  }
  if (!ctx.profile) {
    int64_t minimum = compiler::BuiltinProfile("spec-min")->Get(key) - reserve;
    if (used > minimum) {
      ctx.Report(Diag::LimitPortability, range,
                 fmt::format("{} exceeds the specification's minimum {} = {}{}; "
                             "implementations at the minimum reject it",
                             what, GlName(key), minimum, reserve_note));
    }
  }
  return true;
}

void CheckResources(const CheckContext& ctx) {
  const Program& program = ctx.program;
  Stats& stats = *ctx.stats;
  Reserve reserve = OptionReserve(program);

  // Instructions, and for fragment programs ALU and TEX instructions.
  int alu = 0;
  int tex = 0;
  for (const Instruction& inst : program.instructions) {
    (GetOpcodeInfo(inst.op).klass == OpClass::Tex ? tex : alu)++;
  }
  stats.instructions = static_cast<int>(program.instructions.size());
  stats.alu_instructions = alu;
  stats.tex_instructions = tex;

  auto report_first_over = [&](std::string_view key, int reserve_n, Diag diag,
                               auto counts_instruction, std::string_view what) {
    const compiler::LimitProfile* enforced =
        ctx.profile ? ctx.profile : compiler::BuiltinProfile("mesa");
    int64_t error_limit = enforced->Get(key) - reserve_n;
    int64_t warn_limit =
        ctx.profile ? error_limit : compiler::BuiltinProfile("spec-min")->Get(key) - reserve_n;
    int count = 0;
    bool warned = false;
    for (const Instruction& inst : program.instructions) {
      if (!counts_instruction(inst)) continue;
      ++count;
      if (count > error_limit) {
        CheckLimit(ctx, key, count, reserve_n, diag, inst.opcode_range,
                   fmt::format("{} {}", what, count));
        return;
      }
      if (count > warn_limit && !warned) {
        warned = true;
        CheckLimit(ctx, key, count, reserve_n, diag, inst.opcode_range,
                   fmt::format("{} {}", what, count));
      }
    }
  };
  auto any = [](const Instruction&) { return true; };
  report_first_over(ctx.StageKey("max_instructions"), reserve.instructions, Diag::LimitInstructions,
                    any, "instruction");
  if (!ctx.vp()) {
    auto is_alu = [](const Instruction& inst) {
      return GetOpcodeInfo(inst.op).klass == OpClass::Alu;
    };
    auto is_tex = [](const Instruction& inst) {
      return GetOpcodeInfo(inst.op).klass == OpClass::Tex;
    };
    report_first_over("arbfp.max_alu_instructions", reserve.instructions,
                      Diag::LimitAluInstructions, is_alu, "ALU instruction");
    report_first_over("arbfp.max_tex_instructions", 0, Diag::LimitTexInstructions, is_tex,
                      "texture instruction");
    std::vector<size_t> starts;
    stats.tex_indirections = CountIndirections(program, &starts);
    // Indirection k (k >= 2) starts at starts[k - 2]; report the first past each limit.
    const compiler::LimitProfile* enforced =
        ctx.profile ? ctx.profile : compiler::BuiltinProfile("mesa");
    int64_t error_limit = enforced->Get("arbfp.max_tex_indirections");
    int64_t warn_limit =
        ctx.profile ? error_limit
                    : compiler::BuiltinProfile("spec-min")->Get("arbfp.max_tex_indirections");
    bool warned = false;
    for (size_t k = 0; k < starts.size(); ++k) {
      int64_t count = static_cast<int64_t>(k) + 2;
      const Instruction& inst = program.instructions[starts[k]];
      if (count > error_limit || (count > warn_limit && !warned)) {
        warned = true;
        CheckLimit(ctx, "arbfp.max_tex_indirections", count, 0, Diag::LimitTexIndirections,
                   inst.opcode_range, fmt::format("texture indirection {}", count));
        if (count > error_limit) break;
      }
    }
  }

  // Declared temporaries and address registers, attributes and parameters (distinct).
  int temps = 0;
  int addresses = 0;
  std::set<std::string> attribs;
  std::set<std::string> params;
  std::set<std::string> outputs;
  bool temps_over = false, address_over = false, attribs_over = false, params_over = false;
  for (const Variable& var : program.vars) {
    switch (var.kind) {
      case VarKind::Temp:
        ++temps;
        if (!temps_over) {
          temps_over = !CheckLimit(ctx, ctx.StageKey("max_temporaries"), temps, reserve.temporaries,
                                   Diag::LimitTemporaries, var.decl,
                                   fmt::format("temporary '{}' (number {})", var.name, temps));
        }
        break;
      case VarKind::Address:
        ++addresses;
        if (!address_over) {
          address_over = !CheckLimit(
              ctx, "arbvp.max_address_registers", addresses, 0, Diag::LimitAddressRegisters,
              var.decl, fmt::format("address register '{}' (number {})", var.name, addresses));
        }
        break;
      case VarKind::Attrib:
        for (const Binding& b : var.bindings) {
          if (attribs.insert(BindingName(b, program.kind)).second && !attribs_over) {
            attribs_over =
                !CheckLimit(ctx, ctx.StageKey("max_attribs"), static_cast<int64_t>(attribs.size()),
                            reserve.attribs, Diag::LimitAttributes, var.decl,
                            fmt::format("attribute binding {} ('{}')", attribs.size(),
                                        BindingName(b, program.kind)));
          }
        }
        break;
      case VarKind::Param:
        for (const Binding& b : var.bindings) {
          if (params.insert(CountKey(b, program.kind)).second && !params_over) {
            params_over = !CheckLimit(ctx, ctx.StageKey("max_parameters"),
                                      static_cast<int64_t>(params.size()), reserve.parameters,
                                      Diag::LimitParameters, var.decl,
                                      fmt::format("parameter binding {}", params.size()));
          }
        }
        break;
      case VarKind::Output:
        for (const Binding& b : var.bindings) outputs.insert(BindingName(b, program.kind));
        break;
    }
  }
  stats.temporaries = temps;
  stats.address_registers = addresses;
  stats.attributes = static_cast<int>(attribs.size());
  stats.parameters = static_cast<int>(params.size());
  stats.outputs = static_cast<int>(outputs.size());
}

}  // namespace arbiter::arbvp
