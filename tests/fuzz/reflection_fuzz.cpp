// libFuzzer target for the shader tool's reflection reader: the input is a SPIR-V module (words in
// host order; a trailing partial word is dropped) taken the way asvgf_shaderc takes its own output:
// validated for Vulkan 1.2, then reflected with SPIRV-Cross and checked against the portability
// rules. A clean error is the tool's ToolError (main() prints it and exits 1); any other exception,
// a crash, a sanitizer report, a leak, a hang or an out-of-memory is a finding.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "error.hpp"
#include "portability.hpp"
#include "reflection.hpp"
#include "spirv_tools.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::uint32_t> words(size / 4);
  if (!words.empty()) std::memcpy(words.data(), data, words.size() * 4);
  try {
    shaderc::validate_spirv(words, "fuzz");
    const shaderc::Reflection reflection = shaderc::reflect(words, "fuzz");
    (void)shaderc::check_portability(reflection, "fuzz", "fuzz.comp");
    (void)shaderc::es31_minimum_fit(reflection);
  } catch (const shaderc::ToolError&) {
    // A clean error: the tool reports it and exits 1.
  }
  return 0;
}
