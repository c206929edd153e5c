// The Vulkan device: see device.h.
#include "vulkan/device.h"

#include <fmt/format.h>

#include <vector>

namespace arbiter::runtime::vulkan {

bool Check(VkResult result, const char* step, std::string* error) {
  if (result == VK_SUCCESS) return true;
  *error = fmt::format("vulkan: {} failed (VkResult {})", step, static_cast<int>(result));
  return false;
}

Device::~Device() {
  if (device_ != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device_);
    if (pool_ != VK_NULL_HANDLE) vkDestroyCommandPool(device_, pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
}

bool Device::Create(const std::string& name_prefix, std::string* error) {
  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "arbiter";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo instance_info{};
  instance_info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  instance_info.pApplicationInfo = &app;
  if (!Check(vkCreateInstance(&instance_info, nullptr, &instance_), "vkCreateInstance", error)) {
    instance_ = VK_NULL_HANDLE;
    return false;
  }
  uint32_t count = 0;
  if (!Check(vkEnumeratePhysicalDevices(instance_, &count, nullptr), "vkEnumeratePhysicalDevices",
             error)) {
    return false;
  }
  std::vector<VkPhysicalDevice> devices(count);
  if (!Check(vkEnumeratePhysicalDevices(instance_, &count, devices.data()),
             "vkEnumeratePhysicalDevices", error)) {
    return false;
  }
  std::string names;
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties p{};
    vkGetPhysicalDeviceProperties(d, &p);
    const std::string name = p.deviceName;
    names += (names.empty() ? "" : ", ") + name;
    if (physical_ == VK_NULL_HANDLE && name.rfind(name_prefix, 0) == 0) {
      physical_ = d;
      properties_ = p;
    }
  }
  if (physical_ == VK_NULL_HANDLE) {
    *error = fmt::format("the Vulkan loader offers no '{}' device (found: {})", name_prefix,
                         names.empty() ? "none" : names);
    return false;
  }
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
  uint32_t families = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &families, nullptr);
  std::vector<VkQueueFamilyProperties> family_properties(families);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &families, family_properties.data());
  uint32_t family = families;
  for (uint32_t i = 0; i < families && family == families; ++i) {
    if (family_properties[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) family = i;
  }
  if (family == families) {
    *error = fmt::format("{} has no graphics queue", properties_.deviceName);
    return false;
  }
  // Every feature the device has: the translation may write gl_ClipDistance, for one.
  VkPhysicalDeviceFeatures features{};
  vkGetPhysicalDeviceFeatures(physical_, &features);
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{};
  queue_info.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  queue_info.queueFamilyIndex = family;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  VkDeviceCreateInfo device_info{};
  device_info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  device_info.queueCreateInfoCount = 1;
  device_info.pQueueCreateInfos = &queue_info;
  device_info.pEnabledFeatures = &features;
  if (!Check(vkCreateDevice(physical_, &device_info, nullptr, &device_), "vkCreateDevice", error)) {
    device_ = VK_NULL_HANDLE;
    return false;
  }
  vkGetDeviceQueue(device_, family, 0, &queue_);
  VkCommandPoolCreateInfo pool_info{};
  pool_info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  pool_info.queueFamilyIndex = family;
  if (!Check(vkCreateCommandPool(device_, &pool_info, nullptr, &pool_), "vkCreateCommandPool",
             error)) {
    pool_ = VK_NULL_HANDLE;
    return false;
  }
  description_ = fmt::format("{}, Vulkan {}.{} (lavapipe)", properties_.deviceName,
                             VK_API_VERSION_MAJOR(properties_.apiVersion),
                             VK_API_VERSION_MINOR(properties_.apiVersion));
  return true;
}

int Device::MemoryType(uint32_t type_bits, VkMemoryPropertyFlags flags) const {
  for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    if ((type_bits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & flags) == flags) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

VkCommandBuffer Device::BeginCommands(std::string* error) const {
  VkCommandBufferAllocateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  info.commandPool = pool_;
  info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  info.commandBufferCount = 1;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  if (!Check(vkAllocateCommandBuffers(device_, &info, &commands), "vkAllocateCommandBuffers",
             error)) {
    return VK_NULL_HANDLE;
  }
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  if (!Check(vkBeginCommandBuffer(commands, &begin), "vkBeginCommandBuffer", error)) {
    vkFreeCommandBuffers(device_, pool_, 1, &commands);
    return VK_NULL_HANDLE;
  }
  return commands;
}

bool Device::Submit(VkCommandBuffer commands, std::string* error) const {
  bool ok = Check(vkEndCommandBuffer(commands), "vkEndCommandBuffer", error);
  if (ok) {
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    ok = Check(vkQueueSubmit(queue_, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit", error) &&
         Check(vkQueueWaitIdle(queue_), "vkQueueWaitIdle", error);
  }
  vkFreeCommandBuffers(device_, pool_, 1, &commands);
  return ok;
}

}  // namespace arbiter::runtime::vulkan
