// common/color.glsl: luminance, sample sanitising and fp16 storage limits shared by the denoiser.
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

#endif
