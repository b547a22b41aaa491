// A porting probe, Vulkan's side of ASVGF_GL_PROGRAM_DUMP: with ASVGF_VK_PIPELINE_STATS=<folder>,
// where the driver has VK_KHR_pipeline_executable_properties, every compute pipeline is created
// with its statistics captured and written to <folder>/<pipeline>.txt (NVIDIA's: registers, local
// and shared memory; with any internal representation the driver gives). Compare the same pass
// on two backends, or two variants, by what the driver compiled (hal/PORTING.md).
#pragma once

#include <vulkan/vulkan.h>

#include <string_view>

namespace hal::vulkan {

// The folder, or nullptr when the probe is off.
const char* pipeline_stats_folder();
// Writes the pipeline's executables' statistics and internal representations; a failure is
// printed, never thrown.
void dump_pipeline_stats(VkDevice device, VkPipeline pipeline, std::string_view name);

}  // namespace hal::vulkan
