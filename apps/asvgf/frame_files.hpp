// Output file names and whole-file writes shared by `asvgf render` and `asvgf denoise`.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "io/atomic_file.hpp"

namespace asvgf::cli {

// "<prefix>_NNNN.<ext>", e.g. frame_0007.exr.
inline std::string frame_file(const char* prefix, int frame, const char* ext) {
  char name[64];
  std::snprintf(name, sizeof name, "%s_%04d.%s", prefix, frame, ext);
  return name;
}

// DIR/metrics.csv, whole or not at all (io/atomic_file.hpp).
inline void write_metrics_csv(const std::filesystem::path& dir, const std::string& csv) {
  render::write_file_atomic(dir / "metrics.csv", csv);
}

// Throws CLI::ValidationError naming both files when an output would replace an input: compared as
// files (device and inode), so links and ".." are seen through. Pairs are (option, path).
void refuse_overwriting_inputs(const std::vector<std::pair<std::string, std::filesystem::path>>& inputs,
                               const std::vector<std::pair<std::string, std::filesystem::path>>& outputs);

// Throws CLI::ValidationError naming `option` and the file when an input file lies in `folder`
// (compared as files: links and ".." are seen through).
void refuse_folder_holding_inputs(const std::string& option, const std::filesystem::path& folder,
                                  const std::vector<std::pair<std::string, std::filesystem::path>>& inputs);

// Removes the temporary files that killed runs left in `folder` and says so on stderr.
void report_stale_partials(const char* command, const std::filesystem::path& folder);

}  // namespace asvgf::cli
