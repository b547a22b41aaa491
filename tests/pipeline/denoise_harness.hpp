// Helpers of the denoiser tests (pipeline and stability): fp16 conversion and tolerances, random
// G-buffer-like inputs, and a harness that runs render graphs on a device with inputs uploaded
// into imported images and results copied back to the host.
#pragma once

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "asvgf/graph_runtime.hpp"
#include "cpu_oracle/depth_normal.hpp"
#include "cpu_oracle/image.hpp"
#include "cpu_oracle/octahedral.hpp"
#include "cpu_oracle/rgb9e5.hpp"
#include "hal/hal.hpp"
#include "io/half_float.hpp"

namespace denoise_test {

using asvgf::reference::ImageD;

// ---- fp16 --------------------------------------------------------------------------------------
using asvgf::io::float_to_half;
using asvgf::io::half_to_float;
// One fp16 ulp at magnitude |v| (the error of one fp16 store, rounded either way).
inline double fp16_ulp(double v) {
  const double a = std::abs(v);
  if (a < std::ldexp(1.0, -14)) return std::ldexp(1.0, -24);
  return std::ldexp(1.0, static_cast<int>(std::floor(std::log2(a))) - 10);
}

// ---- Image bytes -------------------------------------------------------------------------------
inline std::vector<std::byte> encode(const ImageD& img, hal::Format format) {
  const std::uint32_t channels = hal::format_channels(format);
  std::vector<std::byte> out(static_cast<std::size_t>(img.width) * img.height * hal::format_size(format));
  std::size_t at = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (std::uint32_t c = 0; c < channels; ++c) {
        const double v = static_cast<int>(c) < img.channels ? img.at(x, y, static_cast<int>(c)) : 0.0;
        switch (format) {
          case hal::Format::R16F:
          case hal::Format::RG16F:
          case hal::Format::RGBA16F: {
            const std::uint16_t h = float_to_half(static_cast<float>(v));
            std::memcpy(out.data() + at, &h, 2), at += 2;
            break;
          }
          case hal::Format::R8Unorm:
          case hal::Format::RGBA8Unorm: {
            const auto b = static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
            std::memcpy(out.data() + at, &b, 1), at += 1;
            break;
          }
          case hal::Format::R32Uint:
          case hal::Format::RG32Uint:
          case hal::Format::RGBA32Uint: {
            const auto u = static_cast<std::uint32_t>(v);
            std::memcpy(out.data() + at, &u, 4), at += 4;
            break;
          }
          case hal::Format::RGBA16Uint: {
            const auto u = static_cast<std::uint16_t>(v);
            std::memcpy(out.data() + at, &u, 2), at += 2;
            break;
          }
          default: {
            const auto f = static_cast<float>(v);
            std::memcpy(out.data() + at, &f, 4), at += 4;
          }
        }
      }
  return out;
}

inline ImageD decode(std::span<const std::byte> bytes, int w, int h, hal::Format format) {
  const int channels = static_cast<int>(hal::format_channels(format));
  ImageD out(w, h, std::max(channels, 4));
  std::size_t at = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c) {
        switch (format) {
          case hal::Format::R16F:
          case hal::Format::RG16F:
          case hal::Format::RGBA16F: {
            std::uint16_t v;
            std::memcpy(&v, bytes.data() + at, 2), at += 2;
            out.at(x, y, c) = half_to_float(v);
            break;
          }
          case hal::Format::R8Unorm:
          case hal::Format::RGBA8Unorm: {
            out.at(x, y, c) = static_cast<double>(static_cast<std::uint8_t>(bytes[at])) / 255.0, at += 1;
            break;
          }
          case hal::Format::R32Uint:
          case hal::Format::RG32Uint:
          case hal::Format::RGBA32Uint: {
            std::uint32_t u;
            std::memcpy(&u, bytes.data() + at, 4), at += 4;
            out.at(x, y, c) = u;
            break;
          }
          case hal::Format::RGBA16Uint: {
            std::uint16_t u;
            std::memcpy(&u, bytes.data() + at, 2), at += 2;
            out.at(x, y, c) = u;
            break;
          }
          default: {
            float f;
            std::memcpy(&f, bytes.data() + at, 4), at += 4;
            out.at(x, y, c) = f;
          }
        }
      }
  return out;
}

// What the GPU sees after an upload in `format` (fp16 rounding, fp32 rounding).
inline ImageD quantize(const ImageD& img, hal::Format format) {
  ImageD q = decode(encode(img, format), img.width, img.height, format);
  ImageD out(img.width, img.height, img.channels);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < img.channels; ++c) out.at(x, y, c) = c < q.channels ? q.at(x, y, c) : 0.0;
  return out;
}

// ---- depth_normal texels (shaders/common/depth_normal.glsl) ------------------------------------
// The references take depth_normal as (z, dz, octahedral x, y); the GPU's RGBA16UI texel holds them
// rounded (cpu_oracle/depth_normal.hpp). depth_normal_texels: the texel's four channels (for an
// upload in RGBA16Uint); depth_normal_values: a texel image (a readback) back to the four values.
inline ImageD depth_normal_texels(const ImageD& dn) {
  ImageD out(dn.width, dn.height, 4);
  for (int y = 0; y < dn.height; ++y)
    for (int x = 0; x < dn.width; ++x) {
      const auto t = asvgf::reference::pack_depth_normal(
          static_cast<float>(dn.at(x, y, 0)), static_cast<float>(dn.at(x, y, 1)),
          std::array<float, 2>{static_cast<float>(dn.at(x, y, 2)), static_cast<float>(dn.at(x, y, 3))});
      for (int c = 0; c < 4; ++c) out.at(x, y, c) = t[c];
    }
  return out;
}
inline ImageD depth_normal_values(const ImageD& texels) {
  ImageD out(texels.width, texels.height, 4);
  for (int y = 0; y < texels.height; ++y)
    for (int x = 0; x < texels.width; ++x) {
      std::array<std::uint16_t, 4> t{};
      for (int c = 0; c < 4; ++c) t[c] = static_cast<std::uint16_t>(texels.at(x, y, c));
      const auto v = asvgf::reference::unpack_depth_normal(t);
      const double values[4] = {v.z, v.dz, v.oct[0], v.oct[1]};
      // No hit: all 0, as the references write background (the texel's 0 bits decode another normal).
      if (v.z != 0.0f || t != std::array<std::uint16_t, 4>{})
        for (int c = 0; c < 4; ++c) out.at(x, y, c) = values[c];
    }
  return out;
}
// What the texel keeps of (z, dz, octahedral x, y): test inputs pass through it, so that the
// references see what the GPU sees.
inline ImageD depth_normal_as_stored(const ImageD& dn) {
  return depth_normal_values(depth_normal_texels(dn));
}

// ---- Packed filter texels (shaders/common/filter_texel.glsl) -----------------------------------
// The RGB9E5 words' twin: cpu_oracle/rgb9e5.hpp.
using asvgf::reference::pack_rgb9e5;
using asvgf::reference::rgb9e5_quantum;
using asvgf::reference::unpack_rgb9e5;
// Each pixel's first three channels as one word (one channel), by `pack`; and words as the three
// values `unpack` gives (a std::array<double, 3>; alpha 0).
template <class Pack>
ImageD words_of(const ImageD& image, Pack pack) {
  ImageD out(image.width, image.height, 1);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      out.at(x, y, 0) = pack(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2));
  return out;
}
template <class Unpack>
ImageD values_of(const ImageD& words, Unpack unpack) {
  ImageD out(words.width, words.height, 4);
  for (int y = 0; y < words.height; ++y)
    for (int x = 0; x < words.width; ++x) {
      const std::array<double, 3> v = unpack(static_cast<std::uint32_t>(words.at(x, y, 0)));
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = v[static_cast<std::size_t>(c)];
    }
  return out;
}
// A motion image's x and y as one word of two halves (shaders/common/motion.glsl), one channel.
inline ImageD motion_half_words(const ImageD& motion) {
  ImageD out(motion.width, motion.height, 1);
  for (int y = 0; y < motion.height; ++y)
    for (int x = 0; x < motion.width; ++x)
      out.at(x, y, 0) = float_to_half(static_cast<float>(motion.at(x, y, 0))) |
                        (std::uint32_t{float_to_half(static_cast<float>(motion.at(x, y, 1)))} << 16);
  return out;
}
// An image's colour as RGB9E5 words (one channel) and as what they hold (rgb, alpha 0).
inline ImageD rgb9e5_words(const ImageD& color) {
  return words_of(color, pack_rgb9e5);
}
inline ImageD rgb9e5_values(const ImageD& words) {
  return values_of(words, unpack_rgb9e5);
}
// Read-back buffers of packed colour and surface texels (2 words a pixel each) as the reference's
// inputs: colour and variance (the halves, exactly), and depth_normal with the packed depth, normal
// (octahedral again, in double) and depth gradient (dz / z's 8-bit code times the depth, in float
// as the GPU).
struct FilterTexels {
  ImageD color, depth_normal;
};
inline FilterTexels unpack_filter_texels(const ImageD& packed_color, const ImageD& packed_surface) {
  const int w = packed_color.width, h = packed_color.height;
  FilterTexels out{ImageD(w, h, 4), ImageD(w, h, 4)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const auto color_word = [&](int c) { return static_cast<std::uint32_t>(packed_color.at(x, y, c)); };
      const auto surface_word = [&](int c) { return static_cast<std::uint32_t>(packed_surface.at(x, y, c)); };
      const auto halves = [](std::uint32_t u) {
        return std::array<double, 2>{half_to_float(static_cast<std::uint16_t>(u & 0xffffu)),
                                     half_to_float(static_cast<std::uint16_t>(u >> 16))};
      };
      const auto rg = halves(color_word(0)), ba = halves(color_word(1)), nxy = halves(surface_word(1));
      const bool z_negative = (surface_word(0) & 0x80000000u) != 0;
      const float z = std::abs(std::bit_cast<float>(surface_word(0) & 0xffffff00u));
      const std::uint32_t code = surface_word(0) & 0xffu;
      const float r = code == 0 ? 0.0f : std::bit_cast<float>((code + ((127u - 20u) << 3)) << 20);
      const double nz = std::sqrt(std::max(1.0 - nxy[0] * nxy[0] - nxy[1] * nxy[1], 0.0));
      const auto oct = asvgf::reference::oct_encode<double>({nxy[0], nxy[1], z_negative ? -nz : nz});
      const double values[2][4] = {{rg[0], rg[1], ba[0], ba[1]}, {z, z * r, oct[0], oct[1]}};
      for (int c = 0; c < 4; ++c) out.color.at(x, y, c) = values[0][c], out.depth_normal.at(x, y, c) = values[1][c];
    }
  return out;
}

// ---- Random inputs -----------------------------------------------------------------------------
struct Random {
  std::mt19937 rng;
  explicit Random(std::uint32_t seed) : rng(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  bool chance(double p) { return uniform(0, 1) < p; }
};

// depth_normal: a tilted plane with steps, 5% misses, normals near +z with a few sharp turns.
inline ImageD random_depth_normal(Random& r, int w, int h, double miss = 0.05) {
  ImageD dn(w, h, 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (r.chance(miss)) continue;  // z = 0: no hit
      const double step = (x / 5 + y / 7) % 3 == 0 ? 1.5 : 0.0;
      dn.at(x, y, 0) = static_cast<float>(3.0 + 0.02 * x + 0.03 * y + step + r.uniform(0, 0.01));
      dn.at(x, y, 1) = static_cast<float>(r.uniform(0.0, 0.06));
      std::array<float, 3> n{static_cast<float>(r.uniform(-0.3, 0.3)), static_cast<float>(r.uniform(-0.3, 0.3)), 1.0f};
      if (r.chance(0.1))
        n = {static_cast<float>(r.uniform(-1, 1)), static_cast<float>(r.uniform(-1, 1)),
             static_cast<float>(r.uniform(-1, 1))};
      if (std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]) < 1e-3f) n = {0, 0, 1};
      const auto e = asvgf::reference::oct_encode<float>(n);
      dn.at(x, y, 2) = e[0];
      dn.at(x, y, 3) = e[1];
    }
  return depth_normal_as_stored(dn);
}

inline ImageD random_color(Random& r, int w, int h, double lo, double hi, double variance_hi) {
  ImageD img(w, h, 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = static_cast<float>(r.uniform(lo, hi));
      img.at(x, y, 3) = static_cast<float>(r.uniform(0, variance_hi));
    }
  return img;
}

// ---- The moments word (shaders/common/denoise.glsl: pack_moments) ------------------------------
// pack_moments's word for (E[l], sqrt(Var[l]), n); `rounding` 0.5 rounds n to nearest, as the
// temporal pass does below n = 32.
inline std::uint32_t pack_moments(double mean, double std_dev, double n, double rounding = 0.5) {
  const auto half_bits = [](double v) {
    return static_cast<std::uint32_t>(float_to_half(static_cast<float>(std::clamp(v, 0.0, 65504.0)))) & 0x7fffu;
  };
  const std::uint32_t sd_half = half_bits(std_dev);
  const std::uint32_t sd = std::min((sd_half + 0x1fu + ((sd_half >> 6) & 1u)) >> 6, 0x1efu);
  std::uint32_t code = 0;
  if (n > 0) {
    const std::uint32_t bits =
        std::bit_cast<std::uint32_t>(static_cast<float>(std::clamp(n, 1.0, 61440.0))) - (127u << 23);
    code = std::min((bits + static_cast<std::uint32_t>(rounding * 524288.0)) >> 19, 254u) + 1u;
  }
  return half_bits(mean) | (sd << 15) | (code << 24);
}
// What a word holds: (E[l], sqrt(Var[l]), n).
inline std::array<double, 3> unpack_moments(std::uint32_t word) {
  const std::uint32_t code = word >> 24;
  return {half_to_float(static_cast<std::uint16_t>(word & 0x7fffu)),
          half_to_float(static_cast<std::uint16_t>(((word >> 15) & 0x1ffu) << 6)),
          code == 0 ? 0.0 : std::bit_cast<float>(((code - 1u) << 19) + (127u << 23))};
}
// Moments images (E[l], sqrt(Var[l]), n, -) as words (one channel) and words as what they hold.
inline ImageD moments_words(const ImageD& moments) {
  return words_of(moments, [](double mean, double std_dev, double n) { return pack_moments(mean, std_dev, n); });
}
inline ImageD moments_values(const ImageD& words) {
  return values_of(words, unpack_moments);
}
// The largest error the word's rounding of a standard deviation or a history length of magnitude v
// makes: half a step of its 4 mantissa bits (after the standard deviation's fp16 rounding).
inline double moments_word_rounding(double v) {
  const double a = std::abs(v);
  if (a < std::ldexp(1.0, -14)) return std::ldexp(1.0, -19) + fp16_ulp(a);
  return std::ldexp(1.0, static_cast<int>(std::floor(std::log2(a))) - 5) + fp16_ulp(a);
}

// Moments as the temporal pass stores them (E[l], sqrt(Var[l]), history length n): lengths of 0 (no
// history), below SVGF's min_history of 4 (the spatial variance estimate) and above.
inline ImageD random_moments(Random& r, int w, int h) {
  ImageD moments(w, h, 4);
  const double lengths[] = {0, 1, 2, 3, 4, 10, 32};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double m1 = r.uniform(0, 4);
      moments.at(x, y, 0) = static_cast<float>(m1);
      moments.at(x, y, 1) = static_cast<float>(std::sqrt(r.uniform(0, 2)));
      moments.at(x, y, 2) = lengths[static_cast<int>(r.uniform(0, 7))];
    }
  return moments;
}

// ---- Comparison --------------------------------------------------------------------------------
// Largest |got - want| / tolerance(want) over channels [0, channels); <= 1 passes.
struct Compare {
  double worst_ratio = 0, worst_error = 0;
  int worst_x = -1, worst_y = -1, worst_c = -1;
  double got = 0, want = 0;
};
// The same with a tolerance per pixel and channel: tolerance(x, y, channel, want).
inline Compare compare(const ImageD& got, const ImageD& want, int channels,
                       const std::function<double(int, int, int, double)>& tolerance) {
  Compare out;
  for (int y = 0; y < want.height; ++y)
    for (int x = 0; x < want.width; ++x)
      for (int c = 0; c < channels; ++c) {
        const double g = got.at(x, y, c), w = want.at(x, y, c);
        const double err = std::abs(g - w);
        const double ratio = std::isfinite(g) ? err / tolerance(x, y, c, w) : 1e30;
        if (ratio > out.worst_ratio) out = {ratio, err, x, y, c, g, w};
      }
  return out;
}
// The same with a tolerance per channel: tolerance(want, channel).
inline Compare compare(const ImageD& got, const ImageD& want, int channels,
                       const std::function<double(double, int)>& tolerance) {
  return compare(got, want, channels, [&tolerance](int, int, int c, double w) { return tolerance(w, c); });
}
inline Compare compare(const ImageD& got, const ImageD& want, int channels,
                       const std::function<double(double)>& tolerance) {
  return compare(got, want, channels, [&tolerance](double w, int) { return tolerance(w); });
}
// Stored moments (the values of pack_moments's words: E[l], sqrt(Var[l]), n) against a reference's:
// the mean within one fp16 store plus 1e-5 magnitude; the standard deviation within the word's
// rounding plus what a variance error of 1e-5 variance_magnitude (fp32 arithmetic on values that
// large) makes of a square root; n within the word's rounding plus 1e-5 magnitude.
inline Compare compare_moments(const ImageD& got, const ImageD& want, double magnitude, double variance_magnitude) {
  const double dv = 1e-5 * variance_magnitude;
  return compare(got, want, 3, [=](double w, int c) {
    if (c == 0) return fp16_ulp(w) + 1e-5 * magnitude;
    if (c == 1) return moments_word_rounding(w) + 2 * dv / (std::abs(w) + std::sqrt(dv));
    return moments_word_rounding(w) + 1e-5 * magnitude;
  });
}
#define DENOISE_CHECK_CLOSE(result, what)                                                                          \
  CHECK_MESSAGE((result).worst_ratio <= 1.0, what << ": worst at (" << (result).worst_x << "," << (result).worst_y \
                                                  << ") channel " << (result).worst_c << ": got " << (result).got  \
                                                  << ", want " << (result).want << " (" << (result).worst_ratio    \
                                                  << " x tolerance)")

// ---- Running graphs on a device ----------------------------------------------------------------
class GraphHarness {
 public:
  explicit GraphHarness(hal::Device& device)
      : device_(device), runtime_(device), cmd_(device.create_command_list("denoise test frame")) {}
  ~GraphHarness() {
    device_.wait();
    cmd_.reset();
    release();
    if (sink_) device_.destroy(sink_);
  }
  GraphHarness(const GraphHarness&) = delete;
  GraphHarness& operator=(const GraphHarness&) = delete;

  asvgf::graph::GraphRuntime& runtime() { return runtime_; }

  // A transient image of the graph holding `data` (uploaded, then copied in by a pass), read by passes.
  asvgf::graph::ResourceId input(asvgf::graph::RenderGraph& g, const std::string& name, const ImageD& data,
                                 hal::Format format) {
    const auto id =
        g.add_image(name, static_cast<std::uint32_t>(data.width), static_cast<std::uint32_t>(data.height), format);
    fill(g, id, data);
    return id;
  }
  // Copies `data` into graph resource `target` (e.g. a persistent image) with a pass "fill.<name>".
  void fill(asvgf::graph::RenderGraph& g, asvgf::graph::ResourceId target, const ImageD& data) {
    const auto decl = g.resource(target);
    const auto image = device_.create_image({"test upload " + decl.name, decl.width, decl.height, decl.format,
                                             hal::ImageUsage::CopySrc | hal::ImageUsage::CopyDst});
    temporaries_.push_back(image);
    device_.upload_image(image, encode(data, decl.format));
    const auto src = g.import("upload " + decl.name, image, hal::State::CopyDst);
    g.add_pass("fill." + decl.name)
        .read(src, asvgf::graph::Use::CopySrc)
        .write(target, asvgf::graph::Use::CopyDst)
        .execute([src, target](asvgf::graph::PassContext& ctx) {
          ctx.commands().copy_image(ctx.image(src), ctx.image(target));
        });
    if (decl.lifetime == asvgf::graph::Lifetime::Persistent) g.output(target);
  }
  // After run(), `*out` holds the resource's contents (as doubles, 4 channels at least).
  void readback(asvgf::graph::RenderGraph& g, asvgf::graph::ResourceId resource, ImageD* out) {
    const auto decl = g.resource(resource);
    const auto image = device_.create_image({"test readback " + decl.name, decl.width, decl.height, decl.format,
                                             hal::ImageUsage::CopySrc | hal::ImageUsage::CopyDst});
    temporaries_.push_back(image);
    const auto dst = g.import("readback " + decl.name, image, hal::State::Undefined);
    g.add_pass("readback." + decl.name)
        .read(resource, asvgf::graph::Use::CopySrc)
        .write(dst, asvgf::graph::Use::CopyDst)
        .execute([resource, dst](asvgf::graph::PassContext& ctx) {
          ctx.commands().copy_image(ctx.image(resource), ctx.image(dst));
        });
    g.output(dst);
    readbacks_.push_back({image, out, decl.width, decl.height, decl.format});
  }
  // After run(), `*out` holds the buffer's 32-bit words as an image of `width` x `height` pixels of
  // `channels` words each (e.g. the a-trous chain's packed filter texels: 4 words a pixel).
  void readback_buffer(asvgf::graph::RenderGraph& g, asvgf::graph::ResourceId resource, int width, int height,
                       int channels, ImageD* out) {
    const auto decl = g.resource(resource);
    REQUIRE(decl.size == std::uint64_t{4} * static_cast<std::uint64_t>(width) * height * channels);
    const auto buffer = device_.create_buffer(
        {"test readback " + decl.name, decl.size, hal::BufferUsage::CopySrc | hal::BufferUsage::CopyDst});
    temporary_buffers_.push_back(buffer);
    const auto dst = g.import("readback " + decl.name, buffer, hal::State::Undefined);
    g.add_pass("readback." + decl.name)
        .read(resource, asvgf::graph::Use::CopySrc)
        .write(dst, asvgf::graph::Use::CopyDst)
        .execute([resource, dst, size = decl.size](asvgf::graph::PassContext& ctx) {
          ctx.commands().copy_buffer(
              {hal::BufferHandle{ctx.resource(resource).id}, hal::BufferHandle{ctx.resource(dst).id}, 0, 0, size});
        });
    g.output(dst);
    buffer_readbacks_.push_back({buffer, out, width, height, channels, decl.size});
  }
  // Compiles, executes, submits and waits; then reads back and releases the frame's test images.
  void run(asvgf::graph::RenderGraph& g) {
    keep_transients_alive(g);
    const auto compiled = runtime_.compile(g);
    runtime_.execute(compiled, *cmd_);
    device_.submit(*cmd_);
    device_.wait();
    cmd_->reset();
    if (!readbacks_.empty() || !buffer_readbacks_.empty()) {
      for (const auto& r : readbacks_) cmd_->barrier({r.image, hal::State::CopyDst, hal::State::CopySrc});
      for (const auto& r : buffer_readbacks_) cmd_->barrier({r.buffer, hal::State::CopyDst, hal::State::CopySrc});
      device_.submit(*cmd_);
      device_.wait();
      cmd_->reset();
      for (const auto& r : readbacks_) {
        std::vector<std::byte> bytes(std::size_t{r.width} * r.height * hal::format_size(r.format));
        device_.read_image(r.image, bytes);
        *r.out = decode(bytes, static_cast<int>(r.width), static_cast<int>(r.height), r.format);
      }
      for (const auto& r : buffer_readbacks_) {
        std::vector<std::uint32_t> words(r.size / 4);
        device_.read_buffer(r.buffer, 0, std::as_writable_bytes(std::span(words)));
        *r.out = ImageD(r.width, r.height, r.channels);
        for (std::size_t i = 0; i < r.out->data.size() && i < words.size(); ++i) r.out->data[i] = words[i];
      }
    }
    release();
  }

 private:
  // Workaround, not a test of the graph: when the runtime aliases two transients in one slot, the
  // new owner's first barrier is recorded from State::Undefined, which hal_vulkan maps to no source
  // stage, so synchronization validation reports a WRITE_AFTER_READ against the previous owner's
  // reads. A final pass that reads every transient keeps all lifetimes overlapping (no aliasing).
  void keep_transients_alive(asvgf::graph::RenderGraph& g) {
    if (!sink_) {
      sink_ = device_.create_buffer({"test keep-alive sink", 4, hal::BufferUsage::Storage});
      auto cmd = device_.create_command_list("sink init");
      cmd->barrier({sink_, hal::State::Undefined, hal::State::ShaderWrite});
      device_.submit(*cmd);
      device_.wait();
    }
    const auto resources = g.resources();
    auto pass = g.add_pass("test.keep_alive");
    for (asvgf::graph::ResourceId id = 0; id < resources.size(); ++id)
      if (resources[id].lifetime == asvgf::graph::Lifetime::Transient) pass.read(id);
    const auto sink = g.import("test keep-alive sink", sink_, hal::State::ShaderWrite);
    pass.write(sink);
    g.output(sink);
  }
  void release() {
    for (auto image : temporaries_) device_.destroy(image);
    for (auto buffer : temporary_buffers_) device_.destroy(buffer);
    temporaries_.clear();
    temporary_buffers_.clear();
    readbacks_.clear();
    buffer_readbacks_.clear();
  }
  struct Readback {
    hal::ImageHandle image;
    ImageD* out;
    std::uint32_t width, height;
    hal::Format format;
  };
  struct BufferReadback {
    hal::BufferHandle buffer;
    ImageD* out;
    int width, height, channels;
    std::uint64_t size;
  };
  hal::Device& device_;
  asvgf::graph::GraphRuntime runtime_;
  std::unique_ptr<hal::CommandList> cmd_;
  std::vector<hal::ImageHandle> temporaries_;
  std::vector<hal::BufferHandle> temporary_buffers_;
  std::vector<Readback> readbacks_;
  std::vector<BufferReadback> buffer_readbacks_;
  hal::BufferHandle sink_;
};

}  // namespace denoise_test
