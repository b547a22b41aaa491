#include "spirv_tools.hpp"

#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

#include "error.hpp"

namespace shaderc {
namespace {

spv_target_env target_env(SpirvEnv env) {
  return env == SpirvEnv::OpenGl45 ? SPV_ENV_OPENGL_4_5 : SPV_ENV_VULKAN_1_2;
}

spvtools::MessageConsumer collect(std::string& log) {
  return [&log](spv_message_level_t, const char*, const spv_position_t& pos, const char* message) {
    log += "  word " + std::to_string(pos.index) + ": " + message + "\n";
  };
}

}  // namespace

std::vector<std::uint32_t> optimize_spirv(const std::vector<std::uint32_t>& spirv, const std::string& shader,
                                          SpirvEnv env) {
  std::string log;
  spvtools::Optimizer optimizer(target_env(env));
  optimizer.SetMessageConsumer(collect(log));
  optimizer.RegisterPerformancePasses();
  // Loops the source marks [[unroll]] are unrolled here, so that every target gets straight code
  // (NVIDIA's OpenGL SPIR-V front end keeps a loop as a conditional loop; docs/performance.md).
  optimizer.RegisterPass(spvtools::CreateLoopUnrollPass(true));
  optimizer.RegisterPerformancePasses();
  std::vector<std::uint32_t> out;
  if (!optimizer.Run(spirv.data(), spirv.size(), &out))
    throw ToolError(shader + ": error: SPIR-V optimisation failed:\n" + log);
  return out;
}

void validate_spirv(const std::vector<std::uint32_t>& spirv, const std::string& shader, SpirvEnv env) {
  std::string log;
  spvtools::SpirvTools tools(target_env(env));
  tools.SetMessageConsumer(collect(log));
  const char* name = env == SpirvEnv::OpenGl45 ? "opengl4.5" : "vulkan1.2";
  if (!tools.Validate(spirv))
    throw ToolError(shader + ": error: emitted SPIR-V fails validation (" + name + "):\n" + log);
}

}  // namespace shaderc
