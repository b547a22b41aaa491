// Presentation: GLFW surface, swapchain (recreated on resize / out of date), and a blit of a HAL
// image into the acquired swapchain image, on the device's one queue.
#include <vulkan/vulkan.h>
// GLFW declares its Vulkan entry points only after the Vulkan header.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <array>

#include "check.hpp"
#include "command_list.hpp"
#include "device.hpp"
#include "hal/layer.hpp"
#include "hal_vulkan/presenter.hpp"

namespace hal::vulkan {

std::vector<std::string> glfw_instance_extensions() {
  if (!glfwVulkanSupported())
    throw Error(ErrorKind::Unsupported, "GLFW", "GLFW found no Vulkan loader (or glfwInit was not called)");
  std::uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names) throw Error(ErrorKind::Unsupported, "GLFW", "GLFW knows no Vulkan surface extension for this platform");
  return std::vector<std::string>(names, names + count);
}

namespace {
constexpr std::uint32_t kFramesInFlight = 2;
}

struct Presenter::Impl {
  VulkanDevice& device;
  GLFWwindow* window;
  bool vsync;
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  VkSwapchainKHR swapchain = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkExtent2D extent{0, 0};
  std::vector<VkImage> images;
  std::vector<VkSemaphore> present_ready;  // per swapchain image: blit done, may present
  struct Frame {
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence done = VK_NULL_HANDLE;
    VkSemaphore acquired = VK_NULL_HANDLE;
  };
  std::array<Frame, kFramesInFlight> frames{};
  std::uint32_t frame = 0;
  std::uint32_t generation = 0;

  Impl(VulkanDevice& d, GLFWwindow* w, bool v) : device(d), window(w), vsync(v) {}

  VkDevice vk() const { return device.device(); }

  void destroy_swapchain_images() {
    for (auto s : present_ready) vkDestroySemaphore(vk(), s, nullptr);
    present_ready.clear();
    images.clear();
  }

  // (Re)creates the swapchain for the window's current framebuffer size; false when it is zero.
  bool create_swapchain() {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    if (width <= 0 || height <= 0) return false;
    device.check_result(vkQueueWaitIdle(device.queue()), "vkQueueWaitIdle", "presenter");

    VkSurfaceCapabilitiesKHR caps;
    device.check_result(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(device.physical(), surface, &caps),
                        "vkGetPhysicalDeviceSurfaceCapabilitiesKHR", "presenter");
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
      throw Error(ErrorKind::Unsupported, "presenter", "swapchain images cannot be transfer destinations");
    VkExtent2D size = caps.currentExtent;
    if (size.width == 0xFFFFFFFFu) {
      size.width = std::clamp(static_cast<std::uint32_t>(width), caps.minImageExtent.width, caps.maxImageExtent.width);
      size.height =
          std::clamp(static_cast<std::uint32_t>(height), caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    if (size.width == 0 || size.height == 0) return false;

    std::uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(device.physical(), surface, &count, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(device.physical(), surface, &count, formats.data());
    if (formats.empty()) throw Error(ErrorKind::Unsupported, "presenter", "the surface reports no formats");
    // UNORM: the composite pass writes display-encoded values; the blit must not re-encode them.
    VkSurfaceFormatKHR chosen = formats.front();
    for (const auto& f : formats)
      if ((f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) &&
          f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) {
        chosen = f;
        break;
      }
    vkGetPhysicalDeviceSurfacePresentModesKHR(device.physical(), surface, &count, nullptr);
    std::vector<VkPresentModeKHR> modes(count);
    vkGetPhysicalDeviceSurfacePresentModesKHR(device.physical(), surface, &count, modes.data());
    VkPresentModeKHR mode = VK_PRESENT_MODE_FIFO_KHR;  // always available
    if (!vsync)
      for (VkPresentModeKHR want : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
        if (std::find(modes.begin(), modes.end(), want) != modes.end()) {
          mode = want;
          break;
        }

    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface;
    info.minImageCount =
        caps.maxImageCount ? std::min(caps.minImageCount + 1, caps.maxImageCount) : caps.minImageCount + 1;
    info.imageFormat = chosen.format;
    info.imageColorSpace = chosen.colorSpace;
    info.imageExtent = size;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                              ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                              : static_cast<VkCompositeAlphaFlagBitsKHR>(caps.supportedCompositeAlpha &
                                                                         (~caps.supportedCompositeAlpha + 1));
    info.presentMode = mode;
    info.clipped = VK_TRUE;
    info.oldSwapchain = swapchain;
    VkSwapchainKHR created = VK_NULL_HANDLE;
    device.check_result(vkCreateSwapchainKHR(vk(), &info, nullptr, &created), "vkCreateSwapchainKHR", "presenter");
    if (swapchain) vkDestroySwapchainKHR(vk(), swapchain, nullptr);
    swapchain = created;
    destroy_swapchain_images();
    format = chosen.format;
    extent = size;
    vkGetSwapchainImagesKHR(vk(), swapchain, &count, nullptr);
    images.resize(count);
    vkGetSwapchainImagesKHR(vk(), swapchain, &count, images.data());
    for (std::uint32_t i = 0; i < count; ++i) {
      VkSemaphoreCreateInfo sem{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
      VkSemaphore s = VK_NULL_HANDLE;
      device.check_result(vkCreateSemaphore(vk(), &sem, nullptr, &s), "vkCreateSemaphore", "presenter");
      present_ready.push_back(s);
    }
    ++generation;
    return true;
  }
};

Presenter::Presenter(hal::Device& device, GLFWwindow* window, bool vsync) {
  // A device behind the validation layer presents through the Vulkan device it wraps.
  auto* vulkan = dynamic_cast<VulkanDevice*>(&hal::backend_of(device));
  if (!vulkan) throw Error(ErrorKind::InvalidUsage, "presenter", "the device is not a Vulkan device");
  if (!window) throw Error(ErrorKind::InvalidUsage, "presenter", "no window");
  if (!vulkan->swapchain_enabled())
    throw Error(ErrorKind::Unsupported, "presenter",
                "the device was created without window-system extensions (DeviceOptions::instance_extensions = "
                "glfw_instance_extensions()) or lacks VK_KHR_swapchain");
  impl_ = std::make_unique<Impl>(*vulkan, window, vsync);
  Impl& p = *impl_;
  p.device.check_result(glfwCreateWindowSurface(vulkan->instance(), window, nullptr, &p.surface),
                        "glfwCreateWindowSurface", "presenter");
  VkBool32 supported = VK_FALSE;
  vkGetPhysicalDeviceSurfaceSupportKHR(vulkan->physical(), vulkan->queue_family(), p.surface, &supported);
  if (!supported) {
    vkDestroySurfaceKHR(vulkan->instance(), p.surface, nullptr);
    throw Error(ErrorKind::Unsupported, "presenter", "the device's queue cannot present to this window");
  }
  for (auto& f : p.frames) {
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pool.queueFamilyIndex = vulkan->queue_family();
    p.device.check_result(vkCreateCommandPool(p.vk(), &pool, nullptr, &f.pool), "vkCreateCommandPool", "presenter");
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = f.pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    p.device.check_result(vkAllocateCommandBuffers(p.vk(), &alloc, &f.cmd), "vkAllocateCommandBuffers", "presenter");
    VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    p.device.check_result(vkCreateFence(p.vk(), &fence, nullptr, &f.done), "vkCreateFence", "presenter");
    VkSemaphoreCreateInfo sem{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    p.device.check_result(vkCreateSemaphore(p.vk(), &sem, nullptr, &f.acquired), "vkCreateSemaphore", "presenter");
  }
}

Presenter::~Presenter() {
  if (!impl_) return;
  Impl& p = *impl_;
  vkQueueWaitIdle(p.device.queue());
  for (auto& f : p.frames) {
    if (f.done) vkDestroyFence(p.vk(), f.done, nullptr);
    if (f.acquired) vkDestroySemaphore(p.vk(), f.acquired, nullptr);
    if (f.pool) vkDestroyCommandPool(p.vk(), f.pool, nullptr);
  }
  p.destroy_swapchain_images();
  if (p.swapchain) vkDestroySwapchainKHR(p.vk(), p.swapchain, nullptr);
  if (p.surface) vkDestroySurfaceKHR(p.device.instance(), p.surface, nullptr);
}

std::pair<std::uint32_t, std::uint32_t> Presenter::extent() const {
  return {impl_->extent.width, impl_->extent.height};
}
std::uint32_t Presenter::swapchain_generation() const {
  return impl_->generation;
}

bool Presenter::present(hal::ImageHandle handle) {
  Impl& p = *impl_;
  p.device.check_alive();
  const ImageObject& source = p.device.images.get(handle.id, "image");
  if (!has(source.desc.usage, ImageUsage::CopySrc))
    throw Error(ErrorKind::InvalidUsage, source.name, "presented images need CopySrc usage");
  const Format f = source.desc.format;
  if (format_is_uint(f))
    throw Error(ErrorKind::InvalidUsage, source.name, "integer images cannot be blitted to the window");

  // Resize: recreate when the framebuffer no longer matches the swapchain.
  int width = 0, height = 0;
  glfwGetFramebufferSize(p.window, &width, &height);
  if (width <= 0 || height <= 0) return false;
  if (!p.swapchain || static_cast<std::uint32_t>(width) != p.extent.width ||
      static_cast<std::uint32_t>(height) != p.extent.height)
    if (!p.create_swapchain()) return false;

  Impl::Frame& frame = p.frames[p.frame];
  p.device.check_result(vkWaitForFences(p.vk(), 1, &frame.done, VK_TRUE, UINT64_MAX), "vkWaitForFences", "presenter");
  std::uint32_t index = 0;
  VkResult acquired = vkAcquireNextImageKHR(p.vk(), p.swapchain, UINT64_MAX, frame.acquired, VK_NULL_HANDLE, &index);
  if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
    if (!p.create_swapchain()) return false;
    acquired = vkAcquireNextImageKHR(p.vk(), p.swapchain, UINT64_MAX, frame.acquired, VK_NULL_HANDLE, &index);
  }
  if (acquired != VK_SUBOPTIMAL_KHR) p.device.check_result(acquired, "vkAcquireNextImageKHR", "presenter");
  p.device.check_result(vkResetFences(p.vk(), 1, &frame.done), "vkResetFences", "presenter");

  p.device.check_result(vkResetCommandPool(p.vk(), frame.pool, 0), "vkResetCommandPool", "presenter");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  p.device.check_result(vkBeginCommandBuffer(frame.cmd, &begin), "vkBeginCommandBuffer", "presenter");
  VkImageMemoryBarrier2 to_dst{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  // Waits on the acquire semaphore at the blit stage, so the layout change starts there too.
  to_dst.srcStageMask = VK_PIPELINE_STAGE_2_BLIT_BIT;
  to_dst.dstStageMask = VK_PIPELINE_STAGE_2_BLIT_BIT;
  to_dst.dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  to_dst.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  to_dst.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  to_dst.srcQueueFamilyIndex = to_dst.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  to_dst.image = p.images[index];
  to_dst.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.imageMemoryBarrierCount = 1;
  dep.pImageMemoryBarriers = &to_dst;
  vkCmdPipelineBarrier2(frame.cmd, &dep);
  VkImageBlit blit{};
  blit.srcSubresource = blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.srcOffsets[1] = {static_cast<std::int32_t>(source.desc.width), static_cast<std::int32_t>(source.desc.height), 1};
  blit.dstOffsets[1] = {static_cast<std::int32_t>(p.extent.width), static_cast<std::int32_t>(p.extent.height), 1};
  vkCmdBlitImage(frame.cmd, source.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, p.images[index],
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
  VkImageMemoryBarrier2 to_present = to_dst;
  to_present.srcStageMask = VK_PIPELINE_STAGE_2_BLIT_BIT;
  to_present.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  to_present.dstStageMask = VK_PIPELINE_STAGE_2_NONE;
  to_present.dstAccessMask = VK_ACCESS_2_NONE;
  to_present.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  to_present.newLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  dep.pImageMemoryBarriers = &to_present;
  vkCmdPipelineBarrier2(frame.cmd, &dep);
  p.device.check_result(vkEndCommandBuffer(frame.cmd), "vkEndCommandBuffer", "presenter");

  VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  wait.semaphore = frame.acquired;
  wait.stageMask = VK_PIPELINE_STAGE_2_BLIT_BIT;
  VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  signal.semaphore = p.present_ready[index];
  signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkCommandBufferSubmitInfo cmd_info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmd_info.commandBuffer = frame.cmd;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.waitSemaphoreInfoCount = 1;
  submit.pWaitSemaphoreInfos = &wait;
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmd_info;
  submit.signalSemaphoreInfoCount = 1;
  submit.pSignalSemaphoreInfos = &signal;
  p.device.check_result(vkQueueSubmit2(p.device.queue(), 1, &submit, frame.done), "vkQueueSubmit2", "presenter");

  VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &p.present_ready[index];
  present.swapchainCount = 1;
  present.pSwapchains = &p.swapchain;
  present.pImageIndices = &index;
  const VkResult presented = vkQueuePresentKHR(p.device.queue(), &present);
  p.frame = (p.frame + 1) % kFramesInFlight;
  if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR || acquired == VK_SUBOPTIMAL_KHR) {
    p.create_swapchain();  // next present uses the new one
    return true;
  }
  p.device.check_result(presented, "vkQueuePresentKHR", "presenter");
  return true;
}

}  // namespace hal::vulkan
