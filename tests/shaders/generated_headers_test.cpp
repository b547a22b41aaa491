// The generated headers (tools/shaderc) describe the three HAL test shaders exactly as their
// GLSL declares them: the Vulkan backend binds by these names and fills uniforms at these offsets.
#include <doctest/doctest.h>

#include <shaders/hal_test_image.hpp>
#include <shaders/hal_test_ray_query.rayquery.hpp>
#include <shaders/hal_test_scale.hpp>

namespace {

using asvgf::shaders::hal_test_image;
using asvgf::shaders::hal_test_ray_query_rayquery;
using asvgf::shaders::hal_test_scale;

// The header is constexpr: binding lookups can be checked at compile time.
// (A binding field, not the pointer: GCC cannot compare a pointer to null in a constant expression
// under -fsanitize=address.)
static_assert(hal_test_scale.find("src")->binding == 1);
static_assert(hal_test_scale.workgroup_size[0] == 64);

void check_binding(const hal::ShaderInfo& info, std::string_view name, std::uint32_t binding, hal::BindingKind kind,
                   hal::Access access, hal::Format format = hal::Format::Undefined) {
  CAPTURE(info.name);
  CAPTURE(name);
  const hal::ShaderBinding* b = info.find(name);
  REQUIRE(b != nullptr);
  CHECK(b->set == 0);
  CHECK(b->binding == binding);
  CHECK(b->kind == kind);
  CHECK(b->access == access);
  CHECK(b->format == format);
}

}  // namespace

TEST_CASE("generated header of hal_test_scale lists its bindings, workgroup size and std140 uniform layout") {
  const auto& s = hal_test_scale;
  CHECK(s.name == "hal_test_scale");
  REQUIRE(s.spirv.size() > 5);
  CHECK(s.spirv[0] == 0x07230203u);  // SPIR-V magic
  CHECK(s.bindings.size() == 3);
  check_binding(s, "params", 0, hal::BindingKind::UniformBuffer, hal::Access::Read);
  check_binding(s, "src", 1, hal::BindingKind::StorageBuffer, hal::Access::Read);
  check_binding(s, "dst", 2, hal::BindingKind::StorageBuffer, hal::Access::Write);
  CHECK(s.find("Input") == nullptr);  // block names are not binding names
  CHECK(s.workgroup_size == std::array<std::uint32_t, 3>{64, 1, 1});
  CHECK(s.uniform_block_size == 12);
  REQUIRE(s.uniform_members.size() == 3);
  CHECK(s.uniform_members[0].name == "count");
  CHECK(s.uniform_members[1].name == "scale");
  CHECK(s.uniform_members[1].offset == 4);
  CHECK(s.uniform_members[2].name == "offset");
  CHECK(s.uniform_members[2].offset == 8);
  CHECK(s.uniform_members[2].size == 4);
  CHECK_FALSE(s.uses_ray_query);
}

TEST_CASE("generated header of hal_test_image lists a sampled texture and a writeonly rgba32f image") {
  const auto& s = hal_test_image;
  CHECK(s.name == "hal_test_image");
  CHECK(s.bindings.size() == 3);
  check_binding(s, "params", 0, hal::BindingKind::UniformBuffer, hal::Access::Read);
  check_binding(s, "src_image", 1, hal::BindingKind::SampledImage, hal::Access::Read);
  check_binding(s, "dst_image", 2, hal::BindingKind::StorageImage, hal::Access::Write, hal::Format::RGBA32F);
  CHECK(s.workgroup_size == std::array<std::uint32_t, 3>{8, 8, 1});
  CHECK(s.uniform_block_size == 16);
  REQUIRE(s.uniform_members.size() == 4);
  CHECK(s.uniform_members[3].name == "offset");
  CHECK(s.uniform_members[3].offset == 12);
  CHECK_FALSE(s.uses_ray_query);
}

TEST_CASE("generated header of the rayquery variant of hal_test_ray_query marks ray query use") {
  const auto& s = hal_test_ray_query_rayquery;
  CHECK(s.name == "hal_test_ray_query.rayquery");
  CHECK(s.uses_ray_query);
  CHECK(s.bindings.size() == 4);
  check_binding(s, "params", 0, hal::BindingKind::UniformBuffer, hal::Access::Read);
  check_binding(s, "scene", 1, hal::BindingKind::AccelerationStructure, hal::Access::Read);
  check_binding(s, "rays", 2, hal::BindingKind::StorageBuffer, hal::Access::Read);
  check_binding(s, "hits", 3, hal::BindingKind::StorageBuffer, hal::Access::Write);
  CHECK(s.workgroup_size == std::array<std::uint32_t, 3>{64, 1, 1});
  CHECK(s.uniform_block_size == 4);
}
