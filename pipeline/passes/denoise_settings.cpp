#include "passes/denoise_settings.hpp"

#include <string>

#include "hal/error.hpp"

namespace asvgf::passes {

void check_uniform_layout(const hal::ShaderInfo& shader, std::size_t size, std::initializer_list<UniformField> fields) {
  const std::string object(shader.name);
  if (shader.uniform_block_size != size)
    throw hal::Error(hal::ErrorKind::BindingMismatch, object,
                     "uniform block is " + std::to_string(shader.uniform_block_size) + " bytes in the shader, " +
                         std::to_string(size) + " in C++");
  for (const UniformField& f : fields) {
    const hal::UniformMember* found = nullptr;
    for (const auto& m : shader.uniform_members)
      if (m.name == f.name) found = &m;
    if (!found)
      throw hal::Error(hal::ErrorKind::BindingMismatch, object,
                       "uniform member '" + std::string(f.name) + "' of the C++ struct is not in the shader");
    if (found->offset != f.offset)
      throw hal::Error(hal::ErrorKind::BindingMismatch, object,
                       "uniform member '" + std::string(f.name) + "' is at offset " + std::to_string(found->offset) +
                           " in the shader, " + std::to_string(f.offset) + " in C++");
  }
  if (shader.uniform_members.size() != fields.size())
    throw hal::Error(hal::ErrorKind::BindingMismatch, object,
                     "the shader's uniform block has " + std::to_string(shader.uniform_members.size()) +
                         " members, the C++ struct " + std::to_string(fields.size()));
}

std::uint32_t group_count(const hal::ShaderInfo& shader, int axis, std::uint32_t extent) {
  const std::uint32_t size = shader.workgroup_size[static_cast<std::size_t>(axis)];
  return (extent + size - 1) / size;
}

}  // namespace asvgf::passes
