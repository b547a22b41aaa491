// asvgf_shaderc: compiles one GLSL compute shader variant into SPIR-V, GLSL 450, ESSL 310, HLSL,
// MSL and WGSL, plus a reflection JSON, a generated C++ header (hal::ShaderInfo) and a depfile.
// CMake runs it through asvgf_add_shader() (shaders/CMakeLists.txt); see the README section.
#include <spirv_cross.hpp>

#include <iostream>
#include <string>

#include "cross_compile.hpp"
#include "emit.hpp"
#include "error.hpp"
#include "files.hpp"
#include "glsl_compile.hpp"
#include "options.hpp"
#include "portability.hpp"
#include "reflection.hpp"
#include "spirv_tools.hpp"
#include "wgsl.hpp"

namespace shaderc {
namespace {

namespace fs = std::filesystem;

std::string depfile_escape(const fs::path& path) {
  std::string out;
  for (char c : path.string()) {
    if (c == ' ' || c == '#') out += '\\';
    if (c == '$') out += '$';
    out += c;
  }
  return out;
}

// Runs one SPIRV-Cross backend. A failure is an error, except for ray-query variants, where it
// only skips the target (SPIRV-Cross' ray query support differs between backends and versions).
template <class Fn>
void cross_target(const Options& o, bool ray_query, const std::string& ext, const std::string& target, Targets& targets,
                  Fn&& fn) {
  try {
    write_if_changed(o.output(ext), fn());
    targets.emitted[ext] = o.output(ext).filename().string();
  } catch (const spirv_cross::CompilerError& e) {
    const std::string file = fs::absolute(o.source).string();
    const std::string what = o.full_name() + ": " + target + ": SPIRV-Cross cannot translate it: " + e.what();
    if (!ray_query) throw ToolError(file + ": error: " + what);
    std::cerr << file << ": warning: " << what << "; " << target << " is not emitted for this variant\n";
    targets.skipped[ext] = std::string("SPIRV-Cross cannot translate ray queries to ") + target + ": " + e.what();
    remove_stale(o.output(ext));
  }
}

void skip(const Options& o, Targets& targets, const std::string& ext, const std::string& reason) {
  targets.skipped[ext] = reason;
  remove_stale(o.output(ext));
}

int run(const Options& o) {
  const std::string source = fs::absolute(o.source).string();
  GlslResult glsl = compile_glsl(o);
  for (const auto& w : glsl.warnings) std::cerr << w << "\n";

  const auto spirv = optimize_spirv(glsl.spirv, o.full_name());
  validate_spirv(spirv, o.full_name());
  const Reflection reflection = reflect(spirv, o.full_name());

  const auto violations = check_portability(reflection, o.full_name(), source);
  if (!violations.empty()) {
    for (const auto& v : violations) std::cerr << v << "\n";
    return 1;
  }

  Targets targets;
  write_if_changed(o.output("spv"), std::string_view(reinterpret_cast<const char*>(spirv.data()), spirv.size() * 4));
  targets.emitted["spv"] = o.output("spv").filename().string();

  const bool rq = reflection.uses_ray_query;
  std::string glsl_text, essl_text;     // embedded in the header for the OpenGL backend
  std::vector<std::uint32_t> gl_spirv;  // the same, as SPIR-V for GL_ARB_gl_spirv
  if (rq) {
    skip(o, targets, "glsl", "ray queries need Vulkan GLSL; OpenGL has no acceleration structures");
    skip(o, targets, "essl", "ray queries need Vulkan GLSL; OpenGL ES has no acceleration structures");
    skip(o, targets, "gl.spv", "ray queries need Vulkan; OpenGL has no acceleration structures");
    skip(o, targets, "wgsl", "WebGPU and naga have no ray queries");
  } else {
    cross_target(o, rq, "glsl", "GLSL 450", targets, [&] { return glsl_text = to_glsl(spirv, reflection, false); });
    cross_target(o, rq, "essl", "ESSL 310", targets, [&] { return essl_text = to_glsl(spirv, reflection, true); });
    gl_spirv = optimize_spirv(compile_gl_spirv(glsl_text, o.full_name()), o.full_name(), SpirvEnv::OpenGl45);
    validate_spirv(gl_spirv, o.full_name(), SpirvEnv::OpenGl45);
    write_if_changed(o.output("gl.spv"),
                     std::string_view(reinterpret_cast<const char*>(gl_spirv.data()), gl_spirv.size() * 4));
    targets.emitted["gl.spv"] = o.output("gl.spv").filename().string();
  }
  cross_target(o, rq, "hlsl", rq ? "HLSL SM 6.5" : "HLSL SM 6.0", targets, [&] { return to_hlsl(spirv, rq); });
  cross_target(o, rq, "msl", rq ? "MSL 2.3" : "MSL 2.1", targets, [&] { return to_msl(spirv, rq); });
  if (!rq) {
    write_if_changed(o.output("wgsl"), to_wgsl(o, o.output("spv")));
    targets.emitted["wgsl"] = o.output("wgsl").filename().string();
  }

  write_if_changed(o.output("json"), json_text(o, reflection, targets));
  const fs::path header = o.header_dir / (o.full_name() + ".hpp");
  write_if_changed(header, header_text(o, reflection, spirv, glsl_text, essl_text, gl_spirv));

  if (!o.depfile.empty()) {
    std::string dep = depfile_escape(fs::absolute(header)) + ":";
    dep += " " + depfile_escape(fs::absolute(o.source));
    for (const auto& inc : glsl.includes) dep += " " + depfile_escape(inc);
    write_if_changed(o.depfile, dep + "\n");
  }
  return 0;
}

}  // namespace
}  // namespace shaderc

int main(int argc, char** argv) {
  try {
    return shaderc::run(shaderc::parse_options(argc, argv));
  } catch (const shaderc::ToolError& e) {
    std::cerr << e.what() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "asvgf_shaderc: error: " << e.what() << "\n";
  }
  return 1;
}
