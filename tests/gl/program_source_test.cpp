// Which translation the OpenGL backend loads: with SPIR-V programs chosen (ASVGF_GL_SHADERS=spirv,
// the default on NVIDIA) a shader is loaded from its OpenGL SPIR-V or refused, never compiled from
// its GLSL behind the caller's back; the SPIR-V suites would otherwise pass on GLSL programs.
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
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

namespace {

void write_text(const std::filesystem::path& path, std::string_view text) {
  std::ofstream out(path, std::ios::trunc);
  out << text;
}

}  // namespace

TEST_CASE(
    "gl programs: ASVGF_GL_PROGRAM_SOURCE compiles a shader from the folder's <name>.glsl, SPIR-V chosen or not, and "
    "refuses a missing folder") {
  // Per process: ctest runs this case on its own and again inside the whole SPIR-V suite, side by side.
  const std::filesystem::path folder = std::filesystem::path("gl_program_source") / std::to_string(getpid());
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const EnvGuard spirv("ASVGF_GL_SHADERS", "spirv");
  const EnvGuard source("ASVGF_GL_PROGRAM_SOURCE", folder.string().c_str());
  std::vector<std::string> messages;
  auto device = open_gl(hal::gl::Flavour::Gl, messages);
  const hal::ShaderInfo& shader = asvgf::shaders::hal_test_scale;
  const std::filesystem::path file = folder / (std::string(shader.name) + ".glsl");

  // No file for the shader: its embedded program, as without the variable.
  device->destroy(device->create_pipeline({"scale", &shader}));
  // The file is what gets compiled: a broken one fails in the GL compiler, under the shader's name.
  write_text(file, "#version 450\nnot a shader\n");
  CHECK_THROWS_WITH_AS(device->create_pipeline({"scale", &shader}),
                       doctest::Contains("the GL compiler rejects shader 'hal_test_scale'"), hal::Error);
  // Its own GLSL, as a porter would start from a dump: compiled from GLSL though SPIR-V is chosen.
  write_text(file, shader.source("glsl"));
  device->destroy(device->create_pipeline({"scale", &shader}));
  // An empty file is an error that names it, not the embedded program in its place.
  write_text(file, "");
  CHECK_THROWS_WITH_AS(device->create_pipeline({"scale", &shader}), doctest::Contains(file.string().c_str()),
                       hal::Error);
  CHECK(messages.empty());
  // A folder that is not there is an error, not the embedded programs timed unannounced.
  std::filesystem::remove_all(folder);
  CHECK_THROWS_WITH_AS(device->create_pipeline({"scale", &shader}), doctest::Contains("no such folder"), hal::Error);
}
