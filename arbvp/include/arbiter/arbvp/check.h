// Checking an ARB vertex or fragment program: parse, semantic checks, resource accounting.
#pragma once

#include <memory>
#include <optional>
#include <string_view>

#include "arbiter/arbvp/ir.h"
#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/limits.h"

namespace arbiter::arbvp {

struct CheckOptions {
  // The limit profile to enforce. nullptr: the mesa profile's limits (what Mesa takes), with
  // no warning for going past the specification's minimum (compiler::BuiltinProfile
  // ("spec-min") makes that an error).
  const compiler::LimitProfile* profile = nullptr;
  // The program kind the caller expects (--stage); nullopt: take it from the header.
  std::optional<ProgramKind> expected_kind;
};

// Resource usage as the specs count it (ARBvp 2.14.3.x, ARBfp 3.11.3.6).
struct Stats {
  int instructions = 0;
  int alu_instructions = 0;
  int tex_instructions = 0;
  int tex_indirections = 0;
  int temporaries = 0;
  int parameters = 0;  // parameter bindings (vectors)
  int attributes = 0;
  int address_registers = 0;
  int outputs = 0;
};

struct CheckResult {
  // The parsed program; null when the header was unusable. Present (possibly partial) even
  // when errors were reported: only use it for execution when `ok`.
  std::unique_ptr<Program> program;
  Stats stats;
  bool ok = false;  // no errors
};

// Parses and checks one program; every problem goes to `sink`.
CheckResult CheckProgram(const compiler::SourceFile& source, const CheckOptions& options,
                         compiler::DiagnosticSink* sink);

// True when the text starts with an ARB program header ("!!ARB").
bool LooksLikeArbProgram(std::string_view text);

// The table of every arbvp diagnostic (for docs and SARIF rules).
const std::vector<const compiler::DiagnosticInfo*>& AllDiagnostics();

}  // namespace arbiter::arbvp
