// GLSL 1.10 4.1.4: floats are single precision. A literal beyond a 32-bit float's range
// silently becomes infinity (or zero, below the smallest denormal) in glslang and in every
// driver; the shader author almost certainly meant something else, so it is a warning.
#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>

#include "strict.h"

namespace arbiter::glsl {
namespace {

bool IsDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// The length of the number token at `at` (digits, '.', an exponent) and whether it is a
// floating-point literal (it has a '.' or an exponent).
size_t NumberLength(std::string_view text, size_t at, bool* is_float) {
  size_t i = at;
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
  return i - at;
}

bool HasNonZeroMantissaDigit(std::string_view number) {
  for (char c : number) {
    if (c == 'e' || c == 'E') break;
    if (c >= '1' && c <= '9') return true;
  }
  return false;
}

}  // namespace

void CheckFloatLiterals(const StrictContext& ctx) {
  for (size_t index = 0; index < ctx.sources.size(); ++index) {
    const compiler::SourceFile* file = ctx.sources[index];
    const std::string& text = BlankedText(ctx, index);
    for (size_t i = 0; i < text.size();) {
      const bool starts =
          IsDigit(text[i]) || (text[i] == '.' && i + 1 < text.size() && IsDigit(text[i + 1]));
      if (!starts || (i > 0 && (IsIdentChar(text[i - 1]) || text[i - 1] == '.'))) {
        // Skip the rest of an identifier, so the digits of 'vec4' or 'a1e5' are no number.
        if (IsIdentChar(text[i])) {
          while (i < text.size() && IsIdentChar(text[i])) ++i;
        } else {
          ++i;
        }
        continue;
      }
      bool is_float = false;
      const size_t length = NumberLength(text, i, &is_float);
      const std::string number = text.substr(i, length);
      if (is_float) {
        const float value = std::strtof(number.c_str(), nullptr);
        if (std::isinf(value) || (value == 0.0f && HasNonZeroMantissaDigit(number))) {
          const compiler::Range range{static_cast<uint32_t>(i), static_cast<uint32_t>(i + length)};
          ctx.sink->Report(Info(Diag::NumberRange), file, range,
                           fmt::format("{} is beyond the range of a 32-bit float: it becomes {}",
                                       number, std::isinf(value) ? "infinity" : "zero"));
        }
      }
      i += std::max<size_t>(length, 1);
      while (i < text.size() && IsIdentChar(text[i])) ++i;  // a suffix glslang reports itself
    }
  }
}

}  // namespace arbiter::glsl
