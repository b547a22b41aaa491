// reflection.hpp: what the generated header and the JSON say about a shader, read from the final
// SPIR-V with SPIRV-Cross. Mirrors hal::ShaderInfo (hal/shader.hpp) with owning strings.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace shaderc {

enum class Kind { UniformBuffer, StorageBuffer, SampledImage, StorageImage, AccelerationStructure };
enum class Access { Read, Write, ReadWrite };
const char* kind_name(Kind kind);        // the hal::BindingKind enumerator
const char* access_name(Access access);  // the hal::Access enumerator

struct Binding {
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  Kind kind = Kind::StorageBuffer;
  Access access = Access::Read;
  std::string name;        // GLSL instance name of a block, or the variable name
  std::string format;      // storage images: GLSL format qualifier ("rgba16f"), else empty
  std::string hal_format;  // storage images: hal::Format enumerator ("RGBA16F"), else "Undefined"
  // OpenGL has one binding namespace per kind and no sets: the unit of this kind (uniform block,
  // SSBO, texture, image) in (set, binding) order. The GLSL/ESSL outputs are written with it.
  std::uint32_t gl_binding = 0;
};

struct UniformMember {
  std::string name;
  std::uint32_t offset = 0;
  std::uint32_t size = 0;
};

// A uniform block (or a struct inside one) as a C++ struct: members in offset order with the C++
// type that has the member's std140 size, and explicit padding where the offsets jump.
struct CppMember {
  std::string name;
  std::string type;  // "std::uint32_t", "std::array<float, 4>", a nested struct's name, "std::uint8_t[N]" padding
  std::uint32_t offset = 0;
  std::uint32_t size = 0;
  bool padding = false;
};
struct CppStruct {
  std::string name;  // the GLSL type name
  std::uint32_t size = 0;
  std::vector<CppMember> members;
};

struct Reflection {
  std::array<std::uint32_t, 3> workgroup_size{1, 1, 1};
  std::vector<Binding> bindings;  // sorted by (set, binding)
  std::uint32_t uniform_block_count = 0;
  std::uint32_t uniform_block_size = 0;
  std::vector<UniformMember> uniform_members;
  std::vector<CppStruct> uniform_structs;  // nested structs first, the block itself last
  std::vector<std::string> specialization_constants;  // names; the HAL has none, so they are refused
  bool uses_ray_query = false;
  bool uses_image_atomics = false;
  // Resources the HAL has no binding kind for (push constants, samplers, ...), described.
  std::vector<std::string> unsupported;
};

// Throws ToolError naming `shader` if SPIRV-Cross cannot parse the module.
Reflection reflect(const std::vector<std::uint32_t>& spirv, const std::string& shader);

}  // namespace shaderc
