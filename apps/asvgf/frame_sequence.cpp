#include "frame_sequence.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>

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

std::optional<int> FramePattern::frame_of(const std::filesystem::path& file) const {
  // The literal text around the one conversion (%% unescaped), then digits between them.
  const std::size_t at = [&] {
    for (std::size_t i = 0; i < pattern_.size(); ++i)
      if (pattern_[i] == '%') {
        if (pattern_[i + 1] == '%')
          ++i;
        else
          return i;
      }
    return pattern_.size();
  }();
  const std::size_t end = pattern_.find('d', at);
  auto literal = [](std::string text) {
    for (std::size_t i = text.find("%%"); i != std::string::npos; i = text.find("%%", i + 1)) text.erase(i, 1);
    return text;
  };
  const std::string prefix = std::filesystem::path(literal(pattern_.substr(0, at))).filename().string();
  const std::string suffix = literal(pattern_.substr(end + 1));
  const std::string name = file.filename().string();
  if (suffix.find('/') != std::string::npos || name.size() <= prefix.size() + suffix.size()) return std::nullopt;
  if (name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return std::nullopt;
  const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
  if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
  const int frame = std::stoi(digits);
  if (path(frame).filename() != file.filename()) return std::nullopt;  // another width, e.g. 7 for %04d
  return frame;
}

std::optional<int> FramePattern::lowest_frame() const {
  const std::filesystem::path folder = path(0).parent_path();
  std::error_code ec;
  std::optional<int> lowest;
  for (const auto& entry : std::filesystem::directory_iterator(folder.empty() ? "." : folder, ec)) {
    const auto frame = frame_of(entry.path());
    if (frame && (!lowest || *frame < *lowest)) lowest = frame;
  }
  return lowest;
}

int count_frames(const FramePattern& pattern, int first, int wanted) {
  int n = 0;
  while (std::filesystem::exists(pattern.path(first + n))) ++n;
  if (n == 0 || (wanted > 0 && n >= wanted)) return n;
  // A missing frame ends the sequence only when no later frame exists: otherwise it is a gap.
  const int missing = first + n;
  const std::filesystem::path folder = pattern.path(missing).parent_path();
  std::error_code ec;
  std::optional<int> later;
  for (const auto& entry : std::filesystem::directory_iterator(folder.empty() ? "." : folder, ec)) {
    const auto frame = pattern.frame_of(entry.path());
    if (frame && *frame > missing && (!later || *frame < *later)) later = frame;
  }
  if (later)
    throw render::ImageIoError(pattern.path(missing).string() + " (" + pattern.option() + ", frame " +
                               std::to_string(missing) + "): missing, but frame " + std::to_string(*later) +
                               " exists: a gap in the sequence (--frames " + std::to_string(n) +
                               " denoises the frames before it)");
  return n;
}

namespace {

std::string frame_what(const std::filesystem::path& path, int frame, const BufferSpec& spec) {
  return path.string() + " (" + spec.name + ", frame " + std::to_string(frame) + ")";
}

void check_size(const std::string& what, std::uint32_t width, std::uint32_t height, const BufferSpec& spec) {
  if (spec.width && (width != spec.width || height != spec.height))
    throw render::ImageIoError(what + ": " + std::to_string(width) + "x" + std::to_string(height) + ", expected " +
                               std::to_string(spec.width) + "x" + std::to_string(spec.height));
}

}  // namespace

void check_frame_header(const FramePattern& pattern, int frame, const BufferSpec& spec) {
  const std::filesystem::path path = pattern.path(frame);
  if (!std::filesystem::exists(path)) return;
  const render::ExrHeader header = render::read_exr_header(path);
  check_size(frame_what(path, frame, spec), header.width, header.height, spec);
}

render::ExrImage read_frame(const FramePattern& pattern, int frame, const BufferSpec& spec) {
  const std::filesystem::path path = pattern.path(frame);
  const std::string what = frame_what(path, frame, spec);
  if (!std::filesystem::exists(path)) throw render::ImageIoError(what + ": missing");
  render::ExrImage image = render::read_exr(path, spec.file_channels);
  check_size(what, image.width, image.height, spec);
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
