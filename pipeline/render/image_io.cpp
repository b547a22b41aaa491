#include "render/image_io.hpp"

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
#include <tinyexr.h>
#pragma GCC diagnostic pop

namespace asvgf::render {
namespace {

std::filesystem::path temporary_for(const std::filesystem::path& path) {
  std::filesystem::path tmp = path;
  tmp += ".partial";
  return tmp;
}

void commit(const std::filesystem::path& tmp, const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw ImageIoError(path.string() + ": cannot write: " + ec.message());
  }
}

void check_size(const std::filesystem::path& path, std::uint32_t w, std::uint32_t h, std::size_t values) {
  if (w == 0 || h == 0 || values != std::size_t(w) * h * 4)
    throw ImageIoError(path.string() + ": image of " + std::to_string(w) + "x" + std::to_string(h) + " has " +
                       std::to_string(values) + " values, expected 4 per pixel");
}

}  // namespace

void write_png(const std::filesystem::path& path, std::uint32_t w, std::uint32_t h, std::span<const std::uint8_t> rgba) {
  check_size(path, w, h, rgba.size());
  const auto tmp = temporary_for(path);
  if (!stbi_write_png(tmp.c_str(), static_cast<int>(w), static_cast<int>(h), 4, rgba.data(), static_cast<int>(w * 4))) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw ImageIoError(path.string() + ": cannot write PNG (is the folder writable?)");
  }
  commit(tmp, path);
}

void write_exr(const std::filesystem::path& path, std::uint32_t w, std::uint32_t h, std::span<const float> rgba) {
  check_size(path, w, h, rgba.size());
  for (std::size_t i = 0; i < rgba.size(); ++i)
    if (!std::isfinite(rgba[i])) {
      const std::size_t pixel = i / 4;
      throw ImageIoError(path.string() + ": refusing to write a non-finite value at pixel (" +
                         std::to_string(pixel % w) + ", " + std::to_string(pixel / w) + ")");
    }
  std::vector<float> rgb(std::size_t(w) * h * 3);
  for (std::size_t p = 0; p < std::size_t(w) * h; ++p)
    for (int c = 0; c < 3; ++c) rgb[3 * p + c] = rgba[4 * p + c];
  const auto tmp = temporary_for(path);
  const char* err = nullptr;
  if (SaveEXR(rgb.data(), static_cast<int>(w), static_cast<int>(h), 3, /*save_as_fp16=*/0, tmp.c_str(), &err) != 0) {
    std::string message = err ? err : "unknown error";
    if (err) FreeEXRErrorMessage(err);
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw ImageIoError(path.string() + ": cannot write EXR: " + message);
  }
  commit(tmp, path);
}

ExrImage read_exr(const std::filesystem::path& path) {
  const std::string name = path.string();
  EXRVersion version;
  if (ParseEXRVersionFromFile(&version, path.c_str()) != TINYEXR_SUCCESS)
    throw ImageIoError(name + ": cannot read EXR: not an OpenEXR file (or unreadable)");
  if (version.multipart || version.non_image)
    throw ImageIoError(name + ": cannot read EXR: multi-part and deep files are not supported");
  EXRHeader header;
  InitEXRHeader(&header);
  const char* err = nullptr;
  auto fail = [&](const std::string& what) {
    std::string message = err ? err : what;
    if (err) FreeEXRErrorMessage(err);
    throw ImageIoError(name + ": cannot read EXR: " + message);
  };
  if (ParseEXRHeaderFromFile(&header, &version, path.c_str(), &err) != TINYEXR_SUCCESS) fail("bad header");
  ExrImage out;
  int index[4] = {-1, -1, -1, -1};  // R, G, B, A
  std::string unsupported;
  for (int i = 0; i < header.num_channels; ++i) {
    const std::string channel = header.channels[i].name;
    out.channels.push_back(channel);
    if (header.pixel_types[i] == TINYEXR_PIXELTYPE_UINT) unsupported = channel;
    header.requested_pixel_types[i] = TINYEXR_PIXELTYPE_FLOAT;
    for (int c = 0; c < 4; ++c)
      if (channel == std::string(1, "RGBA"[c])) index[c] = i;
  }
  if (!unsupported.empty()) {
    FreeEXRHeader(&header);
    throw ImageIoError(name + ": cannot read EXR: channel " + unsupported + " holds unsigned integers, not floats");
  }
  // One channel of any name is a grey image (as tinyexr's LoadEXR reads it).
  if (header.num_channels == 1) {
    index[0] = index[1] = index[2] = 0;
    for (const char* c : {"R", "G", "B"})
      if (out.channels.front() != c) out.channels.emplace_back(c);
  }
  if (index[0] < 0 && index[1] < 0 && index[2] < 0 && index[3] < 0) {
    FreeEXRHeader(&header);
    throw ImageIoError(name + ": cannot read EXR: no R, G, B or A channel (and more than one channel)");
  }
  EXRImage image;
  InitEXRImage(&image);
  if (LoadEXRImageFromFile(&image, &header, path.c_str(), &err) != TINYEXR_SUCCESS) {
    FreeEXRHeader(&header);
    fail("bad pixel data");
  }
  out.width = static_cast<std::uint32_t>(image.width);
  out.height = static_cast<std::uint32_t>(image.height);
  out.rgba.assign(std::size_t(out.width) * out.height * 4, 0.0f);
  for (std::size_t p = 0; p < std::size_t(out.width) * out.height; ++p) out.rgba[4 * p + 3] = 1.0f;
  // Copies one block of planes (the whole image, or a tile) into RGBA.
  auto copy = [&](unsigned char** planes, int x0, int y0, int bw, int bh) {
    for (int c = 0; c < 4; ++c) {
      if (index[c] < 0) continue;
      const float* plane = reinterpret_cast<const float*>(planes[index[c]]);
      for (int y = 0; y < bh; ++y)
        for (int x = 0; x < bw; ++x) {
          if (x0 + x >= image.width || y0 + y >= image.height) continue;
          out.rgba[(std::size_t(y0 + y) * out.width + std::size_t(x0 + x)) * 4 + std::size_t(c)] = plane[y * bw + x];
        }
    }
  };
  if (header.tiled) {
    for (int t = 0; t < image.num_tiles; ++t)
      copy(image.tiles[t].images, image.tiles[t].offset_x * header.tile_size_x,
           image.tiles[t].offset_y * header.tile_size_y, header.tile_size_x, header.tile_size_y);
  } else {
    copy(image.images, 0, 0, image.width, image.height);
  }
  FreeEXRImage(&image);
  FreeEXRHeader(&header);
  return out;
}

}  // namespace asvgf::render
