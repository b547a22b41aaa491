// scene/image.cpp: albedo textures from image files (and glTF's images) through stb_image, after
// checks for the malformed files that Debian's stb_image 2.27 mishandles.
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

// stb_image 2.27 (Debian 12) builds a JPEG Huffman table from a DHT segment's 16 code-length
// counts without checking that they total at most 256 symbols; more write past its 257-entry tables
// (found by tools/fuzz.sh, tests/data/fuzz_regressions/image/). Walk the markers as stb_image reads
// them (bytes between markers skipped, 0xFF00 stuffing and restart markers inside scans) and refuse
// such a table. stb_image reads a table's counts even past the segment's end, so this does too.
void check_jpeg_huffman_tables(const std::vector<unsigned char>& bytes, const std::string& prefix) {
  if (bytes.size() < 2 || bytes[0] != 0xFF || bytes[1] != 0xD8) return;                        // not a JPEG
  auto byte_at = [&](std::size_t i) -> unsigned { return i < bytes.size() ? bytes[i] : 0u; };  // 0 past the end, as stb
  std::size_t at = 2;
  while (at + 1 < bytes.size()) {
    const unsigned marker = bytes[at + 1];
    if (bytes[at] != 0xFF || marker == 0xFF) {  // entropy-coded data, junk or fill bytes
      ++at;
      continue;
    }
    const bool no_length = marker == 0x00 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD9);
    if (no_length) {
      at += 2;
      continue;
    }
    const std::size_t length = (byte_at(at + 2) << 8) | byte_at(at + 3);
    if (marker == 0xC4) {
      std::size_t table = at + 4;
      for (long left = static_cast<long>(length) - 2; left > 0;) {
        std::size_t symbols = 0;
        for (std::size_t i = 1; i <= 16; ++i) symbols += byte_at(table + i);
        if (symbols > 256)
          throw SceneError(prefix + "JPEG Huffman table at byte " + std::to_string(table) + " has " +
                           std::to_string(symbols) + " codes (at most 256)");
        table += 17 + symbols;
        left -= static_cast<long>(17 + symbols);
      }
    }
    at += 2 + std::max<std::size_t>(length, 2);
  }
}

}  // namespace

Texture decode_image(const unsigned char* data, std::size_t size, const std::string& prefix) {
  if (size == 0) throw SceneError(prefix + "cannot read image (no data)");
  const std::vector<unsigned char> bytes(data, data + size);
  check_png_chunks(bytes, prefix);
  check_jpeg_huffman_tables(bytes, prefix);
  const int stb_size = static_cast<int>(std::min<std::size_t>(size, std::numeric_limits<int>::max()));
  int width = 0, height = 0, channels = 0;
  if (stbi_info_from_memory(data, stb_size, &width, &height, &channels) &&
      (width > kMaxTextureSide || height > kMaxTextureSide))
    throw SceneError(prefix + "the image is " + std::to_string(width) + "x" + std::to_string(height) +
                     "; textures may be at most " + std::to_string(kMaxTextureSide) + " on a side");
  stbi_uc* pixels = stbi_load_from_memory(data, stb_size, &width, &height, &channels, 4);
  if (pixels == nullptr) {
    const char* reason = stbi_failure_reason();
    throw SceneError(prefix + "cannot read image (" + (reason ? reason : "unknown error") + ")");
  }
  Texture tex;
  tex.width = static_cast<std::uint32_t>(width);
  tex.height = static_cast<std::uint32_t>(height);
  tex.rgba8.resize(std::size_t{tex.width} * tex.height * 4);
  std::memcpy(tex.rgba8.data(), pixels, tex.rgba8.size());
  stbi_image_free(pixels);
  return tex;
}

Texture load_image(const std::filesystem::path& file, const std::string& where) {
  const std::string prefix = where + ": " + file.string() + ": ";
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError(prefix + "cannot read image (cannot open the file)");
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.empty()) throw SceneError(prefix + "cannot read image (the file is empty)");
  Texture tex = decode_image(bytes.data(), bytes.size(), prefix);
  tex.name = file.string();
  return tex;
}

}  // namespace asvgf::scene::detail
