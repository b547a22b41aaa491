#include "pipeline_stats.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace hal::vulkan {

const char* pipeline_stats_folder() {
  const char* folder = std::getenv("ASVGF_VK_PIPELINE_STATS");
  return folder && *folder ? folder : nullptr;
}

namespace {

std::string statistic_text(const VkPipelineExecutableStatisticKHR& s) {
  switch (s.format) {
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR:
      return s.value.b32 ? "true" : "false";
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR:
      return std::to_string(s.value.i64);
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR:
      return std::to_string(s.value.u64);
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_FLOAT64_KHR:
      return std::to_string(s.value.f64);
    default:
      return "?";
  }
}

}  // namespace

void dump_pipeline_stats(VkDevice device, VkPipeline pipeline, std::string_view name) {
  const char* folder = pipeline_stats_folder();
  if (!folder) return;
  const auto properties = reinterpret_cast<PFN_vkGetPipelineExecutablePropertiesKHR>(
      vkGetDeviceProcAddr(device, "vkGetPipelineExecutablePropertiesKHR"));
  const auto statistics = reinterpret_cast<PFN_vkGetPipelineExecutableStatisticsKHR>(
      vkGetDeviceProcAddr(device, "vkGetPipelineExecutableStatisticsKHR"));
  const auto representations = reinterpret_cast<PFN_vkGetPipelineExecutableInternalRepresentationsKHR>(
      vkGetDeviceProcAddr(device, "vkGetPipelineExecutableInternalRepresentationsKHR"));
  if (!properties || !statistics || !representations) {
    std::fprintf(stderr, "ASVGF_VK_PIPELINE_STATS: the device has no VK_KHR_pipeline_executable_properties\n");
    return;
  }
  std::string text;
  VkPipelineInfoKHR info{VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR, nullptr, pipeline};
  std::uint32_t count = 0;
  properties(device, &info, &count, nullptr);
  std::vector<VkPipelineExecutablePropertiesKHR> executables(count,
                                                             {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR});
  properties(device, &info, &count, executables.data());
  for (std::uint32_t e = 0; e < count; ++e) {
    text += std::string("executable ") + executables[e].name + " (" + executables[e].description + "), subgroup size " +
            std::to_string(executables[e].subgroupSize) + "\n";
    VkPipelineExecutableInfoKHR which{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR, nullptr, pipeline, e};
    std::uint32_t n = 0;
    statistics(device, &which, &n, nullptr);
    std::vector<VkPipelineExecutableStatisticKHR> stats(n, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR});
    statistics(device, &which, &n, stats.data());
    for (const auto& s : stats) text += std::string("  ") + s.name + ": " + statistic_text(s) + "\n";
    std::uint32_t r = 0;
    representations(device, &which, &r, nullptr);
    std::vector<VkPipelineExecutableInternalRepresentationKHR> reps(
        r, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INTERNAL_REPRESENTATION_KHR});
    representations(device, &which, &r, reps.data());  // sizes first
    std::vector<std::vector<char>> data(r);
    for (std::uint32_t i = 0; i < r; ++i) {
      data[i].resize(reps[i].dataSize);
      reps[i].pData = data[i].data();
    }
    representations(device, &which, &r, reps.data());
    for (std::uint32_t i = 0; i < r; ++i) {
      text += std::string("  representation ") + reps[i].name + " (" + reps[i].description + ", " +
              std::to_string(reps[i].dataSize) + " bytes" + (reps[i].isText ? "" : ", binary, not written") + ")\n";
      if (reps[i].isText) text += std::string(data[i].data(), strnlen(data[i].data(), data[i].size())) + "\n";
    }
  }
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  const std::filesystem::path path = std::filesystem::path(folder) / (std::string(name) + ".txt");
  std::ofstream out(path, std::ios::trunc);
  out << text;
  out.close();
  if (!out) std::fprintf(stderr, "ASVGF_VK_PIPELINE_STATS: could not write %s\n", path.string().c_str());
}

}  // namespace hal::vulkan
