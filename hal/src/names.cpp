// Names and sizes of HAL enums: formats, states, binding kinds, device types.
#include <string_view>

#include "hal/device.hpp"
#include "hal/shader.hpp"
#include "hal/types.hpp"

namespace hal {
namespace {
struct FormatInfo {
  Format format;
  std::uint32_t size;
  std::uint32_t channels;
  std::string_view name;
};
constexpr FormatInfo kFormats[] = {
    {Format::Undefined, 0, 0, "undefined"}, {Format::R8Unorm, 1, 1, "r8"},      {Format::RGBA8Unorm, 4, 4, "rgba8"},
    {Format::R16F, 2, 1, "r16f"},           {Format::RG16F, 4, 2, "rg16f"},     {Format::RGBA16F, 8, 4, "rgba16f"},
    {Format::R32F, 4, 1, "r32f"},           {Format::RG32F, 8, 2, "rg32f"},     {Format::RGBA32F, 16, 4, "rgba32f"},
    {Format::R32Uint, 4, 1, "r32ui"},       {Format::RG32Uint, 8, 2, "rg32ui"}, {Format::RGBA32Uint, 16, 4, "rgba32ui"},
    {Format::RGBA16Uint, 8, 4, "rgba16ui"},
};
const FormatInfo& info(Format format) {
  for (const auto& f : kFormats)
    if (f.format == format) return f;
  return kFormats[0];
}
}  // namespace

std::uint32_t format_size(Format format) {
  return info(format).size;
}
std::uint32_t format_channels(Format format) {
  return info(format).channels;
}
std::string_view format_name(Format format) {
  return info(format).name;
}
bool format_is_uint(Format format) {
  return format == Format::R32Uint || format == Format::RG32Uint || format == Format::RGBA32Uint ||
         format == Format::RGBA16Uint;
}
Format format_from_name(std::string_view name) {
  for (const auto& f : kFormats)
    if (f.name == name) return f.format;
  return Format::Undefined;
}

std::string_view to_string(State state) {
  switch (state) {
    case State::Undefined:
      return "undefined";
    case State::ShaderRead:
      return "shader-read";
    case State::ShaderWrite:
      return "shader-write";
    case State::CopySrc:
      return "copy-src";
    case State::CopyDst:
      return "copy-dst";
    case State::AccelBuildInput:
      return "accel-build-input";
    case State::AccelWrite:
      return "accel-write";
    case State::AccelRead:
      return "accel-read";
    case State::Present:
      return "present";
  }
  return "?";
}

std::string_view to_string(BindingKind kind) {
  switch (kind) {
    case BindingKind::UniformBuffer:
      return "uniform-buffer";
    case BindingKind::StorageBuffer:
      return "storage-buffer";
    case BindingKind::SampledImage:
      return "sampled-image";
    case BindingKind::StorageImage:
      return "storage-image";
    case BindingKind::AccelerationStructure:
      return "acceleration-structure";
  }
  return "?";
}

std::string_view to_string(Access access) {
  switch (access) {
    case Access::Read:
      return "read";
    case Access::Write:
      return "write";
    case Access::ReadWrite:
      return "read-write";
  }
  return "?";
}

std::string_view to_string(DeviceType type) {
  switch (type) {
    case DeviceType::Other:
      return "other";
    case DeviceType::IntegratedGpu:
      return "integrated GPU";
    case DeviceType::DiscreteGpu:
      return "discrete GPU";
    case DeviceType::VirtualGpu:
      return "virtual GPU";
    case DeviceType::Cpu:
      return "CPU";
    case DeviceType::NoGpu:
      return "no GPU (recording)";
  }
  return "?";
}

}  // namespace hal
