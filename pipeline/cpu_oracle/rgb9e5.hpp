// cpu_oracle/rgb9e5.hpp: the C++ twin of shaders/common/color.glsl's RGB9E5 words (Vulkan's
// E5B9G9R9_UFLOAT_PACK32 layout), in double: the tests' inputs and read-backs of the colour history,
// the temporal result, the last iteration's colour and the G-buffer's albedo.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace asvgf::reference {

// The value of an RGB9E5 word's shared exponent's step (2^(e - 24)): the colour's quantum.
inline double rgb9e5_quantum(std::uint32_t word) {
  return std::ldexp(1.0, static_cast<int>(word >> 27) - 24);
}
// The quantum pack_rgb9e5 gives (r, g, b): the largest channel's binade (at least 2^-16), the
// next one where it rounds up to 512 steps.
inline double rgb9e5_quantum(double r, double g, double b) {
  const double m = std::max({r, g, b, 0.0});
  int e = m > 0 ? std::max(static_cast<int>(std::floor(std::log2(m))), -16) + 16 : 0;
  if (std::floor(m / std::ldexp(1.0, e - 24) + 0.5) >= 512) ++e;
  return std::ldexp(1.0, e - 24);
}
// pack_rgb9e5's word for (r, g, b) (values of at most 24 significant bits, as fp32 holds them).
inline std::uint32_t pack_rgb9e5(double r, double g, double b) {
  const auto clamped = [](double v) { return std::clamp(v, 0.0, 65408.0); };
  const double c[3] = {clamped(r), clamped(g), clamped(b)};
  const double quantum = rgb9e5_quantum(c[0], c[1], c[2]);
  std::uint32_t word = static_cast<std::uint32_t>(std::lround(std::log2(quantum))) + 24u;
  word <<= 27;
  for (int i = 0; i < 3; ++i) word |= static_cast<std::uint32_t>(std::floor(c[i] / quantum + 0.5)) << (9 * i);
  return word;
}
// What an RGB9E5 word holds (r, g, b).
inline std::array<double, 3> unpack_rgb9e5(std::uint32_t word) {
  const double quantum = rgb9e5_quantum(word);
  return {(word & 511u) * quantum, ((word >> 9) & 511u) * quantum, ((word >> 18) & 511u) * quantum};
}

}  // namespace asvgf::reference
