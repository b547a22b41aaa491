#include "portability.hpp"

#include <algorithm>

namespace shaderc {
namespace {

// WebGPU's default limits; Dawn rejects a pipeline over them unless the device asked for more.
constexpr std::size_t kWebGpuStorageBuffers = 8;   // maxStorageBuffersPerShaderStage
constexpr std::size_t kWebGpuStorageTextures = 4;  // maxStorageTexturesPerShaderStage

bool is_r32(const std::string& format) {
  return format == "r32f" || format == "r32ui" || format == "r32i";
}

}  // namespace

std::string es31_minimum_fit(const Reflection& r) {
  std::size_t counts[5] = {};
  for (const auto& b : r.bindings) ++counts[static_cast<int>(b.kind)];
  struct Limit {
    Kind kind;
    std::size_t guaranteed;
    const char* what;
  };
  const Limit limits[] = {{Kind::StorageBuffer, 4, "storage blocks"},
                          {Kind::StorageImage, 4, "image uniforms"},
                          {Kind::SampledImage, 16, "textures"},
                          {Kind::UniformBuffer, 12, "uniform blocks"}};
  std::string over;
  for (const Limit& l : limits) {
    const std::size_t n = counts[static_cast<int>(l.kind)];
    if (n > l.guaranteed)
      over += (over.empty() ? "" : ", ") + std::to_string(n) + " " + l.what + " (ES 3.1 guarantees " +
              std::to_string(l.guaranteed) + ")";
  }
  return over.empty() ? "fits" : over;
}

std::vector<std::string> check_portability(const Reflection& r, const std::string& shader, const std::string& source) {
  std::vector<std::string> errors;
  auto fail = [&](const std::string& rule, const std::string& detail, const std::string& rejected_by) {
    errors.push_back(source + ": error: " + shader + ": portability rule '" + rule + "' broken: " + detail +
                     "; rejected by " + rejected_by);
  };
  // Variants with ray queries have no WGSL or ESSL output, so only the HAL rules apply to them.
  const bool web = !r.uses_ray_query;

  std::size_t storage_buffers = 0, storage_images = 0;
  for (const auto& b : r.bindings) {
    if (b.kind == Kind::StorageBuffer) ++storage_buffers;
    if (b.kind != Kind::StorageImage) continue;
    ++storage_images;
    if (b.access == Access::ReadWrite && !is_r32(b.format))
      fail("an image both read and written must be r32f, r32ui or r32i",
           "storage image '" + b.name + "' (" + b.format +
               ") is neither readonly nor writeonly; read it as a texture2D with texelFetch and write a "
               "writeonly image, or use an r32 format",
           "WGSL (WebGPU read_write storage textures are r32 only) and ESSL 310 (GLES 3.1 read-write images are "
           "r32 only)");
  }
  if (web && r.uses_image_atomics)
    fail("no image atomics in passes that run on WebGPU", "the shader uses an atomic on a storage image",
         "WGSL (WebGPU has no storage texture atomics) and ESSL 310 (needs OES_shader_image_atomic)");
  if (web && storage_buffers > kWebGpuStorageBuffers)
    fail("stay within WebGPU's default limits",
         std::to_string(storage_buffers) + " storage buffers (maxStorageBuffersPerShaderStage is 8)", "WGSL (WebGPU)");
  if (web && storage_images > kWebGpuStorageTextures)
    fail("stay within WebGPU's default limits",
         std::to_string(storage_images) + " storage images (maxStorageTexturesPerShaderStage is 4)", "WGSL (WebGPU)");
  if (r.uniform_block_count > 1)
    fail("pass parameters in one uniform block", std::to_string(r.uniform_block_count) + " uniform blocks",
         "the HAL (DispatchDesc::uniforms fills one block)");
  if (web && r.uniform_block_count == 1 && !r.uniform_structs.empty()) {
    // WGSL sizes a uniform struct up to its alignment (16 with a vec3/vec4 or a struct inside), and
    // WebGPU refuses a binding smaller than that: the HAL binds the std140 size.
    const auto& block = r.uniform_structs.back();
    std::uint32_t align = 4;
    for (const auto& m : block.members) {
      if (m.padding) continue;
      const bool nested = std::any_of(r.uniform_structs.begin(), r.uniform_structs.end() - 1,
                                      [&](const auto& s) { return s.name == m.type; });
      const bool vector = m.type.starts_with("std::array<");  // arrays and matrices are refused earlier
      const bool pair = vector && m.type.ends_with(", 2>");
      if (nested || (vector && !pair))
        align = 16;
      else if (pair)
        align = std::max(align, 8u);
    }
    if (r.uniform_block_size % align != 0)
      fail("a uniform block's size is a multiple of its alignment",
           std::to_string(r.uniform_block_size) + " bytes, aligned to " + std::to_string(align) +
               "; pad it with uint members to " + std::to_string((r.uniform_block_size + align - 1) / align * align),
           "WGSL (the struct rounds up to its alignment and WebGPU refuses the HAL's smaller binding)");
  }
  for (const auto& name : r.specialization_constants)
    fail("pass parameters in one uniform block", "specialization constant '" + name + "'",
         "the HAL (pipelines take no specializations: use a uniform member or a shader variant)");
  for (const auto& what : r.unsupported)
    fail("bind only uniform/storage buffers, texture2D, storage images and acceleration structures", what,
         "the HAL (hal::BindingKind has no kind for it)");
  return errors;
}

}  // namespace shaderc
