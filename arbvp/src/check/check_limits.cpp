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

// Counts a resource and reports it once at the first count past the spec minimum
// (portability mode) and once at the first count past the enforced limit.
class LimitCounter {
 public:
  LimitCounter(const CheckContext& ctx, std::string key, int reserve, Diag diag)
      : ctx_(ctx), key_(std::move(key)), reserve_(reserve), diag_(diag) {}

  void Add(Range range, const std::string& what) {
    ++count_;
    if (failed_) return;
    const compiler::LimitProfile* enforced =
        ctx_.profile ? ctx_.profile : compiler::BuiltinProfile("mesa");
    bool over_error = count_ > enforced->Get(key_) - reserve_;
    if (warned_ && !over_error) return;
    size_t before = ctx_.sink->diagnostics().size();
    failed_ = !CheckLimit(ctx_, key_, count_, reserve_, diag_, range, what, !warned_);
    if (ctx_.sink->diagnostics().size() != before) warned_ = true;
  }
  int64_t count() const { return count_; }

 private:
  const CheckContext& ctx_;
  std::string key_;
  int reserve_;
  Diag diag_;
  int64_t count_ = 0;
  bool warned_ = false;
  bool failed_ = false;
};

}  // namespace

std::string CheckContext::StageKey(std::string_view name) const {
  return fmt::format("{}.{}", vp() ? "arbvp" : "arbfp", name);
}

bool CheckLimit(const CheckContext& ctx, std::string_view key, int64_t used, int reserve, Diag diag,
                Range range, std::string_view what, bool allow_warning) {
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
  if (!ctx.profile && allow_warning) {
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

  auto count_instructions = [&](std::string key, int reserve_n, Diag diag, auto counts,
                                std::string_view what) {
    LimitCounter counter(ctx, std::move(key), reserve_n, diag);
    for (const Instruction& inst : program.instructions) {
      if (counts(inst))
        counter.Add(inst.opcode_range, fmt::format("{} {}", what, counter.count() + 1));
    }
  };
  auto any = [](const Instruction&) { return true; };
  count_instructions(ctx.StageKey("max_instructions"), reserve.instructions,
                     Diag::LimitInstructions, any, "instruction");
  if (!ctx.vp()) {
    auto is_alu = [](const Instruction& inst) {
      return GetOpcodeInfo(inst.op).klass == OpClass::Alu;
    };
    auto is_tex = [](const Instruction& inst) {
      return GetOpcodeInfo(inst.op).klass == OpClass::Tex;
    };
    count_instructions("arbfp.max_alu_instructions", reserve.instructions,
                       Diag::LimitAluInstructions, is_alu, "ALU instruction");
    count_instructions("arbfp.max_tex_instructions", 0, Diag::LimitTexInstructions, is_tex,
                       "texture instruction");
    std::vector<size_t> starts;
    stats.tex_indirections = CountIndirections(program, &starts);
    // Indirection k (k >= 2) starts at instruction starts[k - 2].
    LimitCounter indirections(ctx, "arbfp.max_tex_indirections", 0, Diag::LimitTexIndirections);
    indirections.Add(Range{}, "");  // the first indirection is free of any instruction
    for (size_t start : starts) {
      indirections.Add(program.instructions[start].opcode_range,
                       fmt::format("texture indirection {}", indirections.count() + 1));
    }
  }

  // Declared temporaries and address registers; distinct attributes and parameters.
  LimitCounter temps(ctx, ctx.StageKey("max_temporaries"), reserve.temporaries,
                     Diag::LimitTemporaries);
  LimitCounter addresses(ctx, "arbvp.max_address_registers", 0, Diag::LimitAddressRegisters);
  LimitCounter attribs(ctx, ctx.StageKey("max_attribs"), reserve.attribs, Diag::LimitAttributes);
  LimitCounter params(ctx, ctx.StageKey("max_parameters"), reserve.parameters,
                      Diag::LimitParameters);
  std::set<std::string> seen_attribs;
  std::set<std::string> seen_params;
  std::set<std::string> outputs;
  std::set<int> relative = RelativelyAddressed(program);
  for (size_t v = 0; v < program.vars.size(); ++v) {
    const Variable& var = program.vars[v];
    switch (var.kind) {
      case VarKind::Temp:
        temps.Add(var.decl, fmt::format("temporary '{}' (number {})", var.name, temps.count() + 1));
        break;
      case VarKind::Address:
        addresses.Add(var.decl, fmt::format("address register '{}' (number {})", var.name,
                                            addresses.count() + 1));
        break;
      case VarKind::Attrib:
        for (const Binding& b : var.bindings) {
          std::string name = BindingName(b, program.kind);
          if (seen_attribs.insert(name).second) {
            attribs.Add(var.decl,
                        fmt::format("attribute binding {} ('{}')", attribs.count() + 1, name));
          }
        }
        break;
      case VarKind::Param:
        for (const Binding& b : var.bindings) {
          // ARBvp 2.14.3.7: each constant of a relatively addressed array counts, even when
          // identical to another; state vectors and other constants count once.
          bool always = b.kind == BindingKind::Constant && relative.count(static_cast<int>(v));
          if (seen_params.insert(CountKey(b, program.kind)).second || always) {
            params.Add(var.decl, fmt::format("parameter binding {}", params.count() + 1));
          }
        }
        break;
      case VarKind::Output:
        for (const Binding& b : var.bindings) outputs.insert(BindingName(b, program.kind));
        break;
    }
  }
  stats.temporaries = static_cast<int>(temps.count());
  stats.address_registers = static_cast<int>(addresses.count());
  stats.attributes = static_cast<int>(attribs.count());
  stats.parameters = static_cast<int>(params.count());
  stats.outputs = static_cast<int>(outputs.size());
}

}  // namespace arbiter::arbvp
