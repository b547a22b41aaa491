// common/filter_texel.glsl: the a-trous iterations' packed texel (a uvec4 a pixel, in a storage
// buffer): everything a tap needs in one 128-bit load, with a normal that needs no octahedral
// decode: the taps' two fetches (colour, depth_normal) and their arithmetic (the octahedral decode
// the largest part) each bounded an iteration (docs/performance.md).
//   x: colour r, g as halves      y: colour b, variance as halves
//   z: depth (float bits; 0 = no hit), negated where the normal's z is negative
//   w: normal x, y as halves; z = +-sqrt(1 - x^2 - y^2) with the depth's sign
// The colour and variance lose nothing against the RGBA16F images they replace. The normal's x and
// y round to half (one fp16 ulp, 2^-11, at worst); z rebuilt from them is within min(0.037,
// 1.4e-3 / |z|): near z = 0 the rebuild is ill-conditioned (up to 2 degrees where a smooth surface's
// normal crosses z = 0: neighbours there weigh about 0.8 instead of 1 under sigma_n = 128). Two
// better-conditioned layouts cost more than they gave: x, y as snorm16 (0.4 degrees) and
// rebuilding the largest component (docs/performance.md). A normal decoded twice is the same, so equal normals weigh 1 (to
// fp32 rounding). Read on the CPU by the tests' unpack_filter_texels (tests/pipeline/denoise_harness.hpp).
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

// z > 0 with a unit normal n; z = 0 (no hit) packs as depth 0.
uvec4 pack_filter_texel(vec4 color_variance, float z, vec3 n) {
  const float signed_z = n.z < 0.0 ? -z : z;
  return uvec4(pack_color_halves(color_variance), floatBitsToUint(signed_z), packHalf2x16(n.xy));
}

vec4 filter_texel_color(uvec4 t) { return unpack_color_halves(t.xy); }
float filter_texel_variance(uvec4 t) { return unpackHalf2x16(t.y).y; }
float filter_texel_depth(uvec4 t) { return abs(uintBitsToFloat(t.z)); }

vec3 filter_texel_normal(uvec4 t) {
  const vec2 xy = unpackHalf2x16(t.w);
  const float z = sqrt(max(1.0 - dot(xy, xy), 0.0));
  return vec3(xy, uintBitsToFloat(t.z) < 0.0 ? -z : z);
}

#endif
