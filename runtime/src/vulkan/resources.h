// The memory objects of one vulkan-spirv run: host-visible buffers (vertices, uniform blocks,
// readback), RGBA32F colour attachments, and the model's textures as sampled images with
// their samplers, framebuffers and descriptor sets. A Resources destroys everything it made.
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <string>
#include <vector>

#include "arbiter/arbvp/exec.h"
#include "vulkan/device.h"

namespace arbiter::runtime::vulkan {

// A buffer in host-visible, coherent memory, mapped at `data`.
struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
  void* data = nullptr;
};

// An image with its memory, one view and (textures) a sampler.
struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
};

// The format of colour attachments and colour textures.
inline constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

// What an image is: its type, its view's type, format, size and layers (a cube's six faces).
struct ImageShape {
  VkImageType type = VK_IMAGE_TYPE_2D;
  VkImageViewType view = VK_IMAGE_VIEW_TYPE_2D;
  VkFormat format = kColorFormat;
  VkExtent3D extent{1, 1, 1};
  uint32_t layers = 1;
};

class Resources {
 public:
  explicit Resources(const Device& device) : device_(device) {}
  Resources(const Resources&) = delete;
  Resources& operator=(const Resources&) = delete;
  ~Resources();

  // A zeroed buffer of `size` bytes for `usage`; null (with `error`) on failure.
  Buffer* CreateBuffer(VkDeviceSize size, VkBufferUsageFlags usage, std::string* error);
  // A width x height RGBA32F colour attachment that can be copied from.
  Image* CreateAttachment(int width, int height, std::string* error);
  // `texture` uploaded (one level; a RECT texture as a 2D image, which a translation that
  // emulates RECT samplers reads with normalised coordinates), sampled as the model says: its
  // filter and wrap, and for a `shadow` sampler a depth comparison by its compare function.
  // A depth texture is D32_SFLOAT (the red channel of each texel); read through a sampler
  // that does not compare, its view spreads the depth as its depth mode says.
  Image* CreateTexture(const arbvp::Texture& texture, bool shadow, std::string* error);
  // A framebuffer of `views` for `render_pass`; VK_NULL_HANDLE (with `error`) on failure.
  VkFramebuffer CreateFramebuffer(VkRenderPass render_pass, const std::vector<VkImageView>& views,
                                  int width, int height, std::string* error);
  // A descriptor set of `layout` from a pool of its own with room for `uniform_buffers`,
  // `samplers` and `storage_buffers`; VK_NULL_HANDLE (with `error`) on failure.
  VkDescriptorSet AllocateSet(VkDescriptorSetLayout layout, uint32_t uniform_buffers,
                              uint32_t samplers, std::string* error, uint32_t storage_buffers = 0);

 private:
  bool Allocate(VkMemoryRequirements needs, VkMemoryPropertyFlags flags, VkDeviceMemory* memory,
                std::string* error);
  // A single-level image of `shape` in device-local memory, without a view yet.
  Image* CreateImage(const ImageShape& shape, VkImageUsageFlags usage, std::string* error);
  [[nodiscard]] bool CreateView(const ImageShape& shape, VkComponentMapping components,
                                Image* image, std::string* error);
  // `texture`'s texels copied to `image` (a depth format takes the red channel), left in
  // SHADER_READ_ONLY_OPTIMAL.
  [[nodiscard]] bool Upload(const arbvp::Texture& texture, const ImageShape& shape, VkImage image,
                            std::string* error);

  const Device& device_;
  std::vector<std::unique_ptr<Buffer>> buffers_;
  std::vector<std::unique_ptr<Image>> images_;
  std::vector<VkFramebuffer> framebuffers_;
  std::vector<VkDescriptorPool> pools_;
};

}  // namespace arbiter::runtime::vulkan
