// Frame sequences on disk for `asvgf denoise`: printf-style file patterns (frames/color_%04d.exr)
// and one frame's EXR checked against what the denoiser needs (size, channels, finite values), with
// errors that name the file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/image_io.hpp"

namespace asvgf::cli {

// A file pattern with exactly one integer conversion (%d, %4d, %04d; %% is a literal %). Throws
// CLI::ValidationError naming `option` otherwise.
class FramePattern {
 public:
  FramePattern() = default;
  FramePattern(std::string option, std::string pattern);
  std::filesystem::path path(int frame) const;
  // The frame number of a file this pattern names (same folder assumed), or nothing.
  std::optional<int> frame_of(const std::filesystem::path& file) const;
  // The lowest frame number with a file, or nothing.
  std::optional<int> lowest_frame() const;
  bool empty() const { return pattern_.empty(); }
  const std::string& option() const { return option_; }

 private:
  std::string option_, pattern_;
};

// What a buffer must hold: its name in messages, size, and the channels it must declare.
struct BufferSpec {
  std::string name;                     // "color", "depth", ...
  std::uint32_t width = 0, height = 0;  // 0: any (the first color frame sets the size)
  std::vector<std::string> channels;    // e.g. {"R", "G"}
  bool infinity_allowed = false;        // +-Inf is a legal value (depth: background)
  // The file's channels read into R, G, B, A in order (e.g. a multilayer file's
  // "ViewLayer.Normal.X"); empty: R, G, B, A by name.
  std::vector<std::string> file_channels = {};
};
// Reads frame `frame` of `pattern` and checks it against `spec`. Throws render::ImageIoError naming
// the file: missing, unreadable, another size, a missing channel, a NaN or (unless allowed) an Inf,
// with its pixel.
render::ExrImage read_frame(const FramePattern& pattern, int frame, const BufferSpec& spec);
// Checks frame `frame` of `pattern` from its header alone, before a run reads any frame: readable
// and of spec's size (a missing file is read_frame's to report). Throws render::ImageIoError as
// read_frame does.
void check_frame_header(const FramePattern& pattern, int frame, const BufferSpec& spec);

// Frames first, first+1, ... while `pattern` has a file; 0 when the first is missing. Throws
// render::ImageIoError naming the first missing file when a later frame exists (a gap), unless
// `wanted` (> 0) frames are there before it.
int count_frames(const FramePattern& pattern, int first, int wanted = 0);

}  // namespace asvgf::cli
