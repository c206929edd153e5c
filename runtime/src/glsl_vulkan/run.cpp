// RunGlslVulkan: the shaders lowered to Vulkan GLSL 4.50 (glsl/lower_vulkan.h), completed with
// generated mains (shaders.h), compiled by glslang and drawn on lavapipe as one point per
// vector; the outputs come back from a storage buffer. The uniform blocks are filled at
// glslang's offsets: --uniform values by name (as RunGlsl sets them, with the same usage
// errors and notes), built-in state from glstate (builtin_state.h).
#include "glsl_exec/run.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>

#include "arbiter/glsl/lower_vulkan.h"
#include "arbiter/glstate/uniforms.h"
#include "arbiter/runtime/glsl_vulkan.h"
#include "exec/draw.h"
#include "exec/textures.h"
#include "glsl_exec/types.h"
#include "glsl_vulkan/builtin_state.h"
#include "glsl_vulkan/shaders.h"
#include "vulkan/device.h"
#include "vulkan/pipeline.h"
#include "vulkan/resources.h"

namespace arbiter::runtime {
namespace {

using glsl_exec::BaseKind;
using glsl_exec::TypeInfo;
using glsl_vulkan::IoPlan;

// A user uniform of the compiled shaders as GL's active uniforms name it ("w[0]" for an
// array), with where it lies in each stage's block.
struct ActiveUniform {
  std::string name;
  std::string type;
  int size = 1;
  std::vector<const glsl::CompiledUniform*> places;  // one per stage
};

TypeInfo TypeOf(const std::string& type) {
  if (type == "sampler") return {"sampler", 0, BaseKind::Sampler, 1, 1};
  return glsl_exec::LookUpType(type);
}

// The blocks' bytes and the samplers' units, filled from the inputs.
struct Uniforms {
  std::vector<uint32_t> vertex;                   // 32-bit words
  std::vector<uint32_t> fragment;                 // idem
  std::map<std::string, std::vector<int>> units;  // sampler (lowered name) -> unit per element
};

// Writes `count` elements of `values` (each of `type`) at element `first` of `u`.
void Put(const glsl::CompiledUniform& u, const TypeInfo& type, int first, size_t count,
         const std::vector<float>& values, Uniforms* out) {
  if (type.base == BaseKind::Sampler) {
    std::vector<int>& units = out->units[u.name];
    units.resize(static_cast<size_t>(u.array_size), 0);
    for (size_t e = 0; e < count && first + e < units.size(); ++e) {
      units[first + e] = static_cast<int>(values[e]);
    }
    return;
  }
  std::vector<uint32_t>& words = u.fragment ? out->fragment : out->vertex;
  const int columns = std::max(type.columns, 1);
  const int rows = type.components / columns;
  for (size_t e = 0; e < count && first + static_cast<int>(e) < u.array_size; ++e) {
    for (int c = 0; c < columns; ++c) {
      for (int r = 0; r < rows; ++r) {
        const float v =
            values[e * static_cast<size_t>(type.components) + static_cast<size_t>(c * rows + r)];
        const int at =
            u.offset + (first + static_cast<int>(e)) * u.array_stride + c * u.matrix_stride + 4 * r;
        const auto byte = static_cast<size_t>(at);
        if (byte / 4 >= words.size()) continue;
        uint32_t word = 0;
        if (type.base == BaseKind::Float) {
          std::memcpy(&word, &v, 4);
        } else if (type.base == BaseKind::Bool) {
          word = v != 0.0f ? 1u : 0u;
        } else {
          const auto i = static_cast<int32_t>(v);
          std::memcpy(&word, &i, 4);
        }
        words[byte / 4] = word;
      }
    }
  }
}

// The user's uniforms (not built-in state, not the engine's), merged across stages.
std::vector<ActiveUniform> ActiveUniforms(const glsl::CompiledPair& compiled) {
  std::vector<ActiveUniform> out;
  for (const glsl::CompiledUniform& c : compiled.uniforms) {
    if (c.name.starts_with("arb_gl_") || c.name.starts_with("arb_depthmode_")) continue;
    const std::string name = glsl_vulkan::UserAccess(c.name);
    auto it = std::find_if(out.begin(), out.end(),
                           [&](const ActiveUniform& u) { return u.name == name; });
    if (it == out.end()) {
      out.push_back({name, c.type, c.array_size, {}});
      it = out.end() - 1;
    }
    it->places.push_back(&c);
  }
  return out;
}

// RunGlsl's SetUniforms on the blocks: false with `usage` for a bad count or a fractional
// integer.
bool SetUserUniforms(const std::vector<ActiveUniform>& active, const GlslExecInputs& inputs,
                     Uniforms* out, std::set<std::string>* used, std::set<size_t>* applied,
                     std::string* usage) {
  for (size_t a = 0; a < inputs.uniforms.size(); ++a) {
    const auto& [name, values] = inputs.uniforms[a];
    for (const ActiveUniform& u : active) {
      int first = 0;
      bool whole = false;
      if (!glsl_exec::MatchUniform(u.name, u.size, name, &first, &whole)) continue;
      const TypeInfo type = TypeOf(u.type);
      if (type.components == 0) {
        *usage =
            fmt::format("--uniform {}: the uniform's type ({}) is not supported", name, u.type);
        return false;
      }
      size_t elements = 0;
      if (!glsl_exec::CheckUniformValues(name, type, u.size, whole, values, &elements, usage)) {
        return false;
      }
      for (const glsl::CompiledUniform* place : u.places) {
        Put(*place, type, first, elements, values, out);
      }
      used->insert(u.name);
      applied->insert(a);
    }
  }
  return true;
}

// The sampler type arbiter's reflection gives the user's sampler `name` ("sampler2D").
std::string SamplerType(const GlslShaders& shaders, const std::string& name) {
  for (const glsl::Reflection* r : {shaders.vertex_reflection, shaders.fragment_reflection}) {
    if (r == nullptr) continue;
    for (const glsl::ReflectedVariable& v : r->samplers) {
      if (v.name == name) return v.type;
    }
  }
  return "sampler2D";
}

arbvp::TexDim DimOf(const std::string& sampler_type) {
  if (sampler_type.starts_with("sampler1D")) return arbvp::TexDim::Tex1D;
  if (sampler_type.starts_with("sampler3D")) return arbvp::TexDim::Tex3D;
  if (sampler_type.starts_with("samplerCube")) return arbvp::TexDim::Cube;
  return arbvp::TexDim::Tex2D;
}

// The texture a sampler of `type` on `unit` reads: the model's, or a 1x1 (0, 0, 0, 1) of the
// sampler's dimension when the unit holds none of it (GL's incomplete texture).
arbvp::Texture TextureFor(const std::string& type, int unit, const GlslExecInputs& inputs) {
  const arbvp::TexDim dim = DimOf(type);
  auto it = inputs.textures.find(unit);
  if (it != inputs.textures.end() && it->second.dim == dim) return it->second;
  arbvp::Texture t;
  t.dim = dim;
  t.depth = dim == arbvp::TexDim::Cube ? 6 : 1;
  for (int i = 0; i < t.depth; ++i) t.texels.insert(t.texels.end(), {0.0f, 0.0f, 0.0f, 1.0f});
  return t;
}

// The built-in state and the depth mode selectors of the shadow samplers.
bool SetEngineUniforms(const glsl::CompiledPair& compiled, const GlslShaders& shaders,
                       const GlslExecInputs& inputs, Uniforms* out, std::string* error) {
  // A shadow lookup expands by its texture's GL_DEPTH_TEXTURE_MODE, which GL keeps with the
  // texture (as the Mesa engine uploads it) and glstate reads as texture[n].depthmode.
  arbvp::GlState state = inputs.state;
  for (const auto& [unit, texture] : inputs.textures) {
    if (unit >= 0 && unit < glstate::kMaxTextureImageUnits) {
      state.depth_texture_mode[static_cast<size_t>(unit)] =
          static_cast<uint32_t>(exec::DepthTextureMode(texture.depth_mode));
    }
  }
  for (const glsl::CompiledUniform& c : compiled.uniforms) {
    const TypeInfo type = TypeOf(c.type);
    if (c.name.starts_with("arb_gl_")) {
      const std::string path = c.name.substr(4);  // gl_...
      const bool array = path.ends_with("[0]") && c.array_size > 1;
      for (int e = 0; e < c.array_size; ++e) {
        std::string element = path;
        if (array) element = fmt::format("{}[{}]", path.substr(0, path.size() - 3), e);
        std::vector<float> value;
        if (!glsl_vulkan::BuiltinStateValue(element, state, &value, error)) return false;
        if (value.size() != static_cast<size_t>(type.components)) {
          *error = fmt::format("{} has {} numbers, its uniform {}", element, value.size(),
                               type.components);
          return false;
        }
        Put(c, type, e, 1, value, out);
      }
    }
    if (c.name.starts_with("arb_depthmode_")) {
      const std::string sampler = c.name.substr(14);
      auto it = out->units.find(sampler);
      const int unit = it != out->units.end() && !it->second.empty() ? it->second[0] : 0;
      glstate::UniformData selector;
      if (!glstate::UniformValue(state, {}, fmt::format("texture[{}].depthmode", unit),
                                 &selector)) {
        selector = glstate::detail::VectorUniform(glstate::DepthModeSelector(0));
      }
      // No texture of the sampler's dimension on the unit: GL's incomplete texture reads
      // (0, 0, 0, 1).
      auto texture = inputs.textures.find(unit);
      if (texture == inputs.textures.end() ||
          texture->second.dim != DimOf(SamplerType(shaders, glsl_vulkan::UserAccess(sampler)))) {
        selector = glstate::detail::VectorUniform({0, 0, 0, 2});
      }
      Put(c, type, 0, 1, std::vector<float>(selector.data.begin(), selector.data.begin() + 4), out);
    }
  }
  return true;
}

// One draw of every vector on lavapipe.
class Draw {
 public:
  Draw(const vulkan::Device& device, vulkan::Resources* resources)
      : device_(device), resources_(resources), pipelines_(device) {}
  Draw(const Draw&) = delete;
  Draw& operator=(const Draw&) = delete;
  ~Draw() {
    const VkDevice d = device_.device();
    if (pipeline_ != VK_NULL_HANDLE) vkDestroyPipeline(d, pipeline_, nullptr);
    if (layout_ != VK_NULL_HANDLE) vkDestroyPipelineLayout(d, layout_, nullptr);
    if (set_layout_ != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(d, set_layout_, nullptr);
    for (VkShaderModule m : modules_) vkDestroyShaderModule(d, m, nullptr);
  }

  // Set 0: the two uniform blocks, the two storage buffers, and each sampler.
  struct Bindings {
    vulkan::Buffer* vertex_block = nullptr;
    vulkan::Buffer* fragment_block = nullptr;
    vulkan::Buffer* inputs = nullptr;
    vulkan::Buffer* outputs = nullptr;
    std::map<int, std::vector<vulkan::Image*>> samplers;  // by binding
  };

  bool Run(const glsl::CompiledPair& compiled, const Bindings& b, size_t count, int width,
           int height, const arbvp::GlState& state, std::string* error) {
    if (!Layout(b, error) || !Pipeline(compiled, error)) return false;
    const VkDescriptorSet set = WriteSet(b, error);
    if (set == VK_NULL_HANDLE) return false;
    vulkan::Image* attachment = resources_->CreateAttachment(width, height, error);
    if (attachment == nullptr) return false;
    const VkFramebuffer framebuffer =
        resources_->CreateFramebuffer(render_pass_, {attachment->view}, width, height, error);
    if (framebuffer == VK_NULL_HANDLE) return false;
    VkCommandBuffer commands = device_.BeginCommands(error);
    if (commands == VK_NULL_HANDLE) return false;
    VkClearValue clear{};
    VkRenderPassBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
    begin.renderPass = render_pass_;
    begin.framebuffer = framebuffer;
    begin.renderArea.extent = {static_cast<uint32_t>(width), static_cast<uint32_t>(height)};
    begin.clearValueCount = 1;
    begin.pClearValues = &clear;
    vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    // y = -1 at the bottom, as GL has it (see vulkan/engine.cpp); the window depth under
    // the depth range, clamped to [0, 1] as GL clamps it.
    const VkViewport viewport{0.0f,
                              static_cast<float>(height),
                              static_cast<float>(width),
                              -static_cast<float>(height),
                              std::clamp(state.depth_near, 0.0f, 1.0f),
                              std::clamp(state.depth_far, 0.0f, 1.0f)};
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &begin.renderArea);
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set, 0,
                            nullptr);
    vkCmdDraw(commands, static_cast<uint32_t>(count), 1, 0, 0);
    vkCmdEndRenderPass(commands);
    VkMemoryBarrier to_host{};
    to_host.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    to_host.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(
        commands, VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
        VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0, nullptr, 0, nullptr);
    return device_.Submit(commands, error);
  }

 private:
  bool Layout(const Bindings& b, std::string* error) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    auto add = [&](int binding, VkDescriptorType type, uint32_t count) {
      VkDescriptorSetLayoutBinding l{};
      l.binding = static_cast<uint32_t>(binding);
      l.descriptorType = type;
      l.descriptorCount = count;
      l.stageFlags = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
      bindings.push_back(l);
    };
    if (b.vertex_block != nullptr) {
      add(glsl::kVertexUniformBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1);
    }
    if (b.fragment_block != nullptr) {
      add(glsl::kFragmentUniformBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1);
    }
    add(glsl_vulkan::kInputBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1);
    add(glsl_vulkan::kOutputBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1);
    for (const auto& [binding, images] : b.samplers) {
      add(binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, static_cast<uint32_t>(images.size()));
    }
    VkDescriptorSetLayoutCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    info.bindingCount = static_cast<uint32_t>(bindings.size());
    info.pBindings = bindings.data();
    if (!vulkan::Check(vkCreateDescriptorSetLayout(device_.device(), &info, nullptr, &set_layout_),
                       "vkCreateDescriptorSetLayout", error)) {
      return false;
    }
    VkPipelineLayoutCreateInfo layout{};
    layout.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layout.setLayoutCount = 1;
    layout.pSetLayouts = &set_layout_;
    return vulkan::Check(vkCreatePipelineLayout(device_.device(), &layout, nullptr, &layout_),
                         "vkCreatePipelineLayout", error);
  }

  bool Module(const std::vector<uint32_t>& spirv, VkShaderModule* module, std::string* error) {
    VkShaderModuleCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    info.codeSize = spirv.size() * sizeof(uint32_t);
    info.pCode = spirv.data();
    if (!vulkan::Check(vkCreateShaderModule(device_.device(), &info, nullptr, module),
                       "vkCreateShaderModule", error)) {
      return false;
    }
    modules_.push_back(*module);
    return true;
  }

  bool Pipeline(const glsl::CompiledPair& compiled, std::string* error) {
    render_pass_ = pipelines_.RenderPass(1, error);
    if (render_pass_ == VK_NULL_HANDLE) return false;
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    for (const auto* spirv : {&compiled.vertex, &compiled.fragment}) {
      if (spirv->empty()) continue;
      VkShaderModule module = VK_NULL_HANDLE;
      if (!Module(*spirv, &module, error)) return false;
      VkPipelineShaderStageCreateInfo& s = stages.emplace_back();
      s.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
      s.stage =
          spirv == &compiled.vertex ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
      s.module = module;
      s.pName = "main";
    }
    VkPipelineVertexInputStateCreateInfo vertex_input{};
    vertex_input.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
    // A vertex shader alone: nothing is rasterised (GL_RASTERIZER_DISCARD in the GL run); the
    // attachment is there for the render pass, its colour writes unused.
    return vulkan::CreatePointPipeline(device_.device(), stages, vertex_input, 1,
                                       compiled.fragment.empty(), layout_, render_pass_, &pipeline_,
                                       error);
  }

  VkDescriptorSet WriteSet(const Bindings& b, std::string* error) {
    uint32_t samplers = 0;
    for (const auto& [binding, images] : b.samplers) {
      samplers += static_cast<uint32_t>(images.size());
    }
    const uint32_t blocks = (b.vertex_block != nullptr ? 1 : 0) + (b.fragment_block != nullptr);
    const VkDescriptorSet set =
        resources_->AllocateSet(set_layout_, blocks, samplers, error, /*storage_buffers=*/2);
    if (set == VK_NULL_HANDLE) return set;
    std::vector<VkDescriptorBufferInfo> buffers;
    std::vector<VkDescriptorImageInfo> images;
    buffers.reserve(4);
    images.reserve(samplers);
    std::vector<VkWriteDescriptorSet> writes;
    auto write = [&](int binding, VkDescriptorType type, uint32_t count) -> VkWriteDescriptorSet& {
      VkWriteDescriptorSet& w = writes.emplace_back();
      w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      w.dstSet = set;
      w.dstBinding = static_cast<uint32_t>(binding);
      w.descriptorCount = count;
      w.descriptorType = type;
      return w;
    };
    auto buffer = [&](int binding, VkDescriptorType type, const vulkan::Buffer* buf) {
      if (buf == nullptr) return;
      buffers.push_back({buf->buffer, 0, buf->size});
      write(binding, type, 1).pBufferInfo = &buffers.back();
    };
    buffer(glsl::kVertexUniformBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, b.vertex_block);
    buffer(glsl::kFragmentUniformBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, b.fragment_block);
    buffer(glsl_vulkan::kInputBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, b.inputs);
    buffer(glsl_vulkan::kOutputBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, b.outputs);
    for (const auto& [binding, list] : b.samplers) {
      const size_t first = images.size();
      for (const vulkan::Image* image : list) {
        images.push_back({image->sampler, image->view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
      }
      write(binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, static_cast<uint32_t>(list.size()))
          .pImageInfo = &images[first];
    }
    vkUpdateDescriptorSets(device_.device(), static_cast<uint32_t>(writes.size()), writes.data(), 0,
                           nullptr);
    return set;
  }

  const vulkan::Device& device_;
  vulkan::Resources* resources_;
  vulkan::Pipelines pipelines_;
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  std::vector<VkShaderModule> modules_;
};

// The input records: each vector's clip position, then its slots' columns ((0, 0, 0, 1)
// where a slot has fewer numbers, as GL's fixed-function calls fill them).
std::vector<float> InputRecords(const IoPlan& plan, const GlslExecInputs& inputs, int width,
                                int height, bool pair) {
  const size_t stride = static_cast<size_t>(plan.input_stride) * 4;
  std::vector<float> data(std::max<size_t>(inputs.vectors.size() * stride, 4), 0.0f);
  for (size_t i = 0; i < inputs.vectors.size(); ++i) {
    const auto& v = inputs.vectors[i];
    float* record = data.data() + i * stride;
    auto depth_it = v.find("gl_FragCoord.z");
    const float depth = pair || depth_it == v.end() ? 0.5f : depth_it->second[0];
    arbvp::Vec4 clip = exec::PixelClipPosition(i, width, height, depth, inputs.state);
    clip[2] = (clip[2] + 1.0f) * 0.5f;  // Vulkan's clip volume has 0 <= z <= w
    std::copy(clip.begin(), clip.end(), record);
    for (const IoPlan::Input& in : plan.inputs) {
      const TypeInfo type = glsl_exec::LookUpType(in.type);
      const int columns = std::max(type.columns, 1);
      const int rows = std::max(type.components / columns, 1);
      auto it = v.find(in.name);
      const std::vector<float> numbers = it != v.end() ? it->second : std::vector<float>{};
      for (int c = 0; c < columns; ++c) {
        float* column = record + 4 * static_cast<size_t>(in.first + c);
        const float fill[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        for (int r = 0; r < 4; ++r) {
          const auto at =
              static_cast<size_t>(c) * static_cast<size_t>(rows) + static_cast<size_t>(r);
          column[r] = r < rows && at < numbers.size() ? numbers[at] : fill[r];
        }
      }
    }
  }
  return data;
}

bool Execute(const GlslShaders& shaders, const GlslExecInputs& inputs, GlslRunResult* result,
             std::string* not_applicable, std::string* error) {
  glsl::LoweredShader vertex;
  glsl::LoweredShader fragment;
  if (!shaders.vertex.empty()) vertex = glsl::LowerForVulkan(glsl::Stage::Vertex, shaders.vertex);
  if (!shaders.fragment.empty()) {
    fragment = glsl::LowerForVulkan(glsl::Stage::Fragment, shaders.fragment);
  }
  for (const glsl::LoweredShader* l : {&vertex, &fragment}) {
    if (!l->not_applicable.empty()) {
      *not_applicable = l->not_applicable;
      return false;
    }
  }
  // gl_TexCoord beyond Mesa's gl_MaxTextureCoords (8), which arbiter's limits allow: the
  // lowering declares Mesa's eight, as the Mesa engine has them.
  for (const glsl::Reflection* r : {shaders.vertex_reflection, shaders.fragment_reflection}) {
    if (r == nullptr) continue;
    for (const auto* list : {&r->builtins_read, &r->builtins_written}) {
      for (const glsl::BuiltinUse& use : *list) {
        const bool beyond =
            (use.name.starts_with("gl_TexCoord[") && std::stoi(use.name.substr(12)) >= 8) ||
            (use.name == "gl_TexCoord" && use.components > 8 * 4);
        if (beyond) {
          *not_applicable =
              fmt::format("not applicable: {} (Mesa's gl_MaxTextureCoords is 8)", use.name);
          return false;
        }
      }
    }
  }
  const size_t count = inputs.vectors.size();
  const int width = arbvp::kFramebufferWidth;
  const int height = std::max(arbvp::FramebufferHeight(count), 1);
  const IoPlan plan = glsl_vulkan::PlanIo(shaders, inputs);
  const glsl_vulkan::Generated texts =
      glsl_vulkan::GenerateMains(shaders, vertex.text, fragment.text, plan, count, height);
  glsl::CompiledPair compiled;
  if (!glsl::CompileLoweredPair(texts.vertex, texts.fragment, &compiled, error)) return false;

  // The uniforms, as RunGlsl sets them.
  Uniforms uniforms;
  uniforms.vertex.assign(static_cast<size_t>(compiled.vertex_block_size + 3) / 4, 0);
  uniforms.fragment.assign(static_cast<size_t>(compiled.fragment_block_size + 3) / 4, 0);
  const std::vector<ActiveUniform> active = ActiveUniforms(compiled);
  std::set<std::string> used;
  std::set<size_t> applied;
  result->vectors.assign(count, GlslVectorResult{});
  if (!SetUserUniforms(active, inputs, &uniforms, &used, &applied, &result->usage_error)) {
    result->vectors.clear();
    return true;
  }
  std::vector<glsl_exec::UniformSeen> seen;
  for (const ActiveUniform& u : active) {
    seen.push_back({u.name, u.size, TypeOf(u.type).base == BaseKind::Sampler});
  }
  glsl_exec::FinishUniformNotes(inputs, seen, used, applied, "glslang", result);
  if (!result->usage_error.empty()) return true;
  if (!SetEngineUniforms(compiled, shaders, inputs, &uniforms, error)) return false;

  vulkan::Device device;
  if (!device.Create("llvmpipe", error)) return false;
  result->description = device.description();
  vulkan::Resources resources(device);
  Draw::Bindings bindings;
  auto upload = [&](const void* bytes, size_t size, VkBufferUsageFlags usage) {
    vulkan::Buffer* b = resources.CreateBuffer(std::max<size_t>(size, 16), usage, error);
    if (b != nullptr && size > 0) std::memcpy(b->data, bytes, size);
    return b;
  };
  if (!compiled.vertex.empty() && compiled.vertex_block_size > 0) {
    bindings.vertex_block = upload(uniforms.vertex.data(), uniforms.vertex.size() * 4,
                                   VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    if (bindings.vertex_block == nullptr) return false;
  }
  if (!compiled.fragment.empty() && compiled.fragment_block_size > 0) {
    bindings.fragment_block = upload(uniforms.fragment.data(), uniforms.fragment.size() * 4,
                                     VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    if (bindings.fragment_block == nullptr) return false;
  }
  const std::vector<float> records =
      InputRecords(plan, inputs, width, height, !shaders.vertex.empty());
  bindings.inputs =
      upload(records.data(), records.size() * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  const size_t out_floats =
      count * static_cast<size_t>(plan.vertex_stride + plan.fragment_stride) + 1;
  bindings.outputs =
      resources.CreateBuffer(out_floats * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, error);
  if (bindings.inputs == nullptr || bindings.outputs == nullptr) return false;
  for (const glsl::CompiledUniform& c : compiled.uniforms) {
    if (c.binding < 0) continue;
    const std::string user = glsl_vulkan::UserAccess(c.name);
    const std::string base = user.substr(0, user.find('['));
    const std::string type = SamplerType(shaders, base);
    const std::vector<int>& units = uniforms.units[c.name];
    std::vector<vulkan::Image*>& list = bindings.samplers[c.binding];
    for (int e = 0; e < c.array_size; ++e) {
      const int unit = static_cast<size_t>(e) < units.size() ? units[static_cast<size_t>(e)] : 0;
      vulkan::Image* image =
          resources.CreateTexture(TextureFor(type, unit, inputs), type.ends_with("Shadow"), error);
      if (image == nullptr) {
        *error = fmt::format("texture unit {} ({}): {}", unit, type, *error);
        return false;
      }
      list.push_back(image);
    }
  }
  if (count == 0) return true;
  Draw draw(device, &resources);
  if (!draw.Run(compiled, bindings, count, width, height, inputs.state, error)) return false;

  const auto* out = static_cast<const float*>(bindings.outputs->data);
  for (size_t v = 0; v < count; ++v) {
    GlslVectorResult& r = result->vectors[v];
    const float* vo = out + v * static_cast<size_t>(plan.vertex_stride);
    for (const glsl_exec::VertexOutput& o : plan.vertex_outputs) {
      r.outputs.push_back({o.name, "vertex", o.type,
                           std::vector<float>(vo, vo + static_cast<size_t>(o.components))});
      vo += o.components;
    }
    if (shaders.fragment.empty()) continue;
    const float* fo = out + count * static_cast<size_t>(plan.vertex_stride) +
                      v * static_cast<size_t>(plan.fragment_stride);
    if (fo[0] != 1.0f) {
      r.discarded = true;
      continue;
    }
    ++fo;
    const glsl_exec::FragmentOutputs& f = plan.fragment_outputs;
    auto take = [&](std::string name, std::string type, size_t n) {
      r.outputs.push_back(
          {std::move(name), "fragment", std::move(type), std::vector<float>(fo, fo + n)});
      fo += n;
    };
    if (f.color) take("gl_FragColor", "vec4", 4);
    for (int n : f.data) take(fmt::format("gl_FragData[{}]", n), "vec4", 4);
    if (f.depth) take("gl_FragDepth", "float", 1);
  }
  return true;
}

}  // namespace

bool RunGlslVulkan(const GlslShaders& shaders, const GlslExecInputs& inputs, GlslRunResult* result,
                   std::string* not_applicable, std::string* error) {
  *result = GlslRunResult{};
  not_applicable->clear();
  const bool ok = Execute(shaders, inputs, result, not_applicable, error);
  if (!ok) result->vectors.clear();
  return ok;
}

WorkerStatus RunGlslVulkanInWorker(const WorkerLimits& limits, const GlslShaders& shaders,
                                   const GlslExecInputs& inputs, GlslRunResult* result,
                                   std::string* not_applicable, std::string* error) {
  auto job = [&](std::string* payload, std::string* job_error) {
    GlslRunResult out;
    std::string refusal;
    if (!RunGlslVulkan(shaders, inputs, &out, &refusal, job_error) && refusal.empty()) {
      return false;
    }
    nlohmann::ordered_json j = GlslRunResultToJson(out);
    j["not_applicable"] = refusal;
    *payload = j.dump();
    return true;
  };
  std::string payload;
  const WorkerStatus status = RunInWorker(limits, job, &payload, error);
  if (status != WorkerStatus::Ok) return status;
  const nlohmann::json j = nlohmann::json::parse(payload, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) {
    *error = "the worker's answer is not JSON";
    return WorkerStatus::Crashed;
  }
  *result = GlslRunResult{};
  if (!j.contains("not_applicable") || !j["not_applicable"].is_string() ||
      !GlslRunResultFromJson(j, result)) {
    *error = "the worker's answer is not a GLSL run's result";
    return WorkerStatus::Crashed;
  }
  *not_applicable = j["not_applicable"].get<std::string>();
  if (!not_applicable->empty()) return WorkerStatus::JobFailed;
  return WorkerStatus::Ok;
}

}  // namespace arbiter::runtime
