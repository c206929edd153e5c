// Recursive-descent parser of ARB programs: tokens -> IR, with name resolution.
#pragma once

#include <memory>

#include "arbiter/arbvp/ir.h"
#include "arbiter/compiler/diagnostic.h"
#include "lexer.h"

namespace arbiter::arbvp {

// Parses the program text after the header. Lexical errors, grammar errors, unresolved
// names and bindings that do not exist in `kind` are reported here, the lexical errors
// first; limits and cross-statement rules are left to the checks (check/checks.h). The
// returned program holds every statement that parsed.
std::unique_ptr<Program> ParseProgram(const compiler::SourceFile& source, ProgramKind kind,
                                      Range header, compiler::DiagnosticSink* sink);

// The names a program of `kind` may not use as identifiers (ARBvp 2.14.2, ARBfp 3.11.2).
bool IsReservedWord(std::string_view word, ProgramKind kind);

}  // namespace arbiter::arbvp
