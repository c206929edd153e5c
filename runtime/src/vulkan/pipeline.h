// The graphics pipelines of the vulkan-spirv engine: a render pass per number of RGBA32F
// colour attachments, and per readback pass (exec::GlslPass) its two shaders compiled to
// SPIR-V with glslang, the descriptor set 0 the binding map describes (the uniform blocks
// and combined image samplers at their bindings), and a point-list pipeline whose vertex
// buffer holds kVertexLocations vec4 attributes per point. Pipelines are cached by shader
// text, as the GL engines cache linked programs.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <list>
#include <string>
#include <vector>

#include "arbiter/arbvp/emit.h"
#include "exec_glsl/glsl_adapt.h"
#include "vulkan/device.h"

namespace arbiter::runtime::vulkan {

// Attribute locations in each vertex of the vertex buffer: the sixteen of the binding map
// (or of the generated pass-through shader), and kPixelLocation for the point's position.
inline constexpr int kPixelLocation = 16;
inline constexpr int kVertexLocations = 17;
inline constexpr int kMaxAttachments = 8;

struct Pipeline {
  std::string key;  // both shaders' text and the attachment count
  VkShaderModule vertex = VK_NULL_HANDLE;
  VkShaderModule fragment = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
};

// A point-list graphics pipeline of `stages` reading `vertex_input`, writing every channel of
// `attachments` colour attachments, with a dynamic viewport and scissor; nothing is rasterised
// when `rasterizer_discard`. False (with `error`) when Vulkan refuses it.
[[nodiscard]] bool CreatePointPipeline(VkDevice device,
                                       const std::vector<VkPipelineShaderStageCreateInfo>& stages,
                                       const VkPipelineVertexInputStateCreateInfo& vertex_input,
                                       int attachments, bool rasterizer_discard,
                                       VkPipelineLayout layout, VkRenderPass render_pass,
                                       VkPipeline* pipeline, std::string* error);

class Pipelines {
 public:
  explicit Pipelines(const Device& device) : device_(device) {}
  Pipelines(const Pipelines&) = delete;
  Pipelines& operator=(const Pipelines&) = delete;
  ~Pipelines();

  // The render pass of `count` (1..kMaxAttachments) cleared colour attachments, left in
  // TRANSFER_SRC_OPTIMAL for the readback copy; VK_NULL_HANDLE (with `error`) on failure.
  VkRenderPass RenderPass(int count, std::string* error);
  // The pipeline of `pass` under `map` (cached; the least recently used of 8 goes); null
  // (with `error`: glslang's messages for a shader that does not compile) on failure.
  const Pipeline* Get(const exec::GlslPass& pass, const arbvp::BindingMap& map, std::string* error);

 private:
  bool Build(const exec::GlslPass& pass, const arbvp::BindingMap& map, Pipeline* p,
             std::string* error);
  void Destroy(Pipeline* p) const;

  const Device& device_;
  std::array<VkRenderPass, kMaxAttachments + 1> render_passes_{};
  std::list<Pipeline> cache_;  // most recently used first
};

}  // namespace arbiter::runtime::vulkan
