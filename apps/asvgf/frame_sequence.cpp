#include "frame_sequence.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace asvgf::cli {

FramePattern::FramePattern(std::string option, std::string pattern)
    : option_(std::move(option)), pattern_(std::move(pattern)) {
  int conversions = 0;
  for (std::size_t i = 0; i < pattern_.size(); ++i) {
    if (pattern_[i] != '%') continue;
    if (i + 1 < pattern_.size() && pattern_[i + 1] == '%') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < pattern_.size() && std::isdigit(static_cast<unsigned char>(pattern_[j]))) ++j;
    if (j >= pattern_.size() || pattern_[j] != 'd' || j - i > 4)
      throw CLI::ValidationError(option_, "'" + pattern_ + "': only %d, %Nd or %0Nd (N < 100) and %% may appear");
    ++conversions;
    i = j;
  }
  if (conversions != 1)
    throw CLI::ValidationError(option_, "'" + pattern_ + "' must hold exactly one frame number (e.g. color_%04d.exr)");
}

std::filesystem::path FramePattern::path(int frame) const {
  const int length = std::snprintf(nullptr, 0, pattern_.c_str(), frame);
  std::vector<char> buffer(static_cast<std::size_t>(std::max(length, 0)) + 1);
  std::snprintf(buffer.data(), buffer.size(), pattern_.c_str(), frame);
  return std::filesystem::path(buffer.data());
}

int count_frames(const FramePattern& pattern, int first) {
  int n = 0;
  while (std::filesystem::exists(pattern.path(first + n))) ++n;
  return n;
}

render::ExrImage read_frame(const FramePattern& pattern, int frame, const BufferSpec& spec) {
  const std::filesystem::path path = pattern.path(frame);
  const std::string what = path.string() + " (" + spec.name + ", frame " + std::to_string(frame) + ")";
  if (!std::filesystem::exists(path)) throw render::ImageIoError(what + ": missing");
  render::ExrImage image = render::read_exr(path);
  if (spec.width && (image.width != spec.width || image.height != spec.height))
    throw render::ImageIoError(what + ": " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                               ", expected " + std::to_string(spec.width) + "x" + std::to_string(spec.height));
  for (const auto& c : spec.channels)
    if (std::find(image.channels.begin(), image.channels.end(), c) == image.channels.end())
      throw render::ImageIoError(what + ": no channel " + c + " (the " + spec.name + " buffer needs " +
                                 std::to_string(spec.channels.size()) + " channels)");
  const std::size_t used = spec.channels.size();
  for (std::size_t i = 0; i < image.rgba.size(); ++i)
    if (i % 4 < used && !std::isfinite(image.rgba[i]) && !(spec.infinity_allowed && std::isinf(image.rgba[i]))) {
      const std::size_t p = i / 4;
      throw render::ImageIoError(what + ": " + (std::isnan(image.rgba[i]) ? "NaN" : "Inf") + " in channel " +
                                 spec.channels[i % 4] + " at pixel (" + std::to_string(p % image.width) + ", " +
                                 std::to_string(p / image.width) + ")");
    }
  return image;
}

}  // namespace asvgf::cli
