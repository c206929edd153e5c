// Reflection of a GLSL 1.10 or 1.20 shader from glslang's AST: its attributes, uniforms,
// samplers and varyings, the built-in state it reads and writes, and the resources they take.
#pragma once

#include <string>
#include <vector>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/source.h"
#include "arbiter/glsl/check.h"

namespace arbiter::glsl {

// One global variable of the shader's interface (attribute, uniform, sampler or varying).
// Reads and writes are static: the shader's text holds them, whether or not they execute
// (GLSL 1.10 7.2), in uncalled functions too. The resources count them all, at the
// conservative end of "active" (GL 2.0 2.15.3).
struct ReflectedVariable {
  std::string name;
  // The type as GLSL spells it: "float", "vec4", "mat3", "sampler2DShadow"; a structure is
  // spelled with its members: "struct Light { vec4 color; float k; }".
  std::string type;
  int array_size = 0;    // elements of an array (its implicit size if undeclared); 0: no array
  int components = 0;    // float/int/bool values it holds, every element (a mat3 holds 9)
  bool read = false;     // statically read
  bool written = false;  // statically written (varyings of a vertex shader)
  // Texture lookup functions called on it, sorted ("texture2D", "shadow2DProj"): samplers.
  std::vector<std::string> lookups;
  // Its declaration: the declared name (file null when it cannot be found).
  const compiler::SourceFile* file = nullptr;
  compiler::Range range;
};

// What a built-in variable is to the pipeline.
enum class BuiltinKind {
  State,      // uniform state: gl_ModelViewMatrix, gl_LightSource, gl_Fog, ...
  Attribute,  // conventional vertex attributes: gl_Vertex, gl_Normal, gl_MultiTexCoord0, ...
  Varying,    // gl_FrontColor, gl_TexCoord, gl_FogFragCoord (vertex); gl_Color, ... (fragment)
  Special,    // gl_Position, gl_PointSize, gl_ClipVertex, gl_FragCoord, gl_FragColor, ...
};

// One built-in variable the shader accesses, by the path it is accessed through: constant
// array indices and structure fields are kept ("gl_LightSource[0].diffuse",
// "gl_TexCoord[1]"); an array indexed by a variable is named alone ("gl_LightSource").
struct BuiltinUse {
  std::string name;
  BuiltinKind kind = BuiltinKind::Special;
  int components = 0;  // values the accessed part holds
  // The first access in the text.
  const compiler::SourceFile* file = nullptr;
  compiler::Range range;
};

// What the shader takes of the implementation's resources (GL 2.0 sections 2.15.3, 2.15.4
// and 3.11.1; GLSL 1.10 sections 4.3.4-4.3.6): counted over statically used variables.
struct ResourceUse {
  // Active uniform values: user uniforms and built-in uniform state (GLSL 1.10 4.3.5 adds
  // them together); samplers count as texture image units instead.
  int uniform_components = 0;
  // Interpolated values: varyings written (vertex) or read (fragment), built-in ones included,
  // gl_Position excluded.
  int varying_floats = 0;
  // Vertex attribute slots: generic attributes (a matN takes N, a float one) and conventional
  // ones (gl_Vertex, gl_Normal, ...). 0 for fragment shaders.
  int vertex_attribs = 0;
  // Active sampler variables (each element of a sampler array).
  int samplers = 0;
};

struct Reflection {
  bool ok = false;  // compiled and linked without errors; otherwise the lists are empty
  Stage stage = Stage::Vertex;
  // Declared interface variables, in declaration order.
  std::vector<ReflectedVariable> attributes;  // user attributes (vertex shaders)
  std::vector<ReflectedVariable> uniforms;    // user uniforms other than samplers
  std::vector<ReflectedVariable> samplers;    // sampler uniforms, with their lookups
  std::vector<ReflectedVariable> varyings;    // user varyings
  // Built-in variables read and written, sorted by name.
  std::vector<BuiltinUse> builtins_read;
  std::vector<BuiltinUse> builtins_written;
  ResourceUse resources;
};

// Compiles and links the sources as one shader of `stage` (as CheckShader, whose diagnostics
// are reported into `sink`) and reflects it. The result's `ok` is false when the shader has
// errors; its lists are then empty. Thread-safe.
Reflection ReflectShader(Stage stage, const std::vector<const compiler::SourceFile*>& sources,
                         compiler::DiagnosticSink* sink, const CheckOptions& options = {});

// "vertex" or "fragment".
std::string_view StageName(Stage stage);

}  // namespace arbiter::glsl
