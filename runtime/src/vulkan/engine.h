// The vulkan-spirv target engine of arbiter verify: the vk450 translation, adapted for
// readback (target_adapt.h), compiled to SPIR-V with glslang and run on Mesa's lavapipe
// through the Vulkan loader: one point per input vector at its pixel, RGBA32F colour
// attachments copied back to host memory, the std140 uniform blocks filled at the binding
// map's offsets from glstate::UniformValue, the model's textures as combined image samplers.
#pragma once

#include <memory>
#include <string>

#include "exec_glsl/target_run.h"

namespace arbiter::runtime::vulkan {

// The engine on a new Vulkan device of lavapipe (the physical device named "llvmpipe ...").
// Null (with `error`) when the loader offers none or it lacks what readback needs.
[[nodiscard]] std::unique_ptr<TargetEngine> CreateVulkanEngine(std::string* error);

}  // namespace arbiter::runtime::vulkan
