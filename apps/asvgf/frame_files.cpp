#include "frame_files.hpp"

#include <sys/stat.h>

#include <CLI/CLI.hpp>
#include <map>

namespace asvgf::cli {

void refuse_overwriting_inputs(const std::vector<std::pair<std::string, std::filesystem::path>>& inputs,
                               const std::vector<std::pair<std::string, std::filesystem::path>>& outputs) {
  std::map<std::pair<dev_t, ino_t>, const std::pair<std::string, std::filesystem::path>*> files;
  struct stat st {};
  for (const auto& in : inputs)
    if (::stat(in.second.c_str(), &st) == 0) files.emplace(std::pair{st.st_dev, st.st_ino}, &in);
  for (const auto& out : outputs) {
    if (::stat(out.second.c_str(), &st) != 0) continue;  // a file that does not exist replaces nothing
    const auto hit = files.find({st.st_dev, st.st_ino});
    if (hit != files.end())
      throw CLI::ValidationError(out.first, "'" + out.second.string() + "' would replace the input '" +
                                                hit->second->second.string() + "' (" + hit->second->first +
                                                "): choose another " + out.first);
  }
}

void refuse_folder_holding_inputs(const std::string& option, const std::filesystem::path& folder,
                                  const std::vector<std::pair<std::string, std::filesystem::path>>& inputs) {
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) return;  // a folder yet to be made holds nothing
  for (const auto& in : inputs) {
    const auto parent = std::filesystem::absolute(in.second, ec).parent_path();
    if (std::filesystem::exists(in.second, ec) && std::filesystem::equivalent(parent, folder, ec))
      throw CLI::ValidationError(option, "'" + folder.string() + "' holds the input '" + in.second.string() + "' (" +
                                             in.first + "), which a report could replace: choose another " + option);
  }
}

void report_stale_partials(const char* command, const std::filesystem::path& folder) {
  for (const auto& file : render::remove_stale_partials(folder))
    std::fprintf(stderr, "asvgf %s: removed %s, a temporary file of a run that did not finish\n", command,
                 file.string().c_str());
}

}  // namespace asvgf::cli
