// Running GLSL 1.10 and 1.20 shaders on a second, independent engine: the shaders lowered to
// Vulkan GLSL 4.50 (glsl/lower_vulkan.h), compiled to SPIR-V with glslang and run on Mesa's
// lavapipe through the Vulkan loader. The result is comparable one to one with RunGlsl's
// (glsl_exec.h): the same outputs (names, stages, types, order) and the same `discarded`.
// Outputs are read back exactly by storage-buffer stores from the generated main.
// docs/exec.md, "GLSL shaders".
#pragma once

#include <string>

#include "arbiter/runtime/glsl_exec.h"
#include "arbiter/runtime/worker.h"

namespace arbiter::runtime {

// Same contract as RunGlsl (glsl_exec.h); the description is like "llvmpipe (...), Vulkan 1.3
// (lavapipe)". False with `not_applicable` set (and `error` empty) when the lowering refuses
// the shaders ("not applicable: <construct>"); false with `error` when glslang rejects the
// lowered text or Vulkan fails.
[[nodiscard]] bool RunGlslVulkan(const GlslShaders& shaders, const GlslExecInputs& inputs,
                                 GlslRunResult* result, std::string* not_applicable,
                                 std::string* error);

// RunGlslVulkan in a worker process (worker.h): a driver crash or hang becomes an error. A
// refusal of the lowering is JobFailed with `not_applicable` set and `error` empty.
WorkerStatus RunGlslVulkanInWorker(const WorkerLimits& limits, const GlslShaders& shaders,
                                   const GlslExecInputs& inputs, GlslRunResult* result,
                                   std::string* not_applicable, std::string* error);

}  // namespace arbiter::runtime
