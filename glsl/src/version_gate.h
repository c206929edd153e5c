// The #version directive, read before glslang sees the shader. arbiter checks GLSL 1.10, and
// 1.10 (3.3) makes any other number an error: "Any number less than 110 will cause an error
// to be generated. Any number greater than the latest version of the language a compiler
// supports will also cause an error to be generated."
#pragma once

#include <string>
#include <string_view>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/source.h"

namespace arbiter::glsl {

// Reports glsl-version at N for the first `#version N` directive of `text` (a shader's first
// string) when N is not 110. When an edit is needed, sets `edited` to the text glslang must
// parse instead (same length) and returns true: a directive before anything else is blanked,
// so glslang checks the rest as 1.10 (its default version); a later one gets 110 as its
// number, so glslang reports only that it comes too late. glslang would otherwise take 100
// as OpenGL ES, a later number as that version (building its built-in tables for it: 0.15 s
// for 4.60; the 1.10 rules then misfire on its gl_PerVertex block), and report an unsupported
// number at 1:1.
bool GateVersion(const compiler::SourceFile& file, std::string_view text, std::string* edited,
                 compiler::DiagnosticSink* sink);

}  // namespace arbiter::glsl
