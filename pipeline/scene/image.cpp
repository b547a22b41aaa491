// scene/image.cpp: albedo textures from image files through stb_image.
//
// libtinygltf.so links Debian's libstb.so, which exports the stb_image symbols; STB_IMAGE_STATIC
// keeps this implementation private to this file so the two never clash.
#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <vector>

#include "scene/mesh_import.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace asvgf::scene::detail {
namespace {

// Textures larger than this on a side are refused before decoding (a header can claim any size).
constexpr int kMaxTextureSide = 16384;

std::uint32_t big_endian32(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]};
}

// stb_image allocates what a PNG chunk's length field claims before reading it: a 76-byte file
// asked for 2 GiB (found by tools/fuzz.sh, tests/data/fuzz_regressions/image/). Every chunk must fit
// in the file.
void check_png_chunks(const std::vector<unsigned char>& bytes, const std::string& prefix) {
  static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kSignature, 8) != 0) return;  // not a PNG
  std::size_t at = 8;
  while (at + 12 <= bytes.size()) {
    const std::uint64_t length = big_endian32(&bytes[at]);
    if (length > bytes.size() - at - 12)
      throw SceneError(prefix + "PNG chunk at byte " + std::to_string(at) + " claims " + std::to_string(length) +
                       " bytes but the file has " + std::to_string(bytes.size() - at - 12) + " left");
    if (std::memcmp(&bytes[at + 4], "IEND", 4) == 0) return;
    at += 12 + static_cast<std::size_t>(length);
  }
}

}  // namespace

Texture load_image(const std::filesystem::path& file, const std::string& where) {
  const std::string prefix = where + ": " + file.string() + ": ";
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError(prefix + "cannot read image (cannot open the file)");
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.empty()) throw SceneError(prefix + "cannot read image (the file is empty)");
  check_png_chunks(bytes, prefix);
  const int size = static_cast<int>(std::min<std::size_t>(bytes.size(), std::numeric_limits<int>::max()));
  int width = 0, height = 0, channels = 0;
  if (stbi_info_from_memory(bytes.data(), size, &width, &height, &channels) &&
      (width > kMaxTextureSide || height > kMaxTextureSide))
    throw SceneError(prefix + "the image is " + std::to_string(width) + "x" + std::to_string(height) +
                     "; textures may be at most " + std::to_string(kMaxTextureSide) + " on a side");
  stbi_uc* pixels = stbi_load_from_memory(bytes.data(), size, &width, &height, &channels, 4);
  if (pixels == nullptr) {
    const char* reason = stbi_failure_reason();
    throw SceneError(prefix + "cannot read image (" + (reason ? reason : "unknown error") + ")");
  }
  Texture tex;
  tex.name = file.string();
  tex.width = static_cast<std::uint32_t>(width);
  tex.height = static_cast<std::uint32_t>(height);
  tex.rgba8.resize(std::size_t{tex.width} * tex.height * 4);
  std::memcpy(tex.rgba8.data(), pixels, tex.rgba8.size());
  stbi_image_free(pixels);
  return tex;
}

}  // namespace asvgf::scene::detail
