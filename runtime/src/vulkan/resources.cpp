// The memory objects of one run: see resources.h.
#include "vulkan/resources.h"

#include <fmt/format.h>

#include <cstring>

namespace arbiter::runtime::vulkan {
namespace {

VkSamplerAddressMode AddressMode(arbvp::TexWrap wrap) {
  switch (wrap) {
    case arbvp::TexWrap::Repeat:
      return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    case arbvp::TexWrap::ClampToEdge:
      return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    case arbvp::TexWrap::MirroredRepeat:
      return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
  }
  return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

VkCompareOp CompareOp(arbvp::CompareFunc func) {
  switch (func) {
    case arbvp::CompareFunc::Never:
      return VK_COMPARE_OP_NEVER;
    case arbvp::CompareFunc::Less:
      return VK_COMPARE_OP_LESS;
    case arbvp::CompareFunc::Equal:
      return VK_COMPARE_OP_EQUAL;
    case arbvp::CompareFunc::Lequal:
      return VK_COMPARE_OP_LESS_OR_EQUAL;
    case arbvp::CompareFunc::Greater:
      return VK_COMPARE_OP_GREATER;
    case arbvp::CompareFunc::Notequal:
      return VK_COMPARE_OP_NOT_EQUAL;
    case arbvp::CompareFunc::Gequal:
      return VK_COMPARE_OP_GREATER_OR_EQUAL;
    case arbvp::CompareFunc::Always:
      return VK_COMPARE_OP_ALWAYS;
  }
  return VK_COMPARE_OP_LESS_OR_EQUAL;
}

// GL_DEPTH_TEXTURE_MODE as a view's swizzle of the depth in R: LUMINANCE (d, d, d, 1),
// INTENSITY (d, d, d, d), ALPHA (0, 0, 0, d).
VkComponentMapping DepthSwizzle(arbvp::DepthMode mode) {
  constexpr VkComponentSwizzle kR = VK_COMPONENT_SWIZZLE_R;
  switch (mode) {
    case arbvp::DepthMode::Luminance:
      return {kR, kR, kR, VK_COMPONENT_SWIZZLE_ONE};
    case arbvp::DepthMode::Intensity:
      return {kR, kR, kR, kR};
    case arbvp::DepthMode::Alpha:
      return {VK_COMPONENT_SWIZZLE_ZERO, VK_COMPONENT_SWIZZLE_ZERO, VK_COMPONENT_SWIZZLE_ZERO, kR};
  }
  return {kR, kR, kR, VK_COMPONENT_SWIZZLE_ONE};
}

VkImageAspectFlags AspectOf(VkFormat format) {
  return format == VK_FORMAT_D32_SFLOAT ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

// The image of texture `t`: RGBA32F, or D32_SFLOAT when `depth`.
bool ShapeOf(const arbvp::Texture& t, bool depth, ImageShape* shape, std::string* error) {
  const auto w = static_cast<uint32_t>(t.width);
  const auto h = static_cast<uint32_t>(t.height);
  const VkFormat format = depth ? VK_FORMAT_D32_SFLOAT : kColorFormat;
  switch (t.dim) {
    case arbvp::TexDim::Tex1D:
      *shape = {VK_IMAGE_TYPE_1D, VK_IMAGE_VIEW_TYPE_1D, format, {w, 1, 1}, 1};
      return true;
    case arbvp::TexDim::Tex2D:
    case arbvp::TexDim::Rect:  // a translation that emulates RECT reads a 2D sampler
      *shape = {VK_IMAGE_TYPE_2D, VK_IMAGE_VIEW_TYPE_2D, format, {w, h, 1}, 1};
      return true;
    case arbvp::TexDim::Tex3D:
      *shape = {VK_IMAGE_TYPE_3D,
                VK_IMAGE_VIEW_TYPE_3D,
                format,
                {w, h, static_cast<uint32_t>(t.depth)},
                1};
      return true;
    case arbvp::TexDim::Cube:
      *shape = {VK_IMAGE_TYPE_2D, VK_IMAGE_VIEW_TYPE_CUBE, format, {w, h, 1}, 6};
      return true;
  }
  *error = "vulkan: a texture of no known dimension";
  return false;
}

// A barrier moving every layer of `image` from one layout to another.
void Transition(VkCommandBuffer commands, VkImage image, VkImageAspectFlags aspect, uint32_t layers,
                VkImageLayout from, VkImageLayout to, VkAccessFlags src_access,
                VkAccessFlags dst_access, VkPipelineStageFlags src_stage,
                VkPipelineStageFlags dst_stage) {
  VkImageMemoryBarrier barrier{};
  barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
  barrier.srcAccessMask = src_access;
  barrier.dstAccessMask = dst_access;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {aspect, 0, 1, 0, layers};
  vkCmdPipelineBarrier(commands, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

}  // namespace

Resources::~Resources() {
  const VkDevice d = device_.device();
  for (VkDescriptorPool p : pools_) vkDestroyDescriptorPool(d, p, nullptr);
  for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(d, f, nullptr);
  for (const auto& b : buffers_) {
    if (b->buffer != VK_NULL_HANDLE) vkDestroyBuffer(d, b->buffer, nullptr);
    if (b->memory != VK_NULL_HANDLE) vkFreeMemory(d, b->memory, nullptr);
  }
  for (const auto& i : images_) {
    if (i->sampler != VK_NULL_HANDLE) vkDestroySampler(d, i->sampler, nullptr);
    if (i->view != VK_NULL_HANDLE) vkDestroyImageView(d, i->view, nullptr);
    if (i->image != VK_NULL_HANDLE) vkDestroyImage(d, i->image, nullptr);
    if (i->memory != VK_NULL_HANDLE) vkFreeMemory(d, i->memory, nullptr);
  }
}

bool Resources::Allocate(VkMemoryRequirements needs, VkMemoryPropertyFlags flags,
                         VkDeviceMemory* memory, std::string* error) {
  const int type = device_.MemoryType(needs.memoryTypeBits, flags);
  if (type < 0) {
    *error = "vulkan: no memory type fits";
    return false;
  }
  VkMemoryAllocateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  info.allocationSize = needs.size;
  info.memoryTypeIndex = static_cast<uint32_t>(type);
  return Check(vkAllocateMemory(device_.device(), &info, nullptr, memory), "vkAllocateMemory",
               error);
}

Buffer* Resources::CreateBuffer(VkDeviceSize size, VkBufferUsageFlags usage, std::string* error) {
  const VkDevice d = device_.device();
  Buffer* b = buffers_.emplace_back(std::make_unique<Buffer>()).get();
  b->size = size;
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  if (!Check(vkCreateBuffer(d, &info, nullptr, &b->buffer), "vkCreateBuffer", error)) {
    b->buffer = VK_NULL_HANDLE;
    return nullptr;
  }
  VkMemoryRequirements needs{};
  vkGetBufferMemoryRequirements(d, b->buffer, &needs);
  if (!Allocate(needs, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                &b->memory, error) ||
      !Check(vkBindBufferMemory(d, b->buffer, b->memory, 0), "vkBindBufferMemory", error) ||
      !Check(vkMapMemory(d, b->memory, 0, VK_WHOLE_SIZE, 0, &b->data), "vkMapMemory", error)) {
    return nullptr;
  }
  std::memset(b->data, 0, static_cast<size_t>(size));
  return b;
}

Image* Resources::CreateImage(const ImageShape& shape, VkImageUsageFlags usage,
                              std::string* error) {
  const VkDevice d = device_.device();
  Image* i = images_.emplace_back(std::make_unique<Image>()).get();
  VkImageCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
  info.flags = shape.view == VK_IMAGE_VIEW_TYPE_CUBE ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
  info.imageType = shape.type;
  info.format = shape.format;
  info.extent = shape.extent;
  info.mipLevels = 1;
  info.arrayLayers = shape.layers;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  if (!Check(vkCreateImage(d, &info, nullptr, &i->image), "vkCreateImage", error)) {
    i->image = VK_NULL_HANDLE;
    return nullptr;
  }
  VkMemoryRequirements needs{};
  vkGetImageMemoryRequirements(d, i->image, &needs);
  if (!Allocate(needs, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, &i->memory, error) ||
      !Check(vkBindImageMemory(d, i->image, i->memory, 0), "vkBindImageMemory", error)) {
    return nullptr;
  }
  return i;
}

bool Resources::CreateView(const ImageShape& shape, VkComponentMapping components, Image* i,
                           std::string* error) {
  VkImageViewCreateInfo view{};
  view.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
  view.image = i->image;
  view.viewType = shape.view;
  view.format = shape.format;
  view.components = components;
  view.subresourceRange = {AspectOf(shape.format), 0, 1, 0, shape.layers};
  if (!Check(vkCreateImageView(device_.device(), &view, nullptr, &i->view), "vkCreateImageView",
             error)) {
    i->view = VK_NULL_HANDLE;
    return false;
  }
  return true;
}

Image* Resources::CreateAttachment(int width, int height, std::string* error) {
  const ImageShape shape{VK_IMAGE_TYPE_2D,
                         VK_IMAGE_VIEW_TYPE_2D,
                         kColorFormat,
                         {static_cast<uint32_t>(width), static_cast<uint32_t>(height), 1},
                         1};
  Image* i = CreateImage(
      shape, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, error);
  return i != nullptr && CreateView(shape, {}, i, error) ? i : nullptr;
}

bool Resources::Upload(const arbvp::Texture& t, const ImageShape& shape, VkImage image,
                       std::string* error) {
  const size_t texels = static_cast<size_t>(shape.extent.width) * shape.extent.height *
                        shape.extent.depth * shape.layers;
  const bool depth = shape.format == VK_FORMAT_D32_SFLOAT;
  Buffer* staging = CreateBuffer(texels * (depth ? 1 : 4) * sizeof(float),
                                 VK_BUFFER_USAGE_TRANSFER_SRC_BIT, error);
  if (staging == nullptr) return false;
  auto* data = static_cast<float*>(staging->data);
  if (depth) {
    for (size_t i = 0; i < texels; ++i) data[i] = t.texels[i * 4];  // the red channel
  } else {
    std::memcpy(data, t.texels.data(), texels * 4 * sizeof(float));
  }
  const VkImageAspectFlags aspect = AspectOf(shape.format);
  VkCommandBuffer commands = device_.BeginCommands(error);
  if (commands == VK_NULL_HANDLE) return false;
  Transition(commands, image, aspect, shape.layers, VK_IMAGE_LAYOUT_UNDEFINED,
             VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
             VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  VkBufferImageCopy copy{};
  copy.imageSubresource = {aspect, 0, 0, shape.layers};
  copy.imageExtent = shape.extent;
  vkCmdCopyBufferToImage(commands, staging->buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                         &copy);
  Transition(commands, image, aspect, shape.layers, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
             VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
             VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
             VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
  return device_.Submit(commands, error);
}

Image* Resources::CreateTexture(const arbvp::Texture& t, bool shadow, std::string* error) {
  const bool depth = shadow || t.depth_texture;
  ImageShape shape;
  if (!ShapeOf(t, depth, &shape, error)) return nullptr;
  if (t.width < 1 || t.height < 1 || t.depth < 1 ||
      t.texels.size() != static_cast<size_t>(shape.extent.width) * shape.extent.height *
                             shape.extent.depth * shape.layers * 4) {
    *error = fmt::format("vulkan: a texture of {} floats does not fit its size {}x{}x{}",
                         t.texels.size(), t.width, t.height, t.depth);
    return nullptr;
  }
  Image* i =
      CreateImage(shape, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, error);
  if (i == nullptr || !Upload(t, shape, i->image, error) ||
      !CreateView(shape, depth && !shadow ? DepthSwizzle(t.depth_mode) : VkComponentMapping{}, i,
                  error)) {
    return nullptr;
  }
  const VkFilter filter =
      t.filter == arbvp::TexFilter::Linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  VkSamplerCreateInfo sampler{};
  sampler.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
  sampler.magFilter = filter;
  sampler.minFilter = filter;
  sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  sampler.addressModeU = AddressMode(t.wrap);
  sampler.addressModeV = AddressMode(t.wrap);
  sampler.addressModeW = AddressMode(t.wrap);
  sampler.compareEnable = shadow ? VK_TRUE : VK_FALSE;
  sampler.compareOp = CompareOp(t.compare_func);
  sampler.minLod = 0.0f;
  sampler.maxLod = 0.0f;
  sampler.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
  if (!Check(vkCreateSampler(device_.device(), &sampler, nullptr, &i->sampler), "vkCreateSampler",
             error)) {
    i->sampler = VK_NULL_HANDLE;
    return nullptr;
  }
  return i;
}

VkFramebuffer Resources::CreateFramebuffer(VkRenderPass render_pass,
                                           const std::vector<VkImageView>& views, int width,
                                           int height, std::string* error) {
  VkFramebufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
  info.renderPass = render_pass;
  info.attachmentCount = static_cast<uint32_t>(views.size());
  info.pAttachments = views.data();
  info.width = static_cast<uint32_t>(width);
  info.height = static_cast<uint32_t>(height);
  info.layers = 1;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  if (!Check(vkCreateFramebuffer(device_.device(), &info, nullptr, &framebuffer),
             "vkCreateFramebuffer", error)) {
    return VK_NULL_HANDLE;
  }
  framebuffers_.push_back(framebuffer);
  return framebuffer;
}

VkDescriptorSet Resources::AllocateSet(VkDescriptorSetLayout layout, uint32_t uniform_buffers,
                                       uint32_t samplers, std::string* error,
                                       uint32_t storage_buffers) {
  std::vector<VkDescriptorPoolSize> sizes;
  if (storage_buffers > 0) sizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, storage_buffers});
  if (uniform_buffers > 0) sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, uniform_buffers});
  if (samplers > 0) sizes.push_back({VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, samplers});
  // A pool needs one size at least, even for a set without bindings.
  if (sizes.empty()) sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1});
  VkDescriptorPoolCreateInfo pool_info{};
  pool_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = static_cast<uint32_t>(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  if (!Check(vkCreateDescriptorPool(device_.device(), &pool_info, nullptr, &pool),
             "vkCreateDescriptorPool", error)) {
    return VK_NULL_HANDLE;
  }
  pools_.push_back(pool);
  VkDescriptorSetAllocateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  info.descriptorPool = pool;
  info.descriptorSetCount = 1;
  info.pSetLayouts = &layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  if (!Check(vkAllocateDescriptorSets(device_.device(), &info, &set), "vkAllocateDescriptorSets",
             error)) {
    return VK_NULL_HANDLE;
  }
  return set;
}

}  // namespace arbiter::runtime::vulkan
