// Hand-written shader reflections for recording-HAL tests: the recording device needs only the
// binding table, never SPIR-V.
#pragma once

#include "hal/shader.hpp"

namespace record_test {

using hal::Access;
using hal::BindingKind;

// Reads buffer `src`, writes buffer `dst`.
inline constexpr hal::ShaderBinding kCopyBindings[] = {
    {0, 0, BindingKind::StorageBuffer, Access::Read, "src"},
    {0, 1, BindingKind::StorageBuffer, Access::Write, "dst"},
};
inline constexpr hal::ShaderInfo kCopyShader{.name = "copy_buffer", .bindings = kCopyBindings};

// Reads and writes buffer `data` in place.
inline constexpr hal::ShaderBinding kInPlaceBindings[] = {
    {0, 0, BindingKind::StorageBuffer, Access::ReadWrite, "data"},
};
inline constexpr hal::ShaderInfo kInPlaceShader{.name = "in_place", .bindings = kInPlaceBindings};

// Reads sampled image `src_image`, writes storage image `dst_image`, with a 16-byte uniform block.
inline constexpr hal::ShaderBinding kImageBindings[] = {
    {0, 0, BindingKind::UniformBuffer, Access::Read, "params"},
    {0, 1, BindingKind::SampledImage, Access::Read, "src_image"},
    {0, 2, BindingKind::StorageImage, Access::Write, "dst_image", hal::Format::RGBA16F},
};
inline constexpr hal::ShaderInfo kImageShader{.name = "filter_image", .bindings = kImageBindings,
                                              .uniform_block_size = 16};

}  // namespace record_test
