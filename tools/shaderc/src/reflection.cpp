#include "reflection.hpp"

#include <spirv_cross.hpp>

#include <algorithm>
#include <utility>

#include "error.hpp"

namespace shaderc {
namespace {

struct FormatName {
  spv::ImageFormat spv;
  const char* glsl;
  const char* hal;
};
// Exactly the formats hal::Format has (hal/include/hal/types.hpp).
constexpr FormatName kFormats[] = {
    {spv::ImageFormatR8, "r8", "R8Unorm"},
    {spv::ImageFormatRgba8, "rgba8", "RGBA8Unorm"},
    {spv::ImageFormatR16f, "r16f", "R16F"},
    {spv::ImageFormatRg16f, "rg16f", "RG16F"},
    {spv::ImageFormatRgba16f, "rgba16f", "RGBA16F"},
    {spv::ImageFormatR32f, "r32f", "R32F"},
    {spv::ImageFormatRg32f, "rg32f", "RG32F"},
    {spv::ImageFormatRgba32f, "rgba32f", "RGBA32F"},
    {spv::ImageFormatR32ui, "r32ui", "R32Uint"},
    {spv::ImageFormatRg32ui, "rg32ui", "RG32Uint"},
    {spv::ImageFormatRgba32ui, "rgba32ui", "RGBA32Uint"},
    {spv::ImageFormatRgba16ui, "rgba16ui", "RGBA16Uint"},
};

// A block's GLSL instance name ("src" in `buffer Input {...} src;`), else its block name.
std::string instance_name(const spirv_cross::Compiler& c, const spirv_cross::Resource& r) {
  const std::string& name = c.get_name(r.id);
  return name.empty() ? r.name : name;
}

Access access_of(const spirv_cross::Bitset& flags) {
  const bool no_write = flags.get(spv::DecorationNonWritable);
  const bool no_read = flags.get(spv::DecorationNonReadable);
  if (no_write) return Access::Read;
  if (no_read) return Access::Write;
  return Access::ReadWrite;
}

Binding make_binding(const spirv_cross::Compiler& c, const spirv_cross::Resource& r, Kind kind, Access access) {
  Binding b;
  b.set = c.get_decoration(r.id, spv::DecorationDescriptorSet);
  b.binding = c.get_decoration(r.id, spv::DecorationBinding);
  b.kind = kind;
  b.access = access;
  b.name = kind == Kind::UniformBuffer || kind == Kind::StorageBuffer ? instance_name(c, r) : c.get_name(r.id);
  b.hal_format = "Undefined";
  return b;
}

bool has_opcode(const std::vector<std::uint32_t>& spirv, spv::Op op) {
  for (std::size_t i = 5; i < spirv.size();) {
    const std::uint32_t count = spirv[i] >> 16;
    if ((spirv[i] & 0xffffu) == static_cast<std::uint32_t>(op)) return true;
    if (count == 0) break;
    i += count;
  }
  return false;
}

}  // namespace

const char* kind_name(Kind kind) {
  switch (kind) {
    case Kind::UniformBuffer:
      return "UniformBuffer";
    case Kind::StorageBuffer:
      return "StorageBuffer";
    case Kind::SampledImage:
      return "SampledImage";
    case Kind::StorageImage:
      return "StorageImage";
    case Kind::AccelerationStructure:
      return "AccelerationStructure";
  }
  return "?";
}

const char* access_name(Access access) {
  switch (access) {
    case Access::Read:
      return "Read";
    case Access::Write:
      return "Write";
    case Access::ReadWrite:
      return "ReadWrite";
  }
  return "?";
}

namespace {

// The C++ mirror of struct type `type_id` (and, first, of the structs it holds) appended to `out`.
void mirror_struct(const spirv_cross::Compiler& c, std::uint32_t type_id, const std::string& shader,
                   std::vector<CppStruct>& out) {
  const auto& type = c.get_type(type_id);
  CppStruct s{c.get_name(type_id), static_cast<std::uint32_t>(c.get_declared_struct_size(type)), {}};
  if (s.name.empty()) s.name = "Struct" + std::to_string(type_id);
  std::uint32_t at = 0;
  auto pad_to = [&](std::uint32_t offset) {
    if (offset > at) s.members.push_back({"pad" + std::to_string(at), "std::uint8_t", at, offset - at, true});
    at = offset;
  };
  for (std::uint32_t m = 0; m < type.member_types.size(); ++m) {
    const std::string name = c.get_member_name(type_id, m);
    const auto& member = c.get_type(type.member_types[m]);
    const auto offset = c.type_struct_member_offset(type, m);
    const auto size = static_cast<std::uint32_t>(c.get_declared_struct_member_size(type, m));
    auto fail = [&](const std::string& why) {
      throw ToolError(shader + ": error: uniform member '" + name + "' " + why +
                      "; the generated C++ struct mirrors scalars, vectors and structs only");
    };
    if (!member.array.empty()) fail("is an array");
    std::string cpp;
    if (member.basetype == spirv_cross::SPIRType::Struct) {
      cpp = c.get_name(type.member_types[m]);
      const bool mirrored =
          std::any_of(out.begin(), out.end(), [&](const CppStruct& done) { return done.name == cpp; });
      if (cpp.empty() || !mirrored) {
        mirror_struct(c, type.member_types[m], shader, out);
        cpp = out.back().name;
      }
    } else {
      switch (member.basetype) {
        case spirv_cross::SPIRType::UInt:
        case spirv_cross::SPIRType::Boolean:
          cpp = "std::uint32_t";
          break;
        case spirv_cross::SPIRType::Int:
          cpp = "std::int32_t";
          break;
        case spirv_cross::SPIRType::Float:
          cpp = "float";
          break;
        default:
          fail("has a type other than uint, int, bool or float");
      }
      if (member.columns > 1) fail("is a matrix");
      if (member.vecsize > 1) cpp = "std::array<" + cpp + ", " + std::to_string(member.vecsize) + ">";
    }
    pad_to(offset);
    s.members.push_back({name, cpp, offset, size, false});
    at = offset + size;
  }
  pad_to(s.size);
  out.push_back(std::move(s));
}

}  // namespace

Reflection reflect(const std::vector<std::uint32_t>& spirv, const std::string& shader) {
  Reflection out;
  try {
    spirv_cross::Compiler c(spirv);
    const auto res = c.get_shader_resources();

    for (std::uint32_t i = 0; i < 3; ++i)
      out.workgroup_size[i] = c.get_execution_mode_argument(spv::ExecutionModeLocalSize, i);

    out.uniform_block_count = static_cast<std::uint32_t>(res.uniform_buffers.size());
    for (const auto& r : res.uniform_buffers) {
      out.bindings.push_back(make_binding(c, r, Kind::UniformBuffer, Access::Read));
      const auto& type = c.get_type(r.base_type_id);
      out.uniform_block_size = static_cast<std::uint32_t>(c.get_declared_struct_size(type));
      for (std::uint32_t m = 0; m < type.member_types.size(); ++m)
        out.uniform_members.push_back({c.get_member_name(r.base_type_id, m), c.type_struct_member_offset(type, m),
                                       static_cast<std::uint32_t>(c.get_declared_struct_member_size(type, m))});
      mirror_struct(c, r.base_type_id, shader, out.uniform_structs);
    }
    for (const auto& r : res.storage_buffers)
      out.bindings.push_back(make_binding(c, r, Kind::StorageBuffer, access_of(c.get_buffer_block_flags(r.id))));
    for (const auto& r : res.separate_images)
      out.bindings.push_back(make_binding(c, r, Kind::SampledImage, Access::Read));
    for (const auto& r : res.storage_images) {
      Binding b = make_binding(c, r, Kind::StorageImage, access_of(c.get_decoration_bitset(r.id)));
      const auto format = c.get_type(r.type_id).image.format;
      auto it =
          std::find_if(std::begin(kFormats), std::end(kFormats), [&](const FormatName& f) { return f.spv == format; });
      if (it == std::end(kFormats)) {
        out.unsupported.push_back("storage image '" + b.name + "' has a format hal::Format lacks (SPIR-V ImageFormat " +
                                  std::to_string(static_cast<int>(format)) + ")");
      } else {
        b.format = it->glsl;
        b.hal_format = it->hal;
      }
      out.bindings.push_back(std::move(b));
    }
    for (const auto& r : res.acceleration_structures)
      out.bindings.push_back(make_binding(c, r, Kind::AccelerationStructure, Access::Read));

    for (const auto& r : res.push_constant_buffers) out.unsupported.push_back("push constant block '" + r.name + "'");
    for (const auto& r : res.sampled_images)
      out.unsupported.push_back("combined image sampler '" + c.get_name(r.id) + "'");
    for (const auto& r : res.separate_samplers) out.unsupported.push_back("sampler '" + c.get_name(r.id) + "'");
    for (const auto& r : res.atomic_counters) out.unsupported.push_back("atomic counter '" + c.get_name(r.id) + "'");

    std::sort(out.bindings.begin(), out.bindings.end(), [](const Binding& a, const Binding& b) {
      return std::pair(a.set, a.binding) < std::pair(b.set, b.binding);
    });
    std::uint32_t next_unit[5] = {};  // per Kind
    for (auto& b : out.bindings) b.gl_binding = next_unit[static_cast<int>(b.kind)]++;

    for (const auto& sc : c.get_specialization_constants()) out.specialization_constants.push_back(c.get_name(sc.id));

    const auto& caps = c.get_declared_capabilities();
    out.uses_ray_query = std::find(caps.begin(), caps.end(), spv::CapabilityRayQueryKHR) != caps.end();
    out.uses_image_atomics = has_opcode(spirv, spv::OpImageTexelPointer);
  } catch (const spirv_cross::CompilerError& e) {
    throw ToolError(shader + ": error: SPIRV-Cross cannot reflect the SPIR-V: " + e.what());
  }
  return out;
}

}  // namespace shaderc
