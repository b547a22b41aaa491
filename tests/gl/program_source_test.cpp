// Which translation the OpenGL backend loads: with SPIR-V programs chosen (ASVGF_GL_SHADERS=spirv,
// the default on NVIDIA) a shader is loaded from its OpenGL SPIR-V or refused, never compiled from
// its GLSL behind the caller's back; the SPIR-V suites would otherwise pass on GLSL programs.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "env_guard.hpp"
#include "gl/gl_device.hpp"
#include "hal/error.hpp"
#include "shaders/hal_test_scale.hpp"

namespace {

// hal_test_scale with its translations but the one named `dropped`.
struct ShaderWithout {
  std::vector<hal::ShaderSource> sources;
  hal::ShaderInfo info;
  explicit ShaderWithout(std::string_view dropped) : info(asvgf::shaders::hal_test_scale) {
    for (const auto& s : info.sources)
      if (s.language != dropped) sources.push_back(s);
    info.sources = sources;
  }
};

}  // namespace

TEST_CASE("gl programs: with SPIR-V chosen, a shader without its OpenGL SPIR-V is refused, not compiled from GLSL") {
  const EnvGuard spirv("ASVGF_GL_SHADERS", "spirv");
  std::vector<std::string> messages;
  auto device = open_gl(hal::gl::Flavour::Gl, messages);
  REQUIRE(device->adapter().api_version.find("programs from SPIR-V") != std::string::npos);

  // The whole shader loads.
  const hal::PipelineHandle whole = device->create_pipeline({"scale", &asvgf::shaders::hal_test_scale});
  device->destroy(whole);

  const ShaderWithout no_spirv("spirv-gl");
  REQUIRE(!no_spirv.info.source("glsl").empty());
  CHECK_THROWS_WITH_AS(device->create_pipeline({"scale without spirv-gl", &no_spirv.info}),
                       doctest::Contains("has no OpenGL SPIR-V translation (spirv-gl)"), hal::Error);
  CHECK(messages.empty());
}

TEST_CASE("gl programs: with GLSL chosen, a shader without its OpenGL SPIR-V still compiles from GLSL") {
  const EnvGuard glsl("ASVGF_GL_SHADERS", "glsl");
  std::vector<std::string> messages;
  auto device = open_gl(hal::gl::Flavour::Gl, messages);
  REQUIRE(device->adapter().api_version.find("programs from GLSL") != std::string::npos);
  const ShaderWithout no_spirv("spirv-gl");
  const hal::PipelineHandle p = device->create_pipeline({"scale without spirv-gl", &no_spirv.info});
  device->destroy(p);
  CHECK(messages.empty());
}
