// The vulkan-spirv engine: see engine.h. Each Run translates, plans the readback passes as
// the GL target engines do (exec::PlanTargetPasses), uploads the points, uniform blocks and
// textures once, and records one render pass and the attachments' copies per pass.
#include "vulkan/engine.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <vector>

#include "arbiter/glstate/uniforms.h"
#include "arbiter/runtime/translate.h"
#include "exec/draw.h"
#include "exec_glsl/glsl_run.h"
#include "exec_glsl/target_adapt.h"
#include "vulkan/device.h"
#include "vulkan/pipeline.h"
#include "vulkan/resources.h"

namespace arbiter::runtime::vulkan {
namespace {

constexpr size_t kVertexFloats = static_cast<size_t>(kVertexLocations) * 4;

// The clip position of vector `index` for Vulkan, whose clip volume has 0 <= z <= w where
// GL's has -w <= z <= w: the same window depth under the viewport's depth range.
arbvp::Vec4 VulkanClipPosition(size_t index, int width, int height, float depth,
                               const arbvp::GlState& state) {
  arbvp::Vec4 clip = exec::PixelClipPosition(index, width, height, depth, state);
  clip[2] = (clip[2] + 1.0f) * 0.5f;
  return clip;
}

// The bytes of uniform block `block` (std140, at the binding map's offsets): parameters and
// state (`state`: the inputs' and the framebuffer's height) from glstate::UniformValue, as
// SetTargetUniforms feeds the GL engines.
bool FillBlock(const arbvp::BindingMap& map, const arbvp::UniformBlock& block,
               const arbvp::ExecInputs& inputs, const arbvp::GlState& state,
               std::vector<float>* data, std::string* error) {
  data->assign(static_cast<size_t>(std::max(block.size, 16)) / sizeof(float), 0.0f);
  auto put = [&](int offset, const float* values, size_t floats, const std::string& name) {
    if (offset < 0 || offset % 4 != 0 || static_cast<size_t>(offset) / 4 + floats > data->size()) {
      *error = fmt::format("{} at byte {} lies outside the {} bytes of {}", name, offset,
                           block.size, block.name);
      return false;
    }
    std::copy_n(values, floats, data->begin() + offset / 4);
    return true;
  };
  for (const arbvp::ParameterArray& p : map.parameters) {
    if (p.target != block.stage || p.offset < 0) continue;
    const arbvp::ProgramParameters& params =
        p.target == arbvp::ProgramKind::Vertex ? inputs.vertex_params : inputs.fragment_params;
    for (int i = 0; i < p.size; ++i) {
      const std::string spelling = fmt::format("program.{}[{}]", p.local ? "local" : "env", i);
      glstate::UniformData value;
      if (!glstate::UniformValue(state, params, spelling, &value)) {
        *error = fmt::format("glstate::UniformValue cannot evaluate '{}' ({})", spelling, p.name);
        return false;
      }
      if (!put(p.offset + 16 * i, value.data.data(), 4, p.name)) return false;
    }
  }
  for (const arbvp::StateUniform& u : map.state) {
    if (u.block != block.name) continue;
    glstate::UniformData value;
    if (!glstate::UniformValue(state, inputs.vertex_params, u.binding, &value)) {
      glstate::StateRef beyond;
      if (!glstate::ParseStateSpelling(u.binding, &beyond)) {
        *error = fmt::format("glstate::UniformValue cannot evaluate '{}' ({})", u.binding, u.name);
        return false;
      }
      value = glstate::UniformData{};  // past the model's arrays: GL's initial (0, 0, 0, 0)
    }
    const bool matrix = value.type == glstate::UniformType::Matrix;
    if (matrix != (u.type == "mat4")) {
      *error = fmt::format("glstate gives a {} for '{}', the uniform {} is a {}",
                           matrix ? "mat4" : "vec4", u.binding, u.name, u.type);
      return false;
    }
    // std140 stores a mat4 as four column vec4s: glstate's column-major data as it is.
    if (!put(u.offset, value.data.data(), matrix ? 16 : 4, u.name)) return false;
  }
  return true;
}

// The texture sampler `s` reads: the model's on its unit, or, when the unit holds none or
// one of another dimension (an incomplete texture in GL, which reads (0, 0, 0, 1)), a 1x1
// texture of the sampler's dimension holding (0, 0, 0, 1).
arbvp::Texture TextureFor(const arbvp::SamplerBinding& s, const arbvp::ExecInputs& inputs) {
  const arbvp::TexDim dim = arbvp::TargetDim(s.target);
  auto it = inputs.textures.find(s.unit);
  if (it != inputs.textures.end() && it->second.dim == dim) return it->second;
  arbvp::Texture t;
  t.dim = dim;
  t.depth = dim == arbvp::TexDim::Cube ? 6 : 1;
  for (int i = 0; i < t.depth; ++i) t.texels.insert(t.texels.end(), {0.0f, 0.0f, 0.0f, 1.0f});
  return t;
}

class VulkanTargetEngine final : public TargetEngine {
 public:
  VulkanTargetEngine(std::unique_ptr<Device> device, int max_attachments)
      : device_(std::move(device)),
        pipelines_(*device_),
        dialect_(exec::DialectOf(arbvp::EmitTarget::Vk450)),
        max_attachments_(max_attachments) {}

  const std::string& description() const override { return device_->description(); }

  bool Run(const ArbPrograms& programs, const arbvp::EmitOptions& emit,
           const arbvp::ExecInputs& inputs, std::vector<arbvp::VectorResult>* results,
           std::string* not_applicable, std::string* error,
           const compiler::SourceFile* vertex_source,
           const compiler::SourceFile* fragment_source) override {
    results->clear();
    CheckedTranslation translation;
    if (!exec::TranslateForTarget(programs, emit, arbvp::EmitTarget::Vk450, vertex_source,
                                  fragment_source, &translation, not_applicable, error)) {
      return false;
    }
    exec::RunPlan plan;
    exec::ContextLimits limits;
    limits.max_draw_buffers = max_attachments_;
    if (!exec::PlanRun(programs, limits, &plan, error)) return false;
    // The point's position has a location of its own, past the binding map's sixteen.
    if (plan.mode != exec::RunMode::Fragment) plan.position_attrib = kPixelLocation;
    std::vector<exec::GlslPass> passes;
    if (!exec::PlanTargetPasses(plan, translation, dialect_, max_attachments_, &passes, error)) {
      return false;
    }
    const bool ok = RunPasses(plan, passes, translation.bindings, inputs, results, error);
    if (!ok) results->clear();
    return ok;
  }

 private:
  // One vertex per vector: every attribute location the pass may read.
  static bool Vertices(const exec::RunPlan& plan, const arbvp::BindingMap& map,
                       const arbvp::ExecInputs& inputs, int width, int height, float* data,
                       std::string* error) {
    for (size_t i = 0; i < inputs.vectors.size(); ++i) {
      auto put = [&](int location, const arbvp::Vec4& value) {
        std::copy(value.begin(), value.end(),
                  data + i * kVertexFloats + 4 * static_cast<size_t>(location));
      };
      const arbvp::InputVector& v = inputs.vectors[i];
      const arbvp::Vec4 clip = VulkanClipPosition(i, width, height, v.fragment.depth, inputs.state);
      if (!exec::PointAttributes(plan, map, v, clip, put, error)) return false;
    }
    return true;
  }

  // The descriptors of set 0: each uniform block's buffer and each sampler's texture.
  struct Descriptors {
    std::map<int, Buffer*> blocks;  // by binding
    std::map<int, Image*> samplers;
  };

  bool Upload(const exec::RunPlan& plan, const arbvp::BindingMap& map,
              const arbvp::ExecInputs& inputs, int width, int height, Resources* resources,
              Buffer** vertices, Descriptors* descriptors, std::string* error) {
    *vertices = resources->CreateBuffer(inputs.vectors.size() * kVertexFloats * sizeof(float),
                                        VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, error);
    if (*vertices == nullptr || !Vertices(plan, map, inputs, width, height,
                                          static_cast<float*>((*vertices)->data), error)) {
      return false;
    }
    arbvp::GlState state = inputs.state;
    state.framebuffer_height = static_cast<float>(height);
    for (const arbvp::UniformBlock& b : map.blocks) {
      std::vector<float> data;
      if (!FillBlock(map, b, inputs, state, &data, error)) return false;
      Buffer* buffer = resources->CreateBuffer(data.size() * sizeof(float),
                                               VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, error);
      if (buffer == nullptr) return false;
      std::memcpy(buffer->data, data.data(), data.size() * sizeof(float));
      descriptors->blocks[b.binding] = buffer;
    }
    for (const arbvp::SamplerBinding& s : map.samplers) {
      if (s.binding < 0 || descriptors->samplers.count(s.binding) != 0) continue;
      Image* texture =
          resources->CreateTexture(TextureFor(s, inputs), arbvp::IsShadowTarget(s.target), error);
      if (texture == nullptr) {
        *error = fmt::format("texture unit {} ({}): {}", s.unit, s.type, *error);
        return false;
      }
      descriptors->samplers[s.binding] = texture;
    }
    return true;
  }

  VkDescriptorSet WriteSet(const Pipeline& pipeline, const Descriptors& descriptors,
                           Resources* resources, std::string* error) const {
    const VkDescriptorSet set = resources->AllocateSet(
        pipeline.set_layout, static_cast<uint32_t>(descriptors.blocks.size()),
        static_cast<uint32_t>(descriptors.samplers.size()), error);
    if (set == VK_NULL_HANDLE) return set;
    std::vector<VkDescriptorBufferInfo> buffers;
    std::vector<VkDescriptorImageInfo> images;
    buffers.reserve(descriptors.blocks.size());
    images.reserve(descriptors.samplers.size());
    std::vector<VkWriteDescriptorSet> writes;
    auto write = [&](int binding, VkDescriptorType type) -> VkWriteDescriptorSet& {
      VkWriteDescriptorSet& w = writes.emplace_back();
      w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      w.dstSet = set;
      w.dstBinding = static_cast<uint32_t>(binding);
      w.descriptorCount = 1;
      w.descriptorType = type;
      return w;
    };
    for (const auto& [binding, buffer] : descriptors.blocks) {
      buffers.push_back({buffer->buffer, 0, buffer->size});
      write(binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER).pBufferInfo = &buffers.back();
    }
    for (const auto& [binding, image] : descriptors.samplers) {
      images.push_back({image->sampler, image->view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
      write(binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER).pImageInfo = &images.back();
    }
    vkUpdateDescriptorSets(device_->device(), static_cast<uint32_t>(writes.size()), writes.data(),
                           0, nullptr);
    return set;
  }

  // Draws the points of one pass and copies its attachments to `readback`.
  bool Draw(const Pipeline& pipeline, VkRenderPass render_pass, VkFramebuffer framebuffer,
            VkDescriptorSet set, const Buffer& vertices, const std::vector<Image*>& attachments,
            const std::vector<Buffer*>& readback, size_t count, int width, int height,
            const arbvp::GlState& state, std::string* error) const {
    VkCommandBuffer commands = device_->BeginCommands(error);
    if (commands == VK_NULL_HANDLE) return false;
    std::vector<VkClearValue> clears(attachments.size());  // (0, 0, 0, 0)
    VkRenderPassBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
    begin.renderPass = render_pass;
    begin.framebuffer = framebuffer;
    begin.renderArea.extent = {static_cast<uint32_t>(width), static_cast<uint32_t>(height)};
    begin.clearValueCount = static_cast<uint32_t>(clears.size());
    begin.pClearValues = clears.data();
    vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.pipeline);
    // A viewport of negative height (Vulkan 1.1) puts y = -1 at the bottom, as GL does: a
    // point lands on GL's row, counted from the bottom, and gl_FragCoord.y (counted from the
    // top) is what the translation flips back with framebuffer.height. GL clamps the depth
    // range to [0, 1]; so does Vulkan's viewport (without VK_EXT_depth_range_unrestricted).
    const VkViewport viewport{0.0f,
                              static_cast<float>(height),
                              static_cast<float>(width),
                              -static_cast<float>(height),
                              std::clamp(state.depth_near, 0.0f, 1.0f),
                              std::clamp(state.depth_far, 0.0f, 1.0f)};
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &begin.renderArea);
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout, 0, 1, &set,
                            0, nullptr);
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(commands, 0, 1, &vertices.buffer, &offset);
    vkCmdDraw(commands, static_cast<uint32_t>(count), 1, 0, 0);
    vkCmdEndRenderPass(commands);
    for (size_t a = 0; a < attachments.size(); ++a) {
      VkBufferImageCopy copy{};
      copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      copy.imageExtent = {static_cast<uint32_t>(width), static_cast<uint32_t>(height), 1};
      vkCmdCopyImageToBuffer(commands, attachments[a]->image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                             readback[a]->buffer, 1, &copy);
    }
    VkMemoryBarrier to_host{};
    to_host.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &to_host, 0, nullptr, 0, nullptr);
    return device_->Submit(commands, error);
  }

  bool RunPasses(const exec::RunPlan& plan, const std::vector<exec::GlslPass>& passes,
                 const arbvp::BindingMap& map, const arbvp::ExecInputs& inputs,
                 std::vector<arbvp::VectorResult>* results, std::string* error) {
    const size_t count = inputs.vectors.size();
    results->assign(count, arbvp::VectorResult{});
    if (count == 0 || passes.empty()) return true;
    const int width = arbvp::kFramebufferWidth;
    const int height = arbvp::FramebufferHeight(count);
    Resources resources(*device_);
    Buffer* vertices = nullptr;
    Descriptors descriptors;
    if (!Upload(plan, map, inputs, width, height, &resources, &vertices, &descriptors, error)) {
      return false;
    }
    size_t most = 1;
    for (const exec::GlslPass& pass : passes) most = std::max(most, pass.attachments.size());
    const size_t pixel_floats = static_cast<size_t>(width) * static_cast<size_t>(height) * 4;
    std::vector<Image*> attachments;
    std::vector<Buffer*> readback;
    for (size_t a = 0; a < most; ++a) {
      attachments.push_back(resources.CreateAttachment(width, height, error));
      readback.push_back(resources.CreateBuffer(pixel_floats * sizeof(float),
                                                VK_BUFFER_USAGE_TRANSFER_DST_BIT, error));
      if (attachments.back() == nullptr || readback.back() == nullptr) return false;
    }
    std::vector<std::vector<float>> values(plan.outputs.size());
    std::vector<float> alive;
    for (const exec::GlslPass& pass : passes) {
      const size_t used = pass.attachments.size();
      const Pipeline* pipeline = pipelines_.Get(pass, map, error);
      if (pipeline == nullptr) return false;
      const VkRenderPass render_pass = pipelines_.RenderPass(static_cast<int>(used), error);
      std::vector<VkImageView> views;
      for (size_t a = 0; a < used; ++a) views.push_back(attachments[a]->view);
      const VkFramebuffer framebuffer =
          render_pass == VK_NULL_HANDLE
              ? VK_NULL_HANDLE
              : resources.CreateFramebuffer(render_pass, views, width, height, error);
      if (framebuffer == VK_NULL_HANDLE) return false;
      const VkDescriptorSet set = WriteSet(*pipeline, descriptors, &resources, error);
      const std::vector<Image*> pass_attachments(
          attachments.begin(), attachments.begin() + static_cast<ptrdiff_t>(used));
      if (set == VK_NULL_HANDLE ||
          !Draw(*pipeline, render_pass, framebuffer, set, *vertices, pass_attachments, readback,
                count, width, height, inputs.state, error)) {
        return false;
      }
      for (size_t a = 0; a < used; ++a) {
        const int slot = pass.attachments[a];
        if (slot == exec::kAliveFlag && !alive.empty()) continue;  // one pass says it
        std::vector<float>& out =
            slot == exec::kAliveFlag ? alive : values[static_cast<size_t>(slot)];
        // GL's rows from the bottom: the image's from the top, reversed.
        const auto* pixels = static_cast<const float*>(readback[a]->data);
        const size_t row = static_cast<size_t>(width) * 4;
        out.resize(pixel_floats);
        for (size_t y = 0; y < static_cast<size_t>(height); ++y) {
          std::copy_n(pixels + (static_cast<size_t>(height) - 1 - y) * row, row,
                      out.begin() + static_cast<ptrdiff_t>(y * row));
        }
      }
    }
    exec::CollectResults(plan, values, alive, exec::GlslComponents, results);
    return true;
  }

  std::unique_ptr<Device> device_;
  Pipelines pipelines_;
  exec::TargetDialect dialect_;
  int max_attachments_ = kMaxAttachments;
};

}  // namespace

std::unique_ptr<TargetEngine> CreateVulkanEngine(std::string* error) {
  auto device = std::make_unique<Device>();
  if (!device->Create("llvmpipe", error)) return nullptr;
  const VkPhysicalDeviceLimits& limits = device->limits();
  if (limits.maxVertexInputAttributes < static_cast<uint32_t>(kVertexLocations) ||
      limits.maxColorAttachments < 2) {
    *error = fmt::format("{} has {} vertex attributes and {} colour attachments ({} and 2 needed)",
                         device->description(), limits.maxVertexInputAttributes,
                         limits.maxColorAttachments, kVertexLocations);
    return nullptr;
  }
  const int attachments = std::min(static_cast<int>(limits.maxColorAttachments), kMaxAttachments);
  return std::make_unique<VulkanTargetEngine>(std::move(device), attachments);
}

}  // namespace arbiter::runtime::vulkan
