// Bytes outside GLSL 1.10's source character set (3.1: a subset of ASCII), found before
// glslang sees the text: glslang reports them without a column ("unexpected token" at the
// start of the line, several times) and stops.
#pragma once

#include <string>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/source.h"

namespace arbiter::glsl {

// Reports every run of bytes that is not a GLSL character: outside comments an error
// (glsl-invalid-character) at its exact line and column, naming it (a byte-order mark, NUL,
// a control character, a non-ASCII character, a byte that is not UTF-8); inside a comment a
// warning (glsl-non-ascii-comment: drivers skip comments, but 3.1 applies to them too).
// Returns the text with each reported byte blanked, so glslang goes on to the real errors,
// or an empty string when every byte is a GLSL character (the common case: no copy).
std::string ReportInvalidCharacters(const compiler::SourceFile& file,
                                    compiler::DiagnosticSink* sink);

}  // namespace arbiter::glsl
