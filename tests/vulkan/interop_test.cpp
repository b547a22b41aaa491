// Vulkan interop (hal_vulkan/interop.hpp) as a renderer with its own Vulkan objects uses it: this
// test creates its instance (validation and synchronization validation on, every message fails the
// test), device, queue, images and command buffer with raw Vulkan, renders a noisy ramp with its own
// compute shader, and in the same command buffer denoises it through the public API
// (asvgf::Denoiser on hal::vulkan::wrap_device, its images imported, recording into the wrapped
// command buffer), then copies the result out with raw Vulkan and checks it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "asvgf/denoiser.hpp"
#include "hal/error.hpp"
#include "hal_vulkan/interop.hpp"
#include "shaders/interop_noisy_gradient.hpp"

namespace {

constexpr std::uint32_t kWidth = 40, kHeight = 24;
constexpr VkFormat kFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

#define VK_OK(call) REQUIRE((call) == VK_SUCCESS)

VKAPI_ATTR VkBool32 VKAPI_CALL collect(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                                       const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  static_cast<std::vector<std::string>*>(user)->push_back(data->pMessage);
  return VK_FALSE;
}

// What a renderer owns: everything below is plain Vulkan, no HAL.
struct Renderer {
  std::vector<std::string> messages;
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  std::uint32_t family = 0;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
  };
  std::vector<Image> images;
  VkBuffer readback = VK_NULL_HANDLE;
  VkDeviceMemory readback_memory = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkDescriptorPool descriptors = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;

  std::uint32_t memory_type(std::uint32_t bits, VkMemoryPropertyFlags want) const {
    VkPhysicalDeviceMemoryProperties props;
    vkGetPhysicalDeviceMemoryProperties(physical, &props);
    for (std::uint32_t i = 0; i < props.memoryTypeCount; ++i)
      if ((bits & (1u << i)) && (props.memoryTypes[i].propertyFlags & want) == want) return i;
    FAIL("no memory type");
    return 0;
  }

  void create() {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.apiVersion = VK_API_VERSION_1_3;
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    const VkValidationFeatureEnableEXT sync = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = &sync;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, &features};
    info.pApplicationInfo = &app;
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &layer;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = &extension;
    VK_OK(vkCreateInstance(&info, nullptr, &instance));
    VkDebugUtilsMessengerCreateInfoEXT m{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    m.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    m.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
    m.pfnUserCallback = &collect;
    m.pUserData = &messages;
    auto create_messenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    REQUIRE(static_cast<bool>(create_messenger));
    VK_OK(create_messenger(instance, &m, nullptr, &messenger));

    std::uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> physicals(count);
    vkEnumeratePhysicalDevices(instance, &count, physicals.data());
    for (VkPhysicalDevice p : physicals) {
      VkPhysicalDeviceProperties props;
      vkGetPhysicalDeviceProperties(p, &props);
      if (props.apiVersion >= VK_API_VERSION_1_3) physical = p;
    }
    REQUIRE(physical);
    std::uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &families, nullptr);
    std::vector<VkQueueFamilyProperties> props(families);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &families, props.data());
    while (family < families && !(props[family].queueFlags & VK_QUEUE_COMPUTE_BIT)) ++family;
    REQUIRE(family < families);

    VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    v13.synchronization2 = VK_TRUE;
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue_info.queueFamilyIndex = family;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;
    VkDeviceCreateInfo device_info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &v13};
    device_info.queueCreateInfoCount = 1;
    device_info.pQueueCreateInfos = &queue_info;
    VK_OK(vkCreateDevice(physical, &device_info, nullptr, &device));
    vkGetDeviceQueue(device, family, 0, &queue);

    VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool_info.queueFamilyIndex = family;
    VK_OK(vkCreateCommandPool(device, &pool_info, nullptr, &pool));
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VK_OK(vkAllocateCommandBuffers(device, &alloc, &cmd));
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_OK(vkCreateFence(device, &fence_info, nullptr, &fence));

    // illumination, albedo, normal, depth, motion, radiance: RGBA32F, storage + sampled + transfer.
    for (int i = 0; i < 6; ++i) {
      Image img;
      VkImageCreateInfo ii{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
      ii.imageType = VK_IMAGE_TYPE_2D;
      ii.format = kFormat;
      ii.extent = {kWidth, kHeight, 1};
      ii.mipLevels = 1;
      ii.arrayLayers = 1;
      ii.samples = VK_SAMPLE_COUNT_1_BIT;
      ii.tiling = VK_IMAGE_TILING_OPTIMAL;
      ii.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                 VK_IMAGE_USAGE_TRANSFER_DST_BIT;
      VK_OK(vkCreateImage(device, &ii, nullptr, &img.image));
      VkMemoryRequirements req;
      vkGetImageMemoryRequirements(device, img.image, &req);
      VkMemoryAllocateInfo mi{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
      mi.allocationSize = req.size;
      mi.memoryTypeIndex = memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
      VK_OK(vkAllocateMemory(device, &mi, nullptr, &img.memory));
      VK_OK(vkBindImageMemory(device, img.image, img.memory, 0));
      VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
      vi.image = img.image;
      vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
      vi.format = kFormat;
      vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
      VK_OK(vkCreateImageView(device, &vi, nullptr, &img.view));
      images.push_back(img);
    }
    VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bi.size = VkDeviceSize{kWidth} * kHeight * 16;
    bi.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    VK_OK(vkCreateBuffer(device, &bi, nullptr, &readback));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device, readback, &req);
    VkMemoryAllocateInfo mi{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    mi.allocationSize = req.size;
    mi.memoryTypeIndex =
        memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    VK_OK(vkAllocateMemory(device, &mi, nullptr, &readback_memory));
    VK_OK(vkBindBufferMemory(device, readback, readback_memory, 0));

    // The renderer's own compute pipeline: one storage image.
    VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo sli{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    sli.bindingCount = 1;
    sli.pBindings = &binding;
    VK_OK(vkCreateDescriptorSetLayout(device, &sli, nullptr, &set_layout));
    VkPipelineLayoutCreateInfo pli{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pli.setLayoutCount = 1;
    pli.pSetLayouts = &set_layout;
    VK_OK(vkCreatePipelineLayout(device, &pli, nullptr, &layout));
    const auto spirv = asvgf::shaders::interop_noisy_gradient.spirv;
    VkShaderModuleCreateInfo smi{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    smi.codeSize = spirv.size_bytes();
    smi.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    VK_OK(vkCreateShaderModule(device, &smi, nullptr, &module));
    VkComputePipelineCreateInfo cpi{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    cpi.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                 nullptr,
                 0,
                 VK_SHADER_STAGE_COMPUTE_BIT,
                 module,
                 "main",
                 nullptr};
    cpi.layout = layout;
    const VkResult made = vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &cpi, nullptr, &pipeline);
    vkDestroyShaderModule(device, module, nullptr);
    VK_OK(made);
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1};
    VkDescriptorPoolCreateInfo dpi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    dpi.maxSets = 1;
    dpi.poolSizeCount = 1;
    dpi.pPoolSizes = &size;
    VK_OK(vkCreateDescriptorPool(device, &dpi, nullptr, &descriptors));
    VkDescriptorSetAllocateInfo dsa{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    dsa.descriptorPool = descriptors;
    dsa.descriptorSetCount = 1;
    dsa.pSetLayouts = &set_layout;
    VK_OK(vkAllocateDescriptorSets(device, &dsa, &set));
    VkDescriptorImageInfo image_info{VK_NULL_HANDLE, images[0].view, VK_IMAGE_LAYOUT_GENERAL};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    write.pImageInfo = &image_info;
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
  }

  // Layout transition of image i with sync2 stages/accesses.
  void transition(std::size_t i, VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 src_stage,
                  VkAccessFlags2 src_access, VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = src_stage;
    b.srcAccessMask = src_access;
    b.dstStageMask = dst_stage;
    b.dstAccessMask = dst_access;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = images[i].image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);
  }

  void destroy() {
    if (!device) return;
    vkDeviceWaitIdle(device);
    for (auto& img : images) {
      vkDestroyImageView(device, img.view, nullptr);
      vkDestroyImage(device, img.image, nullptr);
      vkFreeMemory(device, img.memory, nullptr);
    }
    vkDestroyBuffer(device, readback, nullptr);
    vkFreeMemory(device, readback_memory, nullptr);
    vkDestroyDescriptorPool(device, descriptors, nullptr);
    vkDestroyPipeline(device, pipeline, nullptr);
    vkDestroyPipelineLayout(device, layout, nullptr);
    vkDestroyDescriptorSetLayout(device, set_layout, nullptr);
    vkDestroyFence(device, fence, nullptr);
    vkDestroyCommandPool(device, pool, nullptr);
    vkDestroyDevice(device, nullptr);
    auto destroy_messenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    destroy_messenger(instance, messenger, nullptr);
    vkDestroyInstance(instance, nullptr);
  }
};

double ramp(std::uint32_t x) {
  return (x + 0.5) / kWidth;
}

}  // namespace

TEST_CASE(
    "vulkan interop: a renderer's own VkDevice, images and command buffer denoise through the wrapper, validation "
    "silent") {
  Renderer r;
  r.create();
  enum { kIllumination, kAlbedo, kNormal, kDepth, kMotion, kRadiance };
  std::vector<float> out(std::size_t(kWidth) * kHeight * 4);
  {
    auto device = hal::vulkan::wrap_device({r.instance, r.physical, r.device, r.queue, r.family, false, false, true});
    const auto usage =
        hal::ImageUsage::Sampled | hal::ImageUsage::Storage | hal::ImageUsage::CopySrc | hal::ImageUsage::CopyDst;
    const char* names[] = {"illumination", "albedo", "normal", "depth", "motion", "radiance"};
    std::vector<hal::ImageHandle> hal_images;
    for (std::size_t i = 0; i < 6; ++i)
      hal_images.push_back(
          hal::vulkan::import_image(*device, r.images[i].image, kFormat, kWidth, kHeight, usage, names[i]));
    asvgf::Denoiser denoiser(*device, {.width = kWidth, .height = kHeight, .method = asvgf::DenoiseMethod::Svgf});

    for (int frame = 0; frame < 4; ++frame) {
      VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
      begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
      VK_OK(vkBeginCommandBuffer(r.cmd, &begin));
      // The renderer's frame: its shader writes the noisy ramp, clears fill the G-buffer (albedo 1,
      // normal facing the camera, depth 2, no motion), then everything is made visible to compute
      // shaders in GENERAL, as interop.hpp asks.
      const auto compute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
      const auto transfer = VK_PIPELINE_STAGE_2_CLEAR_BIT;
      const VkImageLayout before = frame == 0 ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_GENERAL;
      const VkAccessFlags2 read = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
      r.transition(kIllumination, before, VK_IMAGE_LAYOUT_GENERAL, compute, read, compute,
                   VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
      vkCmdBindPipeline(r.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, r.pipeline);
      vkCmdBindDescriptorSets(r.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, r.layout, 0, 1, &r.set, 0, nullptr);
      vkCmdDispatch(r.cmd, (kWidth + 7) / 8, (kHeight + 7) / 8, 1);
      const float fills[4][4] = {{1, 1, 1, 1}, {0, 0, -1, 0}, {2, 0, 0, 0}, {0, 0, 0, 0}};
      for (int i = 0; i < 4; ++i) {
        const std::size_t image = kAlbedo + static_cast<std::size_t>(i);
        r.transition(image, before, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, compute, read, transfer,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT);
        VkClearColorValue value;
        std::memcpy(value.float32, fills[i], sizeof value.float32);
        const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(r.cmd, r.images[image].image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &value, 1, &range);
        r.transition(image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL, transfer,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT, compute, read);
      }
      r.transition(kIllumination, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL, compute,
                   VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, compute, read);

      // The denoiser, recorded into the same command buffer.
      auto commands = hal::vulkan::wrap_command_buffer(*device, r.cmd, "denoise");
      const auto F = hal::Format::RGBA32F;
      const auto in = hal::State::ShaderRead;  // GENERAL, the renderer's writes visible to compute
      denoiser.record(*commands,
                      {.illumination = {hal_images[kIllumination], F, in},
                       .albedo = {hal_images[kAlbedo], F, in},
                       .normal = {hal_images[kNormal], F, in},
                       .depth = {hal_images[kDepth], F, in},
                       .motion = {hal_images[kMotion], F, in}},
                      {.radiance = {hal_images[kRadiance], F, frame == 0 ? hal::State::Undefined : hal::State::CopySrc},
                       .final_state = hal::State::CopySrc});

      // The renderer reads the result back (the denoiser left it in TRANSFER_SRC_OPTIMAL, visible
      // to transfers).
      VkBufferImageCopy copy{};
      copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      copy.imageExtent = {kWidth, kHeight, 1};
      vkCmdCopyImageToBuffer(r.cmd, r.images[kRadiance].image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, r.readback, 1,
                             &copy);
      VK_OK(vkEndCommandBuffer(r.cmd));
      // The HAL refuses to submit the caller's command buffer.
      CHECK_THROWS_AS(device->submit(*commands), hal::Error);
      VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
      submit.commandBufferCount = 1;
      submit.pCommandBuffers = &r.cmd;
      VK_OK(vkQueueSubmit(r.queue, 1, &submit, r.fence));
      VK_OK(vkWaitForFences(r.device, 1, &r.fence, VK_TRUE, ~0ull));
      VK_OK(vkResetFences(r.device, 1, &r.fence));
      commands.reset();  // the GPU is done with this frame's uniforms
      VK_OK(vkResetCommandBuffer(r.cmd, 0));
    }
    void* mapped = nullptr;
    VK_OK(vkMapMemory(r.device, r.readback_memory, 0, VK_WHOLE_SIZE, 0, &mapped));
    std::memcpy(out.data(), mapped, out.size() * sizeof(float));
    vkUnmapMemory(r.device, r.readback_memory);
    for (auto h : hal_images) device->destroy(h);
  }

  // The noise is +-0.25 around the ramp; the denoised image follows the ramp far more closely and
  // keeps its slope (the filter must not flatten it).
  // Noise uniform in [-0.25, 0.25]: mean |noisy - ramp| = 0.125.
  const double noisy_error = 0.125;
  double error = 0, left = 0, right = 0;
  int left_n = 0, right_n = 0;
  bool finite = true;
  for (std::uint32_t y = 0; y < kHeight; ++y)
    for (std::uint32_t x = 0; x < kWidth; ++x) {
      const float v = out[(std::size_t(y) * kWidth + x) * 4];
      finite = finite && std::isfinite(v);
      error += std::abs(v - ramp(x)) / (kWidth * kHeight);
      if (x < kWidth / 3) left += v, ++left_n;
      if (x >= 2 * kWidth / 3) right += v, ++right_n;
    }
  CHECK(finite);
  MESSAGE("mean abs error " << error);
  CHECK_MESSAGE(error < noisy_error / 2, "mean |denoised - ramp| " << error << ", noisy " << noisy_error);
  // The ramp's thirds average about 1/6 and 5/6.
  CHECK(right / right_n - left / left_n > 0.5);
  for (const auto& m : r.messages) MESSAGE("validation: " << m);
  CHECK(r.messages.empty());
  r.destroy();
}
