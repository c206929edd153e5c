// Linking GLSL 1.10 and 1.20 shaders as one program (glLinkProgram): each stage's own
// diagnostics, then the rules between the stages and the program's resource limits.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/limits.h"
#include "arbiter/compiler/source.h"
#include "arbiter/glsl/check.h"
#include "arbiter/glsl/reflect.h"

namespace arbiter::glsl {

struct LinkOptions {
  // The limits to enforce. nullptr: Mesa's values (going past the GL 2.0 minimum is no
  // warning; the profile "spec-min" makes it an error). A profile makes going past its values
  // an error; a GLSL key it lacks (compiler/src/limits.def has none yet) takes GlslLimits()'
  // Mesa value for the profile "mesa" and the spec minimum for any other.
  const compiler::LimitProfile* profile = nullptr;
  // How each shader is compiled (extensions, preprocessor options); `link` is implied.
  CheckOptions check;
};

struct LinkResult {
  bool ok = false;  // no errors
  // Each stage's reflection; its `ok` is true when the stage compiled and was reflected
  // (possibly with errors of arbiter's own rules).
  Reflection vertex;
  Reflection fragment;
};

// Compiles `vertex` and `fragment` (each one shader of one or more strings, as CheckShader;
// the vertex shader judged as a program, so that not writing gl_Position is an error), then
// checks them as one program: varyings the fragment shader reads are declared and written by
// the vertex shader with the same type, uniforms and samplers declared in both stages agree,
// and the program fits the limits of `options`. glslang's own link errors are reported when
// arbiter's rules found none. One list may be empty: a one-stage program gets its stage's
// limits. Thread-safe.
LinkResult LinkProgram(const std::vector<const compiler::SourceFile*>& vertex,
                       const std::vector<const compiler::SourceFile*>& fragment,
                       const LinkOptions& options, compiler::DiagnosticSink* sink);

// One shader object of a program: the strings of one glShaderSource, in order.
struct ShaderObject {
  Stage stage;
  std::vector<const compiler::SourceFile*> strings;
};

// Checks shader objects of one or both stages as one program, as glLinkProgram judges it: each
// object compiled (CheckShader), then linked. A stage may have several objects: main() and
// every called function must be defined in one of them (glslang merges the stage's objects).
// With at most one object of each stage the program gets LinkProgram's rules; with more
// objects of a stage, glslang's link of the merged stage decides. `objects` must be
// non-empty. Thread-safe.
bool LinkShaders(const std::vector<ShaderObject>& objects, const LinkOptions& options,
                 compiler::DiagnosticSink* sink);

// One implementation limit of GLSL programs, keyed like compiler/src/limits.def.
struct GlslLimit {
  std::string_view key;      // "glsl.max_varying_floats"
  std::string_view gl_name;  // "MAX_VARYING_FLOATS"
  int64_t spec_min;          // the GL 2.0 state tables' minimum
  int64_t mesa;              // Mesa 22.3.6 through OSMesa (softpipe; llvmpipe where smaller)
  std::string_view description;
};

// The limits LinkProgram checks, in the order it checks them.
const std::vector<GlslLimit>& GlslLimits();

}  // namespace arbiter::glsl
