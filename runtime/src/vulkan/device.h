// The Vulkan device of the vulkan-spirv engine: an instance through the Vulkan loader, the
// physical device of a Mesa driver (lavapipe: "llvmpipe (...)"), one graphics queue, a command
// pool, and one-shot command buffers submitted and waited for.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace arbiter::runtime::vulkan {

// False (with `error` naming `step` and the result) unless `result` is VK_SUCCESS.
[[nodiscard]] bool Check(VkResult result, const char* step, std::string* error);

class Device {
 public:
  Device() = default;
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;
  ~Device();

  // Creates the instance and a device on the first physical device whose name starts with
  // `name_prefix`. False (with `error`) when there is none or a step fails.
  [[nodiscard]] bool Create(const std::string& name_prefix, std::string* error);

  VkDevice device() const { return device_; }
  const VkPhysicalDeviceLimits& limits() const { return properties_.limits; }
  // "llvmpipe (LLVM 15.0.6, 256 bits), Vulkan 1.3 (lavapipe)".
  const std::string& description() const { return description_; }

  // The index of a memory type among `type_bits` with all of `flags`; -1 when none.
  int MemoryType(uint32_t type_bits, VkMemoryPropertyFlags flags) const;

  // A primary command buffer in the recording state (VK_NULL_HANDLE, with `error`, on failure).
  VkCommandBuffer BeginCommands(std::string* error) const;
  // Ends `commands`, submits them, waits for the queue and frees them.
  [[nodiscard]] bool Submit(VkCommandBuffer commands, std::string* error) const;

 private:
  VkInstance instance_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  std::string description_;
};

}  // namespace arbiter::runtime::vulkan
