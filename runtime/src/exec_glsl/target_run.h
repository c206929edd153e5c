// The target engines of arbiter verify: mesa-glsl330 (the glsl330 translation on an EGL
// desktop 3.3 core-profile context), mesa-es300 and mesa-es100 (the es300 / es100
// translations on EGL OpenGL ES 3.0 / 2.0 contexts). Each runs the translation with state as
// uniforms, every uniform fed from its binding-map spelling through the host library
// (glstate::UniformValue), on the same points, textures and float framebuffer as mesa-glsl.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "arbiter/arbvp/emit.h"
#include "arbiter/arbvp/exec.h"
#include "arbiter/compiler/source.h"
#include "arbiter/runtime/exec.h"

namespace arbiter::runtime {

class TargetEngine {
 public:
  virtual ~TargetEngine() = default;
  // "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL ES 3.2 Mesa 22.3.6 (egl)".
  virtual const std::string& description() const = 0;
  // Runs the target translation of `programs` (`emit`'s mutation kept, its target and state
  // source replaced) on every vector of `inputs`, results as ArbExecutor::RunTranslated gives
  // them. When the target refuses the programs, returns false with `error` empty and the
  // refusal (construct and target) in `not_applicable`; false with `error` otherwise.
  // `sources` (optional) give the refusal its line and column.
  virtual bool Run(const ArbPrograms& programs, const arbvp::EmitOptions& emit,
                   const arbvp::ExecInputs& inputs, std::vector<arbvp::VectorResult>* results,
                   std::string* not_applicable, std::string* error,
                   const compiler::SourceFile* vertex_source = nullptr,
                   const compiler::SourceFile* fragment_source = nullptr) = 0;
};

// The engine of `target` (Glsl330, Es300 or Es100) on a new EGL context of `driver` (a
// supported Mesa driver, validated by the caller); of Vk450 on lavapipe (vulkan/engine.h). Null
// (with `error`) when the context cannot be made or lacks what readback needs (float colour
// attachments; ES 2.0 also GL_EXT_draw_buffers).
[[nodiscard]] std::unique_ptr<TargetEngine> CreateTargetEngine(arbvp::EmitTarget target,
                                                               const std::string& driver,
                                                               std::string* error);

}  // namespace arbiter::runtime
