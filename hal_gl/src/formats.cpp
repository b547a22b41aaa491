#include "formats.hpp"

#include <cmath>
#include <cstring>

namespace hal::gl {

GlFormat gl_format(Format format) {
  switch (format) {
    case Format::R8Unorm:
      return {GL_R8, GL_RED, GL_UNSIGNED_BYTE};
    case Format::RGBA8Unorm:
      return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};
    case Format::R16F:
      return {GL_R16F, GL_RED, GL_HALF_FLOAT};
    case Format::RG16F:
      return {GL_RG16F, GL_RG, GL_HALF_FLOAT};
    case Format::RGBA16F:
      return {GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT};
    case Format::R32F:
      return {GL_R32F, GL_RED, GL_FLOAT};
    case Format::RG32F:
      return {GL_RG32F, GL_RG, GL_FLOAT};
    case Format::RGBA32F:
      return {GL_RGBA32F, GL_RGBA, GL_FLOAT};
    case Format::R32Uint:
      return {GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT};
    case Format::RG32Uint:
      return {GL_RG32UI, GL_RG_INTEGER, GL_UNSIGNED_INT};
    case Format::RGBA32Uint:
      return {GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT};
    case Format::RGBA16Uint:
      return {GL_RGBA16UI, GL_RGBA_INTEGER, GL_UNSIGNED_SHORT};
    case Format::Undefined:
      break;
  }
  return {};
}

bool es_storage_format(Format format) {
  switch (format) {
    case Format::RGBA8Unorm:
    case Format::RGBA16F:
    case Format::R32F:
    case Format::RGBA32F:
    case Format::R32Uint:
    case Format::RGBA32Uint:
    case Format::RGBA16Uint:
      return true;
    default:
      return false;
  }
}

namespace {

std::uint16_t to_half(float f) {
  std::uint32_t x;
  std::memcpy(&x, &f, 4);
  const std::uint32_t sign = (x >> 16) & 0x8000u;
  const int exponent = static_cast<int>((x >> 23) & 0xff) - 127 + 15;
  std::uint32_t mantissa = x & 0x7fffffu;
  if (((x >> 23) & 0xff) == 0xff) return static_cast<std::uint16_t>(sign | 0x7c00u | (mantissa ? 0x200u : 0u));
  if (exponent >= 31) return static_cast<std::uint16_t>(sign | 0x7c00u);
  if (exponent <= 0) {
    if (exponent < -10) return static_cast<std::uint16_t>(sign);
    mantissa |= 0x800000u;
    const int shift = 14 - exponent;
    std::uint32_t half = mantissa >> shift;
    if ((mantissa >> (shift - 1)) & 1u) ++half;  // round half up
    return static_cast<std::uint16_t>(sign | half);
  }
  std::uint32_t half = sign | (static_cast<std::uint32_t>(exponent) << 10) | (mantissa >> 13);
  if (mantissa & 0x1000u) ++half;  // round half up
  return static_cast<std::uint16_t>(half);
}

}  // namespace

std::vector<std::byte> texels_of(Format format, std::array<float, 4> value, std::size_t count) {
  const std::uint32_t channels = format_channels(format), size = format_size(format);
  std::vector<std::byte> texel(size);
  for (std::uint32_t c = 0; c < channels; ++c) {
    const float v = value[c];
    switch (format) {
      case Format::R8Unorm:
      case Format::RGBA8Unorm: {
        const auto b = static_cast<std::uint8_t>(std::lround(std::fmin(std::fmax(v, 0.0f), 1.0f) * 255.0f));
        std::memcpy(texel.data() + c, &b, 1);
        break;
      }
      case Format::R16F:
      case Format::RG16F:
      case Format::RGBA16F: {
        const std::uint16_t h = to_half(v);
        std::memcpy(texel.data() + 2 * c, &h, 2);
        break;
      }
      case Format::R32Uint:
      case Format::RG32Uint:
      case Format::RGBA32Uint: {
        const std::uint32_t u = v <= 0.0f ? 0u : static_cast<std::uint32_t>(v);
        std::memcpy(texel.data() + 4 * c, &u, 4);
        break;
      }
      case Format::RGBA16Uint: {
        const auto u = static_cast<std::uint16_t>(v <= 0.0f ? 0.0f : std::fmin(v, 65535.0f));
        std::memcpy(texel.data() + 2 * c, &u, 2);
        break;
      }
      default:
        std::memcpy(texel.data() + 4 * c, &v, 4);
    }
  }
  std::vector<std::byte> out(size * count);
  for (std::size_t i = 0; i < count; ++i) std::memcpy(out.data() + i * size, texel.data(), size);
  return out;
}

}  // namespace hal::gl
