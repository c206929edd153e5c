// GLSL 1.10 3.1's character set, checked byte by byte (charset.h).
#include "charset.h"

#include <fmt/format.h>

#include <cstdint>
#include <string_view>

#include "diag.h"

namespace arbiter::glsl {
namespace {

// Letters, digits, the symbols of 3.1 and its white space. Not '\\', '"', '\'', '$', '@'
// or '`': they are ASCII, and glslang reports them at their token already.
bool IsSourceByte(uint8_t c) {
  if (c >= 0x20 && c < 0x7f) return true;
  return c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

// The length of the UTF-8 sequence at `at` and its code point, or 0 when the bytes there
// are not well-formed UTF-8 (overlong forms, surrogates and values past U+10FFFF included).
size_t Utf8Sequence(std::string_view text, size_t at, uint32_t* code_point) {
  const auto lead = static_cast<uint8_t>(text[at]);
  size_t length = lead >= 0xf0 ? 4 : lead >= 0xe0 ? 3 : lead >= 0xc0 ? 2 : 0;
  if (length == 0 || lead > 0xf4 || at + length > text.size()) return 0;
  uint32_t value = lead & (0x7f >> length);
  for (size_t i = 1; i < length; ++i) {
    const auto next = static_cast<uint8_t>(text[at + i]);
    if ((next & 0xc0) != 0x80) return 0;
    value = (value << 6) | (next & 0x3f);
  }
  constexpr uint32_t kSmallest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (value < kSmallest[length] || value > 0x10ffff || (value >= 0xd800 && value <= 0xdfff)) {
    return 0;
  }
  *code_point = value;
  return length;
}

// What the bytes at `at` are, for the message, and how many of them belong together.
std::string Describe(std::string_view text, size_t at, size_t* length) {
  const auto byte = static_cast<uint8_t>(text[at]);
  *length = 1;
  if (byte == 0) return "a NUL byte";
  if (byte < 0x80) return fmt::format("the control character U+{:04X}", byte);
  uint32_t code_point = 0;
  *length = Utf8Sequence(text, at, &code_point);
  if (*length == 0) {
    *length = 1;
    return fmt::format("the byte 0x{:02X} (not UTF-8)", byte);
  }
  if (code_point == 0xfeff) {
    return at == 0 ? "a byte-order mark" : "U+FEFF (a byte-order mark)";
  }
  return fmt::format("the non-ASCII character U+{:04X} '{}'", code_point, text.substr(at, *length));
}

}  // namespace

std::string ReportInvalidCharacters(const compiler::SourceFile& file,
                                    compiler::DiagnosticSink* sink) {
  const std::string_view text = file.text();
  std::string blanked;
  enum class State { kCode, kLineComment, kBlockComment } state = State::kCode;
  for (size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (IsSourceByte(static_cast<uint8_t>(c))) {
      if (state == State::kCode && c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
        state = State::kLineComment;
        i += 2;
        continue;
      }
      if (state == State::kCode && c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
        state = State::kBlockComment;
        i += 2;
        continue;
      }
      if (state == State::kLineComment && (c == '\n' || c == '\r')) state = State::kCode;
      if (state == State::kBlockComment && c == '*' && i + 1 < text.size() && text[i + 1] == '/') {
        state = State::kCode;
        ++i;
      }
      ++i;
      continue;
    }
    // One diagnostic per run of such bytes (binary garbage would give thousands).
    size_t length = 1;
    std::string what = Describe(text, i, &length);
    size_t end = i + length;
    while (end < text.size() && !IsSourceByte(static_cast<uint8_t>(text[end]))) {
      size_t next = 1;
      Describe(text, end, &next);
      end += next;
    }
    if (end > i + length) what = fmt::format("{} bytes outside ASCII, from {},", end - i, what);
    const compiler::Range range{static_cast<uint32_t>(i), static_cast<uint32_t>(end)};
    if (state == State::kCode) {
      sink->Report(Info(Diag::InvalidCharacter), &file, range,
                   fmt::format("{} {} not allowed: the GLSL source character set is a subset "
                               "of ASCII (GLSL 1.10 3.1){}",
                               what, end > i + length ? "are" : "is",
                               i == 0 && what.find("byte-order") != std::string::npos
                                   ? "; save the file without it"
                                   : ""));
    } else {
      sink->Report(Info(Diag::NonAsciiComment), &file, range,
                   fmt::format("{} in a comment: GLSL 1.10 3.1 allows only ASCII; drivers "
                               "skip comments, other tools may not",
                               what));
    }
    if (blanked.empty()) blanked = std::string(text);
    blanked.replace(i, end - i, end - i, ' ');
    i = end;
  }
  return blanked;
}

}  // namespace arbiter::glsl
