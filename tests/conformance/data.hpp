// Test data helpers shared by conformance tests.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "hal/shader.hpp"
#include "hal/types.hpp"

namespace conformance {

// Random texels that every backend must store bit-exactly: finite values for float formats.
inline std::vector<std::byte> random_texels(hal::Format format, std::uint32_t count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  const std::uint32_t channels = hal::format_channels(format);
  std::vector<std::byte> bytes(std::size_t{count} * hal::format_size(format));
  std::size_t at = 0;
  auto put = [&](const void* value, std::size_t size) {
    std::memcpy(bytes.data() + at, value, size);
    at += size;
  };
  for (std::uint32_t i = 0; i < count * channels; ++i) {
    switch (format) {
      case hal::Format::R8Unorm:
      case hal::Format::RGBA8Unorm: {
        const auto v = static_cast<std::uint8_t>(rng());
        put(&v, 1);
        break;
      }
      case hal::Format::R16F:
      case hal::Format::RG16F:
      case hal::Format::RGBA16F: {
        // Sign, exponent 0..30 (no inf/NaN), any mantissa.
        const auto v = static_cast<std::uint16_t>(((rng() & 1u) << 15) | ((rng() % 31u) << 10) | (rng() & 0x3ffu));
        put(&v, 2);
        break;
      }
      case hal::Format::R32F:
      case hal::Format::RG32F:
      case hal::Format::RGBA32F: {
        const float v = std::uniform_real_distribution<float>(-1e4f, 1e4f)(rng);
        put(&v, 4);
        break;
      }
      case hal::Format::RGBA16Uint: {
        const auto v = static_cast<std::uint16_t>(rng());
        put(&v, 2);
        break;
      }
      default: {
        const std::uint32_t v = rng();
        put(&v, 4);
        break;
      }
    }
  }
  return bytes;
}

template <typename T>
std::span<const std::byte> as_bytes(const std::vector<T>& v) {
  return std::as_bytes(std::span<const T>(v));
}
template <typename T>
std::span<std::byte> as_writable(std::vector<T>& v) {
  return std::as_writable_bytes(std::span<T>(v));
}
template <typename T>
std::span<const std::byte> struct_bytes(const T& value) {
  return std::as_bytes(std::span<const T>(&value, 1));
}

// Fills a shader's uniform block by member name, at the offsets its reflection gives.
class Uniforms {
 public:
  explicit Uniforms(const hal::ShaderInfo& shader) : shader_(shader), bytes_(shader.uniform_block_size) {}
  template <typename T>
  Uniforms& set(std::string_view member, T value) {
    for (const auto& m : shader_.uniform_members)
      if (m.name == member && m.size == sizeof(T) && m.offset + sizeof(T) <= bytes_.size()) {
        std::memcpy(bytes_.data() + m.offset, &value, sizeof(T));
        return *this;
      }
    throw std::runtime_error("uniform member '" + std::string(member) + "' of size " + std::to_string(sizeof(T)) +
                             " not in shader " + std::string(shader_.name));
  }
  std::span<const std::byte> bytes() const { return bytes_; }

 private:
  const hal::ShaderInfo& shader_;
  std::vector<std::byte> bytes_;
};

}  // namespace conformance
