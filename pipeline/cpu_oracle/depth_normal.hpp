// cpu_oracle/depth_normal.hpp: the C++ twin of shaders/common/depth_normal.glsl, the G-buffer's
// 8-byte surface texel (RGBA16UI): depth rounded to 24 bits of fp32, octahedral normal as two
// snorm12, depth gradient as bfloat16. In float, step by step as the shader, so that the tests'
// inputs and the GPU's agree to the bit.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

#include "cpu_oracle/octahedral.hpp"

namespace asvgf::reference {

inline std::uint32_t snorm12(float e) {
  return static_cast<std::uint32_t>(static_cast<int>(std::floor(std::clamp(e, -1.0f, 1.0f) * 2047.0f + 0.5f)) + 2048);
}
inline float from_snorm12(std::uint32_t k) {
  return (static_cast<float>(k) - 2048.0f) / 2047.0f;
}

// The texel's four 16-bit channels from depth, gradient and octahedral coordinates; all 0 unless z > 0.
inline std::array<std::uint16_t, 4> pack_depth_normal(float z, float dz, std::array<float, 2> e) {
  if (!(z > 0.0f)) return {0, 0, 0, 0};
  const std::uint32_t zq = (std::bit_cast<std::uint32_t>(z) + 0x80u) & 0xffffff00u;
  const std::uint32_t ex = snorm12(e[0]), ey = snorm12(e[1]);
  const std::uint32_t w0 = zq | (ex >> 4);
  const std::uint32_t w1 = ((ex & 0xfu) << 28) | (ey << 16) | ((std::bit_cast<std::uint32_t>(dz) + 0x8000u) >> 16);
  return {static_cast<std::uint16_t>(w0 & 0xffffu), static_cast<std::uint16_t>(w0 >> 16),
          static_cast<std::uint16_t>(w1 & 0xffffu), static_cast<std::uint16_t>(w1 >> 16)};
}
// The same from a normal (not zero, any length), as the shader's pack_depth_normal.
inline std::array<std::uint16_t, 4> pack_depth_normal(float z, float dz, std::array<float, 3> n) {
  return pack_depth_normal(z, dz, oct_encode<float>(n));
}

// What the texel holds: depth (0: no hit), depth gradient, octahedral normal.
struct DepthNormal {
  float z = 0, dz = 0;
  std::array<float, 2> oct{};
};
inline DepthNormal unpack_depth_normal(std::array<std::uint16_t, 4> t) {
  const std::uint32_t w0 = t[0] | (std::uint32_t{t[1]} << 16);
  return {std::bit_cast<float>(w0 & 0xffffff00u),
          std::bit_cast<float>(std::uint32_t{t[2]} << 16),
          {from_snorm12(((t[0] & 0xffu) << 4) | (t[3] >> 12)), from_snorm12(t[3] & 0xfffu)}};
}

}  // namespace asvgf::reference
