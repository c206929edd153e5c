// Tokens of ARB program text (ARBvp 2.14.2, ARBfp 3.11.2).
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/source.h"

namespace arbiter::arbvp {

enum class Tok : uint8_t {
  Ident,      // letters, digits, '_', '$'; not starting with a digit (also "1D" "2D" "3D")
  Integer,    // digits
  Float,      // a <floatConstant> that is not a plain integer
  Dot,        // .
  DotDot,     // ..
  Comma,      // ,
  Semicolon,  // ;
  LBracket,   // [
  RBracket,   // ]
  LBrace,     // {
  RBrace,     // }
  Equals,     // =
  Plus,       // +
  Minus,      // -
  Eof,
};

struct Token {
  Tok kind = Tok::Eof;
  uint32_t begin = 0;
  uint32_t end = 0;
};

// Splits text[start..] into tokens; invalid characters and malformed numbers are reported
// and skipped. The last token is always Eof (at the end of the text).
std::vector<Token> Lex(const compiler::SourceFile& source, uint32_t start,
                       compiler::DiagnosticSink* sink);

std::string_view TokenKindName(Tok kind);

}  // namespace arbiter::arbvp
