// The NV options' words (nv_syntax.h).
#include "nv_syntax.h"

#include <array>

namespace arbiter::arbvp {
namespace {

constexpr std::array<std::string_view, 8> kCcRules = {"EQ", "GE", "GT", "LE",
                                                      "LT", "NE", "TR", "FL"};

bool EndsWith(std::string_view s, std::string_view suffix) {
  return s.size() > suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

}  // namespace

bool DecodeOpcodeWord(std::string_view word, OpcodeWord* out) {
  OpcodeWord w;
  if (EndsWith(word, "_SSAT")) {
    w.signed_saturate = true;
    word.remove_suffix(5);
  } else if (EndsWith(word, "_SAT")) {
    w.saturate = true;
    word.remove_suffix(4);
  }
  struct Suffix {
    std::string_view text;
    int8_t value;
  };
  constexpr Suffix kCc[] = {{"", -1}, {"C", 0}, {"C0", 0}, {"C1", 1}};
  constexpr Suffix kPrecision[] = {{"", 0}, {"R", 1}, {"H", 2}, {"X", 3}};
  for (const Suffix& cc : kCc) {
    if (!cc.text.empty() && !EndsWith(word, cc.text)) continue;
    std::string_view rest = word.substr(0, word.size() - cc.text.size());
    for (const Suffix& p : kPrecision) {
      if (!p.text.empty() && !EndsWith(rest, p.text)) continue;
      if (LookupOpcode(rest.substr(0, rest.size() - p.text.size()), &w.op)) {
        w.cc = cc.value;
        w.precision = static_cast<Precision>(p.value);
        *out = w;
        return true;
      }
    }
  }
  return false;
}

std::string_view OpcodeModifiers(const OpcodeInfo& info, ProgramKind kind, int level) {
  if (kind == ProgramKind::Vertex) {
    return level >= 2 ? info.vp_mods : level == 1 ? (info.vp_mods.empty() ? "" : "C") : "";
  }
  return level >= 2   ? info.fp2_mods
         : level == 1 ? info.fp_mods
                      : (info.op == Opcode::KIL ? "" : "S");
}

bool IsNvReservedWord(std::string_view word, const Program& program) {
  const int level = program.NvLevel();
  if (level == 0 || word.empty() || word[0] < 'A' || word[0] > 'Z') return false;
  OpcodeWord w;
  if (!DecodeOpcodeWord(word, &w) || !program.HasOpcode(w.op)) return false;
  const bool plain =
      !w.saturate && !w.signed_saturate && w.cc < 0 && w.precision == Precision::Default;
  if (program.kind == ProgramKind::Vertex) return plain;
  const std::string_view mods = OpcodeModifiers(GetOpcodeInfo(w.op), program.kind, level);
  auto has = [&](char m) { return mods.find(m) != std::string_view::npos; };
  if ((w.saturate || w.signed_saturate) && !has('S')) return false;
  if (w.signed_saturate && level < 2) return false;
  if (w.cc >= 0 && (!has('C') || w.cc == 1)) return false;
  return w.precision == Precision::Default || has("?RHX"[static_cast<int>(w.precision)]);
}

bool IsCcRule(std::string_view word) {
  if (word.size() != 2 && !(word.size() == 3 && (word[2] == '0' || word[2] == '1'))) return false;
  for (std::string_view rule : kCcRules) {
    if (word.substr(0, 2) == rule) return true;
  }
  return false;
}

CcRule CcRuleOf(std::string_view two_letters) {
  for (size_t i = 0; i < kCcRules.size(); ++i) {
    if (two_letters == kCcRules[i]) return static_cast<CcRule>(i);
  }
  return CcRule::TR;
}

std::string_view CcRuleName(CcRule rule) { return kCcRules[static_cast<size_t>(rule)]; }

std::string_view NvOptionName(bool vertex, OpLevel level) {
  if (vertex) return level == OpLevel::Nv2 ? "NV_vertex_program3" : "NV_vertex_program2";
  return level == OpLevel::Nv2 ? "NV_fragment_program2" : "NV_fragment_program";
}

}  // namespace arbiter::arbvp
