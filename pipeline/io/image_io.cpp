#include "io/image_io.hpp"

#include "io/atomic_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image_write.h>
#include <tinyexr.h>
#pragma GCC diagnostic pop

namespace asvgf::render {
namespace {

void check_size(const std::filesystem::path& path, std::uint32_t w, std::uint32_t h, std::size_t values) {
  if (w == 0 || h == 0 || values != std::size_t(w) * h * 4)
    throw ImageIoError(path.string() + ": image of " + std::to_string(w) + "x" + std::to_string(h) + " has " +
                       std::to_string(values) + " values, expected 4 per pixel");
}

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::byte>*>(context);
  const auto* p = static_cast<const std::byte*>(data);
  out->insert(out->end(), p, p + size);
}

// The EXR file's bytes: RGB as 32-bit floats in B, G, R channel order (what viewers expect), ZIP
// compressed but for images under 16x16 (as tinyexr's SaveEXR).
std::vector<std::byte> encode_exr(const std::filesystem::path& path, std::uint32_t w, std::uint32_t h,
                                  std::span<const float> rgba, bool alpha) {
  const std::size_t pixels = std::size_t(w) * h;
  const int count = alpha ? 4 : 3;
  std::vector<float> planes[4];
  for (int c = 0; c < count; ++c) {
    planes[c].resize(pixels);
    for (std::size_t p = 0; p < pixels; ++p) planes[c][p] = rgba[4 * p + std::size_t(c)];
  }
  // Channels in the order OpenEXR sorts their names: (A,) B, G, R.
  float* plane_pointers[4] = {planes[3].data(), planes[2].data(), planes[1].data(), planes[0].data()};
  const char* names = alpha ? "ABGR" : "BGR";
  EXRImage image;
  InitEXRImage(&image);
  image.num_channels = count;
  image.images = reinterpret_cast<unsigned char**>(plane_pointers + (alpha ? 0 : 1));
  image.width = static_cast<int>(w);
  image.height = static_cast<int>(h);
  EXRHeader header;
  InitEXRHeader(&header);
  header.compression_type = w < 16 && h < 16 ? TINYEXR_COMPRESSIONTYPE_NONE : TINYEXR_COMPRESSIONTYPE_ZIP;
  EXRChannelInfo channels[4] = {};
  int pixel_types[4] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT,
                        TINYEXR_PIXELTYPE_FLOAT};
  for (int c = 0; c < count; ++c) channels[c].name[0] = names[c];
  header.num_channels = count;
  header.channels = channels;
  header.pixel_types = pixel_types;
  header.requested_pixel_types = pixel_types;
  unsigned char* memory = nullptr;
  const char* err = nullptr;
  const std::size_t size = SaveEXRImageToMemory(&image, &header, &memory, &err);
  if (size == 0) {
    std::string message = err ? err : "unknown error";
    if (err) FreeEXRErrorMessage(err);
    throw ImageIoError(path.string() + ": cannot encode EXR: " + message);
  }
  std::vector<std::byte> bytes(reinterpret_cast<const std::byte*>(memory),
                               reinterpret_cast<const std::byte*>(memory) + size);
  std::free(memory);
  return bytes;
}

}  // namespace

void write_png(const std::filesystem::path& path, std::uint32_t w, std::uint32_t h,
               std::span<const std::uint8_t> rgba) {
  // stb's lowest level (its default is 8): a small report run, whose time went mostly into its
  // 960x600 plots, is 25% faster for 0.5% more bytes.
  static const bool level_set = [] {
    stbi_write_png_compression_level = 5;
    return true;
  }();
  (void)level_set;
  check_size(path, w, h, rgba.size());
  std::vector<std::byte> bytes;
  if (!stbi_write_png_to_func(append_bytes, &bytes, static_cast<int>(w), static_cast<int>(h), 4, rgba.data(),
                              static_cast<int>(w * 4)))
    throw ImageIoError(path.string() + ": cannot encode PNG");
  write_file_atomic(path, bytes);
}

void write_exr(const std::filesystem::path& path, std::uint32_t w, std::uint32_t h, std::span<const float> rgba,
               bool alpha) {
  check_size(path, w, h, rgba.size());
  for (std::size_t i = 0; i < rgba.size(); ++i)
    if (!std::isfinite(rgba[i])) {
      const std::size_t pixel = i / 4;
      throw ImageIoError(path.string() + ": refusing to write a non-finite value at pixel (" +
                         std::to_string(pixel % w) + ", " + std::to_string(pixel / w) + ")");
    }
  write_file_atomic(path, encode_exr(path, w, h, rgba, alpha));
}

namespace {

// "ViewLayer.Combined, ViewLayer.Depth" for channels "ViewLayer.Combined.R", ..., "ViewLayer.Depth.Z".
std::string layers_of(const std::vector<std::string>& channels) {
  std::vector<std::string> layers;
  for (const auto& c : channels) {
    const auto dot = c.rfind('.');
    const std::string layer = dot == std::string::npos ? "(no layer)" : c.substr(0, dot);
    if (std::find(layers.begin(), layers.end(), layer) == layers.end()) layers.push_back(layer);
  }
  std::string text;
  for (const auto& l : layers) text += (text.empty() ? "" : ", ") + l;
  return text;
}

}  // namespace

ExrHeader read_exr_header(const std::filesystem::path& path) {
  // tinyexr's ParseEXRHeaderFromFile reads the whole file; the header is its first few KiB (a
  // multilayer file's hundreds of channels included), so read a prefix, and a larger one if short.
  std::ifstream file(path, std::ios::binary);
  std::vector<unsigned char> bytes;
  for (const std::size_t limit : {std::size_t{1} << 16, std::size_t{1} << 22}) {
    const std::size_t have = bytes.size();
    bytes.resize(limit);
    file.read(reinterpret_cast<char*>(bytes.data() + have), static_cast<std::streamsize>(limit - have));
    bytes.resize(have + static_cast<std::size_t>(file.gcount()));
    EXRVersion version;
    EXRHeader header;
    InitEXRHeader(&header);
    const char* err = nullptr;
    if (ParseEXRVersionFromMemory(&version, bytes.data(), bytes.size()) == TINYEXR_SUCCESS && !version.multipart &&
        !version.non_image &&
        ParseEXRHeaderFromMemory(&header, &version, bytes.data(), bytes.size(), &err) == TINYEXR_SUCCESS) {
      ExrHeader out;
      out.width = static_cast<std::uint32_t>(header.data_window.max_x - header.data_window.min_x + 1);
      out.height = static_cast<std::uint32_t>(header.data_window.max_y - header.data_window.min_y + 1);
      for (int i = 0; i < header.num_channels; ++i) out.channels.emplace_back(header.channels[i].name);
      FreeEXRHeader(&header);
      return out;
    }
    if (err) FreeEXRErrorMessage(err);
    FreeEXRHeader(&header);
    if (bytes.size() < limit) break;  // the whole file was read (none where it did not open)
  }
  throw ImageIoError(path.string() + ": cannot read EXR: not a single-part OpenEXR file (or unreadable)");
}

ExrImage read_exr(const std::filesystem::path& path, std::span<const std::string> slots) {
  const std::string name = path.string();
  if (slots.size() > 4) throw ImageIoError(name + ": at most 4 channels can be read into one image");
  // The file read once: tinyexr's ...FromFile calls each read the whole file (header, then pixels).
  std::ifstream file(path, std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (file.bad()) throw ImageIoError(name + ": cannot read EXR: reading the file failed (a folder, or an I/O error)");
  EXRVersion version;
  if (ParseEXRVersionFromMemory(&version, bytes.data(), bytes.size()) != TINYEXR_SUCCESS)
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
  if (ParseEXRHeaderFromMemory(&header, &version, bytes.data(), bytes.size(), &err) != TINYEXR_SUCCESS)
    fail("bad header");
  // A region render (Arnold, Karma, Nuke) stores only the region's pixels, placed in a larger frame.
  // Read as a whole frame they would land at the origin, and pair with other buffers pixel for pixel
  // by position in the file, not in the frame: refused rather than silently moved.
  const EXRBox2i data = header.data_window, display = header.display_window;
  if (data.min_x != display.min_x || data.min_y != display.min_y || data.max_x != display.max_x ||
      data.max_y != display.max_y) {
    FreeEXRHeader(&header);
    auto box = [](const EXRBox2i& b) {
      return "(" + std::to_string(b.min_x) + "," + std::to_string(b.min_y) + ")-(" + std::to_string(b.max_x) + "," +
             std::to_string(b.max_y) + ")";
    };
    throw ImageIoError(name + ": cannot read EXR: its data window " + box(data) + " is not its display window " +
                       box(display) +
                       " (a region render?); asvgf reads whole frames: make the region the frame first, e.g. "
                       "`oiiotool IN --fullpixels -o OUT`, or render without a region");
  }
  ExrImage out;
  int index[4] = {-1, -1, -1, -1};  // R, G, B, A
  std::string unsupported;
  for (int i = 0; i < header.num_channels; ++i) {
    const std::string channel = header.channels[i].name;
    out.channels.push_back(channel);
    if (header.pixel_types[i] == TINYEXR_PIXELTYPE_UINT) unsupported = channel;
    header.requested_pixel_types[i] = TINYEXR_PIXELTYPE_FLOAT;
    for (std::size_t c = 0; c < 4; ++c)
      if (slots.empty() ? channel == std::string(1, "RGBA"[c]) : c < slots.size() && channel == slots[c]) index[c] = i;
  }
  if (!slots.empty()) {
    // Named channels (a multilayer file's "Layer.Pass.Channel"): every one must be there.
    for (std::size_t c = 0; c < slots.size(); ++c)
      if (index[c] < 0) {
        const std::string layers = layers_of(out.channels);
        FreeEXRHeader(&header);
        throw ImageIoError(name + ": cannot read EXR: no channel '" + slots[c] + "' (its layers: " + layers + ")");
      }
    out.channels.assign({"R", "G", "B", "A"});
    out.channels.resize(slots.size());
  }
  if (!unsupported.empty()) {
    FreeEXRHeader(&header);
    throw ImageIoError(name + ": cannot read EXR: channel " + unsupported + " holds unsigned integers, not floats");
  }
  // One channel of any name is a grey image (as tinyexr's LoadEXR reads it).
  if (slots.empty() && header.num_channels == 1) {
    index[0] = index[1] = index[2] = 0;
    for (const char* c : {"R", "G", "B"})
      if (out.channels.front() != c) out.channels.emplace_back(c);
  }
  if (index[0] < 0 && index[1] < 0 && index[2] < 0 && index[3] < 0) {
    const std::string layers = layers_of(out.channels);
    FreeEXRHeader(&header);
    if (layers.find("(no layer)") == std::string::npos)
      throw ImageIoError(name + ": cannot read EXR: a multilayer file (layers: " + layers +
                         "): name its channels (asvgf denoise --from cycles, or --channels BUFFER=CHANNELS)");
    throw ImageIoError(name + ": cannot read EXR: no R, G, B or A channel (and more than one channel)");
  }
  EXRImage image;
  InitEXRImage(&image);
  if (LoadEXRImageFromMemory(&image, &header, bytes.data(), bytes.size(), &err) != TINYEXR_SUCCESS) {
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
