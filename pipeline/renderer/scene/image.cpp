// renderer/scene/image.cpp: albedo textures from PNG and JPEG files (and glTF's images, which are PNG or
// JPEG by the glTF spec) through stb_image, after checks for the malformed files that Debian's
// stb_image 2.27 mishandles. Its other decoders (TGA, BMP, PSD, GIF, HDR, PIC, PNM) are left out:
// the fuzzer kept finding faults in them, and no scene needs them.
//
// libtinygltf.so links Debian's libstb.so, which exports the stb_image symbols; STB_IMAGE_STATIC
// keeps this implementation private to this file so the two never clash.
#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <span>
#include <vector>

#include "renderer/scene/mesh_import.hpp"

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
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace asvgf::scene::detail {
namespace {

// Textures larger than this on a side are refused before decoding (a header can claim any size).
constexpr int kMaxTextureSide = 16384;
// A file may not decode to more pixels than this per byte of it: stb_image pads data that ends
// early with zeros, so a 478-byte RLE TGA claiming 8224x8224 made it decode 67 M pixels (a fuzzer
// timeout). The best real compression stays below it: DEFLATE's 1032:1 for 8-bit PNG, a few hundred
// for flat JPEGs; only flat 1- and 2-bit PNGs go further.
constexpr std::uint64_t kMaxPixelsPerByte = 2048;

constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

bool is_png(std::span<const unsigned char> bytes) {
  return bytes.size() >= 8 && std::memcmp(bytes.data(), kPngSignature, 8) == 0;
}
// A JPEG's start marker as stb_image finds it: 0xFF, any number of 0xFF fill bytes, 0xD8.
bool is_jpeg(std::span<const unsigned char> bytes) {
  std::size_t at = 1;
  while (at < bytes.size() && bytes[at] == 0xFF) ++at;
  return !bytes.empty() && bytes[0] == 0xFF && at < bytes.size() && bytes[at] == 0xD8;
}

std::uint32_t big_endian32(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]};
}

// stb_image allocates what a PNG chunk's length field claims before reading it: a 76-byte file
// asked for 2 GiB (found by tools/fuzz.sh, tests/data/fuzz_regressions/image/). Every chunk must fit
// in the file.
void check_png_chunks(std::span<const unsigned char> bytes, const std::string& prefix) {
  if (!is_png(bytes)) return;
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

// stb_image 2.27 (Debian 12) trusts a JPEG's Huffman tables (found by tools/fuzz.sh, kept in
// tests/data/fuzz_regressions/image/): a DHT segment's 16 code-length counts may total more than
// 256 symbols, which writes past its 257-entry tables, and a scan may use a table no DHT segment
// defined, which decodes with uninitialised memory. Walk the markers as stb_image reads them (fill
// bytes skipped, 0xFF00 stuffing and restart markers inside scans) and refuse both. stb_image reads
// a table's counts even past the segment's end (as zeros past the file's), so this does too.
void check_jpeg_huffman_tables(std::span<const unsigned char> bytes, const std::string& prefix) {
  if (!is_jpeg(bytes)) return;
  std::size_t at = 1;
  while (bytes[at] == 0xFF) ++at;  // to the 0xD8 is_jpeg found
  ++at;
  auto byte_at = [&](std::size_t i) -> unsigned { return i < bytes.size() ? bytes[i] : 0u; };  // 0 past the end, as stb
  bool defined[2][4] = {};  // [0: DC, 1: AC][table id]
  bool progressive = false;
  auto require = [&](std::size_t scan, unsigned ac, unsigned id) {
    if (id <= 3 && !defined[ac][id])  // ids above 3 stb_image refuses itself
      throw SceneError(prefix + "JPEG scan at byte " + std::to_string(scan) + " uses " + (ac ? "AC" : "DC") +
                       " Huffman table " + std::to_string(id) + ", which no DHT segment before it defines");
  };
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
    if (marker == 0xC2) progressive = true;
    if (marker == 0xC4) {
      std::size_t table = at + 4;
      for (long left = static_cast<long>(length) - 2; left > 0;) {
        std::size_t symbols = 0;
        for (std::size_t i = 1; i <= 16; ++i) symbols += byte_at(table + i);
        if (symbols > 256)
          throw SceneError(prefix + "JPEG Huffman table at byte " + std::to_string(table) + " has " +
                           std::to_string(symbols) + " codes (at most 256)");
        const unsigned kind = byte_at(table) >> 4, id = byte_at(table) & 15u;
        if (kind <= 1 && id <= 3) defined[kind][id] = true;
        table += 17 + symbols;
        left -= static_cast<long>(17 + symbols);
      }
    }
    if (marker == 0xDA) {
      // Which tables stb_image decodes with: baseline, both per component; progressive, the DC
      // table in a first DC scan (Ss = 0, Ah = 0), none in a DC refinement, the AC table otherwise.
      const unsigned components = byte_at(at + 4);
      const unsigned ss = byte_at(at + 5 + 2 * components), ah = byte_at(at + 7 + 2 * components) >> 4;
      for (unsigned c = 0; c < components; ++c) {
        const unsigned tables = byte_at(at + 6 + 2 * c);
        if (!progressive || (ss == 0 && ah == 0)) require(at, 0, tables >> 4);
        if (!progressive || ss != 0) require(at, 1, tables & 15u);
      }
    }
    at += 2 + std::max<std::size_t>(length, 2);
  }
}

}  // namespace

Texture decode_image(const unsigned char* data, std::size_t size, const std::string& prefix) {
  if (size == 0) throw SceneError(prefix + "cannot read image (no data)");
  const std::span<const unsigned char> bytes(data, size);  // checked in place, not copied
  if (!is_png(bytes) && !is_jpeg(bytes))
    throw SceneError(prefix + "not a PNG or JPEG file (textures are PNG or JPEG, as glTF's are)");
  check_png_chunks(bytes, prefix);
  check_jpeg_huffman_tables(bytes, prefix);
  const int stb_size = static_cast<int>(std::min<std::size_t>(size, std::numeric_limits<int>::max()));
  int width = 0, height = 0, channels = 0;
  if (stbi_info_from_memory(data, stb_size, &width, &height, &channels) &&
      (width > kMaxTextureSide || height > kMaxTextureSide))
    throw SceneError(prefix + "the image is " + std::to_string(width) + "x" + std::to_string(height) +
                     "; textures may be at most " + std::to_string(kMaxTextureSide) + " on a side");
  if (std::uint64_t(std::max(width, 0)) * std::uint64_t(std::max(height, 0)) > kMaxPixelsPerByte * size)
    throw SceneError(prefix + "the image claims " + std::to_string(width) + "x" + std::to_string(height) +
                     " pixels from " + std::to_string(size) + " bytes, more than " + std::to_string(kMaxPixelsPerByte) +
                     " pixels a byte: truncated or a decompression bomb");
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
