// Resource accounting against limit profiles (ARBvp 2.14.3.x and 6.1.12, ARBfp 3.11.3.6).
#include <fmt/format.h>

#include <array>
#include <cassert>
#include <cstdint>
#include <set>
#include <string>

#include "../binding_key.h"
#include "../flat_table.h"
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

// Distinct bindings, as their canonical names tell them apart (BindingName, or for the
// parameter count numeric equality of constants, so that -0 equals 0), compared by key
// (binding_key.h) rather than by name: no string per bound vector.
class DistinctBindings {
 public:
  explicit DistinctBindings(bool signed_zero) : signed_zero_(signed_zero) {}

  // True when no binding before was the same.
  bool Insert(const Binding& b) {
    BindingKey key = KeyOf(b, signed_zero_);
    bool inserted = false;
    BindingKey* slot = seen_.FindOrInsert(
        BindingKeyHash{}(key), [&](const BindingKey& k) { return k == key; }, &inserted);
    if (inserted) *slot = key;
    return inserted;
  }
  size_t size() const { return seen_.size(); }

 private:
  bool signed_zero_;
  FlatTable<BindingKey> seen_;
};

// Counts a resource and reports it once, at the first count past the enforced limit.
class LimitCounter {
 public:
  LimitCounter(const CheckContext& ctx, std::string_view key, int reserve, Diag diag)
      : ctx_(ctx),
        key_(key),
        reserve_(reserve),
        diag_(diag),
        quiet_(QuietLimit(ctx, key_, reserve)) {}

  // Counts one more. `describe` returns what is counted ("instruction 129"); it is called
  // only when a diagnostic is due, as building it for every count is most of the work.
  template <typename Describe>
  void Add(Range range, const Describe& describe) {
    ++count_;
    if (reported_ || count_ <= quiet_) return;
    reported_ = true;
    CheckLimit(ctx_, key_, count_, reserve_, diag_, range, describe());
  }
  int64_t count() const { return count_; }

 private:
  const CheckContext& ctx_;
  std::string_view key_;  // static storage
  int reserve_;
  Diag diag_;
  int64_t quiet_;  // counts up to this one report nothing
  int64_t count_ = 0;
  bool reported_ = false;
};

}  // namespace

std::string_view CheckContext::StageKey(std::string_view name) const {
  std::string_view prefix = vp() ? "arbvp." : "arbfp.";
  for (const compiler::LimitKey& k : compiler::LimitKeys()) {
    if (k.key.size() == prefix.size() + name.size() && k.key.starts_with(prefix) &&
        k.key.ends_with(name)) {
      return k.key;
    }
  }
  assert(false && "unknown limit key");
  return name;
}

namespace {

// The mesa profile's values (the default's), by key, where LimitProfile::Get searches a map of
// strings: the checks look a limit up for every counter and every binding of every program. The
// keys come from LimitKeys() (StageKey) or are the same literals, merged by the linker: a table
// finds them by address, and the text is compared only when the address is not there.
class MesaLimitsTable {
 public:
  MesaLimitsTable() {
    for (const compiler::LimitKey& k : compiler::LimitKeys()) {
      entries_.push_back({k.key, compiler::BuiltinProfile("mesa")->Get(k.key)});
    }
    assert(entries_.size() * 2 <= kSlots);
    for (size_t e = 0; e < entries_.size(); ++e) {
      size_t i = SlotOf(entries_[e].key.data());
      while (by_address_[i] != 0) i = (i + 1) % kSlots;
      by_address_[i] = static_cast<uint16_t>(e + 1);
    }
  }

  int64_t Get(std::string_view key) const {
    for (size_t i = SlotOf(key.data()); by_address_[i] != 0; i = (i + 1) % kSlots) {
      const Entry& e = entries_[by_address_[i] - 1u];
      if (e.key.data() == key.data() && e.key.size() == key.size()) return e.limit;
    }
    for (const Entry& e : entries_) {
      if (e.key == key) return e.limit;
    }
    assert(false && "unknown limit key");
    return 0;  // what LimitProfile::Get answers (after its assert)
  }

 private:
  struct Entry {
    std::string_view key;
    int64_t limit;
  };
  static constexpr size_t kSlots = 256;
  static size_t SlotOf(const char* p) {
    return static_cast<size_t>((reinterpret_cast<uintptr_t>(p) * 0x9E3779B97F4A7C15ull) >> 56);
  }

  std::vector<Entry> entries_;
  std::array<uint16_t, kSlots> by_address_{};  // entry index + 1; 0: empty
};

int64_t MesaLimit(std::string_view key) {
  static const MesaLimitsTable table;
  return table.Get(key);
}

}  // namespace

// Without a profile, the mesa profile's limits.
int64_t CheckContext::EnforcedLimit(std::string_view key) const {
  return profile ? profile->Get(key) : MesaLimit(key);
}

int64_t QuietLimit(const CheckContext& ctx, std::string_view key, int reserve) {
  return ctx.EnforcedLimit(key) - reserve;
}

bool CheckLimit(const CheckContext& ctx, std::string_view key, int64_t used, int reserve, Diag diag,
                Range range, std::string_view what) {
  int64_t limit = ctx.EnforcedLimit(key) - reserve;
  if (used <= limit) return true;
  std::string reserve_note =
      reserve > 0 ? fmt::format(" ({} reserved by the program's options)", reserve) : "";
  ctx.Report(
      diag, range,
      fmt::format("{} exceeds the limit: {} is {} in profile '{}'{}", what, GlName(key), limit,
                  ctx.profile ? std::string_view(ctx.profile->name) : "mesa", reserve_note));
  return false;
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

  auto count_instructions = [&](std::string_view key, int reserve_n, Diag diag, auto counts,
                                std::string_view what) {
    LimitCounter counter(ctx, key, reserve_n, diag);
    for (const Instruction& inst : program.instructions) {
      if (counts(inst)) {
        counter.Add(inst.opcode_range, [&] { return fmt::format("{} {}", what, counter.count()); });
      }
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
    // The first indirection is free of any instruction.
    indirections.Add(Range{}, [] { return std::string(); });
    for (size_t start : starts) {
      indirections.Add(program.instructions[start].opcode_range,
                       [&] { return fmt::format("texture indirection {}", indirections.count()); });
    }
  }

  // Declared temporaries and address registers; distinct attributes and parameters.
  LimitCounter temps(ctx, ctx.StageKey("max_temporaries"), reserve.temporaries,
                     Diag::LimitTemporaries);
  LimitCounter addresses(ctx, "arbvp.max_address_registers", 0, Diag::LimitAddressRegisters);
  LimitCounter attribs(ctx, ctx.StageKey("max_attribs"), reserve.attribs, Diag::LimitAttributes);
  LimitCounter params(ctx, ctx.StageKey("max_parameters"), reserve.parameters,
                      Diag::LimitParameters);
  DistinctBindings seen_attribs(/*signed_zero=*/true);
  const bool vp = program.kind == ProgramKind::Vertex;
  std::set<int> bound_slots;
  for (const Variable& var : program.vars) {
    if (var.kind != VarKind::Attrib || var.relative_array || !vp) continue;
    for (const Binding& b : var.bindings) bound_slots.insert(GenericAttribSlot(b));
  }
  DistinctBindings seen_params(/*signed_zero=*/false);
  DistinctBindings outputs(/*signed_zero=*/true);
  std::set<int> relative = RelativelyAddressed(program);
  for (size_t v = 0; v < program.vars.size(); ++v) {
    const Variable& var = program.vars[v];
    switch (var.kind) {
      case VarKind::Temp:
        temps.Add(var.decl, [&] {
          return fmt::format("temporary '{}' (number {})", var.name, temps.count());
        });
        break;
      case VarKind::Address:
        addresses.Add(var.decl, [&] {
          return fmt::format("address register '{}' (number {})", var.name, addresses.count());
        });
        break;
      case VarKind::Attrib:
        for (const Binding& b : var.bindings) {
          // An element of a relatively addressed array that another binding already holds
          // (vertex.attrib[A0.x] and vertex.position share generic attribute 0, texcoord[n]
          // and attrib[8+n]) is one slot.
          if (var.relative_array && vp && !bound_slots.insert(GenericAttribSlot(b)).second) {
            continue;
          }
          if (seen_attribs.Insert(b)) {
            attribs.Add(var.decl, [&] {
              return fmt::format("attribute binding {} ('{}')", attribs.count(),
                                 BindingName(b, program.kind));
            });
          }
        }
        break;
      case VarKind::Param:
        for (const Binding& b : var.bindings) {
          // ARBvp 2.14.3.7: each constant of a relatively addressed array counts, even when
          // identical to another; state vectors and other constants count once.
          bool always = b.kind == BindingKind::Constant && relative.count(static_cast<int>(v));
          if (seen_params.Insert(b) || always) {
            params.Add(var.decl,
                       [&] { return fmt::format("parameter binding {}", params.count()); });
          }
        }
        break;
      case VarKind::Output:
        for (const Binding& b : var.bindings) outputs.Insert(b);
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
