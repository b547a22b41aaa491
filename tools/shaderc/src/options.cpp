#include "options.hpp"

#include <cctype>
#include <span>
#include <string_view>

#include "error.hpp"

namespace shaderc {
namespace {

constexpr std::string_view kUsage =
    "usage: asvgf_shaderc --source FILE.comp --name SHADER [--variant NAME] [--define NAME[=VALUE]]...\n"
    "                     [--include-dir DIR]... --out-dir DIR --header-dir DIR [--depfile FILE]\n"
    "                     --node NODE --node-modules DIR --naga-script FILE.mjs\n";

bool is_identifier(std::string_view s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  for (char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

}  // namespace

Options parse_options(int argc, char** argv) {
  Options o;
  std::span<char*> args(argv + 1, static_cast<std::size_t>(argc > 0 ? argc - 1 : 0));
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string_view flag = args[i];
    if (i + 1 >= args.size())
      throw ToolError("asvgf_shaderc: " + std::string(flag) + " needs a value\n" + std::string(kUsage));
    std::string value = args[++i];
    if (flag == "--source")
      o.source = value;
    else if (flag == "--name")
      o.shader = value;
    else if (flag == "--variant")
      o.variant = value;
    else if (flag == "--define")
      o.defines.push_back(value);
    else if (flag == "--include-dir")
      o.include_dirs.emplace_back(value);
    else if (flag == "--out-dir")
      o.out_dir = value;
    else if (flag == "--header-dir")
      o.header_dir = value;
    else if (flag == "--depfile")
      o.depfile = value;
    else if (flag == "--node")
      o.node = value;
    else if (flag == "--node-modules")
      o.node_modules = value;
    else if (flag == "--naga-script")
      o.naga_script = value;
    else
      throw ToolError("asvgf_shaderc: unknown option " + std::string(flag) + "\n" + std::string(kUsage));
  }
  if (o.source.empty() || o.shader.empty() || o.out_dir.empty() || o.header_dir.empty() || o.node.empty() ||
      o.node_modules.empty() || o.naga_script.empty())
    throw ToolError("asvgf_shaderc: missing a required option\n" + std::string(kUsage));
  // The names become file names and C++ identifiers.
  if (!is_identifier(o.shader)) throw ToolError("asvgf_shaderc: shader name '" + o.shader + "' is not a C identifier");
  if (!o.variant.empty() && !is_identifier(o.variant))
    throw ToolError("asvgf_shaderc: variant name '" + o.variant + "' is not a C identifier");
  for (const auto& d : o.defines)
    if (!is_identifier(std::string_view(d).substr(0, d.find('='))))
      throw ToolError("asvgf_shaderc: define '" + d + "' does not start with a C identifier");
  return o;
}

}  // namespace shaderc
