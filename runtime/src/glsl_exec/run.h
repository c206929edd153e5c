// The GLSL exec's GL side: the entry points it needs beyond the ARB executor's, building
// programs, setting uniforms, and the vertex (transform feedback) and fragment runs.
#pragma once

#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/runtime/glsl_exec.h"
#include "exec/exec_gl.h"
#include "glsl_exec/types.h"

namespace arbiter::runtime::glsl_exec {

// X(type, member, "glName"): the entry points the ARB executor's table (exec_gl.h) lacks.
#define ARBITER_GLSL_EXEC_GL_FUNCTIONS(X)                                                         \
  X(PFNGLGETACTIVEUNIFORMPROC, GetActiveUniform, "glGetActiveUniform")                            \
  X(PFNGLTRANSFORMFEEDBACKVARYINGSPROC, TransformFeedbackVaryings, "glTransformFeedbackVaryings") \
  X(PFNGLGETTRANSFORMFEEDBACKVARYINGPROC, GetTransformFeedbackVarying,                            \
    "glGetTransformFeedbackVarying")                                                              \
  X(PFNGLBEGINTRANSFORMFEEDBACKPROC, BeginTransformFeedback, "glBeginTransformFeedback")          \
  X(PFNGLENDTRANSFORMFEEDBACKPROC, EndTransformFeedback, "glEndTransformFeedback")                \
  X(PFNGLBINDBUFFERBASEPROC, BindBufferBase, "glBindBufferBase")                                  \
  X(PFNGLGETBUFFERSUBDATAPROC, GetBufferSubData, "glGetBufferSubData")                            \
  X(PFNGLVERTEXATTRIB4FVPROC, VertexAttrib4fv, "glVertexAttrib4fv")                               \
  X(decltype(&glStencilFunc), StencilFunc, "glStencilFunc")                                       \
  X(decltype(&glStencilOp), StencilOp, "glStencilOp")                                             \
  X(decltype(&glDepthMask), DepthMask, "glDepthMask")                                             \
  X(decltype(&glClearStencil), ClearStencil, "glClearStencil")                                    \
  X(decltype(&glScissor), Scissor, "glScissor")

struct Gl : exec::ExecGl {
#define ARBITER_GLSL_EXEC_GL_MEMBER(type, member, name) type member = nullptr;
  ARBITER_GLSL_EXEC_GL_FUNCTIONS(ARBITER_GLSL_EXEC_GL_MEMBER)
#undef ARBITER_GLSL_EXEC_GL_MEMBER
};

// Loads the extra entry points; false (with `error`) when one is missing.
[[nodiscard]] bool LoadExtraGl(const exec::GetProcFn& get_proc, Gl* gl, std::string* error);

// Vertex shader objects and fragment shader objects linked into one program, with the
// attributes of `attributes` bound to locations 1, 2, .. (in order, a matN taking N) and the
// transform feedback varyings `capture` (interleaved). 0 (with `error`) when Mesa rejects it.
struct ProgramSpec {
  std::vector<std::string> vertex;    // shader objects' texts
  std::vector<std::string> fragment;  // idem
  std::vector<GlslInputSlot> attributes;
  std::vector<std::string> capture;
};
GLuint BuildProgram(const Gl& gl, const ProgramSpec& spec, std::string* error);

// The user uniforms (not gl_*) the program keeps active.
struct ActiveUniform {
  std::string name;  // as GL names it: "w[0]" for an array
  GLenum type = 0;
  GLint size = 1;  // array elements
};
std::vector<ActiveUniform> ActiveUniforms(const Gl& gl, GLuint program);

// What either engine (Mesa's, glsl_vulkan's) knows of an active user uniform at the end of a
// run.
struct UniformSeen {
  std::string name;  // "w[0]" for an array
  int size = 1;      // array elements
  bool sampler = false;
};
// The end of a run of either engine: a note for each active uniform nobody set and for each
// --uniform the program does not keep (`compiler` removed it: "Mesa", "glslang"); or, for a
// --uniform that names nothing the shaders declare, the usage error (vectors and notes
// cleared).
void FinishUniformNotes(const GlslExecInputs& inputs, const std::vector<UniformSeen>& active,
                        const std::set<std::string>& used, const std::set<size_t>& applied,
                        std::string_view compiler, GlslRunResult* result);

// Where --uniform `name` lands in the active uniform `active` (GL's name: "w[0]" for an array
// of `size` elements): the first element, and whether it may set several (the whole array).
[[nodiscard]] bool MatchUniform(const std::string& active, int size, const std::string& name,
                                int* first, bool* whole);
// Whether `values` fit `type` (an array of `size` when `whole`): `elements` of them; false with
// the usage error for a wrong count or a fractional integer.
[[nodiscard]] bool CheckUniformValues(const std::string& name, const TypeInfo& type, int size,
                                      bool whole, const std::vector<float>& values,
                                      size_t* elements, std::string* usage);

// Sets the --uniform values that the current `program` keeps; `used` gets the names of the
// active uniforms set. A wrong number of values or a fractional integer is a usage error
// (set in `usage`, false).
[[nodiscard]] bool SetUniforms(const Gl& gl, GLuint program, const GlslExecInputs& inputs,
                               std::set<std::string>* used, std::set<size_t>* applied,
                               std::string* usage);

// The attribute slot's location in a program built from `attributes` (BuildProgram's order).
int AttributeLocation(const std::vector<GlslInputSlot>& attributes, const std::string& name);

// Sends the attributes of vector `v` (built-ins through their fixed-function calls, user
// attributes at their locations) and emits the vertex with gl_Vertex.
void EmitVertex(const Gl& gl, const std::vector<GlslInputSlot>& attributes,
                const std::map<std::string, std::vector<float>>& v);

// An output the vertex shader writes, as transform feedback names it.
struct VertexOutput {
  std::string name;  // "gl_TexCoord[1]", "v[2]", "m"
  std::string type;  // "vec4", "mat3"
  int components = 4;
};
std::vector<VertexOutput> VertexOutputs(const glsl::Reflection& vertex);

// The fragment shader's outputs: colour attachments by index, and whether it writes depth.
struct FragmentOutputs {
  std::vector<int> data;  // gl_FragData indices written
  bool color = false;     // gl_FragColor
  bool depth = false;     // gl_FragDepth
};
FragmentOutputs OutputsOf(const glsl::Reflection& fragment);

// Sets a uniform of GLSL type `type` (a float type, an int, bool or sampler) at `location`
// to `count` elements of `values`.
void UploadUniform(const Gl& gl, GLint location, std::string_view type, GLsizei count,
                   const std::vector<float>& values);

// The runs. Each needs the context current with the GL state and textures set; results get
// their outputs appended (vertex outputs first). False with `error` on a GL failure, with
// `usage` on a bad --uniform.
struct RunContext {
  const Gl& gl;
  const GlslShaders& shaders;
  const GlslExecInputs& inputs;
  std::set<std::string>* used_uniforms;  // active uniforms given a value
  std::set<size_t>* applied;             // --uniform assignments that landed
  std::vector<ActiveUniform>* active;    // every active user uniform seen
  std::string* usage;
};
[[nodiscard]] bool RunVertex(const RunContext& run, std::vector<GlslVectorResult>* results,
                             std::string* error);
[[nodiscard]] bool RunFragment(const RunContext& run, std::vector<GlslVectorResult>* results,
                               std::string* error);

// Links a program, sets the user uniforms on it (current afterwards) and records its active
// uniforms; 0 with `error` (Mesa) or `usage` set.
GLuint PrepareProgram(const RunContext& run, const ProgramSpec& spec, std::string* error);

}  // namespace arbiter::runtime::glsl_exec
