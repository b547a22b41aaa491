#include "wgsl.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <memory>

#include "error.hpp"
#include "files.hpp"

namespace shaderc {
namespace {

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

std::string to_wgsl(const Options& o, const std::filesystem::path& spv) {
  auto tmp = o.output("wgsl");
  tmp += ".new";
  const std::string command = quote(o.node.string()) + " " + quote(o.naga_script.string()) + " " +
                              quote(o.node_modules.string()) + " " + quote(spv.string()) + " " + quote(tmp.string()) +
                              " 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) throw ToolError(o.full_name() + ": error: cannot run Node for the WGSL step: " + command);
  std::string log;
  std::array<char, 4096> buf{};
  while (auto n = std::fread(buf.data(), 1, buf.size(), pipe.get())) log.append(buf.data(), n);
  const int status = pclose(pipe.release());
  if (status != 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    remove_stale(tmp);
    throw ToolError(std::filesystem::absolute(o.source).string() + ": error: " + o.full_name() +
                    ": WGSL: naga cannot translate the SPIR-V:\n" + log);
  }
  std::string text = read_file(tmp);
  remove_stale(tmp);
  return text;
}

}  // namespace shaderc
