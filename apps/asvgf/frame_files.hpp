// Output file names and whole-file writes shared by `asvgf render` and `asvgf denoise`.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

#include "render/atomic_file.hpp"

namespace asvgf::cli {

// "<prefix>_NNNN.<ext>", e.g. frame_0007.exr.
inline std::string frame_file(const char* prefix, int frame, const char* ext) {
  char name[64];
  std::snprintf(name, sizeof name, "%s_%04d.%s", prefix, frame, ext);
  return name;
}

// DIR/metrics.csv, whole or not at all (render/atomic_file.hpp).
inline void write_metrics_csv(const std::filesystem::path& dir, const std::string& csv) {
  render::write_file_atomic(dir / "metrics.csv", csv);
}

}  // namespace asvgf::cli
