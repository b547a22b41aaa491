// Turning VkResult failures into hal::Error naming the call and the object.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <string_view>

#include "hal/error.hpp"

namespace hal::vulkan {

std::string_view result_name(VkResult result);

// Throws hal::Error for any result other than VK_SUCCESS (and VK_INCOMPLETE, which callers of
// enumeration functions handle themselves).
inline void check(VkResult result, std::string_view call, std::string_view object) {
  if (result == VK_SUCCESS || result == VK_INCOMPLETE) return;
  ErrorKind kind = ErrorKind::Backend;
  switch (result) {
    case VK_ERROR_OUT_OF_HOST_MEMORY:
    case VK_ERROR_OUT_OF_DEVICE_MEMORY: kind = ErrorKind::OutOfMemory; break;
    case VK_ERROR_DEVICE_LOST: kind = ErrorKind::DeviceLost; break;
    case VK_ERROR_EXTENSION_NOT_PRESENT:
    case VK_ERROR_FEATURE_NOT_PRESENT:
    case VK_ERROR_FORMAT_NOT_SUPPORTED:
    case VK_ERROR_LAYER_NOT_PRESENT: kind = ErrorKind::Unsupported; break;
    case VK_ERROR_INCOMPATIBLE_DRIVER:
    case VK_ERROR_INITIALIZATION_FAILED: kind = ErrorKind::NoDevice; break;
    default: break;
  }
  throw Error(kind, object, std::string(call) + " failed with " + std::string(result_name(result)));
}

}  // namespace hal::vulkan
