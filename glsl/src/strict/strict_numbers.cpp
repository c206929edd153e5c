// GLSL 1.10 4.1.4: floats are single precision. A literal beyond a 32-bit float's range
// silently becomes infinity (or zero, below the smallest denormal) in glslang and in every
// driver; the shader author almost certainly meant something else, so it is a warning.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "strict.h"

namespace arbiter::glsl {
namespace {

bool IsDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// The length of the literal a number token starts with (digits, '.', an exponent) and whether
// it is a floating-point literal (it has a '.' or an exponent).
size_t LiteralLength(std::string_view text, bool* is_float) {
  size_t i = 0;
  while (i < text.size() && IsDigit(text[i])) ++i;
  *is_float = false;
  if (i < text.size() && text[i] == '.') {
    *is_float = true;
    ++i;
    while (i < text.size() && IsDigit(text[i])) ++i;
  }
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    size_t j = i + 1;
    if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
    if (j < text.size() && IsDigit(text[j])) {
      *is_float = true;
      i = j;
      while (i < text.size() && IsDigit(text[i])) ++i;
    }
  }
  return i;
}

bool HasNonZeroMantissaDigit(std::string_view number) {
  for (char c : number) {
    if (c == 'e' || c == 'E') break;
    if (c >= '1' && c <= '9') return true;
  }
  return false;
}

// The tokens of the text, its directives' included, in text order.
std::vector<Token> AllTokens(std::string_view blanked) {
  std::vector<Token> tokens = Tokenize(blanked);
  for (const Directive& d : Directives(blanked)) {
    tokens.insert(tokens.end(), d.words.begin(), d.words.end());
  }
  std::ranges::sort(tokens, {}, &Token::offset);
  return tokens;
}

}  // namespace

void CheckFloatLiterals(const StrictContext& ctx) {
  for (size_t index = 0; index < ctx.sources.size(); ++index) {
    const compiler::SourceFile* file = ctx.sources[index];
    const std::string& text = BlankedText(ctx, index);
    for (const Token& t : AllTokens(text)) {
      // Digits right after a name or a '.' belong to them ('a.5e50', '1..5'): no literal.
      const char before = t.offset > 0 ? text[t.offset - 1] : ' ';
      if (t.kind != Token::Number || IsIdentChar(before) || before == '.') continue;
      // The literal's digits, point and exponent: glslang reports a suffix itself.
      bool is_float = false;
      const std::string number(t.text.substr(0, LiteralLength(t.text, &is_float)));
      if (!is_float) continue;
      const float value = std::strtof(number.c_str(), nullptr);
      if (std::isinf(value) || (value == 0.0f && HasNonZeroMantissaDigit(number))) {
        const compiler::Range range{t.offset, static_cast<uint32_t>(t.offset + number.size())};
        ctx.sink->Report(Info(Diag::NumberRange), file, range,
                         fmt::format("{} is beyond the range of a 32-bit float: it becomes {}",
                                     number, std::isinf(value) ? "infinity" : "zero"));
      }
    }
  }
}

}  // namespace arbiter::glsl
