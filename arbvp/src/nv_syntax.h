// The words the NV program options add to the ARB grammar: opcode suffixes (precision,
// condition code update, _SAT / _SSAT), condition code rules, and the options' names.
#pragma once

#include <cstdint>
#include <string_view>

#include "arbiter/arbvp/ir.h"

namespace arbiter::arbvp {

// An instruction word split into its opcode and suffixes: "ADDRC_SAT" is ADD, R, C, _SAT.
struct OpcodeWord {
  Opcode op = Opcode::MOV;
  Precision precision = Precision::Default;
  int8_t cc = -1;  // C and C0: 0, C1: 1
  bool saturate = false;
  bool signed_saturate = false;
};

// Splits `word` (table X.5: <opcode>[R|H|X][C|C0|C1][_SAT|_SSAT]); false if no opcode reads
// so. The longest opcode wins: "DDXC" is DDX with C, not DD with X and C.
bool DecodeOpcodeWord(std::string_view word, OpcodeWord* out);

// The suffix letters table X.5 gives `info` in a program of `kind` at NV level `level` (0: no
// NV option): S (_SAT, and _SSAT at level 2), C, R, H, X.
std::string_view OpcodeModifiers(const OpcodeInfo& info, ProgramKind kind, int level);

// The NV options reserve their instruction names: in vertex programs the opcodes
// (NV_vertex_program2_option and NV_vertex_program3 list them), in fragment programs "all the
// instruction names (and variants) listed in Table X.5" (NV_fragment_program_option).
bool IsNvReservedWord(std::string_view word, const Program& program);

// <ccMaskRule>: EQ GE GT LE LT NE TR FL, with a register digit 0 or 1 ("GT1").
bool IsCcRule(std::string_view word);
CcRule CcRuleOf(std::string_view two_letters);
std::string_view CcRuleName(CcRule rule);

// The option that brings `level` to a program kind: NV_vertex_program2 / 3,
// NV_fragment_program / NV_fragment_program2.
std::string_view NvOptionName(bool vertex, OpLevel level);

}  // namespace arbiter::arbvp
