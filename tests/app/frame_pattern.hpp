// The test tools' one frame-pattern expansion: a printf pattern with one frame number
// ("frames/frame_%04d.exr") and a frame, as the frames' file name.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

inline std::string expand_frame_pattern(const char* pattern, int frame) {
  std::vector<char> buffer(std::string(pattern).size() + 32);
  std::snprintf(buffer.data(), buffer.size(), pattern, frame);
  return buffer.data();
}
