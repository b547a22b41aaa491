#include "cross_compile.hpp"

#include <spirv_glsl.hpp>
#include <spirv_hlsl.hpp>
#include <spirv_msl.hpp>

namespace shaderc {

std::string to_glsl(const std::vector<std::uint32_t>& spirv, const Reflection& reflection, bool es) {
  spirv_cross::CompilerGLSL compiler(spirv);
  auto options = compiler.get_common_options();
  options.version = es ? 310 : 450;
  options.es = es;
  options.vulkan_semantics = false;
  // Every value in a temporary: otherwise SPIRV-Cross writes a load from a buffer it sees no store
  // to into each use of the value (a packed texel's word read again for its depth, sign and
  // gradient), and NVIDIA's OpenGL compiler keeps several of those loads (docs/performance.md).
  options.force_temporary = true;
  compiler.set_common_options(options);

  // Sets collide in GL (SPIRV-Cross keeps `binding` and drops `set`): give each resource its unit.
  const auto resources = compiler.get_shader_resources();
  for (const auto* list :
       {&resources.uniform_buffers, &resources.storage_buffers, &resources.separate_images, &resources.storage_images})
    for (const auto& r : *list) {
      const auto set = compiler.get_decoration(r.id, spv::DecorationDescriptorSet);
      const auto binding = compiler.get_decoration(r.id, spv::DecorationBinding);
      for (const auto& b : reflection.bindings)
        if (b.set == set && b.binding == binding) compiler.set_decoration(r.id, spv::DecorationBinding, b.gl_binding);
      compiler.unset_decoration(r.id, spv::DecorationDescriptorSet);
    }

  // texelFetch needs no sampler, but GL only has combined samplers: pair each image with a dummy
  // one and give the pair the image's name and binding.
  const auto dummy = compiler.build_dummy_sampler_for_combined_images();
  if (dummy != 0) compiler.set_decoration(dummy, spv::DecorationDescriptorSet, 0);
  compiler.build_combined_image_samplers();
  for (const auto& pair : compiler.get_combined_image_samplers()) {
    compiler.set_name(pair.combined_id, compiler.get_name(pair.image_id));
    compiler.set_decoration(pair.combined_id, spv::DecorationBinding,
                            compiler.get_decoration(pair.image_id, spv::DecorationBinding));
  }
  return compiler.compile();
}

std::string to_hlsl(const std::vector<std::uint32_t>& spirv, bool ray_query) {
  spirv_cross::CompilerHLSL compiler(spirv);
  auto options = compiler.get_hlsl_options();
  options.shader_model = ray_query ? 65 : 60;
  compiler.set_hlsl_options(options);
  return compiler.compile();
}

std::string to_msl(const std::vector<std::uint32_t>& spirv, bool ray_query) {
  spirv_cross::CompilerMSL compiler(spirv);
  auto options = compiler.get_msl_options();
  if (ray_query)
    options.set_msl_version(2, 3);
  else
    options.set_msl_version(2, 1);
  compiler.set_msl_options(options);
  return compiler.compile();
}

}  // namespace shaderc
