// io/image_io.hpp: writing frames: PNG (8-bit sRGB) and OpenEXR (linear float), encoded in
// memory and written by write_file_atomic (io/atomic_file.hpp): whole or not at all, every
// failure a FileWriteError naming the file and the cause.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace asvgf::render {

class ImageIoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// rgba: width*height*4 bytes, rows top to bottom.
void write_png(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
               std::span<const std::uint8_t> rgba);
// rgba: width*height*4 floats; written as 32-bit floats (RGB, and A with `alpha`), so every finite
// radiance is stored exactly (half floats turned values above 65504 into +Inf). Throws ImageIoError
// when a value is NaN or infinite, naming the file and the first bad pixel.
void write_exr(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
               std::span<const float> rgba, bool alpha = false);

struct ExrImage {
  std::uint32_t width = 0, height = 0;
  std::vector<float> rgba;            // width*height*4, rows top to bottom (A = 1 where the file has none)
  std::vector<std::string> channels;  // the names the file declares ("R", "G", "B", ...), plus R, G, B for a grey file
};
// Reads a single-part OpenEXR file (half or float channels, scanline or tiled): R, G, B and A by
// name, each absent one 0 (A: 1); a file of one channel of any name is grey (into R, G and B).
// With `slots` (at most 4 channel names, e.g. a multilayer file's "ViewLayer.Vector.X"), those
// channels go into R, G, B, A in order instead, each one required; `channels` is then "R", "G", ...
// for the slots read. Throws ImageIoError naming the file (and, for a missing channel, its layers).
ExrImage read_exr(const std::filesystem::path& path, std::span<const std::string> slots = {});
// What a single-part OpenEXR file's header declares: its data window's size and its channel names.
// Reads the header's bytes only (a few KiB), not the pixels. Throws ImageIoError naming the file.
struct ExrHeader {
  std::uint32_t width = 0, height = 0;
  std::vector<std::string> channels;
};
ExrHeader read_exr_header(const std::filesystem::path& path);

}  // namespace asvgf::render
