// common/color.glsl: luminance, sample sanitising, fp16 storage limits and the RGB9E5 colour word
// shared by the denoiser.
// The CPU twin is pipeline/cpu_oracle/denoise_math.hpp; keep the two in step.
#ifndef ASVGF_COMMON_COLOR_GLSL
#define ASVGF_COMMON_COLOR_GLSL

// Rec. 709 luminance.
float luminance(vec3 rgb) { return dot(rgb, vec3(0.2126, 0.7152, 0.0722)); }

// Largest finite fp16 value: everything stored in an fp16 image is clamped to it first, so a firefly
// can never turn into +Inf in a history.
const float kFp16Max = 65504.0;

// NaN or +-Inf, tested on the bits so that no fast-math folding can remove the test.
bool not_finite(float x) { return (floatBitsToUint(x) & 0x7f800000u) == 0x7f800000u; }
bool is_nan_bits(float x) { return not_finite(x) && (floatBitsToUint(x) & 0x007fffffu) != 0u; }
bool any_not_finite(vec3 v) { return not_finite(v.x) || not_finite(v.y) || not_finite(v.z); }
bool any_nan(vec3 v) { return is_nan_bits(v.x) || is_nan_bits(v.y) || is_nan_bits(v.z); }

// A finite sample as the filters use it: negative radiance is not physical, and values are kept
// where fp16 histories can hold them (Q2RTX clamps radiance before filtering too).
vec3 clamp_sample(vec3 v) { return clamp(v, vec3(0.0), vec3(kFp16Max)); }
vec4 clamp_fp16(vec4 v) { return clamp(v, vec4(-kFp16Max), vec4(kFp16Max)); }

// x rounded to the nearest half float (ties to even), as a float that converts to it exactly. The
// conversion an fp16 image store or packHalf2x16 does may round toward zero (Vulkan and GLSL leave
// the mode to the implementation; NVIDIA's stores do): a history stored every frame then loses
// about half an ulp a store, 1/alpha of it at steady state, a bias of some 0.1-0.2% of the energy
// (docs/quality.md). NaN, Inf and magnitudes at or above kFp16Max pass unchanged (callers clamp).
float round_to_half(float x) {
  const float a = abs(x);
  if (not_finite(x) || a >= kFp16Max) return x;
  // Below 2^-14 halves are subnormal: multiples of 2^-24, exact in fp32.
  if (a < 6.103515625e-05) return roundEven(x * 16777216.0) * 5.9604644775390625e-08;
  const uint b = floatBitsToUint(x);
  return uintBitsToFloat((b + 0xFFFu + ((b >> 13) & 1u)) & 0xFFFFE000u);
}
// The same for finite values below kFp16Max (the filters' clamped outputs) in four integer
// operations a channel, for the passes whose time is their arithmetic: below 2^-14 it
// rounds to 10 bits of the float's own exponent and leaves the subnormal half's last bit to the
// conversion (an error below 2^-24).
vec4 round_to_half_clamped(vec4 v) {
  const uvec4 b = floatBitsToUint(v);
  return uintBitsToFloat((b + 0xFFFu + ((b >> 13) & 1u)) & 0xFFFFE000u);
}
vec2 round_to_half(vec2 v) { return vec2(round_to_half(v.x), round_to_half(v.y)); }
vec3 round_to_half(vec3 v) { return vec3(round_to_half(v.x), round_to_half(v.y), round_to_half(v.z)); }
vec4 round_to_half(vec4 v) { return vec4(round_to_half(v.xy), round_to_half(v.zw)); }

// RGB9E5 (Vulkan's E5B9G9R9_UFLOAT_PACK32: r, g, b in bits 0-8, 9-17, 18-26 as 9-bit mantissas
// without an implicit one, a shared exponent with bias 15 in 27-31), rounded to nearest; negative
// values 0, at most 65408 ((511 / 512) 2^16). The largest channel keeps 9 bits (a relative error of
// at most 2^-9 there, against fp16's 2^-11), the others the same absolute step. Colour that is
// written once and read at few places goes this way, 4 bytes a pixel instead of RGBA16F's 8: a
// spatial chain's temporal result and colour history (temporal.comp's COLOR_RGB9E5), and the last
// iteration's colour for the composite (atrous.comp's RGB9E5_OUT). As the iterations' colour texel
// (read at 13 taps a pixel, with the variance's half apart) it moved 16 B a pixel less at 1080p but
// cost the denoiser 11% more time on an H100, each middle iteration 30% (the decode and a third
// load a tap, in passes bound by their instructions: docs/performance.md, "The colour in four bytes").
// CPU twin: pipeline/cpu_oracle/rgb9e5.hpp.
uint pack_rgb9e5(vec3 rgb) {
  const vec3 c = clamp(rgb, vec3(0.0), vec3(65408.0));
  const float m = max(c.r, max(c.g, c.b));
  // max(-16, floor(log2 m)) + 16, from the float's exponent field (0 for m = 0: -127)
  int e = max(int(floatBitsToUint(m) >> 23) - 127, -16) + 16;
  // 2^(24 - e): the mantissas' scale; rounding the largest up to 512 takes the next exponent
  if (floor(m * uintBitsToFloat(uint(151 - e) << 23) + 0.5) >= 512.0) ++e;
  const uvec3 q = uvec3(floor(c * uintBitsToFloat(uint(151 - e) << 23) + 0.5));
  return q.r | (q.g << 9) | (q.b << 18) | (uint(e) << 27);
}
vec3 unpack_rgb9e5(uint u) {
  return vec3(uvec3(u, u >> 9, u >> 18) & 511u) * uintBitsToFloat(((u >> 27) + 103u) << 23);
}
// What an RGB9E5 word holds of rgb: what a renderer divides by when it stores its albedo as words
// (common/albedo.glsl).
vec3 round_to_rgb9e5(vec3 rgb) { return unpack_rgb9e5(pack_rgb9e5(rgb)); }

#endif
