// UTF-8 character stepping shared by column counting and the text renderer (private).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace arbiter::compiler {

// Length in bytes of the character that starts at `pos` in `text` (pos < text.size()):
// 1 for ASCII, 2 to 4 for a well-formed UTF-8 sequence, and 1 for a byte that does not
// start one (a stray continuation byte, an invalid lead byte or a truncated sequence), so
// that every invalid byte counts as one character.
inline size_t Utf8CharLength(std::string_view text, size_t pos) {
  const auto lead = static_cast<uint8_t>(text[pos]);
  size_t length = 1;
  if (lead < 0x80) {
    return 1;
  } else if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
  } else {
    return 1;  // 0x80-0xC1 or 0xF5-0xFF: never the start of a character
  }
  if (pos + length > text.size()) {
    return 1;
  }
  for (size_t i = 1; i < length; ++i) {
    const auto byte = static_cast<uint8_t>(text[pos + i]);
    if ((byte & 0xC0) != 0x80) {
      return 1;
    }
  }
  return length;
}

// True when the character at `pos` is a well-formed multi-byte UTF-8 sequence or ASCII.
inline bool Utf8IsValidAt(std::string_view text, size_t pos) {
  return static_cast<uint8_t>(text[pos]) < 0x80 || Utf8CharLength(text, pos) > 1;
}

}  // namespace arbiter::compiler
