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
  float* data = nullptr;
  int w = 0, h = 0;
  const char* err = nullptr;
  if (LoadEXR(&data, &w, &h, path.c_str(), &err) != 0) {
    std::string message = err ? err : "unknown error";
    if (err) FreeEXRErrorMessage(err);
    throw ImageIoError(path.string() + ": cannot read EXR: " + message);
  }
  ExrImage image{static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(h),
                 std::vector<float>(data, data + std::size_t(w) * std::size_t(h) * 4)};
  std::free(data);
  return image;
}

}  // namespace asvgf::render
