// common/filter_texel.glsl: what the a-trous iterations between a chain's first and last pass on,
// in two storage buffers of one uvec2 a pixel (in rows): the colour texel, which every iteration
// writes, and the surface texel, which the first writes and the others only read (the surface does
// not change between iterations: 8 bytes a pixel read instead of 16 read and written). A tap is two
// 64-bit loads and a normal that needs no octahedral decode: the taps' texel fetches and their
// arithmetic (the octahedral decode the largest part) each bounded an iteration (docs/performance.md).
//   colour   x: r, g as halves      y: b, variance as halves
//   surface  x: depth (float bits; 0 = no hit), negated where the normal's z is negative; its low 8
//               bits (depth_normal rounds them away) hold the centre's depth gradient (below)
//            y: normal x, y as halves; z = +-sqrt(1 - x^2 - y^2) with the depth's sign
// The colour and variance lose nothing against the RGBA16F images they replace; the depth loses
// nothing against depth_normal's. The normal's x and y round to half (one fp16 ulp, 2^-11, at
// worst); z rebuilt from them is within min(0.037, 1.4e-3 / |z|): near z = 0 the rebuild is
// ill-conditioned (up to 2 degrees where a smooth surface's normal crosses z = 0: neighbours there
// weigh about 0.8 instead of 1 under sigma_n = 128). Two better-conditioned layouts cost more than
// they gave: x, y as snorm16 (0.4 degrees) and rebuilding the largest component
// (docs/performance.md). A normal decoded twice is the same, so equal normals weigh 1 (to fp32
// rounding). The depth gradient dz, which only the centre reads (it scales the depth weight's
// tolerance), is kept as r = dz / z in 8 bits, a float with 5 exponent and 3 mantissa bits: codes
// 1..255 are 2^(e - 20) (1 + m / 8), e = code >> 3, m = code & 7 (2^-20 to 3840, within 1/16 of r);
// code 0 is 0 (r below 2^-20: there the 1e-3 z floor of the tolerance holds unless sigma_z x step
// exceeds about 260), larger r saturates. So the gradient costs no image and no bytes of its own.
// Read on the CPU by the tests' unpack_filter_texels (tests/pipeline/denoise_harness.hpp).
#ifndef ASVGF_COMMON_FILTER_TEXEL_GLSL
#define ASVGF_COMMON_FILTER_TEXEL_GLSL

#include "common/color.glsl"

// Colour and variance as four halves (finite, clamped to the fp16 range): lossless for the RGBA16F
// values the filter carries.
uvec2 pack_color_halves(vec4 color_variance) {
  // Rounded first: packHalf2x16's rounding, like a store's, is the implementation's (common/color.glsl).
  const vec4 v = round_to_half_clamped(color_variance);
  return uvec2(packHalf2x16(v.rg), packHalf2x16(v.ba));
}
vec4 unpack_color_halves(uvec2 u) { return vec4(unpackHalf2x16(u.x), unpackHalf2x16(u.y)); }

// The relative depth gradient's 8-bit code (above); 0 for z = 0.
const uint kGradientExponentBias = 127u - 20u;
uint pack_relative_gradient(float z, float dz) {
  const float r = z > 0.0 ? dz / z : 0.0;
  if (!(r > 0.0)) return 0u;
  const uint bits = floatBitsToUint(r) + (1u << 19);  // rounded to 3 mantissa bits
  const uint e = bits >> 23;
  if (e < kGradientExponentBias) return 0u;
  return e - kGradientExponentBias > 31u ? 255u : (((e - kGradientExponentBias) << 3) | ((bits >> 20) & 7u));
}
float unpack_relative_gradient(uint code) {
  return code == 0u ? 0.0 : uintBitsToFloat((code + (kGradientExponentBias << 3)) << 20);
}

float color_halves_variance(uvec2 u) { return unpackHalf2x16(u.y).y; }

// z > 0 as depth_normal holds it (its low 8 bits 0) with a unit normal n and the depth gradient
// dz >= 0; z = 0 (no hit) packs as depth 0.
uvec2 pack_filter_surface(float z, float dz, vec3 n) {
  const float signed_z = n.z < 0.0 ? -z : z;
  return uvec2((floatBitsToUint(signed_z) & 0xffffff00u) | pack_relative_gradient(z, dz), packHalf2x16(n.xy));
}
float filter_surface_depth(uvec2 s) { return abs(uintBitsToFloat(s.x & 0xffffff00u)); }
float filter_surface_gradient(uvec2 s) { return filter_surface_depth(s) * unpack_relative_gradient(s.x & 0xffu); }
vec3 filter_surface_normal(uvec2 s) {
  const vec2 xy = unpackHalf2x16(s.y);
  const float z = sqrt(max(1.0 - dot(xy, xy), 0.0));
  return vec3(xy, (s.x & 0x80000000u) != 0u ? -z : z);
}

#endif
