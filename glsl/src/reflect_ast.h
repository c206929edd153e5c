// Reflection from glslang's AST, shared by ReflectShader and LinkProgram: glslang objects that
// keep the ASTs of a compiled program, and each variable's share of the resource limits.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "arbiter/compiler/source.h"
#include "arbiter/glsl/check.h"
#include "arbiter/glsl/reflect.h"

class TIntermNode;

namespace glslang {
class TIntermTraverser;
struct TSourceLoc;
class TShader;
class TProgram;
}  // namespace glslang

namespace arbiter::glsl {

struct StaticUses;  // reflect.cpp

// The range of `length` bytes at a glslang location (string index, 1-based line and column)
// in `sources`; false when it lies in none of them.
bool RangeOfLoc(const std::vector<const compiler::SourceFile*>& sources,
                const glslang::TSourceLoc& loc, size_t length, const compiler::SourceFile** file,
                compiler::Range* range);

// One program of one or two stages compiled and linked by glslang, as CheckShader compiles
// it, keeping the ASTs. Reports nothing: diagnostics come from CheckShader, which must have
// run first (it initialises glslang once per process).
class CompiledProgram {
 public:
  // Either list may be empty (a one-stage program). The sources must outlive the object.
  CompiledProgram(const std::vector<const compiler::SourceFile*>& vertex,
                  const std::vector<const compiler::SourceFile*>& fragment,
                  const CheckOptions* options = nullptr);
  ~CompiledProgram();
  CompiledProgram(const CompiledProgram&) = delete;
  CompiledProgram& operator=(const CompiledProgram&) = delete;

  // The stage was given and compiled without errors.
  bool parsed(Stage stage) const;
  // The stage parsed and defines main().
  bool HasMain(Stage stage) const;
  // Every given stage compiled and glslang linked them (cross-stage checks included).
  bool linked() const { return linked_; }
  // glslang's link messages ("" when none).
  const char* link_log() const;

  // Reflects a stage that parsed into `out` (all but `ok`). Returns false when the stage's AST
  // has no main(): there is then nothing to reflect.
  bool Reflect(Stage stage, Reflection* out) const;
  // Runs `traverser` over the AST of a stage that parsed (false otherwise); the sources its
  // locations index.
  bool Traverse(Stage stage, glslang::TIntermTraverser* traverser) const;
  const std::vector<const compiler::SourceFile*>& StageSources(Stage stage) const;

 private:
  std::vector<const compiler::SourceFile*> sources_[2];
  CheckOptions options_;  // the target's extensions, the preprocessor options
  std::unique_ptr<glslang::TShader> shaders_[2];
  // Each stage's static uses, collected before glslang's link removes uncalled functions.
  std::unique_ptr<StaticUses> uses_[2];
  std::unique_ptr<glslang::TProgram> program_;
  bool parsed_[2] = {false, false};
  bool linked_ = false;
};

// Whether the AST defines main() (a shader object need not).
bool DefinesMain(TIntermNode* root);

// The resources of ResourceUse.
enum class Resource { UniformComponents, VaryingFloats, VertexAttribs, Samplers };

// One variable's share of a resource.
struct Contribution {
  // What is counted: the variable, or for varyings the interpolant, so that the two stages'
  // shares can be merged (a fragment shader's gl_Color is the vertex shader's gl_FrontColor).
  std::string key;
  std::string what;  // for messages: "uniform 'mvp'", "built-in 'gl_LightSource[0].diffuse'"
  int amount = 0;
  const compiler::SourceFile* file = nullptr;
  compiler::Range range;
};

// What each used variable of a reflected stage takes of `resource`, in declaration order, then
// the built-ins by name. ResourceUse is their sum; the link checks walk them to point at the
// variable that goes past a limit.
std::vector<Contribution> Contributions(const Reflection& reflection, Resource resource);

}  // namespace arbiter::glsl
