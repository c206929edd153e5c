// The graphics pipelines: see pipeline.h.
#include "vulkan/pipeline.h"

#include <fmt/format.h>

#include <map>
#include <vector>

#include "arbiter/targets/targets.h"

namespace arbiter::runtime::vulkan {
namespace {

constexpr size_t kCacheSize = 8;

bool CreateModule(VkDevice device, const std::string& glsl, targets::Stage stage,
                  VkShaderModule* module, std::string* error) {
  std::vector<uint32_t> spirv;
  std::vector<targets::Message> messages;
  if (!targets::CompileGlslToSpirv(glsl, stage, &spirv, &messages)) {
    std::string said;
    for (const targets::Message& m : messages)
      said += (said.empty() ? "" : "; ") + FormatMessage(m);
    *error = fmt::format("the adapted {} shader does not compile to SPIR-V: {}",
                         stage == targets::Stage::Vertex ? "vertex" : "fragment", said);
    return false;
  }
  VkShaderModuleCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  info.codeSize = spirv.size() * sizeof(uint32_t);
  info.pCode = spirv.data();
  if (!Check(vkCreateShaderModule(device, &info, nullptr, module), "vkCreateShaderModule", error)) {
    *module = VK_NULL_HANDLE;
    return false;
  }
  return true;
}

// Set 0 as the binding map describes it: each stage's uniform block and every sampler.
std::vector<VkDescriptorSetLayoutBinding> SetBindings(const arbvp::BindingMap& map) {
  std::map<int, VkDescriptorSetLayoutBinding> bindings;
  for (const arbvp::UniformBlock& b : map.blocks) {
    VkDescriptorSetLayoutBinding& l = bindings[b.binding];
    l.binding = static_cast<uint32_t>(b.binding);
    l.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    l.descriptorCount = 1;
    l.stageFlags |= b.stage == arbvp::ProgramKind::Vertex ? VK_SHADER_STAGE_VERTEX_BIT
                                                          : VK_SHADER_STAGE_FRAGMENT_BIT;
  }
  for (const arbvp::SamplerBinding& s : map.samplers) {
    if (s.binding < 0) continue;
    VkDescriptorSetLayoutBinding& l = bindings[s.binding];
    l.binding = static_cast<uint32_t>(s.binding);
    l.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    l.descriptorCount = 1;
    l.stageFlags = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
  }
  std::vector<VkDescriptorSetLayoutBinding> out;
  out.reserve(bindings.size());
  for (const auto& [binding, l] : bindings) out.push_back(l);
  return out;
}

}  // namespace

bool CreatePointPipeline(VkDevice device,
                         const std::vector<VkPipelineShaderStageCreateInfo>& stages,
                         const VkPipelineVertexInputStateCreateInfo& vertex_input, int attachments,
                         bool rasterizer_discard, VkPipelineLayout layout, VkRenderPass render_pass,
                         VkPipeline* pipeline, std::string* error) {
  VkPipelineInputAssemblyStateCreateInfo assembly{};
  assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
  VkPipelineViewportStateCreateInfo viewport{};
  viewport.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{};
  raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  raster.rasterizerDiscardEnable = rasterizer_discard ? VK_TRUE : VK_FALSE;
  VkPipelineMultisampleStateCreateInfo multisample{};
  multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  std::vector<VkPipelineColorBlendAttachmentState> blends(static_cast<size_t>(attachments));
  for (VkPipelineColorBlendAttachmentState& b : blends) {
    b.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                       VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  }
  VkPipelineColorBlendStateCreateInfo blend{};
  blend.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
  blend.attachmentCount = static_cast<uint32_t>(blends.size());
  blend.pAttachments = blends.data();
  const std::array<VkDynamicState, 2> dynamic_states = {VK_DYNAMIC_STATE_VIEWPORT,
                                                        VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{};
  dynamic.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
  dynamic.dynamicStateCount = static_cast<uint32_t>(dynamic_states.size());
  dynamic.pDynamicStates = dynamic_states.data();
  VkGraphicsPipelineCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
  info.stageCount = static_cast<uint32_t>(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout;
  info.renderPass = render_pass;
  return Check(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, pipeline),
               "vkCreateGraphicsPipelines", error);
}

Pipelines::~Pipelines() {
  for (Pipeline& p : cache_) Destroy(&p);
  for (VkRenderPass r : render_passes_) {
    if (r != VK_NULL_HANDLE) vkDestroyRenderPass(device_.device(), r, nullptr);
  }
}

void Pipelines::Destroy(Pipeline* p) const {
  const VkDevice d = device_.device();
  if (p->pipeline != VK_NULL_HANDLE) vkDestroyPipeline(d, p->pipeline, nullptr);
  if (p->layout != VK_NULL_HANDLE) vkDestroyPipelineLayout(d, p->layout, nullptr);
  if (p->set_layout != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(d, p->set_layout, nullptr);
  if (p->vertex != VK_NULL_HANDLE) vkDestroyShaderModule(d, p->vertex, nullptr);
  if (p->fragment != VK_NULL_HANDLE) vkDestroyShaderModule(d, p->fragment, nullptr);
  *p = Pipeline{};
}

VkRenderPass Pipelines::RenderPass(int count, std::string* error) {
  if (count < 1 || count > kMaxAttachments) {
    *error = fmt::format("vulkan: {} colour attachments (1..{})", count, kMaxAttachments);
    return VK_NULL_HANDLE;
  }
  VkRenderPass& pass = render_passes_[static_cast<size_t>(count)];
  if (pass != VK_NULL_HANDLE) return pass;
  std::vector<VkAttachmentDescription> attachments(static_cast<size_t>(count));
  std::vector<VkAttachmentReference> references(static_cast<size_t>(count));
  for (size_t a = 0; a < attachments.size(); ++a) {
    VkAttachmentDescription& d = attachments[a];
    d.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    d.samples = VK_SAMPLE_COUNT_1_BIT;
    d.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    d.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    d.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    d.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    d.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    d.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    references[a] = {static_cast<uint32_t>(a), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  }
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = static_cast<uint32_t>(count);
  subpass.pColorAttachments = references.data();
  // The copy to the readback buffer waits for the colour writes.
  VkSubpassDependency after{};
  after.srcSubpass = 0;
  after.dstSubpass = VK_SUBPASS_EXTERNAL;
  after.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  after.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  after.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  after.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  VkRenderPassCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
  info.attachmentCount = static_cast<uint32_t>(count);
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &after;
  if (!Check(vkCreateRenderPass(device_.device(), &info, nullptr, &pass), "vkCreateRenderPass",
             error)) {
    pass = VK_NULL_HANDLE;
  }
  return pass;
}

const Pipeline* Pipelines::Get(const exec::GlslPass& pass, const arbvp::BindingMap& map,
                               std::string* error) {
  const std::string key =
      fmt::format("{}\n//--\n{}\n//-- {}", pass.vertex, pass.fragment, pass.attachments.size());
  for (auto it = cache_.begin(); it != cache_.end(); ++it) {
    if (it->key == key) {
      cache_.splice(cache_.begin(), cache_, it);
      return &cache_.front();
    }
  }
  Pipeline p;
  p.key = key;
  if (!Build(pass, map, &p, error)) {
    Destroy(&p);
    return nullptr;
  }
  if (cache_.size() == kCacheSize) {
    Destroy(&cache_.back());
    cache_.pop_back();
  }
  cache_.push_front(std::move(p));
  return &cache_.front();
}

bool Pipelines::Build(const exec::GlslPass& pass, const arbvp::BindingMap& map, Pipeline* p,
                      std::string* error) {
  const VkDevice d = device_.device();
  const int count = static_cast<int>(pass.attachments.size());
  const VkRenderPass render_pass = RenderPass(count, error);
  if (render_pass == VK_NULL_HANDLE ||
      !CreateModule(d, pass.vertex, targets::Stage::Vertex, &p->vertex, error) ||
      !CreateModule(d, pass.fragment, targets::Stage::Fragment, &p->fragment, error)) {
    return false;
  }
  const std::vector<VkDescriptorSetLayoutBinding> bindings = SetBindings(map);
  VkDescriptorSetLayoutCreateInfo set_info{};
  set_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  set_info.bindingCount = static_cast<uint32_t>(bindings.size());
  set_info.pBindings = bindings.data();
  if (!Check(vkCreateDescriptorSetLayout(d, &set_info, nullptr, &p->set_layout),
             "vkCreateDescriptorSetLayout", error)) {
    p->set_layout = VK_NULL_HANDLE;
    return false;
  }
  VkPipelineLayoutCreateInfo layout_info{};
  layout_info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &p->set_layout;
  if (!Check(vkCreatePipelineLayout(d, &layout_info, nullptr, &p->layout), "vkCreatePipelineLayout",
             error)) {
    p->layout = VK_NULL_HANDLE;
    return false;
  }
  std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
  for (size_t s = 0; s < stages.size(); ++s) {
    stages[s].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    stages[s].stage = s == 0 ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[s].module = s == 0 ? p->vertex : p->fragment;
    stages[s].pName = "main";
  }
  const VkVertexInputBindingDescription vertex_binding{
      0, static_cast<uint32_t>(sizeof(float) * 4 * kVertexLocations), VK_VERTEX_INPUT_RATE_VERTEX};
  std::array<VkVertexInputAttributeDescription, kVertexLocations> attributes{};
  for (uint32_t l = 0; l < attributes.size(); ++l) {
    attributes[l] = {l, 0, VK_FORMAT_R32G32B32A32_SFLOAT,
                     static_cast<uint32_t>(sizeof(float) * 4 * l)};
  }
  VkPipelineVertexInputStateCreateInfo vertex_input{};
  vertex_input.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
  vertex_input.vertexBindingDescriptionCount = 1;
  vertex_input.pVertexBindingDescriptions = &vertex_binding;
  vertex_input.vertexAttributeDescriptionCount = static_cast<uint32_t>(attributes.size());
  vertex_input.pVertexAttributeDescriptions = attributes.data();
  if (!CreatePointPipeline(d, {stages.begin(), stages.end()}, vertex_input, count,
                           /*rasterizer_discard=*/false, p->layout, render_pass, &p->pipeline,
                           error)) {
    p->pipeline = VK_NULL_HANDLE;
    return false;
  }
  return true;
}

}  // namespace arbiter::runtime::vulkan
