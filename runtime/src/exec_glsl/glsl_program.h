// GL program objects of the mesa-glsl engine: compiling and linking one pass, and feeding
// the uniforms the translation's binding map names.
#pragma once

#include <string>

#include "arbiter/arbvp/emit.h"
#include "arbiter/arbvp/exec.h"
#include "arbiter/runtime/exec.h"
#include "exec/exec_gl.h"
#include "exec/program_rewrite.h"
#include "exec_glsl/glsl_adapt.h"

namespace arbiter::runtime::exec {

// Compiles and links one pass, binding every attribute location first (the map's
// attributes, the pixel attribute at plan.position_attrib, or the generated inputs of a
// fragment shader alone). 0 (with `error`) when Mesa rejects it.
GLuint LinkGlslPass(const ExecGl& gl, const GlslPass& pass, const arbvp::BindingMap& map,
                    const RunPlan& plan, std::string* error);

// Sets every uniform of `map` that the linked, current `program` keeps: program.env/local
// arrays, samplers (their units) and state uniforms (their values computed from the model
// with arbvp::ReadStateBinding). False (with `error`) when a state uniform names a binding
// the programs do not have.
[[nodiscard]] bool SetGlslUniforms(const ExecGl& gl, GLuint program, const arbvp::BindingMap& map,
                                   const ArbPrograms& programs, const arbvp::ExecInputs& inputs,
                                   std::string* error);

// The target engines' SetGlslUniforms: every value from its ARB spelling in `map` through
// the host library (glstate::UniformValue), program.env/local arrays element by element, so
// that verification tests the library a port uses. `framebuffer_height` is the drawable's
// (glstate's framebuffer_height, for the translations that flip gl_FragCoord.y).
[[nodiscard]] bool SetTargetUniforms(const ExecGl& gl, GLuint program, const arbvp::BindingMap& map,
                                     const arbvp::ExecInputs& inputs, int framebuffer_height,
                                     std::string* error);

}  // namespace arbiter::runtime::exec
