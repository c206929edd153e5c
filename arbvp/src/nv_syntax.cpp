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
