// options.hpp: the command line of asvgf_shaderc (one invocation = one shader variant).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace shaderc {

struct Options {
  std::filesystem::path source;                     // the .comp file
  std::string shader;                               // shader name (a C identifier)
  std::string variant;                              // empty: the default variant
  std::vector<std::string> defines;                 // NAME or NAME=VALUE
  std::vector<std::filesystem::path> include_dirs;  // searched after the including file's folder
  std::filesystem::path out_dir;                    // <out_dir>/<full_name>.<ext>
  std::filesystem::path header_dir;                 // <header_dir>/<full_name>.hpp
  std::filesystem::path depfile;                    // empty: none
  std::filesystem::path node;                       // Node.js, for the WGSL step
  std::filesystem::path node_modules;               // holds naga-wasm
  std::filesystem::path naga_script;                // naga_to_wgsl.mjs

  // "<shader>" or "<shader>.<variant>": file names and ShaderInfo::name.
  std::string full_name() const { return variant.empty() ? shader : shader + "." + variant; }
  // "<shader>" or "<shader>_<variant>": the C++ object in the generated header.
  std::string cpp_name() const { return variant.empty() ? shader : shader + "_" + variant; }
  std::filesystem::path output(const std::string& ext) const { return out_dir / (full_name() + "." + ext); }
};

// Throws ToolError with a usage message on bad arguments.
Options parse_options(int argc, char** argv);

}  // namespace shaderc
