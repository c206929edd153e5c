#include "version_gate.h"

#include <fmt/format.h>

#include <cctype>

#include "diag.h"
#include "strict/strict.h"

namespace arbiter::glsl {
namespace {

bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }

// The message for a number other than 110 (its digits as written).
std::string VersionMessage(std::string_view digits) {
  if (digits.front() == '0') {
    return fmt::format(
        "#version {} is not 110 (a leading 0 makes an octal number); GLSL 1.10 requires an "
        "error for any other number",
        digits);
  }
  if (digits.size() < 3 || (digits.size() == 3 && digits < "110")) {
    return fmt::format(
        "#version {} is below 110; GLSL 1.10 requires an error for any number less than 110 "
        "(100 is OpenGL ES)",
        digits);
  }
  return fmt::format(
      "#version {} is not supported: arbiter checks GLSL 1.10, which requires an error for a "
      "number above the latest version a compiler supports; the shader is checked as 1.10",
      digits);
}

}  // namespace

bool GateVersion(const compiler::SourceFile& file, std::string_view text, std::string* edited,
                 compiler::DiagnosticSink* sink) {
  if (text.find("version") == std::string_view::npos) return false;
  const std::string blanked = BlankComments(text);
  bool first = true;  // nothing but white space and comments so far
  for (size_t line = 0; line < blanked.size();) {
    size_t pos = line;
    while (pos < blanked.size() && IsBlank(blanked[pos])) ++pos;
    size_t end = blanked.find_first_of("\r\n", pos);
    if (end == std::string::npos) end = blanked.size();
    const size_t hash = pos;
    if (pos < end && blanked[pos] == '#') {
      ++pos;
      while (pos < end && IsBlank(blanked[pos])) ++pos;
      if (blanked.compare(pos, 7, "version") == 0 && pos + 7 < end && IsBlank(blanked[pos + 7])) {
        pos += 7;
        while (pos < end && IsBlank(blanked[pos])) ++pos;
        const size_t number = pos;
        while (pos < end && std::isdigit(static_cast<unsigned char>(blanked[pos]))) ++pos;
        const std::string_view digits = std::string_view(blanked).substr(number, pos - number);
        // A missing or malformed number, or a macro, is glslang's to report (at its position).
        if (digits.empty() || (pos < end && !IsBlank(blanked[pos])) || digits == "110") {
          return false;
        }
        sink->Report(Info(Diag::Version), &file,
                     {static_cast<uint32_t>(number), static_cast<uint32_t>(pos)},
                     VersionMessage(digits));
        if (first) {
          // Blank the whole directive, a profile word included: glslang checks as 1.10.
          *edited = std::string(text);
          edited->replace(hash, end - hash, end - hash, ' ');
          return true;
        }
        // Too late anyway: glslang says so ("must occur first") for a "#version 110", where
        // it would take another number as the shader's version (and report that at 1:1).
        if (digits.size() != 3) return false;
        *edited = std::string(text);
        edited->replace(number, 3, "110");
        return true;
      }
    }
    if (pos < end) first = false;
    line = end + 1;
  }
  return false;
}

}  // namespace arbiter::glsl
