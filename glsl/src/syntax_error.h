// Where a glslang syntax error is. glslang names the unexpected token by its grammar name
// ("syntax error, unexpected FLOAT, expecting COMMA or SEMICOLON") and gives its line only;
// this finds the token on that line, and the end of the statement before it when the parser
// wanted a ';' (the usual cause: a missing ';' at the end of the previous line).
#pragma once

#include <optional>
#include <string_view>

#include "arbiter/compiler/source.h"

namespace arbiter::glsl {

struct SyntaxErrorPlace {
  compiler::Range token;  // the unexpected token
  // When the parser expected a ';' and the token starts its line: the end of the last token
  // before it, where the ';' is missing.
  std::optional<compiler::Range> missing_semicolon;
};

// The place of a syntax error glslang reports on 1-based `line` with `message` ("syntax
// error, unexpected NAME[, expecting ...]"); nullopt when the token is not found there.
std::optional<SyntaxErrorPlace> LocateSyntaxError(const compiler::SourceFile& file, uint32_t line,
                                                  std::string_view message);

}  // namespace arbiter::glsl
