// RunGlslVulkan: GLSL 1.10/1.20 shaders lowered to Vulkan GLSL 4.50 and run on lavapipe.
#include "arbiter/runtime/glsl_vulkan.h"

namespace arbiter::runtime {

bool RunGlslVulkan(const GlslShaders& /*shaders*/, const GlslExecInputs& /*inputs*/,
                   GlslRunResult* /*result*/, std::string* /*not_applicable*/, std::string* error) {
  *error = "the Vulkan GLSL engine is not built yet";
  return false;
}

WorkerStatus RunGlslVulkanInWorker(const WorkerLimits& /*limits*/, const GlslShaders& shaders,
                                   const GlslExecInputs& inputs, GlslRunResult* result,
                                   std::string* not_applicable, std::string* error) {
  if (!RunGlslVulkan(shaders, inputs, result, not_applicable, error)) {
    return WorkerStatus::JobFailed;
  }
  return WorkerStatus::Ok;
}

}  // namespace arbiter::runtime
