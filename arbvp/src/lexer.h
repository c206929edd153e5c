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
  Bar,        // |  (NV options: absolute value)
  Colon,      // :  (NV options: a label)
  LParen,     // (  (NV options: a condition code mask)
  RParen,     // )
  Eof,
};

struct Token {
  Tok kind = Tok::Eof;
  uint32_t begin = 0;
  uint32_t end = 0;
};

// Splits text[start..] into tokens, one at a time. Invalid characters and malformed numbers
// are reported to `sink` (when not null) and skipped. After the last token, Next() returns
// Eof (at the end of the text) for ever.
class Lexer {
 public:
  Lexer(const compiler::SourceFile& source, uint32_t start, compiler::DiagnosticSink* sink);

  Token Next();
  // Lexes up to `count` tokens into out[0..], stopping after Eof; returns how many. Cheaper
  // than a call per token.
  size_t Fill(Token* out, size_t count);
  // Reports nothing from now on.
  void Silence() { sink_ = nullptr; }

 private:
  Token Lex1();
  void SkipComment();
  void SkipInvalid();
  Token LexNumber();

  const compiler::SourceFile& source_;
  // The text, NUL-terminated (std::string guarantees it): scans stop at the terminator
  // without a bounds check, and the size check follows only when a scan stopped.
  const char* text_;
  uint32_t size_;
  uint32_t pos_;
  compiler::DiagnosticSink* sink_;
  bool warned_non_ascii_ = false;
};

// All the tokens of text[start..]; the last one is Eof.
std::vector<Token> Lex(const compiler::SourceFile& source, uint32_t start,
                       compiler::DiagnosticSink* sink);

std::string_view TokenKindName(Tok kind);

}  // namespace arbiter::arbvp
