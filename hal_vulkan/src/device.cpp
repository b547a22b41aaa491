// Device creation (adapter choice, extensions and features), submission, waiting, destruction.
#include "device.hpp"
#include "pipeline_stats.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "check.hpp"
#include "command_list.hpp"

namespace hal::vulkan {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool is_index(const std::string& text) {
  return !text.empty() && text.size() < 9 &&
         std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}

int type_rank(DeviceType type) {
  switch (type) {
    case DeviceType::DiscreteGpu:
      return 0;
    case DeviceType::IntegratedGpu:
      return 1;
    case DeviceType::VirtualGpu:
      return 2;
    case DeviceType::Cpu:
      return 3;
    default:
      return 4;
  }
}

std::string list_names(const std::vector<AdapterReport>& adapters) {
  std::string text;
  for (const auto& a : adapters) {
    if (!text.empty()) text += ", ";
    text += std::to_string(a.index) + ": " + a.info.name + " (" + std::string(to_string(a.info.type)) + ")";
  }
  return text;
}

bool has(const std::vector<std::string>& names, const char* name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

std::string describe_bytes(std::uint64_t bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB"};
  double value = static_cast<double>(bytes);
  int unit = 0;
  while (value >= 1024.0 && unit < 5) {
    value /= 1024.0;
    ++unit;
  }
  char text[64];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", value, units[unit]);
  return text;
}

std::uint32_t select_adapter(const std::vector<AdapterReport>& adapters, const std::string& wanted) {
  if (adapters.empty()) throw Error(ErrorKind::NoDevice, wanted, "there is no Vulkan adapter to choose from");
  if (wanted.empty()) {
    // Prefer real GPUs; among equals keep enumeration order. Devices without Vulkan 1.3 come last.
    std::uint32_t best = 0;
    auto rank = [](const AdapterReport& a) {
      unsigned major = 0, minor = 0;
      std::sscanf(a.info.api_version.c_str(), "Vulkan %u.%u", &major, &minor);
      const bool v13 = major > 1 || (major == 1 && minor >= 3);
      return type_rank(a.info.type) + (v13 ? 0 : 10);
    };
    for (std::uint32_t i = 1; i < adapters.size(); ++i)
      if (rank(adapters[i]) < rank(adapters[best])) best = i;
    return best;
  }
  if (is_index(wanted)) {
    const auto index = static_cast<std::uint32_t>(std::stoul(wanted));
    if (index < adapters.size()) return index;
    throw Error(ErrorKind::NoDevice, wanted,
                "there is no adapter with this index; available adapters are " + list_names(adapters));
  }
  const std::string needle = lower(wanted);
  for (std::uint32_t i = 0; i < adapters.size(); ++i)
    if (lower(adapters[i].info.name).find(needle) != std::string::npos) return i;
  throw Error(ErrorKind::NoDevice, wanted,
              "no adapter name contains this text; available adapters are " + list_names(adapters));
}

std::unique_ptr<hal::Device> create_device(const DeviceOptions& options) {
  return std::make_unique<VulkanDevice>(options);
}

VulkanDevice::VulkanDevice(const DeviceOptions& options) {
  InstanceOptions instance_options;
  instance_options.validation = options.validation;
  instance_options.extensions = options.instance_extensions;
  instance_options.on_message = options.on_validation_message;
  instance_ = std::make_unique<Instance>(instance_options);

  const auto physicals = instance_->physical_devices();
  std::vector<AdapterReport> reports;
  for (std::uint32_t i = 0; i < physicals.size(); ++i) reports.push_back(describe_adapter(physicals[i], i));
  std::string wanted = options.adapter;
  if (wanted.empty())
    if (const char* env = std::getenv(kAdapterEnvVar)) wanted = env;
  const std::uint32_t index = select_adapter(reports, wanted);
  physical_ = physicals[index];
  adapter_ = reports[index];

  read_limits();
  if (options.require_ray_query && !adapter_.capabilities.ray_query)
    throw Error(ErrorKind::Unsupported, adapter_.info.name,
                "ray queries were required but the adapter lacks VK_KHR_ray_query / VK_KHR_acceleration_structure");

  create_logical_device(options);
  load_functions();
  create_shared_objects();
}

void VulkanDevice::read_limits() {
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(physical_, &props);
  limits_ = props.limits;
  if (props.apiVersion < VK_API_VERSION_1_3)
    throw Error(ErrorKind::Unsupported, adapter_.info.name,
                "the adapter supports only " + adapter_.info.api_version + "; Vulkan 1.3 is required");
}

void VulkanDevice::create_shared_objects() {
  allocator_ = std::make_unique<MemoryAllocator>(physical_, device_, adapter_.capabilities.acceleration_structures);

  VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  pool_info.queueFamilyIndex = queue_family_;
  check_result(vkCreateCommandPool(device_, &pool_info, nullptr, &transfer_pool_), "vkCreateCommandPool",
               "transfer pool");

  // The upload ring: uniform data of dispatches and TLAS instance arrays, written at record time.
  ring_.size = VkDeviceSize{32} << 20;
  VkBufferCreateInfo ring_info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  ring_info.size = ring_.size;
  ring_info.usage = VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
  if (adapter_.capabilities.acceleration_structures)
    ring_info.usage |= VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
                       VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR;
  check_result(vkCreateBuffer(device_, &ring_info, nullptr, &ring_.buffer), "vkCreateBuffer", "upload ring");
  set_name(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<std::uint64_t>(ring_.buffer), "upload ring");
  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(device_, ring_.buffer, &requirements);
  ring_.memory = allocator_->allocate(requirements, MemoryUse::Upload, ResourceClass::Buffer, "upload ring");
  check_result(vkBindBufferMemory(device_, ring_.buffer, ring_.memory.memory, ring_.memory.offset),
               "vkBindBufferMemory", "upload ring");
  if (adapter_.capabilities.acceleration_structures) {
    VkBufferDeviceAddressInfo address{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
    address.buffer = ring_.buffer;
    ring_.address = vkGetBufferDeviceAddress(device_, &address);
  }
  ring_.ranges = std::make_unique<RangeAllocator>(ring_.size);
}

void VulkanDevice::create_logical_device(const DeviceOptions& options) {
  // A queue family with compute; prefer one that also does graphics (it can present).
  std::uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &family_count, families.data());
  int chosen = -1;
  for (std::uint32_t i = 0; i < family_count && chosen < 0; ++i)
    if ((families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) && (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT))
      chosen = static_cast<int>(i);
  for (std::uint32_t i = 0; i < family_count && chosen < 0; ++i)
    if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) chosen = static_cast<int>(i);
  if (chosen < 0) throw Error(ErrorKind::Unsupported, adapter_.info.name, "the adapter has no compute queue");
  queue_family_ = static_cast<std::uint32_t>(chosen);
  timestamp_bits_ = families[queue_family_].timestampValidBits;
  adapter_.capabilities.timestamps = timestamp_bits_ > 0 && limits_.timestampPeriod > 0.0f;

  // What the device offers.
  const auto available = device_extensions(physical_);
  VkPhysicalDeviceRayQueryFeaturesKHR rq_have{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
  VkPhysicalDeviceAccelerationStructureFeaturesKHR as_have{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceVulkan13Features v13_have{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceVulkan12Features v12_have{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &v13_have};
  VkPhysicalDeviceVulkan11Features v11_have{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES, &v12_have};
  const bool as_ext = has(available, VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME) &&
                      has(available, VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME);
  const bool rq_ext = has(available, VK_KHR_RAY_QUERY_EXTENSION_NAME);
  void* chain = &v11_have;
  if (as_ext) {
    as_have.pNext = chain;
    chain = &as_have;
  }
  if (rq_ext) {
    rq_have.pNext = chain;
    chain = &rq_have;
  }
  VkPhysicalDeviceFeatures2 have{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, chain};
  vkGetPhysicalDeviceFeatures2(physical_, &have);
  if (!v13_have.synchronization2)
    throw Error(ErrorKind::Unsupported, adapter_.info.name, "the adapter lacks the synchronization2 feature");

  // What we enable: only features the device has, each one a reason in the shaders or here.
  VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  v13.synchronization2 = VK_TRUE;
  v13.maintenance4 = v13_have.maintenance4;
  v13.subgroupSizeControl = v13_have.subgroupSizeControl;
  v13.computeFullSubgroups = v13_have.computeFullSubgroups;
  VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &v13};
  v12.shaderFloat16 = v12_have.shaderFloat16;
  v12.shaderInt8 = v12_have.shaderInt8;
  v12.storageBuffer8BitAccess = v12_have.storageBuffer8BitAccess;
  v12.scalarBlockLayout = v12_have.scalarBlockLayout;
  v12.vulkanMemoryModel = v12_have.vulkanMemoryModel;
  v12.vulkanMemoryModelDeviceScope = v12_have.vulkanMemoryModelDeviceScope;
  v12.hostQueryReset = v12_have.hostQueryReset;
  const bool accel = as_ext && as_have.accelerationStructure && v12_have.bufferDeviceAddress;
  const bool ray_query = accel && rq_ext && rq_have.rayQuery;
  v12.bufferDeviceAddress = accel ? VK_TRUE : VK_FALSE;
  VkPhysicalDeviceVulkan11Features v11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES, &v12};
  v11.storageBuffer16BitAccess = v11_have.storageBuffer16BitAccess;
  v11.uniformAndStorageBuffer16BitAccess = v11_have.uniformAndStorageBuffer16BitAccess;
  VkPhysicalDeviceAccelerationStructureFeaturesKHR as_on{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  as_on.accelerationStructure = VK_TRUE;
  VkPhysicalDeviceRayQueryFeaturesKHR rq_on{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
  rq_on.rayQuery = VK_TRUE;
  chain = &v11;
  std::vector<const char*> extensions;
  if (accel) {
    extensions.push_back(VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME);
    extensions.push_back(VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME);
    as_on.pNext = chain;
    chain = &as_on;
  }
  if (ray_query) {
    extensions.push_back(VK_KHR_RAY_QUERY_EXTENSION_NAME);
    rq_on.pNext = chain;
    chain = &rq_on;
  }
  // The porting probe's capture (pipeline_stats.hpp): enabled only when asked for.
  VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR stats_on{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
  stats_on.pipelineExecutableInfo = VK_TRUE;
  if (pipeline_stats_folder()) {
    pipeline_stats_ = has(available, VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
    if (pipeline_stats_) {
      extensions.push_back(VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
      stats_on.pNext = chain;
      chain = &stats_on;
    } else {
      std::fprintf(stderr, "ASVGF_VK_PIPELINE_STATS: %s has no VK_KHR_pipeline_executable_properties\n",
                   adapter_.info.name.c_str());
    }
  }
  swapchain_ = has(options.instance_extensions, VK_KHR_SURFACE_EXTENSION_NAME) &&
               has(available, VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  if (swapchain_) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);

  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, chain};
  features.features.shaderInt16 = have.features.shaderInt16;
  features.features.shaderInt64 = have.features.shaderInt64;
  features.features.shaderStorageImageReadWithoutFormat = have.features.shaderStorageImageReadWithoutFormat;
  features.features.shaderStorageImageWriteWithoutFormat = have.features.shaderStorageImageWriteWithoutFormat;

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = queue_family_;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  check(vkCreateDevice(physical_, &info, nullptr, &device_), "vkCreateDevice", adapter_.info.name);
  vkGetDeviceQueue(device_, queue_family_, 0, &queue_);

  // Capabilities say what this device was created with, not only what the adapter could do.
  Capabilities& caps = adapter_.capabilities;
  caps.acceleration_structures = accel;
  caps.ray_query = ray_query;
  caps.fp16_storage = v11_have.storageBuffer16BitAccess == VK_TRUE;
}

void VulkanDevice::load_functions() {
  const bool accel = adapter_.capabilities.acceleration_structures;
  auto load = [&](const char* name) { return vkGetDeviceProcAddr(device_, name); };
  if (accel) {
    fn_.create_accel = reinterpret_cast<PFN_vkCreateAccelerationStructureKHR>(load("vkCreateAccelerationStructureKHR"));
    fn_.destroy_accel =
        reinterpret_cast<PFN_vkDestroyAccelerationStructureKHR>(load("vkDestroyAccelerationStructureKHR"));
    fn_.accel_sizes =
        reinterpret_cast<PFN_vkGetAccelerationStructureBuildSizesKHR>(load("vkGetAccelerationStructureBuildSizesKHR"));
    fn_.accel_address = reinterpret_cast<PFN_vkGetAccelerationStructureDeviceAddressKHR>(
        load("vkGetAccelerationStructureDeviceAddressKHR"));
    fn_.cmd_build_accel =
        reinterpret_cast<PFN_vkCmdBuildAccelerationStructuresKHR>(load("vkCmdBuildAccelerationStructuresKHR"));
  }
  if (instance_->debug_utils()) {
    auto iload = [&](const char* name) { return vkGetInstanceProcAddr(instance_->handle(), name); };
    fn_.begin_label = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(iload("vkCmdBeginDebugUtilsLabelEXT"));
    fn_.end_label = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(iload("vkCmdEndDebugUtilsLabelEXT"));
    fn_.set_name = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(iload("vkSetDebugUtilsObjectNameEXT"));
  }
}

VulkanDevice::~VulkanDevice() {
  if (!device_) return;
  vkDeviceWaitIdle(device_);
  for (auto& [id, b] : buffers.all()) {
    vkDestroyBuffer(device_, b.buffer, nullptr);
    allocator_->free(b.memory);
  }
  for (auto& [id, i] : images.all()) {
    vkDestroyImageView(device_, i.view, nullptr);
    if (i.owned) vkDestroyImage(device_, i.image, nullptr);
    allocator_->free(i.memory);
  }
  for (auto& [id, s] : binding_sets.all()) vkDestroyDescriptorPool(device_, s.pool, nullptr);
  for (auto& [id, p] : pipelines.all()) {
    vkDestroyPipeline(device_, p.pipeline, nullptr);
    vkDestroyPipelineLayout(device_, p.layout, nullptr);
    for (auto layout : p.set_layouts) vkDestroyDescriptorSetLayout(device_, layout, nullptr);
  }
  for (auto& [id, a] : accels.all()) destroy_accel(a);
  for (auto& [id, t] : timers.all()) vkDestroyQueryPool(device_, t.pool, nullptr);
  if (ring_.buffer) vkDestroyBuffer(device_, ring_.buffer, nullptr);
  if (allocator_) {
    allocator_->free(ring_.memory);
    allocator_.reset();
  }
  if (transfer_pool_) vkDestroyCommandPool(device_, transfer_pool_, nullptr);
  if (owns_device_) vkDestroyDevice(device_, nullptr);
}

void VulkanDevice::check_alive() const {
  if (lost_) throw Error(ErrorKind::DeviceLost, adapter_.info.name, "the device was lost earlier; recreate it");
}

void VulkanDevice::check_result(VkResult result, std::string_view call, std::string_view object) {
  if (result == VK_ERROR_DEVICE_LOST) lost_ = true;
  check(result, call, object);
}

void VulkanDevice::set_name(VkObjectType type, std::uint64_t handle, const std::string& name) const {
  if (!fn_.set_name || name.empty()) return;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = name.c_str();
  fn_.set_name(device_, &info);
}

std::unique_ptr<CommandList> VulkanDevice::create_command_list(std::string_view name) {
  check_alive();
  return std::make_unique<VulkanCommandList>(*this, std::string(name));
}

void VulkanDevice::submit(CommandList& commands) {
  check_alive();
  auto* list = dynamic_cast<VulkanCommandList*>(&commands);
  if (!list) throw Error(ErrorKind::InvalidUsage, "", "the command list was not created by this Vulkan device");
  if (&list->device() != this)
    throw Error(ErrorKind::InvalidUsage, list->name(), "the command list belongs to another device");
  VkCommandBuffer cmd = list->end_for_submit();
  VkCommandBufferSubmitInfo buffer_info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  buffer_info.commandBuffer = cmd;
  VkSubmitInfo2 info{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  info.commandBufferInfoCount = 1;
  info.pCommandBufferInfos = &buffer_info;
  check_result(vkQueueSubmit2(queue_, 1, &info, VK_NULL_HANDLE), "vkQueueSubmit2", list->name());
  list->mark_submitted(++submitted_);
}

void VulkanDevice::wait() {
  check_alive();
  check_result(vkQueueWaitIdle(queue_), "vkQueueWaitIdle", adapter_.info.name);
  completed_ = submitted_;
}

VkCommandBuffer VulkanDevice::begin_transfer() {
  check_alive();
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = transfer_pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  check_result(vkAllocateCommandBuffers(device_, &alloc, &cmd), "vkAllocateCommandBuffers", "transfer");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check_result(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer", "transfer");
  return cmd;
}

void VulkanDevice::finish_transfer(VkCommandBuffer cmd, std::string_view what) {
  VkResult result = vkEndCommandBuffer(cmd);
  if (result == VK_SUCCESS) {
    VkCommandBufferSubmitInfo buffer_info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    buffer_info.commandBuffer = cmd;
    VkSubmitInfo2 info{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    info.commandBufferInfoCount = 1;
    info.pCommandBufferInfos = &buffer_info;
    result = vkQueueSubmit2(queue_, 1, &info, VK_NULL_HANDLE);
    // Waiting for the queue also completes earlier submissions: host transfers are synchronous.
    if (result == VK_SUCCESS) result = vkQueueWaitIdle(queue_);
    if (result == VK_SUCCESS) completed_ = submitted_;
  }
  vkFreeCommandBuffers(device_, transfer_pool_, 1, &cmd);
  check_result(result, "host transfer submission", what);
}

void VulkanDevice::destroy(BufferHandle handle) {
  BufferObject& b = buffers.get(handle.id, "buffer");
  vkDestroyBuffer(device_, b.buffer, nullptr);
  allocator_->free(b.memory);
  buffers.erase(handle.id);
}

void VulkanDevice::destroy(ImageHandle handle) {
  ImageObject& i = images.get(handle.id, "image");
  vkDestroyImageView(device_, i.view, nullptr);
  if (i.owned) vkDestroyImage(device_, i.image, nullptr);
  allocator_->free(i.memory);
  images.erase(handle.id);
}

void VulkanDevice::destroy(PipelineHandle handle) {
  PipelineObject& p = pipelines.get(handle.id, "pipeline");
  vkDestroyPipeline(device_, p.pipeline, nullptr);
  vkDestroyPipelineLayout(device_, p.layout, nullptr);
  for (auto layout : p.set_layouts) vkDestroyDescriptorSetLayout(device_, layout, nullptr);
  pipelines.erase(handle.id);
}

void VulkanDevice::destroy(BindingSetHandle handle) {
  BindingSetObject& s = binding_sets.get(handle.id, "binding set");
  vkDestroyDescriptorPool(device_, s.pool, nullptr);
  binding_sets.erase(handle.id);
}

void VulkanDevice::destroy(TimerQueriesHandle handle) {
  TimerObject& t = timers.get(handle.id, "timer queries");
  vkDestroyQueryPool(device_, t.pool, nullptr);
  timers.erase(handle.id);
}

}  // namespace hal::vulkan
