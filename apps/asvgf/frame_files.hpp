// Output file names and whole-file writes shared by `asvgf render` and `asvgf denoise`.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace asvgf::cli {

// "<prefix>_NNNN.<ext>", e.g. frame_0007.exr.
inline std::string frame_file(const char* prefix, int frame, const char* ext) {
  char name[64];
  std::snprintf(name, sizeof name, "%s_%04d.%s", prefix, frame, ext);
  return name;
}

// DIR/metrics.csv, written to a temporary name and renamed, so that it appears whole or not at all.
inline void write_metrics_csv(const std::filesystem::path& dir, const std::string& csv) {
  const auto tmp = dir / "metrics.csv.partial";
  std::ofstream(tmp) << csv;
  std::filesystem::rename(tmp, dir / "metrics.csv");
}

}  // namespace asvgf::cli
