// hal/shader.hpp: a compiled compute shader and its reflection, as the offline shader tool emits it.
//
// The tool (tools/shaderc) writes one generated header per shader variant that defines a
// `constexpr hal::ShaderInfo`; backends build pipelines only from these. Every field is static data
// owned by the generated header, so a ShaderInfo is a cheap view that never dangles.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

#include "hal/types.hpp"

namespace hal {

enum class BindingKind : std::uint8_t {
  UniformBuffer,  // the shader's one parameter block; filled through DispatchDesc::uniforms
  StorageBuffer,
  SampledImage,  // texture2D read with texelFetch
  StorageImage,
  AccelerationStructure,
};
std::string_view to_string(BindingKind kind);

// What a dispatch does to a bound resource, from the GLSL qualifiers (readonly/writeonly).
enum class Access : std::uint8_t { Read, Write, ReadWrite };
std::string_view to_string(Access access);

struct ShaderBinding {
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  BindingKind kind = BindingKind::StorageBuffer;
  Access access = Access::Read;
  std::string_view name;              // the GLSL instance or variable name, used to bind from C++
  Format format = Format::Undefined;  // storage images only
  // OpenGL unit of this binding's kind (uniform block, SSBO, texture or image unit): GL has no
  // sets, so the shader tool numbers each kind in (set, binding) order and writes the GLSL so.
  std::uint32_t gl_binding = 0;
};

struct UniformMember {
  std::string_view name;
  std::uint32_t offset = 0;  // bytes from the start of the block (std140)
  std::uint32_t size = 0;    // bytes
};

// One translation of a shader for a backend that does not run Vulkan's SPIR-V, named by its language
// ("glsl": OpenGL GLSL 450, "essl": OpenGL ES GLSL 310, with the gl_binding units; "spirv-gl": the
// GLSL 450 compiled to SPIR-V for OpenGL 4.5's GL_ARB_gl_spirv, as bytes). A language a new port
// needs is one more entry the shader tool writes; no HAL header changes.
struct ShaderSource {
  std::string_view language;
  std::string_view text;
};

struct ShaderInfo {
  std::string_view name;  // "<shader>" or "<shader>.<variant>"
  std::span<const std::uint32_t> spirv;
  std::span<const ShaderBinding> bindings;
  std::array<std::uint32_t, 3> workgroup_size{1, 1, 1};
  std::uint32_t uniform_block_size = 0;  // 0: the shader has no uniform block
  std::span<const UniformMember> uniform_members;
  bool uses_ray_query = false;
  // Translations by language (their text empty for ray-query variants).
  std::span<const ShaderSource> sources;

  // The translation into `language`, or empty.
  constexpr std::string_view source(std::string_view language) const {
    for (const auto& s : sources)
      if (s.language == language) return s.text;
    return {};
  }
  // The binding with this name, or nullptr.
  constexpr const ShaderBinding* find(std::string_view binding_name) const {
    for (const auto& b : bindings)
      if (b.name == binding_name) return &b;
    return nullptr;
  }
};

}  // namespace hal
