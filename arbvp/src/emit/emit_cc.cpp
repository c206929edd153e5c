// The NV condition codes and destination update (NV_vertex_program2_option 2.14.4.3,
// NV_fragment_program_option 3.11.4.3): a condition code register is a vec4 holding, per
// component, the last value written through it (its sign is GT, EQ or LT; NaN is UN), so
// each test is one float comparison with IEEE semantics (NaN compares false except !=).
#include <fmt/format.h>

#include <algorithm>

#include "emit/emit_context.h"

namespace arbiter::arbvp::emit {
namespace {

// One row per CcRule (ir.h order): the comparison of a code with 0 and its vector
// function; TR and FL compare nothing. "Comparisons involving condition codes of UN
// evaluate to true for NE and false otherwise": exactly IEEE's != and the others.
struct RuleRow {
  const char* op;
  const char* function;
};
constexpr RuleRow kRules[] = {
    {"==", "equal"},             // EQ
    {">=", "greaterThanEqual"},  // GE
    {">", "greaterThan"},        // GT
    {"<=", "lessThanEqual"},     // LE
    {"<", "lessThan"},           // LT
    {"!=", "notEqual"},          // NE
    {nullptr, nullptr},          // TR
    {nullptr, nullptr},          // FL
};

const RuleRow& Rule(const Context& ctx, CcRule rule) {
  if (rule == CcRule::GT && ctx.Mutated(Mutation::CcGtAsGe)) rule = CcRule::GE;
  return kRules[static_cast<size_t>(rule)];
}

char Letter(Swz s) { return "xyzw01"[static_cast<int>(s)]; }

// The distinct condition code components a test reads, in swizzle order.
std::string DistinctLetters(const CcTest& cc) {
  std::string out;
  for (Swz s : cc.swizzle) {
    if (out.find(Letter(s)) == std::string::npos) out += Letter(s);
  }
  return out;
}

}  // namespace

void DeclareLocal(Context& ctx, const std::string& name, const std::string& declaration) {
  ctx.nv_locals.emplace(name, declaration);
}

// "The condition code register is initialized to a vector of EQ values."
std::string CcName(Context& ctx, int reg) {
  std::string name = fmt::format("arb_cc{}", reg);
  DeclareLocal(
      ctx, name,
      fmt::format("vec4 {} = vec4(0.0);  // condition code CC{}: EQ everywhere", name, reg));
  return name;
}

std::string CcComponentTest(Context& ctx, const CcTest& cc, int comp) {
  if (!cc.present || cc.rule == CcRule::TR) return "true";
  if (cc.rule == CcRule::FL) return "false";
  return fmt::format("{}.{} {} 0.0", CcName(ctx, cc.reg),
                     Letter(cc.swizzle[static_cast<size_t>(comp)]), Rule(ctx, cc.rule).op);
}

std::string CcAnyTest(Context& ctx, const CcTest& cc) {
  if (!cc.present || cc.rule == CcRule::TR) return "true";
  if (cc.rule == CcRule::FL) return "false";
  std::string letters = DistinctLetters(cc);
  std::string name = CcName(ctx, cc.reg);
  if (letters.size() == 1) return fmt::format("{}.{} {} 0.0", name, letters, Rule(ctx, cc.rule).op);
  return fmt::format("any({}({}{}, {}(0.0)))", Rule(ctx, cc.rule).function, name,
                     letters == "xyzw" ? "" : "." + letters,
                     VecType(static_cast<int>(letters.size())));
}

bool NeedsCcWrite(const Instruction& inst) {
  return inst.cc_update >= 0 || (inst.dst.cc.present && inst.dst.cc.rule != CcRule::TR);
}

// UpdateDestination: the result is merged into the destination and, with a C suffix, into
// the condition code, for the components both the write mask and the condition code test
// enable; the test reads the condition code as it was before the instruction.
std::string CcWrite(Context& ctx, const Instruction& inst, const Comps& comps, const Expr& result,
                    const std::function<std::string(int)>& lvalue, bool integer) {
  const CcTest& test = inst.dst.cc;
  if (test.present && test.rule == CcRule::FL) {
    return "// (FL): the condition code test enables no component; nothing is written\n";
  }
  const std::string t = integer ? "arb_ti" : "arb_t";
  DeclareLocal(ctx, t,
               integer ? "ivec4 arb_ti = ivec4(0);  // an NV address result before its write"
                       : "vec4 arb_t = vec4(0.0);  // an NV result before its write");
  const std::string letters = Letters(comps);
  const bool all = comps == AllComps();
  std::string out = fmt::format("{}{} = {};\n", t, all ? "" : "." + letters, result.text);
  const bool masked =
      test.present && test.rule != CcRule::TR && !ctx.Mutated(Mutation::CcWriteMaskIgnored);
  std::string cc = inst.cc_update >= 0 && !ctx.Mutated(Mutation::CcUpdateIgnored)
                       ? CcName(ctx, inst.cc_update)
                       : "";
  // A C suffix on the register the test reads would change codes later components test.
  bool tests_first = masked && inst.cc_update == test.reg && comps.size() > 1;
  bool one_test = true;
  for (int c : comps)
    one_test = one_test &&
               test.swizzle[static_cast<size_t>(c)] == test.swizzle[static_cast<size_t>(comps[0])];
  if (tests_first && !one_test) {
    DeclareLocal(ctx, "arb_m", "bvec4 arb_m = bvec4(false);  // a condition code test");
    std::string swz;
    for (Swz s : test.swizzle) swz += Letter(s);
    out += fmt::format("arb_m = {}({}.{}, vec4(0.0));\n", Rule(ctx, test.rule).function,
                       CcName(ctx, test.reg), swz);
  }
  auto cc_value = [&](const std::string& part, int width) {
    return integer ? fmt::format("{}({})", VecType(width), part) : part;
  };
  auto write = [&](const Comps& which) {
    std::string lines;
    const std::string l = Letters(which);
    const bool whole = which == AllComps();
    const std::string part = t + (whole ? "" : "." + l);
    // Vector destinations take the components at once; a float one (fog, point size,
    // depth, clip distance) its component.
    bool vector = true;
    for (int c : which) vector = vector && lvalue(c).find('.') != std::string::npos;
    if (vector && !which.empty()) {
      std::string base = lvalue(which[0]);
      base = base.substr(0, base.rfind('.'));
      lines += fmt::format("{}{} = {};\n", base, whole ? "" : "." + l, part);
    } else {
      for (int c : which) {
        if (!lvalue(c).empty()) lines += fmt::format("{} = {}.{};\n", lvalue(c), t, "xyzw"[c]);
      }
    }
    if (!cc.empty()) {
      lines += fmt::format("{}{} = {};\n", cc, whole ? "" : "." + l,
                           cc_value(part, static_cast<int>(which.size())));
    }
    return lines;
  };
  auto guarded = [](const std::string& condition, const std::string& lines) {
    if (lines.empty()) return std::string();
    if (std::count(lines.begin(), lines.end(), '\n') == 1) {
      return fmt::format("if ({}) {}", condition, lines);
    }
    std::string body;
    size_t start = 0;
    while (start < lines.size()) {
      size_t end = lines.find('\n', start);
      body += "  " + lines.substr(start, end - start + 1);
      start = end + 1;
    }
    return fmt::format("if ({}) {{\n{}}}\n", condition, body);
  };
  if (!masked) return out + write(comps);
  if (one_test) return out + guarded(CcComponentTest(ctx, test, comps[0]), write(comps));
  for (int c : comps) {
    std::string condition =
        tests_first ? fmt::format("arb_m.{}", "xyzw"[c]) : CcComponentTest(ctx, test, c);
    out += guarded(condition, write({c}));
  }
  return out;
}

}  // namespace arbiter::arbvp::emit
