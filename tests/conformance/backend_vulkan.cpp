// Registers the Vulkan backend with validation and synchronization validation on.
#include "backends.hpp"
#include "hal_vulkan/vulkan.hpp"

namespace {

const conformance::Register vulkan({"vulkan", [](std::vector<std::string>& messages) {
                                      hal::vulkan::DeviceOptions options;
                                      options.validation = true;
                                      options.on_validation_message = [&messages](const std::string& m) {
                                        messages.push_back(m);
                                      };
                                      return hal::vulkan::create_device(options);
                                    }});

}  // namespace
