#include "glsl_compile.hpp"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <memory>
#include <regex>
#include <sstream>

#include "error.hpp"
#include "files.hpp"

namespace shaderc {
namespace {

namespace fs = std::filesystem;

// Resolves "file" relative to the including file, then in the include dirs; <file> only in the
// include dirs. Records every file it opens for the depfile.
class Includer final : public glslang::TShader::Includer {
 public:
  explicit Includer(const std::vector<fs::path>& dirs) : dirs_(dirs) {}

  IncludeResult* includeLocal(const char* name, const char* includer, size_t) override {
    if (auto* r = open(fs::path(includer).parent_path() / name)) return r;
    return includeSystem(name, includer, 0);
  }
  IncludeResult* includeSystem(const char* name, const char*, size_t) override {
    for (const auto& dir : dirs_)
      if (auto* r = open(dir / name)) return r;
    // An empty headerName reports failure; glslang 12 crashes on a nullptr result.
    auto* why = new std::string("file not found next to the including file or in the include directories");
    return new IncludeResult("", why->data(), why->size(), why);
  }
  void releaseInclude(IncludeResult* result) override {
    delete static_cast<std::string*>(result->userData);
    delete result;
  }
  const std::vector<fs::path>& opened() const { return opened_; }

 private:
  IncludeResult* open(const fs::path& candidate) {
    std::error_code ec;
    if (!fs::is_regular_file(candidate, ec)) return nullptr;
    auto path = fs::weakly_canonical(candidate, ec);
    auto* text = new std::string(read_file(path));
    opened_.push_back(path);
    return new IncludeResult(path.string(), text->data(), text->size(), text);
  }

  std::vector<fs::path> dirs_;
  std::vector<fs::path> opened_;
};

// glslang writes "ERROR: file:line: message"; compilers and IDEs expect "file:line: error: message".
std::vector<std::string> reformat_log(const std::string& log, const std::string& fallback_file) {
  static const std::regex located(R"(^(ERROR|WARNING): (.+):(\d+): (.*)$)");
  static const std::regex summary(R"(^(ERROR|WARNING): \d+ compilation errors\..*$)");
  std::vector<std::string> lines;
  std::istringstream in(log);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (line.empty() || std::regex_match(line, summary)) continue;
    if (std::regex_match(line, m, located)) {
      std::string level = m[1] == "ERROR" ? "error" : "warning";
      lines.push_back(m[2].str() + ":" + m[3].str() + ": " + level + ": " + m[4].str());
    } else if (line.rfind("ERROR: ", 0) == 0) {
      lines.push_back(fallback_file + ": error: " + line.substr(7));
    } else if (line.rfind("WARNING: ", 0) == 0) {
      lines.push_back(fallback_file + ": warning: " + line.substr(9));
    } else {
      lines.push_back(fallback_file + ": " + line);
    }
  }
  return lines;
}

std::string join(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

// glslang keeps global state; initialise it once per process.
struct ProcessScope {
  ProcessScope() { glslang::InitializeProcess(); }
  ~ProcessScope() { glslang::FinalizeProcess(); }
  ProcessScope(const ProcessScope&) = delete;
  ProcessScope& operator=(const ProcessScope&) = delete;
};
void start_glslang() {
  static ProcessScope process;
}

}  // namespace

GlslResult compile_glsl(const Options& options) {
  start_glslang();
  const fs::path source_path = fs::absolute(options.source);
  const std::string file = source_path.string();
  const std::string text = read_file(source_path);

  std::string preamble;
  for (const auto& d : options.defines) {
    auto eq = d.find('=');
    preamble += "#define " + (eq == std::string::npos ? d + " 1" : d.substr(0, eq) + " " + d.substr(eq + 1)) + "\n";
  }

  glslang::TShader shader(EShLangCompute);
  const char* strings[] = {text.c_str()};
  const int lengths[] = {static_cast<int>(text.size())};
  const char* names[] = {file.c_str()};
  shader.setStringsWithLengthsAndNames(strings, lengths, names, 1);
  shader.setPreamble(preamble.c_str());
  shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);

  const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  Includer includer(options.include_dirs);
  GlslResult result;
  if (!shader.parse(GetDefaultResources(), 460, false, messages, includer))
    throw ToolError(join(reformat_log(shader.getInfoLog(), file)) + file + ": error: GLSL compilation failed");
  for (auto& w : reformat_log(shader.getInfoLog(), file)) result.warnings.push_back(std::move(w));

  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages))
    throw ToolError(join(reformat_log(program.getInfoLog(), file)) + file + ": error: GLSL link failed");

  spv::SpvBuildLogger logger;
  glslang::SpvOptions spv_options;
  spv_options.disableOptimizer = true;  // SPIRV-Tools runs next, with validation
  glslang::GlslangToSpv(*program.getIntermediate(EShLangCompute), result.spirv, &logger, &spv_options);
  if (auto log = logger.getAllMessages(); !log.empty() && result.spirv.empty())
    throw ToolError(file + ": error: SPIR-V generation failed: " + log);
  result.includes = includer.opened();
  return result;
}

std::vector<std::uint32_t> compile_gl_spirv(const std::string& glsl, const std::string& shader_name) {
  start_glslang();
  glslang::TShader shader(EShLangCompute);
  const char* strings[] = {glsl.c_str()};
  const int lengths[] = {static_cast<int>(glsl.size())};
  shader.setStringsWithLengths(strings, lengths, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientOpenGL, 100);
  shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules);
  const std::string what = shader_name + ": OpenGL SPIR-V: ";
  if (!shader.parse(GetDefaultResources(), 450, false, messages))
    throw ToolError(what + "glslang rejects the GLSL 450 translation:\n" + shader.getInfoLog());
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) throw ToolError(what + "link failed:\n" + std::string(program.getInfoLog()));
  std::vector<std::uint32_t> spirv;
  spv::SpvBuildLogger logger;
  glslang::SpvOptions spv_options;
  spv_options.disableOptimizer = true;  // SPIRV-Tools runs next, with validation
  glslang::GlslangToSpv(*program.getIntermediate(EShLangCompute), spirv, &logger, &spv_options);
  if (spirv.empty()) throw ToolError(what + "SPIR-V generation failed: " + logger.getAllMessages());
  return spirv;
}

}  // namespace shaderc
